"""Transmissions as data: published ratios, the shift table, per-gear efficiency, two-dof trains
at an operating point, and the assembly conditions of planetary sets.

Reference values come from the literature (the makers' ratio tables) or from computations
written here with none of gearlib: the Willis equation of each simple set solved by sympy, a
carrier-frame power balance per planetary set, and a torque balance in generalised
coordinates.
"""

import copy
import itertools
import json
import math
import warnings

import numpy as np
import pytest
import sympy
import yaml

import gearlib as gl
from cli_tools import run


def run_cli(*args):
    r = run(*args)
    return r.returncode, r.stdout, r.stderr

# --------------------------------------------------------------------------- published ratio tables
# i = omega_in / omega_out as the makers print it, to the printed digits
PUBLISHED = {
    # Wikipedia, "ZF 8HP transmission", gearset table (8HP 70)
    "zf_8hp70": (4, {"1st": 4.6957, "2nd": 3.1304, "3rd": 2.1039, "4th": 1.6667, "5th": 1.2845, "6th": 1.0000,
                     "7th": 0.8392, "8th": 0.6667, "R": -3.2968}),
    # Wikipedia, "GM 8L transmission", gearset table (8L 90)
    "gm_8l90": (4, {"1st": 4.5600, "2nd": 2.9709, "3rd": 2.0751, "4th": 1.6876, "5th": 1.2700, "6th": 1.0000,
                    "7th": 0.8455, "8th": 0.6515, "R": -3.8176}),
    # Ford 6R75/6R80 workshop manual, "Gear Ratios" (the ZF 6HP26 gearset)
    "zf_6hp26": (2, {"1st": 4.17, "2nd": 2.34, "3rd": 1.52, "4th": 1.14, "5th": 0.87, "6th": 0.69, "R": -3.40}),
}


@pytest.mark.parametrize("name", sorted(PUBLISHED))
def test_published_ratios_are_reproduced_to_the_printed_digits(name):
    digits, printed = PUBLISHED[name]
    m = gl.catalog.load(name)
    assert [g.name for g in m.schedule] == list(printed)
    table = gl.shift_table(m, efficiency=False)
    for g in table.gears:
        assert abs(float(g.i) - printed[g.name]) <= 0.5 * 10 ** -digits, (name, g.name, float(g.i))
        # and the plain kinematics agree
        assert g.ratio == gl.ratio(m, output=m.output, input=m.inputs[0], ground=m.ground,
                                   **m.gear_constraints(g.name))


def test_6hp26_set_ratios_printed_by_ford():
    # "front planetary gearset ratio of 1.52:1", "rear ... 2.74:1" (1st), "1.54:1" (2nd), "2.24:1" (R)
    m = gl.catalog.load("zf_6hp26")
    front = gl.ratio(m, output=3, input=1, ground=0, **m.gear_constraints("1st"))  # carrier 1 / ring 1
    assert round(1 / float(front), 2) == 1.52
    for gear, printed in (("1st", 2.74), ("2nd", 1.54), ("R", -2.24)):
        c = m.gear_constraints(gear)
        r = gl.ratio(m, output=7, input=3, ground=0, **c)
        assert round(1 / float(r), 2) == printed, gear


def test_steps_and_spread_of_the_8hp():
    t = gl.shift_table(gl.catalog.load("zf_8hp70"), efficiency=False)
    # published steps 1.5000, 1.4879, 1.2623, 1.2975, 1.2845, 1.1917, 1.2587 and spread 7.0435
    steps = [round(float(g.step), 4) for g in t.gears if g.step is not None]
    assert steps == [1.5000, 1.4879, 1.2623, 1.2975, 1.2845, 1.1917, 1.2587]
    assert round(float(t.spread), 4) == 7.0435
    assert t.gear("8th").step is None and t.gear("R").step is None


# --------------------------------------------------------------------------- an independent model of the 8HP
# shafts: 1 input = carrier 2, 2 suns 1+2, 3 ring 1, 4 carrier 1 = ring 4, 5 ring 2 = sun 3,
# 6 ring 3 = sun 4, 7 carrier 3, 8 output = carrier 4; sets as (sun, ring, carrier, Z_s, Z_r)
SETS_8HP = [(2, 3, 4, 48, 96), (2, 5, 1, 48, 96), (5, 6, 7, 69, 111), (6, 4, 8, 23, 85)]
ELEMENTS_8HP = {"A": (2,), "B": (3,), "C": (1, 6), "D": (7, 8), "E": (5, 6)}


def _sympy_combination(elements):
    """Solve the Willis equations of the four sets with the elements engaged and input speed 1."""
    w = sympy.symbols("w1:9")
    eqs = [sympy.Eq(w[s - 1] - w[c - 1], -sympy.Rational(zr, zs) * (w[r - 1] - w[c - 1]))
           for s, r, c, zs, zr in SETS_8HP]
    for name in elements:
        links = ELEMENTS_8HP[name]
        eqs.append(sympy.Eq(w[links[0] - 1], 0) if len(links) == 1 else sympy.Eq(w[links[0] - 1], w[links[1] - 1]))
    free = sympy.linsolve(eqs, w)
    (sol,) = free
    if sol[0] == 0:
        return "tie-up", None
    sol = sympy.linsolve(eqs + [sympy.Eq(w[0], 1)], w)
    (s,) = sol
    if s[7].free_symbols:
        return "under-constrained", None
    return "gear", s[7]


def test_every_combination_of_three_elements_matches_sympy():
    m = gl.catalog.load("zf_8hp70")
    combos = gl.gains.classify(m)
    assert len(combos) == math.comb(5, 3)
    for c in combos:
        kind, ratio = _sympy_combination(c.elements)
        assert c.kind == kind, c.elements
        if kind == "gear":
            assert c.ratio == ratio and c.gear is not None
    assert [c.label for c in combos if c.kind == "tie-up"] == ["A+C+E"]


def test_classification_of_every_size_and_the_other_kinds():
    m = gl.catalog.load("zf_8hp70")
    by_size = {k: [c.kind for c in gl.gains.classify(m, k)] for k in range(6)}
    assert by_size[0] == ["under-constrained"] and set(by_size[1]) == set(by_size[2]) == {"under-constrained"}
    assert set(by_size[4]) == set(by_size[5]) == {"tie-up"}  # four independent elements lock all four freedoms
    six = {c.label: c for c in gl.gains.classify(gl.catalog.load("zf_6hp26"))}
    # B+C: carrier 1 held with sun 1 in the housing locks ring 1 (the input); D+E: the input held by D
    assert six["B+C"].kind == six["D+E"].kind == "tie-up"
    assert six["C+D"].kind == "output held"  # both Ravigneaux members held, the front set idles
    # over-constrained: a second clutch that repeats what the first already does
    data = yaml.safe_load(gl.catalog.path("simpson").read_text())
    data["shift_elements"] = [{"name": "C1", "type": "clutch", "links": [1, 2]},
                              {"name": "C2", "type": "clutch", "links": [2, 3]}]
    data["schedule"] = [{"gear": "3rd", "engaged": ["C1"]}]
    data["output"] = 3
    simpson = gl.Mechanism.from_dict(data)
    both = gl.gains.classify(simpson, 2, input=2)
    assert [(c.kind, c.dof) for c in both] == [("over-constrained", 1)] and "C2" in both[0].note
    with pytest.raises(gl.InputError, match="from 0 to 2"):
        gl.gains.classify(simpson, 3, input=2)


def test_slip_speeds_of_the_open_elements():
    t = gl.shift_table(gl.catalog.load("zf_8hp70"), efficiency=False)
    first = t.gear("1st")
    # 1st: sets 1 held (R4 = 0), S4 at input speed: output 23/108; D slips at w7 - w8, E at w5 - w6
    w = first.speeds
    assert w[8] == sympy.Rational(23, 108) and first.slips["E"] == w[5] - w[6] and first.slips["D"] == w[7] - w[8]
    assert set(first.slips) == {"D", "E"}
    # set 2 with sun held and carrier at 1: ring 2 at 3/2; ring 3 = sun 4 at 1 (clutch C)
    assert w[5] == sympy.Rational(3, 2) and first.slips["E"] == sympy.Rational(1, 2)
    sixth = t.gear("6th")
    assert sixth.slips == {"A": 1, "B": 1}  # direct drive: both brakes slip at input speed


# --------------------------------------------------------------------------- per-gear efficiency
ETA_EXT, ETA_INT = 0.98, 0.99


def _set_power_balance(gear):
    """Efficiency of a gear of the 8HP by a carrier-frame power balance per set, with plain numpy.

    Unknowns: the torque the outside applies to the sun, ring and carrier of each set (12), the
    torque of each engaged element (3), the output torque. Each set: its three torques sum to
    zero, and in the carrier frame the driven member receives eta0 = eta_ext * eta_int of the
    power the driving one gives (a set that does not roll: the lossless torque ratio). Each
    shaft: the torques on it sum to zero. Unit input torque on shaft 1."""
    m = gl.catalog.load("zf_8hp70")
    engaged = next(g.engaged for g in m.schedule if g.name == gear)
    w = _speeds_of(engaged)
    n_sets = len(SETS_8HP)
    elems = list(engaged)
    nvar = 3 * n_sets + len(elems) + 1

    def solve(drives):
        rows, rhs = [], []
        for k, (s, r, c, zs, zr) in enumerate(SETS_8HP):
            row = np.zeros(nvar)
            row[3 * k:3 * k + 3] = 1
            rows.append(row)
            rhs.append(0)
            ws, wr = w[s] - w[c], w[r] - w[c]
            row = np.zeros(nvar)
            if abs(ws) < 1e-12 and abs(wr) < 1e-12:  # rigid: T_r = (Z_r / Z_s) T_s
                row[3 * k], row[3 * k + 1] = zr / zs, -1
            elif drives[k] == "sun":  # T_r w_r = -eta0 T_s w_s
                row[3 * k], row[3 * k + 1] = drives["eta"] * ws, wr
            else:  # T_s w_s = -eta0 T_r w_r
                row[3 * k], row[3 * k + 1] = ws, drives["eta"] * wr
            rows.append(row)
            rhs.append(0)
        for shaft in range(1, 9):
            row = np.zeros(nvar)
            for k, members in enumerate(SETS_8HP):
                for j in range(3):
                    if members[j] == shaft:
                        row[3 * k + j] = -1  # the set's member pushes back on the shaft
            for e, name in enumerate(elems):
                links = ELEMENTS_8HP[name]
                if shaft == links[0]:
                    row[3 * n_sets + e] = 1
                elif len(links) == 2 and shaft == links[1]:
                    row[3 * n_sets + e] = -1
            if shaft == 8:
                row[-1] = 1
            rows.append(row)
            rhs.append(-1.0 if shaft == 1 else 0.0)
        return np.linalg.solve(np.array(rows), np.array(rhs))

    lossless = solve({"eta": 1.0, **{k: "sun" for k in range(n_sets)}})
    drives = {"eta": ETA_EXT * ETA_INT}
    for k, (s, _r, c, _zs, _zr) in enumerate(SETS_8HP):
        drives[k] = "sun" if lossless[3 * k] * (w[s] - w[c]) > 0 else "ring"
    x = solve(drives)
    return -x[-1] * w[8] / (1.0 * w[1])


def _speeds_of(engaged):
    w = sympy.symbols("w1:9")
    eqs = [sympy.Eq(w[s - 1] - w[c - 1], -sympy.Rational(zr, zs) * (w[r - 1] - w[c - 1]))
           for s, r, c, zs, zr in SETS_8HP] + [sympy.Eq(w[0], 1)]
    for name in engaged:
        links = ELEMENTS_8HP[name]
        eqs.append(sympy.Eq(w[links[0] - 1], 0) if len(links) == 1 else sympy.Eq(w[links[0] - 1], w[links[1] - 1]))
    (sol,) = sympy.linsolve(eqs, w)
    return {k + 1: float(v) for k, v in enumerate(sol)}


def test_every_gear_of_the_8hp_against_a_per_set_power_balance():
    t = gl.shift_table(gl.catalog.load("zf_8hp70"))  # Glover's 0.98 external, 0.99 internal
    for g in t.gears:
        assert g.efficiency == pytest.approx(_set_power_balance(g.name), abs=1e-9), g.name
    assert t.gear("6th").efficiency == 1  # direct drive: nothing rolls
    assert all(not m.rolling for m in t.gear("6th").meshes)
    # 3rd splits the input: straight to sun 4 through C, and through set 2 (locked by C and E) to
    # sun 1 and set 1 into ring 4; the two paths meet at carrier 4
    third = t.gear("3rd")
    assert third.element_torques["C"] > 0.3 and third.element_torques["E"] > 0.3
    rolling = {m.gears for m in third.meshes if m.rolling > 1e-9}
    assert rolling == {(2, 9), (9, 3), (6, 12), (12, 4)}


def test_reverse_of_the_8hp_circulates_power():
    r = gl.shift_table(gl.catalog.load("zf_8hp70")).gear("R")
    # set 3 rolls faster than the input power: its meshes carry more than the input (circulation)
    assert any(m.rolling > 1 for m in r.meshes if m.gears in {(5, 11), (11, 6)})
    assert (11, 6) in r.circulating
    assert r.efficiency < min(g.efficiency for g in gl.shift_table(gl.catalog.load("zf_8hp70")).gears if g.name != "R")


def test_efficiency_with_clutches_and_direct_drive():
    s = gl.catalog.simpson()
    # Simpson third gear: the front set locked by its clutch; exactly 1, exact and numeric
    assert gl.davies.efficiency(s, 0, 2, 3, joined=[(1, 2)]).value == 1
    assert gl.davies.efficiency(s, 0, 2, 3, joined=[(1, 2)], symbolic="exact").value == 1
    res = gl.davies.efficiency(s, 0, 2, 3, joined=[(1, 2)])
    assert all(m.driver is None and m.loss == 0 for m in res.meshes)
    assert any("not roll" in n for n in res.notes)


def test_a_mesh_efficiency_of_one():
    p = gl.catalog.simple_planetary(sun=30, ring=78)
    # sun in, carrier out, ring held: eta = (1 + eta0 Z_r/Z_s) / (1 + Z_r/Z_s), here eta0 = 1 * 0.99
    k = 78 / 30
    res = gl.davies.efficiency(p, 3, 1, 4, eta={(1, 2): 1, (2, 3): 0.99})
    assert res.value == pytest.approx((1 + 0.99 * k) / (1 + k), abs=1e-12)
    assert gl.davies.efficiency(p, 3, 1, 4, eta=1).value == pytest.approx(1, abs=1e-12)
    assert gl.davies.efficiency(p, 3, 1, 4, eta=1, symbolic="exact").value == 1


def test_the_two_dof_error_names_every_way_out():
    with pytest.raises(gl.ConstraintError) as info:
        gl.davies.efficiency(gl.catalog.simpson(), 0, 2, 3)
    text = str(info.value)
    assert "--joined U,V" in text and "--gear" in text and "operating_point" in text


# --------------------------------------------------------------------------- two-dof trains
def _torque_balance(free, pairs, ports, speeds, torque_given, eta):
    """Generalised-coordinate equilibrium: one torque per mesh (on gear a; b gets k tau, the carrier
    -(1 + k) tau), unknown port torques; k from the carrier-relative power balance."""
    unknown_ports = [p for p in ports if p not in torque_given]

    def rel(x, c):
        return speeds[x] - speeds[c]

    def solve(ks):
        nvar = len(pairs) + len(unknown_ports)
        rows, rhs = [], []
        for x in free:
            row = np.zeros(nvar)
            for i, (a, b, c) in enumerate(pairs):
                row[i] += (x == a) + ks[i] * (x == b) - (1 + ks[i]) * (x == c)
            for j, p in enumerate(unknown_ports):
                row[len(pairs) + j] += x == p
            rows.append(row)
            rhs.append(-torque_given.get(x, 0.0))
        return np.linalg.solve(np.array(rows), np.array(rhs))

    base = [-rel(a, c) / rel(b, c) for a, b, c in pairs]
    x0 = solve(base)
    ks = []
    for i, (a, _b, c) in enumerate(pairs):
        a_drives = x0[i] * rel(a, c) < 0  # the mesh's force on gear a takes power from it (carrier frame)
        ks.append(base[i] * (eta if a_drives else 1 / eta))
    x = solve(ks)
    torques = dict(torque_given)
    torques.update({p: x[len(pairs) + j] for j, p in enumerate(unknown_ports)})
    powers = {p: torques[p] * speeds[p] for p in ports}
    p_in = sum(v for v in powers.values() if v > 0)
    return powers, -sum(v for v in powers.values() if v < 0) / p_in


@pytest.mark.parametrize("pinion_torque", [-10.0, 10.0])  # power in at the pinion, or in at the wheels
def test_differential_at_an_operating_point_against_a_torque_balance(pinion_torque):
    m = gl.catalog.load("cyl_standard_differential")  # pinion 1, side gears 2, 3, planet 4, case 5
    speeds = {0: 0.0, 1: -140.0, 2: 26.0, 3: 30.0, 4: 124 / 5, 5: 28.0}  # from e_{4,2}=5/8, e_{4,3}=-5/8, e_{5,1}=-5
    pairs = [(4, 2, 5), (4, 3, 5), (5, 1, 0)]
    pairs_e = {(4, 2, 5): 5 / 8, (4, 3, 5): -5 / 8, (5, 1, 0): -5.0}
    for (a, b, c), e in pairs_e.items():  # the speeds above obey every Willis equation
        assert speeds[b] - speeds[c] == pytest.approx(e * (speeds[a] - speeds[c]))
    powers, eta = _torque_balance([1, 2, 3, 4, 5], pairs, [1, 2, 3], speeds, {1: pinion_torque}, 0.98)
    op = gl.davies.operating_point(m, 0, speeds={2: 26, 3: 30}, torques={1: pinion_torque}, eta=0.98)
    assert op.efficiency == pytest.approx(eta, rel=1e-12)
    for p in op.ports:
        assert p.power == pytest.approx(powers[p.link], rel=1e-12)
    assert op.loss == pytest.approx(sum(m.loss for m in op.meshes), rel=1e-9)
    assert op.input_power - op.output_power == pytest.approx(sum(powers.values()), rel=1e-12)


POWER_SPLIT = {
    "name": "power-split planetary (test)",
    "links": {0: "housing", 1: "sun (generator)", 2: "planet", 3: "ring (output)", 4: "carrier (engine)"},
    "turning_pairs": [[0, 1, "a"], [0, 3, "a"], [0, 4, "a"], [4, 2, "b"]],
    "gear_pairs": [{"gears": [1, 2], "teeth": [30, 24]}, {"gears": [2, 3], "teeth": [24, 78], "type": "internal"}],
    "ground": 0,
}


@pytest.mark.parametrize("ring_speed", [150.0, 400.0])  # sun generating (1 in, 2 out) or motoring (2 in, 1 out)
def test_power_split_device_against_a_per_set_power_balance(ring_speed):
    m = gl.Mechanism.from_dict(POWER_SPLIT)
    zs, zr, t_engine, w_c = 30, 78, 100.0, 200.0
    w_s = w_c + (zr / zs) * (w_c - ring_speed)  # Willis: (w_s - w_c) = -(Z_r/Z_s)(w_r - w_c)
    # the set: T_s + T_r + T_c = 0; carrier frame: the driven member gets eta0 of the driver's power
    eta0 = 0.98 * 0.99
    lossless_ts = -t_engine * zs / (zs + zr)  # T_s : T_r : T_c = Z_s : Z_r : -(Z_s + Z_r), lossless
    sun_drives = lossless_ts * (w_s - w_c) > 0
    k = (zr / zs) * (eta0 if sun_drives else 1 / eta0)  # T_r = k T_s
    ts = -t_engine / (1 + k)
    tr = k * ts
    powers = {1: ts * w_s, 3: tr * ring_speed, 4: t_engine * w_c}
    p_in = sum(p for p in powers.values() if p > 0)
    eta = -sum(p for p in powers.values() if p < 0) / p_in
    op = gl.davies.operating_point(m, 0, speeds={4: w_c, 3: ring_speed}, torques={4: t_engine}, ports=[1])
    assert op.efficiency == pytest.approx(eta, rel=1e-12)
    for link, power in powers.items():
        assert op.port(link).power == pytest.approx(power, rel=1e-12)
    ins = sorted(p.link for p in op.ports if p.power > 0)
    assert ins == ([4] if ring_speed == 150 else [1, 4])


def test_operating_point_errors():
    m = gl.Mechanism.from_dict(POWER_SPLIT)
    with pytest.raises(gl.InputError, match="give 2 port speed"):
        gl.davies.operating_point(m, 0, speeds={4: 200}, torques={4: 100, 3: 1})
    with pytest.raises(gl.InputError, match="need 1 torque"):
        gl.davies.operating_point(m, 0, speeds={4: 200, 3: 100}, torques={}, ports=[1])
    with pytest.raises(gl.InputError, match="ground 0 cannot be a port"):
        gl.davies.operating_point(m, 0, speeds={0: 1, 3: 100}, torques={4: 1})
    with pytest.raises(gl.InputError, match="must be a number"):
        gl.davies.operating_point(m, 0, speeds={4: "fast", 3: 100}, torques={4: 1})


# --------------------------------------------------------------------------- assembly conditions
def test_concentricity_over_the_chapter_3_ring_sweep():
    # the review's sweep: sun 30, planet 24, ring 66 ... 90; only Z_r = Z_s + 2 Z_p = 78 fits
    for ring in range(66, 91):
        m = gl.catalog.simple_planetary(sun=30, ring=ring, planet=24)
        (c,) = [c for c in gl.assembly_conditions(m) if c.condition == "concentricity"]
        assert c.ok == (ring - 30 - 2 * 24 == 0) and c.value == ring - 30 - 48


def test_concentric_teeth_keep_every_set_buildable():
    """A ring resized with its planet following: the planet is (Z_r - Z_s) / 2 by hand, the set
    is concentric, and the carrier turns at Z_s / (Z_s + Z_r) of the sun with the ring held
    (the textbook formula, not gearlib's solver)."""
    base = gl.catalog.simple_planetary(sun=30, ring=78, planet=24)
    for ring in range(60, 110, 2):
        m = gl.with_concentric_teeth(base, {3: ring})
        assert [gp.teeth for gp in m.gear_pairs] == [(30, (ring - 30) // 2), ((ring - 30) // 2, ring)]
        assert all(c.ok for c in gl.assembly_conditions(m))
        assert gl.ratio(m, output=4, input=1, ground=3) == sympy.Rational(30, 30 + ring)
    # the transmission's ring 1 is shared by two sets: both planets follow it
    t = gl.with_concentric_teeth(gl.catalog.load("liu_chen_transmission"), {1: 80})
    teeth = {gp.gears: gp.teeth for gp in t.gear_pairs}
    assert teeth[(1, 6)] == (80, 25) and teeth[(1, 7)] == (80, 22) and teeth[(2, 3)] == (30, 24)
    for bad, text in (({3: 61}, "odd number"), ({3: 40}, "fewer than 12"), ({2: 20}, "not the sun or the ring"),
                      ({3: 70.5}, "whole number")):
        with pytest.raises(gl.InputError, match=text):
            gl.with_concentric_teeth(base, bad, min_planet_teeth=12)


def test_transmission_explorer_and_its_twin_show_only_sets_that_assemble():
    mech = gl.catalog.load("liu_chen_transmission")
    ex = gl.gains.transmission_explorer(mech, gl.transmission.LIU_CHEN_MODES, pairs=[(1, 6), (7, 8), (3, 5)],
                                        concentric=True)
    assert set(ex.teeth) == {"N_1", "N_8", "N_5"}
    ex.update(mode="3rd", N_5=90)
    assert "planets 3: 30, 6: 21, 7: 18 teeth" in ex.text and "does not assemble" not in ex.text
    assert all(c.ok for c in gl.assembly_conditions(ex.mechanism_for()))
    ex.update(N_1=40)
    assert "no such set" in ex.text and "planet 6" in ex.text
    with warnings.catch_warnings():
        warnings.simplefilter("error", gl.AssemblyWarning)   # no set of the sweep fails to assemble
        ax = gl.transmission.plot_mode_sweep(mech, gl.transmission.LIU_CHEN_MODES, pair=(3, 5), gear=5,
                                             values=range(60, 110, 6), concentric=True)
    assert "does not assemble" not in [t.get_text() for t in ax.get_legend().get_texts()]
    import matplotlib.pyplot as plt

    plt.close(ax.figure)


def _planetary(sun, planet, ring, count, **pair):
    m = gl.catalog.simple_planetary(sun=sun, ring=ring, planet=planet)
    return m.replace(planets={2: count}, gear_pairs=[gp if not pair else type(gp)(**{**gp.__dict__, **pair})
                                                    for gp in m.gear_pairs])


def test_equal_spacing_and_neighbour_clearance_by_hand():
    spacing = {c.condition: c for c in gl.assembly_conditions(_planetary(30, 21, 72, 4))}
    assert not spacing["equal spacing"].ok and spacing["equal spacing"].value == (30 + 72) / 4  # 25.5
    assert {c.condition: c.ok for c in gl.assembly_conditions(_planetary(30, 21, 72, 3))}["equal spacing"]
    # sun 12, planet 30, ring 72: centre distance 21 modules, planet tips 32 modules across
    for n, fits in ((4, False), (3, True)):
        (c,) = [c for c in gl.assembly_conditions(_planetary(12, 30, 72, n)) if c.condition == "neighbour clearance"]
        assert c.ok == fits and c.value == pytest.approx(2 * 21 * math.sin(math.pi / n) - 32)


def _inv(a):
    return math.tan(a) - a


def test_profile_shift_offsets_a_concentricity_error():
    six = gl.catalog.load("zf_6hp26")
    assert all(c.ok for c in gl.assembly_conditions(six))
    long_pinion = [c for c in gl.assembly_conditions(six) if c.condition == "concentricity" and 10 in c.set.planets]
    assert len(long_pinion) == 1
    # working centre distances by hand: inv(a_w) = inv(a) + 2 tan(a) (x1 +- x2) / (z1 +- z2)
    alpha = math.radians(20)
    from scipy.optimize import brentq

    def working(z1, z2, x_sum, internal):
        zsum = (z2 - z1) if internal else (z1 + z2)
        target = _inv(alpha) + 2 * math.tan(alpha) * x_sum / zsum
        aw = brentq(lambda a: _inv(a) - target, 1e-3, 1.2)
        return zsum / 2 * math.cos(alpha) / math.cos(aw)

    ext = working(23, 38, 0.25 + 0.2793, False)
    internal = working(23, 85, 0.25 - 0.25, True)
    assert abs(ext - internal) < 1e-3 and internal == pytest.approx(31)
    # the same set without its profile shift fails, and says profile shift would help
    data = yaml.safe_load(gl.catalog.path("zf_6hp26").read_text())
    for gp in data["gear_pairs"]:
        gp.pop("profile_shift", None)
    with pytest.warns(gl.AssemblyWarning, match=r"85 - 38 - 2\*23 = 1.*profile_shift"):
        gl.loads(yaml.safe_dump(data))


def test_impossible_sets_warn_on_load_and_in_the_shift_table_but_load(tmp_path):
    data = yaml.safe_load(gl.catalog.path("simpson").read_text())
    data["gear_pairs"][1]["teeth"] = [21, 74]  # front ring 74 with sun 30 and planet 21
    data["gear_pairs"] = [data["gear_pairs"][0], data["gear_pairs"][1]] + data["gear_pairs"][2:]
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.warns(gl.AssemblyWarning, match="sun 1, planet 5, ring 2 on carrier 3: Z_r - Z_s - 2 Z_p = 74 - 30"):
        m = gl.load(path)
    assert isinstance(m, gl.Mechanism)
    assert issubclass(gl.AssemblyWarning, gl.GearlibWarning) and issubclass(gl.GearlibWarning, UserWarning)
    m = m.replace(output=3, shift_elements=[{"name": "B1", "type": "brake", "link": 4}],
                  schedule=[{"gear": "1st", "engaged": ["B1"]}])
    with pytest.warns(gl.AssemblyWarning):
        gl.shift_table(m, input=2, efficiency=False)


def test_the_catalogue_loads_without_warnings():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for name in gl.catalog.names():
            gl.load(gl.catalog.path(name))


BAD_GEAR_DATA = [
    ({"profile_shift": [0.2]}, "profile_shift"),
    ({"profile_shift": [3, 0]}, "must lie within"),
    ({"profile_shift": ["a", 0]}, "finite number"),
    ({"pressure_angle": "50*deg"}, "between 0 and 45"),
]


@pytest.mark.parametrize("extra, text", BAD_GEAR_DATA, ids=[t for _, t in BAD_GEAR_DATA])
def test_malformed_profile_shift_and_pressure_angle(extra, text):
    d = copy.deepcopy(yaml.safe_load(gl.catalog.path("simple_planetary").read_text()))
    d["gear_pairs"][0].update(extra)
    with pytest.raises(gl.DataFormatError, match=text):
        gl.Mechanism.from_dict(d)


def test_profile_shift_round_trips():
    m = gl.catalog.load("zf_6hp26")
    assert gl.Mechanism.from_dict(m.to_dict()) == m
    assert m.gear_pair(10, 5)[0].profile_shift == (0.25, 0.2793)


# --------------------------------------------------------------------------- the command line
def test_shifts_command_text_json_and_csv():
    code, out, err = run_cli("shifts", "zf_8hp70")
    assert code == 0 and "Glover's defaults: 0.98" in out and "A+C+E" in out and "4.6957" in out
    code, out, _ = run_cli("shifts", "zf_8hp70", "--json", "--eta", "0.97")
    data = json.loads(out)
    assert [g["gear"] for g in data["gears"]][-1] == "R" and data["eta"] == "0.97 per mesh"
    assert data["gears"][0]["i_exact"] == "108/23"
    code, out, _ = run_cli("shifts", "zf_6hp26", "--csv", "--table", "combinations")
    lines = out.strip().splitlines()
    assert lines[0].startswith("elements,kind") and len(lines) == 1 + math.comb(5, 2)


@pytest.mark.parametrize("args, text", [
    (("shifts", "simpson"), "has no schedule"),
    (("shifts", "zf_8hp70", "--k", "9"), "from 0 to 5"),
    (("ratio", "zf_8hp70", "--input", "1", "--output", "8", "--gear", "9th"), "no gear '9th'"),
    (("efficiency", "zf_8hp70", "--input", "1", "--output", "8", "--joined", "1"), "expected two links"),
    (("efficiency", "zf_8hp70", "--input", "1", "--output", "8", "--eta-pair", "2,9=1.5"), "(0, 1]"),
    (("efficiency", "cyl_standard_differential", "--speed", "2=26", "--torque", "1=-10"), "give 2 port speed"),
])
def test_command_line_errors_are_one_line(args, text):
    code, out, err = run_cli(*args)
    assert code == 2 and text in err and len(err.strip().splitlines()) == 1, err
    code, out, err = run_cli(*args, "--json") if args[0] != "ratio" else (2, "", err)
    assert code == 2


def test_efficiency_command_with_clutches_gears_and_operating_points():
    code, out, _ = run_cli("efficiency", "simpson", "--input", "2", "--output", "3", "--joined", "1,2")
    assert code == 0 and ": 1 " in out and "ordinary efficiencies: Glover's defaults" in out
    code, out, _ = run_cli("efficiency", "zf_8hp70", "--input", "1", "--output", "8", "--gear", "3rd", "--json")
    data = json.loads(out)
    assert data["efficiency"] == pytest.approx(_set_power_balance("3rd"), abs=1e-9)
    code, out, _ = run_cli("efficiency", "cyl_standard_differential", "--speed", "2=26", "--speed", "3=30",
                           "--torque", "1=-10", "--json")
    data = json.loads(out)
    assert code == 0 and {p["link"] for p in data["ports"]} == {"1", "2", "3"} and "Glover" in data["eta"]
    code, out, _ = run_cli("efficiency", "--help")
    assert "0.98" in out and "0.99" in out and "--joined" in out and "--speed" in out


def test_every_kinematic_command_takes_a_gear():
    for args in (("speeds", "zf_8hp70", "--input", "1=1"), ("ratio", "zf_8hp70", "--input", "1", "--output", "8"),
                 ("dof", "zf_8hp70")):
        code, out, err = run_cli(*args, "--gear", "2nd")
        assert code == 0, err
    code, out, _ = run_cli("ratio", "zf_8hp70", "--input", "1", "--output", "8", "--gear", "2nd")
    assert "23/72" in out


def test_combinations_are_all_the_subsets():
    m = gl.catalog.load("zf_6hp26")
    labels = [c.label for c in gl.gains.classify(m)]
    assert labels == ["+".join(c) for c in itertools.combinations("ABCDE", 2)]


def test_davies_layout_takes_pitch_radii_from_the_module():
    d = yaml.safe_load(gl.catalog.path("simple_planetary").read_text())
    for gp in d["gear_pairs"]:
        gp["module"] = 2.5
    m = gl.Mechanism.from_dict(d)
    lay = gl.davies.layout(m)
    for gp, mesh in zip(m.gear_pairs, lay.meshes):
        assert tuple(float(r) for r in mesh.radii) == tuple(2.5 * z / 2 for z in gp.teeth)  # r = m z / 2
    for gp in d["gear_pairs"]:
        del gp["module"]
        gp["normal_module"], gp["helix_angle"] = 2, "30*deg"
    helical = gl.davies.layout(gl.Mechanism.from_dict(d))
    m_t = 2 / math.cos(math.radians(30))
    assert float(helical.meshes[0].radii[0]) == pytest.approx(m_t * 24 / 2, rel=1e-12)


def test_the_command_line_reports_an_impossible_set_in_one_line_and_goes_on(tmp_path):
    # the review's case: ring 100 with sun 21 and planet 39 (100 - 21 - 78 = 1)
    path = tmp_path / "ring100.yaml"
    path.write_text(yaml.safe_dump({
        "links": [1, 2, 3, 4], "turning_pairs": [[4, 1, "a"], [4, 3, "a"], [4, 2, "b"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [21, 39]}, {"gears": [2, 3], "teeth": [39, 100], "type": "internal"}],
        "ground": 3}))
    code, out, err = run_cli("ratio", str(path), "--input", "1", "--output", "4", "--json")
    assert code == 0 and json.loads(out)["ratio"][0] == pytest.approx(21 / 121)  # 1 / (1 + 100/21)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"gearlib ratio: warning: {path}: planetary set")
    assert "100 - 21 - 2*39 = 1" in lines[0]
