"""Helpers for the course kit's tests: notebooks as data, answers written into them as code,
nbgrader run by its own command line, and the text of files to search for answers."""

from __future__ import annotations

import html
import json
import os
import pathlib
import re
import subprocess
import sys
from fractions import Fraction

import sympy

from notebook_tools import ROOT

BIN = pathlib.Path(sys.executable).parent


def load(path: pathlib.Path) -> dict:
    return json.loads(path.read_text(encoding="utf-8"))


def save(path: pathlib.Path, nb: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(nb, indent=1, ensure_ascii=False), encoding="utf-8")


def text(cell) -> str:
    s = cell.get("source", "")
    return "".join(s) if isinstance(s, list) else s


def cell(nb: dict, cell_id: str) -> dict:
    hits = [c for c in nb["cells"] if c.get("id") == cell_id]
    assert len(hits) == 1, f"{len(hits)} cells with id {cell_id}"
    return hits[0]


def literal(value) -> str:
    """Python source that evaluates to *value* in an exercise notebook (which imports Fraction)."""
    if isinstance(value, (sympy.Rational, Fraction)) and not isinstance(value, sympy.Integer):
        value = Fraction(int(sympy.Rational(value).p), int(sympy.Rational(value).q))
        return f"Fraction({value.numerator}, {value.denominator})"
    if isinstance(value, sympy.Integer):
        return str(int(value))
    if isinstance(value, sympy.Float):
        return repr(float(value))
    if isinstance(value, dict):
        return "{" + ", ".join(f"{literal(k)}: {literal(v)}" for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(literal(v) for v in value) + "]"
    if isinstance(value, (str, int, float, bool)) or value is None:
        return repr(value)
    raise TypeError(f"no literal for {type(value).__name__}")


def answer_with(code: str, variable: str, value_source: str) -> str:
    """An answer cell of a released notebook with ``variable = value_source`` just before its check."""
    lines = code.split("\n")
    at = next(i for i, line in enumerate(lines) if line.startswith("gl.check."))
    return "\n".join([*lines[:at], f"{variable} = {value_source}", *lines[at:]])


def solved(code: str) -> str:
    """A source cell with its worked solution kept and nbgrader's markers removed."""
    return "\n".join(line for line in code.split("\n") if line.strip() not in ("### BEGIN SOLUTION",
                                                                             "### END SOLUTION"))


def nbgrader(course: pathlib.Path, *args: str, timeout: int = 900) -> str:
    """nbgrader's command line in the course directory; its output (fails the test on an error)."""
    env = {**os.environ, "PATH": f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}", "JUPYTER_PREFER_ENV_PATH": "1"}
    env.pop("MPLBACKEND", None)
    done = subprocess.run([str(BIN / "nbgrader"), *args], cwd=course, capture_output=True, text=True, env=env,
                          timeout=timeout)
    out = done.stdout + done.stderr
    assert done.returncode == 0, f"nbgrader {' '.join(args)} failed:\n{out[-4000:]}"
    return out


def grades(course: pathlib.Path) -> dict:
    """``{(student, assignment): {grade id: (score, max score)}}`` from the gradebook."""
    from nbgrader.api import Gradebook

    out = {}
    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        for assignment in gb.assignments:
            for submission in assignment.submissions:
                out[(submission.student_id, assignment.name)] = {
                    g.name: (g.score, g.max_score) for nb in submission.notebooks for g in nb.grades}
    return out


def html_text(path: pathlib.Path) -> str:
    page = path.read_text(encoding="utf-8", errors="replace")
    page = re.sub(r"<(script|style)\b.*?</\1>", " ", page, flags=re.S)
    return html.unescape(re.sub(r"<[^>]+>", " ", page))


def run_course_build(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "course.build", *args], cwd=ROOT, capture_output=True, text=True,
                          timeout=900)
