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


def rings(symbols):
    """The rational and the integer polynomial rings of *symbols*, in sympy's own order of
    generators (it fixes the signs of the factors as :func:`sympy.factor` prints them)."""
    from sympy.polys.polyutils import _sort_gens
    from sympy.polys.rings import ring

    order = _sort_gens(list(symbols))
    return ring(order, sympy.QQ)[0], ring(order, sympy.ZZ)[0]


def ring_factor_list(p, Z):
    """``(constant, [(factor over ZZ, multiplicity)])`` of a polynomial *p* over QQ, with
    :func:`gearlib._common.multilinear.factor_list` in *Z*, its ring over the integers."""
    from .._common.multilinear import factor_list

    den, p = p.clear_denoms()  # p * den has integer coefficients
    const, facs = factor_list(p.set_ring(Z))
    return sympy.Rational(int(const)) / sympy.Rational(den), facs


def _ring_factors(expr):
    """``((cn, fn), (cd, fd))`` as :func:`sympy.factor_list` gives them for the numerator and
    the denominator of *expr*, computed in the integer polynomial ring of its symbols (in
    the order sympy gives them) with :func:`gearlib._common.multilinear.factor_list`; None when
    *expr* is not a rational function with rational coefficients."""
    from sympy.polys.polytools import _sorted_factors

    if not expr.free_symbols or any(not s.is_Symbol for s in expr.free_symbols):
        return None
    R, Z = rings(expr.free_symbols)
    try:
        num, den = (R.from_expr(part) for part in expr.as_numer_denom())
    except (ValueError, TypeError, sympy.polys.polyerrors.PolynomialError, sympy.polys.polyerrors.CoercionFailed):
        return None
    if not den:
        return None
    symbols = R.symbols
    out = []
    for p in (num, den):
        const, facs = ring_factor_list(p, Z)
        # sympy's order of the factors (it decides which sum absorbs the constant when printed)
        used = [x for i, x in enumerate(symbols) if any(m[i] for m in p.itermonoms())] or list(symbols[:1])
        polys = [(sympy.Poly(f.as_expr(), *used, domain=sympy.ZZ), k) for f, k in facs]
        out.append((const, [(f.as_expr(), k) for f, k in _sorted_factors(polys, "factor")]))
    return out


def factored(expr) -> sympy.Expr:
    """*expr* as a product of irreducible factors with common factors cancelled."""
    expr = sympy.sympify(expr)
    if not expr.free_symbols:
        return sympy.nsimplify(expr, rational=True) if expr.is_Float else sympy.simplify(expr) if expr.has(sympy.sqrt) else expr
    fast = _ring_factors(expr)
    if fast is not None:
        (cn, fn), (cd, fd) = fast
    else:
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
