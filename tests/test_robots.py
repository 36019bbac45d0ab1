"""Geared robot manipulators (Chen 1998): the wrist's eqs. (26)-(30), Fig. 10's eq. (25), the gains
of Tables 1 and 2 for every reconstructed unit of Fig. 8, and the torque mapping.

Expected gains are typed from Chen's tables and equations (with C98-E1..E3 corrected); the
actuator displacements are cross-checked with the symbolic speed solver.
"""

import pytest
import sympy

import gearlib as gl
from gearlib.gains.robots import UNIT_TYPES

S = sympy.Symbol
th1, th2, th3 = sympy.symbols("theta_1 theta_2 theta_3")


def same(a, b):
    return sympy.simplify(sympy.sympify(a) - sympy.sympify(b)) == 0


def speeds_from_joint_angles(robot):
    """Every link's displacement from the joint angles, by the exact solver (independent)."""
    p = robot.primary
    inputs = {p[1]: th1}
    for i in range(2, len(p)):
        inputs[f"{p[i]}/{p[i - 1]}"] = [th1, th2, th3][i - 1]
    return gl.speeds(robot.mechanism, ground=p[0], inputs=inputs, method="symbolic")


def test_wrist_structure_matrix_eq_30():
    robot = gl.geared_robot(gl.catalog.robotic_wrist(), end_effector=3)
    assert robot.primary == (0, 1, 2, 3) and robot.secondary == (4, 5, 6, 7)
    e = {n: S(n) for n in ("e_5_4", "e_7_6", "e_3_5", "e_3_7")}
    A = sympy.Matrix([[1, 1, 1], [0, e["e_5_4"], e["e_7_6"]], [0, e["e_5_4"] * e["e_3_5"], e["e_7_6"] * e["e_3_7"]]])
    assert (robot.structure_matrix() - A).applyfunc(sympy.simplify) == sympy.zeros(3, 3)
    assert [u.type for u in robot.line(4).units] == ["IU-1", "TU-1", "TU-1"]
    assert robot.line(1).length == 1  # the direct drive line, eq. (28)


def test_wrist_actuator_displacements_eqs_26_to_28_equal_the_solver():
    robot = gl.geared_robot(gl.catalog.robotic_wrist(), end_effector=3)
    phi = robot.actuator_displacements()
    sol = speeds_from_joint_angles(robot)
    for k, j in enumerate(robot.inputs):
        assert same(phi[k], sol[j])  # relative to the base 0
    assert same(phi[1], th1 + S("e_5_4") * th2 + S("e_5_4") * S("e_3_5") * th3)  # eq. (26)


def test_torque_mapping_by_virtual_work():
    robot = gl.geared_robot(gl.catalog.robotic_wrist(), end_effector=3)
    sol = speeds_from_joint_angles(robot)
    J = sympy.Matrix([[sympy.diff(sol[j], t) for t in (th1, th2, th3)] for j in robot.inputs])  # Phi = J Theta
    xi = sympy.Matrix(sympy.symbols("xi_1 xi_4 xi_6"))
    assert (J.T * xi - robot.joint_torques()).applyfunc(sympy.simplify) == sympy.zeros(3, 1)  # eq. (31)


def fig10():
    return gl.Mechanism.from_dict({
        "name": "Chen Fig. 10", "links": list(range(8)),
        "turning_pairs": [[0, 1, "a"], [0, 4, "a"], [1, 2, "b"], [1, 5, "b"], [1, 7, "b"], [7, 6, "d"], [2, 3, "c"]],
        "gear_pairs": [{"gears": [1, 6], "ratio": "e_1_6", "carrier": 7},
                       {"gears": [6, 5], "ratio": "e_6_5", "carrier": 7},
                       {"gears": [5, 4], "ratio": "e_5_4", "carrier": 1},
                       {"gears": [3, 7], "ratio": "e_3_7", "carrier": 2}],
        "ground": 0})


def test_fig10_eq_25_with_tu6_used_backwards():
    robot = gl.geared_robot(fig10(), end_effector=3, inputs=[4])
    line = robot.line(4)
    assert [u.type for u in line.units] == ["IU-1", "TU-6", "TU-1"] and line.units[1].backwards
    k = S("e_5_4") * (1 - S("e_1_6") * S("e_6_5"))
    assert same(robot.actuator_displacements()[0], th1 + k * th2 + S("e_3_7") * k * th3)  # eq. (25)
    assert same(robot.actuator_displacements()[0], speeds_from_joint_angles(robot)[4])


def e(pairs, a, b):
    """The ratio e_{a,b} in the template's symbols (the reciprocal when the pair runs b -> a)."""
    return S(f"e_{a}_{b}") if (a, b) in pairs else 1 / S(f"e_{b}_{a}")


TABLES = {  # Chen (1998), Tables 1 and 2: forward gains G_f = q_{x,p} / q_{y,p}
    "IU-2": lambda E: E("y", "g1") * E("g1", "x"),
    "IU-3": lambda E: 1 / (1 - E("p", "g1") * E("g1", "y")),
    "IU-4": lambda E: E("y", "g2") * E("g2", "g1") * E("g1", "x"),
    "IU-5": lambda E: 1 / (1 - E("p", "g1") * E("g1", "g2") * E("g2", "y")),
    "TU-1": lambda E: E("y", "x"),
    "TU-2": lambda E: E("y", "g1") * E("g1", "x"),
    "TU-3": lambda E: E("y", "g2") * E("g2", "g1") * E("g1", "x"),
    "TU-4": lambda E: E("y", "g2") * E("g2", "g1") * E("g1", "x"),
    "TU-5": lambda E: E("y", "g2") * E("g2", "g1") * E("g1", "x"),
    "TU-6": lambda E: E("y", "g2") / (1 - E("p", "g1") * E("g1", "g2")),
    "TU-7": lambda E: E("g1", "x") / (1 - E("p", "g2") * E("g2", "y")),
}


def template_robot(name):
    """A two-joint robot whose one transmission line runs through the unit *name*."""
    tps, gps = UNIT_TYPES[name]
    turning = [list(t) for t in tps]
    gears = [{"gears": [a, b], "ratio": f"e_{a}_{b}", "carrier": c} for a, b, c in gps]
    roles = {r for t in tps for r in t[:2]}
    if name.startswith("TU"):  # base b, primary p, end-effector y; input x through IU-1
        links = sorted(roles | {"b"})
        turning.append(["b", "p", "a"])
        return gl.Mechanism.from_dict({"links": links, "turning_pairs": turning, "gear_pairs": gears,
                                       "ground": "b"}), "y", "p"
    links = sorted(roles | {"P1", "P2"})  # the unit on the base p, then TU-1 from y to P2 on P1
    turning += [["p", "P1", "a"], ["P1", "P2", "j"]]
    gears.append({"gears": ["y", "P2"], "ratio": "e_y_P2", "carrier": "P1"})
    return gl.Mechanism.from_dict({"links": links, "turning_pairs": turning, "gear_pairs": gears,
                                   "ground": "p"}), "P2", "P1"


@pytest.mark.parametrize("name", sorted(TABLES))
def test_every_reconstructed_unit_is_identified_and_has_its_table_gain(name):
    mech, end, _ = template_robot(name)
    robot = gl.geared_robot(mech, end_effector=end, inputs=["x"])
    units = robot.line("x").units
    pairs = {gp.gears for gp in mech.gear_pairs}
    unit = units[-1] if name.startswith("TU") else units[0]
    assert unit.type == name and not unit.backwards
    assert same(unit.gain, TABLES[name](lambda a, b: e(pairs, a, b)))
    # the whole line against the solver: q_{x,P0} from the joint angles
    sol = speeds_from_joint_angles(robot)
    assert same(robot.actuator_displacements()[0], sol["x"] - sol[robot.primary[0]])


def test_coupled_lines_and_bad_inputs_are_refused():
    wrist = gl.catalog.robotic_wrist()
    coupled = wrist.replace(gear_pairs=wrist.gear_pairs + ({"gears": [5, 6], "ratio": "e_5_6", "carrier": 1},))
    with pytest.raises(gl.MechanismError, match="coupled"):
        gl.geared_robot(coupled, end_effector=3, inputs=[4, 6])
    with pytest.raises(gl.InputError, match="base"):
        gl.geared_robot(wrist, end_effector=3, inputs=[0])
    with pytest.raises(gl.InputError, match="not an input"):
        gl.geared_robot(wrist, end_effector=3).line(5)


@pytest.mark.parametrize("make, end, inputs", [(gl.catalog.robotic_wrist, 3, None), (fig10, 3, [4])])
def test_structure_matrix_equals_the_null_space_for_random_ratios(make, end, inputs):
    import numpy as np

    rng = np.random.default_rng(7)
    mech = make()
    for _ in range(3):
        numeric = mech
        for gp in mech.gear_pairs:
            sign = -1 if rng.random() < 0.7 else 1
            numeric = numeric.with_gear_pair(gp.gears, ratio=sympy.Rational(sign * int(rng.integers(12, 80)), 37))
        robot = gl.geared_robot(numeric, end_effector=end, inputs=inputs)
        A = robot.structure_matrix(method="exact")
        p = robot.primary
        for i in range(1, len(p)):  # joint angle i = 1, the others 0
            angles = {p[1]: 0.0, **{f"{p[m]}/{p[m - 1]}": 0.0 for m in range(2, len(p))}}
            angles[p[1] if i == 1 else f"{p[i]}/{p[i - 1]}"] = 1.0
            sol = gl.speeds(numeric, ground=p[0], inputs=angles, method="nullspace")
            for k, line in enumerate(robot.lines):
                phi = complex(sol.relative(line.input, line.start))
                assert abs(phi - complex(A[i - 1, k])) < 1e-9


PRINTED = {  # Chen (1998), Tables 1 and 2, in the paper's own symbols (1 and 2 written g1 and g2 here)
    "IU-2": "e_y_g1*e_g1_x", "IU-3": "1/(1 - e_p_g1*e_g1_y)", "IU-4": "e_y_g2*e_g2_g1*e_g1_x",
    "IU-5": "1/(1 - e_p_g1*e_g1_g2*e_g2_y)", "TU-1": "e_y_x", "TU-2": "e_y_g1*e_g1_x",
    "TU-3": "e_y_g2*e_g2_g1*e_g1_x", "TU-4": "e_y_g2*e_g2_g1*e_g1_x", "TU-5": "e_y_g2*e_g2_g1*e_g1_x",
    "TU-6": "e_y_g2/(1 - e_p_g1*e_g1_g2)", "TU-7": "e_g1_x/(1 - e_p_g2*e_g2_y)",
}


@pytest.mark.parametrize("name", sorted(PRINTED))
def test_unit_gains_read_as_the_tables_print_them(name):
    """Issue 25: the templates' gear pairs run as the tables write their ratios, so each derived
    gain is the printed expression symbol for symbol (no e_{b,a} = 1/e_{a,b} to apply)."""
    printed = sympy.sympify(PRINTED[name].replace("g1", "1").replace("g2", "2"))
    derived = gl.robots.unit_gains()[name]
    assert sympy.simplify(derived - printed) == 0 and derived.free_symbols == printed.free_symbols
