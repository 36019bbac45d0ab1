"""A catalogue of malformed inputs across the file loader, the library API, the command line
and the exercise checks. Each must give a one-line, specific gearlib error (the command line:
exit status 2, one line on stderr, no traceback), and nothing may be written or changed."""

import math
import os
import pathlib

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


# =============================================================================================
# Issue 25: bad input by class. Each case below is new (the lists above are the catalogue as it
# stood before); test_catalogue_size counts them.
# =============================================================================================
import json  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402

import numpy as np  # noqa: E402
import sympy  # noqa: E402

SIMPSON = gl.catalog.simpson()
PAIR = "links: [1, 2, 3]\nturning_pairs: [[3, 1, a], [3, 2, b]]\n"


def _alias_bomb(levels=9, width=9):
    text = "a0: &a0 [" + ", ".join(["x"] * width) + "]\n"
    for k in range(1, levels):
        text += f"a{k}: &a{k} [" + ", ".join([f"*a{k - 1}"] * width) + "]\n"
    return text + f"links: *a{levels - 1}\n"


# ----------------------------------------------------------------------------- files, by text
FILES_25 = [
    ("alias bomb", _alias_bomb(), gl.FileFormatError, "alias bomb"),
    ("deep flow nesting", "links: " + "[" * 100_000 + "]" * 100_000 + "\n", gl.FileFormatError, "nested more than"),
    ("deep mapping nesting", "links: [1]\nname: " + "{a: " * 5000 + "1" + "}" * 5000 + "\n", gl.FileFormatError,
     "nested more than"),
    ("deep block nesting", "links: [1]\nname:\n" + "- " * 3000 + "x\n", gl.FileFormatError, "nested more than"),
    ("duplicate YAML key", GOOD + "\nname: again\n", gl.FileFormatError, "given twice"),
    ("duplicate key in a gear pair", GOOD.replace("teeth: [24, 18]", "teeth: [24, 18], teeth: [24, 19]"),
     gl.FileFormatError, "'teeth' is given twice"),
    ("duplicate JSON key", '{"links": [1, 2], "links": [1, 2, 3]}', gl.FileFormatError, "'links' is given twice"),
    ("type and kind contradict", GOOD.replace("type: internal", "type: external, kind: internal"),
     gl.DataFormatError, "disagree"),
    ("a link's name is a mapping", GOOD.replace("1: sun", "1: {a: 1}"), gl.DataFormatError, "link 1: `name`"),
    ("the mechanism's name is a mapping", GOOD.replace("name: simple planetary", "name: {a: 1}"),
     gl.DataFormatError, "`name` must be text"),
    ("the mechanism's name is a list", GOOD.replace("name: simple planetary", "name: [a, b]"),
     gl.DataFormatError, "`name` must be text"),
    ("tooth number of thousands of digits", GOOD.replace("[24, 18]", "[" + "9" * 5000 + ", 18]"),
     gl.FileFormatError, "thousands of digits"),
    ("tooth number of 400 digits", GOOD.replace("[24, 18]", "[" + "9" * 400 + ", 18]"),
     gl.ToothNumberError, "an integer of 400 digits is larger than"),
    ("ratio 1e400", PAIR + "gear_pairs: [{gears: [1, 2], ratio: '1e400'}]\n", gl.DataFormatError,
     "beyond the range of a float"),
    ("ratio exp(1000)", PAIR + "gear_pairs: [{gears: [1, 2], ratio: 'exp(1000)'}]\n", gl.DataFormatError,
     "beyond the range of a float"),
    ("ratio power tower", PAIR + "gear_pairs: [{gears: [1, 2], ratio: '9^9^9^9'}]\n", gl.DataFormatError,
     "far too large"),
    ("ratio 2^-5000", PAIR + "gear_pairs: [{gears: [1, 2], ratio: '2^-5000'}]\n", gl.DataFormatError,
     "far too large"),
    ("ratio of 3000 characters", PAIR + "gear_pairs: [{gears: [1, 2], ratio: '" + "1+" * 1500 + "1'}]\n",
     gl.DataFormatError, "too long"),
    ("angle power tower", PAIR + "gear_pairs: [{gears: [1, 2], teeth: [20, 40], type: bevel, "
     "angles: ['9^9^9^9', 0]}]\n", gl.DataFormatError, "far too large"),
    ("angle 1e400", PAIR + "gear_pairs: [{gears: [1, 2], teeth: [20, 40], type: bevel, angles: [1e400, 0]}]\n",
     gl.DataFormatError, "angle"),
    ("angle sin(1e300)", PAIR + "gear_pairs: [{gears: [1, 2], teeth: [20, 40], type: bevel, "
     "angles: ['sin(1e300)', 0]}]\n", gl.DataFormatError, "far too large"),
    ("parentheses 60 deep", PAIR + "gear_pairs: [{gears: [1, 2], ratio: '" + "(" * 60 + "2" + ")" * 60 + "'}]\n",
     gl.DataFormatError, "parentheses"),
    ("no axis label and no carrier", "links: [1, 2, 3]\nturning_pairs: [[3, 1], [3, 2]]\n"
     "gear_pairs: [{gears: [1, 2], teeth: [20, 40]}]\n", gl.AxisError, "no axis label"),
    ("a given label contradicts the carriers", "links: [1, 2, 3, 4]\nturning_pairs: [[4, 1, a], [1, 2, b], [4, 3]]\n"
     "gear_pairs: [{gears: [2, 3], teeth: [20, 40], carrier: 4}]\n", gl.AxisError, "the carriers put it"),
    ("a disconnected file lists its pieces briefly", "links: [" + ", ".join(map(str, range(2000))) + "]\n",
     gl.DisconnectedError, "; ..."),
]


@pytest.mark.parametrize("name, text, error, message", FILES_25, ids=[f[0] for f in FILES_25])
def test_file_loader_issue_25(tmp_path, name, text, error, message):
    test_file_loader(tmp_path, name, text, error, message)
    assert len(str(pytest.raises(error, gl.loads, text).value)) < 600  # one short line, whatever the file


# ----------------------------------------------------------------------------- files, by kind
def _fifo(d):
    os.mkfifo(d / "pipe.yaml")
    return d / "pipe.yaml"


def _loop(d):
    (d / "loop.yaml").symlink_to(d / "loop.yaml")
    return d / "loop.yaml"


def _huge(d):
    with open(d / "huge.yaml", "wb") as f:
        f.truncate(65 * 2**20)  # sparse: costs no disk
    return d / "huge.yaml"


def _directory(d):
    (d / "sub.yaml").mkdir()
    return d / "sub.yaml"


def _binary(d):
    (d / "bin.yaml").write_bytes(b"\xff\xfe\x00links")
    return d / "bin.yaml"


KINDS_25 = [
    ("a FIFO", _fifo, "named pipe"),
    ("a symbolic-link loop", _loop, "loops back on itself"),
    ("a 65 MiB file", _huge, "MiB"),
    ("a directory", _directory, "is a directory"),
    ("/dev/zero", lambda d: pathlib.Path("/dev/zero"), "is a device"),
    ("not UTF-8", _binary, "not a text file"),
]


@pytest.mark.parametrize("name, make, message", KINDS_25, ids=[k[0] for k in KINDS_25])
def test_files_that_are_not_mechanism_files(tmp_path, name, make, message):
    path = make(tmp_path)
    for read in (gl.load, gl.load_bearings):  # a mechanism file and a --bearings file alike
        with pytest.raises(gl.FileFormatError) as info:
            read(path)
        assert message in str(info.value) and str(path) in str(info.value) and "\n" not in str(info.value)


# ----------------------------------------------------------------------------- library slips
API_25 = [
    ("held='14' is link 14, not links 1 and 4", lambda: gl.speeds(SIMPSON, ground=0, inputs={1: 1}, held="14"),
     gl.UnknownLinkError, "held link '14'"),
    ("ground=[3]", lambda: gl.speeds(PLAN, ground=[3], inputs={1: 1}), gl.DataFormatError, "ground: expected one link"),
    ("ground=True", lambda: gl.speeds(PLAN, ground=True, inputs={3: 1}), gl.DataFormatError, "True/False"),
    ("ground={}", lambda: gl.speeds(PLAN, ground={}, inputs={3: 1}), gl.DataFormatError, "got a dict"),
    ("ground=1.5", lambda: gl.dof(PLAN, ground=1.5), gl.DataFormatError, "got a float"),
    ("ratio input=[1]", lambda: gl.ratio(PLAN, output=4, input=[1], ground=3), gl.DataFormatError, "input: expected"),
    ("ratio output=[4]", lambda: gl.ratio(PLAN, output=[4], input=1, ground=3), gl.DataFormatError, "output: expected"),
    ("unit_ratio input=[1]", lambda: gl.unit_ratio(PLAN, output=4, input=[1], ground=3), gl.DataFormatError,
     "input: expected"),
    ("efficiency input=[5]", lambda: gl.efficiency(EPI, 1, [5], 2, eta=0.98), gl.DataFormatError, "input: expected"),
    ("terminal_constraint ground=[0]", lambda: gl.terminal_constraint(GKC8, (1, 2, 3), ground=[0]),
     gl.DataFormatError, "ground: expected"),
    ("identify grounds=99", lambda: gl.identify(GKC8, 3, grounds=99), gl.UnknownLinkError, "ground 99"),
    ("choose_inputs candidates=5", lambda: gl.choose_inputs(PLAN, ground=3, candidates=5), gl.UnknownLinkError,
     "candidate 5"),
    ("joined=[(1, 2, 3)]", lambda: gl.speeds(SIMPSON, ground=0, inputs={1: 1}, joined=[(1, 2, 3)]),
     gl.DataFormatError, "pair of links"),
    ("joined='12'", lambda: gl.dof(SIMPSON, 0, joined="12"), gl.DataFormatError, "pairs of links"),
    ("mech=None", lambda: gl.speeds(None, ground=3, inputs={1: 1}), gl.DataFormatError, "mech: expected a Mechanism"),
    ("mech=a dict", lambda: gl.dof(PLAN.to_dict()), gl.DataFormatError, "Mechanism.from_dict"),
    ("mech=3", lambda: gl.kinematic_units(3), gl.DataFormatError, "got 3"),
    ("mech=an unknown name", lambda: gl.propagate("planetary", 4, [1], ground=3), gl.DataFormatError,
     "neither a catalogue name"),
    ("adjacency_matrix(name)", lambda: gl.adjacency_matrix("simple_planetary"), gl.DataFormatError,
     "gl.catalog.load('simple_planetary')"),
    ("gl.load(None)", lambda: gl.load(None), gl.FileFormatError, "expected a file name"),
    ("gl.load(3)", lambda: gl.load(3), gl.FileFormatError, "expected a file name"),
    ("gl.load(a Mechanism)", lambda: gl.load(PLAN), gl.FileFormatError, "already a Mechanism"),
    ("gl.load('')", lambda: gl.load(""), gl.FileFormatError, "file name is empty"),
    ("gl.loads(None)", lambda: gl.loads(None), gl.FileFormatError, "expected the text"),
    ("gl.save(mech, None)", lambda: gl.save(PLAN, None), gl.FileFormatError, "expected a file name"),
    ("gl.save(name, path)", lambda: gl.save("simple_planetary", "/nonexistent/x.yaml"), gl.DataFormatError,
     "expected a Mechanism"),
    ("gl.save into a missing folder", lambda: gl.save(PLAN, "/nonexistent/x.yaml"), gl.FileFormatError,
     "cannot be written"),
    ("random_mechanism(1)", lambda: gl.random_mechanism(1), gl.DataFormatError, "n_links"),
    ("random_mechanism(2.5)", lambda: gl.random_mechanism(2.5), gl.DataFormatError, "whole number"),
    ("random_mechanism('5')", lambda: gl.random_mechanism("5"), gl.DataFormatError, "whole number"),
    ("random_mechanism(10**9)", lambda: gl.random_mechanism(10**9), gl.DataFormatError, "from 2 to 200000"),
    ("random_mechanism(dof=0)", lambda: gl.random_mechanism(5, dof=0), gl.DataFormatError, "dof"),
    ("random_mechanism(rng='x')", lambda: gl.random_mechanism(5, rng="x"), gl.DataFormatError, "rng"),
    ("random_mechanism(bevel=2)", lambda: gl.random_mechanism(5, bevel=2), gl.DataFormatError, "probability"),
    ("random_mechanism(max_teeth=3)", lambda: gl.random_mechanism(5, max_teeth=3), gl.DataFormatError, "max_teeth"),
    ("serial_train(0)", lambda: gl.serial_train(0), gl.DataFormatError, "n_pairs"),
    ("serial_train(10**8)", lambda: gl.serial_train(10**8), gl.DataFormatError, "n_pairs"),
    ("serial_train(teeth=5)", lambda: gl.serial_train(3, teeth=5), gl.DataFormatError, "two tooth numbers"),
    ("derive_rule(9)", lambda: gl.derive_rule(9), gl.InputError, "numbered 1 to 5"),
    ("derive_rule('2')", lambda: gl.derive_rule("2"), gl.InputError, "numbered 1 to 5"),
    ("derive_rule(True)", lambda: gl.derive_rule(True), gl.InputError, "numbered 1 to 5"),
    ("null_space with NaN", lambda: gl.null_space(np.array([[1.0, np.nan]])), gl.DataFormatError, "entry (0, 1)"),
    ("null_space with inf", lambda: gl.null_space([[1.0, np.inf]]), gl.DataFormatError, "finite"),
    ("null_space of ragged rows", lambda: gl.null_space([[1, 2], [3]]), gl.DataFormatError, "rows of equal length"),
    ("null_space of a 3-D array", lambda: gl.null_space(np.zeros((2, 2, 2))), gl.DataFormatError, "2 dimensions"),
    ("null_space of text", lambda: gl.null_space("abc"), gl.DataFormatError, "matrix of numbers"),
    ("null_space rtol=-1", lambda: gl.null_space(np.eye(2), rtol=-1), gl.DataFormatError, "rtol"),
    ("reduced_basis with NaN", lambda: gl.reduced_basis(np.array([[np.nan, 1.0]])), gl.DataFormatError, "K:"),
    ("same_subspace with NaN", lambda: gl.same_subspace(np.full((2, 1), np.nan), np.eye(2)), gl.DataFormatError,
     "K1:"),
    ("number('x')", lambda: gl.number("x"), gl.DataFormatError, "expected a number"),
    ("number(10**5000)", lambda: gl.number(10**5000), gl.DataFormatError, "5001 digits"),
    ("number(digits=-1)", lambda: gl.number(1, digits=-1), gl.DataFormatError, "digits"),
    ("direction('x')", lambda: gl.direction("x"), gl.DataFormatError, "direction"),
    ("direction(nan)", lambda: gl.direction(math.nan), gl.DataFormatError, "finite"),
    ("omega(None)", lambda: gl.omega(None), gl.DataFormatError, "omega: link"),
    ("omega([1])", lambda: gl.omega([1]), gl.DataFormatError, "omega: link"),
    ("speeds input 1e400", lambda: gl.speeds(PLAN, ground=3, inputs={1: "1e400"}), gl.DataFormatError,
     "beyond the range"),
    ("speeds input exp(1000)", lambda: gl.speeds(PLAN, ground=3, inputs={1: "exp(1000)"}), gl.DataFormatError,
     "beyond the range"),
    ("speeds input 9^9^9^9", lambda: gl.speeds(PLAN, ground=3, inputs={1: "9^9^9^9"}), gl.DataFormatError,
     "far too large"),
    ("speeds input 10**5000", lambda: gl.speeds(PLAN, ground=3, inputs={1: 10**5000}), gl.DataFormatError,
     "5001 digits"),
    ("speeds input of 5000 digits", lambda: gl.speeds(PLAN, ground=3, inputs={1: "1" * 5000}), gl.DataFormatError,
     "too long"),
    ("speeds that overflow a float", lambda: gl.speeds(DIFF, ground=1, inputs={3: 1e308, 4: 1e308}),
     gl.InputError, "exceed a float's range"),
    ("speeds input True", lambda: gl.speeds(PLAN, ground=3, inputs={1: True}), gl.DataFormatError, "got True"),
    ("frequencies input 1e400", lambda: gl.frequency_table(DIFF, ground=1, inputs={3: "1e400", 4: 1}),
     gl.DataFormatError, "beyond the range"),
    ("with_gear_pair teeth of 5000 digits", lambda: PLAN.with_gear_pair((1, 2), teeth=(10**5000, 2)),
     gl.ToothNumberError, "5001 digits"),
    ("eta for a pair that does not exist", lambda: gl.efficiency(EPI, 1, 5, 2, eta={(1, 5): 0.9}), gl.InputError,
     "no gear pair between 1 and 5"),
    ("eta keyed by junk", lambda: gl.efficiency(EPI, 1, 5, 2, eta={3.5: 0.9}), gl.DataFormatError,
     "a key must be a gear pair"),
    ("eta for a pair that does not exist, torque balance",
     lambda: gl.torque_balance_efficiency(EPI, 1, 5, 2, eta={(1, 5): 0.9}), gl.InputError, "no gear pair"),
    ("NaN torque", lambda: gl.efficiency(EPI, 1, 5, 2, eta=0.98, torque=math.nan), gl.DataFormatError,
     "torque: expected a finite number"),
    ("infinite speed", lambda: gl.efficiency(EPI, 1, 5, 2, eta=0.98, speed=math.inf), gl.DataFormatError,
     "speed: expected a finite number"),
    ("torque as text", lambda: gl.efficiency(EPI, 1, 5, 2, eta=0.98, torque="x"), gl.InputError, "torque"),
    ("torque balance eta=2", lambda: gl.torque_balance_efficiency(EPI, 1, 5, 2, eta=2), gl.InputError, "(0, 1]"),
    ("torque balance eta=NaN", lambda: gl.torque_balance_efficiency(EPI, 1, 5, 2, eta=math.nan), gl.InputError,
     "(0, 1]"),
    ("match_rule(None)", lambda: gl.match_rule(None, (1, 2), (3, 4)), gl.InputError, "kinematic unit"),
    ("planetary_sets speeds='x'", lambda: gl.planetary_sets(PLAN, speeds="x"), gl.DataFormatError, "speeds:"),
    ("shift_table unknown option", lambda: gl.shift_table(gl.catalog.load("zf_8hp70"), foo=1), gl.DataFormatError,
     "unknown option 'foo'"),
    ("plot_speeds(a Mechanism)", lambda: gl.plot_speeds(PLAN), gl.DataFormatError, "solve first"),
    ("draw_graph(ax='x')", lambda: gl.draw_graph(PLAN, ax="x"), gl.DataFormatError, "ax: expected matplotlib Axes"),
    ("dgm_explorer(None)", lambda: gl.dgm_explorer(None), gl.DataFormatError, "chains"),
    ("unit_explorer(['nope'])", lambda: gl.unit_explorer(["nope"]), gl.UnknownLinkError, "no catalogue entry"),
    ("check.get('nope')", lambda: gl.check.get("nope"), gl.UnknownLinkError, "no exercise check"),
    ("catalog.load('../...')", lambda: gl.catalog.load("../catalog/data/simpson"), gl.UnknownLinkError,
     "no catalogue entry"),
    ("catalog.path('/etc/passwd')", lambda: gl.catalog.path("/etc/passwd"), gl.UnknownLinkError,
     "no catalogue entry"),
    ("catalog.load(None)", lambda: gl.catalog.load(None), gl.UnknownLinkError, "no catalogue entry None"),
]


@pytest.mark.parametrize("name, call, error, message", API_25, ids=[a[0] for a in API_25])
def test_library_api_issue_25(name, call, error, message):
    test_library_api(name, call, error, message)


def test_an_unknown_check_is_still_an_attribute_error():
    assert not hasattr(gl.check, "no_such_check")  # hasattr needs AttributeError


# ----------------------------------------------------------------------------- where the intent is plain
ACCEPTED_25 = [
    ("held=4 is held=[4]", lambda: gl.speeds(SIMPSON, ground=0, inputs={1: 1}, held=4).values,
     lambda: gl.speeds(SIMPSON, ground=0, inputs={1: 1}, held=[4]).values),
    ("held=4 in propagation", lambda: gl.unit_ratio(SIMPSON, output=2, input=1, ground=0, held=4),
     lambda: gl.ratio(SIMPSON, output=2, input=1, ground=0, held=[4])),
    ("joined=(1, 2) is one clutch", lambda: gl.speeds(SIMPSON, ground=0, inputs={1: 1}, joined=(1, 2)).values,
     lambda: gl.speeds(SIMPSON, ground=0, inputs={1: 1}, joined=[(1, 2)]).values),
    ("a catalogue name for the mechanism", lambda: gl.speeds("simple_planetary", ground=3, inputs={1: 1}).values,
     lambda: gl.speeds(PLAN, ground=3, inputs={1: 1}).values),
    ("a mechanism file's path", lambda: int(gl.dof(str(gl.catalog.path("simpson")), 0)),
     lambda: int(gl.dof(SIMPSON, 0))),
    ("ground 3.0 is link 3", lambda: gl.speeds(PLAN, ground=3.0, inputs={1: 1}).values,
     lambda: gl.speeds(PLAN, ground=3, inputs={1: 1}).values),
    ("propagate with one input link", lambda: gl.propagate(PLAN, 4, 1, ground=3).ratio,
     lambda: gl.propagate(PLAN, 4, [1], ground=3).ratio),
    ("plan with inputs=None takes the file's inputs", lambda: gl.plan(PLAN, ground=3, inputs=None, output=4).inputs,
     lambda: gl.plan(PLAN, ground=3, inputs=list(PLAN.inputs), output=4).inputs),
    ("unit_explorer with one name", lambda: gl.unit_explorer("simpson").names, lambda: ["simpson"]),
]


@pytest.mark.parametrize("name, got, want", ACCEPTED_25, ids=[a[0] for a in ACCEPTED_25])
def test_what_is_plain_is_accepted(name, got, want):
    assert got() == want()


# ----------------------------------------------------------------------------- command line
CLI_25 = [
    (["speeds", "simple_planetary", "--ground", "3", "--input", "1=1", "--input", "1=2"], "given twice"),
    (["speeds", "simple_planetary", "--ground", "3", "--input", "1=1e400", "--json"], "beyond the range"),
    (["speeds", "simple_planetary", "--ground", "3", "--input", "1=9^9^9^9", "--json"], "far too large"),
    (["speeds", "simple_planetary", "--ground", "3", "--input", "1=exp(1000)"], "beyond the range"),
    (["speeds", "simple_planetary", "--ground", "3", "--input", "1=1", "--held", "14"], "held link '14'"),
    (["speeds", "../catalog/data/simple_planetary", "--ground", "3", "--input", "1=1"], "no such file"),
    (["catalog", "../../etc/passwd"], "no catalogue entry"),
    (["frequencies", "car_differential", "--ground", "1", "--input", "3=1e400", "--input", "4=1", "--json"],
     "beyond the range"),
    (["efficiency", "laus_epicyclic", "--ground", "1", "--input", "5", "--output", "2", "--eta-pair", "1,5=0.9"],
     "no gear pair between 1 and 5"),
    (["efficiency", "ravigneaux", "--ground", "0", "--speed", "1=1", "--speed", "1=2", "--torque", "3=1"],
     "given twice"),
    (["efficiency", "ravigneaux", "--ground", "0", "--speed", "1=1", "--speed", "2=1", "--torque", "3=nan",
      "--json"], "finite"),
    (["dof", "BOMB", "--json"], "alias bomb"),
    (["dof", "DEEP", "--json"], "nested more than"),
    (["dof", "DUPLICATE"], "given twice"),
    (["dof", "FIFO", "--json"], "named pipe"),
    (["dof", "LOOP"], "loops back"),
    (["dof", "/dev/zero", "--json"], "is a device"),
    (["dof", "DIR"], "is a directory"),
    (["frequencies", "car_differential", "--ground", "1", "--input", "3=1", "--input", "4=1", "--bearings", "LOOP",
      "--json"], "loops back"),
    (["frequencies", "car_differential", "--ground", "1", "--input", "3=1", "--input", "4=1", "--bearings", "FIFO"],
     "named pipe"),
    (["frequencies", "car_differential", "--ground", "1", "--input", "3=1", "--input", "4=1", "--bearings", "BOMB"],
     "alias bomb"),
    (["frequencies", "car_differential", "--ground", "1", "--input", "3=1", "--input", "4=1", "--bearings",
      "/dev/zero"], "is a device"),
]


def _special_files(d):
    (d / "BOMB").write_text(_alias_bomb())
    (d / "DEEP").write_text("links: " + "[" * 100_000 + "]" * 100_000 + "\n")
    (d / "DUPLICATE").write_text(GOOD + "\nname: again\n")
    os.mkfifo(d / "FIFO")
    (d / "LOOP").symlink_to(d / "LOOP")
    (d / "DIR").mkdir()


@pytest.mark.parametrize("argv, message", CLI_25, ids=[" ".join(c[0][:2]) + f" 25-{i}" for i, c in enumerate(CLI_25)])
def test_command_line_issue_25(tmp_path, argv, message):
    _special_files(tmp_path)
    names = {"BOMB", "DEEP", "DUPLICATE", "FIFO", "LOOP", "DIR"}
    argv = [str(tmp_path / a) if a in names else a for a in argv]
    before = sorted(os.listdir(tmp_path))
    result = run(*argv)
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0] and "Traceback" not in result.stderr, result.stderr
    if "--json" in argv:  # the error as JSON on stdout: valid, strict JSON
        assert message in json.loads(result.stdout, parse_constant=_no_constant)["error"]
    assert sorted(os.listdir(tmp_path)) == before


def _no_constant(name):
    raise AssertionError(f"{name} is not JSON")


def test_json_never_prints_infinity(capsys):
    # speeds beyond a float's range (the pinion turns 5 x 1e308): an error, as strict JSON
    for method in ("exact", "numeric", "nullspace"):
        out = run("speeds", "car_differential", "--ground", "1", "--input", "3=1e308", "--input", "4=1e308",
                  "--method", method, "--json")
        assert out.returncode == 2 and out.stderr.count("\n") == 1, out.stderr  # no numpy warning lines either
        assert "beyond" in json.loads(out.stdout, parse_constant=_no_constant)["error"] or \
            "exceed a float's range" in out.stdout
    # and whatever a result holds, --json writes a number that is not finite as null
    from gearlib.cli import print_json

    print_json({"a": math.inf, "b": [math.nan, 1.0, -math.inf], "c": {"d": 2}})
    assert json.loads(capsys.readouterr().out, parse_constant=_no_constant) == {"a": None, "b": [None, 1.0, None],
                                                                                "c": {"d": 2}}


@pytest.mark.parametrize("encoding", ["ascii", "latin-1"])
def test_a_terminal_without_unicode_gets_ascii(encoding):
    env = dict(os.environ, PYTHONIOENCODING=encoding)
    out = subprocess.run([sys.executable, "-m", "gearlib", "speeds", "penaud_example_1", "--ground", "1", "--input",
                          "2=1"], capture_output=True, env=env)
    text = out.stdout.decode(encoding)
    assert out.returncode == 0 and "Traceback" not in out.stderr.decode(encoding, "replace")
    planet = next(line for line in text.splitlines() if "planet " in line and "/_" in line)
    assert "1.36216/_" in planet  # |omega_3| = 1.36216 at its angle (chapter 4), the angle sign in ASCII


def test_piping_into_head_ends_quietly():
    cmd = (f"{sys.executable} -m gearlib frequencies car_differential --ground 1 --input 3=1 --input 4=1 "
           "--harmonics 50 --sidebands 5 | head -1")
    out = subprocess.run(["bash", "-o", "pipefail", "-c", cmd], capture_output=True, text=True)
    assert out.stdout.count("\n") == 1 and out.stderr == "" and out.returncode == 0


# ----------------------------------------------------------------------------- exercise checks
JUNK_25 = ["9^9^9^9", "9**9**9**9", "1e400", "exp(1000)", "1" * 3000, 10**5000,
           sympy.Pow(9, sympy.Pow(9, sympy.Pow(9, 9, evaluate=False), evaluate=False), evaluate=False),
           [[0.5] * 2000 for _ in range(2000)], _alias_bomb(), "(" * 300 + "1" + ")" * 300]


@pytest.mark.parametrize("answer", JUNK_25, ids=[f"25-{i}" for i in range(len(JUNK_25))])
def test_checks_take_any_junk_issue_25(answer):
    test_checks_take_any_junk(answer)


def test_a_check_given_a_2000_by_2000_array():
    big = np.random.default_rng(1).random((2000, 2000))
    for name in gl.check.names():
        result = gl.check.get(name)(big)
        assert not result.passed and "\n" not in result.message


def test_catalogue_size_issue_25():
    before = len(FILES) + len(API) + len(CLI) + len(JUNK_ANSWERS)
    new = (len(FILES_25) + len(KINDS_25) + len(API_25) + len(ACCEPTED_25) + len(CLI_25) + len(JUNK_25)
           + 5)  # the JSON, two encodings, the pipe and the 2000 x 2000 array
    assert before == 92 and new >= 60, (before, new)
