"""Safe parsing of the values that appear in mechanism data.

Numbers and expressions come from YAML/JSON files, dicts and the command line. Text is
never passed to ``eval`` unchecked: an expression is first split into tokens (numbers,
names, ``+ - * / ^ ( )``), names beginning with ``_`` are refused, and only then is it
handed to sympy with a fixed vocabulary (``pi``, ``I``, ``E``, ``deg``, ``sqrt``, ``exp``,
``sin``, ``cos``, ``tan``); every other name becomes a sympy symbol.

Every number must fit a float (``|x|`` up to about 1.8e308), since results are printed and
plotted as floats: ``1e400``, ``exp(1000)`` or an integer of thousands of digits is refused
with a message. Text is evaluated one operation at a time with limits on its length, the
digits and exponent of each number and the size of every power, so ``9^9^9^9`` gets a
message at once instead of a hang.
"""

from __future__ import annotations

import math
import numbers
import re
import sys
from fractions import Fraction
from functools import lru_cache

import sympy

from ..errors import DataFormatError, ToothNumberError

MAX_TEETH = 100_000
"""Largest tooth number accepted; larger values are almost always a unit or typing mistake."""

FLOAT_MAX = sys.float_info.max
"""Largest magnitude of a number in the data (results are printed and plotted as floats)."""
MAX_TEXT = 2000      # characters of one expression
MAX_DIGITS = 100     # digits of one number written in an expression
MAX_E = 400          # |exponent| of a number written in e-notation
MAX_BITS = 4000      # bits of a power computed exactly (about 1200 digits; a float needs 1024)

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
    if len(text) > MAX_TEXT:
        raise DataFormatError(f"{where}: the expression is too long ({len(text)} characters; at most {MAX_TEXT})")
    tokens = _tokens(text, where)
    if not tokens:
        raise DataFormatError(f"{where}: empty expression")
    names: dict[str, object] = {}
    pieces = []
    depth = 0
    for i, (kind, value) in enumerate(tokens):
        if kind == "op" and value in "()":
            depth += 1 if value == "(" else -1
            if depth > 50:
                raise DataFormatError(f"{where}: the expression nests parentheses more than 50 deep")
        if kind == "num":
            mantissa, _, exp = value.lower().partition("e")
            if sum(c.isdigit() for c in mantissa) > MAX_DIGITS:
                raise DataFormatError(f"{where}: a number in {shown(text)} has more than {MAX_DIGITS} digits")
            if exp and abs(int(exp)) > MAX_E:
                raise DataFormatError(f"{where}: {value} is beyond the range of a float (about 1.8e308)")
            pieces.append(f"Rational('{value}')" if ("." in value or "e" in value.lower()) else f"Integer({value})")
        elif kind == "name":
            is_call = i + 1 < len(tokens) and tokens[i + 1] == ("op", "(")
            if value in _FUNCTIONS and is_call:
                names[value] = _FUNCTIONS[value]
            elif value in _CONSTANTS:
                names[value] = _CONSTANTS[value]
            else:
                if is_call:
                    raise DataFormatError(f"{where}: unknown function {value!r} in {shown(text)}")
                names[value] = sympy.Symbol(value)
            pieces.append(value)
        else:
            pieces.append("**" if value == "^" else value)
    code = " ".join(pieces)
    namespace = {"Rational": sympy.Rational, "Integer": sympy.Integer, "__builtins__": {}}
    namespace.update(names)
    try:
        # Only the tokens checked above reach here: numbers, allow-listed names and operators.
        # Nothing is computed yet (evaluate=False): _evaluate computes one bounded step at a time.
        with sympy.evaluate(False):
            tree = eval(code, namespace)  # noqa: S307
        expr = _evaluate(sympy.sympify(tree), where, text)
    except (SyntaxError, TypeError, ZeroDivisionError, ValueError, RecursionError, MemoryError) as err:
        if isinstance(err, DataFormatError):
            raise
        raise DataFormatError(f"{where}: cannot read {shown(text)} as an expression ({err})") from None
    return expr


def _log2(x) -> float:
    """log2 of |x| for an exact number already built (0 for zero)."""
    if isinstance(x, sympy.Rational):
        p, q = abs(int(x.p)), int(x.q)
        return (p.bit_length() if p else 0) - q.bit_length()
    try:
        v = abs(complex(sympy.N(x, 15)))
    except (TypeError, ValueError, OverflowError):
        return float("inf")
    return math.log2(v) if v else 0.0


def _evaluate(node, where: str, text: str):
    """Evaluate an unevaluated sympy tree bottom-up, refusing any power or exponential whose
    value would be too large before computing it."""
    if not node.args:
        return node
    args = [_evaluate(a, where, text) for a in node.args]
    if isinstance(node, sympy.Pow) and args[1].is_number:
        e = abs(complex(sympy.N(args[1], 15)))
        size = abs(_log2(args[0])) if args[0].is_number else 1.0
        if size * e > MAX_BITS or (not args[0].is_number and e > 1000):
            raise DataFormatError(f"{where}: a power in {shown(text)} is far too large")
    if isinstance(node, sympy.exp) and args[0].is_number and abs(complex(sympy.N(args[0], 15)).real) > 2000:
        raise DataFormatError(f"{where}: {shown(text)} is beyond the range of a float (about 1.8e308)")
    if isinstance(node, (sympy.sin, sympy.cos, sympy.tan)) and args[0].is_number \
            and abs(complex(sympy.N(args[0], 15))) > 1e9:
        raise DataFormatError(f"{where}: the angle in {shown(text)} is far too large")
    return node.func(*args)


def check_range(expr, value, where: str):
    """*expr* (read from *value*) if it is a number within a float's range, or a symbolic
    expression; else a :class:`DataFormatError`."""
    if expr.free_symbols:
        return expr
    if isinstance(expr, sympy.Rational):
        p, q = abs(int(expr.p)), int(expr.q)
        if p.bit_length() - q.bit_length() < 1020:
            return expr
    try:
        z = complex(sympy.N(expr, 20))
    except (TypeError, ValueError, OverflowError):
        z = complex(math.inf)
    if not (abs(z.real) <= FLOAT_MAX and abs(z.imag) <= FLOAT_MAX):
        raise DataFormatError(f"{where}: {shown(value)} is beyond the range of a float (about 1.8e308)")
    return expr


def parse_expr(value, where: str) -> sympy.Expr:
    """Read a number or expression into an exact sympy expression.

    Floats are read by their shortest decimal form (``0.98`` -> ``49/50``).
    """
    if isinstance(value, bool) or value is None:
        raise DataFormatError(f"{where}: expected a number or an expression, got {value!r}")
    if isinstance(value, sympy.Basic):
        expr = value
    elif isinstance(value, numbers.Integral):
        if not -FLOAT_MAX <= value <= FLOAT_MAX:
            raise DataFormatError(f"{where}: {shown(value)} is beyond the range of a float (about 1.8e308)")
        expr = sympy.Integer(int(value))
    elif isinstance(value, Fraction):
        if not -FLOAT_MAX <= value <= FLOAT_MAX or value.denominator.bit_length() > MAX_BITS:
            raise DataFormatError(f"{where}: {shown(value)} is beyond the range of a float (about 1.8e308)")
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
        raise DataFormatError(f"{where}: {shown(value)} is not a finite value")
    return check_range(expr, value, where)


def parse_real_expr(value, where: str) -> sympy.Expr:
    """An exact expression that must be a finite real number (an angle, say)."""
    expr = parse_expr(value, where)
    if expr.free_symbols or expr.is_real is False or not expr.is_number:
        raise DataFormatError(f"{where}: expected a real number, got {shown(value)}")
    try:
        v = complex(expr.evalf(30))
    except (TypeError, ValueError):
        raise DataFormatError(f"{where}: expected a real number, got {shown(value)}") from None
    if v.imag != 0 or not math.isfinite(v.real):
        raise DataFormatError(f"{where}: expected a real number, got {shown(value)}")
    return expr


def parse_teeth(value, where: str) -> int:
    """A tooth number: a positive integer no larger than :data:`MAX_TEETH`."""
    if type(value) is int and 0 < value <= MAX_TEETH:  # the common case, fast
        return value
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ToothNumberError(f"{where}: tooth number must be a positive integer, got {shown(value)}")
    if isinstance(value, numbers.Integral):
        n = int(value)
    else:
        f = float(value)
        if not math.isfinite(f) or f != int(f):
            raise ToothNumberError(f"{where}: tooth number must be a positive integer, got {shown(value)}")
        n = int(f)
    if n <= 0:
        raise ToothNumberError(f"{where}: tooth number must be positive, got {shown(n)}")
    if n > MAX_TEETH:
        raise ToothNumberError(f"{where}: tooth number {n if n < 10**30 else shown(n)} is larger than {MAX_TEETH}; "
                               "check the units")
    return n


def parse_link_id(value, where: str):
    """A link id: an integer, or a short name made of letters, digits and ``_ ' . -``.

    Text made only of digits is read as an integer, so ``"3"`` (a JSON key, a command-line
    argument) is link 3.
    """
    if type(value) is int:  # the common case first: the ABC checks below cost about 1 us each
        return value
    if isinstance(value, bool):
        raise DataFormatError(f"{where}: link id must be an integer or a short name, got {shown(value)}")
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, str) and _LINK_ID.match(value):
        return int(value) if value.isdigit() else value  # "3" from JSON keys or the command line is link 3
    raise DataFormatError(
        f"{where}: link id must be an integer or a short name (letters, digits, _ ' . -; at most 32), "
        f"got {shown(value)}"
    )


def parse_count(value, where: str, low: int = 0, high: int | None = None) -> int:
    """A whole number in ``[low, high]`` (a count of links, pairs, terminals, harmonics)."""
    if isinstance(value, float) and value.is_integer():
        value = int(value)
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise DataFormatError(f"{where}: expected a whole number, got {shown(value)}")
    value = int(value)
    if value < low or (high is not None and value > high):
        span = f"from {low} to {high}" if high is not None else f"of at least {low}"
        raise DataFormatError(f"{where}: expected a whole number {span}, got {shown(value)}")
    return value


def parse_probability(value, where: str) -> float:
    """A number in [0, 1]."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not 0 <= float(value) <= 1:
        raise DataFormatError(f"{where}: expected a probability from 0 to 1, got {shown(value)}")
    return float(value)


def parse_real(value, where: str) -> float:
    """A finite real number."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(float(value)):
        raise DataFormatError(f"{where}: expected a finite number, got {shown(value)}")
    return float(value)


def parse_positive(value, where: str) -> float:
    """A positive finite real number (a length, a diameter)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(float(value)):
        raise DataFormatError(f"{where}: expected a positive number, got {shown(value)}")
    if float(value) <= 0:
        raise DataFormatError(f"{where}: expected a positive number, got {shown(value)}")
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


def hashable(x) -> bool:
    """True when *x* can be a dict key (a link id must be)."""
    try:
        hash(x)
    except TypeError:
        return False
    return True


def iterable(x) -> bool:
    """True when *x* can be iterated (a list of links, a pair)."""
    try:
        iter(x)
    except TypeError:
        return False
    return True


def shown(x, limit: int = 60) -> str:
    """``repr(x)`` for a message, cut to *limit* characters (an integer of thousands of digits by its size)."""
    if isinstance(x, int) and not isinstance(x, bool) and x.bit_length() > 200:
        n = abs(x)
        digits = int(n.bit_length() * 0.30102999566398)
        digits += n >= 10**digits
        return f"an integer of {digits} digits"
    try:
        text = repr(x)
    except Exception:  # noqa: BLE001 - a repr that fails says nothing useful anyway
        text = f"a {type(x).__name__}"
    return text if len(text) <= limit else text[: limit - 3] + "..."
