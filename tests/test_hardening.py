"""A catalogue of malformed inputs across the file loader, the library API, the command line
and the exercise checks. Each must give a one-line, specific gearlib error (the command line:
exit status 2, one line on stderr, no traceback), and nothing may be written or changed."""

import math
import os

import pytest

import gearlib as gl
from cli_tools import run

GOOD = gl.catalog.path("simple_planetary").read_text()

# ----------------------------------------------------------------------------- file loader
FILES = [
    ("empty file", "", gl.FileFormatError, "empty"),
    ("only whitespace", "  \n\n", gl.FileFormatError, "empty"),
    ("a YAML list", "- 1\n- 2\n", gl.FileFormatError, "top level must be a mapping"),
    ("a YAML scalar", "42\n", gl.FileFormatError, "found int"),
    ("broken YAML", "links: [1, 2\n", gl.FileFormatError, "not valid YAML"),
    ("broken JSON", '{"links": [1, 2}', gl.FileFormatError, "not valid YAML"),
    ("tabs in YAML", "links:\n\t- 1\n", gl.FileFormatError, "not valid YAML"),
    ("no links", "gear_pairs: []\n", gl.DataFormatError, "missing `links`"),
    ("links empty", "links: []\n", gl.DataFormatError, "`links` is empty"),
    ("misspelt field", GOOD.replace("gear_pairs:", "gearpairs:"), gl.DataFormatError, "unknown field 'gearpairs'"),
    ("teeth zero", GOOD.replace("teeth: [24, 18]", "teeth: [0, 18]"), gl.ToothNumberError, "must be positive"),
    ("teeth negative", GOOD.replace("teeth: [24, 18]", "teeth: [-24, 18]"), gl.ToothNumberError, "must be positive"),
    ("teeth NaN", GOOD.replace("teeth: [24, 18]", "teeth: [.nan, 18]"), gl.ToothNumberError, "nan"),
    ("teeth infinite", GOOD.replace("teeth: [24, 18]", "teeth: [.inf, 18]"), gl.ToothNumberError, "inf"),
    ("teeth huge", GOOD.replace("teeth: [24, 18]", "teeth: [1000000000, 18]"), gl.ToothNumberError, "larger than"),
    ("teeth as text", GOOD.replace("teeth: [24, 18]", "teeth: [twenty, 18]"), gl.ToothNumberError, "'twenty'"),
    ("unknown link id", GOOD.replace("[4, 2, b]", "[4, 9, b]"), gl.UnknownLinkError, "unknown link 9"),
    ("gear without bearing", GOOD.replace("  - [4, 2, b]\n", ""), gl.CarrierError, "gear 2 has no turning pair"),
    ("no carrier", GOOD.replace("[4, 3, a]", "[1, 3, c]"), gl.CarrierError, "no possible carrier"),
    ("layout not a mapping", GOOD + "\nlayout2: 1\n", gl.DataFormatError, "unknown field 'layout2'"),
    ("turning pairs not a list", "links: [1, 2]\nturning_pairs: 3\n", gl.DataFormatError, "must be a list"),
]


@pytest.mark.parametrize("name, text, error, message", FILES, ids=[f[0] for f in FILES])
def test_file_loader(tmp_path, name, text, error, message):
    path = tmp_path / "m.yaml"
    path.write_text(text)
    before = path.stat().st_mtime_ns, os.listdir(tmp_path)
    with pytest.raises(error) as info:
        gl.load(path)
    text_ = str(info.value)
    assert message in text_ and "\n" not in text_ and str(path) in text_
    assert (path.stat().st_mtime_ns, os.listdir(tmp_path)) == before  # nothing written


# ----------------------------------------------------------------------------- library API
PLAN = gl.catalog.simple_planetary()
DIFF = gl.catalog.car_differential()
WRIST = gl.catalog.robotic_wrist()
TRANS = gl.catalog.load("liu_chen_transmission")
EPI = gl.catalog.load("laus_epicyclic")
GKC8 = gl.catalog.load("cyl_gkc_8")
API = [
    ("too few inputs", lambda: gl.speeds(DIFF, ground=1, inputs={3: 1}), gl.InputError, "needs 2 inputs"),
    ("too many inputs", lambda: gl.speeds(PLAN, ground=3, inputs={1: 1, 2: 1}), gl.InputError, "needs 1 input"),
    ("input on the ground", lambda: gl.speeds(PLAN, ground=3, inputs={3: 1}), gl.InputError, "is the ground"),
    ("dependent inputs", lambda: gl.speeds(DIFF, ground=1, inputs={2: 1, 7: 1}), gl.InputError, "not independent"),
    ("unknown ground", lambda: gl.speeds(PLAN, ground=99, inputs={1: 1}), gl.UnknownLinkError, "ground 99"),
    ("unknown input", lambda: gl.speeds(PLAN, ground=3, inputs={"sunn": 1}), gl.UnknownLinkError, "sunn"),
    ("NaN input", lambda: gl.speeds(PLAN, ground=3, inputs={1: math.nan}), gl.DataFormatError, "finite"),
    ("infinite input", lambda: gl.speeds(PLAN, ground=3, inputs={1: math.inf}), gl.DataFormatError, "finite"),
    ("text input", lambda: gl.speeds(PLAN, ground=3, inputs={1: "fast"}), gl.InputError, "is not a number"),
    ("inputs not a mapping", lambda: gl.speeds(PLAN, ground=3, inputs=3.5), gl.DataFormatError, "inputs must be"),
    ("held and driven", lambda: gl.speeds(gl.catalog.simpson(), ground=0, inputs={4: 1}, held=[4]),
     gl.ConstraintError, "held"),
    ("ground held too", lambda: gl.speeds(PLAN, ground=3, inputs={1: 1}, held=[3]), gl.ConstraintError,
     "already fixed"),
    ("clutch on one link", lambda: gl.speeds(PLAN, ground=3, inputs={1: 1}, joined=[(1, 1)]), gl.ConstraintError,
     "joins a link to itself"),
    ("bad method", lambda: gl.speeds(PLAN, ground=3, inputs={1: 1}, method="fast"), gl.DataFormatError, "method"),
    ("ratio of a 3-dof wrist", lambda: gl.ratio(WRIST, output=3, input=4, ground=0), gl.InputError, "needs 3"),
    ("symbolic mechanism, numeric method", lambda: gl.speeds(WRIST, ground=0, inputs={1: 1, 4: 1, 6: 1},
                                                             method="numeric"), gl.DataFormatError, "symbolic"),
    ("no such gear pair", lambda: PLAN.with_gear_pair((1, 3), teeth=(1, 2)), gl.UnknownLinkError, "no gear pair"),
    ("no such catalogue entry", lambda: gl.catalog.load("planetary"), gl.UnknownLinkError, "no catalogue entry"),
    ("locking gear loop", lambda: gl.Mechanism.from_dict({
        "links": [0, 1, 2, 3], "turning_pairs": [[0, 1, "a"], [0, 2, "b"], [0, 3, "c"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [20, 30]}, {"gears": [2, 3], "teeth": [30, 40]},
                       {"gears": [3, 1], "teeth": [40, 20]}]}), gl.OverconstrainedError, "locks its gears"),
    ("not a dict", lambda: gl.Mechanism.from_dict([1, 2, 3]), gl.DataFormatError, "must be a mapping"),
    # chapter 3: unit-by-unit gains
    ("gains: one input for two freedoms", lambda: gl.unit_ratio(DIFF, output=2, input=3, ground=1), gl.InputError,
     "needs 2 inputs"),
    ("gains: unknown method", lambda: gl.propagate(PLAN, output=4, inputs=[1], ground=3).relation("fast"),
     gl.InputError, "method must be one of"),
    ("gains: unknown output", lambda: gl.unit_ratio(PLAN, output=44, input=1, ground=3), gl.UnknownLinkError,
     "output 44"),
    ("shift table: mode not a mapping", lambda: gl.shift_table(TRANS, [("4th", 9, 2, 8)]), gl.DataFormatError,
     "expected a mapping"),
    # chapter 4: frequencies and cornering
    ("frequencies: NaN speed", lambda: gl.frequency_table(DIFF, ground=1, inputs={3: math.nan, 4: 1}),
     gl.DataFormatError, "not a finite number"),
    ("cornering: zero turn radius", lambda: gl.wheel_speeds(speed=30, turn_radius=0), gl.InputError,
     "non-zero radius"),
    ("bearing: balls larger than the pitch circle",
     lambda: gl.Bearing(pitch_diameter=10, ball_diameter=20, balls=8), gl.DataFormatError, "must be smaller"),
    # chapter 5: Davies' efficiency
    ("efficiency: two freedoms", lambda: gl.efficiency(gl.catalog.load("ravigneaux"), ground=0, input=1, output=2,
                                                       eta=0.98), gl.ConstraintError, "Davies' efficiency needs one"),
    ("efficiency: above one", lambda: gl.efficiency(EPI, 1, 5, 2, eta=1.5), gl.InputError, "must be in (0, 1]"),
    ("efficiency: NaN", lambda: gl.efficiency(EPI, 1, 5, 2, eta=math.nan), gl.InputError, "must be in (0, 1]"),
    ("efficiency: input is output", lambda: gl.efficiency(EPI, 1, 5, 5, eta=0.98), gl.InputError,
     "choose two different links"),
    ("efficiency: unknown output", lambda: gl.efficiency(EPI, 1, 5, 77, eta=0.98), gl.UnknownLinkError, "output 77"),
    # chapter 6: differential synthesis
    ("dgm: unknown terminal", lambda: gl.terminal_constraint(GKC8, (1, 2, 99), ground=0), gl.UnknownLinkError,
     "terminal 99"),
    ("dgm: the ground as a terminal", lambda: gl.terminal_constraint(GKC8, (0, 1, 2), ground=0), gl.InputError,
     "cannot also be a terminal"),
    ("dgm: a terminal twice", lambda: gl.terminal_constraint(GKC8, (1, 1, 2), ground=0), gl.InputError,
     "name a link twice"),
    # timing helper of chapter 3
    ("scaling: unknown method", lambda: gl.scaling.scaling("qr", (10,)), gl.InputError, "unknown method 'qr'"),
]


@pytest.mark.parametrize("name, call, error, message", API, ids=[a[0] for a in API])
def test_library_api(name, call, error, message):
    with pytest.raises(error) as info:
        call()
    assert message in str(info.value) and "\n" not in str(info.value)


# ----------------------------------------------------------------------------- command line
CLI = [
    (["speeds", "car_differential", "--ground", "1", "--input", "3=26"], "needs 2 inputs"),
    (["speeds", "car_differential", "--ground", "1", "--input", "3=nan", "--input", "4=1"], "not a number"),
    (["speeds", "missing.yaml", "--ground", "1"], "no such file"),
    (["speeds", "simple_planetary", "--ground", "3", "--input", "1=1", "--joined", "1"], "expected two links"),
    (["ratio", "simple_planetary", "--ground", "3", "--input", "1", "--output", "77"], "77"),
    (["dof", "EMPTY"], "empty"),
    (["dof", "NOT_A_MAPPING"], "top level must be a mapping"),
    (["catalog", "no_such_entry"], "no catalogue entry"),
    (["units", "missing.yaml"], "no such file"),
    (["units", "EMPTY"], "empty"),
    (["gains", "liu_chen_transmission", "--ground", "1", "--input", "4", "--output", "99"], "is not a link"),
    (["gains", "car_differential", "--ground", "1", "--input", "3", "--output", "2"], "needs 2 inputs"),
    (["frequencies", "car_differential", "--ground", "1", "--input", "3=1"], "needs 2 inputs"),
    (["frequencies", "car_differential", "--ground", "1", "--input", "3=inf", "--input", "4=1"], "not a number"),
    (["dgm", "cyl_gkc_8", "--ground", "99"], "99"),
    (["dgm", "NOT_A_MAPPING"], "top level must be a mapping"),
    (["efficiency", "laus_epicyclic", "--ground", "1", "--input", "5", "--output", "2", "--eta", "1.5"],
     "must be in (0, 1]"),
    (["efficiency", "laus_epicyclic", "--ground", "1", "--input", "5", "--output", "5"], "two different links"),
    (["efficiency", "ravigneaux", "--ground", "0", "--input", "1", "--output", "2"], "needs one"),
]


@pytest.mark.parametrize("argv, message", CLI, ids=[" ".join(c[0][:2]) + f" {i}" for i, c in enumerate(CLI)])
def test_command_line(tmp_path, argv, message):
    (tmp_path / "EMPTY").write_text("")
    (tmp_path / "NOT_A_MAPPING").write_text("- a\n")
    argv = [str(tmp_path / a) if a in ("EMPTY", "NOT_A_MAPPING") else a for a in argv]
    before = sorted(os.listdir(tmp_path))
    result = run(*argv)
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0] and "Traceback" not in result.stderr
    assert sorted(os.listdir(tmp_path)) == before


def test_command_line_usage_errors_exit_2():
    result = run("speeds")
    assert result.returncode == 2 and "Traceback" not in result.stderr and "usage:" in result.stderr


# ----------------------------------------------------------------------------- exercise checks
JUNK_ANSWERS = [None, "", "2/0", "1/0", "oo", "x y", "__import__('os')", float("nan"), float("inf"), [[1, 2], [3]],
                {"x": 1}, object(), b"2/7", 10**400, -(10**400), 1e308 * 10]


@pytest.mark.parametrize("answer", JUNK_ANSWERS, ids=[repr(a)[:20] for a in JUNK_ANSWERS])
def test_checks_take_any_junk(answer):
    for name in gl.check.names():
        result = gl.check.get(name)(answer)
        assert not result.passed and result.message and "\n" not in result.message


def test_catalogue_size():
    assert len(FILES) + len(API) + len(CLI) + len(JUNK_ANSWERS) >= 40
