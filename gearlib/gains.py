"""Local gains of kinematic units and their propagation to a global input-output relation.

Inside a kinematic unit with carrier *k*, the fundamental-circuit (Willis) equations
``theta_{b,k} = e_{a,b} theta_{a,k}`` chain along the gear tree: relative to the carrier every
gear *g* turns at ``c_g`` times the first gear, ``c_g`` the product of the ratios on the path
(Liu, Chen and Chang eq. (1); ``c_k = 0`` for the carrier). Any two coaxial links *z, w* of the
unit then turn relative to each other at ``c_z - c_w``, and the **local gain** from a local
input ``theta_{x,y}`` to a local output ``theta_{z,w}`` is

    G(z, w; x, y) = theta_{z,w} / theta_{x,y} = (c_z - c_w) / (c_x - c_y).

Rules 1-5 of the paper are the special cases of this formula (see :mod:`gearlib.rules`, which
derives each in sympy from the circuit equations); :mod:`gearlib.relation` combines local gains
along the propagation paths. Derived in chapter 3.

>>> import gearlib as gl
>>> ku2 = gl.kinematic_units(gl.catalog.load("liu_chen_fig1")).unit(2)
>>> gl.local_gain(ku2, output=(3, 5), input=(1, 5), method="symbolic")   # eq. (19)
-1/(e_2_1*e_5_2 - 1)
>>> gl.local_gain(ku2, output=(3, 5), input=(1, 5))
Fraction(1, 3)
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction

import sympy

from ._parse import to_fraction
from .errors import ConstraintError, InputError, UnknownLinkError
from .mechanism import GearPair
from .units import KinematicUnit

__all__ = ["unit_speeds", "local_gain", "LocalGain", "GainSymbol"]


class GainSymbol(sympy.Symbol):
    """A sympy symbol for one local gain, printed ``G2(3,5;1,5)`` and in LaTeX as the paper's
    :math:`{}^{3,5}[\\mathrm{K4{-}1S}]_{1,5}`."""

    def __new__(cls, name, tex=None):
        obj = super().__new__(cls, name)
        if tex is not None:
            obj._tex = tex
        return obj

    def _latex(self, printer):
        return getattr(self, "_tex", self.name)


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


def local_gain(unit: KinematicUnit, output, input, *, method: str = "exact"):
    """The local gain ``theta_out / theta_in`` of a kinematic unit.

    *output* and *input* are pairs ``(z, w)`` (``theta_{z,w}``, z relative to w), text
    ``"z/w"``, or a single gear (relative to the carrier). Both must join coaxial links of the
    unit (a thin edge, g-c or g-g). Works for units of any size.

    >>> import gearlib as gl
    >>> ku2 = gl.kinematic_units(gl.catalog.load("liu_chen_transmission")).unit(2)
    >>> gl.local_gain(ku2, output=(8, 1), input=(2, 1), method="symbolic")  # Rule 5, corrected eq. (24)
    (e_1_7*e_7_8 - 1)/(e_1_6*e_6_2 - 1)
    """
    if method not in ("exact", "symbolic"):
        raise InputError(f"method must be 'exact' or 'symbolic', got {method!r}")
    if not isinstance(unit, KinematicUnit):
        raise InputError(f"local_gain needs a kinematic unit, such as gl.kinematic_units(mech).unit(1); got "
                         f"{type(unit).__name__}")
    z, w = _pair(unit, output, "output")
    x, y = _pair(unit, input, "input")
    c = _tree(unit).speed
    den = c(x, method) - c(y, method)
    if den == 0:
        raise ConstraintError(f"in {unit.name} links {x} and {y} always turn together; theta_{x},{y} cannot drive it")
    value = (c(z, method) - c(w, method)) / den
    if method == "symbolic":
        return sympy.factor(sympy.cancel(value))
    return value


@dataclass(frozen=True)
class LocalGain:
    """One local gain used in a propagation: unit, local output and input pairs, the rule it
    matches (1-5, or None), and its symbol."""

    unit: KinematicUnit
    output: tuple
    input: tuple
    symbol: GainSymbol = field(compare=False)

    @property
    def rule(self):
        from .rules import match_rule

        m = match_rule(self.unit, self.output, self.input)
        return m.rule if m else None

    @property
    def expression(self):
        """The gain in the gear-ratio symbols."""
        return local_gain(self.unit, self.output, self.input, method="symbolic")

    @property
    def value(self):
        return local_gain(self.unit, self.output, self.input)

    @property
    def latex(self) -> str:
        return self.symbol._latex(None)

    def __repr__(self) -> str:
        return str(self.symbol)

    def __str__(self) -> str:
        return f"{self.symbol} = theta_{self.output[0]},{self.output[1]} / theta_{self.input[0]},{self.input[1]} in " \
               f"{self.unit.name} ({self.unit.label})"


def _gain_symbol(unit, z, w, x, y) -> GainSymbol:
    name = f"G{unit.index}({z},{w};{x},{y})"
    kind = unit.label.replace("-", "{-}").replace(" ", r"\ ")
    tex = rf"{{}}^{{{z},{w}}}[\mathrm{{{kind}}}]_{{{x},{y}}}"
    return GainSymbol(name, tex)
