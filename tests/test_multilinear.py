"""The multilinear factoring behind fast symbolic ratios agrees with sympy's general
factorization (the oracle) on random products of multilinear polynomials, with monomial
factors, integer contents, signs, and some inputs that are not multilinear at all."""

import random

import pytest
from sympy import ZZ
from sympy.polys.rings import ring

import gearlib as gl
from gearlib._common.multilinear import factor_list

R, *X = ring("a b c d e f g h", ZZ)


def random_multilinear(rng, variables):
    p = R.zero
    for _ in range(rng.randint(1, 5)):
        term = R(rng.choice([-3, -2, -1, 1, 2, 5]))
        for v in variables:
            if rng.random() < 0.5:
                term *= v
        p += term
    return p


def random_case(rng):
    names = X[:]
    rng.shuffle(names)
    k = rng.randint(1, 3)
    cut = sorted(rng.sample(range(1, 8), k - 1))
    p = R(rng.choice([1, -1, 2, -6]))
    for group in (names[i:j] for i, j in zip([0] + cut, cut + [8])):
        p *= random_multilinear(rng, group)
    if rng.random() < 0.5:
        p *= rng.choice(X) ** rng.randint(1, 3) * rng.choice(X)
    if rng.random() < 0.2:
        p *= random_multilinear(rng, rng.sample(X, 3))  # usually no longer multilinear
    return p


@pytest.mark.parametrize("seed", range(4))
def test_agrees_with_sympy_factor_list(seed):
    rng = random.Random(seed)
    for _ in range(150):
        p = random_case(rng)
        if not p:
            continue
        ours, oracle = factor_list(p), p.factor_list()
        assert ours[0] == oracle[0], p
        assert sorted(map(str, ours[1])) == sorted(map(str, oracle[1])), p


def test_factors_that_vanish_on_an_arithmetic_progression():
    # a - f + 3 is zero at a = n, f = n + 3 for every n: evaluation points must avoid that
    p = (X[0] - X[5] + 3) * (X[1] * X[2] - 1) * X[3] ** 2
    assert sorted(map(str, factor_list(p)[1])) == sorted(map(str, p.factor_list()[1]))


def test_symbolic_ratios_keep_their_factored_form():
    # Liu and Chen's transmission, third gear: two planetary factors over one coupled one
    m = gl.catalog.load("liu_chen_transmission")
    r = gl.unit_ratio(m, output=8, input=4, ground=1, method="symbolic")
    assert str(r) == "(e_1_7*e_7_8 - 1)*(e_2_3*e_3_5 - 1)/(e_1_6*e_2_3*e_3_5*e_6_2 - e_2_3*e_3_5 + 1)"


def test_davies_factoring_matches_sympy_factor_list():
    """gearlib.davies._rational factors numerators and denominators of rational functions
    with rational coefficients (Davies' formulas in friction coefficients, radii, ordinary
    efficiencies) in the polynomial ring; the constants and factors (with their signs) must
    be sympy's (their order may differ where sympy splits a product before factoring)."""
    import sympy

    from gearlib.davies._rational import _ring_factors, factored

    rng = random.Random(17)
    symbols = sympy.symbols("zeta_C zeta_D r1 r2 eta_1_2 eta_4_2")
    compared = 0
    for _ in range(60):
        parts = []
        for _ in range(2):
            p = random_multilinear(rng, rng.sample(X[:6], rng.randint(1, 4)))
            expr = p.as_expr().subs(dict(zip(sympy.symbols("a b c d e f"), symbols)), simultaneous=True)
            parts.append(expr * sympy.Rational(rng.choice([1, 2, 3]), rng.choice([1, 5, 7])))
        expr = parts[0] / parts[1] if rng.random() < 0.8 else parts[0] * parts[1] ** 2
        if not expr.free_symbols:
            assert _ring_factors(expr) is None  # constants are factored() before this route
            continue
        got = _ring_factors(expr)
        assert got is not None
        num, den = expr.as_numer_denom()
        for (const, facs), part in zip(got, (num, den)):
            want_const, want = sympy.factor_list(sympy.expand(part))
            assert const == want_const and sorted(facs, key=str) == sorted(want, key=str), part
        assert sympy.cancel(factored(expr) - expr) == 0
        compared += 1
    assert compared >= 50
