"""Fast simplification of rational functions by factoring numerator and denominator.

``sympy.cancel`` on a quotient of two large expanded polynomials in many symbols is slow
(a multivariate gcd). Davies' formulas are products of small factors, so factoring the
numerator and the denominator separately and cancelling common factors is much faster.
"""

from __future__ import annotations

from collections import Counter

import sympy

__all__ = ["factored", "substitute"]


def _factors(poly_expr):
    const, facs = sympy.factor_list(sympy.expand(poly_expr))
    return const, facs


def factored(expr) -> sympy.Expr:
    """*expr* as a product of irreducible factors with common factors cancelled."""
    expr = sympy.sympify(expr)
    if not expr.free_symbols:
        return sympy.nsimplify(expr, rational=True) if expr.is_Float else sympy.simplify(expr) if expr.has(sympy.sqrt) else expr
    num, den = sympy.fraction(sympy.together(expr))
    cn, fn = _factors(num)
    cd, fd = _factors(den)
    counts: Counter = Counter()
    for f, k in fn:
        counts[f] += k
    for f, k in fd:
        if -f in counts and f not in counts:
            counts[-f] -= k
            cn = -cn
        else:
            counts[f] -= k
    out = sympy.Rational(1) * cn / cd
    for f, k in counts.items():
        if k:
            out *= f ** k
    return out


def substitute(expr, subs: dict) -> sympy.Expr:
    """``expr.subs(subs)`` simplified factor by factor (each factor of *expr* separately)."""
    expr = factored(expr)
    parts = sympy.Mul.make_args(expr)
    out = sympy.Integer(1)
    for p in parts:
        base, exp = p.as_base_exp()
        if base.free_symbols & set(subs):
            out *= factored(base.subs(subs)) ** exp
        else:
            out *= p
    return sympy.factor(factored(out))  # factor() keeps a constant outside the sums
