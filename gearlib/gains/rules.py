"""Rules 1-5 of Liu, Chen and Chang, derived in sympy from the fundamental-circuit equations.

Inside a kinematic unit with carrier *k* the fundamental-circuit equations
``theta_{b,k} = e_{a,b} theta_{a,k}`` chain along the gear tree into eq. (1),
``theta_{y,k} = E_{x,y} theta_{x,k}``, with ``E_{x,y}`` the product of the ratios on the path
from x to y. Coaxial links add up (eq. (3), corrected: ``theta_{x,y} = theta_{x,k} - theta_{y,k}``).
Where the local input and output sit decides the rule:

==========  ====================================  =====================================
rule        local output / local input            gain
==========  ====================================  =====================================
1           g-c vs g-c: (y,k) / (x,k)             E_{x,y}
2           g-g vs g-c, coaxial: (x,y) / (y,k)    E_{y,x} - 1
3           g-g vs g-c: (x,y) / (r,k)             (E_{y,x} - 1) E_{r,y}
4           g-g vs g-g: (x,q) / (y,p)             (E_{p,x} - E_{p,q}) / (E_{p,y} - 1)
5           g-g vs g-g, coaxial: (x,p) / (y,p)    (E_{p,x} - 1) / (E_{p,y} - 1)
==========  ====================================  =====================================

:func:`derive_rule` derives each twice, without typing the result: once in the path products
``E`` (eq. (1) and the coaxial conditions, solved by sympy), and once from every circuit
equation of a unit from the catalogue (the template), and checks that the two agree.
:func:`match_rule` says which rule a connection in any unit follows (of any size; the paper's
Table 2 used for the six-link unit of the transmission, eq. (25)). Derived in chapter 3.

>>> import gearlib as gl
>>> d = gl.derive_rule(2)
>>> d.general
E_y_x - 1
>>> d.agrees
True
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy

from .._common.parse import shown
from ..errors import InputError
from ..units.unit import KinematicUnit

__all__ = ["RuleDerivation", "RuleMatch", "derive_rule", "match_rule", "RULES"]

RULES = {
    1: ("g-c vs g-c", "K4-2", {"x": 2, "y": 3}),
    2: ("g-c vs g-g, coaxial vertices", "K4-1S", {"x": 2, "y": 3}),
    3: ("g-c vs g-g, non-coaxial vertices", "K5-6S", {"x": 2, "y": 3, "r": 4}),
    4: ("g-g vs g-g, different axis labels", "K5-4D", {"x": 1, "q": 3, "y": 2, "p": 4}),
    5: ("g-g vs g-g, coaxial", "K5-7D", {"x": 2, "y": 3, "p": 4}),
}
"""Rule number -> (name, template unit from the catalogue, roles of the template's gears)."""

# local output and input of each rule, as pairs of roles ("k" is the carrier)
_PORTS = {1: (("y", "k"), ("x", "k")), 2: (("x", "y"), ("y", "k")), 3: (("x", "y"), ("r", "k")),
          4: (("x", "q"), ("y", "p")), 5: (("x", "p"), ("y", "p"))}
# eq. (1) along the gear paths of each rule: theta_{b,k} = E_{a,b} theta_{a,k} for each (a, b)
_CHAINS = {1: (("x", "y"),), 2: (("y", "x"),), 3: (("r", "y"), ("y", "x")),
           4: (("p", "x"), ("p", "q"), ("p", "y")), 5: (("p", "x"), ("p", "y"))}


def _E(a, b) -> sympy.Symbol:
    return sympy.Symbol(f"E_{a}_{b}")


@dataclass(frozen=True)
class RuleDerivation:
    """A rule derived two ways.

    ``general``: the gain in path products ``E_u_v`` (roles x, y, ...), solved by sympy from
    eq. (1) and the coaxial conditions (``general_equations``). ``gain``: the gain of the
    template unit in its gear-ratio symbols, solved from all its circuit equations
    (``equations``). ``E`` maps each path product of the template to its ratios.
    """

    rule: int
    name: str
    template: str
    roles: dict
    general_equations: tuple
    general: sympy.Expr
    equations: tuple
    gain: sympy.Expr
    E: dict = field(default_factory=dict)

    @property
    def agrees(self) -> bool:
        """The two derivations give the same gain."""
        return sympy.simplify(self.general.subs(self.E) - self.gain) == 0


def _solve_ratio(equations, unknowns, output):
    sol = sympy.solve(equations, unknowns, dict=True)
    if len(sol) != 1:
        raise ValueError("the circuit equations do not fix the unit's motion")
    return sympy.factor(sympy.cancel(output.subs(sol[0])))


def derive_rule(n: int) -> RuleDerivation:
    """Derive rule *n* (1-5) in sympy; see the module documentation."""
    if isinstance(n, bool) or not isinstance(n, int) or n not in RULES:
        raise InputError(f"derive_rule: Liu and Chen's rules are numbered 1 to 5, got {shown(n)}")
    from ..units.catalogue import ku_catalogue

    name, template, gears = RULES[n]
    (zo, wo), (xi, yi) = _PORTS[n]
    # 1. general: eq. (1) along the gear paths, then the coaxial condition of the input
    roles = sorted(gears)
    th = {g: sympy.Symbol(f"theta_{g},k") for g in roles}
    th["k"] = sympy.Integer(0)
    eqs = [sympy.Eq(th[b], _E(a, b) * th[a]) for a, b in _CHAINS[n]]
    t_in = sympy.Symbol("theta_in")
    eqs.append(sympy.Eq(t_in, th[xi] - th[yi]))
    general = sympy.factor(_solve_ratio(eqs, [th[g] for g in roles], (th[zo] - th[wo]) / t_in))
    # 2. the template unit: every circuit equation, the carrier held
    entry = next(e for e in ku_catalogue(variants=True) if e.name == template)
    unit = entry.unit()
    link = dict(gears, k="k")
    om = {g: sympy.Symbol(f"theta_{g},k") for g in unit.gears}
    om["k"] = sympy.Integer(0)
    circuit = [sympy.Eq(om[gp.gears[1]], gp.symbol * om[gp.gears[0]]) for gp in unit.gear_pairs]
    t_in2 = sympy.Symbol("theta_in")
    closing = sympy.Eq(t_in2, om[link[xi]] - om[link[yi]])
    gain = _solve_ratio(circuit + [closing], [om[g] for g in unit.gears],
                        (om[link[zo]] - om[link[wo]]) / t_in2)
    # the path products of the template, as products of its ratios
    from .unit_tree import unit_speeds

    c = unit_speeds(unit, "symbolic")
    E = {}
    for sym in general.free_symbols:
        _, a, b = sym.name.split("_")
        E[sym] = sympy.cancel(c[link[b]] / c[link[a]])
    return RuleDerivation(n, name, template, link, tuple(eqs), general, tuple(circuit + [closing]), gain, E)


@dataclass(frozen=True)
class RuleMatch:
    """Which rule a local output/input of a unit follows: ``rule``, the ``roles`` of the links
    (x, y, k, r, p, q), ``sign`` and ``inverse`` (the gain is ``sign * rule`` or
    ``sign / rule`` when the input and output play the rule's roles the other way round), and
    the ``formula`` in path products ``E_a_b`` named by the unit's links."""

    rule: int
    roles: dict
    sign: int
    inverse: bool
    formula: sympy.Expr
    unit: KinematicUnit = field(repr=False)

    @property
    def expression(self):
        """The formula with each path product written in the unit's ratio symbols."""
        from .unit_tree import unit_speeds

        c = unit_speeds(self.unit, "symbolic")
        subs = {}
        for s in self.formula.free_symbols:
            _, a, b = s.name.split("_", 2)
            la, lb = _find(self.unit, a), _find(self.unit, b)
            subs[s] = c[lb] / c[la]
        return sympy.factor(sympy.cancel(self.formula.subs(subs)))

    def __str__(self) -> str:
        roles = ", ".join(f"{k}={v}" for k, v in self.roles.items())
        how = " (inverted)" if self.inverse else ""
        return f"Rule {self.rule}{how}: {roles}; gain {self.formula}"


def _find(unit, text):
    for x in unit.links:
        if str(x) == text:
            return x
    raise KeyError(text)


def _rule_formula(n, roles):
    general = derive_rule(n).general
    return general.subs({s: _E(roles[s.name.split("_")[1]], roles[s.name.split("_")[2]])
                         for s in general.free_symbols})


def match_rule(unit: KinematicUnit, output, input) -> RuleMatch | None:
    """The rule that the local gain ``theta_output / theta_input`` of *unit* follows, or None.

    Pairs are ``(u, v)`` for ``theta_{u,v}``; both must be coaxial links of the unit.

    >>> import gearlib as gl
    >>> ku2 = gl.kinematic_units(gl.catalog.load("liu_chen_transmission")).unit(2)
    >>> print(gl.match_rule(ku2, (8, 1), (2, 5)))          # the 6-link unit, eq. (25)
    Rule 3: x=8, y=1, r=2, k=5; gain E_2_1*(E_1_8 - 1)
    """
    from .unit_tree import _pair

    z, w = _pair(unit, output, "output")
    a, b = _pair(unit, input, "input")
    k = unit.carrier
    out_gc, in_gc = k in (z, w), k in (a, b)
    sign = 1

    def gear_first(u, v):
        nonlocal sign
        if u == k:
            sign = -sign
            return v, u
        return u, v

    if out_gc and in_gc:
        (y, _), (x, _) = gear_first(z, w), gear_first(a, b)
        roles, n, inverse = {"x": x, "y": y, "k": k}, 1, False
    elif out_gc != in_gc:
        inverse = out_gc  # the rule's output is the g-g pair
        (x, y), (r, _) = ((a, b), gear_first(z, w)) if inverse else ((z, w), gear_first(a, b))
        if r == x:
            x, y = y, x
            sign = -sign
        if r == y:
            roles, n = {"x": x, "y": y, "k": k}, 2
        else:
            roles, n = {"x": x, "y": y, "r": r, "k": k}, 3
    else:
        inverse = False
        common = {z, w} & {a, b}
        if common:
            (p,) = common
            if z == p:
                z, w, sign = w, z, -sign
            if a == p:
                a, b, sign = b, a, -sign
            roles, n = {"x": z, "y": a, "p": p, "k": k}, 5
        else:
            roles, n = {"x": z, "q": w, "y": a, "p": b, "k": k}, 4
    formula = _rule_formula(n, roles)
    formula = sign * (1 / formula if inverse else formula)
    return RuleMatch(n, roles, sign, inverse, sympy.factor(formula), unit)
