"""Speeds and ratios reproduce the papers' numbers (corrected where the seed notes say so).

Every expected value here is typed from a paper, from the seed notes' errata, or from a
classic closed-form formula: none comes from gearlib.
"""

import cmath
import math
from fractions import Fraction

import numpy as np
import pytest
import sympy

import gearlib as gl

E = sympy.Symbol
PRINTED_2 = 0.005  # half a unit in the last of two printed decimals
PRINTED_3 = 0.0005


def polar(z):
    return abs(z), cmath.phase(z)


# --------------------------------------------------------------------- Penaud and Alazard
@pytest.mark.parametrize("method", ["exact", "nullspace", "numeric"])
def test_penaud_example_1_bevel_planet(method):
    m = gl.catalog.load("penaud_example_1")
    sol = gl.speeds(m, ground=1, inputs={2: 1}, method=method)
    w = sol.as_complex()
    # eq. (11): Omega_0 = [0, 1, 1.36 e^{0.639 i}, 0.6250]
    assert abs(w[0]) < 1e-12 and abs(w[1] - 1) < 1e-12
    r, phi = polar(w[2])
    assert abs(r - 1.36) <= PRINTED_2 and abs(phi - 0.639) <= PRINTED_3
    assert abs(w[3] - 0.6250) <= 0.00005
    # "omega_2 = 1.6 omega_4, the same result as Nelson's"
    assert abs(w[1] / w[3] - 1.6) < 1e-9
    # eq. (12) corrected (PA-E1): omega_{3/4} = 0.9375 e^{i pi/3}, the direction alpha = pi/3
    r, phi = polar(complex(sol.relative(3, 4)))
    assert abs(r - 0.9375) < 1e-9 and abs(phi - math.pi / 3) < 1e-9


def test_penaud_example_1_gear_frequency():
    # eq. (13): with omega_2 = 10 Hz both mesh frequencies are 93.75 Hz
    m = gl.catalog.load("penaud_example_1")
    w = gl.speeds(m, ground=1, inputs={2: 10}, method="numeric").as_complex()
    table = gl.link_table(m)
    f13 = abs(complex(table[(1, 3)])) * abs(w[0] - w[3])
    f23 = abs(complex(table[(2, 3)])) * abs(w[1] - w[3])
    assert f13 == pytest.approx(93.75, abs=1e-9) and f23 == pytest.approx(93.75, abs=1e-9)


def test_penaud_example_2_speed_ratio_matrix():
    d = gl.catalog.car_differential()
    W = gl.speed_ratio_matrix(d, zero_speed=[1], normalize_to=[3, 4])
    # eq. (15), both columns
    printed = [
        [(0, 0), (0, 0)], [(2.5, math.pi), (2.5, math.pi)], [(1, 0), (0, 0)], [(0, 0), (1, 0)],
        [(0.86, 0.95), (0.86, -0.95)], [(0.86, -0.95), (0.86, 0.95)], [(0.5, 0), (0.5, 0)],
    ]
    for i, row in enumerate(printed):
        for j, (r, phi) in enumerate(row):
            z = W[i, j]
            assert abs(abs(z) - r) <= PRINTED_2, (i, j, z)
            if r > 0:
                assert abs(cmath.phase(z) - phi) <= PRINTED_2 or abs(abs(cmath.phase(z)) - math.pi) < 1e-9
    assert np.linalg.matrix_rank(gl.adjacency_matrix(d)) == 4  # the second planet duplicates the first


@pytest.mark.parametrize("method", ["exact", "nullspace", "numeric"])
def test_penaud_example_2_operating_cases(method):
    d = gl.catalog.car_differential()

    def run(w3, w4):
        return gl.speeds(d, ground=1, inputs={3: w3, 4: w4}, method=method).as_complex()

    # straight ahead: [0 -5 1 1 1 1 1] omega
    assert np.allclose(run(1, 1), [0, -5, 1, 1, 1, 1, 1], atol=1e-12)
    # jacked up, corrected (PA-E2): omega_6 = -1.4 i = -omega_5
    assert np.allclose(run(1, -1), [0, 0, 1, -1, 1.4j, -1.4j, 0], atol=1e-12)
    # eq. (16), cornering at 30 km/h: omega_3 = 26, omega_4 = 30 rad/s
    w = run(26, 30)
    assert np.allclose(w[[0, 1, 2, 3, 6]], [0, -140, 26, 30, 28], atol=1e-9)
    for k, sign in ((4, -1), (5, 1)):
        r, phi = polar(w[k])
        assert abs(r - 28.14) <= PRINTED_2 and abs(phi - sign * 0.10) <= PRINTED_2


# --------------------------------------------------------------------- Liu, Chen and Chang
def test_liu_chen_eq_21():
    m = gl.catalog.load("liu_chen_fig1")
    got = gl.ratio(m, output=3, input=4, ground=5, method="symbolic")
    expected = E("e_4_1") / (1 - E("e_5_2") * E("e_2_1"))
    assert sympy.simplify(got - expected) == 0


def test_liu_chen_eq_22():
    m = gl.catalog.load("liu_chen_fig3a")
    sol = gl.speeds(m, ground=4, inputs=[1, 6], method="symbolic")
    t14, t64 = gl.omega(1), gl.omega(6)
    expected = E("e_2_3") * (E("e_1_2") * t14 - E("e_6_5") * t64)
    assert sympy.simplify(sol.relative(3, 5) - expected) == 0


# --------------------------------------------------------------------- Chen, Yao and Lee
def test_chen_yao_lee_eq_3():
    m = gl.catalog.load("cyl_standard_differential")
    sol = gl.speeds(m, ground=0, inputs=[2, 3], method="symbolic")
    w1, w2, w3 = sol[1], gl.omega(2), gl.omega(3)
    g32 = E("e_4_2") / E("e_4_3")
    g51 = E("e_5_1")
    assert sympy.simplify((g32 - 1) * w1 + g51 * w2 - g51 * g32 * w3) == 0


# --------------------------------------------------------------------- Chen 1998 wrist
def test_chen_1998_eqs_26_to_28_from_joint_angles():
    wrist = gl.catalog.robotic_wrist()
    th1, th2, th3 = sympy.symbols("theta_1 theta_2 theta_3")
    sol = gl.speeds(wrist, ground=0, inputs={1: th1, "2/1": th2, "3/2": th3}, method="symbolic")
    e = E
    assert sympy.simplify(sol[1] - th1) == 0  # eq. (28)
    assert sympy.simplify(sol[4] - (th1 + e("e_5_4") * th2 + e("e_5_4") * e("e_3_5") * th3)) == 0  # (26)
    assert sympy.simplify(sol[6] - (th1 + e("e_7_6") * th2 + e("e_7_6") * e("e_3_7") * th3)) == 0  # (27)


# --------------------------------------------------------------------- classic and Laus
@pytest.mark.parametrize("sun, ring", [(24, 60), (30, 72), (18, 90), (40, 100)])
def test_classic_planetary_reduction(sun, ring):
    m = gl.catalog.simple_planetary(sun, ring)
    reduction = gl.ratio(m, output=1, input=4, ground=3)  # sun / carrier, ring held
    assert reduction == 1 + Fraction(ring, sun)


def test_compound_train_is_the_product_of_its_stages():
    m = gl.catalog.compound_train(((20, 60), (15, 45)))
    assert gl.ratio(m, output=3, input=1, ground=0) == Fraction(-20, 60) * Fraction(-15, 45)


def test_humpage_speed_ratio_and_willis_carrier_speed():
    h = gl.catalog.humpage()
    assert gl.ratio(h, output=4, input=1) == Fraction(17, 1176)  # Nelson and Cipra
    assert gl.ratio(h, output=6, input=1) == Fraction(20, 20 + 76)  # r1/(r1 + r5), digest D5.6


def test_laus_epicyclic_ratio():
    assert gl.ratio(gl.catalog.load("laus_epicyclic"), output=2, input=5) == Fraction(-5, 9)


def test_numeric_catalogue_entries_agree_across_methods():
    for name in gl.catalog.names():
        m = gl.catalog.load(name)
        if m.is_symbolic:
            continue
        gear = m.gear_constraints(m.schedule[0].name) if m.schedule else {}  # a transmission: its first gear
        n = int(gl.dof(m, m.ground, **gear))
        inputs = {x: k + 1 for k, x in enumerate(m.inputs[:n])}
        ref = gl.speeds(m, inputs=inputs, method="exact", **gear).as_complex()
        for method in ("nullspace", "numeric"):
            assert np.allclose(gl.speeds(m, inputs=inputs, method=method, **gear).as_complex(), ref, atol=1e-9), name
        sym = gl.speeds(m, inputs=inputs, method="symbolic", **gear)
        subs = gl.ratio_symbols(m)
        got = np.array([complex(sympy.N(sympy.sympify(v).subs(subs))) for v in sym.values])
        assert np.allclose(got, ref, atol=1e-9), name


# --------------------------------------------------------------------- inputs that do not fit
def test_input_count_errors_say_how_many_are_needed():
    d = gl.catalog.car_differential()
    with pytest.raises(gl.InputError, match="needs 2 inputs; got 1"):
        gl.speeds(d, ground=1, inputs={3: 26})
    with pytest.raises(gl.InputError, match="needs 2 inputs; got 3"):
        gl.speeds(d, ground=1, inputs={3: 26, 4: 30, 2: 1})
    for method in ("nullspace", "numeric"):
        with pytest.raises(gl.InputError, match="needs 2 inputs; got 1"):
            gl.speeds(d, ground=1, inputs={3: 26}, method=method)


def test_inputs_that_are_not_independent_are_named():
    d = gl.catalog.car_differential()
    with pytest.raises(gl.InputError, match="not independent"):
        gl.speeds(d, ground=1, inputs={2: 1, 7: 2})  # the crown follows the pinion
    with pytest.raises(gl.InputError, match="not independent"):
        gl.speeds(d, ground=1, inputs={2: 1, 7: 2}, method="numeric")


def test_other_bad_inputs():
    m = gl.catalog.simple_planetary()
    with pytest.raises(gl.InputError, match="link 3 is the ground"):
        gl.speeds(m, ground=3, inputs={3: 1})
    with pytest.raises(gl.UnknownLinkError, match="input link 9"):
        gl.speeds(m, ground=3, inputs={9: 1})
    with pytest.raises(gl.ConstraintError, match="held"):
        gl.speeds(gl.catalog.simpson(), ground=0, inputs={4: 1}, held=[4])
    with pytest.raises(gl.InputError, match="choose a ground"):
        gl.speeds(m.replace(ground=None), inputs={1: 1})
    with pytest.raises(gl.DataFormatError, match="method"):
        gl.speeds(m, ground=3, inputs={1: 1}, method="magic")
    with pytest.raises(gl.DataFormatError):
        gl.speeds(m, ground=3, inputs={1: float("inf")})


def test_brakes_and_clutches_make_the_gears_of_a_simpson_set():
    s = gl.catalog.simpson()
    # first gear: input ring 2, rear carrier 4 braked, output 3. Hand derivation with
    # front Willis (sun-ring) and rear Willis: see the unit-gains chapter.
    zs, zr = 30, 72
    first = gl.ratio(s, output=3, input=2, ground=0, held=[4])
    # rear set, carrier held: omega_3 = -(zs/zr) omega_1; front: omega_1 - omega_3 = -(zr/zs)(omega_2 - omega_3)
    k = Fraction(zr, zs)
    w1 = sympy.Symbol("w1")
    w3 = -w1 / k
    sol = sympy.solve(sympy.Eq(w1 - w3, -k * (1 - w3)), w1)[0]
    assert first == Fraction(str(w3.subs(w1, sol)))
    direct = gl.ratio(s, output=3, input=2, ground=0, joined=[(1, 2)])  # sun locked to ring: 1:1
    assert direct == 1


@pytest.mark.parametrize("seed", range(4))
def test_repeated_numeric_calls_equal_a_first_call(seed):
    """A second numeric solve with the same ground and input link skips validation
    (kinematics._repeat_numeric); it must give exactly what a first call on a fresh copy of
    the mechanism gives, for any input value, and still refuse bad values with the message
    of the full path."""
    m = gl.random_mechanism(12, dof=1, rng=seed)
    gl.speeds(m, ground=0, inputs={1: 1}, method="numeric")
    for v in (2, -3.5, 0, 1e-9, 7e8, 1e-300):
        again = gl.speeds(m, ground=0, inputs={1: v}, method="numeric")
        fresh = gl.speeds(gl.random_mechanism(12, dof=1, rng=seed), ground=0, inputs={1: v}, method="numeric")
        assert again.values == fresh.values
        assert again.constraints == fresh.constraints and again.dof == fresh.dof == 1
        exact = gl.speeds(m, ground=0, inputs={1: v})
        assert again.values == pytest.approx([float(x) for x in exact.values], rel=1e-9, abs=1e-12 * max(1, abs(v)))
    for bad in (float("nan"), float("inf"), "fast"):
        with pytest.raises(gl.errors.GearlibError, match="input 1"):
            gl.speeds(m, ground=0, inputs={1: bad}, method="numeric")
