"""The instructor's version of an exercise notebook, as nbgrader's ``source/`` wants it.

For each exercise with a check, the reader's answer cells become nbgrader *solution* cells
holding the worked solution between ``### BEGIN SOLUTION`` and ``### END SOLUTION`` (taken
from the solution page, where the check's calls carry the answer: ``gl.check.x(value)``
becomes ``answer = value``), and an autograder *test* cell follows, worth the exercise's
points (its stars): ``gl.check.grade("x", answer, variant=STUDENT)``, the same check that
gives the reader's hint. ``nbgrader generate_assignment`` then removes the solutions.

Every check call of a course notebook passes ``variant=STUDENT``, set in one cell near the
top: ``STUDENT = gl.check.student(None)`` here (the book's numbers), the student's id in each
student's copy (:mod:`students`).
"""

from __future__ import annotations

import re

from .exercises import Call, CourseError, Exercise, Page, check_calls, source

STUDENT_CELL = "course-student"
INTRO_CELL = "course-intro"
STUDENT_CODE = ("# Your student id: your exercises' numbers are drawn from it, and the grader checks your\n"
                "# answers against them (keep it as it is)\n"
                "STUDENT = gl.check.student({student})")

INTRO = """**Course notebook: exercises of chapter {chapter}.** Answer each exercise in the cell
below it, where the check gives a hint when an answer is not right yet. The cell after it,
*Autograder test*, is the one the grader runs to score the exercise: as many points as the
exercise has stars ({points} points in all, about {minutes} minutes). Run the notebook from
top to bottom (*Run > Run All Cells*) before you hand it in; the check of a *predict* exercise
asks for your prediction before your answer."""


def _cell(cell_type: str, text: str, cell_id: str, metadata: dict | None = None) -> dict:
    cell = {"cell_type": cell_type, "id": cell_id, "metadata": metadata or {}, "source": text}
    if cell_type == "code":
        cell.update(execution_count=None, outputs=[])
    return cell


def _plain(cell: dict) -> dict:
    out = {k: v for k, v in cell.items() if k != "attachments"}
    out["source"] = source(cell)
    if out["cell_type"] == "code":
        out.update(execution_count=None, outputs=[])
    return out


def _nbgrader(**kw) -> dict:
    return {"nbgrader": {"schema_version": 3, **kw}}


def heading(exercise: Exercise, points: int, body: str) -> str:
    unit = "point" if points == 1 else "points"
    return (f"### Exercise {exercise.number}: {exercise.title} · {'★' * exercise.stars} · "
            f"{exercise.minutes} min · {points} {unit}\n\n{body}")


def with_variant(code: str, call: Call) -> str:
    """*code* with ``variant=STUDENT`` added to *call*."""
    if call.has_variant:
        return code
    lines = code.split("\n")
    line, col = call.insert_at
    lines[line] = lines[line][:col] + ", variant=STUDENT" + lines[line][col:]
    return "\n".join(lines)


def _regions(exercise: Exercise, answers: list[Call], setup: str) -> list[str]:
    """The worked solution cut into one region per answer cell: up to the solution's own call
    of the same kind, which becomes an assignment to the answer cell's variable."""
    code = exercise.solution
    if not code.strip():
        raise CourseError(f"exercise {exercise.number} ({exercise.check}): no worked solution on its solution page "
                          f"(a :::{{solution}} {exercise.label} cell followed by code)")
    lines = code.split("\n")
    solved = [c for c in check_calls(code) if c.name == exercise.check]
    regions, start = [], 0
    for k, answer in enumerate(answers):
        if not re.fullmatch(r"[A-Za-z_]\w*(\[.*\])?", answer.argument):
            raise CourseError(f"exercise {exercise.number}: the check is called with {answer.argument!r}; call it "
                              "with the variable the reader assigns (answer = None ... gl.check.x(answer))")
        kind = [c for c in solved if c.predict == answer.predict and c.statement[0] >= start]
        if not kind:
            what = f"gl.check.{exercise.check}{'.predict' if answer.predict else ''}(...)"
            raise CourseError(f"exercise {exercise.number}: its solution does not call {what} with the answer")
        call = kind[-1] if not answer.predict else kind[0]
        first, last = call.statement
        end = len(lines) - 1 if k == len(answers) - 1 else last
        given = [] if answer.argument == call.argument else [f"{answer.argument} = {call.argument}"]
        body = lines[start:first] + given + lines[last + 1:end + 1]
        regions.append("\n".join(body).strip("\n"))
        start = end + 1
    if setup.strip():
        regions[0] = setup.strip("\n") + "\n\n" + regions[0]
    return regions


def source_notebook(page: Page, checks: dict, notes: list | None = None) -> dict:
    """The nbgrader source notebook of *page*; *checks*: name -> gearlib Check. An exercise
    whose worked solution cannot be read raises :class:`CourseError`, or, given a *notes*
    list, is noted there and left without a solution (its reference then earns nothing)."""
    graded = [e for e in page.exercises if e.check in checks]
    intro = INTRO.format(chapter=int(page.chapter), points=sum(checks[e.check].points for e in graded),
                         minutes=sum(e.minutes for e in page.exercises))
    cells = [_cell("markdown", intro, INTRO_CELL)]
    student = _cell("code", STUDENT_CODE.format(student="None"), STUDENT_CELL, {"gearlib": {"student": True}})
    placed = False
    for cell in page.preamble:
        out = _plain(cell)
        if out["cell_type"] == "markdown":
            # the course's HTML book has no solution pages, and the course notebook says how to answer
            paragraphs = [p for p in out["source"].split("\n\n") if not re.search(r"(?i)worked solutions", p)]
            out["source"] = "\n\n".join(paragraphs)
        cells.append(out)
        if not placed and out["cell_type"] == "code" and "import gearlib as gl" in out["source"]:
            cells.append(student)
            placed = True
    if not placed:
        student["source"] = "import gearlib as gl\n\n" + student["source"]
        cells.insert(1, student)
    setup = page.setup
    for exercise in page.exercises:
        check = checks.get(exercise.check)
        points = check.points if check else exercise.stars
        tag = exercise.label
        meta = {"gearlib": {"exercise": exercise.number, "check": exercise.check}}
        cells.append(_cell("markdown", heading(exercise, points, exercise.body), f"{tag}-statement", meta))
        answer_cells = [i for i, c in enumerate(exercise.cells) if c["cell_type"] == "code" and check is not None
                        and any(call.name == exercise.check for call in check_calls(source(c)))]
        calls = [[c for c in check_calls(source(exercise.cells[i])) if c.name == exercise.check][0]
                 for i in answer_cells]
        regions = []
        if answer_cells:
            try:
                regions = _regions(exercise, calls, setup)
                setup = ""
            except CourseError as err:
                if notes is None:
                    raise
                notes.append(f"{page.path.name}: {err}; source/ has no worked solution for it")
                regions = [""] * len(calls)
        for i, cell in enumerate(exercise.cells):
            if i not in answer_cells:
                cells.append(_plain(cell))
                continue
            k = answer_cells.index(i)
            call = calls[k]
            code = with_variant(source(cell), call)
            lines = code.split("\n")
            first = call.statement[0]
            code = "\n".join([*lines[:first], "### BEGIN SOLUTION", regions[k], "### END SOLUTION", *lines[first:]])
            role = "guess" if call.predict else "answer"
            cells.append(_cell("code", code, f"{tag}-{role}",
                               {**meta, **_nbgrader(grade=False, solution=True, locked=False,
                                                    grade_id=f"{tag}-{role}")}))
            if i == answer_cells[-1]:
                answer = [c for c in calls if not c.predict]
                argument = answer[-1].argument if answer else call.argument
                unit = "point" if points == 1 else "points"
                test = (f"# Autograder test of exercise {exercise.number} ({points} {unit}): the check above, "
                        f"with your numbers\ngl.check.grade({exercise.check!r}, {argument}, variant=STUDENT)")
                cells.append(_cell("code", test, f"{tag}-test",
                                   {**meta, **_nbgrader(grade=True, solution=False, locked=True, points=points,
                                                        grade_id=tag)}))
    nb = page.notebook
    return {"cells": cells, "metadata": {"kernelspec": nb["metadata"].get("kernelspec", {}),
                                         "language_info": {"name": "python"}},
            "nbformat": 4, "nbformat_minor": 5}
