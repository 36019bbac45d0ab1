"""Geared robot manipulators: transmission lines, input and transmission units, structure matrix.

Chen (1998) reads a geared robot manipulator as an open-loop chain driven through gear trains:

* the **canonical spanning tree**: the turning pairs with every coaxial group hung from its
  member nearest the base, so that no path from the base repeats an axis;
* the **equivalent open-loop chain**: the tree path from the base to the end-effector; its
  links are the *primary* links ``P0 (base), P1, ..., Pn`` and its joint angles
  ``theta_i = q_{Pi, Pi-1}``; every other link is *secondary*;
* a **mechanical transmission line** for each input (actuated) link: the secondary links and
  gear pairs that carry its torque to the joints. It falls into an **input unit** and
  **transmission units** in series, one per joint it crosses, joined by *connecting links*
  coaxial with those joints. Each unit has one primary link *p*, a pre-connecting link *x*
  (its local input) and a post-connecting link *y* (its local output);
* the **forward gain** of a unit, ``G_f = q_{x,p} / q_{y,p}`` (the *input* through the
  output: the reverse of Liu and Chen's convention), derived here from the unit's own circuit
  equations, and ``G_b = 1 / G_f``;
* the actuator displacements ``q_{j,P_s}`` as sums of products of gains times joint angles
  (eq. (24), with the limits corrected: C98-E1..E3), hence the **structure matrix** ``A`` with
  ``Phi = A^T Theta`` and ``tau = A xi`` (eqs. (29)-(31)).

Units are named after Chen's Fig. 8 (IU-1..5, TU-1..7), reconstructed from the gains of
Tables 1 and 2 because the figure is lost (see :data:`UNIT_TYPES`). Derived in chapter 3.

>>> import gearlib as gl
>>> robot = gl.geared_robot(gl.catalog.robotic_wrist(), end_effector=3)
>>> robot.primary
(0, 1, 2, 3)
>>> [str(u) for u in robot.line(4).units]
['IU-1 (p=0, x=4, y=4): G = 1', 'TU-1 (p=1, x=4, y=5): G = e_5_4', 'TU-1 (p=2, x=5, y=3): G = e_3_5']
>>> robot.structure_matrix()
Matrix([
[1,         1,         1],
[0,     e_5_4,     e_7_6],
[0, e_3_5*e_5_4, e_3_7*e_7_6]])
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from functools import cached_property

import sympy

from . import _robot_units
from ._robot_units import _identify, _unit_gain, unit_gains
from ..errors import InputError, MechanismError
from ..mechanism.data import Mechanism
from ..mechanism._accept import takes_mechanism

__all__ = ["GearedRobot", "TransmissionLine", "RobotUnit", "geared_robot", "canonical_spanning_tree",
           "UNIT_TYPES", "unit_gains"]

UNIT_TYPES = _robot_units.UNIT_TYPES
"""Chen's Fig. 8, reconstructed, as data: ``name -> (turning pairs, gear pairs)`` over the roles
p (primary), x, y (connecting) and g1, g2 (the other secondary links); turning pairs are
``(parent, child, axis)`` and gear pairs ``(a, b, carrier)``. TU-7 is certain (the paper writes
its equations); IU-2..5, TU-2 and TU-6 follow from their gains and Chen's rules (11) and (13);
TU-3, TU-4 and TU-5 share one gain and their numbering is a guess."""


def canonical_spanning_tree(mech: Mechanism, base) -> dict:
    """``{link: (parent, axis)}``: the turning pairs re-arranged so that every coaxial group
    hangs from its member nearest the base (Chen's canonical spanning tree)."""
    base = mech.resolve(base, "base")
    adj: dict = {}
    for tp in mech.turning_pairs:
        a, b = tp.links
        adj.setdefault(a, []).append((b, tp.axis))
        adj.setdefault(b, []).append((a, tp.axis))
    depth, parent, hub = {base: 0}, {base: None}, {}
    queue = deque([base])
    while queue:
        a = queue.popleft()
        for b, label in adj.get(a, ()):
            if b in depth:
                continue
            # the hub of the coaxial group (a, label) is the group's member nearest the base
            key = (label, mech._groups.membership[a][label])
            h = hub.setdefault(key, a)
            depth[b] = depth[a] + 1
            parent[b] = (h, label)
            queue.append(b)
    missing = [x for x in mech.link_ids if x not in parent]
    if missing:
        raise MechanismError(f"links {', '.join(map(str, missing))} are not joined to the base {base} by turning pairs")
    return parent


@dataclass(frozen=True)
class RobotUnit:
    """An input or transmission unit: primary link *p*, connecting links *x* (pre) and *y* (post),
    its links and gear pairs, its name in Chen's Fig. 8 (None when it matches none) and whether it
    is used backwards (*x* and *y* swapped relative to the figure). ``gain`` is
    ``q_{x,p} / q_{y,p}``: the forward gain used forwards, the backward gain used backwards."""

    p: object
    x: object
    y: object
    links: tuple
    gear_pairs: tuple
    gain: sympy.Expr
    type: str | None = None
    backwards: bool = False

    @property
    def is_input_unit(self) -> bool:
        """True for the first unit of a line (an input unit, IU-k)."""
        return bool(self.type and self.type.startswith("IU"))

    def __str__(self) -> str:
        name = (self.type or "unit") + (" used backwards" if self.backwards else "")
        return f"{name} (p={self.p}, x={self.x}, y={self.y}): G = {self.gain}"


@dataclass(frozen=True)
class TransmissionLine:
    """The mechanical transmission line of one input link: its units in series, the primary
    link the actuator is mounted on (``start``), and the joints it crosses."""

    input: object
    start: object
    units: tuple
    joints: tuple

    @property
    def length(self) -> int:
        return len(self.units)

    def displacement(self, theta: dict):
        """``q_{input, start}`` from joint angles: eq. (24), corrected (C98-E2, -E3)."""
        total, prod = sympy.Integer(0), sympy.Integer(1)
        for unit, joint in zip(self.units, self.joints):
            prod = prod * unit.gain
            total += prod * theta[joint]
        return sympy.expand(total)

    def __str__(self) -> str:
        return f"line of input {self.input}: " + " -> ".join(u.type or "unit" for u in self.units)


@dataclass(frozen=True, eq=False)
class GearedRobot:
    """A geared robot manipulator analysed by Chen's structural decomposition."""

    mechanism: Mechanism
    base: object
    end_effector: object
    inputs: tuple
    tree: dict
    primary: tuple
    lines: tuple

    @property
    def secondary(self) -> tuple:
        return tuple(x for x in self.mechanism.link_ids if x not in self.primary)

    @cached_property
    def joint_angles(self) -> tuple:
        """Symbols ``theta_1 .. theta_n``."""
        return tuple(sympy.Symbol(f"theta_{i}") for i in range(1, len(self.primary)))

    def line(self, input_link) -> TransmissionLine:
        link = self.mechanism.resolve(input_link, "input link")
        for ln in self.lines:
            if ln.input == link:
                return ln
        raise InputError(f"link {link} is not an input of this robot; inputs are {', '.join(map(str, self.inputs))}")

    def structure_matrix(self, method: str = "symbolic") -> sympy.Matrix:
        """``A`` with ``Phi = A^T Theta`` (rows: joints, columns: inputs), eqs. (29)-(30).

        ``method="symbolic"`` writes each gear ratio as its symbol ``e_a_b``; ``"exact"`` puts in
        the ratios of the mechanism's tooth numbers."""
        if method not in ("symbolic", "exact"):
            raise InputError(f"method must be 'symbolic' or 'exact', got {method!r}")
        n = len(self.primary) - 1
        rows = [[sympy.Integer(0)] * len(self.lines) for _ in range(n)]
        for k, ln in enumerate(self.lines):
            prod = sympy.Integer(1)
            for unit, joint in zip(ln.units, ln.joints):
                prod = prod * unit.gain
                rows[joint - 1][k] = sympy.factor(prod)
        A = sympy.Matrix(rows)
        if method == "exact":
            from ..mechanism.equations import ratio_symbols

            A = A.subs(ratio_symbols(self.mechanism)).applyfunc(sympy.nsimplify)
        return A

    def actuator_displacements(self, method: str = "symbolic") -> sympy.Matrix:
        """``Phi = A^T Theta``: each input's displacement relative to the link it is mounted on."""
        return self.structure_matrix(method).T * sympy.Matrix(self.joint_angles)

    def joint_torques(self, xi=None, method: str = "symbolic") -> sympy.Matrix:
        """``tau = A xi`` (eq. (31)); *xi* defaults to symbols ``xi_<input>``."""
        if xi is None:
            xi = [sympy.Symbol(f"xi_{j}") for j in self.inputs]
        return self.structure_matrix(method) * sympy.Matrix(list(xi))


@takes_mechanism
def geared_robot(mech: Mechanism, *, base=None, end_effector=None, inputs=None) -> GearedRobot:
    """Decompose a geared robot manipulator (see the module documentation).

    Parameters
    ----------
    base : the base link (default ``mech.ground``)
    end_effector : the output link (default: the link deepest in the canonical spanning tree)
    inputs : the actuated links (default ``mech.inputs``), one per degree of freedom

    Raises
    ------
    MechanismError
        When a transmission line cannot be cut into units (coupled lines, or a line that
        reaches no joint), with the offending input named.
    """
    base = mech.resolve(mech.ground if base is None else base, "base")
    tree = canonical_spanning_tree(mech, base)
    depth = {}
    for z in mech.link_ids:
        d, w = 0, z
        while tree[w] is not None:
            w, d = tree[w][0], d + 1
        depth[z] = d
    if end_effector is None:
        end_effector = max(mech.link_ids, key=lambda z: (depth[z], -mech.index[z]))
    end_effector = mech.resolve(end_effector, "end_effector")
    chain = [end_effector]
    while tree[chain[-1]] is not None:
        chain.append(tree[chain[-1]][0])
    primary = tuple(reversed(chain))
    inputs = tuple(mech.resolve(i, "input") for i in (mech.inputs if inputs is None else inputs))
    if not inputs:
        raise InputError("give the actuated links: inputs=[...]")
    circuits = [(gp, {gp.gears[0], gp.gears[1], gp.carrier}) for gp in mech.gear_pairs]
    pset = set(primary)
    owner: dict = {}
    for j in inputs:
        for z in () if j in pset else _secondary_of(circuits, pset, j):
            if z in owner and owner[z] != j:
                raise MechanismError(
                    f"the transmission lines of inputs {owner[z]} and {j} share secondary link {z}: they are "
                    "coupled, and Chen's unit-by-unit decomposition needs decoupled lines")
            owner[z] = j
    lines = tuple(_line(mech, primary, tree, circuits, j) for j in inputs)
    return GearedRobot(mech, base, end_effector, inputs, tree, primary, lines)


def _secondary_of(circuits, primary: set, j) -> set:
    """The secondary links of input j's line: reached from j through circuits, not through primary links."""
    found, queue = {j}, deque([j])
    while queue:
        z = queue.popleft()
        for _gp, members in circuits:
            if z in members:
                for u in members:
                    if u not in primary and u not in found:
                        found.add(u)
                        queue.append(u)
    return found


def _line(mech, primary, tree, circuits, j) -> TransmissionLine:
    pindex = {z: i for i, z in enumerate(primary)}
    if j in pindex:
        i = pindex[j]
        if i == 0:
            raise InputError(f"input {j} is the base; choose an actuated link")
        return TransmissionLine(j, primary[i - 1], (RobotUnit(primary[i - 1], j, j, (primary[i - 1], j), (),
                                                             sympy.Integer(1), "IU-1"),), (i,))
    # secondary input: the primary link it is mounted on (its nearest primary ancestor)
    w = j
    while w not in pindex:
        w = tree[w][0]
    s = pindex[w]
    secondary = _secondary_of(circuits, set(pindex), j)
    # the line ends on the farthest primary link that shares a circuit with its secondary links
    reached = [pindex[u] for _, m in circuits if m & secondary for u in m if u in pindex]
    end = max(reached, default=s)
    if end <= s:
        raise MechanismError(f"the transmission line of input {j} reaches no joint beyond link {primary[s]}")

    def coaxial_with_joint(z, i):  # z on the axis of joint i (between primary i-1 and i)
        label = mech.coaxial(primary[i - 1], primary[i])
        return label is not None and mech.coaxial(z, primary[i]) == label and mech.coaxial(z, primary[i - 1]) == label

    connecting = [j]
    joints = list(range(s + 1, end + 1))
    for i in joints[:-1]:
        cands = [z for z in sorted(secondary, key=str) if coaxial_with_joint(z, i)
                 and any(z in m and primary[i] in m for _, m in circuits)]
        if j in cands:
            cands = [j]
        if len(cands) != 1:
            which = f"links {', '.join(map(str, cands))} could all" if cands else "no link can"
            raise MechanismError(f"input {j}: {which} connect its transmission line across joint {i}")
        connecting.append(cands[0])
    connecting.append(primary[end])
    # cut the line at its connecting links: each cluster of other secondary links belongs to
    # the unit whose primary and connecting links it touches
    inner = secondary - set(connecting)
    cluster: dict = {}
    for z in sorted(inner, key=str):
        if z in cluster:
            continue
        comp, todo = {z}, [z]
        while todo:
            u = todo.pop()
            for _, m in circuits:
                if u in m:
                    for v in m & inner:
                        if v not in comp:
                            comp.add(v)
                            todo.append(v)
        for u in comp:
            cluster[u] = frozenset(comp)
    units, taken = [], set()
    for n, joint in enumerate(joints):
        p = primary[joint - 1]
        x, y = connecting[n], connecting[n + 1]
        ends = {p, x, y}
        members = set(ends)
        for comp in set(cluster.values()):
            touch = set().union(*(m for _, m in circuits if m & comp)) - comp
            if touch <= ends:
                members |= comp
        pairs = tuple(gp for gp, m in circuits if m <= members and id(gp) not in taken)
        taken |= {id(gp) for gp in pairs}
        links = tuple(sorted(members, key=str))
        gain = _unit_gain(mech, p, x, y, links, pairs)
        name, backwards = _identify(mech, p, x, y, links, pairs)
        units.append(RobotUnit(p, x, y, links, pairs, gain, name, backwards))
    stray = [gp for gp, m in circuits if m & secondary and id(gp) not in taken]
    if stray:
        raise MechanismError(f"input {j}: gear pair {stray[0].label} belongs to no unit of its transmission line")
    return TransmissionLine(j, primary[s], tuple(units), tuple(joints))
