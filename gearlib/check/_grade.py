"""Checks in a course's graded notebooks: whose numbers a notebook uses, and the points an
autograder's test cell gives.

A course notebook (``make course``) starts with ``STUDENT = gl.check.student("s1234")``
and checks each answer against that student's numbers. Its autograder test cells (nbgrader)
call :func:`~gearlib.check.grade`, the same check that gives the reader's hint. While the
course's grader runs a submission, the variable ``GEARLIB_VARIANT`` names the variant of the
student who submitted it (the course's ``nbgrader_config.py`` sets it from the submission's
student id); then :func:`student` and :func:`~gearlib.check.grade` use that variant, whatever
id the notebook was given, so that a student who types another student's id is still graded
against their own numbers.
"""

from __future__ import annotations

import os
import warnings

from ._core import variant_key
from ._read import Unreadable

__all__ = ["student", "score", "VARIANT_VARIABLE"]

VARIANT_VARIABLE = "GEARLIB_VARIANT"
"""The environment variable through which a course's autograder names the variant of the
student being graded (empty for the book's numbers)."""


def student(student_id=None) -> str | None:
    """The variant a course notebook checks against: *student_id* (a student's id: their own
    numbers; ``None``: the book's), or, while the course's autograder runs the notebook, the
    variant of the student who submitted it.

    >>> import gearlib as gl
    >>> gl.check.student("s1234")
    's1234'
    >>> gl.check.student() is None
    True
    """
    graded = os.environ.get(VARIANT_VARIABLE)
    if graded is not None:
        return graded.strip() or None
    return variant_key(student_id)


def score(check, answer, variant=None) -> float:
    """:func:`~gearlib.check.grade` for a :class:`~gearlib.check.Check` object."""
    try:
        variant = student(variant)
    except Unreadable as err:
        print(f"✘ {err}")
        return 0.0
    # a grader counts a test cell that writes to stderr as failed: no warning may reach it
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = check(answer, variant=variant)
    print(result)
    return float(min(max(result.score, 0.0), check.points))
