"""Fault frequencies (issue 23): planetary stages against McFadden and Smith's formulas written
out here, a two-stage gearbox by hand, MATLAB's documented examples, the Case Western Reserve
bearing rig's published multipliers, and synthetic vibration signals whose FFT peaks must sit
where the table says, within one frequency bin.

Reference values are computed in this file from the standard formulas (Willis' equation for
the speeds; McFadden and Smith 1985 for the planetary lines; SKF/Harris for bearings) or
copied from the publications, never from gearlib.
"""

import csv
import io
import json
import math
import subprocess
import sys

import numpy as np
import pytest

import gearlib as gl
from cli_tools import run
from notebook_tools import ROOT

# the catalogue's planetary stage, written out: sun 17, three planets of 40, ring 97 (fixed)
ZS, ZP, ZR, N = 17, 40, 97, 3
RPM = 1480.0


def stage_by_hand(f_sun, zs=ZS, zp=ZP, zr=ZR, n=N):
    """A fixed-ring planetary stage, sun driven at f_sun Hz (Willis; McFadden and Smith 1985)."""
    fc = f_sun * zs / (zs + zr)  # carrier
    gmf = zs * (f_sun - fc)  # = zr * fc
    return {
        "carrier": fc, "gmf": gmf, "planet pass": n * fc,
        "sun fault": n * (f_sun - fc), "ring fault": n * fc,
        "planet one flank": gmf / zp, "planet both flanks": 2 * gmf / zp,
        "planet speed": abs(fc - (zs / zp) * (f_sun - fc)),  # relative to the housing
    }


def one(table, **kw):
    rows = table.select(fundamental=True, **kw)
    assert len(rows) == 1, rows
    return rows[0]


@pytest.fixture(scope="module")
def stage():
    m = gl.catalog.load("planetary_stage")
    assert [gp.teeth for gp in m.gear_pairs] == [(ZS, ZP), (ZP, ZR)] and m.planet_count(2) == N
    return gl.fault_table(m, inputs={1: f"{RPM:g}rpm"}, harmonics=3, sidebands=3)


# ----------------------------------------------------------------------------- a planetary stage
def test_planetary_stage_against_mcfadden_and_smith(stage):
    ref = stage_by_hand(RPM / 60)
    assert stage.reference_hz == pytest.approx(RPM / 60) and stage.input_unit == "rpm"
    assert one(stage, family="mesh", link=0).frequency == pytest.approx(ref["gmf"], rel=1e-12)
    assert one(stage, family="mesh", link=1).frequency == pytest.approx(ref["gmf"], rel=1e-12)
    assert one(stage, family="planet pass").frequency == pytest.approx(ref["planet pass"], rel=1e-12)
    assert one(stage, family="sun fault").frequency == pytest.approx(ref["sun fault"], rel=1e-12)
    assert one(stage, family="ring fault").frequency == pytest.approx(ref["ring fault"], rel=1e-12)
    planet = {r.name: r.frequency for r in stage.select(family="planet fault", fundamental=True)}
    assert sorted(planet.values()) == pytest.approx([ref["planet one flank"], ref["planet both flanks"]], rel=1e-12)
    # the sun fault is N times the sun's tooth rate, not once per planet mesh (review, problem 3)
    assert one(stage, family="sun fault").frequency == pytest.approx(N * ref["gmf"] / ZS)
    # shafts in Hz, rpm and orders of the sun
    shafts = {x: (f, o) for x, _, f, o in stage.shafts}
    assert shafts[3] == pytest.approx((ref["carrier"], ref["carrier"] / (RPM / 60)))
    assert shafts[2][0] == pytest.approx(ref["planet speed"])
    assert one(stage, family="shaft", link=3).rpm == pytest.approx(60 * ref["carrier"])


def test_sun_fault_sidebands_sit_around_the_sun_mesh(stage):
    ref = stage_by_hand(RPM / 60)
    got = sorted(r.frequency for r in stage.select(family="sun fault", kind="sideband") if r.harmonic == 1)
    want = sorted(ref["gmf"] + k * ref["sun fault"] for k in (-3, -2, -1, 1, 2, 3))
    assert got == pytest.approx(want, rel=1e-12)


def test_planet_pass_comb_is_mcfadden_and_smiths(stage):
    """Ring fixed, 97 = 32 x 3 + 1 teeth: the mesh harmonic m GMF cancels unless 3 divides 97 m,
    and only multiples q f_pp of the planet pass survive, the nearest ones to m x 97/3."""
    ref = stage_by_hand(RPM / 60)
    fpp = ref["planet pass"]
    for m in (1, 2, 3):
        comb = sorted(r.frequency for r in stage.select(family="planet pass", kind="sideband") if r.harmonic == m)
        q0 = round(m * ZR / N)
        present = (m * ZR) % N == 0  # then q0 f_pp is m GMF itself, a mesh line, not a sideband
        assert comb == pytest.approx([q * fpp for q in range(q0 - 3, q0 + 4) if q != q0 or not present], rel=1e-12)
        mesh = [r for r in stage.select(family="mesh", kind="GMF") if r.harmonic == m and 0 in r.links][0]
        assert ("cancels" in mesh.note) == ((m * ZR) % N != 0)
    assert stage.sets[0].passing == N and "in sequence" in stage.sets[0].notes[0]


def test_four_planets_in_phase_and_a_star_stage():
    # sun 25, 4 planets of 35, ring 95: 95 = 23 x 4 + 3 (sequence); a star stage holds the carrier
    data = {"name": "four planets", "links": {0: "housing", 1: "sun", 2: "planet", 3: "carrier", 4: "ring"},
            "turning_pairs": [[0, 1, "a"], [0, 3, "a"], [0, 4, "a"], [3, 2, "b"]],
            "gear_pairs": [{"gears": [1, 2], "teeth": [25, 35]}, {"gears": [2, 4], "teeth": [35, 95],
                                                                   "type": "internal"}],
            "planets": {2: 4}}
    m = gl.Mechanism.from_dict(data)
    t = gl.fault_table(m, ground=0, inputs={1: "50Hz", 4: 0})
    ref = stage_by_hand(50, 25, 35, 95, 4)
    assert one(t, family="sun fault").frequency == pytest.approx(ref["sun fault"])
    assert one(t, family="planet pass").frequency == pytest.approx(ref["planet pass"])
    # star: carrier held, ring free. No planet pass; the sun still meets 4 planets per turn
    star = gl.fault_table(m, ground=0, inputs={1: "50Hz", 3: 0})
    assert not star.select(family="planet pass")
    assert one(star, family="sun fault").frequency == pytest.approx(4 * 50)
    ring_speed = 50 * 25 / 95
    assert one(star, family="ring fault").frequency == pytest.approx(4 * ring_speed)


def test_side_gear_of_the_differential_meets_two_planets():
    car = gl.catalog.car_differential()
    t = gl.fault_table(car, ground=1, inputs={3: 26, 4: 30})  # rad/s, as in Table A
    hz = 1 / (2 * math.pi)
    for side in (3, 4):  # |omega_side - omega_case| = 2 rad/s, two planets: 4 rad/s (review, problem 3)
        assert one(t, family="central gear fault", link=side).frequency == pytest.approx(4 * hz)
    assert one(t, family="planet pass").frequency == pytest.approx(2 * 28 * hz)
    assert sorted(r.frequency for r in t.select(family="planet fault", fundamental=True)) == pytest.approx(
        [2.8 * hz, 2.8 * hz, 5.6 * hz, 5.6 * hz])


# ----------------------------------------------------------------------------- a two-stage gearbox
def test_two_stage_gearbox_by_hand():
    m = gl.catalog.load("two_stage_gearbox")
    assert [gp.teeth for gp in m.gear_pairs] == [(19, 71), (21, 39), (39, 99)]
    t = gl.fault_table(m, inputs={1: "1480rpm"})
    f1 = 1480 / 60
    f2 = f1 * 19 / 71
    ref = stage_by_hand(f2, 21, 39, 99, 3)
    gmf12 = 19 * f1
    assert one(t, kind="GMF", link=1).frequency == pytest.approx(gmf12)
    assert one(t, kind="GMF", link=0).frequency == pytest.approx(ref["gmf"])
    assert one(t, family="sun fault").frequency == pytest.approx(ref["sun fault"])
    assert one(t, family="shaft", link=4).order == pytest.approx(ref["carrier"] / f1)
    # tooth factors: 19/71 share nothing (no assembly-phase line), 21/39 and 39/99 share 3
    ht = {r.links: r.frequency for r in t.select(family="hunting tooth")}
    assert ht[(1, 2)] == pytest.approx(gmf12 / (19 * 71))
    assert ht[(2, 3)] == pytest.approx(ref["gmf"] * 3 / (21 * 39))
    ap = {r.links: r.frequency for r in t.select(family="assembly phase")}
    assert set(ap) == {(2, 3), (3, 0)} and ap[(2, 3)] == pytest.approx(ref["gmf"] / 3)
    assert all("every 3rd tooth" in r.note for r in t.select(family="assembly phase"))
    # 99 = 33 x 3: planets in phase, so the planet-pass sidebands are GMF +/- k f_pp
    t3 = gl.fault_table(m, inputs={1: "1480rpm"}, sidebands=2)
    comb = sorted(r.frequency for r in t3.select(family="planet pass", kind="sideband"))
    assert comb == pytest.approx([ref["gmf"] + k * ref["planet pass"] for k in (-2, -1, 1, 2)])


# ----------------------------------------------------------------------------- published values
def pair(z1, z2):
    return gl.Mechanism.from_dict({"links": [0, 1, 2], "turning_pairs": [[0, 1, "a"], [0, 2, "b"]],
                                   "gear_pairs": [{"gears": [1, 2], "teeth": [z1, z2]}]})


def test_matlab_gear_mesh_fault_bands_examples():
    # gearMeshFaultBands(20, 8, 42): Fi 20, Fo 3.8095, Fa 80, Fm 160; 'Sidebands', 1:3 adds
    # Fm +/- k Fi (100 ... 220) and Fm +/- k Fo (148.57 ... 171.43)
    t = gl.fault_table(pair(8, 42), ground=0, inputs={1: "20Hz"}, sidebands=3)
    assert one(t, family="shaft", link=2).frequency == pytest.approx(3.8095, abs=5e-5)
    assert one(t, kind="GMF").frequency == pytest.approx(160)
    assert one(t, family="assembly phase").frequency == pytest.approx(80)
    sb = sorted(round(r.frequency, 4) for r in t.select(family="mesh", kind="sideband"))
    assert sb == sorted([100, 120, 140, 180, 200, 220] + [round(160 + k * 20 * 8 / 42, 4) for k in (-3, -2, -1, 1, 2, 3)])
    assert 148.5714 in sb
    # gearMeshFaultBands(1800, 6, 8): Fo 1350, Fa 5400, Fm 10800
    t = gl.fault_table(pair(6, 8), ground=0, inputs={1: "1800Hz"})
    assert (one(t, family="shaft", link=2).frequency, one(t, family="assembly phase").frequency,
            one(t, kind="GMF").frequency) == pytest.approx((1350, 5400, 10800))


def test_matlab_bearing_fault_bands_example_and_its_ball_convention():
    # bearingFaultBands(25, 8, 2, 12, 15): Fc 10.5, Fb 73, Fo 83.9, Fi 116.1 Hz (printed)
    m = pair(8, 42).replace(turning_pairs=(
        {"links": [0, 1], "axis": "a", "bearings": [{"name": "b", "pitch_diameter": 12, "ball_diameter": 2,
                                                      "balls": 8, "contact_angle": "15*deg", "inner": 1}]},
        [0, 2, "b"]))
    t = gl.fault_table(m, ground=0, inputs={1: "25Hz"})
    got = {r.kind: r.frequency for r in t.select(bearing="b", fundamental=True)}
    assert got["FTF"] == pytest.approx(10.5, abs=0.05) and got["BPFO"] == pytest.approx(83.9, abs=0.05)
    assert got["BPFI"] == pytest.approx(116.1, abs=0.05)
    assert got["BSF"] == pytest.approx(73, abs=0.5)  # MATLAB's Fb is the ball spin ...
    assert got["2xBSF"] == pytest.approx(2 * got["BSF"])  # ... the defect rate is twice it


# SKF 6205-2RS JEM and 6203-2RS JEM, Case Western Reserve bearing data centre: defect
# frequencies as multiples of the running speed (the "rolling element" column is 2 x BSF)
# frequencies as multiples of the running speed (the "rolling element" column is 2 x BSF).
# The 6203 row agrees with its published geometry to 3e-4 only (0.3817 for (1 - g)/2 = 0.38164)
CWRU = {"input DE": ({"BPFI": 5.4152, "BPFO": 3.5848, "FTF": 0.39828, "2xBSF": 4.7135}, 1e-4),
        "input NDE": ({"BPFI": 4.9469, "BPFO": 3.0530, "FTF": 0.3817, "2xBSF": 3.9874}, 3e-4)}


def test_case_western_reserve_multipliers(stage):
    for name, (multipliers, tol) in CWRU.items():
        for kind, k in multipliers.items():
            line = one(stage, bearing=name, kind=kind)
            assert line.order == pytest.approx(k, abs=tol), (name, kind)  # orders of the input shaft
    # at the rig's 1797 rpm: BPFO of the drive-end bearing 107.4 Hz, as the data sets list it
    t = gl.fault_table(gl.catalog.load("planetary_stage"), inputs={1: "1797rpm"})
    assert one(t, bearing="input DE", kind="BPFO").frequency == pytest.approx(107.4, abs=0.05)


# ----------------------------------------------------------------------------- synthetic signals
def spectrum(x, fs):
    X = np.abs(np.fft.rfft(x * np.hanning(len(x)))) / len(x)
    return np.fft.rfftfreq(len(x), 1 / fs), X


def peak_near(freqs, X, f, floor):
    """The local maximum of |X| within one bin of f, above floor; None if there is none."""
    df = freqs[1] - freqs[0]
    i = int(round(f / df))
    window = X[max(i - 1, 1):i + 2]
    j = int(np.argmax(window)) + max(i - 1, 1)
    is_peak = X[j] >= X[j - 1] and X[j] >= X[j + 1] and X[j] > floor
    return freqs[j] if is_peak and abs(freqs[j] - f) <= df else None


def test_synthetic_mcfadden_smith_signal_has_its_peaks_on_the_comb(stage):
    """A sensor on the fixed ring hears each planet's ring mesh through a window of the
    planet's angle: sum_i w(theta_c + 2 pi i/N) cos(Z_r (theta_c + 2 pi i/N)). Its FFT has
    peaks where the table's planet-pass comb is, and nothing at GMF (97 teeth, 3 planets)."""
    fc = stage_by_hand(RPM / 60)["carrier"]
    fs, revs = 4096.0, 40
    t = np.arange(int(revs / fc * fs)) / fs
    x = np.zeros_like(t)
    for i in range(N):
        theta = 2 * np.pi * fc * t + 2 * np.pi * i / N
        x += np.exp(2.0 * np.cos(theta)) * np.cos(ZR * theta)
    freqs, X = spectrum(x, fs)  # every component on a bin: 40 carrier turns
    floor = 1e-6 * X.max()
    for r in stage.select(family="planet pass", kind="sideband"):
        if r.harmonic == 1 and abs(r.sideband) <= 2:
            assert peak_near(freqs, X, r.frequency, floor) is not None, r.name
    gmf = one(stage, kind="GMF", link=0).frequency
    assert peak_near(freqs, X, gmf, floor) is None  # McFadden and Smith: it cancels


def test_synthetic_mesh_modulated_by_the_planet_pass_and_a_sun_fault():
    m = gl.catalog.load("two_stage_gearbox")
    t = gl.fault_table(m, inputs={1: "1480rpm"}, sidebands=2)
    gmf = one(t, kind="GMF", link=0).frequency
    fpp = one(t, family="planet pass").frequency
    fsun = one(t, family="sun fault").frequency
    fs, T = 8192.0, 8.0
    tt = np.arange(int(fs * T)) / fs
    pulses = sum(np.exp(-0.5 * ((tt - k / fsun) / 2e-4) ** 2) for k in range(int(T * fsun) + 1))
    passing = np.exp(1.5 * np.cos(2 * np.pi * fpp * tt))  # each planet passing the sensor: every harmonic
    x = (passing + 0.6 * pulses) * np.cos(2 * np.pi * gmf * tt)
    freqs, X = spectrum(x, fs)
    floor = 1e-3 * X.max()
    assert peak_near(freqs, X, gmf, floor) is not None
    for r in t.select(family=("planet pass", "sun fault"), kind="sideband"):
        assert peak_near(freqs, X, r.frequency, floor) is not None, r.name


def test_synthetic_bearing_impacts_have_envelope_peaks_at_bpfo_and_bpfi(stage):
    from scipy.signal import hilbert

    t_ = gl.fault_table(gl.catalog.load("planetary_stage"), inputs={1: "1797rpm"}, sidebands=1)
    bpfo = one(t_, bearing="input DE", kind="BPFO").frequency
    bpfi = one(t_, bearing="input DE", kind="BPFI").frequency
    fr = 1797 / 60
    fs, T, f_res, tau = 20000.0, 4.0, 3000.0, 4e-4
    tt = np.arange(int(fs * T)) / fs

    def impacts(rate, gain=lambda t: 1.0):
        x = np.zeros_like(tt)
        n = int(10 * tau * fs)
        for k in range(int(T * rate)):
            t0 = k / rate
            i0 = int(np.ceil(t0 * fs))
            s = tt[i0:i0 + n] - t0
            x[i0:i0 + n] += gain(t0) * np.exp(-s / tau) * np.sin(2 * np.pi * f_res * s)
        return x

    outer = impacts(bpfo)  # outer race fixed: impacts of equal strength
    inner = impacts(bpfi, lambda t: 1 + 0.8 * np.cos(2 * np.pi * fr * t))  # the defect turns through the load zone
    for x, lines in ((outer, [bpfo]), (inner, [r.frequency for r in t_.select(bearing="input DE", family="inner race")])):
        env = np.abs(hilbert(x))
        freqs, X = spectrum(env - env.mean(), fs)
        floor = 1e-3 * X.max()
        for f in lines:
            assert peak_near(freqs, X, f, floor) is not None, f
    assert len(lines) == 3  # BPFI and BPFI +/- 1 x the shaft


# ----------------------------------------------------------------------------- cross-check, errors
def test_meshes_agree_with_the_per_contact_table():
    for name in ("planetary_stage", "two_stage_gearbox", "car_differential", "ravigneaux"):
        m = gl.catalog.load(name)
        n = int(gl.dof(m, m.ground))
        inputs = {x: k + 7 for k, x in enumerate(m.inputs[:n])}
        contacts = gl.frequency_table(m, inputs=inputs)  # rad/s
        faults = gl.fault_table(m, inputs=inputs)  # bare numbers: rad/s, lines in Hz
        for r in contacts.select(kind="mesh"):
            mesh = [x for x in faults.select(kind="GMF", fundamental=True) if set(x.links) == set(r.pair)][0]
            assert mesh.frequency == pytest.approx(float(r.frequency) / (2 * math.pi), rel=1e-12), (name, r.pair)


@pytest.mark.parametrize("kwargs, error, text", [
    ({"inputs": {1: "1480 rpmm"}}, gl.InputError, "unknown unit 'rpmm'"),
    ({"inputs": {1: "1480rpm"}, "harmonics": -1}, gl.InputError, "harmonics"),
    ({"inputs": {1: "1480rpm"}, "tolerance": 2}, gl.InputError, "tolerance"),
    ({"inputs": {1: "1480rpm"}, "reference": 9}, gl.UnknownLinkError, "9"),
    ({"inputs": {1: "x rpm"}}, gl.InputError, "must be a number"),
    ({"inputs": {1: "1480rpm"}, "unit": "furlong"}, gl.InputError, "unknown speed unit"),
])
def test_bad_input_gives_named_errors(kwargs, error, text):
    with pytest.raises(error, match=text):
        gl.fault_table(gl.catalog.load("planetary_stage"), **kwargs)


def test_bare_numbers_beside_units_need_a_unit():
    m = gl.catalog.car_differential()
    with pytest.raises(gl.InputError, match="has no unit while other inputs do"):
        gl.fault_table(m, ground=1, inputs={3: "250rpm", 4: "30"})
    same = gl.fault_table(m, ground=1, inputs={3: "250rpm", 4: "5Hz"})  # mixed units, converted
    assert one(same, family="shaft", link=4).frequency == pytest.approx(5)
    with pytest.raises(gl.InputError, match="does not turn"):
        gl.fault_table(m, ground=1, inputs={3: "250rpm", 4: "5Hz"}, reference=1)


# ----------------------------------------------------------------------------- the spectrum map
def test_fault_map_labels_never_overlap_and_the_y_axis_names_families(stage):
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    for table in (stage, gl.fault_table(gl.catalog.load("two_stage_gearbox"), inputs={1: "1480rpm"}, harmonics=3,
                                        sidebands=2, tolerance=0.01)):
        fig = Figure(figsize=(7.5, 9))
        ax = gl.plot_fault_map(table, ax=fig.add_subplot())
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        FigureCanvasAgg(fig).draw()
        renderer = fig.canvas.get_renderer()
        boxes = [t.get_window_extent(renderer) for t in ax.texts if t.get_gid() == "fault-label"]
        assert len(boxes) >= 10
        clashes = [(a, b) for i, a in enumerate(boxes) for b in boxes[i + 1:] if a.overlaps(b)]
        assert not clashes
        names = [t.get_text() for t in ax.get_yticklabels()]
        assert set(names) <= set(gl.adjacency.FAMILIES) and "mesh" in names
        assert ax.get_xscale() == "log"


# ----------------------------------------------------------------------------- the command line
STAGE = ("frequencies", "planetary_stage", "--input", "1=1480rpm")


def test_cli_units_json_csv_and_plot(tmp_path):
    a = json.loads(run(*STAGE, "--json").stdout)
    b = json.loads(run("frequencies", "planetary_stage", "--input", "1=74/3Hz", "--json").stdout)
    assert a["input_unit"] == "rpm" and b["input_unit"] == "Hz"
    assert [r["hz"] for r in a["lines"]] == pytest.approx([r["hz"] for r in b["lines"]], rel=1e-12)
    c = json.loads(run("frequencies", "planetary_stage", "--input", f"1={1480 * math.pi / 30}rad/s", "--json").stdout)
    assert [r["hz"] for r in c["lines"]] == pytest.approx([r["hz"] for r in a["lines"]], rel=1e-9)
    rows = list(csv.DictReader(io.StringIO(run(*STAGE, "--csv", "--sidebands", "1").stdout)))
    sun = [r for r in rows if r["family"] == "sun fault" and r["sideband"] == "0"]
    assert float(sun[0]["hz"]) == pytest.approx(stage_by_hand(RPM / 60)["sun fault"])
    out = tmp_path / "map.png"
    res = run(*STAGE, "--plot", str(out))
    assert res.returncode == 0 and out.read_bytes()[:4] == b"\x89PNG"
    assert "sun 1 local fault" in res.stdout and "rpm" in res.stdout and "order" in res.stdout


@pytest.mark.parametrize("extra, text", [
    (("--input", "1=1480 rpmm"), "unknown unit"),
    (("--input", "1=1480rpm", "--plot", "no/such/dir/map.png"), "no directory"),
    (("--input", "1=1480rpm", "--plot", "map.bmp"), ".png, .svg or .pdf"),
    (("--input", "1=1480rpm", "--harmonics", "x"), "invalid int value"),
    (("--input", "1=1480rpm", "--reference", "0"), "does not turn"),
])
def test_cli_json_stays_json_on_errors(extra, text):
    res = run("frequencies", "planetary_stage", *extra, "--json")
    assert res.returncode == 2 and "Traceback" not in res.stderr and text in res.stderr
    assert text in json.loads(res.stdout)["error"]


def test_cli_piped_into_head_ends_quietly():
    cmd = (f"{sys.executable} -m gearlib frequencies two_stage_gearbox --input 1=1480rpm --harmonics 20 "
           "--sidebands 20 | head -n 3")
    out = subprocess.run(["bash", "-c", cmd], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert out.stdout.startswith("fault frequencies of 'two-stage gearbox'")
    assert out.stderr == "", out.stderr
