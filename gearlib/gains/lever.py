"""Lever diagrams of planetary trains (the lever analogy of Benford and Leising, SAE 810102).

A planetary set is a lever: the speeds of its sun, carrier and ring, drawn as horizontal
arrows from three points of a vertical bar, end on one straight line. That holds when the
points are spaced by tooth numbers: the carrier between the others, sun-carrier : carrier-ring
``= Z_r : Z_s`` (a double-pinion set puts the ring between sun and carrier instead). It is
Willis' equation in pictures: with the carrier at 0 and the sun at ``Z_r``,
``omega_r - omega_c = -(Z_s/Z_r) (omega_s - omega_c)`` puts the ring at ``-Z_s``.

Here every *set* is found from the data: a carrier on the main axis with the central gears its
planets connect (a Ravigneaux set, whose carrier holds two kinds of pinion, is one set of four
members). Each central gear ``g`` has its basic ratio ``E_g = omega(g/c) / omega(ref/c)``
(the product of the gear ratios along its planets), and stands at ``x_g = E_g s`` from the
carrier, ``s`` the tooth number that makes a simple set's spacing its teeth. Sets that share
two members (the Simpson set's common sun and its front carrier that is the rear ring) make
one **combined lever**, since two points fix a straight line: their members' positions are
solved exactly together. Levers that share one member are drawn side by side, the member's
nodes joined. Derived in chapter 3.

>>> import gearlib as gl
>>> lev = gl.lever_diagram(gl.catalog.simple_planetary(sun=24, ring=60))
>>> [(n.link, n.role, n.position) for n in lev.levers[0].nodes]
[(3, 'R', Fraction(-24, 1)), (4, 'C', Fraction(0, 1)), (1, 'S', Fraction(60, 1))]
>>> lev.speeds({"ground": 3, "inputs": {1: 1}})[4]
Fraction(2, 7)
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import sympy

from ..errors import MechanismError
from ..mechanism.data import Mechanism
from ..mechanism.kinematics import Solution, speeds
from ..mechanism._accept import takes_mechanism

__all__ = ["LeverSet", "LeverNode", "Lever", "LeverDiagram", "lever_diagram"]


@dataclass(frozen=True)
class LeverSet:
    """One planetary set: its ``carrier``, its central ``gears`` (links on the main axis), the
    reference gear and each gear's basic ratio ``E_g = omega(g/c) / omega(ref/c)``."""

    carrier: object
    gears: tuple
    ref: object
    basic: tuple    # (gear, E_g) in the order of ``gears``
    teeth: tuple    # (gear, teeth) where the data give them


@dataclass(frozen=True)
class LeverNode:
    """A member on a lever: its link, its place along the lever (tooth units) and its role
    (``S``, ``C``, ``R`` in a simple set; ``C`` and the link's name elsewhere)."""

    link: object
    position: Fraction
    role: str


@dataclass(frozen=True)
class Lever:
    """One lever: the sets it combines and its nodes, from the lowest position up."""

    sets: tuple
    nodes: tuple

    def node(self, link) -> LeverNode:
        return next(n for n in self.nodes if n.link == link)


@dataclass(frozen=True)
class LeverDiagram:
    """The levers of a mechanism's planetary sets (see the module docstring)."""

    mechanism: Mechanism
    levers: tuple

    def speeds(self, state=None) -> dict:
        """``{link: speed}`` (exact) of every link in a *state*: a :class:`~gearlib.Solution`, a gear
        of the schedule (``"1st"``: its shift elements, the mechanism's ground, its first input at
        1), or a mapping with ``ground``, ``inputs``, ``held`` and ``joined`` for :func:`gearlib.speeds`."""
        return dict(_solution(self.mechanism, state).items())


def _solution(mech, state) -> Solution:
    if isinstance(state, Solution):
        return state
    if isinstance(state, str):
        if not mech.inputs:
            raise MechanismError(f"{mech.name!r} names no input link: give the state as "
                                 "{'ground': ..., 'inputs': {link: 1}, ...}")
        return speeds(mech, mech.ground, {mech.inputs[0]: 1}, **mech.gear_constraints(state))
    if isinstance(state, dict):
        unknown = set(state) - {"ground", "inputs", "held", "joined"}
        if unknown:
            raise MechanismError(f"lever state: unknown key {sorted(unknown, key=str)[0]!r}; give ground, inputs, "
                                 "held, joined")
        return speeds(mech, state.get("ground"), state.get("inputs"), held=state.get("held", ()),
                      joined=state.get("joined", ()))
    raise MechanismError(f"lever state must be a gear name, a mapping or a gl.Solution, got {type(state).__name__}")


def _fraction(value, what) -> Fraction:
    v = sympy.nsimplify(sympy.simplify(value))
    if v.free_symbols:
        raise MechanismError(f"{what} is the symbolic {value}: a lever diagram needs numbers (give the teeth)")
    if not v.is_Rational:
        raise MechanismError(f"{what} is {value}, not a real fraction: a lever is drawn for sets whose basic "
                             "ratios are real (spur gears, or bevel gears whose planets join coaxial gears)")
    return Fraction(int(v.p), int(v.q))


def _main_axis(mech):
    g = mech._groups
    order = {x: i for i, x in enumerate(mech.link_ids)}
    if not g.members:
        raise MechanismError(f"{mech.name!r} has no turning pairs, so no planetary set to draw as a lever")
    best = min(range(len(g.members)), key=lambda i: (-len(g.members[i]), mech.ground not in g.members[i],
                                                      min(order[x] for x in g.members[i])))
    return g.labels[best], g.members[best]


def _sets(mech) -> list[LeverSet]:
    label, central = _main_axis(mech)
    out = []
    for c in mech.link_ids:
        if c not in central:
            continue
        pairs = [gp for gp in mech.gear_pairs if gp.carrier == c]
        adj: dict = {}
        for gp in pairs:
            a, b = gp.gears
            adj.setdefault(a, []).append((b, gp, 1))
            adj.setdefault(b, []).append((a, gp, -1))
        seen = set()
        for start in [x for x in mech.link_ids if x in adj]:
            if start in seen:
                continue
            ratio = {start: sympy.Integer(1)}   # omega(x/c) / omega(start/c)
            queue = [start]
            seen.add(start)
            while queue:
                x = queue.pop(0)
                for y, gp, sign in adj[x]:
                    if y not in ratio:
                        ratio[y] = ratio[x] * (gp.e if sign == 1 else 1 / gp.e)
                        seen.add(y)
                        queue.append(y)
            gears = [x for x in mech.link_ids if x in ratio and x in central and mech.coaxial(x, c) == label]
            if len(gears) < 2:
                continue
            internal = {g for gp in pairs if gp.kind == "internal" for g in gp.gears}
            ref = next((g for g in gears if g not in internal), gears[0])   # a sun, where there is one
            basic = tuple((g, _fraction(ratio[g] / ratio[ref], f"the basic ratio of gear {g} to {ref} on carrier {c}"))
                          for g in gears)
            teeth = {}
            for gp in pairs:
                if gp.teeth is not None:
                    for g, z in zip(gp.gears, gp.teeth):
                        if g in gears:
                            teeth.setdefault(g, z)
            first = min(i for i, gp in enumerate(mech.gear_pairs) if gp.carrier == c and set(gp.gears) & set(ratio))
            out.append((first, LeverSet(c, tuple(gears), ref, basic, tuple(teeth.items()))))
    out = [s for _, s in sorted(out, key=lambda t: t[0])]   # in the order the data give the sets
    if not out:
        raise MechanismError(
            f"{mech.name!r} has no planetary set (a carrier on the main axis whose planets join two gears on "
            "that axis): no lever diagram to draw")
    return out


def _solve_positions(sets) -> dict | None:
    """Positions that put every set's speeds on one line, or None when the sets leave more than
    two degrees of freedom (they cannot share a lever). Exact Gauss-Jordan on fractions."""
    first = sets[0]
    links = list(dict.fromkeys(x for s in sets for x in (s.carrier, *s.gears)))
    col = {x: i for i, x in enumerate(links)}
    rows = []
    for s in sets:
        for g, e in s.basic:
            if g == s.ref:
                continue
            r = [Fraction(0)] * (len(links) + 1)   # x_g - x_c - e (x_ref - x_c) = 0
            r[col[g]] += 1
            r[col[s.carrier]] += e - 1
            r[col[s.ref]] -= e
            rows.append(r)
    scale = _scale(first)
    for link, value in ((first.carrier, Fraction(0)), (first.ref, scale)):
        r = [Fraction(0)] * (len(links) + 1)
        r[col[link]] = Fraction(1)
        r[-1] = value
        rows.append(r)
    n = len(links)
    piv_row = 0
    where = {}
    for j in range(n):
        p = next((i for i in range(piv_row, len(rows)) if rows[i][j] != 0), None)
        if p is None:
            continue
        rows[piv_row], rows[p] = rows[p], rows[piv_row]
        inv = 1 / rows[piv_row][j]
        rows[piv_row] = [v * inv for v in rows[piv_row]]
        for i in range(len(rows)):
            if i != piv_row and rows[i][j] != 0:
                f = rows[i][j]
                rows[i] = [a - f * b for a, b in zip(rows[i], rows[piv_row])]
        where[j] = piv_row
        piv_row += 1
    if len(where) < n or any(all(v == 0 for v in r[:-1]) and r[-1] != 0 for r in rows):
        return None
    return {x: rows[where[col[x]]][-1] for x in links}


def _scale(s: LeverSet) -> Fraction:
    """The factor that spaces a simple set by its teeth: the reference gear's teeth over the
    smallest basic ratio (in size) of the others."""
    teeth = dict(s.teeth)
    smallest = min(abs(e) for g, e in s.basic if g != s.ref)
    return Fraction(teeth.get(s.ref, 1)) / smallest


def _roles(mech, lever_sets) -> dict:
    """``S`` (an external central gear), ``R`` (a ring) or ``C`` (the carrier) in each set, joined
    by ``/`` for a member with several (the Simpson set's front carrier and rear ring: ``C/R``)."""
    roles: dict = {}
    for s in lever_sets:
        found = {s.carrier: "C"}
        for g in s.gears:
            internal = any(gp.kind == "internal" for gp in mech.gear_pairs if gp.carrier == s.carrier and g in gp.gears)
            found[g] = "R" if internal else "S"
        for link, role in found.items():
            roles.setdefault(link, [])
            if role not in roles[link]:
                roles[link].append(role)
    return {link: "/".join(r) for link, r in roles.items()}


@takes_mechanism
def lever_diagram(mech: Mechanism) -> LeverDiagram:
    """The lever diagram of *mech*'s planetary sets: one lever per set, sets that share two members
    combined (see the module docstring).

    Raises :class:`~gearlib.errors.MechanismError` when the mechanism has no planetary set, or a set
    whose gear ratios are symbolic or complex.
    """
    if not isinstance(mech, Mechanism):
        raise MechanismError(f"lever_diagram needs a gl.Mechanism, got {type(mech).__name__}")
    groups = [[s] for s in _sets(mech)]
    merged = True
    while merged:   # two levers sharing two members are one (two points fix a line)
        merged = False
        for i in range(len(groups)):
            for j in range(i + 1, len(groups)):
                a = {x for s in groups[i] for x in (s.carrier, *s.gears)}
                b = {x for s in groups[j] for x in (s.carrier, *s.gears)}
                if len(a & b) >= 2 and _solve_positions(groups[i] + groups[j]) is not None:
                    groups[i] = groups[i] + groups[j]
                    del groups[j]
                    merged = True
                    break
            if merged:
                break
    levers = []
    for sets in groups:
        pos = _solve_positions(sets)
        if pos is None:  # pragma: no cover - a single set always has its line
            raise MechanismError(f"{mech.name!r}: the sets on carrier {sets[0].carrier} leave no straight lever")
        roles = _roles(mech, sets)
        nodes = tuple(sorted((LeverNode(x, p, roles.get(x, "")) for x, p in pos.items()),
                             key=lambda n: (n.position, str(n.link))))
        levers.append(Lever(tuple(sets), nodes))
    return LeverDiagram(mech, tuple(levers))
