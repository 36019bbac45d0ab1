"""Every exercise check: the reference answer passes, wrong answers get a hint that does not
show the answer, a rounded answer is never told its method is wrong, malformed answers get a
hint at once, and nothing public on a check carries its answer.

The reference answers in :data:`ANSWERS` are worked here by hand (comments), independently of
the library; the wrong answers are typical mistakes. Add a row when a chapter adds a check.
The generic requirements are the ``assert_*`` helpers of ``check_tools``; the last tests run
them on deliberately broken checks to show that each one fails when it should.
"""

from __future__ import annotations

import json
import math
import os
import re
import subprocess
import sys
from fractions import Fraction

import pytest
import sympy

import gearlib as gl
from check_tools import (
    assert_hint_without_answer,
    assert_malformed_answers_get_a_hint_fast,
    assert_nothing_public_carries_the_answer,
    assert_passes,
    assert_rounding_is_not_a_method_error,
    leaks_in,
)
from gearlib.check import _core

F = Fraction
S = sympy.Symbol
_NAMES = {"N": S("N")}  # a number of planets, not sympy's N()


def _stepped_model():
    # the reducer of exercise 1.2 with the reader's own link ids and order
    return {"links": {10: "carrier", 20: "ring", 30: "planet", 40: "sun"},
            "turning_pairs": [[10, 40, "z"], [10, 30, "p"], [10, 20, "z"]],
            "gear_pairs": [{"gears": [30, 20], "teeth": [15, 69], "type": "internal"},
                           {"gears": [40, 30], "teeth": [18, 36]}]}


def _offset_crank(e, mu=0.1, a2=3.0):
    """The slider-crank of exercise 7.4 as data: crank 1, coupler a2, slide at height e."""
    cx = 1.0 + math.sqrt(a2 ** 2 - e ** 2)
    return {"space": "planar", "links": {10: "frame", 11: "crank", 12: "coupler", 13: "slider"}, "ground": 10,
            "joints": [{"name": "A", "kind": "revolute", "links": [10, 11], "point": [0, 0]},
                       {"name": "B", "kind": "revolute", "links": [11, 12], "point": [1, 0]},
                       {"name": "C", "kind": "revolute", "links": [12, 13], "point": [cx, e]},
                       {"name": "D", "kind": "prismatic", "links": [13, 10], "point": [cx, e], "axis": [-1, 0],
                        "friction": {"mu": mu}}],
            "ports": [{"name": "torque", "joint": "A", "role": "input"}, {"name": "load", "joint": "D",
                                                                          "role": "output"}]}


def _t_b(a1, a2, deg):
    th = math.radians(deg)
    bx = a1 * math.cos(th)
    cx = bx + math.sqrt(a2 ** 2 - (a1 * math.sin(th)) ** 2)
    return cx / (bx - cx)


def _limb1_force(mx, my, mz):
    import numpy as np

    rows = []
    for k in range(3):
        al = 2 * math.pi * k / 3
        v = np.array([mx - 0.5 * math.cos(al), my - 0.5 * math.sin(al), mz])
        rows.append(v / np.linalg.norm(v))
    return float(np.linalg.solve(np.array(rows).T, [0.0, 0.0, 10_000.0])[0])


def _stepped_wrong(change):
    data = _stepped_model()
    change(data)
    return data


def _crcr_model():
    # the set of exercise 2.5 with the reader's own link ids and order
    return {"links": {10: "A", 11: "B", 12: "S1", 13: "S2", 14: "P1", 15: "P2"},
            "turning_pairs": [[10, 12, "x"], [10, 11, "x"], [11, 13, "x"], [10, 14, "p"], [11, 15, "q"]],
            "gear_pairs": [{"gears": [12, 14], "teeth": [27, 24]}, {"gears": [14, 11], "teeth": [24, 75], "type": "internal"},
                           {"gears": [13, 15], "teeth": [33, 21]}, {"gears": [15, 10], "teeth": [21, 75], "type": "internal"}]}


def _crcr_wrong(change):
    data = _crcr_model()
    change(data)
    return data


def _wolfrom_model():
    # the reducer of exercise 3.5 with the reader's own link ids and order
    return {"links": {40: "carrier", 20: "housing", 30: "output ring", 10: "sun", 50: "planet"},
            "turning_pairs": [[20, 10, "z"], [20, 30, "z"], [10, 40, "z"], [40, 50, "p"]],
            "gear_pairs": [{"gears": [10, 50], "teeth": [18, 27]}, {"gears": [50, 20], "teeth": [27, 72], "type": "internal"},
                           {"gears": [50, 30], "teeth": [24, 69], "type": "internal"}]}


def _wolfrom_wrong(change):
    data = _wolfrom_model()
    change(data)
    return data


def _centre_model():
    # the centre differential of exercise 6.8 with the reader's own link ids and order
    return {"links": {10: "sun", 20: "ring", 30: "inner planet", 40: "outer planet", 50: "carrier", 90: "housing"},
            "turning_pairs": [[90, 50, "a"], [90, 10, "a"], [90, 20, "a"], [50, 30, "p"], [50, 40, "q"]],
            "gear_pairs": [{"gears": [10, 30], "teeth": [30, 17]}, {"gears": [40, 30], "teeth": [19, 17]},
                           {"gears": [40, 20], "teeth": [19, 78], "type": "internal"}]}


def _centre_wrong(change):
    data = _centre_model()
    change(data)
    return data


def _bevel_model(change=None):
    # the differential of exercise 4.10 with the reader's own ids and pair order: theta_i - theta_j of a
    # pair is the angle from i's axis to j's, negated (axes pointing away from the apex: left pi, right 0,
    # planet pi/2), so (left, planet) has -pi/2 and (planet, right) has -pi/2
    data = {"links": {10: "case", 20: "planet", 30: "left gear", 40: "right gear"},
            "turning_pairs": [[10, 30, "x"], [10, 40, "x"], [10, 20, "y"]],
            "gear_pairs": [{"gears": [30, 20], "teeth": [30, 18], "type": "bevel", "angles": ["-pi/2", "0"]},
                           {"gears": [20, 40], "teeth": [18, 30], "type": "bevel", "angles": ["0", "pi/2"]}]}
    if change:
        change(data)
    return data


def _two_bsf(big, small, alpha, f_r):
    import math

    g = small * math.cos(math.radians(alpha)) / big
    return big / small * (1 - g * g) * f_r


def _stepped_with_losses(change=None, eta=None):
    # the reducer of exercise 5.8 with the reader's own ids; its mesh efficiencies named by link ids
    data = {"links": {10: "carrier", 20: "ring", 30: "planet", 40: "sun"},
            "turning_pairs": [[10, 40, "z"], [10, 30, "p"], [10, 20, "z"]],
            "gear_pairs": [{"gears": [30, 20], "teeth": [16, 76], "type": "internal"},
                           {"gears": [40, 30], "teeth": [20, 40]}]}
    if change:
        change(data)
    return {"model": data, "eta": eta or {(40, 30): 0.975, ("planet", "ring"): 0.99}}


def _second_gear(eta0):
    set2 = eta0 * (1 + 2) / (eta0 * 2 + 1)                  # sun held, carrier in, ring out
    set4 = (1 + eta0 * 85 / 23) / (1 + 85 / 23)             # ring held, sun in, carrier out
    return set2 * set4


def _fast():
    return 0.985**2 * 0.97 * 5 * 12 / (1 + 0.985**2)


def _diff_efficiency():
    slow = 0.97 * 5 * 12 / (1 + 0.985**2)
    return (slow * 24 + _fast() * 31) / (12 * 5 * (24 + 31) / 2)


# name -> (reference worked by hand, [typical wrong answers])
ANSWERS = {
    # ---------------------------------------------------------------- 0 introduction
    # -N1/N2 = -21/56
    "intro_gear_ratio": (F(-3, 8), [F(3, 8), F(-8, 3), "0.375"]),
    # N_s/(N_s + N_r) = 30/102
    "intro_planetary_ratio": (F(5, 17), [F(12, 17), F(72, 30), F(17, 5)]),
    # omega_3 - omega_4 = E (0 - omega_4): omega_4/omega_3 = 1/(1 - E)
    "intro_sun_held": ("1/(1 - e_1_2*e_2_3)", ["e_1_2*e_2_3/(e_1_2*e_2_3 - 1)", "1 - e_1_2*e_2_3", F(5, 7)]),
    # carrier held: e_13 = (-22/25)(25/72)
    "intro_star": (F(-11, 36), [F(11, 36), F(-22, 25)]),
    "intro_willis_frame": ({"link": "the carrier", "reason": "A"},
                           [{"link": "the frame", "reason": "A"}, ("the carrier", "D"), ("gear a", "C")]),
    # one module: N_ring = 21 + 2 * 27 = 75; ring held: 21 / (21 + 75)
    "intro_data_sheet": ({"reason": "A", "ring": 75, "ratio": F(7, 32)},
                         [("B", 48, F(7, 31)), ("A", 72, F(7, 31)), ("A", 75, F(-7, 32))]),
    # ---------------------------------------------------------------- 1 graph representation
    # 4 holds 2 on b and is coaxial with 5 through 4-1-0-5 on a
    "graph_carrier": (4, [0, 5, "1"]),
    "graph_model_stepped": (_stepped_model(), [
        _stepped_wrong(lambda d: d["gear_pairs"][0].pop("type")),                       # ring as an external gear
        _stepped_wrong(lambda d: d["gear_pairs"][1].update(teeth=[36, 18])),             # teeth swapped
        _stepped_wrong(lambda d: d["turning_pairs"].__setitem__(1, [20, 30, "p"]))]),    # planet on the ring
    # rows omega_b - omega_c - e (omega_a - omega_c), columns 0, 1, 2, 4, 5, in another order and scaled
    "graph_willis_matrix": ([[0, 0, "-2*e_2_5", "2*e_2_5 - 2", 2], [0, "-e_1_2", 1, "e_1_2 - 1", 0],
                             [-1, 0, "e_2_0", "1 - e_2_0", 0]],
                            [[[0, 0, "-e_2_5", "e_2_5 - 1", 1], [0, "-e_1_2", 1, "e_1_2 - 1", 0],
                              [1, 0, "-e_2_0", 0, "e_2_0 - 1"]],
                             [[0, "-e_1_2", 1, "e_1_2 - 1", 0], [1, 0, "-e_2_0", "e_2_0 - 1", 0]]]),
    # (-18/54)(-12/48)
    "graph_compound_ratio": (F(1, 12), [F(-1, 12), 12, F(-1, 3)]),
    # the idler cancels: (-24/31)(-31/40) = 24/40
    "graph_idler": (F(3, 5), [F(-3, 5), F(5, 3), F(-24, 31)]),
    # step 2 should read +N_2/N_3; then omega_4/omega_1 = 22/(22 + 78)
    "graph_mistake_derivation": ({"step": "2", "ratio": F(11, 50)},
                                 [{"step": "5", "ratio": F(-11, 28)}, ("2", F(-11, 28)), ("4", F(11, 50))]),
    # 7 links, J_R = 6 (a tree), J_G = 4
    "graph_dof_simpson": ({"dof": 2, "reason": "A"}, [(2, "B"), (3, "A"), (1, "D")]),
    # J_R = 5, J_G = 6: count -1; rank: 5 unknowns, 4 independent equations: 1
    "graph_three_planets": ({"count": -1, "rank": 1, "reason": "A"},
                            [(-1, -1, "A"), (1, 1, "D"), {"count": -1, "rank": 1, "reason": "B"}]),
    # e35 (w3 - w7) = e45 (w4 - w7)
    "graph_case_symbolic": ("(e_3_5*omega_3 - e_4_5*omega_4)/(e_3_5 - e_4_5)",
                            ["(omega_3 + omega_4)/2", "(e_4_5*omega_3 - e_3_5*omega_4)/(e_4_5 - e_3_5)",
                             "e_3_5*omega_3 - e_4_5*omega_4"]),
    # case 22 rad/s, omega_2 = 22/(-1/5)
    "graph_differential_pinion": (-110, [22, 110, F(-22, 5), "-110 rpm"]),
    # case 21.5, new convention e = +1/5: omega_2 = 107.5
    "graph_bevel_sign": ({"ratio": F(1, 5), "pinion": F(215, 2), "reason": "A"},
                         [(F(-1, 5), F(-215, 2), "B"), (F(1, 5), F(-215, 2), "A"), (5, F(215, 2), "C")]),
    # N1 (N4 N2 - N3 N5) / ((N1 + N5) N4 N2) = 18 * 30 / (88 * 1500)
    "graph_humpage_ratio": (F(9, 2200), [F(9, 44), F(-63, 250), "0.004091"]),
    "graph_design_planetary": ({"sun": 30, "planet": 54, "ring": 138},
                               [{"sun": 30, "planet": 54, "ring": 140}, {"sun": 20, "planet": 36, "ring": 92},
                                {"sun": 18, "planet": 33, "ring": 84}]),
    # ---------------------------------------------------------------- 2 kinematic units
    "units_series": ([{3, 1, 2, 0}, {5, 3, 4, 0}], [[{1, 2, 0}, {3, 4, 0}], [{0, 1, 2, 3, 4, 5}],
                                                     [{3, 1, 2}, {5, 3, 4}]]),
    "unit_type_series": ("K4-1S", ["K4-1", "K5-2", "K3-1"]),
    "linkage_series": (("two-link chain", "a"), [("coaxial triangle", "B"), ("2-link chain", "C")]),
    "atlas_single_unit_chains": (None, [81, 54, 7]),  # counted in test_single_unit_chains_by_another_route
    "units_model_crcr": (_crcr_model(), [
        _crcr_wrong(lambda d: d["gear_pairs"][1].pop("type")),                          # front ring external
        _crcr_wrong(lambda d: d["turning_pairs"].__setitem__(4, [10, 15, "q"])),         # P2 on A, not on B
        _crcr_wrong(lambda d: d["gear_pairs"][3].update(gears=[15, 11]))]),              # P2 meshes B: loop
    # step 4 joins common *gears*; in the unit of carrier A, B is its only common gear: sun-planet-ring, K4-1
    "units_mistake_crcr": ({"step": "4", "type": "K4-1"},
                           [{"step": "5", "type": "K4-1S"}, ("4", "K4-1S"), ("3", "K4-1")]),
    # FGEs: planet set 2 (suns 1, ring 3) and planet set 5 (sun 6, ring 3); units: one tree 1-2-3-5-6 on carrier 4
    "units_fge_predict": ({"fges": 2, "units": 1, "reason": "A"},
                          [(2, 2, "B"), (1, 1, "A"), {"fges": 2, "units": 1, "reason": "D"}]),
    # omega_0 - omega_5 = e_3_4 e_4_0 (omega_3 - omega_5)
    "units_block_derive": ("(omega_0 - e_3_4*e_4_0*omega_3)/(1 - e_3_4*e_4_0)",
                           ["-e_3_4*e_4_0*omega_3/(1 - e_3_4*e_4_0)", "(omega_3 - e_3_4*e_4_0*omega_0)/(1 - e_3_4*e_4_0)",
                            "e_3_4*e_4_0*omega_3"]),
    # units {A, S1, P1, B} and {B, S2, P2, A}: A held and S1 driven solve the first; S2 only in the second
    "units_plan_design": ({"held": "A", "input": "S1", "output": "S2"},
                          [{"held": "A", "input": "S1", "output": "B"}, {"held": "S2", "input": "S1", "output": "A"},
                           {"held": "P1", "input": "S1", "output": "S2"}]),
    # a star (the planet meshes 1, 0 and 5) with all three outer gears on axis a; no common links
    "units_star_type": ("K5-7", ["K5-7D", "K5-4", "K4-1"]),
    "units_three_planets": ({"units": 1, "reason": "A"}, [(3, "B"), (1, "D"), (1, "C")]),
    # ---------------------------------------------------------------- 3 unit-by-unit gains
    # E_25 = (-34/22)(22/78) = -17/39; Rule 2: E_25 - 1
    "gain_rule2": ({"gain": F(-56, 39), "rule": "2"}, [(F(-17, 39), "2"), (F(-56, 39), "1"), (F(56, 39), "2")]),
    # KU1: -18/45; KU2: -1/(E_51 - 1), E_51 = (78/21)(-21/36) = -13/6
    "propagation_fig1": (F(-12, 95), [F(-2, 5), F(6, 19), F(12, 95)]),
    # KU1 with 5 held: omega_2 = omega_4 (E - 1)/E, E = e23 e35; KU2 on its held carrier: omega_8 = E_28 omega_2
    "third_gear": ("e_1_7*e_7_8*(e_2_3*e_3_5 - 1)/(e_1_6*e_6_2*e_2_3*e_3_5)",
                   ["e_1_7*e_7_8/(e_1_6*e_6_2)", "(e_2_3*e_3_5 - 1)/(e_2_3*e_3_5)", 1]),
    # Chen's gains, input over output: TU-2 on link 1 gives 1/(e45 e57)
    "structure_matrix": ([[1, 1, 1], [0, "1/(e_4_5*e_5_7)", "1/e_8_9"], [0, "1/(e_4_5*e_5_7*e_7_3)", "1/(e_8_9*e_9_3)"]],
                         [[[1, 0, 0], [1, "1/(e_4_5*e_5_7)", "1/(e_4_5*e_5_7*e_7_3)"], [1, "1/e_8_9", "1/(e_8_9*e_9_3)"]],
                          [[1, 1, 1], [0, "e_4_5*e_5_7", "e_8_9"], [0, "e_4_5*e_5_7*e_7_3", "e_8_9*e_9_3"]],
                          [[1, 1], [0, "1/e_8_9"]]]),
    # E_05 = (72/27)(24/69) = 64/69, E_01 = (72/27)(-27/18) = -4; Rule 5: (64/69 - 1)/(-4 - 1)
    "gains_model_wolfrom": (_wolfrom_model(), [
        _wolfrom_wrong(lambda d: d["gear_pairs"][2].update(teeth=[27, 69])),              # planet not stepped
        _wolfrom_wrong(lambda d: d["gear_pairs"][2].pop("type")),                        # output ring external
        _wolfrom_wrong(lambda d: d["gear_pairs"][1].pop("type"))]),                       # fixed ring external
    "gains_wolfrom_rule": ({"rule": "5", "gain": F(1, 69)}, [("5", F(-1, 115)), ("1", F(1, 69)), ("5", F(-1, 69))]),
    # rear unit, 4 held: omega_1 = -(78/34) omega_3; front unit: omega_3 (72 + 34) = 72 omega_2 + 34 omega_1
    "gains_simpson_first": (F(9, 23), [F(36, 53), F(-17, 39), F(72, 28)]),
    # (21/102)(28/94), in either order
    "gains_series_predict": (F(49, 799), [F(7, 34), F(14, 47), F(-49, 799)]),
    # theta_25 = theta_24 - theta_54 = -8 + 4; theta_35 = (-36/18)(-4)
    "gains_triangle_mistake": ({"step": "3", "speed": 8}, [{"step": "5", "speed": 24}, ("3", 24), ("4", 8)]),
    # second gear 1 + 44/82 = 1.537, first 1 + 144/82 = 2.756; (44 + 82)/3 and (44 + 100)/3 whole
    "gains_simpson_design": ({"sun": 44, "front_planet": 19, "front_ring": 82, "rear_planet": 28, "rear_ring": 100},
                             [{"sun": 44, "front_planet": 19, "front_ring": 82, "rear_planet": 28, "rear_ring": 101},
                              {"sun": 30, "front_planet": 18, "front_ring": 66, "rear_planet": 18, "rear_ring": 66},
                              {"sun": 46, "front_planet": 19, "front_ring": 84, "rear_planet": 28, "rear_ring": 102}]),
    # row 3 of A: 1/(e45 e57 e73) = 8/9 and 1/(e89 e93) = -3/4; 7 (8/9) + 5 (-3/4)
    "gains_robot_torque": (F(89, 36), [F(-9, 2), F(29, 24), F(56, 9)]),
    # D+B: input joined to the held sun; B+L: both sets stand, the input shaft is free
    "gains_shift_combinations": ({"D+B": "tie-up", "B+L": "output held", "reason": "A"},
                                 [{"D+B": "over-constrained", "B+L": "output held", "reason": "C"},
                                  ("gear", "tie-up", "B"), ("tie-up", "under-constrained", "A")]),
    # lever: carrier in the middle, (30 + 78) omega_c = 30 omega_s + 78 omega_r
    "gains_lever_split": (F(13931, 5), [F(-13931, 5), F(108 * 1650 - 30 * 1213, 78), F(30 * 1650 + 78 * 1213, 108)]),
    # ---------------------------------------------------------------- 4 complex adjacency
    "adjacency_planet_ratio": ("5/2*exp(I*pi/3)", [-2.5, 2.5, "2/5*exp(-I*pi/3)", "-5/2*exp(I*pi/3)", 1.25]),
    # carrier 20*30/120 = 5 Hz; sun relative 15 Hz; 30 teeth
    "adjacency_mesh_frequency": (450, [600, 300, 1800, -450, 2827]),
    # planet relative to the carrier: 15 Hz
    "adjacency_planet_tooth_frequency": (15, [10, 450, 5, 20, -15]),
    # (9/2)(1 - 6/40) * 15
    "adjacency_outer_ring_frequency": (F(459, 8), [F(153, 4), F(621, 8), F(135, 2), 135, "-57.375"]),
    # 1200 rpm = 20 Hz; carrier 20 * 19/96; planet pass 4 f_c = 95/6; sun tooth 4 (20 - f_c) = 385/6
    "adjacency_planetary_lines": ({"planet_pass": F(95, 6), "sun_fault": F(385, 6)},
                                  [{"planet_pass": F(95, 24), "sun_fault": F(385, 6)}, (F(95, 6), 80),
                                   (F(385, 6), F(95, 6)), ("15.83 Hz", "403.2")]),
    # ring held: the carrier turns at 21/96 of the sun; a ring tooth meets 3 planets per carrier turn
    "adjacency_ring_fault": (F(21, 32), [F(75, 32), F(7, 32), F(525, 32), "0.6563 Hz"]),
    # f_c = f_s Z_s/(Z_s + Z_r); N (f_s - f_c)
    "adjacency_sun_fault_formula": ("N*Z_r*f_s/(Z_s + Z_r)", ["N*Z_s*f_s/(Z_s + Z_r)", "N*f_s",
                                                             "Z_r*f_s/(Z_s + Z_r)", F(375, 8)]),
    # pinion 25 Hz, mesh 600 Hz; gcd(24, 90) = 6, lcm 360; wheel 25 * 24/90 = 20/3 Hz
    "adjacency_hunting_tooth": ({"assembly": 100, "hunting": F(5, 3), "sideband": F(1780, 3)},
                                [(25, F(5, 3), F(1780, 3)), (100, F(600, 2160), 575), (600, 25, F(1820, 3))]),
    # theta_a - theta_b must be the angle from a's axis to b's (both pointing away from the apex)
    "adjacency_bevel_angles": ({"N_a": 20, "N_b": 61, "theta_a": "pi/2", "theta_b": 0},
                               [{"N_a": 20, "N_b": 60, "theta_a": 0, "theta_b": 0},
                                {"N_a": 20, "N_b": 60, "theta_a": "-pi/2", "theta_b": 0},
                                {"N_a": 20, "N_b": 50, "theta_a": "pi/2", "theta_b": 0}]),
    "adjacency_bevel_model": (_bevel_model(), [
        _bevel_model(lambda d: d["gear_pairs"][1].update(angles=["pi/2", "0"])),        # right gear reversed
        _bevel_model(lambda d: d["gear_pairs"][0].update(teeth=[18, 30])),              # teeth swapped
        _bevel_model(lambda d: d["gear_pairs"][0].update(angles=["0", "0"]))]),         # spur-like angles
    # 19 + 2 * 20 = 59; (19 + 59)/3 = 26; reduction 78/19 = 4.1; mesh 19 * 25 * 59/78 = 359 Hz; no common factors
    "adjacency_quiet_planetary": ({"sun": 19, "planet": 20, "ring": 59},
                                  [{"sun": 20, "planet": 31, "ring": 82}, {"sun": 19, "planet": 20, "ring": 60},
                                   {"sun": 24, "planet": 24, "ring": 72}]),
    # 2 BSF = (D_m/d_b)(1 - g^2) f_r, g = 11 cos 25 deg/62, f_r = 30 Hz; step 3 divides by cos(alpha) too
    "adjacency_ball_line": ({"step": "3", "frequency": _two_bsf(62, 11, 25, 30)},
                            [("3", 181.7), ("2", _two_bsf(62, 11, 25, 30)), ("3", _two_bsf(62, 11, 25, 30) / 2)]),
    "adjacency_bearing_placement": ({"speed": "C", "reason": "B"}, [("A", "A"), ("C", "C"), ("B", "B")]),
    # f_r = 1750/60 = 175/6 Hz, g = 9/46: BPFI (10/2)(1 + g) f_r, FTF (1 - g) f_r/2, BPFI + f_r
    "adjacency_shaft_bearing": ({"bpfi": F(10, 2) * F(55, 46) * F(175, 6), "ftf": F(37, 92) * F(175, 6),
                                 "sideband": F(10, 2) * F(55, 46) * F(175, 6) + F(175, 6)},
                                [(F(10, 2) * F(37, 46) * F(175, 6), F(55, 92) * F(175, 6), 145.2),
                                 ("174.4", "11.73", "145.2"), ("1096", "73.7", "1279")]),
    # ---------------------------------------------------------------- 5 Davies efficiency
    # r1 r2 (1 - eta)/(r1 + eta r2) = 0.06/2.94
    "davies_pair_zeta": (F(1, 49), [0.06 / 2.97, 0.03, -1 / 49, 1.0]),
    # Laus eq. (49), r1 = 1, r2 = 2, zeta_12 = 1/49: (2 - zeta_B - zeta_12)/(2 (1 + zeta_A + zeta_12))
    "davies_pair_bearings": ((2 - 0.03 - 1 / 49) / (2 * (1 + 0.012 + 1 / 49)),
                             [0.97, (2 - 0.012 - 1 / 49) / (2 * (1 + 0.03 + 1 / 49)), 0.97 * 0.988 * 0.97,
                              (2 - 0.03) / (2 * 1.012)]),
    # eq. (76): 0.9604 * 500 / (1400 - 0.9604 * 900)
    "davies_epicyclic_efficiency": (0.9604 * 500 / (1400 - 0.9604 * 900), [0.88912, 1.1247076, 0.9604, 89.65]),
    # 40 * 39 / (40 * 39 - 64 * 15)
    "davies_recirculation": (F(13, 5), [1, F(14, 5), F(-13, 5)]),
    # (H1) with eta_12 = 0.99, eta_25 = 0.98, eta_43 = 0.985
    "davies_humpage_efficiency": (136 * (20 + 0.99 * 0.98 * 76) / (96 * (1960 - 0.98 * 0.985 * 1824)),
                                  [0.99 * 0.98 * 0.985, 0.98, 0.776897, 1 / 0.666314]),
    "davies_humpage_driver": (5, [2, 1, 6]),
    # carrier in, sun out, ring held: relative to the carrier the ring drives the sun, so T_sun = eta0 T_ring/k,
    # k = Z_r/Z_s; eta = -P_sun/P_carrier = eta0 (1 + k)/(eta0 + k)
    "davies_planetary_formula": ("eta_1*eta_2*(Z_s + Z_r)/(eta_1*eta_2*Z_s + Z_r)",
                                 ["(Z_s + eta_1*eta_2*Z_r)/(Z_s + Z_r)", "eta_1*eta_2",
                                  "(eta_1*eta_2*Z_s + Z_r)/(eta_1*eta_2*(Z_s + Z_r))", 0.969]),
    "davies_model_efficiency": (_stepped_with_losses(), [
        _stepped_with_losses(eta={(40, 30): 0.99, (30, 20): 0.975}),                         # efficiencies exchanged
        _stepped_with_losses(lambda d: d["gear_pairs"][0].pop("type")),                      # ring external
        _stepped_with_losses(eta={("sun", "planet"): 0.975})]),                              # a mesh left out
    # eq. (76) with eta_13 eta_42 = 0.970225: 485.11/(1400 - 873.20) = 0.9209
    "davies_design_etas": ({"eta_13": 0.985, "eta_42": 0.985},
                           [{"eta_13": 0.99, "eta_42": 0.99}, {"eta_13": 0.98, "eta_42": 0.98},
                            {"eta_13": 0.999, "eta_42": 0.97}]),
    "davies_why_carrier": ({"observer": "the carrier", "reason": "C"},
                           [("the frame", "D"), ("the carrier", "A"), ("the planet", "C")]),
    # (H1) at 0.97 per mesh: 136 (20 + 0.9409 * 76)/(96 (1960 - 0.9409 * 1824))
    "davies_humpage_axis": ({"step": "2", "efficiency": 136 * (20 + 0.9409 * 76) / (96 * (1960 - 0.9409 * 1824))},
                            [("2", 0.3289), ("4", 0.5317), ("2", 0.97**3)]),
    # a = r1 r4 = 37 * 19, b = r2 r3 = 38 * 18, r1 < r2, input 2: eq. (78) (b - eta^2 a)/(b - a)
    "davies_self_locking": ((684 - 0.9604 * 703) / (684 - 703),
                            [0.9604 * 19 / (703 - 0.9604 * 684), -(684 - 0.9604 * 703) / (684 - 703), -2.15]),
    # ring 4 held (set 1 locked by A and B): set 2 carrier in, ring out, sun held, k = 2; set 4 sun in, carrier
    # out, ring held, k = 85/23; eta0 = 0.975 * 0.985
    "davies_second_gear": (_second_gear(0.975 * 0.985), [
        (1 + 0.975 * 0.985 * 85 / 23) / (1 + 85 / 23), (0.975 * 0.985) ** 2, _second_gear(0.98 * 0.99)]),
    # case torque 0.97 * 5 * 12 = 58.2; slow 58.2/(1 + 0.985^2), fast 0.985^2 times it; out over 12 * 5 * 27.5 in
    "davies_differential": ({"torque": _fast(), "efficiency": _diff_efficiency()},
                            [(58.2 / (1 + 0.985**2), _diff_efficiency()), (29.1, _diff_efficiency()),
                             (_fast(), 0.97)]),
    # chord D (2 -> 3) closes through B reversed, A and C; chord E (0 -> 2) through C and A reversed
    "davies_circuit_matrix": ([[1, -1, 1, 1, 0], [-1, 0, -1, 0, 1]],
                              [[[-1, 1, -1, -1, 0], [1, 0, 1, 0, -1]], [[1, -1], [-1, 0], [1, -1], [1, 0], [0, 1]],
                               [[1, 1, 1, 1, 0], [1, 0, 1, 0, 1]]]),
    # ---------------------------------------------------------------- 6 differential synthesis
    "synth_ground_links": ([1, 2, 3, 6], [[1, 2, 3], [1, 2, 3, 6, 7], "4", [4, 5]]),
    # omega_4 = e14 omega_1 and e37 (omega_3 - omega_1) = e67 (omega_6 - omega_1)
    "synth_constraint": ("e_1_4*e_3_7*omega_3 + (e_6_7 - e_3_7)*omega_4 - e_1_4*e_6_7*omega_6",
                         ["e_1_4*e_3_7*omega_3 + (e_3_7 - e_6_7)*omega_4 - e_1_4*e_6_7*omega_6",
                          "omega_3 + omega_4", [0, 1, 1], "e_1_4*omega_3 - omega_4"]),
    "synth_redundant_links": ([5], [[5, 7], [1], (1, 5, 7)]),
    "synth_many_grounds": (None, [11, 25, 50]),  # counted in test_chains_with_many_grounds_by_another_route
    # ground 1: omega_7 = e37 omega_3 = e67 omega_6
    "synth_two_constraints": ({"ground": 1, "terminals": [3, 6, 7], "reason": "A"},
                              [(1, [3, 6, 7], "D"), (2, [1, 3, 6], "A"), (1, [2, 3, 6], "A")]),
    # a one-dof four-link chain (rotation graphs with 3 and 2 kinds of link) and a gear pair on a
    # carrier (2 kinds) share one link: (3 + 2) * 2; counted in test_fractionated_six_by_another_route
    "synth_fractionated_six": (10, [12, 42, 3]),
    "diff_model": (_centre_model(), [
        _centre_wrong(lambda d: d["gear_pairs"][2].pop("type")),                          # ring as an external gear
        _centre_wrong(lambda d: d["gear_pairs"].__setitem__(0, {"gears": [10, 40], "teeth": [30, 19]})),  # wrong planet
        _centre_wrong(lambda d: d["turning_pairs"].__setitem__(4, [90, 30, "q"]))]),      # planet on the housing
    # relative to the carrier omega_r - omega_c = (N_s/N_r)(omega_s - omega_c): N_s w_s - N_r w_r + (N_r - N_s) w_c = 0;
    # torques in proportion to the coefficients: 30 / (78 - 30)
    "diff_torque_split": ({"ratio": F(5, 8), "reason": "A"},
                          [(F(8, 5), "A"), (F(5, 13), "A"), (F(5, 8), "D"), (1, "B")]),
    # N_r = 2 N_s; (84 - 42)/3 = 14; centres 29 and 34 apart 16 (a triangle); 84 - 42 - 32 = 10 > 4
    "diff_equal_split": ({"sun": 42, "inner": 16, "outer": 16, "ring": 84},
                         [{"sun": 30, "inner": 17, "outer": 19, "ring": 78}, {"sun": 40, "inner": 16, "outer": 16, "ring": 80},
                          {"sun": 42, "inner": 20, "outer": 20, "ring": 84}]),
    # links 3, 4, 5 lie in one circuit each (N3: terminals); the only link coaxial with all three is 2
    "synth_design_dgm": ({"ground": 2, "terminals": [5, 3, 4]},
                         [{"ground": 1, "terminals": [3, 4, 5]}, {"ground": 2, "terminals": [1, 4, 5]},
                          {"ground": 2, "terminals": [3, 4, 8]}]),
    # no gear pair (6, 7); solved by sympy in test_misprint_by_another_route
    "synth_misprint": ({"symbol": "e_6_7", "constraint": "(e_2_7 - e_5_7)*(e_3_8 - e_6_8)*omega_4 + e_1_4*e_5_7*(e_3_8 - "
                        "e_6_8)*omega_5 + e_1_4*e_2_7*e_6_8*omega_6"},
                       [("e_6_8", "(e_2_7 - e_5_7)*(e_3_8 - e_6_8)*omega_4 + e_1_4*e_5_7*(e_3_8 - e_6_8)*omega_5 + "
                         "e_1_4*e_2_7*e_6_8*omega_6"),
                        ("e_6_7", "(e_2_7 - e_5_7)*(e_3_8 - e_6_7)*omega_4 + e_1_4*e_5_7*(e_3_8 - e_6_8)*omega_5 + "
                         "e_1_4*e_2_7*e_6_8*omega_6"),
                        ("e_6_7", "(e_2_7 - e_5_7)*(e_3_8 - e_6_8)*omega_4 - e_1_4*e_5_7*(e_3_8 - e_6_8)*omega_5 + "
                         "e_1_4*e_2_7*e_6_8*omega_6")]),
    # link 3 turns on link 2 (axis d); it lies in one circuit, so it must be a terminal (N3)
    "synth_left_out": ({"link": 3, "terminals": [4, 1, 3]}, [(7, [1, 4, 7]), (3, [3, 4, 8]), (6, [1, 3, 4])]),
    # ---------------------------------------------------------------- 7 Davies beyond gear trains
    # eq. (120): 1 - (0.25/pi) ln(130/50) = 1 - 0.0795775 * 0.955511
    "linkage_crank_efficiency": (1 - 0.25 / math.pi * math.log(130 / 50),
                                 [math.pi / (math.pi + 0.25 * math.log(130 / 50)), 1 - 0.25 * math.log(130 / 50),
                                  1 - 0.25 / math.pi * math.log(90 / 40)]),
    # eq. (123): pi / (pi + 0.25 ln(130/50))
    "linkage_slider_efficiency": (math.pi / (math.pi + 0.25 * math.log(130 / 50)),
                                  [1 - 0.25 / math.pi * math.log(130 / 50), 1 / (1 + 0.25 * math.log(130 / 50)),
                                   0.5]),
    # C_x = a1 cos + sqrt(a2^2 - (a1 sin - h)^2), differentiated
    "linkage_offset_speed": ("-a1*sin(theta) - a1*cos(theta)*(a1*sin(theta) - h)/sqrt(a2**2 - (a1*sin(theta) - h)**2)",
                             ["-a1*sin(theta) - a1**2*sin(theta)*cos(theta)/sqrt(a2**2 - a1**2*sin(theta)**2)",
                              "-a1*sin(theta) - a1*cos(theta)*(a1*sin(theta) + h)/sqrt(a2**2 - (a1*sin(theta) + h)**2)",
                              "-a1*sin(theta)"]),
    "linkage_model_offset": (_offset_crank(0.5), [_offset_crank(0.0), _offset_crank(0.5, mu=0.0),
                                                  _offset_crank(0.5, mu=0.2), _offset_crank(0.5, a2=2.5)]),
    # stroke 2 a1 = 0.1; efficiency 1 - (0.15/pi) ln(0.55/0.45) = 0.99042 >= 0.985; 0.5 <= 0.6
    "linkage_design_crank": ({"a1": 0.05, "a2": 0.5},
                             [{"a1": 0.1, "a2": 0.5}, {"a1": 0.05, "a2": 0.3}, {"a1": 0.05, "a2": 0.7}]),
    "linkage_concept_place": ("A", ["B", "C"]),
    "linkage_concept_annuli": ("A", ["C", "B"]),
    "linkage_concept_torques": ("A", ["B", "C"]),
    # theta = 70 deg: B_x = 2 cos 70 = 0.684040, C_x = B_x + sqrt(25 - 4 sin^2 70) = 5.317388; t_B = C_x/(B_x - C_x)
    "linkage_mistake_motion": (_t_b(2, 5, 70), [-_t_b(2, 5, 70), 1 / _t_b(2, 5, 70), 0.147634]),
    "linkage_predict_pins": (None, [0.7393, 0.5, 1.2]),       # run in test_worse_pins_by_another_route
    # virtual work: J^T f = (0, 0, 10000) with the limbs' unit vectors at M = (0, 0.25, 0.8)
    "linkage_virtual_work": (_limb1_force(0.0, 0.25, 0.8), [-_limb1_force(0.0, 0.25, 0.8), 10_000 / 3, 2000.0]),
    "linkage_explore_limb": (None, ["1", "3"]),                # found in test_the_lossiest_limb_by_another_route
}


def _numeric(value):
    """A number for the rounding test, or None for answers that are not one number."""
    if isinstance(value, (int, float, Fraction)) and not isinstance(value, bool):
        return complex(value)
    if isinstance(value, str):
        try:
            x = sympy.sympify(value, locals=_NAMES)
        except (sympy.SympifyError, SyntaxError, TypeError):
            return None
        return complex(x) if x.is_number else None
    return None


@pytest.fixture(scope="module")
def checks():
    _core._forget_predictions()
    names = gl.check.names()
    for name in names:
        check = gl.check.get(name)
        if check.predicts:  # record a guess for the book's numbers and a few variants
            for v in (None, "s1", "s2", "s3", 12345):
                check.predict(_core._SECRETS[name].prediction.choice.options.__iter__().__next__(), variant=v)
    return names


def _reference(name):
    ref = ANSWERS[name][0]
    if ref is None:
        return _core._reference(gl.check.get(name))[1]
    return ref


def test_every_check_has_reference_answers(checks):
    assert sorted(set(checks) - set(ANSWERS)) == [], "add reference answers to ANSWERS"
    assert sorted(set(ANSWERS) - set(checks)) == [], "ANSWERS names checks that do not exist"


@pytest.mark.parametrize("name", sorted(ANSWERS))
def test_reference_passes(checks, name):
    check = gl.check.get(name)
    ref = ANSWERS[name][0]
    if ref is not None:
        assert_passes(check, ref)
    assert_passes(check, _core._example(check))


@pytest.mark.parametrize("name", sorted(ANSWERS))
def test_each_variant_passes_its_own_reference(checks, name):
    check = gl.check.get(name)
    for variant in ("s1", "s2", "s3", 12345):
        assert_passes(check, _core._example(check, variant), variant)
        assert check.given(variant) == check.given(str(variant))


@pytest.mark.parametrize("name", sorted(ANSWERS))
def test_wrong_answers_get_a_hint_not_the_answer(checks, name):
    ref, wrongs = ANSWERS[name]
    check = gl.check.get(name)
    shown = ref if ref is not None else _core._reference(check)[1]
    assert len(wrongs) >= 2
    for wrong in wrongs:
        assert_hint_without_answer(check, wrong, _plain(shown))


def _plain(ref):
    """A reference as the representations of check_tools know it: expressions as sympy, a
    mechanism (a model's answer, many right ones) as nothing."""
    if isinstance(ref, str) and re.search(r"[a-z]_\d|exp|\d", ref) and not re.fullmatch(r"K\d.*|\d-link.*|[a-z]+(_\d+)+", ref):
        # (a single symbol's name, "e_6_7", is an option of a choice: kept as text)
        try:
            return sympy.sympify(ref, locals=_NAMES)
        except (sympy.SympifyError, SyntaxError, TypeError):
            return ref
    if isinstance(ref, dict):
        if "links" in ref or "mech" in ref or "model" in ref:
            return None
        return {k: _plain(v) for k, v in ref.items()}
    return ref


@pytest.mark.parametrize("name", sorted(ANSWERS))
def test_rounded_answers_pass_or_ask_for_digits(checks, name):
    ref = ANSWERS[name][0]
    check = gl.check.get(name)
    parts = ref if isinstance(ref, dict) else {None: ref}
    for key, value in parts.items():
        z = _numeric(value)
        if z is None or (z.imag == 0 and z.real == int(z.real) and abs(z.real) < 10**4):
            continue  # whole numbers and non-numbers have no digits to round
        if key is None:
            assert_rounding_is_not_a_method_error(check, z)
        else:
            for rounded_answer in (f"{z.real:.4g}",):
                answer = dict(parts, **{key: rounded_answer})
                result = check(answer)
                assert result.passed or "significant figure" in result.message or "exact value" in result.message, \
                    (name, key, result.message)


@pytest.mark.parametrize("name", sorted(ANSWERS))
def test_malformed_answers_get_a_hint_in_bounded_time(checks, name):
    check = gl.check.get(name)
    check(ANSWERS[name][0] if ANSWERS[name][0] is not None else 0)  # the reference, computed once per process
    assert_malformed_answers_get_a_hint_fast(check)


@pytest.mark.parametrize("name", sorted(ANSWERS))
def test_nothing_public_on_a_check_carries_its_answer(checks, name):
    check = gl.check.get(name)
    assert_nothing_public_carries_the_answer(check, _plain(_reference(name)))
    for variant in ("s1", "s2"):
        assert_nothing_public_carries_the_answer(check, _plain(_core._reference(check, variant)[1]))


def test_every_check_is_numbered_titled_and_marked(checks):
    seen = set()
    for info in gl.check.catalogue():
        assert info["exercise"] not in seen
        seen.add(info["exercise"])
        assert info["title"] and info["stars"] in (1, 2, 3) and 0 < info["minutes"] <= 120
        assert info["kind"] in gl.check.KINDS and info["points"] == info["stars"]
    per_chapter = {}
    for info in gl.check.catalogue():
        per_chapter.setdefault(int(info["chapter"]), []).append(info)
    assert len(per_chapter[0]) >= 3 and len({i["kind"] for i in per_chapter[0]}) >= 5
    for chapter, infos in sorted(per_chapter.items()):
        numbers = sorted(int(i["exercise"].split(".")[1]) for i in infos)
        assert numbers == list(range(1, len(numbers) + 1)), f"chapter {chapter} numbers its exercises 1, 2, ..."
        if chapter:
            assert len(infos) >= 10, f"chapter {chapter} has {len(infos)} exercises"
            kinds = {i["kind"] for i in infos}
            assert {"compute", "model", "derive", "design", "concept", "mistake", "predict"} <= kinds, chapter
    assert set(per_chapter) >= set(range(7)), "every chapter has its exercises"


# ----------------------------------------------------------------------------- independent counts
def _coaxial_neighbours(mech):
    """Links coaxial with each link: a path of thin edges with one label (own union-find)."""
    out = {link.id: set() for link in mech.links}
    for label in {tp.axis for tp in mech.turning_pairs}:
        parent = {}

        def find(x, parent=parent):
            while parent.setdefault(x, x) != x:
                x = parent[x]
            return x

        for tp in mech.turning_pairs:
            if tp.axis == label:
                parent[find(tp.links[0])] = find(tp.links[1])
        groups = {}
        for x in parent:
            groups.setdefault(find(x), set()).add(x)
        for g in groups.values():
            for x in g:
                out[x] |= g - {x}
    return out


def test_chains_with_many_grounds_by_another_route(checks):
    count = sum(1 for m in gl.atlas.geared_chains(7, 2)
                if sum(1 for x in _coaxial_neighbours(m).values() if len(x) >= 3) >= 4)
    assert gl.check.synth_many_grounds(count).passed
    assert not gl.check.synth_many_grounds(count + 1).passed


def test_single_unit_chains_by_another_route(checks):
    import networkx as nx

    count = 0
    for m in gl.atlas.geared_chains(6, 1):
        carriers = {gp.carrier for gp in m.gear_pairs}
        gears = nx.Graph([gp.gears for gp in m.gear_pairs])
        count += len(carriers) == 1 and nx.is_connected(gears)
    assert gl.check.atlas_single_unit_chains(count).passed


def test_grounds_by_another_route(checks):
    chain = next(m for m in gl.atlas.geared_chains(7, 2) if m.name == "GKC 7-2-7")
    grounds = sorted(k for k, v in _coaxial_neighbours(chain).items() if len(v) >= 3)
    assert grounds == [1, 2, 3, 6]



def test_propagation_plans_by_another_route(checks):
    """Exercise 2.9: of the 24 ordered choices of three central links, exactly those whose held
    link and input lie in one unit (and are not the chain A-B itself) and whose output lies only
    in the other unit pass; the units {A, S1, B} and {B, S2, A} are read off the description."""
    from itertools import permutations

    first, second = {"A", "S1", "B"}, {"B", "S2", "A"}
    passed = 0
    for held, inp, out in permutations(["S1", "S2", "A", "B"], 3):
        right = any({held, inp} <= u and out not in u for u in (first, second) if {held, inp} != {"A", "B"})
        result = gl.check.units_plan_design({"held": held, "input": inp, "output": out})
        assert result.passed == right, (held, inp, out, result.message)
        passed += right
    assert passed == 8


def test_simpson_designs_by_another_route(checks):
    """Exercise 3.10: every design a direct search finds (first gear 1 + (s + r2)/r1, second
    1 + s/r1) passes, and moving one ring by two teeth breaks it."""
    found = 0
    for s in range(30, 60):
        for p1 in range(17, 40):
            for p2 in range(17, 50):
                r1, r2 = s + 2 * p1, s + 2 * p2
                if max(r1, r2) > 150 or (s + r1) % 3 or (s + r2) % 3:
                    continue
                if not (abs((1 + F(s + r2, r1)) / F(274, 100) - 1) <= F(1, 100)
                        and abs((1 + F(s, r1)) / F(154, 100) - 1) <= F(1, 100)):
                    continue
                design = {"sun": s, "front_planet": p1, "front_ring": r1, "rear_planet": p2, "rear_ring": r2}
                assert gl.check.gains_simpson_design(design).passed, design
                assert not gl.check.gains_simpson_design(dict(design, rear_planet=p2 + 1, rear_ring=r2 + 2)).passed
                found += 1
    assert found >= 5


def test_chapters_2_and_3_have_ten_exercises_of_every_kind(checks):
    for chapter in (2, 3):
        infos = gl.check.catalogue(chapter)
        assert len(infos) >= 10, f"chapter {chapter} has {len(infos)} exercises"
        numbers = sorted(int(i["exercise"].split(".")[1]) for i in infos)
        assert numbers == list(range(1, len(numbers) + 1)), f"chapter {chapter} numbers its exercises 1, 2, ..."
        assert {"compute", "model", "derive", "design", "concept", "mistake", "predict"} <= {i["kind"] for i in infos}
        for info in infos:
            check = gl.check.get(info["name"])
            if any(isinstance(v, (int, str)) and re.fullmatch(r"-?\d+(\.\d+)?(/\d+)?", str(v)) for v in check.given().values()):
                assert check.variants, f"{info['exercise']} has numbers but no variants"


def _rotation_graph(circuits):
    """A chain's gear pairs as a networkx graph: a node per link and per gear pair, the pair
    joined to its two gears ("gear") and to its carrier ("carrier")."""
    import networkx as nx

    g = nx.Graph()
    for k, (a, b, c) in enumerate(circuits):
        g.add_edge(("pair", k), ("link", a), kind="gear")
        g.add_edge(("pair", k), ("link", b), kind="gear")
        g.add_edge(("pair", k), ("link", c), kind="carrier")
    return g


def test_fractionated_six_by_another_route(checks):
    """Two one-dof chains, four links and three, share one link (every way, deduplicated by
    networkx): the fractionated two-dof six-link rotation graphs."""
    import networkx as nx

    fours = [[(1, 2, 3), (2, 4, 3)], [(1, 3, 2), (2, 4, 1)]]  # three gears on a carrier; two carriers carrying each other
    three = [(5, 6, 7)]
    found = []
    for four in fours:
        for shared in (1, 2, 3, 4):
            for other in (5, 6, 7):
                glued = four + [tuple(shared if x == other else x for x in three[0])]
                g = _rotation_graph(glued)
                if not any(nx.is_isomorphic(g, h, edge_match=lambda x, y: x["kind"] == y["kind"]) for h in found):
                    found.append(g)
    assert len(found) == 10
    assert gl.check.synth_fractionated_six(len(found)).passed


def test_the_eight_link_chains_are_the_atlas_chains(checks):
    from gearlib.check.synthesis_eight import EIGHT_LINK

    atlas = {m.name: m for m in gl.atlas.geared_chains(8, 2)}
    for name, data in EIGHT_LINK.items():
        mine = gl.Mechanism.from_dict(data)
        assert mine.turning_pairs == atlas[name].turning_pairs, name
        assert [(gp.gears, gp.carrier) for gp in mine.gear_pairs] == \
            [(gp.gears, gp.carrier) for gp in atlas[name].gear_pairs], name


def test_design_dgm_and_left_out_link_by_another_route(checks):
    from gearlib.check.synthesis_eight import EIGHT_LINK

    def one_circuit(data):  # links in a single fundamental circuit (as a gear or as the carrier)
        count = {}
        for gp in data["gear_pairs"]:
            for x in (*gp["gears"], gp["carrier"]):
                count[x] = count.get(x, 0) + 1
        return {x for x, n in count.items() if n == 1}

    data = EIGHT_LINK["GKC 8-2-324"]
    terminals = one_circuit(data)
    near = _coaxial_neighbours(gl.Mechanism.from_dict(data))
    grounds = [g for g in near if terminals <= near[g]]
    assert terminals == {3, 4, 5} and grounds == [2]
    assert gl.check.synth_design_dgm({"ground": 2, "terminals": sorted(terminals)}).passed
    data = EIGHT_LINK["GKC 8-2-667"]
    (missing,) = _coaxial_neighbours(gl.Mechanism.from_dict(data))[2] - {1, 4, 7, 8}
    assert missing == 3 and one_circuit(data) == {3, 4}
    assert gl.check.synth_left_out({"link": missing, "terminals": [1, 3, 4]}).passed


def test_misprint_by_another_route(checks):
    from gearlib.check.synthesis_eight import _PRINTED, EIGHT_LINK

    w = {k: S(f"omega_{k}") for k in range(1, 9)}
    w[3] = 0  # the ground
    rows = [w[b] - w[c] - S(f"e_{a}_{b}") * (w[a] - w[c]) for a, b, c in
            ((gp["gears"][0], gp["gears"][1], gp["carrier"]) for gp in EIGHT_LINK["GKC 8-2-161"]["gear_pairs"])]
    sol = sympy.solve(rows[:4], [w[1], w[2], w[7], w[8]], dict=True)[0]
    mine = sympy.factor(sympy.numer(sympy.together(rows[4].subs(sol))))
    assert gl.check.synth_misprint({"symbol": "e_6_7", "constraint": mine}).passed
    printed = sympy.sympify(_PRINTED)
    assert not gl.check.synth_misprint({"symbol": "e_6_7", "constraint": printed}).passed
    assert printed.subs(S("e_6_7"), S("e_6_8")) != printed  # one symbol away from ...
    assert gl.check.synth_misprint({"symbol": "e_6_7", "constraint": printed.subs(S("e_6_7"), S("e_6_8"))}).passed


def test_each_broken_design_condition_is_named(checks):
    cases = {
        "tooth numbers": {"sun": 13, "inner": 14, "outer": 14, "ring": 26},
        "equal torque": {"sun": 30, "inner": 17, "outer": 19, "ring": 78},
        "planets mesh": {"sun": 42, "inner": 14, "outer": 14, "ring": 200},
        "clear of sun and ring": {"sun": 42, "inner": 20, "outer": 20, "ring": 84},
        "equal spacing": {"sun": 40, "inner": 16, "outer": 16, "ring": 80},
    }
    for condition, design in cases.items():
        result = gl.check.diff_equal_split(design)
        assert not result.passed and condition in result.details["broken"], (condition, result.message)
    # five pairs: planets 20 teeth on sun 45 clear the central gears, but overlap the next pair
    five = next(f"v{k}" for k in range(100) if gl.check.diff_equal_split.given(f"v{k}")["pairs"] == 5)
    result = gl.check.diff_equal_split({"sun": 45, "inner": 20, "outer": 20, "ring": 90}, variant=five)
    assert not result.passed and result.details["broken"] == ["neighbouring pairs"], result.message
    assert gl.check.diff_equal_split({"sun": 45, "inner": 20, "outer": 20, "ring": 90}).passed  # three pairs fit
    for condition, design in {"N2": {"ground": 3, "terminals": [2, 4, 5]}, "C3": {"ground": 1, "terminals": [3, 4, 5]},
                              "one constraint (C1)": {"ground": 1, "terminals": [5, 6, 7]},
                              "every terminal in it": {"ground": 2, "terminals": [3, 4, 8]},
                              "no redundant link": {"ground": 2, "terminals": [1, 4, 5]}}.items():
        result = gl.check.synth_design_dgm(design)
        assert not result.passed and result.details["broken"][0] == condition, (condition, result.message)


def test_worse_pins_by_another_route(checks):
    """7.9: the half lift's efficiency with the pins at 0.22, from the actuators' forces and the
    limbs' lengthening rates of the test's own kinematics (J dM/dt), integrated here."""
    import numpy as np

    robot = gl.linkages.load("laus_3upu", parameters={"mu_pin": 0.22})
    res = gl.linkages.run(robot, "lift_half")
    power = np.zeros(len(res.times))
    for i, t in enumerate(res.times):
        m = np.array([0.1, 0.2, 0.5 + 0.4 * t])
        for port, k in (("BC", 0), ("FG", 1), ("JK", 2)):
            al = 2 * math.pi * k / 3
            v = m - 0.5 * np.array([math.cos(al), math.sin(al), 0.0])
            power[i] += res.port_series(port)[i] * (v / np.linalg.norm(v)) @ np.array([0.0, 0.0, 0.4])
    energy = float(np.sum((power[1:] + power[:-1]) / 2 * np.diff(res.times)))
    eta = 10_000 * 0.2 / energy
    assert gl.check.linkage_predict_pins(eta).passed
    assert 0.7 < eta < gl.linkages.run(gl.linkages.load("laus_3upu"), "lift_half").efficiency


def test_the_lossiest_limb_by_another_route(checks):
    """7.11: each limb's annuli dissipate mu (|Q_1| + |Q_2|) |q| (eq. 129); integrated here from
    the lift's forces and the limbs' lengthening rates of the test's own kinematics."""
    import numpy as np

    res = gl.linkages.run(gl.linkages.load("laus_3upu"), "lift")
    losses = []
    for k, (b, c) in enumerate((("B", "C"), ("F", "G"), ("J", "K"))):
        al = 2 * math.pi * k / 3
        rate = []
        for t in res.times:
            v = np.array([0.1, 0.2, 0.5 + 0.4 * t]) - 0.5 * np.array([math.cos(al), math.sin(al), 0.0])
            rate.append(abs((v / np.linalg.norm(v))[2] * 0.4))
        normal = sum(abs(res.series(f"Q_{x}{i}")) for x in (b, c) for i in (1, 2))
        p = 0.11 * normal * np.array(rate)
        losses.append(float(np.sum((p[1:] + p[:-1]) / 2 * np.diff(res.times))))
    best = str(1 + int(np.argmax(losses)))
    assert gl.check.linkage_explore_limb(best).passed
    assert sum(losses) == pytest.approx(sum(v for k, v in res.losses().items() if k.startswith("Q_")), rel=1e-6)


# ----------------------------------------------------------------------------- tolerance and forms
@pytest.mark.parametrize("answer", [F(-3, 8), "-3/8", "\u22123/8", "-0.375", -0.375, "-.375", "\u22120.375",
                                    "-0.3750", "-3/8 + 0*I", sympy.Rational(-3, 8), "-37.5/100"])
def test_the_usual_forms_of_a_right_answer(checks, answer):
    assert gl.check.intro_gear_ratio(answer).passed, answer


@pytest.mark.parametrize("name, answer", [
    ("intro_planetary_ratio", "0.2941"), ("intro_planetary_ratio", 0.294), ("gain_rule2", ("-1.436", "2")),
    ("davies_pair_zeta", "0.020408"), ("davies_pair_zeta", 0.02041), ("davies_epicyclic_efficiency", "0.8965"),
    ("davies_epicyclic_efficiency", "89.65 %"), ("davies_epicyclic_efficiency", "89.65%"),
    ("davies_humpage_efficiency", "0.6663"), ("adjacency_planet_ratio", 1.25 + 2.165j),
    ("adjacency_planet_ratio", "1.25+2.165i"), ("adjacency_planet_ratio", "2.5*exp(i*pi/3)"),
    ("adjacency_planet_ratio", "5/2 e^(j pi/3)"), ("adjacency_mesh_frequency", "450 Hz"),
    ("adjacency_mesh_frequency", "2827 rad/s"), ("adjacency_mesh_frequency", "27000 rpm"),
    ("adjacency_mesh_frequency", 450.0), ("graph_differential_pinion", "-110 rad/s"),
    ("graph_differential_pinion", "\u2212110"), ("unit_type_series", "K41S"), ("unit_type_series", "k4-1s"),
    ("linkage_series", {"Kind": "Two-link chain", "REASON": "(a)"}), ("intro_sun_held", "1/(1 - e_{1,2} e_{2,3})"),
    ("intro_sun_held", 1 / (1 - S("e_1_2", positive=True) * S("e_2_3"))),
    ("graph_case_symbolic", "(e_3_5 ω_3 − e_4_5 ω_4)/(e_3_5 − e_4_5)"),
    ("adjacency_ring_fault", "0.6563 orders"), ("adjacency_ring_fault", "21/32"),
    ("adjacency_planetary_lines", ("950 rpm", "403.2 rad/s")), ("adjacency_hunting_tooth", ("100 Hz", "100 rpm", "593.3")),
    ("adjacency_sun_fault_formula", "N·Z_r·f_s/(Z_r + Z_s)"), ("davies_planetary_formula", "η_1*η_2*(Z_s + Z_r)/(η_1 η_2 Z_s + Z_r)"),
    ("davies_self_locking", "−0.4652"), ("davies_second_gear", "95.57 %"),
    ("adjacency_bevel_angles", {"N_a": 17, "N_b": 51, "theta_a": 0, "theta_b": "-π/2"}),
    ("adjacency_bevel_angles", {"N_a": 20, "N_b": 60, "theta_a": "1.571", "theta_b": 0}),
])
def test_rounded_unicode_and_unit_forms_pass(checks, name, answer):
    result = gl.check.get(name)(answer)
    assert result.passed, (answer, result.message)


@pytest.mark.parametrize("name, answer, says", [
    ("intro_planetary_ratio", "0.29", "right to 2 significant figures"),
    ("intro_planetary_ratio", "0.3", "right to 1 significant figure"),
    ("davies_pair_zeta", "0.0204", "right to 3 significant figures"),
    ("graph_humpage_ratio", "0.004091", "exact value"),
    ("adjacency_mesh_frequency", "2827", "rad/s"),
    ("adjacency_mesh_frequency", "450 mm", "unit does not fit"),
    ("intro_gear_ratio", "-3/8 Hz", "no unit"),
    ("davies_epicyclic_efficiency", 1 / 0.8964980, "exchanged input and output"),
    ("davies_epicyclic_efficiency", 1 - 0.8964980, "loss"),
    ("davies_epicyclic_efficiency", 89.65, "percentage"),
    ("davies_humpage_efficiency", 0.99 * 0.98 * 0.985, "product of the mesh efficiencies"),
    ("davies_humpage_efficiency", 0.985, "one mesh"),
    ("davies_pair_zeta", -1 / 49, "positive length"),
    ("adjacency_outer_ring_frequency", -57.375, "never negative"),
    ("adjacency_mesh_frequency", 450 * 60, "per minute"),
    ("intro_sun_held", F(5, 7), "formula"),
    ("third_gear", "e_1_7*e_7_8*(e_2_3*e_3_5 - 1)/(e_1_6*e_6_2*e_2_3*e_3_5*x)", "x"),
    ("adjacency_planetary_lines", ("99.48", "403.2"), "rad/s"),
    ("adjacency_hunting_tooth", (6000, F(5, 3), F(1780, 3)), "per minute"),
    ("adjacency_ring_fault", "0.6563 Hz", "unit does not fit"),
    ("adjacency_bevel_model", _bevel_model(lambda d: d["gear_pairs"][0].update(angles=["pi/2", "0"])), "degrees away"),
    ("adjacency_bevel_angles", {"N_a": 20, "N_b": 60, "theta_a": 0, "theta_b": 0}, "opposite senses"),
    ("adjacency_quiet_planetary", {"sun": 20, "planet": 31, "ring": 82}, "resonance"),
    ("davies_planetary_formula", "(eta_1*eta_2*Z_s + Z_r)/(eta_1*eta_2*(Z_s + Z_r))", "exchanged input and output"),
    ("davies_planetary_formula", "(Z_s + eta_1*eta_2*Z_r)/(Z_s + Z_r)", "sun as the input"),
    ("davies_second_gear", 1 / _second_gear(0.975 * 0.985), "exchanged input and output"),
    ("davies_self_locking", 1 / ((684 - 0.9604 * 703) / (684 - 703)), "exchanged input and output"),
    ("davies_model_efficiency", _stepped_with_losses(eta={(40, 30): 0.99, (30, 20): 0.975}), "loss of each mesh"),
    ("davies_design_etas", {"eta_13": 0.99, "eta_42": 0.99}, "target"),
    ("davies_circuit_matrix", [[-1, 1, -1, -1, 0], [1, 0, 1, 0, -1]], "oriented along its chord"),
])
def test_hints_fit_the_quantity(checks, name, answer, says):
    result = gl.check.get(name)(answer)
    assert not result.passed and says.lower() in result.message.lower(), result.message


def test_efficiency_hints_are_not_speed_ratio_hints(checks):
    names = ("davies_epicyclic_efficiency", "davies_humpage_efficiency", "davies_pair_bearings", "davies_second_gear",
             "davies_self_locking")
    for answer in (1 / 0.8964980, -0.8964980, 0.5, 1 / 0.6663138, 1 / 0.9556700, 1 / 0.944196, -1 / 0.4652):
        for name in names:
            message = gl.check.get(name)(answer).message
            assert not re.search("speed goes on top|output over input|external meshes|reciprocal", message), message
    for part in ({"torque": 28.66, "efficiency": 1 / 0.9681343}, {"step": "2", "efficiency": 1 / 0.5317381}):
        name = "davies_differential" if "torque" in part else "davies_humpage_axis"
        message = gl.check.get(name)(part).message
        assert "exchanged input and output" in message and "reciprocal" not in message, message
    for wrong in ("1/(eta_1*eta_2)", "(eta_1*eta_2*Z_s + Z_r)/(eta_1*eta_2*(Z_s + Z_r))"):
        message = gl.check.davies_planetary_formula(wrong).message
        assert not re.search("output over input|speed goes on top|reciprocal", message), message
    assert "external meshes" not in gl.check.davies_pair_zeta(-1 / 49).message


def test_the_hints_that_gave_answers_away_are_gone(checks):
    for answer in (1, 3, 0):
        message = gl.check.graph_dof_simpson((answer, "A")).message
        assert "seven links" not in message and "six turning" not in message, message
    message = gl.check.unit_type_series("K4-1").message
    assert "g-g" not in message and " S" not in message, message
    assert gl.check.linkage_series(("two-link chain", "A")).passed


# ----------------------------------------------------------------------------- variants, predictions, grading
def test_variants_draw_other_numbers_deterministically_across_processes(checks):
    code = ("import json, gearlib as gl; print(json.dumps({n: gl.check.get(n).given('s1234567') "
            "for n in gl.check.names() if gl.check.get(n).variants}, default=str, sort_keys=True))")
    runs = [subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                           env={**os.environ, "PYTHONHASHSEED": seed}).stdout for seed in ("1", "2")]
    assert runs[0] == runs[1]
    given = json.loads(runs[0])
    assert len(given) >= 20
    assert given["intro_gear_ratio"] != gl.check.intro_gear_ratio.given()   # not the book's numbers
    assert gl.check.intro_gear_ratio.given() == {"N1": 21, "N2": 56}         # the default is the book's
    assert "{" not in gl.check.intro_gear_ratio.statement("s1234567")


def test_a_variant_is_checked_with_its_own_numbers(checks):
    check = gl.check.intro_gear_ratio
    g = check.given("s99")
    mine = F(-g["N1"], g["N2"])
    assert check(mine, variant="s99").passed
    assert not check(mine).passed or mine == F(-3, 8)
    assert not check(F(-3, 8), variant="s99").passed or mine == F(-3, 8)


def test_a_prediction_is_recorded_before_the_answer_and_then_kept(checks):
    import uuid

    variant = f"p-{uuid.uuid4().hex}"  # a variant no other test has predicted
    check = gl.check.graph_idler
    g = check.given(variant)
    right = F(g["n1"], g["n3"])
    first = check(right, variant=variant)
    assert not first.passed and "predict" in first.message
    assert check.predict("the size changes", variant=variant)
    result = check(right, variant=variant)
    assert result.passed and result.details["prediction"] == "the size changes"
    assert result.details["prediction_right"] is False
    late = check.predict("the sign changes", variant=variant)
    assert not late.passed and "checked already" in late.message
    assert gl.check.graph_idler(right, variant=variant).details["prediction"] == "the size changes"
    assert not check.predict("maybe", variant=variant + "-2").passed


def test_a_result_is_what_a_grader_needs(checks):
    ok = gl.check.graph_humpage_ratio(F(9, 2200))
    assert ok and ok.points == 3 and ok.score == 3 and ok.exercise == "1.12"
    half = gl.check.graph_dof_simpson((2, "B"))
    assert not half and 0 < half.score < half.points and half.details == {"dof": True, "reason": False}
    data = half.to_dict()
    assert json.loads(json.dumps(data)) == data and not leaks_in(json.dumps(data), 2 + 0.5)


def test_a_model_is_checked_by_its_motion_not_its_text(checks):
    data = _stepped_model()
    roles = {"sun": 40, "planet": 30, "ring": 20, "carrier": 10}
    unnamed = {**data, "links": [10, 20, 30, 40]}
    assert gl.check.graph_model_stepped((unnamed, roles)).passed
    yaml_text = gl.Mechanism.from_dict(data).to_dict()
    import yaml

    assert gl.check.graph_model_stepped(yaml.safe_dump(yaml_text)).passed
    message = gl.check.graph_model_stepped(unnamed).message
    assert "name the links" in message.lower()


# ----------------------------------------------------------------------------- the tests can fail
def _toy(spec, compute, **kw):
    """A check outside the registry, for the tests of the machinery."""
    name = f"toy_{len(_core._SECRETS)}"
    check = _core.Check(name, "9.99", "toy", 1, 1, "compute", "", spec.form)
    _core._SECRETS[name] = _core._Secret(compute, spec, {}, None, None)
    return check


class _ExactOnly(gl.check.Value):
    """Over-strict: compares like the old checks, relative tolerance 1e-6."""

    def judge(self, answer, reference, params):
        from gearlib.check._read import read

        ok = abs(complex(read(answer).value) - complex(reference)) <= 1e-6 * abs(complex(reference))
        return gl.check.Verdict(ok, "Well done" if ok else "Go back to the Willis equations.")


class _LeakyHint(gl.check.Value):
    def judge(self, answer, reference, params):
        return gl.check.Verdict(False, f"Not yet: the ratio is {reference}.")


class _LeakyCheck(_core.Check):
    __slots__ = ()
    _PUBLIC = (*_core.Check._PUBLIC, "expected")

    @property
    def expected(self):
        return _core._state(self.name, None)[1]


def test_each_generic_test_fails_on_a_broken_check():
    strict = _toy(_ExactOnly("ratio"), lambda: F(2, 7))
    with pytest.raises(AssertionError, match="rounded"):
        assert_rounding_is_not_a_method_error(strict, F(2, 7))
    leaky = _toy(_LeakyHint("ratio"), lambda: F(2, 7))
    with pytest.raises(AssertionError, match="shows the answer"):
        assert_hint_without_answer(leaky, F(7, 2), F(2, 7))
    good = _toy(gl.check.Value("ratio"), lambda: F(2, 7))
    exposed = _LeakyCheck(good.name, "9.98", "toy", 1, 1, "compute", "", "")
    with pytest.raises(AssertionError, match="expected"):
        assert_nothing_public_carries_the_answer(exposed, F(2, 7))
    assert_rounding_is_not_a_method_error(good, F(2, 7))
    assert_hint_without_answer(good, F(7, 2), F(2, 7))
    assert_nothing_public_carries_the_answer(good, F(2, 7))

    class _Slow(gl.check.Value):
        def judge(self, answer, reference, params):
            import time

            time.sleep(1.1)
            return gl.check.Verdict(False, "Slow.")

        def check_form(self, answer):
            return None

    with pytest.raises(AssertionError, match="took"):
        assert_malformed_answers_get_a_hint_fast(_toy(_Slow("ratio"), lambda: F(2, 7)))


# ----------------------------------------------------------------------------- the pages
def _cells(path):
    return json.loads(path.read_text(encoding="utf-8"))["cells"]


@pytest.mark.parametrize("chapter", sorted({gl.check.get(n).chapter for n in ANSWERS}))
def test_each_exercise_is_on_its_page_with_its_title_and_a_solution(checks, chapter):
    from notebook_tools import ROOT

    page = next((ROOT / "exercises").glob(f"{chapter}_*.ipynb"))
    solutions = next((ROOT / "book" / "solutions").glob(f"{chapter}_*.ipynb"))
    cells = _cells(page)
    text = ["".join(c["source"]) for c in cells]
    solved = "\n".join("".join(c["source"]) for c in _cells(solutions))
    for info in gl.check.catalogue(chapter):
        name, number = info["name"], info["exercise"]
        calls = [i for i, t in enumerate(text) if re.search(rf"gl\.check\.{name}\((?!.*\bvariant=)", t)]
        assert len(calls) == 1, f"{number} {name}: checked {len(calls)} times on {page.name}"
        header = f":::{{exercise}} {number}: {info['title']} · {'★' * info['stars']} · {info['minutes']} min"
        before = [i for i, t in enumerate(text[:calls[0]]) if t.startswith(":::{exercise}")]
        assert before and text[before[-1]].startswith(header), f"{number}: the cell before the check is not '{header}'"
        label = re.search(r":label: (\S+)", text[before[-1]]).group(1)
        assert f":::{{solution}} {label}" in solved, f"{number}: no solution for {label} on {solutions.name}"
        assert f"gl.check.{name}(" in solved, f"{number}: the solution page does not run the check"
        # the exercise's block, the cells up to its check, and the shared descriptions above it
        shared = [t for c, t in zip(cells[1:before[-1]], text[1:before[-1]])
                  if c["cell_type"] == "markdown" and not t.startswith(":::")]
        statement = "\n".join([*shared, *text[before[-1]:calls[0]]])
        check = gl.check.get(name)
        for key, value in check.given().items():
            shown = str(value) if not isinstance(value, float) else f"{value:g}"
            if key.endswith("printed"):
                continue
            assert re.search(rf"(?<![\d.]){re.escape(shown)}(?![\d])", statement), \
                f"{number}: the page does not show {key} = {shown} (the check's book numbers)"


def _numbers_of(reference):
    """``{part: number}`` of a reference that is one number or a dict holding numbers."""
    parts = reference if isinstance(reference, dict) else {None: reference}
    out = {}
    for key, value in parts.items():
        if isinstance(value, sympy.Basic) and value.is_number:
            out[key] = complex(sympy.N(value, 30))
    return out


@pytest.mark.parametrize("name", sorted(ANSWERS))
def test_variants_round_and_hint_like_the_book(checks, name):
    """For other numbers too: the reference rounded to four figures is not a method error, and
    typical wrong numbers (sign, reciprocal, a factor) get a hint without the answer."""
    check = gl.check.get(name)
    for variant in ("s1", "s2", "s3"):
        _, reference = _core._reference(check, variant)
        for key, z in _numbers_of(reference).items():
            if z == 0 or (z.imag == 0 and z.real == int(z.real) and abs(z.real) < 10**4):
                continue
            wrongs = [-z, 1 / z, 1.37 * z]
            exact = _core._example(check, variant)
            for wrong in wrongs:
                value = wrong.real if wrong.imag == 0 else wrong
                answer = value if key is None else dict(exact, **{key: value})
                if not isinstance(answer, dict):
                    assert_hint_without_answer(check, answer, reference, variant)
                else:
                    result = check(answer, variant=variant)
                    assert not result.passed and not leaks_in(result.message, reference[key], percent=True), \
                        (name, variant, result.message)
            if key is None:
                assert_rounding_is_not_a_method_error(check, z, variant)
