"""The class list, and each student's copy of a released notebook with their own numbers.

A class list is a CSV file with a header: ``id`` (the student's id, as nbgrader and the hub
know them) and optionally nbgrader's ``first_name``, ``last_name``, ``email``, and
``variant``: the seed of the student's numbers, their id when empty, ``book`` for the book's
numbers (a test account, or a course that gives everyone the same numbers).
"""

from __future__ import annotations

import copy
import csv
import pathlib
import re
from dataclasses import dataclass

from .assignments import INTRO_CELL, STUDENT_CODE
from .exercises import CourseError, source

ID = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._@+-]{0,99}$")


@dataclass(frozen=True)
class Student:
    id: str
    first_name: str = ""
    last_name: str = ""
    email: str = ""
    variant: str | None = None     # None: the book's numbers


def read_class(path: pathlib.Path) -> list[Student]:
    """The students of a class list (see the module's description)."""
    text = path.read_text(encoding="utf-8")
    rows = [line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")]
    reader = csv.DictReader(rows)
    if not reader.fieldnames or "id" not in [f.strip() for f in reader.fieldnames]:
        raise CourseError(f"{path}: a class list is a CSV file whose header has an 'id' column")
    students, seen = [], set()
    for n, row in enumerate(reader, start=2):
        row = {(k or "").strip(): (v or "").strip() for k, v in row.items()}
        sid = row.get("id", "")
        if not ID.match(sid):
            raise CourseError(f"{path}, row {n}: {sid!r} is not a student id (letters, digits and . _ @ + -, "
                              "at most 100 characters, no spaces or slashes)")
        if sid in seen:
            raise CourseError(f"{path}, row {n}: student {sid!r} is listed twice")
        seen.add(sid)
        variant = row.get("variant") or sid
        students.append(Student(sid, row.get("first_name", ""), row.get("last_name", ""), row.get("email", ""),
                                None if variant == "book" else variant))
    return students


def _escape(text: str) -> str:
    """Plain text shown as Markdown: no emphasis out of ``a*b`` or a link out of brackets."""
    return re.sub(r"([\\`*_\[\]<>])", r"\\\1", text)


def _choices(prose: str) -> str:
    """The lettered options of an exercise's statement (``- **A.** ...`` and the lines that
    continue them), which a student's statement, written from the check's question, keeps."""
    kept, inside = [], False
    for line in prose.splitlines():
        if re.match(r"^[-*] \*\*[A-Z]\.\*\*", line):
            inside = True
        elif not line.startswith("  ") or not line.strip():
            inside = False
        if inside:
            kept.append(line)
    return "\n".join(kept)


def student_copy(release: dict, student: Student, checks: dict) -> dict:
    """*release* (a released notebook) with *student*'s id, and the statement of every
    exercise whose numbers vary with the numbers drawn for them."""
    nb = copy.deepcopy(release)
    found = False
    for cell in nb["cells"]:
        meta = cell.get("metadata", {}).get("gearlib", {})
        if cell.get("id") == INTRO_CELL and student.variant is not None:
            cell["source"] = source(cell) + (
                f"\n\n**Your numbers.** The exercises whose statement begins with *Your numbers* were drawn for "
                f"you (student {_escape(student.id)}): use the numbers of that statement, not the book's numbers "
                "in the text around it.")
        elif meta.get("student"):
            cell["source"] = STUDENT_CODE.format(student=repr(student.variant))
            cell["metadata"].update(editable=False, deletable=False)
            found = True
        elif cell["cell_type"] == "markdown" and meta.get("check") in checks and student.variant is not None:
            check = checks[meta["check"]]
            if check.variants:
                heading, _, prose = source(cell).partition("\n\n")
                choices = _choices(prose)
                cell["source"] = (f"{heading}\n\n**Your numbers** (student {_escape(student.id)}). "
                                  f"{_escape(check.statement(student.variant))}" + (f"\n\n{choices}" if choices else ""))
    if not found:
        raise CourseError("a released notebook without its STUDENT cell: run make course again")
    return nb
