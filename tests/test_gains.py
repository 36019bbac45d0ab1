"""Unit-by-unit gains (chapter 3): Rules 1-5, eqs. (19)-(29) of Liu, Chen and Chang (corrected per
the seed notes LC-E2, E5, E6, E7), and agreement with the null-space solver.

Expected formulas are typed from the paper (with its errata corrected); numbers are compared with
gl.speeds(..., method="nullspace"), an independent solver.
"""

import json
from fractions import Fraction

import numpy as np
import pytest
import sympy
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import gearlib as gl
from cli_tools import run

E = sympy.Symbol


def same(a, b):
    return sympy.simplify(sympy.sympify(a) - sympy.sympify(b)) == 0


def with_random_teeth(mech, rng):
    for gp in mech.gear_pairs:
        mech = mech.with_gear_pair(gp.gears, teeth=tuple(int(x) for x in rng.integers(12, 90, size=2)))
    return mech


def nullspace_coefficients(prop):
    return {k: complex(v) for k, v in prop.reference("nullspace").items()}


def assert_matches_nullspace(prop):
    ref = nullspace_coefficients(prop)
    for k, v in prop.relation().items():
        got = complex(v)
        assert abs(got - ref[k]) <= 1e-9 * max(1.0, abs(ref[k])), (k, got, ref[k])


# --------------------------------------------------------------------- Rules 1-5
PAPER_RULES = {  # Liu, Chen and Chang, eqs. (2), (4) corrected (LC-E2), (6), (9a), (9b)
    1: E("E_x_y"),
    2: E("E_y_x") - 1,
    3: (E("E_y_x") - 1) * E("E_r_y"),
    4: (E("E_p_x") - E("E_p_q")) / (E("E_p_y") - 1),
    5: (E("E_p_x") - 1) / (E("E_p_y") - 1),
}


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_rules_derived_from_circuit_equations_match_the_paper(n):
    d = gl.derive_rule(n)
    assert same(d.general, PAPER_RULES[n])
    assert d.agrees  # the template unit's full circuit equations give the same gain
    assert d.gain.free_symbols <= {gp.symbol for gp in gl.ku_catalogue(variants=True)[0].mechanism().gear_pairs} \
        or all(s.name.startswith("e_") for s in d.gain.free_symbols)


def test_rule_matching_in_the_paper_examples():
    fig1 = gl.kinematic_units(gl.catalog.load("liu_chen_fig1"))
    m = gl.match_rule(fig1.unit(2), (3, 5), (1, 5))  # eq. (19): -[G(1,5;5,3)]^-1
    assert m.rule == 2 and m.inverse and same(m.formula, -1 / (E("E_5_1") - 1))
    assert same(m.expression, gl.local_gain(fig1.unit(2), (3, 5), (1, 5), method="symbolic"))
    m = gl.match_rule(fig1.unit(1), (1, 5), (4, 5))  # eq. (20)
    assert m.rule == 1 and same(m.formula, E("E_4_1"))
    # eq. (25): the six-link unit of the transmission fits Table 2 (rule 3)
    ku2 = gl.kinematic_units(gl.catalog.load("liu_chen_transmission")).unit(2)
    m = gl.match_rule(ku2, (8, 1), (2, 5))
    assert m.rule == 3 and same(m.expression, gl.local_gain(ku2, (8, 1), (2, 5), method="symbolic"))
    assert gl.match_rule(ku2, (8, 1), (2, 1)).rule == 5
    assert gl.match_rule(ku2, (8, 5), (2, 5)).rule == 1


def test_local_gain_errors():
    ku2 = gl.kinematic_units(gl.catalog.load("liu_chen_fig1")).unit(2)
    with pytest.raises(gl.UnknownLinkError, match="not in KU2"):
        gl.local_gain(ku2, (4, 5), (1, 5))
    with pytest.raises(gl.InputError, match="different axes"):
        gl.local_gain(ku2, (2, 1), (1, 5))
    with pytest.raises(gl.InputError, match="itself"):
        gl.local_gain(ku2, (1, 1), (1, 5))


# --------------------------------------------------------------------- eqs. (17)-(22)
def test_eq_21_fig1():
    prop = gl.propagate(gl.catalog.load("liu_chen_fig1"), 3, [4], ground=5)
    assert same(prop.symbolic()[(4, 5)], E("e_4_1") / (1 - E("e_5_2") * E("e_2_1")))
    # eq. (17): one path, the product of two local gains
    (path,) = prop.paths
    assert path[0] == (4, 5) and [g.unit.index for g in path[2]] == [1, 2]


def test_eq_22_fig3a():
    prop = gl.propagate(gl.catalog.load("liu_chen_fig3a"), (3, 5), [1, 6], ground=4)
    sym = prop.symbolic()
    assert same(sym[(1, 4)], E("e_2_3") * E("e_1_2")) and same(sym[(6, 4)], -E("e_2_3") * E("e_6_5"))
    assert len(prop.paths) == 2  # two propagation paths merge at the coaxial triangle (eq. 18)


@pytest.mark.parametrize("name, output, inputs, ground", [
    ("liu_chen_fig1", 3, [4], 5),
    ("liu_chen_fig3a", (3, 5), [1, 6], 4),
])
def test_paper_examples_equal_the_null_space_for_random_teeth(name, output, inputs, ground):
    rng = np.random.default_rng(11)
    for _ in range(5):
        mech = with_random_teeth(gl.catalog.load(name), rng)
        assert_matches_nullspace(gl.propagate(mech, output, inputs, ground=ground))


# --------------------------------------------------------------------- the transmission, eqs. (23)-(29)
def E_path(*links):
    out = sympy.Integer(1)
    for a, b in zip(links, links[1:]):
        out *= E(f"e_{a}_{b}") if (a, b) in {(2, 3), (3, 5), (1, 6), (6, 2), (1, 7), (7, 8)} else 1 / E(f"e_{b}_{a}")
    return out


def test_transmission_gears_symbolic_corrected():
    table = gl.shift_table(gl.catalog.load("liu_chen_transmission"), gl.transmission.LIU_CHEN_MODES)
    first, second, third = (row.expression for row in table.rows)
    assert same(first, E_path(2, 6, 1, 7, 8))  # eq. (23) corrected (LC-E6): E_{2,8}
    assert same(second, (E_path(1, 7, 8) - 1) / (E_path(1, 6, 2) - 1))  # eq. (24) corrected (LC-E5)
    # eqs. (27)-(29) corrected (LC-E7): (E_{2,8} - E_{2,1}) / (1/(E'_{2,5} - 1) + 1 - E_{2,1})
    expected = (E_path(2, 6, 1, 7, 8) - E_path(2, 6, 1)) / (1 / (E_path(2, 3, 5) - 1) + 1 - E_path(2, 6, 1))
    assert same(third, expected)


def test_transmission_every_gear_propagation_equals_null_space():
    rng = np.random.default_rng(5)
    mech = gl.catalog.load("liu_chen_transmission")
    for trial in range(4):
        m = mech if trial == 0 else with_random_teeth(mech, rng)
        for row in gl.shift_table(m, gl.transmission.LIU_CHEN_MODES).rows:
            assert row.agrees, row.mode
            assert isinstance(row.ratio, Fraction)


def test_third_gear_follows_the_paper_decomposition():
    prop = gl.propagate(gl.catalog.load("liu_chen_transmission"), 8, [4], ground=1)
    names = {str(g.symbol) for g in prop.gains}
    # theta_{4,1} = theta_{4,2} + theta_{2,1}, both driven by theta_{2,5} (eqs. 26-28)
    assert names == {"G2(8,1;2,5)", "G1(4,2;2,5)", "G2(2,1;2,5)"}
    g = {str(x.symbol): x.expression for x in prop.gains}
    assert same(g["G1(4,2;2,5)"], 1 / (E_path(2, 3, 5) - 1)) and same(g["G2(2,1;2,5)"], 1 - E_path(2, 6, 1))


def test_brakes_and_clutches_of_a_simpson_set():
    s = gl.catalog.simpson()
    modes = {"1st": {"ground": 0, "input": 2, "output": 3, "held": [4]},
             "2nd": {"ground": 0, "input": 2, "output": 3, "held": [1]},
             "3rd": {"ground": 0, "input": 2, "output": 3, "joined": [[1, 2]]},
             "reverse": {"ground": 0, "input": 1, "output": 3, "held": [4]}}
    for row in gl.shift_table(s, modes).rows:
        m = row.mode
        assert row.ratio == gl.ratio(s, output=3, input=m.input, ground=0, held=m.held, joined=m.joined)
    assert gl.shift_table(s, modes).rows[2].ratio == 1


def test_operating_mode_errors():
    m = gl.catalog.load("liu_chen_transmission")
    with pytest.raises(gl.DataFormatError, match="missing 'output'"):
        gl.shift_table(m, {"1st": {"ground": 5, "input": 2}})
    with pytest.raises(gl.DataFormatError, match="unknown field"):
        gl.shift_table(m, {"1st": {"ground": 5, "input": 2, "output": 8, "brake": 4}})


# --------------------------------------------------------------------- size and errors
@pytest.mark.parametrize("n", [1, 7, 2000])
def test_serial_train_exact_ratio(n):
    assert gl.unit_ratio(gl.serial_train(n), output=n + 1, input=1, ground=0) == Fraction(-1, 2) ** n


def test_wrong_inputs_get_the_solvers_messages():
    m = gl.catalog.load("liu_chen_fig1")
    with pytest.raises(gl.InputError, match="needs 1 input; got 2"):
        gl.propagate(m, 3, [4, 1], ground=5)
    f3 = gl.catalog.load("liu_chen_fig3a")
    with pytest.raises(gl.InputError, match="needs 2 inputs; got 1"):
        gl.propagate(f3, 3, [1], ground=4)
    with pytest.raises(gl.InputError, match="not independent"):
        gl.propagate(f3, 3, [1, 2], ground=4)
    planetary = gl.catalog.simple_planetary()
    idler = planetary.replace(links=(*planetary.links, gl.Link(5, "idler arm")),
                              turning_pairs=(*planetary.turning_pairs, gl.TurningPair((4, 5), "z")))
    with pytest.raises(gl.InputError, match="link 5 .* turns freely"):
        gl.propagate(idler, 4, [1], ground=3)


# --------------------------------------------------------------------- random mechanisms
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 10**6), st.integers(3, 12), st.integers(1, 2), st.sampled_from([0.0, 0.0, 0.5]))
def test_propagation_equals_null_space_on_random_mechanisms(seed, n, dof, bevel):
    try:
        m = gl.random_mechanism(n, dof=dof, rng=seed, bevel=bevel)
    except ValueError:
        return
    rng = np.random.default_rng(seed)
    inputs = gl.choose_inputs(m, 0)
    others = [x for x in m.link_ids if x not in inputs and x != 0]
    output = others[int(rng.integers(len(others)))] if others else inputs[-1]
    # a relative output when possible: a link relative to one coaxial with it
    partners = [y for y in m.link_ids if y != output and m.coaxial(output, y)]
    out = (output, partners[0]) if partners and rng.random() < 0.5 else output
    ins = list(inputs)
    if len(ins) == 2 and rng.random() < 0.5:  # drive the first input relative to the second
        ins[0] = (ins[0], ins[1])
    assert_matches_nullspace(gl.propagate(m, out, ins, ground=0))


# --------------------------------------------------------------------- command line
def test_cli_gains_third_gear():
    out = run("gains", "liu_chen_transmission", "--ground", "1", "--input", "4", "--output", "8", "--symbolic",
              "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert data["relation"]["4/1"]["exact"] == "9/5"
    assert len(data["steps"]) == 2 and "tear" in data["steps"][0]
    text = run("gains", "liu_chen_fig1", "--ground", "5", "--input", "4", "--output", "3")
    assert "theta_3,5 = G1(1,5;4,5)*G2(3,5;1,5)*theta_4,5" in text.stdout
    bad = run("gains", "liu_chen_fig1", "--ground", "5", "--input", "4", "--input", "1", "--output", "3")
    assert bad.returncode == 2 and "needs 1 input" in bad.stderr and len(bad.stderr.strip().splitlines()) == 1


# ------------------------------------------- relative inputs, any ground, brakes: against the exact solve
def _exact_coefficients(m, ground, ins, out, held):
    """theta_out per unit of each input, from gl.speeds (the exact solve of every Willis equation)."""
    coef = []
    for k in range(len(ins)):
        sol = gl.speeds(m, ground=ground, inputs={x: int(j == k) for j, x in enumerate(ins)}, held=held)
        o, r = out if isinstance(out, tuple) else (out, ground)
        coef.append(sol[o] - sol[r])
    return coef


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 10**6), st.integers(3, 10), st.integers(1, 2), st.data())
def test_propagation_equals_the_exact_solve_for_relative_inputs_and_any_ground(seed, n, dof, data):
    """Issue 25: relative inputs whose links are neither the ground (Rules 4 and 5 with the carrier
    held, the transmission's second gear with link 5 held) once raised 'not independent' where the
    exact solve has an answer. Any ground, any brake, inputs u/v between any two links: the
    propagation either equals gl.speeds or both refuse the inputs."""
    try:
        m = gl.random_mechanism(n, dof=dof + 1, rng=seed)  # one more freedom: room for a brake
    except ValueError:
        return
    links = list(m.link_ids)
    ground = data.draw(st.sampled_from(links))
    rest = [x for x in links if x != ground]
    held = data.draw(st.sampled_from([(), (rest[0],)]))
    free = [x for x in rest if x not in held]
    ins = []
    for _ in range(gl.dof(m, ground, held=held)):
        u = data.draw(st.sampled_from(free))
        v = data.draw(st.sampled_from([x for x in links if x != u]))
        ins.append((u, v))
    out = data.draw(st.sampled_from([x for x in links if x != ground] + [(links[-1], links[-2])]))
    try:
        want = _exact_coefficients(m, ground, ins, out, held)
    except gl.InputError:
        with pytest.raises(gl.InputError):
            gl.propagate(m, out, ins, ground=ground, held=held).relation()
        return
    got = gl.propagate(m, out, ins, ground=ground, held=held).relation()
    assert [got[x] for x in ins] == want


# Rules 4 and 5 on their template units (the paper's setting: carrier k held, local input theta_y,p
# between two gears). Path products typed by hand from the templates' gear pairs: K5-4D meshes 4-1
# (e_1_4), 2-1 (e_2_1), 2-3 (e_2_3); K5-7D meshes 1-3, 1-4, 2-1.
e14, e21, e23, e13 = E("e_1_4"), E("e_2_1"), E("e_2_3"), E("e_1_3")
RULE_CASES = {  # rule: (template, output, input, paths E_p_.. of eqs. (9a), (9b))
    4: ("K5-4D", (1, 3), (2, 4), {"E_p_x": 1 / e14, "E_p_q": e23 / (e21 * e14), "E_p_y": 1 / (e21 * e14)}),
    5: ("K5-7D", (2, 4), (3, 4), {"E_p_x": 1 / (e14 * e21), "E_p_y": e13 / e14}),
}


@pytest.mark.parametrize("n", [4, 5])
def test_rules_4_and_5_with_any_link_held(n):
    template, out, inp, paths = RULE_CASES[n]
    m = next(e for e in gl.ku_catalogue(variants=True) if e.name == template).mechanism()
    want = PAPER_RULES[n].subs({E(k): v for k, v in paths.items()})
    for ground in m.link_ids:  # the carrier k first, then each gear
        assert same(gl.propagate(m, out, [inp], ground=ground).symbolic()[inp], want), ground


def test_transmission_second_gear_relative_input():
    """Link 5 held, input theta_2,1, output theta_8,1: (e17 e78 - 1)/(e16 e62 - 1) (issue 25)."""
    m = gl.catalog.load("liu_chen_transmission")
    got = gl.propagate(m, (8, 1), [(2, 1)], ground=5).symbolic()[(2, 1)]
    assert same(got, (E("e_1_7") * E("e_7_8") - 1) / (E("e_1_6") * E("e_6_2") - 1))
    assert gl.unit_ratio(m, output=(8, 1), input=(2, 1), ground=5) == \
        (lambda s: s[8] - s[1])(gl.speeds(m, ground=5, inputs={(2, 1): 1}))
