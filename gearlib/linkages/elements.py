"""The parts of a linkage: joints with their geometry and friction, and ports.

A **joint** joins two links, its *tail* and its *head* (the order fixes the sense of its
motions: the head relative to the tail). Its geometry is given in the *reference pose*, the
position in which the linkage is drawn in the file (every link's frame is then the world
frame):

==============  =============================  ===========================================
kind            freedoms                       geometry
==============  =============================  ===========================================
revolute        1 rotation                     ``point``; ``axis`` (spatial only)
prismatic       1 translation                  ``point`` on the line; ``axis``; optional
                                               ``normal`` (a face normal, fixed in the tail)
                                               and ``split`` (two couplings, below)
universal       2 rotations                    ``point``; ``axes`` (two perpendicular axes,
                                               the first fixed in ``fixed_in[0]``, the second
                                               in ``fixed_in[1]``; default tail, head)
spherical       3 rotations                    ``point``
cylindrical     1 rotation + 1 translation     ``point``; ``axis``; optional ``normal``
==============  =============================  ===========================================

A **split** prismatic pair (Laus 2011, section 4.1.1) is two couplings in parallel: a *square
annulus* at a point fixed in the tail (one translation, two small rotations; it carries two
forces and the torque about the axis) and a *round annulus* at a point fixed in the head (one
translation, three rotations; two forces); ``split_in`` fixes both points in one link (a
block on a long guide); in a planar linkage each half is a slider with one normal force.
Together they allow the one translation and lock nothing in their loop; each carries its normal forces at a known place, so that friction
follows the forces that the pair's transmitted torques cause.

A **port** is where power enters or leaves: an actuated joint (a torque about a revolute's
axis, a force along a prismatic's) or a load on a point of a link, taken in through a
*virtual coupling* between the ground and that link (all freedoms, one action: the load).
Its role is ``input`` (a source) or ``output`` (a sink).

>>> from gearlib.linkages.elements import Joint
>>> j = Joint("A", "revolute", (0, 1), point=(0.0, 0.0))
>>> j.freedoms, j.planar
(1, True)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..errors import DataFormatError

__all__ = ["KINDS", "Friction", "Joint", "Port", "ROLES"]

KINDS = {"revolute": 1, "prismatic": 1, "universal": 2, "spherical": 3, "cylindrical": 2}
"""Joint kinds and their numbers of freedoms."""
SPATIAL_ONLY = ("universal", "spherical", "cylindrical")
ROLES = ("input", "output")
LAWS = ("cosine", "constant")


def _vector(value, dim: int, where: str, *, unit: bool = False) -> tuple:
    if not isinstance(value, (list, tuple)) or len(value) != dim:
        raise DataFormatError(f"{where}: expected {dim} coordinates, got {value!r}")
    out = []
    for v in value:
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(float(v)):
            raise DataFormatError(f"{where}: {v!r} is not a finite number")
        out.append(float(v))
    if unit:
        n = math.sqrt(sum(x * x for x in out))
        if n < 1e-12:
            raise DataFormatError(f"{where}: a direction cannot be the zero vector")
        if abs(n - 1.0) > 4e-16:  # a unit vector stays as written (saving and loading change nothing)
            out = [x / n for x in out]
    return tuple(out)


def _dot(a, b) -> float:
    return sum(x * y for x, y in zip(a, b))


@dataclass(frozen=True)
class Friction:
    """Coulomb friction in a joint (Laus 2011, eqs. (98), (127)-(129), (133)).

    ``mu`` is the coefficient; ``radius`` the pin radius of a rotation freedom (no friction
    torque without it). A friction torque about a rotation axis is ``mu radius`` times the
    forces the joint carries: ``thrust`` times the force along that axis (a flat face; 1 as the
    thesis' eq. (146) with inner radius 0, whose corrected form gives 1/2) plus a multiplier times
    the forces across it (a cylindrical face: Table 16, ``law="cosine"`` for worn surfaces, 4/pi;
    ``"constant"`` for new ones, pi/2; or ``multiplier`` directly). A friction force along a
    translation is ``mu`` times the normal forces. ``norm``: ``"sum"`` adds the absolute values
    of the forces across (eqs. (127)-(129)), ``"resultant"`` takes their resultant (eq. (133));
    by default a revolute or cylindrical pin uses the resultant (its transverse directions are
    arbitrary) and the other joints the sum, as the thesis does.
    """

    mu: float = 0.0
    radius: float | None = None
    law: str = "cosine"
    multiplier: float | None = None
    thrust: float = 1.0
    norm: str | None = None

    def __post_init__(self):
        for name in ("mu", "thrust"):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or v < 0:
                raise DataFormatError(f"friction: {name} must be a number >= 0, got {v!r}")
        if self.radius is not None and (isinstance(self.radius, bool) or not isinstance(self.radius, (int, float))
                                        or not math.isfinite(self.radius) or self.radius <= 0):
            raise DataFormatError(f"friction: radius must be a positive length, got {self.radius!r}")
        if self.law not in LAWS:
            raise DataFormatError(f"friction: law must be one of {', '.join(LAWS)}, got {self.law!r}")
        if self.multiplier is not None and not (isinstance(self.multiplier, (int, float)) and self.multiplier > 0):
            raise DataFormatError(f"friction: multiplier must be a positive number, got {self.multiplier!r}")
        if self.norm not in (None, "sum", "resultant"):
            raise DataFormatError(f"friction: norm must be 'sum' or 'resultant', got {self.norm!r}")

    @property
    def across(self) -> float:
        """The multiplier of the forces across a pin (on its cylindrical face)."""
        if self.multiplier is not None:
            return float(self.multiplier)
        from ..davies.friction import bearing_multiplier

        return bearing_multiplier(math.pi / 2, self.law)

    def to_data(self) -> dict:
        out: dict = {"mu": self.mu}
        if self.radius is not None:
            out["radius"] = self.radius
        if self.multiplier is not None:
            out["multiplier"] = self.multiplier
        elif self.law != "cosine":
            out["law"] = self.law
        if self.thrust != 1.0:
            out["thrust"] = self.thrust
        if self.norm is not None:
            out["norm"] = self.norm
        return out


@dataclass(frozen=True)
class Joint:
    """One joint (see the module documentation). Points and directions have 2 coordinates in a
    planar linkage and 3 in a spatial one; directions need not be unit vectors."""

    name: str
    kind: str
    links: tuple
    point: tuple
    axis: tuple | None = None
    axes: tuple | None = None
    fixed_in: tuple | None = None
    normal: tuple | None = None
    split: tuple | None = None
    split_names: tuple | None = None
    split_in: tuple | None = None
    friction: Friction | None = None
    planar: bool = field(default=True, compare=False, repr=False)

    def __post_init__(self):
        where = f"joint {self.name}"
        if self.kind not in KINDS:
            raise DataFormatError(f"{where}: kind {self.kind!r} is not one of {', '.join(KINDS)}")
        dim = len(self.point)
        object.__setattr__(self, "planar", dim == 2)
        object.__setattr__(self, "point", _vector(self.point, dim, f"{where}: point"))
        if dim not in (2, 3):
            raise DataFormatError(f"{where}: a point has 2 (planar) or 3 (spatial) coordinates")
        if self.planar and self.kind in SPATIAL_ONLY:
            raise DataFormatError(f"{where}: a {self.kind} joint moves out of the plane; make the linkage spatial")
        if self.kind in ("prismatic", "cylindrical") or (self.kind == "revolute" and not self.planar):
            if self.axis is None:
                raise DataFormatError(f"{where}: a {self.kind} joint needs an `axis`")
            object.__setattr__(self, "axis", _vector(self.axis, dim, f"{where}: axis", unit=True))
        elif self.axis is not None and not (self.kind == "revolute" and self.planar):
            raise DataFormatError(f"{where}: a {self.kind} joint takes no single `axis`")
        elif self.axis is not None:
            raise DataFormatError(f"{where}: a planar revolute turns about the normal to the plane; leave out `axis`")
        self._check_axes(where, dim)
        if self.normal is not None:
            if self.kind not in ("prismatic", "cylindrical") or self.planar:
                raise DataFormatError(f"{where}: `normal` is for spatial prismatic and cylindrical joints")
            n = _vector(self.normal, dim, f"{where}: normal", unit=True)
            if abs(_dot(n, self.axis)) > 1e-9:
                raise DataFormatError(f"{where}: `normal` must be perpendicular to the axis (cosine "
                                      f"{_dot(n, self.axis):.3g})")
            object.__setattr__(self, "normal", n)
        self._check_split(where, dim)
        if self.friction is not None:
            f = self.friction
            if f.mu > 0 and self.kind == "spherical":
                raise DataFormatError(f"{where}: friction in a spherical joint is not modelled; give mu: 0")

    def _check_axes(self, where, dim):
        if self.kind != "universal":
            if self.axes is not None or self.fixed_in is not None:
                raise DataFormatError(f"{where}: `axes` and `fixed_in` are for universal joints")
            return
        if self.axes is None or len(self.axes) != 2:
            raise DataFormatError(f"{where}: a universal joint needs `axes`: two perpendicular directions")
        a = tuple(_vector(x, dim, f"{where}: axes", unit=True) for x in self.axes)
        c = _dot(*a)
        if abs(c) > 1e-9:
            raise DataFormatError(f"{where}: the two axes of a universal joint must be perpendicular; they are at "
                                  f"{math.degrees(math.acos(max(-1.0, min(1.0, c)))):.4g} degrees")
        object.__setattr__(self, "axes", a)
        on = tuple(self.fixed_in) if self.fixed_in is not None else tuple(self.links)
        if len(on) != 2 or set(on) != set(self.links):
            raise DataFormatError(f"{where}: `fixed_in` names the link each axis is fixed in: the joint's two links, "
                                  f"{self.links[0]} and {self.links[1]}, in some order")
        object.__setattr__(self, "fixed_in", on)

    def _check_split(self, where, dim):
        if self.split is None:
            if self.split_names is not None or self.split_in is not None:
                raise DataFormatError(f"{where}: `split_names` and `split_in` need `split`")
            return
        if self.kind not in ("prismatic", "cylindrical"):
            raise DataFormatError(f"{where}: only prismatic and cylindrical pairs can be split")
        if len(self.split) != 2:
            raise DataFormatError(f"{where}: `split` is two points: one fixed in the tail, one in the head")
        pts = tuple(_vector(p, dim, f"{where}: split", unit=False) for p in self.split)
        for p in pts:
            d = [x - y for x, y in zip(p, self.point)]
            along = _dot(d, self.axis)
            off = math.sqrt(sum((x - along * a) ** 2 for x, a in zip(d, self.axis)))
            if off > 1e-9 * max(1.0, math.sqrt(_dot(d, d))):
                raise DataFormatError(f"{where}: split point {list(p)} is {off:.3g} off the axis; it must lie on the "
                                      "line of the pair")
        object.__setattr__(self, "split", pts)
        names = tuple(self.split_names) if self.split_names is not None else (f"{self.name}1", f"{self.name}2")
        if len(names) != 2 or len(set(names)) != 2 or not all(isinstance(n, str) and n for n in names):
            raise DataFormatError(f"{where}: `split_names` are two different names for the two couplings")
        object.__setattr__(self, "split_names", names)
        on = tuple(self.split_in) if self.split_in is not None else tuple(self.links)
        if len(on) != 2 or not set(on) <= set(self.links):
            raise DataFormatError(f"{where}: `split_in` names the link each split point is fixed in (the tail or the "
                                  f"head, {self.links[0]} or {self.links[1]})")
        object.__setattr__(self, "split_in", on)

    @property
    def tail(self):
        return self.links[0]

    @property
    def head(self):
        return self.links[1]

    @property
    def freedoms(self) -> int:
        return KINDS[self.kind]

    @property
    def couplings(self) -> tuple:
        """Names of the couplings this joint becomes (two for a split pair)."""
        return self.split_names if self.split is not None else (self.name,)

    def to_data(self) -> dict:
        out: dict = {"name": self.name, "kind": self.kind, "links": list(self.links), "point": list(self.point)}
        for key in ("axis", "normal"):
            if getattr(self, key) is not None and not (key == "axis" and self.kind == "revolute" and self.planar):
                out[key] = list(getattr(self, key))
        if self.axes is not None:
            out["axes"] = [list(a) for a in self.axes]
            if self.fixed_in != tuple(self.links):
                out["fixed_in"] = list(self.fixed_in)
        if self.split is not None:
            out["split"] = [list(p) for p in self.split]
            out["split_names"] = list(self.split_names)
            if self.split_in != tuple(self.links):
                out["split_in"] = list(self.split_in)
        if self.friction is not None:
            out["friction"] = self.friction.to_data()
        return out


@dataclass(frozen=True)
class Port:
    """Where power enters or leaves: ``joint`` (an actuated joint) or ``link`` with ``point``
    and ``force`` or ``torque`` (a load through a virtual coupling between the ground and the
    link). ``role`` is ``input`` (a source) or ``output`` (a sink)."""

    name: str
    role: str
    joint: str | None = None
    link: object = None
    point: tuple | None = None
    force: tuple | None = None
    torque: tuple | None = None

    def __post_init__(self):
        where = f"port {self.name}"
        if self.role not in ROLES:
            raise DataFormatError(f"{where}: role must be 'input' (a source) or 'output' (a sink), got {self.role!r}")
        if (self.joint is None) == (self.link is None):
            raise DataFormatError(f"{where}: give either `joint` (an actuated joint) or `link` and `point` (a load)")
        if self.joint is not None:
            if any(getattr(self, k) is not None for k in ("point", "force", "torque")):
                raise DataFormatError(f"{where}: a port on a joint acts along the joint's freedom; leave out "
                                      "point, force and torque")
            return
        if self.point is None:
            raise DataFormatError(f"{where}: a load on link {self.link} needs the `point` it acts at")
        dim = len(self.point)
        object.__setattr__(self, "point", _vector(self.point, dim, f"{where}: point"))
        if (self.force is None) == (self.torque is None):
            raise DataFormatError(f"{where}: give the direction of the load as `force` or `torque`")
        key = "force" if self.force is not None else "torque"
        if key == "torque" and dim == 2:
            value = self.torque if isinstance(self.torque, (list, tuple)) else [self.torque]
            if len(value) != 1 or value[0] not in (1, -1):
                raise DataFormatError(f"{where}: a planar torque is [1] or [-1] (about the normal to the plane)")
            object.__setattr__(self, "torque", (float(value[0]),))
            return
        object.__setattr__(self, key, _vector(getattr(self, key), dim, f"{where}: {key}", unit=True))

    @property
    def kind(self) -> str:
        return "joint" if self.joint is not None else "load"

    def to_data(self) -> dict:
        out: dict = {"name": self.name, "role": self.role}
        if self.joint is not None:
            out["joint"] = self.joint
        else:
            out["link"] = self.link
            out["point"] = list(self.point)
            key = "force" if self.force is not None else "torque"
            out[key] = list(getattr(self, key))
        return out
