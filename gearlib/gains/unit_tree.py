"""Speeds inside one kinematic unit, relative to its carrier: the algebra every local gain
and rule stands on.

Inside a kinematic unit with carrier *k*, the fundamental-circuit (Willis) equations
``theta_{b,k} = e_{a,b} theta_{a,k}`` chain along the gear tree: relative to the carrier every
gear *g* turns at ``c_g`` times the first gear, ``c_g`` the product of the ratios on the path
(Liu, Chen and Chang eq. (1); ``c_k = 0`` for the carrier).

>>> import gearlib as gl
>>> ku2 = gl.kinematic_units(gl.catalog.load("liu_chen_fig1")).unit(2)
>>> gl.gains.unit_speeds(ku2)   # carrier 3; e_{5,2} = +80/20 (internal), e_{2,1} = -20/40
{3: Fraction(0, 1), 5: Fraction(1, 1), 2: Fraction(4, 1), 1: Fraction(-2, 1)}
"""

from __future__ import annotations
from fractions import Fraction
import sympy
from .._common.parse import to_fraction
from ..errors import InputError, UnknownLinkError
from ..mechanism.elements import GearPair
from ..units.unit import KinematicUnit

__all__ = ['unit_speeds']


# ------------------------------------------------------------------------------ unit speeds
def _int_ratio(gp: GearPair):
    """``(num, den)`` of the ratio as integers, or None when it is not rational."""
    if gp.teeth is not None and gp.ratio is None and gp.angles is None and gp.kind != "bevel":
        na, nb = gp.teeth
        return (-na if gp.kind == "external" else na), nb
    f = to_fraction(gp.e)
    return None if f is None else (f.numerator, f.denominator)


class _Tree:
    """The gear tree of a unit, rooted at its first gear, for speeds relative to the carrier."""

    def __init__(self, unit: KinematicUnit):
        adj: dict = {}
        for gp in unit.gear_pairs:
            a, b = gp.gears
            adj.setdefault(a, []).append((b, gp, False))
            adj.setdefault(b, []).append((a, gp, True))
        self.unit, self.root = unit, unit.gears[0]
        self.parent = {self.root: None}
        stack = [self.root]
        while stack:
            a = stack.pop()
            for b, gp, inverse in adj.get(a, ()):
                if b not in self.parent:
                    self.parent[b] = (a, gp, inverse)
                    stack.append(b)
        self.memo: dict = {"exact": {}, "symbolic": {}}

    def speed(self, link, mode: str):
        """c_link: the link's speed relative to the carrier with the root gear at 1."""
        if link == self.unit.carrier:
            return Fraction(0) if mode == "exact" else sympy.Integer(0)
        memo = self.memo[mode]
        if link in memo:
            return memo[link]
        path = []
        x = link
        while x not in memo and self.parent[x] is not None:
            path.append(self.parent[x])
            x = self.parent[x][0]
        start = memo.get(x, Fraction(1) if mode == "exact" else sympy.Integer(1))
        if mode == "exact":
            num, den, other = 1, 1, []
            for _, gp, inverse in path:
                r = _int_ratio(gp)
                if r is None:
                    other.append(gp.e ** (-1 if inverse else 1))
                    continue
                n, d = r
                num, den = (num * d, den * n) if inverse else (num * n, den * d)
            value = start * Fraction(num, den)
            for factor in other:
                value = sympy.nsimplify(value) * factor if not isinstance(value, sympy.Basic) else value * factor
        else:
            value = start
            for _, gp, inverse in path:
                e = gp.symbol if not gp.e.free_symbols else gp.e
                value = value / e if inverse else value * e
        memo[link] = value
        return value


def _tree(unit: KinematicUnit) -> _Tree:
    tree = unit.__dict__.get("_tree")
    if tree is None:
        tree = _Tree(unit)
        unit.__dict__["_tree"] = tree  # a cache on the immutable unit (like functools.cached_property)
    return tree


def unit_speeds(unit: KinematicUnit, mode: str = "exact") -> dict:
    """``{link: c}``: each link's speed relative to the carrier when the first gear turns at 1
    relative to it (the carrier has 0). The circuit equations solved along the gear tree.

    ``mode="exact"`` gives fractions for tooth numbers (sympy numbers for complex or symbolic
    ratios); ``mode="symbolic"`` writes each ratio as its symbol ``e_a_b``.

    >>> import gearlib as gl
    >>> ku2 = gl.kinematic_units(gl.catalog.load("liu_chen_fig1")).unit(2)
    >>> gl.gains.unit_speeds(ku2, "symbolic")
    {3: 0, 5: 1, 2: e_5_2, 1: e_2_1*e_5_2}
    """
    if mode not in ("exact", "symbolic"):
        raise InputError(f"mode must be 'exact' or 'symbolic', got {mode!r}")
    tree = _tree(unit)
    return {x: tree.speed(x, mode) for x in unit.links}


def _pair(unit: KinematicUnit, p, what: str) -> tuple:
    if not isinstance(unit, KinematicUnit):
        raise InputError(f"unit: expected a kinematic unit, such as gl.kinematic_units(mech).unit(1); got "
                         f"{type(unit).__name__}")
    if isinstance(p, str) and "/" in p:
        p = tuple(p.split("/", 1))
    if not isinstance(p, (tuple, list)):
        p = (p, unit.carrier)
    if len(p) != 2:
        raise InputError(f"{what} must be a pair (u, v) of links of {unit.name}, got {p!r}")
    out = []
    for x in p:
        y = _link_in(unit, x)
        if y is None:
            raise UnknownLinkError(
                f"{what}: link {x!r} is not in {unit.name} (links {', '.join(map(str, unit.links))}); "
                "a local input or output is a relative rotation of two links of the unit")
        out.append(y)
    u, v = out
    if u == v:
        raise InputError(f"{what} {u}/{v} relates a link to itself; give two different links of {unit.name}")
    if not unit.coaxial(u, v):
        raise InputError(
            f"{what}: links {u} and {v} of {unit.name} turn about different axes ({unit.axis(u)} and "
            f"{unit.axis(v)}), so their relative rotation is not a thin edge; choose coaxial links")
    return u, v


def _link_in(unit, x):
    if x in unit:
        return x
    try:
        y = int(x)
    except (TypeError, ValueError):
        return None
    return y if y in unit else None
