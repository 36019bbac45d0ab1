"""A gear train as a Davies network: couplings, unit screws and the network matrices.

:func:`gearlib.davies.network` turns a :class:`gearlib.Mechanism` (with a ground, an input and an output
link) into a :class:`Network`:

* couplings, named ``A, B, C, ...`` in Laus's order: the input port (ground to input link),
  the output port (ground to output link), the gear meshes, the other turning pairs, then
  brakes and clutches. A port uses the turning pair between the ground and the port link,
  or a virtual coupling when the two are coaxial but not joined directly;
* one *motion variable* per freedom (``t_A``: a rotation about ``z``; ``p_C``: about another
  direction) and the *action variables*: transmitted forces ``U``, torques across the axis
  plane (``S``/``P``), the port torques ``T_A`` (source) and ``T_B`` (sink), friction torques
  of meshes and bearings, viscous torques, brake reactions;
* the unit motion and action matrices ``M_D`` and ``A_D``, the circuit and cutset matrices
  ``B`` and ``Q`` of the coupling graph, their column replications ``B_M`` and ``Q_A``, and
  the network matrices ``M_N`` (Laus eq. 56) and ``A_N`` (eq. 19).

>>> import gearlib as gl
>>> net = gl.davies.network(gl.catalog.load("laus_simple_pair"), ground=0, input=1, output=2)
>>> [c.name for c in net.couplings], net.coordinates
(['A', 'B', 'C'], ('t', 'u'))
>>> net.M_D()
Matrix([
[1, 1, 1],
[0, 3, 1]])
>>> net.action_names(lossless=False)
['T_A', 'U_A', 'T_B', 'U_B', 'T_C', 'U_C']
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
import sympy

from .._common.topology import CoaxialGroups
from ..errors import ConstraintError, InputError
from ..mechanism.data import Mechanism
from ._columns import Coupling, Variable, letters, select, unique, variables
from .geometry import Layout, layout as make_layout
from .graph import CouplingGraph, replicate

__all__ = ["Coupling", "Variable", "Network", "network", "LOSS_ROLES"]

LOSS_ROLES = ("friction", "bearing", "viscous")
"""Roles of the action columns that dissipate power (left out of a lossless analysis)."""


@dataclass(frozen=True)
class Network:
    """A gear train as a Davies network (see the module documentation)."""

    mechanism: Mechanism
    ground: object
    input: object
    output: object
    layout: Layout
    couplings: tuple
    graph: CouplingGraph
    coordinates: tuple
    action_coordinates: tuple
    motion_vars: tuple
    action_vars: tuple
    exact: bool
    notes: tuple = ()
    options: dict = field(default_factory=dict, compare=False, repr=False)

    # ------------------------------------------------------------------ lookups
    @property
    def d(self) -> int:
        """Order of the screw system (2 for spur trains, 3 for bevel trains)."""
        return len(self.coordinates)

    def coupling(self, name) -> Coupling:
        for c in self.couplings:
            if c.name == name:
                return c
        raise InputError(f"no coupling {name!r}; couplings are {', '.join(c.name for c in self.couplings)}")

    def mesh_coupling(self, a, b) -> Coupling:
        """The coupling of the gear pair between gears *a* and *b*."""
        a, b = self.mechanism.resolve(a), self.mechanism.resolve(b)
        for c in self.couplings:
            if c.kind == "mesh" and set(c.mesh.gears) == {a, b}:
                return c
        raise InputError(f"no gear pair between {a} and {b}")

    @property
    def meshes(self) -> tuple:
        return tuple(c for c in self.couplings if c.kind == "mesh")

    def port(self, which: str) -> Coupling:
        for c in self.couplings:
            if c.role == which:
                return c
        raise InputError(f"no {which} port")

    def columns(self, lossless: bool = False) -> list[int]:
        """Indices of the action variables used (without the loss columns when *lossless*)."""
        return [i for i, v in enumerate(self.action_vars) if not (lossless and v.role in LOSS_ROLES)]

    def motion_names(self) -> list[str]:
        return [v.name for v in self.motion_vars]

    def action_names(self, lossless: bool = False) -> list[str]:
        return [self.action_vars[i].name for i in self.columns(lossless)]

    # ------------------------------------------------------------------ matrices
    def _matrix(self, rows):
        if self.exact:
            return sympy.Matrix(rows)
        return np.array(rows, dtype=float).reshape(len(rows), -1 if rows and rows[0] else 0)

    def M_D(self):
        """Unit motion matrix ``[M_D]_{d x F}``: one unit motion screw per column."""
        return self._matrix([[v.screw[r] for v in self.motion_vars] for r in range(self.d)])

    def A_D(self, lossless: bool = False):
        """Unit action matrix ``[A_D]_{d x C}``."""
        cols = self.columns(lossless)
        return self._matrix([[self.action_vars[i].screw[r] for i in cols] for r in range(self.d)])

    @cached_property
    def B(self) -> np.ndarray:
        """Fundamental circuit matrix of the coupling graph (l x e)."""
        return self.graph.circuit_matrix()

    @cached_property
    def Q(self) -> np.ndarray:
        """Fundamental cutset matrix of the coupling graph (k x e)."""
        return self.graph.cutset_matrix()

    def _counts(self, vars_, cols=None):
        cols = range(len(vars_)) if cols is None else cols
        names = self.graph.names
        counts = [0] * len(names)
        order = []
        for i in cols:
            j = names.index(vars_[i].coupling)
            counts[j] += 1
            order.append(j)
        if order != sorted(order):
            raise AssertionError("variables must be grouped by coupling in coupling order")
        return counts

    def B_M(self) -> np.ndarray:
        """Circuit matrix of the motion graph: columns of ``B`` repeated once per freedom."""
        return replicate(self.B, self._counts(self.motion_vars))

    def Q_A(self, lossless: bool = False) -> np.ndarray:
        """Cutset matrix of the action graph: columns of ``Q`` repeated once per action."""
        return replicate(self.Q, self._counts(self.action_vars, self.columns(lossless)))

    def _stack(self, unit, rep):
        d = self.d
        rows = []
        for i in range(rep.shape[0]):
            for r in range(d):
                rows.append([unit[r, j] * int(rep[i, j]) for j in range(rep.shape[1])])
        if not rows:
            return self._matrix([[0] * rep.shape[1]]) if rep.shape[1] else self._matrix([[]])
        return self._matrix(rows)

    def M_N(self):
        """Network unit motion matrix ``[M_N]_{dl x F}`` (Laus eq. 56): circuit by circuit."""
        return self._stack(self.M_D(), self.B_M())

    def A_N(self, lossless: bool = False):
        """Network unit action matrix ``[A_N]_{dk x C}`` (Laus eq. 19): cutset by cutset."""
        return self._stack(self.A_D(lossless), self.Q_A(lossless))

    def __repr__(self) -> str:
        return (f"<Davies network of {self.mechanism.name!r}: {self.graph.n} links, {self.graph.e} couplings, "
                f"d = {self.d}, F = {len(self.motion_vars)}, C = {len(self.action_vars)}>")


# ------------------------------------------------------------------------------ building
def network(mech: Mechanism, ground=None, input=None, output=None, *, held=(), joined=(), bearings=None,
            viscous=None, chords=None, layout=None, mode: str = "auto", exact: bool = True, radii=None,
            axes=None, pitch_points=None, ports=()) -> Network:
    """The Davies network of *mech* with ports at *input* and *output* (both relative to *ground*).

    Parameters
    ----------
    held : links held to the ground (brakes); joined : pairs of links turning together (clutches).
    ports : further port links (role ``"port"``, each with a torque between the ground and the
        link), for trains with more than one degree of freedom (:func:`gearlib.davies.operating_point`).
    bearings : couplings (names, or turning pairs as ``(u, v)``) that get a Coulomb friction torque.
    viscous : couplings (names, link pairs or gear pairs) that get a viscous torque.
    chords : names of the couplings to use as chords of the spanning tree.
    layout : a :class:`~gearlib.davies.Layout`; otherwise one is made with ``mode``, ``exact``,
        ``radii``, ``axes`` and ``pitch_points`` (see :func:`gearlib.davies.layout`).
    """
    ground = mech.ground if ground is None else ground
    if ground is None:
        raise InputError(f"choose a ground link for {mech.name!r} (ground=...)")
    ground = mech.resolve(ground, "ground")
    if input is None:
        if not mech.inputs:
            raise InputError(f"choose an input link for {mech.name!r} (input=...)")
        input = mech.inputs[0]
    input = mech.resolve(input, "input")
    if output is None:
        raise InputError(f"choose an output link for {mech.name!r} (output=...)")
    output = mech.resolve(output, "output")
    for name, link in (("input", input), ("output", output)):
        if link == ground:
            raise InputError(f"the {name} link {link} is the ground; a port joins the ground to another link")
    if input == output:
        raise InputError(f"input and output are both link {input}; choose two different links")
    if mech.ground != ground:
        mech = mech.replace(ground=ground)
    lay = layout if layout is not None else make_layout(mech, mode=mode, exact=exact, radii=radii, axes=axes,
                                                        pitch_points=pitch_points)
    exact = exact or radii is not None
    planar = lay.planar
    coords = ("t", "u") if planar else ("s", "t", "u")
    acoords = ("T", "U") if planar else ("S", "T", "U")
    keep = slice(1, 3) if planar else slice(0, 3)

    def red(screw):
        return tuple(screw[keep])

    groups = CoaxialGroups([(tp.links[0], tp.links[1], tp.axis) for tp in mech.turning_pairs])
    redundant = set(groups.redundant)
    used = set()
    specs = []  # (kind, role, tail, head, axis, mesh, source, locked)

    def find_tp(u, v):
        for i, tp in enumerate(mech.turning_pairs):
            if set(tp.links) == {u, v} and i not in used:
                return i, tp
        return None, None

    def port(role, link, locked=False):
        i, tp = find_tp(ground, link)
        ax = lay.common_axis(ground, link)
        if ax is None:
            raise InputError(
                f"the {role} link {link} is not coaxial with the ground {ground}: a port torque acts about an axis "
                f"the two links share. Choose an input/output on the ground's axes, or another ground"
            )
        if i is not None:
            used.add(i)
            return ("revolute", role, ground, link, ax, None, tp, locked)
        return ("virtual", role, ground, link, ax, None, None, locked)

    specs.append(port("input", input))
    specs.append(port("output", output))
    extra = tuple(mech.resolve(p, "port") for p in ports)
    for p in extra:
        if p in (ground, input, output) or extra.count(p) > 1:
            raise InputError(f"port link {p} is the ground or another port; each port is a different link")
        specs.append(port("port", p))
    for gp, mg in zip(mech.gear_pairs, lay.meshes):
        specs.append(("mesh", None, gp.gears[0], gp.gears[1], None, mg, gp, False))
    notes = list(lay.notes)
    brakes = []
    held = mech.resolve_links(held, "held link")
    for h in held:
        if h in (ground, input, output):
            raise ConstraintError(f"held link {h} is the ground or a port; hold another link")
        brakes.append(port("held", h, locked=True))
    joined_pairs = []
    for u, v in mech.resolve_pairs(joined, "joined link"):
        joined_pairs.append((u, v))
        ax = lay.common_axis(u, v)
        if ax is None:
            raise ConstraintError(f"joined links {u} and {v} are not coaxial; a clutch joins two links on one axis")
        i, tp = find_tp(u, v)
        if i is not None:
            used.add(i)
            brakes.append(("revolute", "joined", u, v, ax, None, tp, True))
        else:
            brakes.append(("virtual", "joined", u, v, ax, None, None, True))
    for i, tp in enumerate(mech.turning_pairs):
        if i in used:
            continue
        if i in redundant:
            notes.append(f"turning pair {tp.links} closes a loop of coaxial bearings and is left out "
                         "(it would lock an undetermined force)")
            continue
        ax = lay.common_axis(*tp.links)
        specs.append(("revolute", None, tp.links[0], tp.links[1], ax, None, tp, False))
    specs.extend(brakes)

    names = letters()
    couplings = tuple(Coupling(next(names), t, h, kind, role, ax, mg, src, locked)
                      for kind, role, t, h, ax, mg, src, locked in specs)
    bearing_set = select(mech, couplings, bearings, "bearings")
    viscous_set = select(mech, couplings, viscous, "viscous")
    mvars, avars = [], []
    for c in couplings:
        m, a = variables(c, planar, red, bearing_set, viscous_set)
        mvars.extend(m)
        avars.extend(a)
    avars = unique(avars)
    graph = CouplingGraph(tuple(mech.link_ids), tuple((c.name, c.tail, c.head) for c in couplings),
                          tuple(chords) if chords else None)
    graph.chords  # noqa: B018  (choose the spanning tree now, so a bad choice of chords fails here)
    return Network(mech, ground, input, output, lay, couplings, graph, coords, acoords, tuple(mvars), tuple(avars),
                   exact, tuple(notes), {"held": held, "joined": tuple(joined_pairs), "bearings": bearing_set, "viscous": viscous_set})


