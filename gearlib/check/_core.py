"""The machinery behind exercise checks.

A check compares a reader's answer with a value gearlib computes, and answers with a
short confirmation or a hint. It never prints the expected value, never raises, and
accepts the usual forms of an answer: int, float, :class:`fractions.Fraction`, complex,
numpy numbers and arrays, sympy expressions, and text such as ``"2/7"`` or
``"e_1_2*e_2_3/(e_1_2*e_2_3 - 1)"``.

A chapter defines a check with ``register``::

    @register("intro_planetary_ratio", chapter="00", hints=[...])
    def intro_planetary_ratio():
        return gl.ratio(gl.catalog.simple_planetary(24, 60), output=4, input=1, ground=3)

and readers call ``gl.check.intro_planetary_ratio(answer)``.
"""

from __future__ import annotations

import math
import numbers
import random
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np
import sympy

__all__ = ["CheckResult", "Check", "register", "register_custom", "REGISTRY", "as_value", "close", "Hint"]

REGISTRY: dict[str, Check] = {}


@dataclass(frozen=True)
class CheckResult:
    """The verdict of a check: ``passed`` and a message. Truthy when passed."""

    passed: bool
    message: str
    name: str = ""

    def __bool__(self) -> bool:
        return self.passed

    def __str__(self) -> str:
        mark = "✔ Correct." if self.passed else "✘ Not yet."
        return f"{mark} {self.message}".strip()

    def __repr__(self) -> str:
        return str(self)

    def _repr_html_(self) -> str:
        color = "#1a7f37" if self.passed else "#9a6700"
        return f"<p style='color:{color}'><b>{'✔ Correct.' if self.passed else '✘ Not yet.'}</b> {self.message}</p>"


class _Unreadable(Exception):
    pass


def as_value(answer):
    """Turn an answer into a sympy object (number, expression, Matrix) for comparison."""
    from .._common.parse import parse_expr

    if answer is None:
        raise _Unreadable("no answer yet: replace `None` with your answer")
    if isinstance(answer, bool):
        raise _Unreadable("a yes/no value is not an answer to this question")
    if isinstance(answer, (sympy.MatrixBase, np.ndarray)) or (
        isinstance(answer, Sequence) and not isinstance(answer, (str, bytes))
    ):
        arr = answer.tolist() if hasattr(answer, "tolist") else list(answer)
        if arr and isinstance(arr[0], (list, tuple)):
            return sympy.Matrix([[as_value(x) for x in row] for row in arr])
        return sympy.Matrix([as_value(x) for x in arr])
    if isinstance(answer, sympy.Basic):
        if isinstance(answer, sympy.Equality):
            raise _Unreadable("give an expression, not an equation (drop the `Eq(...)`)")
        return answer
    if isinstance(answer, np.generic):
        answer = answer.item()
    if isinstance(answer, (numbers.Number, str)):
        try:
            return parse_expr(answer, "your answer")
        except Exception as err:  # a bad string, NaN, ...
            raise _Unreadable(f"could not read your answer ({err})") from None
    raise _Unreadable(f"could not read an answer of type {type(answer).__name__}; give a number or an expression")


def _numeric(expr, subs):
    value = complex(sympy.N(expr.subs(subs), 30))
    if not (math.isfinite(value.real) and math.isfinite(value.imag)):
        raise ZeroDivisionError
    return value


def close(a, b, *, rtol: float = 1e-9, atol: float = 1e-12) -> bool:
    """True when sympy values *a* and *b* are equal: exactly, or at random points for
    expressions with symbols, or within ``rtol`` for floating-point numbers."""
    if isinstance(a, sympy.MatrixBase) or isinstance(b, sympy.MatrixBase):
        if not (isinstance(a, sympy.MatrixBase) and isinstance(b, sympy.MatrixBase)) or a.shape != b.shape:
            return False
        return all(close(x, y, rtol=rtol, atol=atol) for x, y in zip(a, b))
    a, b = sympy.sympify(a), sympy.sympify(b)
    syms = sorted(a.free_symbols | b.free_symbols, key=str)
    rng = random.Random(20261122)  # a local generator: no global random state is touched
    trials = 5 if syms else 1
    ok = 0
    for _ in range(trials * 3):
        subs = {s: sympy.Rational(rng.randint(2, 97), rng.randint(2, 97)) for s in syms}
        try:
            x, y = _numeric(a, subs), _numeric(b, subs)
        except (ZeroDivisionError, TypeError, ValueError):
            continue
        if abs(x - y) > atol + rtol * max(abs(x), abs(y)):
            return False
        ok += 1
        if ok >= trials:
            return True
    return False


@dataclass(frozen=True)
class Hint:
    """A typical mistake: ``test(answer, expected) -> bool`` and what to say about it."""

    test: Callable
    message: str


def _standard_hints(rtol):
    def near(f):
        def test(ans, exp):
            try:
                return close(ans, f(exp), rtol=rtol)
            except Exception:
                return False

        return test

    return [
        Hint(near(lambda e: -e), "The size is right but the sign is not: check which way each mesh turns "
             "(external meshes reverse the direction, internal ones keep it)."),
        Hint(near(lambda e: 1 / e), "You have the reciprocal: check which speed goes on top "
             "(in this book a ratio is output over input)."),
        Hint(near(lambda e: -1 / e), "You have minus the reciprocal: check both which speed goes on top "
             "and the sign."),
    ]


@dataclass(frozen=True)
class Check:
    """One exercise check. Call it with an answer to get a :class:`CheckResult`."""

    name: str
    compute: Callable
    chapter: str = ""
    question: str = ""
    hints: tuple = ()
    rtol: float = 1e-6
    generic_hint: str = "Go back to the Willis equation of each gear pair and write it out step by step."
    standard_hints: bool = True
    accept: Callable | None = field(default=None, compare=False)
    _memo: dict = field(default_factory=dict, compare=False, repr=False)

    @property
    def expected(self):
        return self.compute()

    def _expected(self):
        """``compute()``, computed once per check: a reader who tries again, or a page of
        checks, does not redo the work (some enumerate an atlas). Matrices are kept immutable
        so that nothing the check hands out can change it."""
        if "value" not in self._memo:
            value = self.compute()
            if isinstance(value, sympy.MatrixBase):
                value = sympy.ImmutableMatrix(value)
            else:
                value = sympy.sympify(value)
            self._memo["value"] = value
        return self._memo["value"]

    def __call__(self, answer) -> CheckResult:
        try:
            return self._check(answer)
        except Exception as err:  # a check must never crash on a reader's answer
            return CheckResult(False, f"This answer could not be checked ({type(err).__name__}). "
                               "Give a number, a fraction or a sympy expression.", self.name)

    def _check(self, answer) -> CheckResult:
        if self.accept is not None:
            ok, message = self.accept(answer)
            return CheckResult(bool(ok), message, self.name)
        try:
            value = as_value(answer)
        except _Unreadable as err:
            return CheckResult(False, str(err)[0].upper() + str(err)[1:] + ".", self.name)
        expected = self._expected()
        if isinstance(expected, sympy.MatrixBase) != isinstance(value, sympy.MatrixBase):
            shape = "a matrix or list" if isinstance(expected, sympy.MatrixBase) else "a single value"
            return CheckResult(False, f"This question asks for {shape}.", self.name)
        if isinstance(expected, sympy.MatrixBase) and expected.shape != value.shape:
            return CheckResult(False, f"The shape is not right: expected {expected.shape[0]} x {expected.shape[1]} "
                               "entries.", self.name)
        if close(value, expected, rtol=self.rtol):
            return CheckResult(True, "Well done.", self.name)
        if not isinstance(expected, sympy.MatrixBase):
            extra = value.free_symbols - expected.free_symbols if isinstance(value, sympy.Basic) else set()
            if extra:
                names = ", ".join(sorted(str(s) for s in extra))
                return CheckResult(False, f"Your answer uses {names}, which the answer does not need.", self.name)
        hints = list(self.hints) + (_standard_hints(self.rtol) if self.standard_hints else [])
        for hint in hints:
            try:
                if hint.test(value, expected):
                    return CheckResult(False, hint.message, self.name)
            except Exception:
                continue
        return CheckResult(False, self.generic_hint, self.name)


def register(name: str, *, chapter: str = "", question: str = "", hints=(), rtol: float = 1e-6,
             generic_hint: str | None = None, standard_hints: bool = True):
    """Decorator: register a function that computes the expected answer as check *name*."""

    def deco(fn):
        kw = {}
        if generic_hint is not None:
            kw["generic_hint"] = generic_hint
        check = Check(name, fn, chapter, question or (fn.__doc__ or "").strip(), tuple(hints), rtol,
                      standard_hints=standard_hints, **kw)
        if name in REGISTRY:
            raise ValueError(f"check {name!r} is registered twice")
        REGISTRY[name] = check
        return check

    return deco


def register_custom(name: str, accept: Callable, *, chapter: str = "", question: str = ""):
    """Register a check that judges the answer itself: ``accept(answer) -> (ok, message)``.

    Use it for answers that are not values (a function, a set of links, a choice). The
    message must not reveal the solution.
    """
    check = Check(name, lambda: None, chapter, question, accept=accept)
    if name in REGISTRY:
        raise ValueError(f"check {name!r} is registered twice")
    REGISTRY[name] = check
    return check
