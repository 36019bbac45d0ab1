"""Davies' efficiency formula worked out in polynomial rings, without sympy expressions.

The lossy action analysis leaves every action as ``numerator / denominator`` over the
integer polynomials in the meshes' friction coefficients ``zeta`` (:class:`ExactSolution`).
The efficiency needs only the two port actions, and their common denominator cancels:

    eta = -P_out / P_in = -(s_out / s_in) * numerator_out / numerator_in

with ``s`` the port screws dotted with the (numeric) port motions. Both numerators are
multilinear in the ``zeta`` (each friction column meets one row), so they factor quickly
(:mod:`gearlib._common.multilinear`). Each ``zeta`` is then replaced by the Moebius function of its
ordinary efficiency that Laus's eqs. 72-75 give, ``zeta = a(eta) / b(eta)`` with ``a`` and
``b`` linear: a factor ``f`` of degree ``d_i`` in ``zeta_i`` becomes the polynomial
``sum_m c_m prod_i a_i^m_i b_i^(d_i - m_i)`` over ``prod_i b_i^d_i``, again multilinear, again
factored quickly. Only the final factors become sympy expressions.

:func:`formula` returns None whenever this does not apply (other symbols in the port
motions, coefficients outside the rationals); the caller then takes the general route.
"""

from __future__ import annotations

from collections import Counter

import sympy

from ._rational import ring_factor_list as _factor, rings as _rings
from ._solve import ExactSolution

__all__ = ["formula"]


def _product(const, counts) -> sympy.Expr:
    out = sympy.Rational(1) * const
    for f, k in counts.items():
        if k:
            out *= f.as_expr() ** k
    return out


def formula(values, k_out: int, k_in: int, coef, subs: dict):
    """``(formula in zeta, formula in eta)`` as sympy expressions, or None.

    *values*: the lossy actions; *k_out*, *k_in*: the positions of the port torques in them;
    *coef*: ``-s_out / s_in``; *subs*: ``{zeta symbol: zeta as a function of eta}``.
    """
    if not isinstance(values, ExactSolution):
        return None
    dom = values.domain
    coef = sympy.sympify(coef)
    if not (getattr(dom, "is_PolynomialRing", False) and (dom.domain.is_ZZ or dom.domain.is_QQ)
            and coef.is_Rational and coef != 0):
        return None
    symbols = list(dom.symbols)
    if not set(symbols) <= set(subs):
        return None
    Q, Z = _rings(symbols)
    n_out = values.numerators[k_out].set_ring(Q)  # set_ring reorders the generators
    n_in = values.numerators[k_in].set_ring(Q)
    if not n_in:
        return None
    cn, fn = _factor(n_out, Z)
    cd, fd = _factor(n_in, Z)
    counts: Counter = Counter()
    for f, k in fn:
        counts[f] += k
    for f, k in fd:
        counts[f] -= k
    const = coef * cn / cd
    in_zeta = _product(const, counts)

    # zeta_i = a_i / b_i, linear in the ordinary efficiencies
    parts = {}
    for s in Z.symbols:
        num, den = sympy.sympify(subs[s]).as_numer_denom()
        parts[s] = (num, den)
    eta_symbols = set().union(*(num.free_symbols | den.free_symbols for num, den in parts.values()))
    if not eta_symbols or eta_symbols & set(symbols):
        return None
    QE, ZE = _rings(eta_symbols)
    try:
        ab = [(QE.from_expr(num), QE.from_expr(den)) for num, den in (parts[s] for s in Z.symbols)]
    except (ValueError, TypeError, sympy.polys.polyerrors.PolynomialError, sympy.polys.polyerrors.CoercionFailed):
        return None
    powers: dict = {}

    def power(i, which, e):
        key = (i, which, e)
        if key not in powers:
            powers[key] = ab[i][which] ** e
        return powers[key]

    eta_counts: Counter = Counter()
    b_exponent = [0] * len(ab)
    const_eta = const
    for f, k in counts.items():
        if not k:
            continue
        degree = [max(m[i] for m in f.itermonoms()) for i in range(len(ab))]
        g = QE.zero
        for m, c in f.items():
            term = QE(QE.domain.convert_from(c, Z.domain))
            for i, (e, d) in enumerate(zip(m, degree)):
                if e:
                    term *= power(i, 0, e)
                if d - e:
                    term *= power(i, 1, d - e)
            g += term
        for i, d in enumerate(degree):
            b_exponent[i] += d * k
        if not g:
            return None
        c, facs = _factor(g, ZE)
        const_eta *= c ** k
        for h, j in facs:
            eta_counts[h] += j * k
    for i, e in enumerate(b_exponent):
        if e:
            c, facs = _factor(ab[i][1], ZE)
            const_eta /= c ** e
            for h, j in facs:
                eta_counts[h] -= j * e
    # as sympy.factor prints it: the constant kept outside the sums (its factors are these,
    # primitive and signed in the same generator order)
    from sympy.core.mul import _keep_coeff

    rest = sympy.Mul(*[f.as_expr() ** k for f, k in eta_counts.items() if k])
    return in_zeta, _keep_coeff(sympy.Rational(const_eta), rest)
