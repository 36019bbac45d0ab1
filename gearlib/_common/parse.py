"""Safe parsing of the values that appear in mechanism data.

Numbers and expressions come from YAML/JSON files, dicts and the command line. Text is
never passed to ``eval`` unchecked: an expression is first split into tokens (numbers,
names, ``+ - * / ^ ( )``), names beginning with ``_`` are refused, and only then is it
handed to sympy with a fixed vocabulary (``pi``, ``I``, ``E``, ``deg``, ``sqrt``, ``exp``,
``sin``, ``cos``, ``tan``); every other name becomes a sympy symbol.
"""

from __future__ import annotations

import math
import numbers
import re
from fractions import Fraction
from functools import lru_cache

import sympy

from ..errors import DataFormatError, ToothNumberError

MAX_TEETH = 100_000
"""Largest tooth number accepted; larger values are almost always a unit or typing mistake."""

_TOKEN = re.compile(
    r"\s*(?:(?P<num>\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)"
    r"|(?P<name>[A-Za-z][A-Za-z0-9_]*)|(?P<op>\*\*|[-+*/^()]))"
)
_FUNCTIONS = {"sqrt": sympy.sqrt, "exp": sympy.exp, "sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan}
_CONSTANTS = {"pi": sympy.pi, "I": sympy.I, "E": sympy.E, "deg": sympy.pi / 180}
_LINK_ID = re.compile(r"^[A-Za-z0-9_'.-]{1,32}$")


def _tokens(text: str, where: str) -> list[tuple[str, str]]:
    pos, out = 0, []
    text = text.strip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            raise DataFormatError(
                f"{where}: cannot read {text!r} as an expression (unexpected {text[pos:pos + 10]!r}); "
                "use numbers, names, + - * / ^ ( ) and pi, I, deg, sqrt, exp, sin, cos, tan"
            )
        kind = m.lastgroup
        out.append((kind, m.group(kind)))
        pos = m.end()
    return out


@lru_cache(maxsize=4096)
def _parse_text(text: str, where: str) -> sympy.Expr:
    tokens = _tokens(text, where)
    if not tokens:
        raise DataFormatError(f"{where}: empty expression")
    names: dict[str, object] = {}
    pieces = []
    for i, (kind, value) in enumerate(tokens):
        if kind == "num":
            pieces.append(f"Rational('{value}')" if ("." in value or "e" in value.lower()) else f"Integer({value})")
        elif kind == "name":
            is_call = i + 1 < len(tokens) and tokens[i + 1] == ("op", "(")
            if value in _FUNCTIONS and is_call:
                names[value] = _FUNCTIONS[value]
            elif value in _CONSTANTS:
                names[value] = _CONSTANTS[value]
            else:
                if is_call:
                    raise DataFormatError(f"{where}: unknown function {value!r} in {text!r}")
                names[value] = sympy.Symbol(value)
            pieces.append(value)
        else:
            pieces.append("**" if value == "^" else value)
    code = " ".join(pieces)
    namespace = {"Rational": sympy.Rational, "Integer": sympy.Integer, "__builtins__": {}}
    namespace.update(names)
    try:
        # Only the tokens checked above reach here: numbers, allow-listed names and operators.
        expr = eval(code, namespace)  # noqa: S307
    except (SyntaxError, TypeError, ZeroDivisionError, ValueError) as err:
        raise DataFormatError(f"{where}: cannot read {text!r} as an expression ({err})") from None
    return sympy.sympify(expr)


def parse_expr(value, where: str) -> sympy.Expr:
    """Read a number or expression into an exact sympy expression.

    Floats are read by their shortest decimal form (``0.98`` -> ``49/50``).
    """
    if isinstance(value, bool) or value is None:
        raise DataFormatError(f"{where}: expected a number or an expression, got {value!r}")
    if isinstance(value, sympy.Basic):
        expr = value
    elif isinstance(value, numbers.Integral):
        expr = sympy.Integer(int(value))
    elif isinstance(value, Fraction):
        expr = sympy.Rational(value.numerator, value.denominator)
    elif isinstance(value, numbers.Real):
        if not math.isfinite(float(value)):
            raise DataFormatError(f"{where}: {value!r} is not a finite number")
        expr = sympy.Rational(repr(float(value)))
    elif isinstance(value, numbers.Complex):
        z = complex(value)
        if not (math.isfinite(z.real) and math.isfinite(z.imag)):
            raise DataFormatError(f"{where}: {value!r} is not a finite number")
        expr = sympy.Rational(repr(z.real)) + sympy.I * sympy.Rational(repr(z.imag))
    elif isinstance(value, (list, tuple)) and len(value) == 2 and not any(isinstance(v, str) for v in value):
        # [re, im], the form complex numbers take in JSON
        expr = parse_expr(value[0], where) + sympy.I * parse_expr(value[1], where)
    elif isinstance(value, str):
        expr = _parse_text(value, where)
    else:
        raise DataFormatError(f"{where}: expected a number or an expression, got {type(value).__name__}")
    if expr.has(sympy.nan, sympy.zoo, sympy.oo, -sympy.oo):
        raise DataFormatError(f"{where}: {value!r} is not a finite value")
    return expr


def parse_real_expr(value, where: str) -> sympy.Expr:
    """An exact expression that must be a finite real number (an angle, say)."""
    expr = parse_expr(value, where)
    if expr.free_symbols or expr.is_real is False or not expr.is_number:
        raise DataFormatError(f"{where}: expected a real number, got {value!r}")
    try:
        v = complex(expr.evalf(30))
    except (TypeError, ValueError):
        raise DataFormatError(f"{where}: expected a real number, got {value!r}") from None
    if v.imag != 0 or not math.isfinite(v.real):
        raise DataFormatError(f"{where}: expected a real number, got {value!r}")
    return expr


def parse_teeth(value, where: str) -> int:
    """A tooth number: a positive integer no larger than :data:`MAX_TEETH`."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ToothNumberError(f"{where}: tooth number must be a positive integer, got {value!r}")
    if isinstance(value, numbers.Integral):
        n = int(value)
    else:
        f = float(value)
        if not math.isfinite(f) or f != int(f):
            raise ToothNumberError(f"{where}: tooth number must be a positive integer, got {value!r}")
        n = int(f)
    if n <= 0:
        raise ToothNumberError(f"{where}: tooth number must be positive, got {n}")
    if n > MAX_TEETH:
        raise ToothNumberError(f"{where}: tooth number {n} is larger than {MAX_TEETH}; check the units")
    return n


def parse_link_id(value, where: str):
    """A link id: an integer, or a short name made of letters, digits and ``_ ' . -``.

    Text made only of digits is read as an integer, so ``"3"`` (a JSON key, a command-line
    argument) is link 3.
    """
    if type(value) is int:  # the common case first: the ABC checks below cost about 1 us each
        return value
    if isinstance(value, bool):
        raise DataFormatError(f"{where}: link id must be an integer or a short name, got {value!r}")
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, str) and _LINK_ID.match(value):
        return int(value) if value.isdigit() else value  # "3" from JSON keys or the command line is link 3
    raise DataFormatError(
        f"{where}: link id must be an integer or a short name (letters, digits, _ ' . -; at most 32), "
        f"got {value!r}"
    )


def parse_real(value, where: str) -> float:
    """A finite real number."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(float(value)):
        raise DataFormatError(f"{where}: expected a finite number, got {value!r}")
    return float(value)


def parse_positive(value, where: str) -> float:
    """A positive finite real number (a length, a diameter)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(float(value)):
        raise DataFormatError(f"{where}: expected a positive number, got {value!r}")
    if float(value) <= 0:
        raise DataFormatError(f"{where}: expected a positive number, got {value!r}")
    return float(value)


def to_fraction(expr: sympy.Expr) -> Fraction | None:
    """The exact rational value of *expr*, or None if it is not a rational number."""
    if isinstance(expr, sympy.Rational):
        return Fraction(int(expr.p), int(expr.q))
    return None


def expr_to_data(expr: sympy.Expr):
    """Write an expression back as plain data: int, or a string sympy can read again."""
    if isinstance(expr, sympy.Integer):
        return int(expr)
    return str(expr)
