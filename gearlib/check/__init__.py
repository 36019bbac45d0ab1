"""Exercise checks: ``gl.check.<name>(answer)``, and the machinery to write new ones.

A check answers a right answer with a short confirmation and a wrong one with a hint that
diagnoses the usual mistakes of its kind of quantity; it never shows the answer (no
attribute, method, repr or message of a check carries it), never raises, and returns in
bounded time whatever it is given. Answers may be ints, floats, fractions, complex numbers,
numpy or sympy values, or text (``"2/7"``, ``"−1.3846"``, ``"120 Hz"``, ``"89.6 %"``); a
decimal is right when it is within half a unit of its last digit.

>>> import gearlib as gl
>>> gl.check.intro_gear_ratio(None)
✘ Not yet. No answer yet: replace `None` with your answer.
>>> gl.check.intro_gear_ratio("2 pi / e_1_2")
✘ Not yet. Your answer uses the name 'e_1_2'; give a number.
>>> gl.check.intro_gear_ratio.given()
{'N1': 21, 'N2': 56}

Each check is numbered and described (``exercise``, ``title``, ``stars``, ``minutes``,
``kind``), can draw other numbers for a student (``check(answer, variant="s1234")``,
``check.given(variant)``, ``check.statement(variant)``), and returns a
:class:`CheckResult` a grader can score; :func:`grade` is a course autograder's test
cell, and :func:`student` the variant a course notebook uses. Chapters register their checks
in their own module here (``gearlib/check/<subpackage>.py``) with :func:`register` and a spec
(:class:`Value`, :class:`Symbolic`, :class:`Choice`, ...); every module of this package whose
name does not start with ``_`` is imported on first use.
"""

from __future__ import annotations

import importlib
import pkgutil

from .._common.parse import shown
from ..errors import UnknownLinkError
from ._choice import Choice, Groups, LinkId, LinkSet, Parts
from ._core import KINDS, REGISTRY, Check, Prediction, register, register_custom
from ._design import Condition, Design, Matrix
from ._grade import VARIANT_VARIABLE, student
from ._grade import score as _score
from ._model import Model, Scenario
from ._read import Unreadable
from ._result import CheckResult
from ._spec import Spec, Verdict
from ._value import QUANTITIES, Hint, Mistake, Symbolic, Value

__all__ = ["names", "get", "catalogue", "register", "register_custom", "Check", "CheckResult", "KINDS",
           "QUANTITIES", "Value", "Symbolic", "Mistake", "Hint", "Choice", "LinkId", "LinkSet", "Groups",
           "Parts", "Model", "Scenario", "Design", "Condition", "Matrix", "Prediction", "Spec", "Verdict",
           "Unreadable", "student", "grade", "VARIANT_VARIABLE"]

_loaded = False


def _load_all() -> None:
    global _loaded
    if not _loaded:
        for info in pkgutil.iter_modules(__path__):
            if not info.name.startswith("_"):
                importlib.import_module(f"{__name__}.{info.name}")
        _loaded = True


def names() -> list[str]:
    """Names of every registered check."""
    _load_all()
    return sorted(REGISTRY)


def get(name: str) -> Check:
    """The check called *name*."""
    _load_all()
    try:
        return REGISTRY[name]
    except (KeyError, TypeError):
        raise UnknownCheckError(f"no exercise check {shown(name)}; see gl.check.names()") from None


class UnknownCheckError(UnknownLinkError, AttributeError):
    """No exercise check of that name (an :class:`AttributeError` too, so ``hasattr(gl.check, name)``
    keeps working)."""


def grade(name: str, answer, variant=None) -> float:
    """An autograder's test: check *answer* to exercise check *name* for *variant* (see
    :func:`student`), print the verdict (the check's hint when the answer is wrong, never the
    answer) and return the points it earns, between 0 and the exercise's points (its stars;
    parts of an answer that are right count their share). nbgrader reads the returned number
    as the cell's partial credit.

    >>> import gearlib as gl
    >>> gl.check.grade("intro_gear_ratio", None)
    ✘ Not yet. No answer yet: replace `None` with your answer.
    0.0
    """
    return _score(get(name), answer, variant)


def _order(check: Check) -> tuple:
    chapter, k = check.exercise.split(".")
    return int(chapter), int(k)


def catalogue(chapter=None) -> list[dict]:
    """Every exercise (or those of one chapter, ``"01"`` or 1), in the book's order, as
    :meth:`Check.info` dictionaries: what a course kit lists (never an answer)."""
    _load_all()
    checks = sorted(REGISTRY.values(), key=_order)
    if chapter is not None:
        checks = [c for c in checks if int(c.chapter) == int(chapter)]
    return [c.info() for c in checks]


def __getattr__(name: str):
    if name.startswith("__"):
        raise AttributeError(name)
    if any(info.name == name for info in pkgutil.iter_modules(__path__)):
        return importlib.import_module(f"{__name__}.{name}")  # a chapter's module: gl.check.mechanism
    return get(name)


def __dir__():
    _load_all()
    return sorted(set(__all__) | set(REGISTRY))
