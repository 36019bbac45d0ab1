"""The book's exercises as the course kit reads them: every ``exercises/NN_*.ipynb`` and its
worked solutions ``book/solutions/NN_*.ipynb``, found by their names, never listed by hand.

An exercise is a Markdown cell ``:::{exercise} 1.3: Title · ★★ · 10 min`` (with ``:label:``),
followed by the cells up to the next exercise; the code cells among them that call its check,
``gl.check.<name>(answer)`` or ``gl.check.<name>.predict(guess)``, are where the reader
answers. Its solution is the code that follows ``:::{solution} <label>`` on the solution page,
where the same calls carry the worked answer.
"""

from __future__ import annotations

import ast
import json
import pathlib
import re
from dataclasses import dataclass, field

ROOT = pathlib.Path(__file__).resolve().parents[1]

HEADER = re.compile(r"^:::\{exercise\}\s+(?P<number>\d+\.\d+):\s*(?P<title>.*?)\s*·\s*(?P<stars>★+)\s*·\s*"
                    r"(?P<minutes>\d+)\s*min\s*$")
SOLUTION = re.compile(r"^:::\{solution\}\s+(?P<label>\S+)")


class CourseError(Exception):
    """An exercise or a solution the kit cannot turn into a graded one (says which, and why)."""


@dataclass
class Call:
    """A call of an exercise's check in a code cell: ``gl.check.<name>(<argument>)``."""

    name: str
    predict: bool
    argument: str            # the source of the first argument, e.g. "answer"
    statement: tuple         # (first line, last line) of the top-level statement holding it, 0-based
    insert_at: tuple         # (line, column) just before the call's closing bracket
    has_variant: bool


@dataclass
class Exercise:
    number: str
    title: str
    stars: int
    minutes: int
    label: str
    body: str                                      # the statement, Markdown
    cells: list = field(default_factory=list)      # the cells after the header, up to the next exercise
    check: str | None = None
    solution: str = ""                             # the solution's code (the check calls still in it)


@dataclass
class Page:
    """One exercise notebook: the cells before the first exercise, then the exercises."""

    path: pathlib.Path
    notebook: dict
    preamble: list
    exercises: list
    setup: str = ""      # the solution page's code before its first solution

    @property
    def name(self) -> str:
        return self.path.stem

    @property
    def chapter(self) -> str:
        return self.name.split("_")[0]


def source(cell) -> str:
    s = cell.get("source", "")
    return "".join(s) if isinstance(s, list) else s


def check_calls(code: str) -> list[Call]:
    """Every ``gl.check.<name>(...)`` and ``gl.check.<name>.predict(...)`` in *code*, in order."""
    try:
        tree = ast.parse(code)
    except SyntaxError:
        return []
    lines = code.splitlines()
    out = []
    for stmt in tree.body:
        for node in ast.walk(stmt):
            if not (isinstance(node, ast.Call) and node.args):
                continue
            chain = _attribute_chain(node.func)
            if len(chain) == 3 and chain[:2] == ["gl", "check"]:
                name, predict = chain[2], False
            elif len(chain) == 4 and chain[:2] == ["gl", "check"] and chain[3] == "predict":
                name, predict = chain[2], True
            else:
                continue
            argument = ast.get_source_segment(code, node.args[0])
            end_line, end_col = node.end_lineno - 1, node.end_col_offset - 1
            assert lines[end_line][end_col] == ")"
            out.append(Call(name, predict, argument, (stmt.lineno - 1, stmt.end_lineno - 1), (end_line, end_col),
                            any(k.arg == "variant" for k in node.keywords)))
    return out


def _attribute_chain(node) -> list[str]:
    parts = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if isinstance(node, ast.Name):
        parts.append(node.id)
        return parts[::-1]
    return []


def _header(text: str):
    first, _, rest = text.partition("\n")
    m = HEADER.match(first.strip())
    if not m:
        return None
    label, body = None, []
    lines = rest.splitlines()
    i = 0
    while i < len(lines) and lines[i].startswith(":") and not lines[i].startswith(":::"):
        if lines[i].startswith(":label:"):
            label = lines[i].split(":", 2)[2].strip()
        i += 1
    body = "\n".join(lines[i:]).strip()
    body = re.sub(r"\n?:::\s*$", "", body).strip()
    number = m["number"]
    return Exercise(number, m["title"], len(m["stars"]), int(m["minutes"]),
                    label or "ex-" + number.replace(".", "-"), body)


def read_page(path: pathlib.Path, solutions: pathlib.Path | None = None) -> Page:
    notebook = json.loads(path.read_text(encoding="utf-8"))
    preamble, exercises = [], []
    for cell in notebook["cells"]:
        exercise = _header(source(cell)) if cell["cell_type"] == "markdown" else None
        if exercise is not None:
            exercises.append(exercise)
        elif exercises:
            exercises[-1].cells.append(cell)
        else:
            preamble.append(cell)
    for exercise in exercises:
        names = {c.name for cell in exercise.cells if cell["cell_type"] == "code" for c in check_calls(source(cell))}
        if len(names) > 1:
            raise CourseError(f"{path.name}, exercise {exercise.number}: its cells call several checks "
                              f"({', '.join(sorted(names))}); an exercise has one")
        exercise.check = names.pop() if names else None
    page = Page(path, notebook, preamble, exercises)
    if solutions is not None and solutions.is_file():
        _read_solutions(page, solutions)
    return page


def _read_solutions(page: Page, path: pathlib.Path) -> None:
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    code: dict[str, list[str]] = {}
    setup, label = [], None
    for cell in cells:
        m = SOLUTION.match(source(cell)) if cell["cell_type"] == "markdown" else None
        if m:
            label = m["label"]
            code.setdefault(label, [])
        elif cell["cell_type"] == "code":
            (code[label] if label else setup).append(source(cell))
    page.setup = "\n\n".join(setup)
    for exercise in page.exercises:
        exercise.solution = "\n\n".join(code.get(exercise.label, []))


def pages(root: pathlib.Path = ROOT) -> list[Page]:
    """Every exercise notebook of the book, in chapter order, with its solutions."""
    out = []
    for path in sorted((root / "exercises").glob("[0-9]*_*.ipynb")):
        out.append(read_page(path, root / "book" / "solutions" / path.name))
    return out


def chapters(root: pathlib.Path = ROOT) -> list[pathlib.Path]:
    """Every chapter notebook, in order."""
    return sorted((root / "chapters").glob("[0-9]*_*.ipynb"))
