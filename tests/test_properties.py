"""Property tests on random valid mechanisms: every solver agrees, every Willis equation holds."""

import numpy as np
import pytest
import sympy
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import gearlib as gl

mechanisms = st.builds(
    lambda seed, n, dof, bevel: (seed, n, dof, bevel),
    st.integers(0, 10**6), st.integers(3, 10), st.integers(1, 3), st.sampled_from([0.0, 0.5]),
)


def build(params):
    seed, n, dof, bevel = params
    assume(n >= dof + 2)
    try:
        return gl.random_mechanism(n, dof=dof, rng=seed, bevel=bevel)
    except ValueError:
        assume(False)


def inputs_for(m, rng):
    """Independent inputs, with random speeds."""
    return {link: int(rng.integers(1, 9)) for link in gl.choose_inputs(m, 0)}


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mechanisms)
def test_three_solvers_agree_and_satisfy_willis(params):
    m = build(params)
    rng = np.random.default_rng(params[0])
    inputs = inputs_for(m, rng)
    mob = gl.dof(m, 0)
    assert mob.rank == params[2]  # the generator's promise
    exact = gl.speeds(m, ground=0, inputs=inputs, method="exact")
    ref = exact.as_complex()
    for method in ("nullspace", "numeric"):
        got = gl.speeds(m, ground=0, inputs=inputs, method=method).as_complex()
        assert np.allclose(got, ref, rtol=1e-8, atol=1e-8 * max(1.0, np.abs(ref).max()))
    sym = gl.speeds(m, ground=0, inputs=inputs, method="symbolic")
    subs = gl.ratio_symbols(m)
    sym_num = np.array([complex(sympy.N(sympy.sympify(v).subs(subs), 30)) for v in sym.values])
    assert np.allclose(sym_num, ref, rtol=1e-9, atol=1e-9 * max(1.0, np.abs(ref).max()))
    # every Willis equation holds exactly for the exact solution
    values = {gl.omega(k): v if isinstance(v, sympy.Basic) else sympy.Rational(v.numerator, v.denominator)
              for k, v in exact.items()}
    for eq in gl.willis_equations(m, symbolic=False):
        residual = sympy.expand_complex(eq.residual.subs(values))
        assert residual == 0 or abs(complex(sympy.N(residual, 60))) < 1e-40
    # inputs are reproduced
    for link, value in inputs.items():
        assert exact[link] == value


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 10**6), st.integers(3, 30))
def test_counts_equal_rank_for_tree_mechanisms(seed, n):
    m = gl.random_mechanism(n, dof=1, rng=seed)
    mob = gl.dof(m, 0)
    assert mob.rank == mob.count == 1
    assert mob.planar == 1 if m.is_planar else True


def test_large_random_mechanism_numeric_matches_exact():
    m = gl.random_mechanism(300, dof=1, rng=7)
    exact = gl.speeds(m, ground=0, inputs={1: 1}).as_complex()
    numeric = gl.speeds(m, ground=0, inputs={1: 1}, method="numeric").as_complex()
    assert np.allclose(numeric, exact, rtol=1e-6, atol=1e-9 * np.abs(exact).max())


@pytest.mark.parametrize("n", [1, 5, 40])
def test_serial_train_ratio(n):
    m = gl.serial_train(n, teeth=(20, 40))
    from fractions import Fraction

    assert gl.ratio(m, output=n + 1, input=1, ground=0) == Fraction(-1, 2) ** n


# ------------------------------------------------ the rank certified modulo a prime (issue 25)
def _exact_ranks(m, extra):
    from gearlib.mechanism.mobility import _rank_and_basis

    ech, rank_w = _rank_and_basis(m, extra)
    return rank_w, ech.rank, [t for t in ech.dependent if t is not None]


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 10**6), st.integers(3, 40), st.integers(1, 3), st.integers(0, 2))
def test_the_modular_certificate_agrees_with_exact_elimination(seed, n, dof, n_held):
    """Whenever the fast path of gl.dof answers (every row independent modulo a prime, no pair
    locked), the exact rational elimination gives the same ranks; when it cannot, it declines."""
    from gearlib.mechanism.mobility import _modular_certificate

    assume(n >= dof + 1)
    m = gl.random_mechanism(n, dof=dof, rng=seed)
    held = list(m.link_ids[1:1 + n_held])
    extra = [{0: 1}] + [{m.index[h]: 1} for h in held]
    cert = _modular_certificate(m, extra)
    rank_w, rank, dependent = _exact_ranks(m, extra)
    if cert is not None:
        assert cert == (rank_w, rank) and not dependent
    else:  # it declines only for a reason the exact path also finds
        assert dependent or gl.dof(m, 0, held=held).locked_gear_pairs


def test_the_certificate_declines_what_it_cannot_certify():
    from gearlib.mechanism.mobility import _modular_certificate

    car = gl.catalog.car_differential()  # a second planet: a dependent row
    assert _modular_certificate(car, [{car.index[1]: 1}]) is None
    train = gl.serial_train(250)  # more than 200 pairs: gl.dof takes the fast path
    assert _modular_certificate(train, [{0: 1}, {1: 1}]) is None  # no freedom left: every pair locked
    locked = gl.dof(train, 0, held=[1])
    assert int(locked) == 0 and len(locked.locked_gear_pairs) == 250
    assert int(gl.dof(train, 0)) == 1 and gl.dof(train, 0).locked_gear_pairs == ()
    wrist = gl.catalog.robotic_wrist()  # symbolic ratios: not rational, left to the exact path
    assert _modular_certificate(wrist, [{0: 1}]) is None
