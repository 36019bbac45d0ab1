"""Helpers for the tests of exercise checks, written independently of gearlib.check.

* :func:`representations`: the texts a value shows up as (fractions, decimals at 3 to 6
  significant figures, percentages, complex forms, sympy's printing of an expression).
* :func:`leaks_in`: which of those a text contains.
* the ``assert_*`` functions: the generic requirements of every check (used for the
  registered checks, and on deliberately broken checks to show that each one can fail).
* :data:`MALFORMED`: answers no check may crash or hang on.
"""

from __future__ import annotations

import cmath
import math
import re
import time
from decimal import Decimal
from fractions import Fraction

import numpy as np
import sympy


def _sig(x: float, n: int) -> str:
    return f"{x:.{n}g}"


def _decimals(x: float, figures=(3, 4, 5, 6)) -> set[str]:
    out = set()
    if x == 0 or not math.isfinite(x):
        return out
    for n in figures:
        s = _sig(x, n)
        if "e" in s:
            continue
        digits = s.replace("-", "").replace(".", "").lstrip("0")
        if len(digits) >= 3:  # "0.5" or "12" are everywhere; "0.286" is not
            out.add(s)
            if s.startswith("0."):
                out.add(s[1:])
    return out


def representations(value, *, percent: bool = False) -> set[str]:
    """Texts that would show *value*: ``-3/8``, ``0.375``, ``37.5%``, ``1.25+2.165j`` ...
    Whole numbers below 100 and one- or two-digit decimals are left out (they appear in any
    text); so are choices given by a letter."""
    out: set[str] = set()
    if isinstance(value, bool) or value is None:
        return out
    if isinstance(value, dict):
        for v in value.values():
            out |= representations(v, percent=percent)
        return out
    if isinstance(value, (list, tuple, set, frozenset, sympy.MatrixBase)):
        return out  # link sets and matrices: checked entry by entry where it matters
    if isinstance(value, str):
        text = value.strip()
        if len(text) > 3 and not re.fullmatch(r"[A-Da-d]", text):
            out.add(text)
        return out
    if isinstance(value, Fraction) or (isinstance(value, sympy.Rational) and not isinstance(value, sympy.Integer)):
        f = Fraction(int(sympy.Rational(value).p), int(sympy.Rational(value).q)) if not isinstance(value, Fraction) \
            else value
        if f.denominator != 1:
            out.add(f"{abs(f.numerator)}/{f.denominator}")  # the size alone gives the answer away too
            out.add(rf"\frac{{{abs(f.numerator)}}}{{{f.denominator}}}")
        value = float(f)
    if isinstance(value, (int, sympy.Integer)) and not isinstance(value, bool):
        if abs(int(value)) >= 100:
            out.add(str(abs(int(value))))
        return out
    if isinstance(value, (float, np.floating)):
        out |= _decimals(abs(float(value)))
        if percent and 0 < value <= 1:
            out |= {s + "%" for s in _decimals(100 * float(value), (3, 4))}
            out |= {s + " %" for s in _decimals(100 * float(value), (3, 4))}
        return out
    if isinstance(value, complex):
        for n in (3, 4, 5):
            re_, im_ = _sig(value.real, n), _sig(abs(value.imag), n)
            sign = "-" if value.imag < 0 else "+"
            out |= {f"{re_}{sign}{im_}j", f"{re_} {sign} {im_}j", f"{re_}{sign}{im_}i", f"{re_} {sign} {im_}i",
                    f"{_sig(abs(value), n)}∠{_sig(cmath.phase(value), n)}",
                    # the book's polar form: the angle in degrees (gearlib's polar_text)
                    f"{_sig(abs(value), n)}∠{_sig(math.degrees(cmath.phase(value)), n)}°"}
        return {o for o in out if len(re.sub(r"[^0-9]", "", o)) >= 4}
    if isinstance(value, sympy.Basic):
        if value.free_symbols:
            for form in (value, sympy.factor(value), sympy.simplify(value), sympy.expand(value)):
                out.add(str(form).replace(" ", ""))
            return out
        z = complex(sympy.N(value, 20))
        return representations(z.real if abs(z.imag) < 1e-15 else z, percent=percent)
    return out


def leaks_in(text: str, value, *, percent: bool = False, reps=None) -> list[str]:
    """The representations of *value* found in *text* (spaces ignored for expressions);
    *reps*: those representations, when the caller computed them already."""
    squashed = text.replace(" ", "")
    found = []
    for r in representations(value, percent=percent) if reps is None else reps:
        if re.search(r"[A-Za-z_]", r):  # an expression or a word: compare without spaces
            if r.replace(" ", "") in squashed:
                found.append(r)
        elif re.search(rf"(?<![0-9.]){re.escape(r)}(?![0-9])", text):
            found.append(r)
    return found


# ----------------------------------------------------------------------------- requirements
def assert_passes(check, answer, variant=None):
    result = check(answer, variant=variant)
    assert result.passed, f"{check.name}: the reference {answer!r} fails: {result.message}"


def _options_listed(text: str) -> bool:
    """A message that lists every option ("give one of 'a', 'b', ...") singles none out."""
    return "one of " in text


def _strings(value) -> list:
    if isinstance(value, str):
        return [value]
    if isinstance(value, dict):
        return [v for x in value.values() for v in _strings(x)]
    return []


def assert_hint_without_answer(check, wrong, reference, variant=None):
    result = check(wrong, variant=variant)
    assert not result.passed, f"{check.name}: the wrong answer {wrong!r} passes"
    assert result.message and "\n" not in result.message
    leaks = leaks_in(result.message, reference, percent=True)
    if _options_listed(result.message):
        leaks = [x for x in leaks if x not in _strings(reference)]
    assert not leaks, f"{check.name}: the hint for {wrong!r} shows the answer ({leaks}): {result.message}"
    return result


def rounded(value, figures: int = 4):
    """*value* (a number) rounded to *figures* significant figures, as text."""
    z = complex(value)
    if abs(z.imag) > 1e-12 * max(1.0, abs(z)):
        return f"{_sig(z.real, figures)}{'+' if z.imag >= 0 else '-'}{_sig(abs(z.imag), figures)}j"
    return _sig(z.real, figures)


def assert_rounding_is_not_a_method_error(check, reference, variant=None, figures: int = 4):
    """The reference rounded to *figures* significant figures passes, or is told to give more
    digits (or the exact value): never a hint about the method."""
    text = rounded(reference, figures)
    for answer in (text, complex(text.replace("i", "j")) if "j" in text else float(text)):
        result = check(answer, variant=variant)
        ok = result.passed or re.search(r"right to \d+ significant figure|exact value", result.message, re.I)
        assert ok, f"{check.name}: the rounded {answer!r} gets '{result.message}'"


def public_texts(check) -> dict[str, str]:
    """Everything the reader can reach on *check* without an underscore: each name of
    ``dir()`` with the text of its value (called when it is a method taking no argument)."""
    out = {"repr": repr(check), "str": str(check)}
    for name in dir(check):
        if name.startswith("_"):
            continue
        value = getattr(check, name)
        if callable(value):
            try:
                value = value()
            except TypeError:
                continue
        out[name] = repr(value)
    return out


def assert_nothing_public_carries_the_answer(check, reference):
    assert not hasattr(check, "__dict__"), f"{check.name}: a check must not keep attributes in a __dict__"
    for forbidden in ("expected", "answer", "reference", "solution", "compute", "value"):
        assert not hasattr(check, forbidden), f"{check.name}.{forbidden} is reachable"
    statement = check.question + " " + check.form
    reps = representations(reference, percent=True)  # once: sympy.simplify of an expression takes seconds
    for name, text in public_texts(check).items():
        # a choice's right option is one of the options the question lists: not a leak there
        leaks = [x for x in leaks_in(text, reference, percent=True, reps=reps) if not (x in _strings(reference) and x in statement)]
        assert not leaks, f"{check.name}.{name} shows the answer ({leaks})"


class _Raises:
    def __eq__(self, other):
        raise RuntimeError("comparison")

    def __float__(self):
        raise RuntimeError("float")

    def __repr__(self):
        return "<an object whose comparison raises>"

    __hash__ = None


class _Number(float):
    """A float subclass whose arithmetic raises."""

    def __add__(self, other):
        raise RuntimeError("add")

    __radd__ = __mul__ = __rmul__ = __sub__ = __truediv__ = __add__


def _nested(depth):
    x = [1]
    for _ in range(depth):
        x = [x]
    return x


def _cycle():
    a = []
    a.append(a)
    return a


MALFORMED = {
    "None": None, "empty": "", "blank": "   ", "empty list": [], "empty dict": {}, "list": [1, 2, 3],
    "dict": {"a": 1}, "NaN": float("nan"), "inf": float("inf"), "-inf": -float("inf"), "complex NaN": complex("nan"),
    "huge int": 10**400, "enormous int": 10**5000, "power tower **": "9**9**9**9", "power tower ^": "9^9^9^9",
    "power of powers": "(9**9)**(9**9)", "huge exponent": "1e999999", "long text": "1" * 100_000,
    "code": "__import__('os').system('echo leaked')", "lambda text": "lambda: 1", "exec": "exec('1')",
    "dunder": "().__class__.__bases__", "object": object(), "raising object": _Raises(), "raising float": _Number(2.0),
    "sympy tower": sympy.Pow(9, sympy.Pow(9, sympy.Pow(9, 9, evaluate=False), evaluate=False), evaluate=False),
    "bytes": b"2/7", "True": True, "function": (lambda x: x), "numpy NaN": np.array([np.nan]),
    "numpy matrix": np.array([[1, 2]]), "deep list": _nested(500), "cyclic list": _cycle(),
    "generator": (x for x in range(3)), "symbol": sympy.Symbol("x") + 1, "1/0": "1/0", "x y": "x y", "oo": "oo",
    "nan text": "nan", "unicode infinity": "∞", "Decimal NaN": Decimal("NaN"), "set": {1, 2},
    "dict of junk": {"sun": 10**400, "planet": "9**9**9", "ring": None}, "tuple of text": ("a", "b", "c"),
    "integral": sympy.Integral(sympy.Symbol("x"), sympy.Symbol("x")), "equation": sympy.Eq(sympy.Symbol("x"), 1),
}


def assert_malformed_answers_get_a_hint_fast(check, limit: float = 1.0):
    for label, junk in MALFORMED.items():
        start = time.perf_counter()
        result = check(junk)
        took = time.perf_counter() - start
        assert not result.passed, f"{check.name} accepts {label}"
        assert isinstance(result.message, str) and result.message and "\n" not in result.message, (check.name, label)
        assert took < limit, f"{check.name}: {label} took {took:.2f} s"
