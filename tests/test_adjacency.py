"""Penaud and Alazard's complex adjacency matrix: the paper's equations (9) to (16), corrected
per the seed notes (PA-E1, PA-E2), the stable basis, constraint rows and the display of T and M.

Expected values are typed from the paper (printed digits, with half a unit of the last digit
as tolerance), from the seed notes' errata, or from hand computations: none comes from gearlib.
"""

import cmath
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import gearlib as gl

P2, P3, P4 = 0.005, 0.0005, 0.00005  # half a unit of the last of 2, 3, 4 printed decimals


def rect(r, phi):
    return cmath.rect(r, phi)


def assert_polar(z, r, phi, tol_r, tol_phi):
    assert abs(abs(z) - r) <= tol_r, (z, r)
    assert abs(cmath.phase(z) - phi) <= tol_phi, (z, phi)


@pytest.fixture(scope="module")
def ex1():
    return gl.catalog.load("penaud_example_1")


@pytest.fixture(scope="module")
def car():
    return gl.catalog.car_differential()


# ----------------------------------------------------------------------------- example 1
def test_eq9_adjacency_matrix_of_the_bevel_planet(ex1):
    pi = math.pi
    a, b = pi / 3, pi / 4  # alpha, beta
    t13, t31 = rect(15, b), rect(10, b - a)  # Table 1: N1 e^{i beta}, N3 e^{i(beta - alpha)}
    t23, t32 = rect(25, 2 * a - b - pi), rect(10, a - b)
    expected = np.array([[t13, 0, t31, -t13 - t31], [0, t23, t32, -t23 - t32]])
    assert np.allclose(gl.adjacency_matrix(ex1), expected, atol=1e-12)
    # the printed angles of eq. (9): pi/4, -pi/12, -7pi/12, pi/12
    for z, phi in ((t13, pi / 4), (t31, -pi / 12), (t23, -7 * pi / 12), (t32, pi / 12)):
        assert abs(cmath.phase(z) - phi) < 1e-12


def test_eq10_printed_null_space_spans_the_computed_one(ex1):
    printed = np.array([
        [rect(0.357, 2.147), rect(0.729, -0.070)],
        [rect(0.412, -0.686), rect(0.444, 0.633)],
        [rect(0.828, 0.125), rect(0.069, -0.106)],
        [rect(0.136, -0.382), rect(0.517, 0.284)],
    ])
    M = gl.adjacency_matrix(ex1)
    # three printed decimals: M K is zero to about 1e-2 of |M| |K|, and the subspaces agree to ~1e-3
    assert np.abs(M @ printed).max() < 0.02 * np.abs(M).max()
    K = gl.null_space(M)
    assert K.shape == (4, 2)
    assert gl.same_subspace(K, printed, tol=5e-3)
    assert not gl.same_subspace(K, printed[:, ::-1].conj(), tol=5e-3)
    # the stable (reduced) basis of the printed columns equals that of the computed ones
    B_printed, _ = gl.reduced_basis(printed)
    assert np.allclose(gl.null_space(M, basis="reduced"), B_printed, atol=1e-2)


def test_eq4_counts_the_free_rotation_of_the_whole_chain(ex1, car):
    for mech, n_dof_paper in ((ex1, 2), (car, 3)):
        M = gl.adjacency_matrix(mech)
        assert len(mech.links) - np.linalg.matrix_rank(M) == n_dof_paper
        assert np.allclose(M @ np.ones(len(mech.links)), 0)  # [1, ..., 1] is always in Ker M
    assert int(gl.dof(car, 1)) == 2  # grounding the frame removes that freedom
    assert int(gl.dof(ex1, 1)) == 1


def test_eq11_speed_ratio_vector_with_the_sun_held(ex1):
    W = gl.speed_ratio_matrix(ex1, zero_speed=[1], normalize_to=[2])
    assert W.shape == (4, 1)
    w = W[:, 0]
    assert abs(w[0]) < 1e-12 and abs(w[1] - 1) < 1e-12
    assert_polar(w[2], 1.36, 0.639, P2, P3)
    assert abs(w[3] - 0.6250) <= P4
    assert abs(w[1] / w[3] - 1.6) < 1e-12  # "omega_2 = 1.6 omega_4", Nelson's result
    # cross-check: the Willis equations solved exactly (another method) give the same vector
    exact = gl.speeds(ex1, ground=1, inputs={2: 1}, method="exact").as_complex()
    assert np.allclose(w, exact, atol=1e-12)


def test_eq12_corrected_relative_speed_points_along_alpha(ex1):
    w = gl.speed_ratio_matrix(ex1, zero_speed=[1], normalize_to=[2])[:, 0]
    rel = w[2] - w[3]
    d = gl.direction(rel)
    assert abs(d.magnitude - 0.9375) < 1e-12
    assert abs(d.angle - math.pi / 3) < 1e-12  # PA-E1: e^{i pi/3}, the angle alpha
    assert abs(d.angle - math.pi / 4) > 0.2  # not the printed e^{i pi/4}
    # by hand: omega_3 - omega_4 = e_{2,3}(omega_2 - omega_4) with e_{2,3} = -(25/10) e^{i(-7pi/12 - pi/12)}
    e23 = -2.5 * cmath.exp(1j * (-7 * math.pi / 12 - math.pi / 12))
    assert abs(rel - e23 * (1 - 0.625)) < 1e-12


def test_ring_held_instead_gives_three_eighths(ex1):
    # by hand: omega_4 / omega_1 = e13 / (e13 - e23), and e23 / e13 = -5/3
    w = gl.speed_ratio_matrix(ex1, zero_speed=[2], normalize_to=[1])[:, 0]
    assert abs(w[3] - 3 / 8) < 1e-12


# ----------------------------------------------------------------------------- example 2
def test_eq14_adjacency_matrix_of_the_car_differential(car):
    q = math.pi / 4
    p, m = rect(14, -q), rect(14, q)  # N4 e^{-i theta2}, N4 e^{i theta2}
    s, t = rect(10, q), rect(10, -q)  # N3 e^{i theta2}, N3 e^{-i theta2}
    expected = np.array([
        [-78, 13, 0, 0, 0, 0, 65],
        [0, 0, p, 0, s, 0, -p - s],
        [0, 0, m, 0, 0, t, -m - t],
        [0, 0, 0, m, t, 0, -m - t],
        [0, 0, 0, p, 0, s, -p - s],
    ])
    assert np.allclose(gl.adjacency_matrix(car), expected, atol=1e-12)
    assert np.linalg.matrix_rank(expected) == 4  # the second planet repeats the first


PRINTED_15 = [  # eq. (15): (modulus, phase) of both columns
    [(0, 0), (0, 0)], [(2.5, math.pi), (2.5, math.pi)], [(1, 0), (0, 0)], [(0, 0), (1, 0)],
    [(0.86, 0.95), (0.86, -0.95)], [(0.86, -0.95), (0.86, 0.95)], [(0.5, 0), (0.5, 0)],
]


@pytest.mark.parametrize("basis", ["orthonormal", "reduced"])
def test_eq15_speed_ratio_matrix_normalised_to_the_wheels(car, basis):
    W = gl.speed_ratio_matrix(car, zero_speed=[1], normalize_to=[3, 4], basis=basis)
    assert W.shape == (7, 2)
    for i, row in enumerate(PRINTED_15):
        for j, (r, phi) in enumerate(row):
            if r == 0:
                assert abs(W[i, j]) < 1e-12
            else:
                assert_polar(W[i, j], r, phi, P2, P2)
    # by hand, pair (3, 5) on carrier 7 with omega_3 = 1, omega_7 = 1/2:
    # omega_5 = 1/2 - (14/10) e^{-i pi/2} (1 - 1/2) = 0.5 + 0.7i
    assert abs(W[4, 0] - (0.5 + 0.7j)) < 1e-12 and abs(W[5, 0] - (0.5 - 0.7j)) < 1e-12


def test_normalised_matrix_does_not_depend_on_the_basis(car):
    M = gl.adjacency_matrix(car)
    C = gl.constraint_rows(car, zero_speed=[1])
    K = gl.null_space(np.vstack([M, C]))
    U = np.array([[2.0 + 1j, -0.5], [0.3j, 1.5 - 0.2j]])  # any invertible change of basis
    for basis in (K, K @ U):
        W = basis @ np.linalg.inv(basis[[2, 3], :])
        assert np.allclose(W, gl.speed_ratio_matrix(car, zero_speed=[1], normalize_to=[3, 4]), atol=1e-12)
    assert not np.allclose(K, K @ U)  # while the raw columns differ
    B1, p1 = gl.reduced_basis(K)
    B2, p2 = gl.reduced_basis(K @ U)
    assert p1 == p2 and np.allclose(B1, B2, atol=1e-12)


def test_straight_jacked_up_and_cornering(car):
    W = gl.speed_ratio_matrix(car, zero_speed=[1], normalize_to=[3, 4])
    # driving straight ahead: [0 -5 1 1 1 1 1] omega
    assert np.allclose(W @ [1, 1], [0, -5, 1, 1, 1, 1, 1], atol=1e-12)
    # jacked up, corrected (PA-E2): omega_6 = -1.4 i = 1.4 e^{-i pi/2} = -omega_5
    jack = W @ [1, -1]
    assert np.allclose(jack, [0, 0, 1, -1, 1.4j, -1.4j, 0], atol=1e-12)
    printed_omega6 = -1.4 * cmath.exp(-1j * math.pi / 2)
    assert abs(jack[5] - printed_omega6) > 2  # the printed value is +1.4i, the planet's twin
    # eq. (16), turning right at 30 km/h: omega_3 = 26, omega_4 = 30 rad/s
    w = W @ [26, 30]
    assert np.allclose(w[[0, 1, 2, 3, 6]], [0, -140, 26, 30, 28], atol=1e-12)
    assert_polar(w[4], 28.14, -0.10, P2, P2)
    assert_polar(w[5], 28.14, 0.10, P2, P2)


def test_constraint_rows_reduce_the_freedoms(car):
    # wheels made to turn together (equal speeds): one freedom left, the straight-ahead vector
    W = gl.speed_ratio_matrix(car, zero_speed=[1], equal=[(3, 4)], normalize_to=[3])
    assert np.allclose(W[:, 0], [0, -5, 1, 1, 1, 1, 1], atol=1e-12)
    # one wheel held (link 4 still): the other wheel turns at -2/5 of the pinion
    W = gl.speed_ratio_matrix(car, zero_speed=[1, 4], normalize_to=[2])
    assert abs(W[2, 0] - (-0.4)) < 1e-12 and abs(W[6, 0] - (-0.2)) < 1e-12
    C = gl.constraint_rows(car, zero_speed=[1], equal=[(3, "4")])
    assert C.tolist() == [[1, 0, 0, 0, 0, 0, 0], [0, 0, 1, -1, 0, 0, 0]]


@pytest.mark.parametrize("kwargs, error, text", [
    ({"zero_speed": [1], "normalize_to": [3]}, gl.InputError, "2 degrees of freedom"),
    ({"zero_speed": [1], "normalize_to": [7, 2]}, gl.InputError, "not independent"),
    ({"zero_speed": [9], "normalize_to": [3, 4]}, gl.UnknownLinkError, "9"),
    ({"equal": [(3,)]}, gl.DataFormatError, "pair of links"),
    ({"equal": [(3, 3)]}, gl.ConstraintError, "one link twice"),
    ({"basis": "qr"}, gl.DataFormatError, "basis"),
])
def test_bad_options_give_named_errors(car, kwargs, error, text):
    with pytest.raises(error, match=text):
        gl.speed_ratio_matrix(car, **kwargs)


# ----------------------------------------------------------------------------- display
def test_link_table_display_matches_table_1(ex1):
    view = gl.show_link_table(ex1)
    assert view.rows == ["1", "2", "3", "4"]
    e = view.entries
    assert e[0][2] == "15e^(iπ/4)" and e[0][3] == "(p)" and e[0][1] == ""
    assert e[1][2] == "25e^(-7iπ/12)"  # N2 e^{i(2 alpha - beta - pi)}
    assert e[2][0] == "10e^(-iπ/12)" and e[2][1] == "10e^(iπ/12)"
    assert "<sup>iπ/4</sup>" in view._repr_html_()


def test_matrix_display_matches_eq_14(car):
    view = gl.show_matrix(car)
    assert view.rows[0] == "(2, 7)/1" and view.cols == [str(i) for i in range(1, 8)]
    assert view.entries[0] == ["-78", "13", "0", "0", "0", "0", "65"]
    assert view.entries[1][6] == "-14e^(-iπ/4) - 10e^(iπ/4)"
    polar = gl.show_matrix(gl.speed_ratio_matrix(car, zero_speed=[1], normalize_to=[3, 4]), style="polar")
    # 0.5 + 0.7i exactly: modulus sqrt(0.74), direction atan(1.4) = 54.46 degrees
    assert polar.entries[4][0] == "0.8602∠54.46°" and polar.entries[1] == ["-2.5", "-2.5"]
    assert "∠" in str(polar)


def test_every_polar_form_in_gearlib_writes_degrees_with_the_sign():
    """One polar form everywhere (chapter 4, the notation page): r∠phi° with phi in degrees, in
    matrix tables, prose numbers, speed lists, directions and the CLI's speeds. The angle of
    -1.4i is -90 degrees (-1.5708 rad); of 28 - 2.8i, atan(-0.1) = -5.7106 degrees."""
    z = 28 - 2.8j
    texts = {
        "format_entry": gl.adjacency.format_entry(z, style="polar", digits=5),
        "number": repr(gl.number(z, 5)),
        "format_value": gl.mechanism.format_value(z, 5),
    }
    assert texts["format_entry"] == texts["number"] == texts["format_value"] == "28.14∠-5.7106°", texts
    assert str(gl.direction(z)) == "28.1397∠-5.71059°"  # |z| = 28.13966, six digits
    assert gl.number(-1.4j, 4)._repr_latex_() == r"$1.4\angle -90^\circ$"
    assert gl.mechanism.format_value(-1.4j) == "1.4∠-90°" and gl.mechanism.format_value(-2.5 + 0j) == "-2.5"
    car = gl.catalog.car_differential()
    sol = gl.speeds(car, ground=1, inputs={3: 1, 4: -1})
    assert "1.4∠90°" in str(sol) and "∠1.571" not in str(sol)


def test_direction_of_a_complex_speed():
    d = gl.direction(-1.4j)
    assert d.magnitude == pytest.approx(1.4) and d.degrees == pytest.approx(-90)
    assert gl.direction(-5).angle == pytest.approx(math.pi)
    assert str(gl.direction(0)) == "0"


# ----------------------------------------------------------------------------- properties
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 10**6), st.integers(4, 9), st.integers(1, 2), st.sampled_from([0.0, 0.5]))
def test_null_space_normalised_to_inputs_matches_exact_speeds(seed, n, dof, bevel):
    assume(n >= dof + 2)
    m = gl.random_mechanism(n, dof=dof, rng=seed, bevel=bevel)
    # inputs: the first links, in order, whose speeds are independent (the reduced basis' pivots)
    K = gl.speed_ratio_matrix(m, zero_speed=[0], basis="reduced")
    _, pivots = gl.reduced_basis(K)
    links = [m.link_ids[i] for i in pivots]
    W = gl.speed_ratio_matrix(m, zero_speed=[0], normalize_to=links)
    rng = np.random.default_rng(seed)
    values = [int(v) for v in rng.integers(1, 9, size=len(links))]
    exact = gl.speeds(m, ground=0, inputs=dict(zip(links, values)), method="exact").as_complex()
    assert np.allclose(W @ values, exact, rtol=1e-8, atol=1e-8 * max(1.0, np.abs(exact).max()))


def test_adjacency_rank_is_the_papers_count(ex1, car):
    """gl.adjacency_rank: rank(M) and N - rank(M) (Penaud's eq. (4)), against numpy's matrix_rank
    and sympy's exact rank; with a link held the count equals gl.dof (the rank of the Willis rows)."""
    for mech, n_dof_paper, ground in ((ex1, 2, 1), (car, 3, 1)):
        count = gl.adjacency_rank(mech)
        M = gl.adjacency_matrix(mech)
        assert count.rank == np.linalg.matrix_rank(M) == gl.adjacency_rank(mech, exact=True).rank
        assert count.dof == int(count) == n_dof_paper and count.rows == M.shape[0]
        held = gl.adjacency_rank(mech, zero_speed=[ground])
        assert held.dof == int(gl.dof(mech, ground)) == gl.null_space(np.vstack([M, gl.constraint_rows(
            mech, zero_speed=[ground])])).shape[1]
    assert gl.adjacency_rank(car).redundant_rows == 1  # the second planet repeats the first (eq. (14))


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 10**6), st.integers(4, 12), st.integers(1, 3))
def test_adjacency_rank_with_a_link_held_is_the_dof(seed, n, dof):
    m = gl.random_mechanism(n, dof=dof, rng=seed, bevel=0.3)  # n >= dof + 1
    assert gl.adjacency_rank(m, zero_speed=[0]).dof == int(gl.dof(m, 0)) == dof
