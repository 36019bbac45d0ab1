"""Exercise checks: ``gl.check.<name>(answer)``, and the machinery to write new ones.

A check answers a right answer with a short confirmation and a wrong one with a hint that
diagnoses the usual mistakes of its kind of quantity; it never shows the answer (no
attribute, method, repr or message of a check carries it), never raises, and returns in
bounded time whatever it is given. Answers may be ints, floats, fractions, complex numbers,
numpy or sympy values, or text (``"2/7"``, ``"−1.3846"``, ``"450 Hz"``, ``"89.6 %"``); a
decimal is right when it is within half a unit of its last digit.

>>> import gearlib as gl
>>> gl.check.intro_gear_ratio(None)
✘ Not yet. No answer yet: replace `None` with your answer.
>>> gl.check.intro_gear_ratio("3/8")
✘ Not yet. The size is right but the sign is not: count the external meshes from input to output (each reverses the direction relative to its carrier; an internal one keeps it); for bevel gears the sign follows the axis directions the exercise chose.

Each check is numbered and described (``exercise``, ``title``, ``stars``, ``minutes``,
``kind``), can draw other numbers for a student (``check(answer, variant="s1234")``,
``check.given(variant)``, ``check.statement(variant)``), and returns a
:class:`CheckResult` a grader can score. Chapters register their checks in their own
module here (``gearlib/check/<subpackage>.py``) with :func:`register` and a spec
(:class:`Value`, :class:`Symbolic`, :class:`Choice`, ...); every module of this package whose
name does not start with ``_`` is imported on first use.
"""

from __future__ import annotations

import importlib
import pkgutil

from ._choice import Choice, Groups, LinkId, LinkSet, Parts
from ._core import KINDS, Check, Prediction, Spec, Verdict, catalogue, get, names, register, register_custom
from ._design import Condition, Design, Matrix
from ._model import Model, Scenario
from ._read import Unreadable
from ._result import CheckResult
from ._value import QUANTITIES, Hint, Mistake, Symbolic, Value

__all__ = ["names", "get", "catalogue", "register", "register_custom", "Check", "CheckResult", "KINDS",
           "QUANTITIES", "Value", "Symbolic", "Mistake", "Hint", "Choice", "LinkId", "LinkSet", "Groups",
           "Parts", "Model", "Scenario", "Design", "Condition", "Matrix", "Prediction", "Spec", "Verdict",
           "Unreadable"]

_loaded = False


def _load_all() -> None:
    global _loaded
    if not _loaded:
        for info in pkgutil.iter_modules(__path__):
            if not info.name.startswith("_"):
                importlib.import_module(f"{__name__}.{info.name}")
        _loaded = True


def __getattr__(name: str):
    if name.startswith("__"):
        raise AttributeError(name)
    return get(name)


def __dir__():
    _load_all()
    from ._core import REGISTRY

    return sorted(set(__all__) | set(REGISTRY))
