"""The global relation between inputs and output, found unit by unit (Liu, Chen and Chang, Sec. 4).

:func:`propagate` evaluates a propagation plan (:func:`gearlib.plan`): the output as a sum over
propagation paths of products of local gains (eq. (16)), in exact numbers, in the gear-ratio
symbols ``e_a_b``, or in local-gain symbols. With exact fractions it runs in time linear in
the number of gear pairs. Derived in chapter 3.

>>> import gearlib as gl
>>> prop = gl.propagate(gl.catalog.load("liu_chen_fig1"), output=3, inputs=[4], ground=5)
>>> prop.expression()                         # eq. (17)
G1(1,5;4,5)*G2(3,5;1,5)*theta_4,5
>>> prop.symbolic()[(4, 5)]                   # eq. (21)
-e_4_1/(e_2_1*e_5_2 - 1)
>>> prop.ratio
Fraction(-1, 6)
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import sympy

from ._evaluate import Evaluator, RatioRing, solve_tears
from .._common.nogc import no_gc
from .._common.parse import to_fraction
from ..errors import InputError
from ..mechanism.data import Mechanism
from .propagation import Plan, plan, theta
from ..mechanism._accept import takes_mechanism

__all__ = ["Propagation", "propagate", "unit_ratio", "METHODS"]

METHODS = ("exact", "symbolic", "gains")


@dataclass(frozen=True, eq=False)
class Propagation:
    """The global relation ``theta_out = sum_k coefficient_k * theta_in_k`` found unit by unit.

    Use :meth:`relation` (``method="exact"``, ``"symbolic"`` or ``"gains"``), :attr:`ratio`
    for one input, :meth:`expression` for the relation in local-gain symbols (the paper's
    eq. (16)), :attr:`paths` for the propagation paths, :meth:`plot` for a drawing.
    """

    plan: Plan

    @property
    def output(self) -> tuple:
        return self.plan.output

    @property
    def inputs(self) -> tuple:
        return self.plan.inputs

    @cached_property
    def _exact(self):
        return self._run("exact")

    @no_gc
    def _run(self, method):
        p = self.plan
        field = _ratio_field(p.mechanism) if method == "symbolic" else None
        ev = Evaluator(p, method, field)
        out = ev.theta(*p.output)
        rows = ev.equations() if (p.equations or p.n_tears) else []
        sym = method != "exact"
        if sym:
            sol, _ = solve_tears(rows, p.n_tears, len(p.inputs), True, p.mechanism, p, self._exact[2], field)
        else:
            sol, piv = solve_tears(rows, p.n_tears, len(p.inputs), False, p.mechanism, p)
        zero = field.zero if field is not None else sympy.Integer(0) if sym else 0
        coef = {k: out.get(("in", k), zero) for k in range(len(p.inputs))}
        for j, expr in sol.items():
            t = out.get(("t", j), zero)
            for k in range(len(p.inputs)):
                coef[k] = coef[k] + t * expr[("in", k)]
        result = {p.inputs[k]: coef[k] for k in range(len(p.inputs))}
        if field is not None:
            result = {k: _factored(field, v) for k, v in result.items()}
        elif method == "symbolic":
            result = {k: sympy.factor(sympy.cancel(v)) for k, v in result.items()}
        if sym:
            return result, ev.gains, None
        return result, ev.gains, piv

    @cached_property
    def _symbolic(self):
        res, _, _ = self._run("symbolic")
        return res

    @cached_property
    def _gains(self):
        res, gains, _ = self._run("gains")
        return {k: sympy.factor(sympy.cancel(v)) if v.free_symbols else v for k, v in res.items()}, gains

    def relation(self, method: str = "exact") -> dict:
        """``{input pair: coefficient}``, exact, in ``e_a_b`` symbols, or in local-gain symbols."""
        if method == "exact":
            res = self._exact[0]
            return {k: (v if not isinstance(v, sympy.Basic) else _simplify_number(v)) for k, v in res.items()}
        if method == "symbolic":
            return dict(self._symbolic)
        if method == "gains":
            return dict(self._gains[0])
        raise InputError(f"method must be one of {', '.join(METHODS)}, got {method!r}")

    def symbolic(self) -> dict:
        """The relation in the gear-ratio symbols ``e_a_b``."""
        return self.relation("symbolic")

    @property
    def ratio(self):
        """The exact ratio ``theta_out / theta_in`` (one input only)."""
        if len(self.inputs) != 1:
            raise InputError(f"ratio needs one input; this propagation has {len(self.inputs)}: use relation()")
        return next(iter(self.relation().values()))

    @property
    def steps(self) -> tuple:
        """The plan's steps that the relation uses (units with a local gain, and tears)."""
        used = {g.unit.index for g in self.gains}
        return tuple(s for s in self.plan.steps if s.unit.index in used or s.source == "tear")

    @property
    def gains(self) -> tuple:
        """The local gains the relation uses."""
        return tuple(self._gains[1].values())

    def expression(self):
        """theta_out as a sympy expression in local-gain symbols and input symbols (eq. (16))."""
        rel = self.relation("gains")
        return sum((v * sympy.Symbol(theta(*k)) for k, v in rel.items()), sympy.Integer(0))

    def substitutions(self, method: str = "symbolic") -> dict:
        """``{gain symbol: value}`` to turn :meth:`expression` into the ratio symbols (or numbers)."""
        return {g.symbol: (g.expression if method == "symbolic" else g.value) for g in self.gains}

    @property
    def paths(self) -> tuple:
        """Propagation paths: ``(input pair, sign-and-constant, (LocalGain, ...))`` for each term of
        the numerator of each coefficient in local-gain symbols."""
        rel, gains = self._gains
        out = []
        for k, v in rel.items():
            num, _ = sympy.fraction(sympy.together(v))
            for term in sympy.Add.make_args(sympy.expand(num)):
                coeff, factors = term.as_coeff_mul()
                chain = []
                for f in factors:
                    base, exp = f.as_base_exp()
                    chain += [gains[base]] * int(exp) if base in gains else []
                out.append((k, coeff, tuple(chain)))
        return tuple(out)

    def reference(self, method: str = "nullspace") -> dict:
        """The same coefficients from :func:`gearlib.speeds` (an independent check)."""
        from ..mechanism.kinematics import speeds

        p = self.plan
        out = {}
        for k, pair in enumerate(p.inputs):
            values = {q: (1 if i == k else 0) for i, q in enumerate(p.inputs)}
            sol = speeds(p.mechanism, p.ground, values, method=method, held=p.held, joined=p.joined)
            out[pair] = sol.relative(*p.output)
        return out

    def plot(self, ax=None, **kwargs):
        """Draw the propagation (:func:`gearlib.gains.draw_propagation`)."""
        from .drawing import draw_propagation

        return draw_propagation(self, ax=ax, **kwargs)

    def __str__(self) -> str:
        lines = [str(s) for s in self.steps]
        rhs = self.expression()
        lines.append(f"{theta(*self.output)} = {rhs}")
        return "\n".join(lines)


def _ratio_field(mech: Mechanism):
    """Unreduced fractions over the integer polynomial ring of the gear-ratio symbols ``e_a_b``
    (or of the symbols in a ratio given as an expression); None when that ring cannot hold them."""
    from sympy.polys.rings import ring

    exprs = [gp.symbol if not gp.e.free_symbols else gp.e for gp in mech.gear_pairs]
    symbols = sorted(set().union(*(e.free_symbols for e in exprs)), key=str)
    if not symbols:
        return None
    R = ring(symbols, sympy.ZZ)[0]
    field = RatioRing(R)
    try:
        for e in exprs:
            field.from_sympy(e)
    except (ValueError, TypeError, sympy.polys.polyerrors.PolynomialError):
        return None  # irrational or transcendental ratios: use sympy expressions
    return field


def _factored(field, v):
    """A ratio as sympy's ``factor`` prints it: numerator and denominator factored in the
    polynomial ring (multilinear ones quickly, :mod:`gearlib._common.multilinear`), common factors
    cancelled, so no separate gcd is needed."""
    from collections import Counter

    from .._common.multilinear import factor_list

    if not v:
        return sympy.Integer(0)
    (cn, fn), (cd, fd) = factor_list(v.num), factor_list(v.den)
    count: Counter = Counter()
    for f, k in fn:
        count[f] += k
    for f, k in fd:
        count[f] -= k
    out = sympy.Rational(int(cn), int(cd))
    for f, k in count.items():
        if k:
            out *= f.as_expr() ** k
    return out


def _simplify_number(v):
    v = sympy.nsimplify(sympy.simplify(v)) if not v.free_symbols else sympy.factor(sympy.cancel(v))
    f = to_fraction(v)
    return f if f is not None else v


@takes_mechanism
def propagate(mech: Mechanism, output, inputs=None, *, ground=None, held=(), joined=()) -> Propagation:
    """The global relation from inputs to output, unit by unit (Liu, Chen and Chang, Sec. 4).

    Parameters
    ----------
    mech : Mechanism
    output : link or pair ``(u, v)`` / ``"u/v"`` (relative to the ground by default)
    inputs : links or pairs (default: ``mech.inputs``), one per degree of freedom
    ground : link held fixed (default ``mech.ground``)
    held, joined : brakes and clutches

    Raises
    ------
    InputError
        When the inputs do not match the degrees of freedom (with the same message as
        :func:`gearlib.speeds`), or a link turns freely.
    """
    if inputs is None:
        inputs = mech.inputs
    p = plan(mech, ground, inputs, output, held=held, joined=joined)
    prop = Propagation(p)
    _ = prop._exact  # validate now: wrong input counts raise here
    return prop


@takes_mechanism
def unit_ratio(mech: Mechanism, output, input, *, ground=None, held=(), joined=(), method: str = "exact"):
    """``theta_out / theta_in`` of a one-dof mechanism by unit-by-unit propagation: the same
    answer as :func:`gearlib.ratio`, found without solving the whole linear system.

    Linear in the number of gear pairs with exact fractions:

    >>> import gearlib as gl
    >>> gl.unit_ratio(gl.serial_train(200), output=201, input=1, ground=0) == gl.ratio(
    ...     gl.serial_train(200), output=201, input=1, ground=0)
    True
    """
    prop = propagate(mech, output, [input], ground=ground, held=held, joined=joined)
    if method == "exact":
        return prop.ratio
    return next(iter(prop.relation(method).values()))
