"""Every exercise check accepts its reference solution and answers wrong ones with a hint.

Reference solutions are the worked solutions of the book's solution pages, typed here;
the wrong answers are typical mistakes. Add a row whenever a chapter adds a check.
"""

from fractions import Fraction

import numpy as np
import pytest
import sympy

import gearlib as gl

# name -> (reference solution, [wrong answers])
ANSWERS = {
    # ---------------------------------------------------------------- 00 introduction
    "intro_gear_ratio": (Fraction(-1, 3), [Fraction(1, 3), -3, "-0.3"]),
    "intro_planetary_ratio": (Fraction(2, 7), [Fraction(7, 2), Fraction(5, 7), 0.3, "-2/7"]),
    # ---------------------------------------------------------------- 01 graph representation
    "graph_carrier": (4, [5, 1, "3"]),
    "graph_dof_simpson": (2, [1, 3, 0]),
    "graph_compound_ratio": (Fraction(1, 12), [Fraction(-1, 12), 12, 0.1]),
    "graph_differential_pinion": (-110, [22, 110, Fraction(-22, 5)]),
    "graph_humpage_ratio": (Fraction(17, 1176), [Fraction(5, 24), Fraction(1176, 17), Fraction(480, 1960)]),
    # ---------------------------------------------------------------- 02 kinematic units
    "units_simpson": ([{3, 1, 5, 2}, {4, 1, 6, 3}], [[{1, 5, 2}, {1, 6, 3}], [{0, 1, 2, 3, 4, 5, 6}], [{3, 1, 5, 2}]]),
    # names are typed with "_" for "-" here only because the test sympifies references ("K4-1S" is accepted too)
    "unit_type_simpson": ("K4_1S", ["K4-1", "K5-2", "K4-2", "K3-1"]),
    "linkage_wrist": ("coaxial_triangle", ["2-link chain", "triangle", "3"]),
    "atlas_single_unit_chains": (7, [13, 10, 5]),
    # ---------------------------------------------------------------- 03 unit-by-unit gains
    "gain_rule2": (Fraction(-18, 13), [Fraction(-5, 13), Fraction(18, 13), Fraction(-13, 18)]),
    "propagation_fig1": (Fraction(-1, 6), [Fraction(-1, 2), Fraction(1, 3), Fraction(1, 6), -6]),
    "third_gear": ("(e_1_7*e_7_8 - 1)*(e_2_3*e_3_5 - 1)/(e_1_6*e_2_3*e_3_5*e_6_2 - e_2_3*e_3_5 + 1)",
                   ["e_1_7*e_7_8/(e_1_6*e_6_2)", "(e_1_7*e_7_8 - 1)/(e_1_6*e_6_2 - 1)",
                    "(e_1_7*e_7_8 - 1)*(e_2_3*e_3_5 - 1)"]),
    "structure_matrix": ([[1, 1, 1], [0, "-e_5_4*(e_1_6*e_6_5 - 1)", "e_9_8"],
                          [0, "-e_3_7*e_5_4*(e_1_6*e_6_5 - 1)", "e_3_9*e_9_8"]],
                         [[[1, 0, 0], [1, "-e_5_4*(e_1_6*e_6_5 - 1)", "-e_3_7*e_5_4*(e_1_6*e_6_5 - 1)"],
                           [1, "e_9_8", "e_3_9*e_9_8"]],
                          [[1, 1, 1], [0, "e_5_4", "e_9_8"], [0, "e_3_7*e_5_4", "e_3_9*e_9_8"]],
                          [[1, 1], [0, "e_9_8"]]]),
    # ---------------------------------------------------------------- 04 complex adjacency
    "adjacency_planet_ratio": ("5/2*exp(I*pi/3)", [-2.5, 2.5, "5/2*exp(I*pi/4)", "2/5*exp(-I*pi/3)",
                                                   "-5/2*exp(I*pi/3)", 1.25]),
    "adjacency_mesh_frequency": (450, [600, 300, 1800, -450, 15]),
    "adjacency_planet_tooth_frequency": (15, [10, 450, 5, 20, -15]),
    "adjacency_outer_ring_frequency": (54, [36, 81, 67.5, 135, "-54"]),
    # ---------------------------------------------------------------- 05 Davies efficiency
    "davies_pair_zeta": (0.06 / 2.94, [0.06 / 2.97, 0.03, -0.06 / 2.94, 1.0]),
    "davies_epicyclic_efficiency": (5 * 0.98**2 / (14 - 9 * 0.98**2), [0.88912, 1.1247076, 0.9604, 0.946207]),
    "davies_recirculation": (Fraction(13, 5), [1, Fraction(14, 5), Fraction(-13, 5), Fraction(5, 13)]),
    "davies_humpage_efficiency": (0.7768967, [0.597708, 0.970299, 0.632647]),
    "davies_humpage_driver": (5, [2, 1, 6]),
    "davies_pair_bearings": (0.99**2 * 0.97, [0.97, 0.99 * 0.97, 0.960498]),
    # ---------------------------------------------------------------- 06 differential synthesis
    "synth_ground_links": ([1, 3, 4, 6], [[1, 3, 4], [1, 3, 4, 6, 7], "4", [2, 5]]),
    "synth_redundant_links": ({1, 2, 6}, [[1, 2], [5], (1, 2, 5, 6)]),
    "synth_differential_constraint": (
        "(e_4_2 - e_4_3)*omega_1 + e_4_3*e_5_1*omega_2 - e_4_2*e_5_1*omega_3",
        ["(e_4_3 - e_4_2)*omega_1 + e_4_3*e_5_1*omega_2 - e_4_2*e_5_1*omega_3", "omega_1 + omega_2", [0, 1, 1],
         "e_4_2*omega_1 - e_5_1*omega_3"],
    ),
    "synth_seven_link_dgms": (4, [50, 1, 20]),
    "synth_six_link_rotation_graphs": (2, [3, 12, 45]),
}


def test_every_check_has_reference_answers():
    missing = sorted(set(gl.check.names()) - set(ANSWERS))
    assert not missing, f"add reference answers for {missing}"


@pytest.mark.parametrize("name", sorted(ANSWERS))
def test_reference_solution_passes(name):
    ref, _ = ANSWERS[name]
    result = gl.check.get(name)(ref)
    assert result.passed, result.message


@pytest.mark.parametrize("name", sorted(ANSWERS))
def test_wrong_answers_get_a_hint_not_the_solution(name):
    ref, wrongs = ANSWERS[name]
    assert len(wrongs) >= 2
    check = gl.check.get(name)
    for wrong in wrongs:
        result = check(wrong)
        assert not result.passed, wrong
        assert result.message and "Well done" not in result.message
        for shown in {str(ref), str(sympy.sympify(ref) if not callable(ref) else "")} - {""}:
            if len(shown) > 2:
                assert shown not in result.message, f"{name} reveals the solution"


@pytest.mark.parametrize("name", sorted(ANSWERS))
def test_checks_never_crash_and_stubs_fail(name):
    check = gl.check.get(name)
    for junk in (None, "", "not an answer", float("nan"), [1, 2, 3], {"a": 1}, object(), np.array([[1, 2]]),
                 sympy.Symbol("x") + 1, lambda x: x, True, 10**400):
        result = check(junk)
        assert not result.passed, (name, junk)
        assert isinstance(result.message, str) and result.message


def test_a_check_computes_its_answer_once_and_keeps_it_intact():
    calls = []

    def compute():
        calls.append(1)
        return sympy.Matrix([[1, 2], [3, 4]])

    check = gl.check.Check("counting", compute)
    assert not check([[1, 2], [3, 5]]).passed
    assert check([[1, 2], [3, 4]]).passed
    assert check(np.array([[1, 2], [3, 4]])).passed
    assert len(calls) == 1, "the expected value was computed again for each answer"
    kept = check._expected()
    with pytest.raises(TypeError):
        kept[0, 0] = 7  # what the check compares with cannot be changed from outside
    assert check([[1, 2], [3, 4]]).passed
