"""nbgrader's configuration for a course on the book (``make course`` copies it into the course
directory, ``course/_build/nbgrader/``, where every ``nbgrader`` command is run).

What differs from nbgrader's defaults:

* The autograder runs each submission with the variable ``GEARLIB_VARIANT`` set to the
  variant of the student who submitted it (``variants.json`` beside this file, written from
  the class list; a student missing from it has their id as variant). ``gl.check.grade`` and
  ``gl.check.student`` read it, so each student is graded against their own numbers whatever
  id their notebook holds.
* A solution region is replaced by nothing: the reader's answer cell keeps its
  ``answer = None`` line (``ClearSolutions.code_stub``).
* A cell may run for five minutes (some exercises count chains of an atlas), not 30 s.
"""

import json
import os
import pathlib

from nbgrader.converters import Autograde
from nbgrader.preprocessors import Execute

from gearlib.check import VARIANT_VARIABLE  # "GEARLIB_VARIANT"

c = get_config()  # noqa: F821 (nbgrader's configuration loader provides it)

c.CourseDirectory.course_id = "gearlib"
c.ClearSolutions.code_stub = {"python": ""}
c.Execute.timeout = 300

VARIANTS_FILE = pathlib.Path(__file__).with_name("variants.json")


class ExecuteAsStudent(Execute):
    """nbgrader's Execute, with the submitting student's variant in the kernel's environment."""

    def preprocess(self, nb, resources=None, km=None):
        student = resources["nbgrader"]["student"]
        variants = json.loads(VARIANTS_FILE.read_text(encoding="utf-8")) if VARIANTS_FILE.is_file() else {}
        variant = variants.get(student, student)
        os.environ[VARIANT_VARIABLE] = variant or ""  # empty: the book's numbers
        try:
            return super().preprocess(nb, resources, km=km)
        finally:
            os.environ.pop(VARIANT_VARIABLE, None)


c.Autograde.autograde_preprocessors = [
    ExecuteAsStudent if p is Execute else p for p in Autograde.class_traits()["autograde_preprocessors"].default()
]
