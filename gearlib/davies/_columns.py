"""The columns of a Davies network: coupling names and motion and action variables (private)."""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import InputError
from . import screws

__all__ = ["Variable", "Coupling", "letters", "select", "variables", "unique"]


@dataclass(frozen=True)
class Variable:
    """One motion or action variable: its name, its coupling, its unit screw (in the network's
    coordinates) and its role. ``scale`` converts the magnitude to physical units (1 unless
    the screw is a bevel pitch line kept unnormalised for exact work)."""

    name: str
    coupling: str
    screw: tuple
    role: str
    scale: object = 1


@dataclass(frozen=True)
class Coupling:
    """An edge of the coupling graph: motion of *head* relative to *tail*."""

    name: str
    tail: object
    head: object
    kind: str  # "revolute", "mesh" or "virtual"
    role: str | None = None  # "input", "output", "port", "held", "joined" or None
    axis: object = None  # geometry.Axis for revolute and virtual couplings
    mesh: object = None  # geometry.MeshGeometry for meshes
    source: object = None  # the TurningPair or GearPair
    locked: bool = False

    @property
    def carrier(self):
        return self.mesh.carrier if self.mesh is not None else None


def letters():
    k = 0
    while True:
        name, x = "", k
        while True:
            name = chr(ord("A") + x % 26) + name
            x = x // 26 - 1
            if x < 0:
                break
        yield name
        k += 1

def torque_name(direction, planar: bool) -> str:
    if planar:
        return "T"
    dy, dz = direction
    if dy == 0:
        return "T"
    if dz == 0:
        return "S"
    return "P"

def select(mech, couplings, spec, what) -> frozenset:
    if not spec:
        return frozenset()
    out = set()
    for item in spec:
        found = None
        for c in couplings:
            if item == c.name:
                found = c
            elif isinstance(item, (tuple, list)) and len(item) == 2:
                try:
                    pair = {mech.resolve(x) for x in item}
                except Exception:
                    pair = None
                if pair == {c.tail, c.head} and not c.locked:
                    found = c
        if found is None:
            raise InputError(f"{what}: {item!r} is not a coupling; couplings are "
                             f"{', '.join(c.name for c in couplings)} (or give two link ids)")
        if what == "bearings" and found.kind == "mesh":
            raise InputError(f"{what}: {found.name} is a gear mesh; mesh friction comes from its ordinary efficiency")
        out.add(found.name)
    return frozenset(out)

def variables(c: Coupling, planar, red, bearing_set, viscous_set):
    if c.kind == "mesh":
        mg = c.mesh
        point = mg.apex if mg.apex is not None else mg.pitch_point
        motion = [Variable(("t" if planar else "p") + "_" + c.name, c.name,
                           red(screws.revolute(point, mg.direction)), "motion", mg.scale)]
        tname = torque_name(mg.direction, planar)
        acts = [Variable(f"{tname}_{c.name}", c.name, red(screws.torque(mg.direction)), "friction", mg.scale)]
        if c.name in viscous_set:
            acts.append(Variable(f"{tname}‡_{c.name}", c.name, red(screws.torque(mg.direction)), "viscous", mg.scale))
        acts.append(Variable(f"U_{c.name}", c.name, red(screws.x_force(mg.pitch_point)), "constraint"))
        return motion, acts
    ax = c.axis
    mname = "t" if torque_name(ax.direction, planar) == "T" else "p"
    motion = [] if c.locked else [Variable(f"{mname}_{c.name}", c.name, red(screws.revolute(ax.point, ax.direction)),
                                          "motion")]
    tname = torque_name(ax.direction, planar)
    acts = []
    if c.kind == "revolute" and not planar:
        perp = screws.perpendicular(ax.direction)
        acts.append(Variable(f"{torque_name(perp, planar)}_{c.name}", c.name, red(screws.torque(perp)), "constraint"))
    if c.role in ("input", "output", "port"):
        acts.append(Variable(f"{tname}_{c.name}", c.name, red(screws.torque(ax.direction)), c.role))
    elif c.locked:
        acts.append(Variable(f"{tname}_{c.name}", c.name, red(screws.torque(ax.direction)), "reaction"))
    if c.name in bearing_set:
        acts.append(Variable(f"{tname}*_{c.name}", c.name, red(screws.torque(ax.direction)), "bearing"))
    if c.name in viscous_set:
        acts.append(Variable(f"{tname}‡_{c.name}", c.name, red(screws.torque(ax.direction)), "viscous"))
    if c.kind == "revolute":
        acts.append(Variable(f"U_{c.name}", c.name, red(screws.x_force(ax.point)), "constraint"))
    return motion, acts

def unique(avars):
    seen: dict = {}
    out = []
    for v in avars:
        name = v.name
        while name in seen:
            name += "'"
        seen[name] = True
        out.append(v if name == v.name else Variable(name, v.coupling, v.screw, v.role, v.scale))
    return out
