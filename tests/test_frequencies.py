"""Contact frequencies: Penaud and Alazard's eq. (13) and Table A (gear rows exactly, bearing rows
in both the standard form and the paper's convention), a planetary gearbox with a rotating
carrier against hand-derived values, the widget's car model, the command line, and errors.

Expected values come from the paper's printed numbers, the seed notes' errata (PA-E3, PA-E4,
PA-E6) or hand formulas written out here; none comes from gearlib.
"""

import json
import math
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import gearlib as gl
from cli_tools import run

PRINTED_1 = 0.05  # half a unit of one printed decimal

# the car differential's bearings (PA Sec. 3): D_m = 54 mm, d_b = 5 mm, Z = 25, alpha = 15 degrees
DM, DB, Z, ALPHA = 54.0, 5.0, 25, math.radians(15)
FR = 28.0  # |omega_7 - omega_1| when cornering (caveat 6)
G = DB * math.cos(ALPHA) / DM


@pytest.fixture(scope="module")
def car():
    return gl.catalog.car_differential()


@pytest.fixture(scope="module")
def cornering(car):
    return gl.frequency_table(car, ground=1, inputs={3: 26, 4: 30})


@pytest.fixture(scope="module")
def cornering_paper(car):
    return gl.frequency_table(car, ground=1, inputs={3: 26, 4: 30}, convention="paper")


def planetary(sun=24, planet=18, ring=60):
    """A simple planetary written out here (not from the catalogue): sun 1, planet 2, ring 3, carrier 4."""
    return gl.Mechanism.from_dict({
        "name": "planetary",
        "links": {1: "sun", 2: "planet", 3: "ring", 4: "carrier"},
        "turning_pairs": [[4, 1, "a"], [4, 3, "a"], [4, 2, "b"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [sun, planet]},
                       {"gears": [2, 3], "teeth": [planet, ring], "type": "internal"}],
    })


# ----------------------------------------------------------------------------- example 1
def test_eq13_gear_frequencies_of_the_bevel_planet():
    ex1 = gl.catalog.load("penaud_example_1")
    table = gl.frequency_table(ex1, ground=1, inputs={2: 10}, unit="Hz")
    meshes = table.select(kind="mesh")
    assert [r.pair for r in meshes] == [(1, 3), (2, 3)]
    for r in meshes:
        assert float(r.frequency) == pytest.approx(93.75, abs=1e-9)  # eq. (13)
    # by hand: the carrier turns at 0.625 * 10 Hz, so the sun (held) meets it at 6.25 Hz
    assert float(table.select(kind="tooth", link=1)[0].frequency) == pytest.approx(6.25, abs=1e-9)
    assert table.select(kind="tooth", link=1)[0].sources == 15


# ----------------------------------------------------------------------------- Table A, gear rows
TABLE_A_GEARS = [  # (pair, kind, link, printed frequency, sources)
    ((2, 7), "mesh", None, 1820, None),
    ((2, 7), "tooth", 2, 140, 13),
    ((2, 7), "tooth", 7, 28, 65),
] + [
    row
    for pair in ((3, 5), (3, 6), (4, 5), (4, 6))
    for row in ((pair, "mesh", None, 28, None), (pair, "tooth", pair[0], 2, 14), (pair, "tooth", pair[1], 2.8, 10))
]


@pytest.mark.parametrize("pair, kind, link, printed, sources", TABLE_A_GEARS)
def test_table_a_gear_rows_exactly(cornering, pair, kind, link, printed, sources):
    rows = cornering.select(kind=kind, pair=pair, link=link)
    assert len(rows) == 1
    row = rows[0]
    assert float(row.frequency) == pytest.approx(printed, abs=1e-9)
    assert row.sources == sources


def test_spur_and_bevel_meshes_agree_from_either_gear(cornering, car):
    # the mesh frequency from gear j, N_j |omega_j - omega_k|, is the same as from gear i
    for gp in car.gear_pairs:
        mesh = cornering.select(kind="mesh", pair=gp.gears)[0]
        tooth_b = cornering.select(kind="tooth", pair=gp.gears, link=gp.gears[1])[0]
        assert float(mesh.frequency) == pytest.approx(gp.teeth[1] * float(tooth_b.frequency), rel=1e-12)


# ----------------------------------------------------------------------------- Table A, bearing rows
def test_table_a_bearing_rows_in_the_papers_convention(cornering_paper):
    rows = cornering_paper.select(pair=(1, 7))
    assert [r.kind for r in rows] == ["inner ring", "outer ring", "ball"] * 2
    printed = [381.3, 318.7, 310.6] * 2
    sources = [1, 1, 25] * 2
    for r, f, n in zip(rows, printed, sources):
        assert abs(float(r.frequency) - f) <= PRINTED_1, r
        assert r.sources == n
    assert [r.bearing for r in rows] == ["bearing 1"] * 3 + ["bearing 2"] * 3


def test_table_a_bearing_rows_in_the_standard_form(cornering):
    rows = {(r.bearing, r.kind): float(r.frequency) for r in cornering.select(pair=(1, 7))}
    for name in ("bearing 1", "bearing 2"):
        # PA-E3 corrected formulas, the same in both conventions: 381.3 and 318.7 as printed
        assert abs(rows[name, "inner ring"] - 381.3) <= PRINTED_1
        assert abs(rows[name, "outer ring"] - 318.7) <= PRINTED_1
        # PA-E4: the standard ball spin is 149.99 and a ball defect 2 x 149.99 = 299.98, not 310.6
        assert abs(rows[name, "ball spin"] - 149.99) <= 0.005
        assert abs(rows[name, "ball"] - 299.98) <= 0.005
        # cage relative to the (still) outer ring, FTF = (1 - g) f_r / 2, by hand
        assert rows[name, "cage"] == pytest.approx((1 - G) / 2 * FR, rel=1e-12)


def test_bearing_formulas_by_hand():
    brg = gl.Bearing(pitch_diameter=DM, ball_diameter=DB, balls=Z, contact_angle="15*deg", inner=7)
    f = gl.bearing_frequencies(brg, omega_inner=28, omega_outer=0)
    # SKF / Harris standard forms, written out
    assert f.inner_ring == pytest.approx(Z / 2 * (1 + G) * FR, rel=1e-12)
    assert f.outer_ring == pytest.approx(Z / 2 * (1 - G) * FR, rel=1e-12)
    assert f.ball_spin == pytest.approx(DM / (2 * DB) * (1 - G**2) * FR, rel=1e-12)
    assert f.ball_defect == pytest.approx(2 * f.ball_spin)
    # the paper's Table A ball line: d_b -> d_b cos(alpha) in the prefactor as well (PA-E4)
    assert f.paper_ball == pytest.approx(DM / (DB * math.cos(ALPHA)) * (1 - G**2) * FR, rel=1e-12)
    assert abs(f.paper_ball - 310.563) < 5e-4
    assert f.paper_ball / f.ball_defect == pytest.approx(1 / math.cos(ALPHA))  # the +3.5 %
    # PA-E6: with alpha = 15 read as radians the inner ring would be at 325.4 instead of 381.3
    g_rad = DB * math.cos(15) / DM
    assert abs(Z / 2 * (1 + g_rad) * FR - 325.4) <= PRINTED_1


def test_bearing_with_both_rings_turning_uses_their_relative_speed():
    brg = gl.Bearing(pitch_diameter=40, ball_diameter=8, balls=9)
    g = 8 / 40
    moving = gl.bearing_frequencies(brg, omega_inner=37, omega_outer=12)  # relative speed 25
    still = gl.bearing_frequencies(brg, omega_inner=25)
    assert moving.inner_ring == pytest.approx(still.inner_ring) == pytest.approx(4.5 * (1 + g) * 25)
    assert moving.outer_ring == pytest.approx(4.5 * (1 - g) * 25)
    # the cage: ((1 - g) omega_i + (1 + g) omega_e) / 2, and BPFI + BPFO = Z f_r
    assert moving.cage_speed == pytest.approx(((1 - g) * 37 + (1 + g) * 12) / 2)
    assert moving.inner_ring + moving.outer_ring == pytest.approx(9 * 25)


# ----------------------------------------------------------------------------- rotating carrier
def test_planetary_with_a_rotating_carrier_against_hand_values():
    # ring held, sun at 70 rad/s. By hand: carrier = 70 * 24 / (24 + 60) = 20 rad/s; planet relative
    # to the carrier = -(24/18)(70 - 20) = -200/3 rad/s; mesh = 24 * 50 = 18 * 200/3 = 60 * 20 = 1200.
    table = gl.frequency_table(planetary(), ground=3, inputs={1: 70})
    expected = [
        ((1, 2), "mesh", None, Fraction(1200), None),
        ((1, 2), "tooth", 1, Fraction(50), 24),
        ((1, 2), "tooth", 2, Fraction(200, 3), 18),
        ((2, 3), "mesh", None, Fraction(1200), None),
        ((2, 3), "tooth", 2, Fraction(200, 3), 18),
        ((2, 3), "tooth", 3, Fraction(20), 60),
    ]
    got = [(r.pair, r.kind, r.link, r.frequency, r.sources) for r in table]
    assert got == expected
    # relative to the ground the planet turns at 140/3 rad/s: not its tooth frequency
    assert table.select(kind="tooth", link=2)[0].frequency != Fraction(140, 3)


def test_planetary_two_inputs_and_a_planet_bearing():
    # sun, ring and carrier on a frame 0; sun at 100 and ring at -20 rad/s, the carrier free. By hand:
    # omega_c = (N_s omega_s + N_r omega_r) / (N_s + N_r) = (2400 - 1200) / 84 = 100/7
    mech = gl.Mechanism.from_dict({
        "links": {0: "frame", 1: "sun", 2: "planet", 3: "ring", 4: "carrier"},
        "turning_pairs": [[0, 1, "a"], [0, 3, "a"], [0, 4, "a"], [4, 2, "b"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [24, 18]},
                       {"gears": [2, 3], "teeth": [18, 60], "type": "internal"}],
    })
    bearing = [{"pair": [4, 2], "name": "planet bearing", "pitch_diameter": 30, "ball_diameter": 6, "balls": 8,
                "inner": 4}]
    table = gl.frequency_table(mech, ground=0, inputs={1: 100, 3: -20}, bearings=bearing)
    wc = Fraction(100, 7)
    mesh = 24 * (100 - wc)
    assert table.select(kind="mesh", pair=(1, 2))[0].frequency == mesh == Fraction(14400, 7)
    assert table.select(kind="mesh", pair=(2, 3))[0].frequency == 60 * (wc + 20)  # the same, from the ring
    planet_rel = mesh / 18
    assert table.select(kind="tooth", pair=(1, 2), link=2)[0].frequency == planet_rel
    # the planet bearing sees the planet relative to the carrier: f_r = 800/7
    g = 6 / 30
    outer = table.select(kind="outer ring", pair=(4, 2))[0]
    assert float(outer.frequency) == pytest.approx(8 / 2 * (1 - g) * float(planet_rel), rel=1e-12)
    assert outer.link == 2 and table.select(kind="inner ring")[0].link == 4


def test_given_speeds_must_satisfy_willis():
    mech = planetary()
    good = {1: 70, 2: Fraction(-140, 3), 3: 0, 4: 20}
    assert gl.frequency_table(mech, good).select(kind="mesh")[0].frequency == 1200
    with pytest.raises(gl.ConstraintError, match=r"Willis equation of gear pair \(1, 2\)"):
        gl.frequency_table(mech, {1: 70, 2: -40, 3: 0, 4: 20})
    with pytest.raises(gl.InputError, match="no speed for link 4"):
        gl.frequency_table(mech, {1: 70, 2: -40, 3: 0})
    with pytest.raises(gl.InputError, match="3 values for the 4 links"):
        gl.frequency_table(mech, [70, -40, 0])


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 10**6), st.integers(4, 9), st.sampled_from([0.0, 0.5]))
def test_every_mesh_frequency_is_the_same_from_both_gears(seed, n, bevel):
    assume(n >= 3)
    m = gl.random_mechanism(n, dof=1, rng=seed, bevel=bevel)
    table = gl.frequency_table(m, ground=0, inputs={m.link_ids[1]: 7}, method="numeric")
    for gp in m.gear_pairs:
        if gp.teeth is None:
            continue
        mesh = float(table.select(kind="mesh", pair=gp.gears)[0].frequency)
        tb = float(table.select(kind="tooth", pair=gp.gears, link=gp.gears[1])[0].frequency)
        assert mesh == pytest.approx(gp.teeth[1] * tb, rel=1e-9, abs=1e-9)


# ----------------------------------------------------------------------------- errors
@pytest.mark.parametrize("bearings, error, text", [
    ([{"pair": [2, 5], "pitch_diameter": 54, "ball_diameter": 5, "balls": 25}], gl.UnknownLinkError,
     r"pair \(2, 5\), which is not a turning pair"),
    ([{"pair": [1, 9], "pitch_diameter": 54, "ball_diameter": 5, "balls": 25}], gl.UnknownLinkError, "9"),
    ([{"pair": [1, 7], "pitch_diameter": 54, "ball_diameter": 60, "balls": 25}], gl.DataFormatError,
     "ball_diameter 60.0 must be smaller than pitch_diameter 54.0"),
    ([{"pair": [1, 7], "pitch_diameter": 54, "ball_diameter": 5, "balls": 25, "contact_angle": 15}],
     gl.DataFormatError, r"15\*deg"),
    ([{"pair": [1, 7], "pitch_diameter": 54, "ball_diameter": 5, "balls": 0}], gl.ToothNumberError, "positive"),
    ([{"pitch_diameter": 54, "ball_diameter": 5, "balls": 25}], gl.DataFormatError, "missing `pair"),
    ([{"pair": [1, 7], "pitch_diameter": 54, "ball_diameter": 5, "balls": 25, "inner": 3}], gl.UnknownLinkError,
     "inner ring on link 3"),
    ("not a list", gl.FileFormatError, "no such file"),
])
def test_malformed_bearings_give_named_errors(car, bearings, error, text):
    with pytest.raises(error, match=text):
        gl.frequency_table(car, ground=1, inputs={3: 26, 4: 30}, bearings=bearings)


@pytest.mark.parametrize("kwargs, error, text", [
    ({"ground": 1, "inputs": {3: 26}}, gl.InputError, "needs 2 inputs; got 1"),
    ({"ground": 1, "inputs": {3: 26, 8: 1}}, gl.UnknownLinkError, "8"),
    ({"ground": 1, "inputs": {3: 26, 4: 30}, "convention": "skf"}, gl.DataFormatError, "convention"),
    ({"ground": 1, "inputs": {7: 1, 2: 1}}, gl.InputError, "not independent"),
])
def test_wrong_inputs_give_named_errors(car, kwargs, error, text):
    with pytest.raises(error, match=text):
        gl.frequency_table(car, **kwargs)


def test_bearings_file_replaces_the_pairs_bearings(car, tmp_path):
    path = tmp_path / "b.yaml"
    path.write_text("bearings:\n  - {pair: [7, 1], name: big, pitch_diameter: 80, ball_diameter: 10, balls: 16,"
                    " inner: 7}\n")
    table = gl.frequency_table(car, ground=1, inputs={3: 26, 4: 30}, bearings=str(path))
    rows = table.select(pair=(1, 7))
    assert {r.bearing for r in rows} == {"big"}
    assert float(table.select(kind="outer ring")[0].frequency) == pytest.approx(8 * (1 - 10 / 80) * FR)
    (tmp_path / "empty.yaml").write_text("")
    with pytest.raises(gl.FileFormatError, match="empty"):
        gl.load_bearings(tmp_path / "empty.yaml")


# ----------------------------------------------------------------------------- data, display, plot
def test_table_as_data_text_and_json(cornering):
    data = cornering.to_json()
    assert data["unit"] == "rad/s" and data["speeds"]["2"] == [-140.0, 0.0]
    assert data["rows"][0] == {"pair": [2, 7], "kind": "mesh", "frequency": 1820.0,
                               "description": "mesh of gear pair (2, 7) (carrier 1)", "sources": None,
                               "link": None, "bearing": None}
    text = str(cornering)
    assert "1820" in text and "defect on the inner ring of bearing 1" in text
    assert "<table>" in cornering._repr_html_()


def test_spectrum_plot_draws_one_line_per_distinct_frequency(cornering):
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    ax = Figure().add_subplot()
    assert gl.plot_spectrum(cornering, ax=ax) is ax
    distinct = {round(float(f), 9) for f in cornering.frequencies() if f > 0}
    assert sum(len(c.get_segments()) for c in ax.collections) == len(distinct)
    assert len(ax.collections) == len({c.get_label() for c in ax.collections})  # one collection per kind
    assert ax.get_xscale() == "log"  # 2 to 1820 rad/s


# ----------------------------------------------------------------------------- widget's car model
def test_wheel_speeds_reproduce_the_papers_corner():
    # v / r = (30 / 3.6) / (25/84) = 28 rad/s; t / 2R = 0.75 / 10.5 = 1/14
    left, right = gl.wheel_speeds(30, 10.5)
    assert left == pytest.approx(30) and right == pytest.approx(26)
    assert gl.wheel_speeds(30, -10.5) == pytest.approx((26, 30))
    for bad in (0, float("nan"), "10"):
        with pytest.raises(gl.InputError):
            gl.wheel_speeds(30, bad)


def test_cornering_explorer_updates_without_a_browser():
    ex = gl.cornering_explorer()
    png = ex.update(speed=30, turn_radius=10.5, turn="right")
    assert png.startswith(b"\x89PNG")
    assert ex.speeds[2] == pytest.approx(-140) and ex.speeds[3] == pytest.approx(26)
    assert float(ex.table.select(kind="mesh", pair=(2, 7))[0].frequency) == pytest.approx(1820)
    ex.update(speed=30, turn="straight")
    planet_teeth = ex.table.select(kind="tooth", link=5)
    assert all(abs(float(r.frequency)) < 1e-9 for r in planet_teeth)  # no relative motion in the case
    with pytest.raises(gl.InputError, match="turn must be"):
        ex.update(turn="up")


def test_static_twin_plots(car):
    from matplotlib.figure import Figure

    ax = Figure().add_subplot()
    assert gl.plot_cornering(car, what="frequencies", ax=ax, curvatures=[-0.1, 0, 0.1]) is ax
    assert ax.get_lines()
    with pytest.raises(gl.DataFormatError):
        gl.plot_cornering(car, what="torques", ax=ax)


def test_cornering_twin_names_every_curve_without_overlap(car):
    """The static twin names each curve beside the axes (no legend), at 8 pt, and pushes the
    labels apart: ball (300), BPFO (319) and BPFI (381 rad/s) lie within 0.11 decades."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7.5, 4.2))
    ax = gl.plot_cornering(car, ax=fig.add_subplot())
    fig.canvas.draw()
    labels = [t for t in ax.texts if t.get_text() and not t.get_text().startswith("R =")]
    names = [t.get_text() for t in labels]
    assert ax.get_legend() is None and {"BPFI (2 bearings)", "BPFO (2 bearings)", "ball (2 bearings)"} <= set(names)
    assert min(t.get_fontsize() for t in labels) >= 8
    # label centres (axes fractions, va=center) at least one line of 8-pt text apart, in pixels
    centres = sorted(t.xyann[1] * ax.bbox.height for t in labels)
    line = 1.2 * 8 * fig.dpi / 72
    assert all(b - a >= line for a, b in zip(centres, centres[1:])), "two curve labels overlap"


def test_table_titles_name_the_bearing_convention_only_with_bearings(car):
    """Example 1 has no bearings: no "(standard bearing formulas)" in its title. Table cells are
    padded and the pair column does not wrap ("(2, 7)" stays on one line)."""
    t1 = gl.frequency_table(gl.catalog.load("penaud_example_1"), ground=1, inputs={2: 10})
    assert "bearing" not in t1.title and "bearing" not in str(t1).splitlines()[0]
    t2 = gl.frequency_table(car, ground=1, inputs={3: 26, 4: 30})
    assert t2.title.endswith("(standard bearing formulas)")
    html = t2._repr_html_()
    assert "padding" in html and "white-space: nowrap'>(2, 7)</td>" in html
    ax = t2.plot()
    assert "not an amplitude" in ax.get_ylabel()


# ----------------------------------------------------------------------------- command line
CORNER = ("frequencies", "car_differential", "--ground", "1", "--input", "3=26", "--input", "4=30")


def test_cli_frequencies_json_paper_convention():
    out = run(*CORNER, "--convention", "paper", "--json", "--contacts")  # the paper's per-contact table
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    freqs = sorted({round(r["frequency"], 1) for r in data["rows"]})
    assert freqs == [2.0, 2.8, 28.0, 140.0, 310.6, 318.7, 381.3, 1820.0]  # Table A's numbers


def test_cli_frequencies_with_a_bearings_file(tmp_path):
    path = tmp_path / "b.yaml"
    path.write_text("- {pair: [1, 2], name: pinion bearing, pitch_diameter: 40, ball_diameter: 8, balls: 9, "
                    "inner: 2}\n")
    result = run(*CORNER, "--bearings", str(path), "--contacts")
    assert result.returncode == 0, result.stderr
    out = result.stdout
    # the pinion turns at 140 rad/s: BPFO = 4.5 (1 - 0.2) 140 = 504
    assert "504" in out and "pinion bearing" in out
    # the fault table gives it in Hz (the inputs are in rad/s): 504 / (2 pi) = 80.21
    result = run(*CORNER, "--bearings", str(path))
    assert "BPFO pinion bearing" in result.stdout and "80.214" in result.stdout


@pytest.mark.parametrize("extra, text", [
    (("--input", "3=26"), "needs 2 inputs; got 1"),
    (("--input", "3=26", "--input", "4=30", "--bearings", "nope.yaml"), "no such file"),
    (("--input", "3=26", "--input", "4=30", "--bearings", "BAD"), "not a turning pair"),
])
def test_cli_errors_are_one_line(tmp_path, extra, text):
    bad = tmp_path / "bad.yaml"
    bad.write_text("- {pair: [2, 5], pitch_diameter: 54, ball_diameter: 5, balls: 25}\n")
    extra = tuple(str(bad) if x == "BAD" else x for x in extra)
    result = run("frequencies", "car_differential", "--ground", "1", *extra)
    status, err = result.returncode, result.stderr
    assert status == 2
    assert "Traceback" not in err and text in err
    assert len(err.strip().splitlines()) == 1


def test_speed_bars_keep_their_labels_apart(car):
    """Seven links with long names and complex speeds: no two tick labels, and no two value
    labels, overlap (drawn at the size plot_speeds chooses)."""
    ax = gl.speeds(car, ground=1, inputs={3: 26, 4: 30}).plot()
    fig = ax.figure
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for texts in (ax.get_xticklabels(), ax.texts):
        boxes = sorted((t.get_window_extent(renderer) for t in texts if t.get_text()), key=lambda b: b.x0)
        assert len(boxes) == 7
        clashes = [(a.x1, b.x0) for a, b in zip(boxes, boxes[1:]) if a.x1 > b.x0]
        assert not clashes, f"labels overlap: {clashes}"
    import matplotlib.pyplot as plt

    plt.close(fig)
