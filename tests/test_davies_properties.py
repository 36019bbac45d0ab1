"""Davies' method on random trains whose radii fit their topology (gl.davies.random_train).

Independent references: the core Willis solver (gl.ratio), a conventional torque balance
(gl.davies.torque_balance_efficiency, no screws and no graph), Tellegen's theorem, and exact
arithmetic against floating point.
"""

import numpy as np
import pytest
import sympy
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import gearlib as gl

dv = gl.davies
cases = st.builds(lambda seed, kind: (seed, kind), st.integers(0, 10**6), st.sampled_from(dv.KINDS))
SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def make(params):
    seed, kind = params
    rng = np.random.default_rng(seed)
    case = dv.random_train(rng, kind)
    etas = {gp.gears: float(rng.uniform(0.95, 1.0)) for gp in case.mechanism.gear_pairs}
    return case, etas, rng


@SETTINGS
@given(cases)
def test_lossless_train_has_efficiency_one_and_the_core_speed_ratio(params):
    case, _, _ = make(params)
    m, g, i, o = case.mechanism, case.ground, case.input, case.output
    res = dv.efficiency(m, g, i, o, eta=1.0)
    assert res.value == pytest.approx(1.0, abs=1e-12)
    ratio = gl.ratio(m, output=o, input=i, ground=g)
    assert res.ratio == pytest.approx(float(ratio), rel=1e-12, abs=1e-12)
    powers = dv.coupling_powers(res.motions, res.actions)
    ports = {res.network.port("input").name, res.network.port("output").name}
    assert all(abs(p) < 1e-12 for name, p in powers.items() if name not in ports)


@SETTINGS
@given(cases)
def test_power_balance_and_agreement_with_the_torque_balance(params):
    case, etas, _ = make(params)
    m, g, i, o = case.mechanism, case.ground, case.input, case.output
    res = dv.efficiency(m, g, i, o, eta=etas)
    assert abs(dv.tellegen(res.motions, res.actions)) < 1e-12  # input power is 1
    conv = dv.torque_balance_efficiency(m, g, i, o, eta=etas)
    assert res.value == pytest.approx(conv.value, abs=1e-11)
    drivers = {(mm.driver, mm.driven) for mm in res.meshes if abs(mm.virtual_power) > 1e-9}
    assert drivers <= set(conv.drivers.values())


@SETTINGS
@given(cases)
def test_efficiency_is_in_zero_one_in_the_practical_range(params):
    case, etas, _ = make(params)
    res = dv.efficiency(case.mechanism, case.ground, case.input, case.output, eta=etas)
    assert res.value <= 1 + 1e-12
    # first-order loss estimate from the recirculating (virtual) power; beyond ~0.7 a train may self-lock
    estimate = sum((1 - etas[mm.gears]) * abs(mm.virtual_power) for mm in res.meshes)
    if estimate < 0.7:
        assert res.value > 0
    # every mesh loses power, and the ordinary efficiency used is the one asked for
    for mm in res.meshes:
        assert mm.loss <= 1e-15
        assert mm.eta == etas[mm.gears]


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cases)
def test_exact_layouts_and_float_agree(params):
    case, etas, _ = make(params)
    m, g, i, o = case.mechanism, case.ground, case.input, case.output
    exact_etas = {k: sympy.Rational(str(round(v, 4))) for k, v in etas.items()}
    exact = dv.efficiency(m, g, i, o, eta=exact_etas, symbolic="exact")
    floats = [dv.efficiency(m, g, i, o, eta={k: float(v) for k, v in exact_etas.items()}, mode=mode).value
              for mode in ("auto", "right-angle", "kinematic")]
    assert floats == pytest.approx([float(exact.value)] * 3, abs=1e-11)


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cases)
def test_reversing_the_ports_inverts_the_formula(params):
    """Laus's rule: exchanging input and output gives 1/eta with every eta_ij -> 1/eta_ji."""
    case, _, _ = make(params)
    m, g, i, o = case.mechanism, case.ground, case.input, case.output
    forward = dv.efficiency(m, g, i, o, symbolic=True)
    backward = dv.efficiency(m, g, o, i, symbolic=True)
    f = forward.formula if forward.formula is not None else forward.value
    b = backward.formula if backward.formula is not None else backward.value
    subs = {}
    for s in f.free_symbols:
        _, a, c = str(s).split("_")
        subs[s] = 1 / sympy.Symbol(f"eta_{c}_{a}", positive=True)
    assert sympy.simplify(1 / f.subs(subs) - b) == 0


def test_simpson_first_gear_with_a_brake_agrees_with_the_torque_balance():
    simpson = gl.catalog.simpson()
    res = dv.efficiency(simpson, 0, 2, 3, eta=0.98, held=[4])
    conv = dv.torque_balance_efficiency(simpson, 0, 2, 3, eta=0.98, held=[4])
    assert res.value == pytest.approx(conv.value, abs=1e-12)
    assert res.ratio == pytest.approx(float(gl.ratio(simpson, output=3, input=2, ground=0, held=[4])))


def test_ravigneaux_without_a_planar_layout_agrees_with_the_torque_balance():
    rav = gl.catalog.ravigneaux()
    res = dv.efficiency(rav, 0, 1, 4, eta=0.98, held=[2])
    assert any("do not close" in n for n in res.notes)
    conv = dv.torque_balance_efficiency(rav, 0, 1, 4, eta=0.98, held=[2])
    assert res.value == pytest.approx(conv.value, abs=1e-12)


def _general_route():
    """Patches that turn off the two shortcuts of the symbolic efficiency: the Woodbury solve
    of a system with a few symbolic entries (davies._solve._few_symbols) and the formula in
    polynomial rings (davies._ringformula.formula); both then return None and the caller
    takes the general route (full fraction-free elimination, sympy expressions)."""
    from unittest import mock

    from gearlib.davies import _ringformula, _solve

    return (mock.patch.object(_solve, "_few_symbols", lambda *a, **k: None),
            mock.patch.object(_ringformula, "formula", lambda *a, **k: None))


def _efficiency_both_ways(m, g, i, o, **kw):
    fast = dv.efficiency(m, g, i, o, **kw)
    a, b = _general_route()
    with a, b:
        slow = dv.efficiency(m, g, i, o, **kw)
    return fast, slow


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cases)
def test_shortcuts_of_the_symbolic_formula_change_nothing(params):
    """The same formula, printed the same, and the same mesh coefficients, with or without
    the shortcuts (the general route is the reference)."""
    case, _, _ = make(params)
    m, g, i, o = case.mechanism, case.ground, case.input, case.output
    fast, slow = _efficiency_both_ways(m, g, i, o, symbolic=True)
    assert str(fast.value) == str(slow.value)
    assert sympy.cancel(fast.formula_zeta - slow.formula_zeta) == 0
    for a, b in zip(fast.meshes, slow.meshes):
        assert (a.driver, a.driven) == (b.driver, b.driven)
        assert sympy.simplify(a.zeta - b.zeta) == 0
    point = {s: sympy.Rational(1, 3 + k) for k, s in enumerate(sorted(fast.zeta_symbols.values(), key=str))}
    assert [sympy.nsimplify(x.subs(point)) for x in fast.actions.values] == [
        sympy.nsimplify(y.subs(point)) for y in slow.actions.values]


def test_shortcuts_on_the_book_examples():
    for name, ports in (("laus_epicyclic", (1, 5, 2)), ("laus_simple_pair", (0, 1, 2))):
        fast, slow = _efficiency_both_ways(gl.catalog.load(name), *ports, symbolic=True)
        assert str(fast.value) == str(slow.value)
    fast, slow = _efficiency_both_ways(gl.catalog.humpage(), 5, 1, 4, symbolic=True)
    assert str(fast.value) == str(slow.value) == "-17*(19*eta_1_2*eta_2_5 + 5)/(24*(228*eta_2_5*eta_4_2 - 245))"


def test_woodbury_solve_agrees_with_elimination():
    """davies._solve: random square systems with a few ``c * symbol`` entries, solved by the
    Woodbury shortcut and by sympy's LU solve of the same matrix."""
    from gearlib.davies import _solve

    rng = np.random.default_rng(5)
    zs = sympy.symbols("z0:4")
    for trial in range(6):
        n = 6
        A = sympy.Matrix(n, n, lambda r, c: int(rng.integers(-4, 5)) if rng.random() < 0.6 else 0) + 7 * sympy.eye(n)
        for s in zs[: 1 + trial % 4]:
            A[int(rng.integers(n)), int(rng.integers(n))] = sympy.Rational(int(rng.integers(1, 5)), 3) * s
        b = sympy.Matrix([int(v) for v in rng.integers(-3, 4, n)])
        sol = _solve._few_symbols(A, b)
        assert sol is not None
        for _ in range(2):  # exact comparison at random rational points: A(z) x = b solved by sympy
            point = {s: sympy.Rational(int(rng.integers(-9, 10)), int(rng.integers(1, 7))) for s in zs}
            ref = A.subs(point).LUsolve(b)
            assert [sympy.nsimplify(sol[k].subs(point)) for k in range(n)] == list(ref)
    # a singular A0 (here: a zero column outside the symbolic entry) is left to the general route
    A = sympy.Matrix([[zs[0], 0], [1, 0]])
    assert _solve._few_symbols(A, sympy.Matrix([1, 1])) is None
