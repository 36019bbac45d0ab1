"""The ``linkage`` command: a linkage rated over a task, a crank cycle or a trajectory file."""

import json
import math

import pytest

from cli_tools import run, run_subprocess


def test_a_crank_cycle_gives_the_closed_form_efficiency():
    out = run("linkage", "laus_slider_crank", "--cycle", "A", "--action", "A=1", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert abs(data["efficiency"] - (1 - 0.1 / math.pi * math.log(2))) < 1e-9      # eq. (120), a1 = 1, a2 = 3
    assert data["loss_shares"] == {"D": 1.0}
    assert abs(data["energy_in"] - 2 * math.pi) < 1e-9


def test_the_lift_in_text_names_every_coupling():
    out = run("linkage", "laus_3upu", "--task", "lift_half", "--steps", "20")
    assert out.returncode == 0, out.stderr
    assert "energy out           2000" in out.stdout
    for coupling in "ABCDEFGHIJKL":
        assert f"\n  {coupling} " in out.stdout


def test_friction_can_be_changed_from_the_command_line():
    out = run("linkage", "laus_3upu", "--task", "lift_half", "--steps", "10", "--mu", "0", "--json")
    data = json.loads(out.stdout)
    assert abs(data["efficiency"] - 1) < 1e-9 and data["losses"] == {}


def test_a_trajectory_file(tmp_path):
    rows = ["t,M.x,M.y,M.z"] + [f"{k / 20},0.1,0.2,{0.5 + 0.4 * k / 20}" for k in range(21)]
    path = tmp_path / "lift.csv"
    path.write_text("\n".join(rows) + "\n")
    out = run("linkage", "laus_3upu", "--trajectory", str(path), "--action", "M=10000", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert abs(data["energy_out"] - 4000) < 1e-6
    assert 0.6 < data["efficiency"] < 0.7


@pytest.mark.parametrize("args, text", [
    (("linkage", "nope.yaml"), "no such file"),
    (("linkage", "laus_3upu", "--task", "nope"), "no task 'nope'"),
    (("linkage", "laus_slider_crank", "--cycle", "D", "--action", "A=1"), "a cycle turns a revolute joint"),
    (("linkage", "laus_slider_crank", "--cycle", "A"), "--action"),
    (("linkage", "laus_slider_crank", "--cycle", "A", "--action", "A"), "expected PORT=VALUE"),
    (("linkage", "laus_3upu", "--task", "lift", "--action", "Q=1"), "not a port"),
    (("linkage", "laus_3upu", "--steps", "0"), "--steps 0"),
    (("linkage", "laus_3upu", "--mu", "-1"), "--mu -1"),
    (("linkage", "laus_3upu", "--trajectory", "missing.csv"), "no such trajectory file"),
    (("linkage", "laus_slider_crank", "--cycle", "A", "--action", "A=9^9^9"), "powers"),
])
def test_errors_are_one_line_and_exit_2_also_with_json(args, text):
    for extra in ((), ("--json",)):
        out = run(*args, *extra)
        assert out.returncode == 2, out.stdout
        assert "Traceback" not in out.stderr and len(out.stderr.strip().splitlines()) == 1
        assert text in out.stderr
        if extra:
            assert text in json.loads(out.stdout)["error"]


def test_a_bad_trajectory_file(tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("t,M.x\n0,1\n1,x\n2,3\n")
    out = run("linkage", "laus_3upu", "--trajectory", str(path), "--action", "M=1", "--json")
    assert out.returncode == 2 and "error" in json.loads(out.stdout)
    path.write_text("t,M.x\n0,0.1\n0.5,0.1\n1,0.1\n")   # one coordinate for a point with three
    out = run("linkage", "laus_3upu", "--trajectory", str(path), "--action", "M=1")
    assert out.returncode == 2 and "coordinate" in out.stderr


def test_the_real_command_line():
    out = run_subprocess("linkage", "laus_slider_crank", "--json")
    assert out.returncode == 0, out.stderr
    assert abs(json.loads(out.stdout)["efficiency"] - 0.9779364) < 1e-7
