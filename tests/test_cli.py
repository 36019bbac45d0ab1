"""The command line: numbers, JSON, and one-line errors with exit status 2."""

import json

import pytest

from cli_tools import run, run_subprocess


def test_speeds_json_cornering_car():
    # a real `python -m gearlib` in a new interpreter, as a user runs it (the others run in process)
    out = run_subprocess("speeds", "car_differential", "--ground", "1", "--input", "3=26", "--input", "4=30", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert data["dof"] == 2
    assert data["speeds"]["2"] == [-140.0, 0.0] and data["speeds"]["7"] == [28.0, 0.0]
    re, im = data["speeds"]["5"]
    assert abs((re**2 + im**2) ** 0.5 - 28.14) < 0.005  # Penaud eq. (16)


def test_speeds_from_a_file(tmp_path):
    path = tmp_path / "pair.yaml"
    path.write_text("links: [0, 1, 2]\nturning_pairs: [[0, 1, a], [0, 2, b]]\n"
                    "gear_pairs: [{gears: [1, 2], teeth: [20, 60]}]\n")
    out = run("speeds", str(path), "--ground", "0", "--input", "1=3", "--json")
    assert json.loads(out.stdout)["speeds"]["2"] == [-1.0, 0.0]


def test_ratio_symbolic_json_first_gear():
    out = run("ratio", "liu_chen_transmission", "--ground", "5", "--input", "2", "--output", "8", "--symbolic", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert set(data) == {"ratio", "expression"}
    # LC eq. (23) corrected (LC-E6): E_{2,8} = e_26 e_61 e_17 e_78 = e_17 e_78 / (e_62 e_16)
    import sympy

    e = sympy.Symbol
    expected = e("e_1_7") * e("e_7_8") / (e("e_6_2") * e("e_1_6"))
    assert sympy.simplify(sympy.sympify(data["expression"]) - expected) == 0


@pytest.mark.parametrize("args, text", [
    (("speeds", "car_differential", "--ground", "1", "--input", "3=26"), "needs 2 inputs; got 1"),
    (("speeds", "nope.yaml", "--ground", "1"), "no such file"),
    (("speeds", "car_differential", "--ground", "9", "--input", "3=1"), "ground '9' is not a link"),
    (("speeds", "car_differential", "--ground", "1", "--input", "3"), "expected LINK=SPEED"),
    (("speeds", "car_differential", "--ground", "1", "--input", "3=abc(", "--input", "4=1"), "unknown function"),
    (("ratio", "chen_wrist", "--ground", "0", "--input", "4", "--output", "3"), "needs 3 inputs"),
])
def test_errors_are_one_line_and_exit_2(args, text):
    out = run(*args)
    assert out.returncode == 2
    assert "Traceback" not in out.stderr
    assert text in out.stderr
    assert len(out.stderr.strip().splitlines()) == 1


def test_empty_file_is_a_clean_error(tmp_path):
    (tmp_path / "e.yaml").write_text("")
    out = run_subprocess("dof", str(tmp_path / "e.yaml"))  # a real one: status 2, no traceback
    assert out.returncode == 2 and "empty" in out.stderr and "Traceback" not in out.stderr
