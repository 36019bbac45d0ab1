"""Reading a reader's answer safely: text, numbers and sympy objects into a :class:`Reading`.

Nothing is evaluated. Text is split into tokens and parsed (:mod:`gearlib.check._parse`)
into sympy objects built one operation at a time, with limits on its length, its nesting,
the digits of each number, the size of every exponent and the size of every intermediate
number, so that ``9**9**9**9`` or ``"1e999999"`` get a message at once instead of a hang.
Text may use ``I``, ``i`` or ``j`` for the imaginary unit (``2+3j``, ``2.5*exp(i*pi/3)``),
the Unicode minus and multiplication signs of a rendered page (``−``, ``×``, ``·``), ``π``,
Greek letters for names (``ω_4`` is ``omega_4``), ``e_{1,2}`` for ``e_1_2``, a percent sign
and a unit suffix (``"120 Hz"``, ``"2827 rad/s"``, ``"3.2 orders"``, ``"89.6 %"``).

A decimal number carries its precision: ``"0.2857"`` is 0.2857 give or take half a unit of
its last digit, and so is the float ``0.2857`` (read by its shortest repr). The precision of
an expression with several decimals is found by moving each decimal by half a unit of its
last digit (:attr:`Reading.spread`).
"""

from __future__ import annotations

import math
import numbers
import re
from dataclasses import dataclass, field
from decimal import Decimal
from fractions import Fraction

import sympy

from ._parse import MAX_BITS, MAX_DEPTH, MAX_EXPONENT, MAX_NODES, MAX_TEXT, Unreadable, _bounded, _size, build
from ._parse import normalise, parse

__all__ = ["Reading", "Unreadable", "read", "read_text", "MAX_TEXT"]

UNITS = {
    "hz": ("Hz", 1), "1/s": ("Hz", 1), "s^-1": ("Hz", 1), "/s": ("Hz", 1), "khz": ("Hz", 1000),
    "rad/s": ("rad/s", 1), "rad s^-1": ("rad/s", 1), "rad/sec": ("rad/s", 1),
    "rpm": ("rpm", 1), "r/min": ("rpm", 1), "rev/min": ("rpm", 1), "1/min": ("rpm", 1), "min^-1": ("rpm", 1),
    "deg/s": ("deg/s", 1), "°/s": ("deg/s", 1),
    "mm": ("mm", 1), "cm": ("mm", 10), "m": ("mm", 1000),
    "orders": ("orders", 1), "order": ("orders", 1),
}
_UNIT_SUFFIX = re.compile(r"^(?P<body>.*?\S)\s*(?P<unit>" + "|".join(
    re.escape(u) for u in sorted(UNITS, key=len, reverse=True)) + r")\s*$", re.IGNORECASE | re.S)



@dataclass(frozen=True)
class Reading:
    """An answer read into sympy.

    ``value`` is a sympy number or expression; ``spread`` the half-width of the interval the
    answer stands for (0 for an exact answer such as ``2/7`` or ``Fraction(2, 7)``; half a
    unit of the last digit for ``0.2857``), or a complex number for the real and imaginary
    parts separately; ``unit`` the unit suffix written (``"Hz"``), ``percent`` whether it
    was written with ``%``; ``decimal`` whether it was written with decimals.
    """

    value: sympy.Basic
    spread: complex = 0
    unit: str | None = None
    unit_factor: object = 1
    percent: bool = False
    decimal: bool = False
    text: str = field(default="", repr=False)

    @property
    def exact(self) -> bool:
        return self.spread == 0


def read_text(text: str, *, names: bool = False, units: bool = True) -> Reading:
    """Read *text* (see the module docstring); ``names=True`` lets symbols through."""
    if len(text) > MAX_TEXT:
        raise Unreadable(f"the answer is too long (more than {MAX_TEXT} characters)")
    raw = text
    text = normalise(text)
    if not text:
        raise Unreadable("the answer is empty: type a value between the quotes")
    if re.fullmatch(r"[+-]?\d+,\d+", text):
        raise Unreadable("write the decimal point as '.', not ','")
    unit, factor = None, 1
    m = _UNIT_SUFFIX.match(text) if units else None
    if m and not re.search(r"[A-Za-z_]$", m.group("body")):
        unit, factor = UNITS[m.group("unit").lower()]
        text = m.group("body")
    if text.count("=") == 1:
        left, right = text.split("=")
        if re.fullmatch(r"\s*[A-Za-z_][A-Za-z0-9_/ ()]*\s*", left) and right.strip():
            text = right
    tree, literals, percent = parse(text, names)
    exact = [v for v, _ in literals]
    value = build(tree, exact)
    spread: complex = 0
    if literals:
        if not value.is_number:
            spread = 0  # decimals inside a symbolic answer are read exactly
        else:
            v0 = complex(sympy.N(value, 30))
            re_s = im_s = 0.0
            for k, (lit, half) in enumerate(literals):
                moved = list(exact)
                moved[k] = lit + half
                d = complex(sympy.N(build(tree, moved), 30)) - v0
                re_s += abs(d.real)
                im_s += abs(d.imag)
            spread = complex(re_s, im_s) if im_s else re_s
    if factor != 1:
        value = value * factor
        spread = spread * factor
    return Reading(value, spread, unit, 1, percent, bool(literals), raw)


# ----------------------------------------------------------------------------- other forms
_ALLOWED = (sympy.Add, sympy.Mul, sympy.Pow, sympy.Rational, sympy.Float, sympy.NumberSymbol, sympy.Symbol,
            sympy.exp, sympy.sin, sympy.cos, sympy.tan, sympy.atan, sympy.log, sympy.Abs, sympy.re, sympy.im,
            sympy.arg, sympy.conjugate)


def _check_sympy(expr, budget=None, depth=0) -> None:
    """Refuse sympy expressions that are too large, or that would take long to evaluate: the
    arguments are checked before any exponent is evaluated (so a power tower stops at its
    first large exponent)."""
    budget = budget if budget is not None else [MAX_NODES]
    budget[0] -= 1
    if budget[0] < 0 or depth > 2 * MAX_DEPTH:
        raise Unreadable("the expression is far too large")
    if expr is sympy.I or isinstance(expr, sympy.core.numbers.ImaginaryUnit):
        return
    if not isinstance(expr, _ALLOWED):
        raise Unreadable(f"the answer uses {type(expr).__name__}, which a check cannot read; "
                         "give numbers, + - * / ** and the functions sqrt, exp, sin, cos, tan, log")
    if isinstance(expr, sympy.Rational) and max(abs(expr.p).bit_length(), expr.q.bit_length()) > MAX_BITS:
        raise Unreadable("a number in the answer is far too large")
    if isinstance(expr, sympy.Float) and not math.isfinite(float(expr)):
        raise Unreadable("the answer is not a finite number")
    for arg in expr.args:
        _check_sympy(arg, budget, depth + 1)
    if isinstance(expr, sympy.Pow) and expr.exp.is_number:
        try:
            e = abs(complex(sympy.N(expr.exp, 15)))
        except (TypeError, ValueError, OverflowError):
            raise Unreadable("an exponent in the answer cannot be read") from None
        if e > MAX_EXPONENT or (expr.base.is_number and _size(expr.base) * e > 3000):
            raise Unreadable("a power in the answer is far too large")


def _from_float(x: float) -> Reading:
    """A float by its shortest repr (``0.2857`` stands for 0.2857 give or take 0.00005); a
    whole float such as ``450.0`` is the integer."""
    if not math.isfinite(x):
        raise Unreadable("the answer is not a finite number (NaN or infinity)")
    if x == int(x) and abs(x) < 2**53:
        return Reading(sympy.Integer(int(x)))
    return read_text(repr(x), units=False)


def read(answer, *, names: bool = False) -> Reading:
    """Read one value: int, float, complex, Fraction, Decimal, numpy scalar, sympy number or
    expression, or text. Anything else raises :class:`Unreadable` with a message."""
    if answer is None:
        raise Unreadable("no answer yet: replace `None` with your answer")
    if isinstance(answer, bool):
        raise Unreadable("True or False is not an answer to this question")
    if isinstance(answer, (bytes, bytearray)):
        raise Unreadable("give the answer as text (in quotes) or as a number, not as bytes")
    mod = type(answer).__module__ or ""
    if mod.startswith("numpy"):
        if getattr(answer, "ndim", 1) != 0 and not hasattr(answer, "item"):
            raise Unreadable("this asks for a single value")
        if getattr(answer, "size", 1) != 1 or getattr(answer, "ndim", 0) > 0:
            raise Unreadable("this asks for a single value, not an array")
        answer = answer.item()
    if isinstance(answer, bool):
        raise Unreadable("True or False is not an answer to this question")
    if isinstance(answer, int):
        if answer.bit_length() > MAX_BITS:
            raise Unreadable("that number is far too large")
        return Reading(sympy.Integer(answer))
    if isinstance(answer, Fraction):
        if max(abs(answer.numerator).bit_length(), answer.denominator.bit_length()) > MAX_BITS:
            raise Unreadable("that number is far too large")
        return Reading(sympy.Rational(answer.numerator, answer.denominator))
    if isinstance(answer, float):
        return _from_float(answer)
    if isinstance(answer, complex):
        re_, im_ = _from_float(answer.real), _from_float(answer.imag)
        return Reading(re_.value + sympy.I * im_.value, complex(abs(re_.spread), abs(im_.spread)),
                       decimal=re_.decimal or im_.decimal)
    if isinstance(answer, Decimal):
        if not answer.is_finite():
            raise Unreadable("the answer is not a finite number (NaN or infinity)")
        return read_text(str(answer), units=False)
    if isinstance(answer, sympy.Basic):
        if isinstance(answer, sympy.core.relational.Relational) or (
                isinstance(answer, sympy.logic.boolalg.Boolean) and not isinstance(answer, sympy.Expr)):  # a Symbol is both
            raise Unreadable("give an expression, not an equation or a condition (drop the `Eq(...)`)")
        if isinstance(answer, sympy.MatrixBase) or not isinstance(answer, sympy.Expr):
            raise Unreadable("this asks for a single value")
        _check_sympy(answer)
        if isinstance(answer, sympy.Float):
            return _from_float(float(answer))
        if answer.free_symbols and not names:
            raise Unreadable("your answer uses " + ", ".join(sorted(map(str, answer.free_symbols)))
                             + "; give a number")
        return Reading(_bounded(answer), decimal=bool(answer.atoms(sympy.Float)))
    if isinstance(answer, str):
        return read_text(answer, names=names)
    if isinstance(answer, numbers.Number):  # another number type: read it through float or complex
        try:
            z = complex(answer)
        except Exception:
            raise Unreadable(f"could not read a number of type {type(answer).__name__}") from None
        return read(z.real if z.imag == 0 else z, names=names)
    if isinstance(answer, (list, tuple, set, frozenset, dict)) or hasattr(answer, "__iter__"):
        raise Unreadable("this asks for a single value, not a collection")
    if callable(answer):
        raise Unreadable("that is a function: call it, or give its result")
    raise Unreadable(f"could not read an answer of type {type(answer).__name__}; give a number or text")
