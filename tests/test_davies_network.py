"""The coupling graph, the layout, the network matrices, bad input, drawings, widget and CLI."""

import json
import re

import numpy as np
import pytest
import sympy

import gearlib as gl
from cli_tools import run

dv = gl.davies


# ------------------------------------------------------------------ graph
def test_epicyclic_circuit_and_cutset_matrices_eqs55_and_61():
    net = dv.network(gl.catalog.load("laus_epicyclic"), 1, 5, 2)
    assert net.graph.chords == ("D", "E") and net.graph.branches == ("A", "B", "C")
    assert net.B.tolist() == [[0, 1, -1, 1, 0], [-1, 0, 1, 0, 1]]  # (55)
    assert net.Q.tolist() == [[1, 0, 0, 0, 1], [0, 1, 0, -1, 0], [0, 0, 1, 1, -1]]  # (61), collapsed
    assert net.Q_A(lossless=True).tolist() == [[1, 1, 0, 0, 0, 0, 1], [0, 0, 1, 1, 0, -1, 0], [0, 0, 0, 0, 1, 1, -1]]
    assert net.M_N().shape == (4, 5) and net.A_N(lossless=True).shape == (6, 7)


@pytest.mark.parametrize("seed", range(5))
def test_cutsets_are_orthogonal_to_circuits_for_any_tree(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(3, 8))
    edges = [(f"E{k}", k, int(rng.integers(0, k))) for k in range(1, n)]  # a spanning tree
    edges += [(f"X{k}", int(rng.integers(0, n)), int(rng.integers(0, n))) for k in range(int(rng.integers(1, 5)))]
    edges = [e for e in edges if e[1] != e[2]]
    g = dv.CouplingGraph(tuple(range(n)), tuple(edges))
    assert not (g.cutset_matrix() @ g.circuit_matrix().T).any()
    a = sympy.Matrix(g.reduced_incidence(0))
    assert g.spanning_tree_count() == (a * a.T).det()
    assert g.l + g.k == g.e


def test_chords_can_be_chosen():
    net = dv.network(gl.catalog.load("laus_epicyclic"), 1, 5, 2, chords=["C", "E"])
    assert net.graph.chords == ("C", "E")
    assert dv.efficiency(gl.catalog.load("laus_epicyclic"), 1, 5, 2, chords=["C", "E"], eta=0.99).value == \
        pytest.approx(0.946206870, abs=1e-9)
    with pytest.raises(gl.InputError, match="spanning tree"):
        dv.network(gl.catalog.load("laus_epicyclic"), 1, 5, 2, chords=["A", "B", "C"])


def test_replicate_and_screws():
    assert dv.replicate(np.array([[1, -1]]), [2, 1]).tolist() == [[1, 1, -1]]
    from gearlib.davies import screws

    m, f = screws.revolute((0, 5), (1, 0)), screws.x_force((0, 5))
    assert screws.power(f, m) == 0  # a force through the axis does no work on the rotation about it


# ------------------------------------------------------------------ layout
def test_planetary_layout_closes_the_centre_distances():
    m = gl.catalog.simple_planetary(sun=24, ring=60)
    lay = dv.layout(m)
    planet = lay.axis_of(2, "b")
    assert planet.point == (sympy.Rational(24 + 18, 2), 0)
    assert {mg.gears: mg.pitch_point for mg in lay.meshes} == {(1, 2): (12, 0), (2, 3): (30, 0)}


def test_reverted_compound_train_closes_its_loop():
    data = {"links": {0: "frame", 1: "in", 2: "counter", 3: "out"},
            "turning_pairs": [[0, 1, "a"], [0, 3, "a"], [0, 2, "b"]],
            "gear_pairs": [{"gears": [1, 2], "teeth": [20, 40]}, {"gears": [2, 3], "teeth": [25, 35]}]}
    m = gl.Mechanism.from_dict(data)
    lay = dv.layout(m)
    assert lay.mode == "physical" and lay.axis_of(2, "b").point == (30, 0)
    res = dv.efficiency(m, 0, 1, 3, eta=0.98)
    assert res.value == pytest.approx(0.98**2, abs=1e-12)


def test_radii_that_disagree_with_the_teeth_are_refused():
    data = gl.catalog.load("laus_simple_pair").to_dict()
    data["gear_pairs"][0]["radii"] = [1, 3]
    with pytest.raises(gl.GeometryError, match="radii"):
        dv.layout(gl.Mechanism.from_dict(data))


def test_strict_physical_mode_names_the_open_loop():
    with pytest.raises(gl.GeometryError, match="do not close"):
        dv.layout(gl.catalog.ravigneaux(), mode="physical")
    with pytest.raises(gl.DataFormatError, match="mode"):
        dv.layout(gl.catalog.ravigneaux(), mode="flat")


# ------------------------------------------------------------------ bad input
@pytest.mark.parametrize("args, error, words", [
    ((1, 5, 5), gl.InputError, "different links"),
    ((1, 1, 2), gl.InputError, "ground"),
    ((1, 3, 2), gl.InputError, "not coaxial"),
    ((1, 9, 2), gl.UnknownLinkError, "9"),
])
def test_bad_ports(args, error, words):
    with pytest.raises(error, match=words):
        dv.efficiency(gl.catalog.load("laus_epicyclic"), *args)


def test_bad_friction_data():
    epi = gl.catalog.load("laus_epicyclic")
    with pytest.raises(gl.InputError, match=r"\(0, 1\]"):
        dv.efficiency(epi, 1, 5, 2, eta=1.2)
    with pytest.raises(gl.InputError, match="same sign"):
        dv.efficiency(epi, 1, 5, 2, torque=-1)
    with pytest.raises(gl.InputError, match="gear mesh"):
        dv.efficiency(epi, 1, 5, 2, bearings={"C": 0.01})
    with pytest.raises(gl.InputError, match="not a coupling"):
        dv.efficiency(epi, 1, 5, 2, bearings={"Z": 0.01})
    with pytest.raises(gl.InputError, match="viscous law"):
        dv.efficiency(epi, 1, 5, 2, viscous={"A": (0.1, "sticky")})
    with pytest.raises(gl.InputError, match="symbolic=True"):
        dv.efficiency(epi, 1, 5, 2, eta=sympy.Symbol("x"))


def test_wrong_degrees_of_freedom_and_redundant_planets():
    with pytest.raises(gl.ConstraintError, match="held"):
        dv.efficiency(gl.catalog.simpson(), 0, 2, 3)
    with pytest.raises(gl.ConstraintError, match="ground or a port"):
        dv.efficiency(gl.catalog.simpson(), 0, 2, 3, held=[2])
    two_planets = {"links": {1: "sun", 2: "planet A", 5: "planet B", 3: "ring", 4: "carrier"},
                   "turning_pairs": [[1, 3, "a"], [1, 4, "a"], [4, 2, "b"], [4, 5, "c"]],
                   "gear_pairs": [{"gears": [1, 2], "teeth": [24, 18]},
                                  {"gears": [2, 3], "teeth": [18, 60], "type": "internal"},
                                  {"gears": [1, 5], "teeth": [24, 18]},
                                  {"gears": [5, 3], "teeth": [18, 60], "type": "internal"}]}
    with pytest.raises(gl.ConstraintError, match="one planet"):
        dv.efficiency(gl.Mechanism.from_dict(two_planets), 3, 1, 4)


def test_penaud_complex_bevel_weights_are_refused_with_a_hint():
    with pytest.raises(gl.DataFormatError, match="signed real"):
        dv.efficiency(gl.catalog.car_differential(), 7, 3, 4)


def test_every_error_is_a_gearlib_error_not_a_traceback():
    epi = gl.catalog.load("laus_epicyclic")
    for kwargs in ({"eta": "not a number"}, {"eta": {(1, 3): -1}}, {"zeta": {(1, 9): 0.1}}, {"speed": 0}):
        with pytest.raises(gl.GearlibError):
            dv.efficiency(epi, 1, 5, 2, **kwargs)


# ------------------------------------------------------------------ drawings, widget
def test_drawings_return_their_axes():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    res = dv.efficiency(gl.catalog.humpage(), 5, 1, 4, eta=0.98)
    fig, axs = plt.subplots(2, 3)
    assert dv.draw_coupling_graph(res.network, ax=axs[0, 0]) is axs[0, 0]
    assert dv.plot_layout(res.network, ax=axs[0, 1]) is axs[0, 1]
    assert dv.plot_coupling_powers(res, ax=axs[0, 2]) is axs[0, 2]
    assert dv.plot_power_flow(res, ax=axs[1, 0]) is axs[1, 0]
    heights = [p.get_height() for p in axs[1, 0].patches]
    assert max(heights) == pytest.approx(5795 / 408)  # the recirculating power of mesh D, lossless
    assert res.plot(ax=axs[1, 1]) is axs[1, 1]
    ax = dv.plot_efficiency_sweep(gl.catalog.load("laus_epicyclic"), 1, 5, 2, pair=(1, 3), gear=1,
                                  values=[78, 80], etas=(0.99,), ax=axs[1, 2])
    assert ax.lines[0].get_ydata()[1] == pytest.approx(0.946206870, abs=1e-9)
    plt.close(fig)


def test_widget_updates_without_a_browser():
    ex = dv.efficiency_explorer(gl.catalog.load("laus_epicyclic"), 1, 5, 2, eta=0.99)
    png = ex.update()
    assert png[:4] == b"\x89PNG" and "0.94621" in ex.text
    ex.update(eta_1_3=0.98, eta_2_3=0.98)
    assert ex.result.value == pytest.approx(5 * 0.98**2 / (14 - 9 * 0.98**2), abs=1e-12)
    ex.update(N_3_in_2_3=60)  # planet gear as large as the annulus: the train cannot be built
    assert ex.text.startswith("cannot compute")
    assert set(ex.keys()) >= {"N_1_in_1_3", "eta_2_3"}


def test_with_teeth_keeps_the_module():
    m = dv.with_teeth(gl.catalog.load("laus_epicyclic"), (2, 3), 2, 64)
    gp, _ = m.gear_pair(2, 3)
    assert gp.teeth == (64, 35) and gp.radii == (64.0, 35.0)


# ------------------------------------------------------------------ command line
def test_cli_efficiency_json_and_symbolic():
    out = run("efficiency", "laus_epicyclic", "--ground", "1", "--input", "5", "--output", "2", "--eta", "0.99",
              "--symbolic", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert data["efficiency"] == pytest.approx(0.946206870, abs=1e-9)
    assert [m["driver"] for m in data["meshes"]] == ["1", "3"]
    eta = sympy.Symbol("eta_1_3", positive=True) * sympy.Symbol("eta_3_2", positive=True)
    assert sympy.simplify(sympy.sympify(data["formula"], locals={"eta_1_3": sympy.Symbol("eta_1_3", positive=True),
                                                                  "eta_3_2": sympy.Symbol("eta_3_2", positive=True)})
                          - 5 * eta / (14 - 9 * eta)) == 0


def test_cli_text_and_errors():
    out = run("efficiency", "humpage", "--input", "1", "--output", "4", "--eta-pair", "1,2=0.99")
    assert out.returncode == 0 and "0.6" in out.stdout and "driver" in out.stdout
    bad = run("efficiency", "simpson", "--input", "2", "--output", "3")
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "held" in bad.stderr
    bad = run("efficiency", "humpage", "--input", "1", "--output", "4", "--eta-pair", "1-2=0.9")
    assert bad.returncode == 2 and "A,B=ETA" in bad.stderr


# ----------------------------------------------------------------------------- what a reader sees
def test_result_tables_are_padded_name_their_columns_and_round_noise():
    """The efficiency table of chapter 5: padded cells (no "0.99-0.860656"), an arrow for the
    driver, named columns with their meaning under the table; the 8HP70's sixth gear, where
    no mesh rolls, prints 0 rather than 3e-31."""
    res = gl.davies.efficiency(gl.catalog.load("laus_epicyclic"), 1, 5, 2, eta=0.99)
    html = res._repr_html_()
    assert "padding" in html and "1 → 3" in html and "-&gt;" not in html and "->" not in html
    assert "ordinary η" in html and "ζ (signed)" in html and "per unit input power" in html
    assert "η_ij" not in html
    import dataclasses

    unloaded = dataclasses.replace(res.meshes[0], virtual_power=3.05e-31, loss=-2e-17)
    noise = dataclasses.replace(res, meshes=(unloaded,))
    assert noise.table()[0][6:] == ("0", "0") and not re.search(r"\de-\d", noise._repr_html_())


def test_layout_and_power_flow_drawings_say_what_they_show():
    from matplotlib.figure import Figure

    lay = gl.davies.layout(gl.catalog.humpage(), exact=False)
    ax = gl.davies.plot_layout(lay, ax=Figure().add_subplot())
    assert "plane x = 0" in ax.get_title()
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any("pitch point" in t for t in legend) and any("axis" in t for t in legend)
    assert any("pitch line" in t for t in legend)  # a bevel train: lines from the apex
    res = gl.davies.efficiency(gl.catalog.load("laus_epicyclic"), 1, 5, 2, eta=0.99)
    ax = res.plot(ax=Figure().add_subplot())
    ticks = [t.get_text() for t in ax.get_xticklabels()]
    assert ticks[:3] == ["A\n1-5 in", "B\n1-2 out", "C\nmesh 1-3"]


def test_efficiencies_named_by_gears():
    """Laus names the compound planet's gears 3 and 4: the library's eta_3_2 (link 3 drives
    link 2) is his eta_42, its eta_2_3 his eta_24 (Laus 2011, eqs. 76-79)."""
    e13, e32, e23 = (sympy.Symbol(n, positive=True) for n in ("eta_1_3", "eta_3_2", "eta_2_3"))
    out = gl.davies.by_gears(e13 * e32 + e23, {(2, 3): (2, 4)})
    e42, e24 = (sympy.Symbol(n, positive=True) for n in ("eta_42", "eta_24"))
    assert out == e13 * e42 + e24
    formulas = gl.davies.efficiency_formulas(gl.catalog.load("laus_epicyclic"), 1, 5, 2)
    names = {s.name for row in formulas for s in gl.davies.by_gears(row.formula, {(2, 3): (2, 4)}).free_symbols
             if s.name.startswith("eta")}
    assert names <= {"eta_1_3", "eta_3_1", "eta_42", "eta_24"} and {"eta_42", "eta_24"} <= names


def test_a_ring_declared_external_is_named_as_the_likely_mistake():
    """A planetary whose ring lacks `type: internal` does not close its loop of centre
    distances (an external 18/60 pair needs its axes 39 apart, the sun puts them 21 apart):
    the note says what to check, not only that the efficiency is unaffected."""
    m = gl.Mechanism.from_dict({
        "links": {1: "sun", 2: "planet", 3: "ring", 4: "carrier"},
        "turning_pairs": [[3, 1, "a"], [3, 4, "a"], [4, 2, "b"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [24, 18]}, {"gears": [2, 3], "teeth": [18, 60]}]})
    res = gl.davies.efficiency(m, 3, 1, 4, eta=0.98)
    assert any("type: internal" in n and "do not close a loop" in n for n in res.notes)
