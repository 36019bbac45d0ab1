"""Evaluation of a propagation plan: speeds as linear combinations of inputs and tears.

Private helpers of :mod:`gearlib.gains.relation`. A link's speed (relative to the ground) is a dict
``{("in", k): coefficient, ("t", j): coefficient}`` over the inputs and the tears; a step's
signal is its local input. Quantities are computed lazily, only those the output and the
consistency equations need, in the plan's order (no recursion: linear in the plan's length).
"""

from __future__ import annotations

import sympy

from ..errors import ConstraintError, InputError
from .local import LocalGain, _gain_symbol
from .unit_tree import _tree
from .propagation import Plan

class Evaluator:
    """Evaluates a plan's quantities lazily, as linear combinations of inputs and tears."""

    def __init__(self, p: Plan, method: str, field=None):
        """*field*: for ``method="symbolic"``, a sympy fraction field holding the gear ratios;
        the arithmetic then runs on its elements (reduced fractions of polynomials), which is
        far faster than on sympy expressions."""
        self.plan, self.method, self.field = p, method, field
        self.gains: dict = {}
        self.memo: dict = {}
        self._converted: dict = {}
        sym = method != "exact"
        if field is not None:
            self.zero, self.one = field.zero, field.one
        else:
            self.zero = sympy.Integer(0) if sym else 0
            self.one = sympy.Integer(1) if sym else 1

    def _speed(self, unit, link):
        c = _tree(unit).speed(link, self.method)
        if self.field is None:
            return c
        key = (unit.index, link)
        if key not in self._converted:
            self._converted[key] = self.field.from_sympy(c)
        return self._converted[key]

    def gain(self, unit, z, w, x, y):
        if z == w:
            return self.zero
        if (z, w) == (x, y):
            return self.one
        if (z, w) == (y, x):
            return -self.one
        if self.method == "gains":
            s = _gain_symbol(unit, z, w, x, y)
            self.gains.setdefault(s, LocalGain(unit, (z, w), (x, y), s))
            return s
        c = self._speed
        den = c(unit, x) - c(unit, y)
        if den == 0:
            raise ConstraintError(f"in {unit.name} links {x} and {y} always turn together; choose other inputs")
        return (c(unit, z) - c(unit, w)) / den

    # node keys: ("pot", link) and ("sig", step index)
    def _deps(self, node):
        kind, ref = node
        p = self.plan
        if kind == "pot":
            how = p.known_by[ref]
            if how[0] == "edge":
                return [("pot", how[2])]
            if how[0] == "step":
                s = p.steps[how[1]]
                return [("pot", s.anchor), ("sig", s.index)]
            return []
        s = p.steps[ref]
        if s.source == "tear":
            return []
        if s.chain is not None:
            return [("sig", s.chain)]
        return [("pot", s.input[0]), ("pot", s.input[1])]

    def _order(self, node):
        kind, ref = node
        return self.plan.order[ref] if kind == "pot" else self.plan.steps[ref].order

    def need(self, nodes):
        todo, seen = list(nodes), set()
        while todo:
            n = todo.pop()
            if n in seen or n in self.memo:
                continue
            seen.add(n)
            todo.extend(self._deps(n))
        for n in sorted(seen, key=self._order):
            self.memo[n] = self._compute(n)

    def value(self, node):
        if node not in self.memo:
            self.need([node])
        return self.memo[node]

    def _compute(self, node):
        kind, ref = node
        p = self.plan
        if kind == "pot":
            how = p.known_by[ref]
            if how[0] in ("ground", "held"):
                return {}
            if how[0] == "tear":
                return {("t", how[1]): self.one}
            if how[0] == "edge":
                k, other, sign = how[1], how[2], how[3]
                base = dict(self.memo[("pot", other)])
                if k is not None:
                    _acc(base, ("in", k), self.one if sign > 0 else -self.one)
                return base
            s = p.steps[how[1]]
            return self.relative(s, ref, s.anchor, base=self.memo[("pot", s.anchor)])
        s = p.steps[ref]
        if s.source == "tear":
            return {("t", s.tear): self.one}
        if s.chain is not None:
            c = p.steps[s.chain]
            return _scale(self.memo[("sig", c.index)], self.gain(c.unit, *s.input, *c.input))
        x, w = s.input
        return _sub(self.memo[("pot", x)], self.memo[("pot", w)])

    def relative(self, s, z, w, base=None):
        """theta_{z,w} through step s's unit, plus *base*."""
        out = dict(base or {})
        for key, v in self.memo[("sig", s.index)].items():
            _acc(out, key, v * self.gain(s.unit, z, w, *s.input))
        return out

    def theta(self, o, r):
        """The combination for theta_{o,r}."""
        p = self.plan
        for s in p.steps:
            if o in s.unit and r in s.unit:
                self.need([("sig", s.index)])
                return self.relative(s, o, r)
        self.need([("pot", o), ("pot", r)])
        return _sub(self.memo[("pot", o)], self.memo[("pot", r)])

    def equations(self):
        p = self.plan
        rows = []
        for eq in p.equations:
            if eq[0] == "check":
                s, z = p.steps[eq[1]], eq[2]
                self.need([("pot", z), ("pot", s.anchor), ("sig", s.index)])
                rows.append(_sub(self.memo[("pot", z)], self.relative(s, z, s.anchor, self.memo[("pot", s.anchor)])))
            else:
                e = eq[1]
                k, u, v = _edge(p, e)
                self.need([("pot", u), ("pot", v)])
                row = _sub(self.memo[("pot", u)], self.memo[("pot", v)])
                if k is not None:
                    _acc(row, ("in", k), -self.one)
                rows.append(row)
        return rows


def _edge(p: Plan, e):
    ins = list(p.inputs)
    if e < len(ins):
        return (e, *ins[e])
    u, v = p.joined[e - len(ins)]
    return (None, u, v)


def _acc(d, key, v):
    d[key] = d.get(key, 0) + v


def _scale(d, g):
    return {k: v * g for k, v in d.items()}


def _sub(a, b):
    out = dict(a)
    for k, v in b.items():
        _acc(out, k, -v)
    return out


def _is_zero(v) -> bool:
    if isinstance(v, sympy.Basic):
        return sympy.simplify(v) == 0
    return v == 0


def solve_tears(rows, n_tears, n_inputs, symbolic, mech, plan_: Plan, pivots=None, field=None):
    """Solve the consistency equations for the tears: ``{j: {("in", k): coef}}``."""
    zero = sympy.Integer(0) if symbolic else 0
    A = [[r.get(("t", j), zero) for j in range(n_tears)] for r in rows]
    B = [[r.get(("in", k), zero) for k in range(n_inputs)] for r in rows]
    if symbolic:
        if pivots is None:
            raise ValueError("symbolic solve needs pivot rows from the exact solve")
        rows_used = pivots
        if not n_tears:
            return {}, pivots
        if field is not None:  # Gauss-Jordan on the exact solve's pivot rows, in the field
            m = [[field.convert(v) for v in A[i] + B[i]] for i in rows_used]
            for j in range(n_tears):
                r = next(i for i in range(j, n_tears) if m[i][j])
                m[j], m[r] = m[r], m[j]
                inv = 1 / m[j][j]
                m[j] = [v * inv for v in m[j]]
                for i in range(n_tears):
                    if i != j and m[i][j]:
                        f = m[i][j]
                        m[i] = [a - f * b for a, b in zip(m[i], m[j])]
            return {j: {("in", k): -m[j][n_tears + k] for k in range(n_inputs)} for j in range(n_tears)}, pivots
        Am = sympy.Matrix([A[i] for i in rows_used])
        Bm = sympy.Matrix([B[i] for i in rows_used])
        T = Am.LUsolve(-Bm)
        return {j: {("in", k): sympy.cancel(T[j, k]) for k in range(n_inputs)} for j in range(n_tears)}, pivots
    # exact elimination, recording pivot rows
    m = [a + b for a, b in zip(A, B)]
    used, piv_rows, where = set(), [], {}
    for j in range(n_tears):
        r = next((i for i in range(len(m)) if i not in used and not _is_zero(m[i][j])), None)
        if r is None:
            raise InputError(count_message(mech, plan_, "needs more inputs"))
        used.add(r)
        piv_rows.append(r)
        where[j] = r
        inv = 1 / m[r][j]
        m[r] = [v * inv for v in m[r]]
        for i in range(len(m)):
            if i != r and not _is_zero(m[i][j]):
                f = m[i][j]
                m[i] = [a - f * b for a, b in zip(m[i], m[r])]
    for i in range(len(m)):
        if i not in used and any(not _is_zero(v) for v in m[i][n_tears:]):
            raise InputError(count_message(mech, plan_, "inputs not independent"))
    sol = {j: {("in", k): -m[where[j]][n_tears + k] for k in range(n_inputs)} for j in range(n_tears)}
    return sol, sorted(piv_rows)


def count_message(mech, p: Plan, why) -> str:
    """The solvers' messages: a wrong number of inputs, or inputs that are not independent."""
    from ..mechanism.mobility import dof

    n = int(dof(mech, p.ground, held=p.held, joined=p.joined))
    names = ", ".join(f"{u}/{v}" for u, v in p.inputs) or "none"
    if len(p.inputs) == n:
        return (f"inputs {names} of {mech.name!r} are not independent: together they fix fewer than {n} "
                "freedoms. Choose other input links")
    return (f"{mech.name!r} has {n} degree{'s' if n != 1 else ''} of freedom with link {p.ground} grounded, so it "
            f"needs {n} input{'s' if n != 1 else ''}; got {len(p.inputs)} ({names})")


class _Ratio:
    """``num / den`` over a sympy polynomial ring, kept unreduced (no gcd per operation).

    Propagation multiplies and adds a handful of small local gains; reducing after every
    operation (as a fraction field does) costs most of the time. Equal denominators are
    added without growth, and :meth:`reduced` cancels once at the end.
    """

    __slots__ = ("num", "den")

    def __init__(self, num, den):
        self.num, self.den = num, den

    def _lift(self, other):
        if isinstance(other, _Ratio):
            return other
        ring = self.num.ring
        return _Ratio(ring(other), ring.one)

    def __add__(self, other):
        o = self._lift(other)
        if self.den == o.den:
            return _Ratio(self.num + o.num, self.den)
        return _Ratio(self.num * o.den + o.num * self.den, self.den * o.den)

    __radd__ = __add__

    def __neg__(self):
        return _Ratio(-self.num, self.den)

    def __sub__(self, other):
        return self + (-self._lift(other))

    def __rsub__(self, other):
        return self._lift(other) - self

    def __mul__(self, other):
        o = self._lift(other)
        return _Ratio(self.num * o.num, self.den * o.den)

    __rmul__ = __mul__

    def __truediv__(self, other):
        o = self._lift(other)
        if not o.num:
            raise ZeroDivisionError("division by a zero ratio")
        return _Ratio(self.num * o.den, self.den * o.num)

    def __rtruediv__(self, other):
        return self._lift(other) / self

    def __bool__(self):
        return bool(self.num)

    def __eq__(self, other):
        o = self._lift(other)
        return self.num * o.den == o.num * self.den

    __hash__ = None

    def reduced(self):
        """``(numerator, denominator)`` without common factors, the denominator's leading
        coefficient positive."""
        num, den = self.num.cancel(self.den)
        return num, den


class RatioRing:
    """Factory of :class:`_Ratio` values over the polynomial ring of a mechanism's gear ratios."""

    def __init__(self, ring):
        self.ring = ring
        self.zero = _Ratio(ring.zero, ring.one)
        self.one = _Ratio(ring.one, ring.one)

    def from_sympy(self, expr):
        num, den = sympy.sympify(expr).as_numer_denom()
        return _Ratio(self.ring.from_expr(num), self.ring.from_expr(den))

    def convert(self, value):
        if isinstance(value, _Ratio):
            return value
        if isinstance(value, sympy.Basic):
            return self.from_sympy(value)
        return _Ratio(self.ring(value), self.ring.one)
