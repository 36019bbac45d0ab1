"""Exercise checks: ``gl.check.<name>(answer)``.

Each check answers a wrong value with a hint and a right one with a short confirmation;
it never shows the solution and never raises. Answers may be ints, floats, fractions,
complex numbers, sympy expressions or text (``"2/7"``).

>>> import gearlib as gl
>>> gl.check.intro_planetary_ratio(None)
✘ Not yet. No answer yet: replace `None` with your answer.
>>> gl.check.intro_planetary_ratio("7/2")
✘ Not yet. You have the reciprocal: check which speed goes on top (in this book a ratio is output over input).

Chapters add checks in their own module here (``gearlib/check/<chapter>.py``) with
``register``; every module in this package is imported on first use.
"""

from __future__ import annotations

import importlib
import pkgutil

from ._core import REGISTRY, Check, CheckResult, Hint, as_value, close, register, register_custom

__all__ = ["names", "get", "Check", "CheckResult", "Hint", "register", "register_custom", "as_value", "close"]

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
    except KeyError:
        raise AttributeError(f"no exercise check {name!r}; see gl.check.names()") from None


def __getattr__(name: str):
    if name.startswith("__"):
        raise AttributeError(name)
    return get(name)


def __dir__():
    _load_all()
    return sorted(list(globals()) + list(REGISTRY))
