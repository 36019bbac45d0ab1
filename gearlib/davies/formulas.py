"""Turning conditions, every efficiency formula of a train, and Laus's validation rule.

The formula for a train's efficiency depends on which gear drives in each mesh (relative to
its carrier) and on which port is the input. With the pitch radii as symbols the lossless
virtual power flow of each mesh is a rational function of the radii; the factors of it that
can change sign are the mesh's **turning condition** (Laus 2011, section 3.4.1.4). Factors
known to be positive are dropped: radii, sums of positive terms, the difference of radii of
an internal pair, and any radius a loop of centre distances expresses through the others.

:func:`efficiency_formulas` writes one formula per sign pattern of the turning conditions
and per choice of input, like Laus's Table 5; :func:`derivative_check` applies the rule
``d eta / d eta_ij > 0`` (section 3.6.2), which exposes a formula written for the wrong
flow directions but, as Laus notes, not one with input and output exchanged.

>>> import gearlib as gl
>>> m = gl.catalog.load("laus_epicyclic")
>>> [str(tc.expression) for tc in gl.davies.turning_conditions(m, ground=1, input=5, output=2)]
['r1 - r2', 'r1 - r2']
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import sympy

from ..errors import InputError
from . import _rational
from .geometry import layout as make_layout
from .motion import motions as solve_motions
from .coupling_network import network as make_network
from .overall import efficiency
from .power import mesh_flows
from .statics import actions as solve_actions
from ..mechanism._accept import takes_mechanism

__all__ = ["TurningCondition", "turning_conditions", "FormulaCase", "efficiency_formulas", "derivative_check",
           "by_gears"]


def by_gears(expr, gears: dict):
    """*expr* with its ordinary efficiencies named by gears instead of links.

    The library names the efficiency of a mesh by the links that carry its gears: ``eta_3_2``
    is the mesh of links 3 and 2 with link 3 driving. When a link carries two gears (a
    compound planet) a book or a paper names them apart. *gears* maps a mesh's links
    ``(a, b)`` to the names of its gears ``(g_a, g_b)``; ``eta_a_b`` becomes ``eta_<g_a><g_b>``
    and ``eta_b_a`` becomes ``eta_<g_b><g_a>`` (both ways round). Meshes not listed keep
    their names.

    >>> import sympy
    >>> e = sympy.Symbol("eta_3_2", positive=True) * sympy.Symbol("eta_1_3", positive=True)
    >>> by_gears(e, {(2, 3): (2, 4), (1, 3): (1, 3)})    # link 3 carries gears 3 and 4
    eta_13*eta_42
    """
    subs = {}
    for (a, b), (ga, gb) in gears.items():
        for (x, y), (gx, gy) in (((a, b), (ga, gb)), ((b, a), (gb, ga))):
            subs[sympy.Symbol(f"eta_{x}_{y}", positive=True)] = sympy.Symbol(f"eta_{gx}{gy}", positive=True)
    return sympy.sympify(expr).xreplace(subs)


@dataclass(frozen=True)
class TurningCondition:
    """The turning condition of one mesh.

    ``flow`` is the lossless carrier-relative power flow per unit input power (positive: the
    tail gear drives); ``expression`` the product of its factors that can change sign (None
    when the driver never changes); ``sign`` the sign of the rest, so that the tail gear
    drives exactly when ``sign * expression > 0``."""

    coupling: str
    gears: tuple
    carrier: object
    flow: object
    expression: object
    sign: int

    def tail_drives(self, values: dict) -> bool:
        if self.expression is None:
            return self.sign > 0
        return self.sign * float(self.expression.subs(values)) > 0


def _facts(net) -> list:
    """Expressions known to be positive for this layout."""
    lay = net.layout
    facts = list(lay.relations.values())
    for m in lay.meshes:
        if m.kind == "spur" and net.mechanism.gear_pairs[m.index].kind == "internal":
            ra, rb = m.radii
            facts.append(ra - rb if float(sympy.sympify(ra - rb).subs(lay.values)) > 0 else rb - ra)
    return [sympy.expand(f) for f in facts]


def _split(expr, facts, values):
    """``(sign, product of sign-changing factors or None)`` for a rational function."""
    expr = _rational.factored(expr)
    sign, changing = 1, []
    for part in sympy.Mul.make_args(expr):
        base, exp = part.as_base_exp()
        if base.is_number:
            sign *= 1 if float(part) > 0 else -1
            continue
        b = sympy.expand(base)
        if b.is_positive:
            continue
        if b.is_negative:
            sign *= (-1) ** int(exp)
            continue
        if any(sympy.expand(b - f) == 0 for f in facts):
            continue
        if any(sympy.expand(b + f) == 0 for f in facts):
            sign *= (-1) ** int(exp)
            continue
        if int(exp) % 2:
            changing.append(base)
    if not changing:
        return sign, None
    return sign, sympy.Mul(*changing)


@takes_mechanism
def turning_conditions(mech, ground=None, input=None, output=None, *, radii="symbols", held=(), **options) -> tuple:
    """The turning condition of every mesh (:class:`TurningCondition`), with the pitch radii as
    symbols (``radii="symbols"`` or a mapping as in :func:`gearlib.davies.layout`)."""
    net = make_network(mech, ground, input, output, held=held, radii=radii, **options)
    mo = solve_motions(net)
    act = solve_actions(net)
    facts = _facts(net)
    out = []
    for f in mesh_flows(mo, act):
        flow = _rational.factored(f.tail_power)
        sign, expr = _split(flow, facts, net.layout.values)
        out.append(TurningCondition(f.coupling, f.gears, f.carrier, flow, expr, sign))
    return tuple(out)


@dataclass(frozen=True)
class FormulaCase:
    """One row of a formula table: input and output, the sign of each turning-condition
    expression, the driver of each mesh, the formula, and whether the data's radii fall in it."""

    input: object
    output: object
    conditions: tuple
    drivers: dict
    formula: object
    applies: bool


@takes_mechanism
def efficiency_formulas(mech, ground=None, input=None, output=None, *, radii="symbols", both_ways: bool = True,
                        eta=None, held=(), **options) -> tuple:
    """Every efficiency formula of the train (Laus's Table 5): for each input/output choice and
    each sign pattern of the distinct turning-condition expressions."""
    ground = mech.resolve(mech.ground if ground is None else ground)
    ports = [(mech.resolve(input), mech.resolve(output))]
    if both_ways:
        ports.append(ports[0][::-1])
    rows = []
    lay = make_layout(mech.replace(ground=ground) if mech.ground != ground else mech, radii=radii)
    values = lay.values
    for inp, out in ports:
        tcs = turning_conditions(mech, ground, inp, out, radii=radii, held=held, **options)
        exprs = []
        for tc in tcs:
            if tc.expression is not None and all(sympy.expand(tc.expression - e) != 0 and
                                                  sympy.expand(tc.expression + e) != 0 for e in exprs):
                exprs.append(tc.expression)
        for signs in itertools.product((1, -1), repeat=len(exprs)):
            drivers = {}
            for tc in tcs:
                if tc.expression is None:
                    s = tc.sign
                else:
                    k = next(i for i, e in enumerate(exprs) if sympy.expand(tc.expression - e) == 0
                             or sympy.expand(tc.expression + e) == 0)
                    same = sympy.expand(tc.expression - exprs[k]) == 0
                    s = tc.sign * signs[k] * (1 if same else -1)
                drivers[tc.gears] = tc.gears[0] if s > 0 else tc.gears[1]
            res = efficiency(mech, ground, inp, out, symbolic=True, radii=radii, held=held, drivers=drivers,
                             eta=eta, **options)
            applies = all((float(e.subs(values)) > 0) == (s > 0) for e, s in zip(exprs, signs))
            conds = tuple((e, ">" if s > 0 else "<") for e, s in zip(exprs, signs))
            rows.append(FormulaCase(inp, out, conds, drivers, res.formula if res.formula is not None else res.value,
                                    applies))
    return tuple(rows)


def derivative_check(formula, at=0.98, values=None) -> dict:
    """``{eta_ij: d eta / d eta_ij}`` at every ordinary efficiency equal to *at* (a number, or
    ``{symbol: value}``) and the radii in *values*; Laus's rule wants every one positive."""
    formula = sympy.sympify(formula)
    etas = sorted((s for s in formula.free_symbols if str(s).startswith("eta")), key=str)
    if not etas:
        raise InputError("the formula has no ordinary efficiencies eta_i_j")
    point = dict(values or {})
    for s in etas:
        point[s] = at[s] if isinstance(at, dict) else at
    return {s: float(sympy.diff(formula, s).subs(point)) for s in etas}

