"""Reading a reader's answer safely: text, numbers and sympy objects into a :class:`Reading`.

Nothing is evaluated. Text is split into tokens and parsed here (a small precedence parser)
into sympy objects built one operation at a time, with limits on its length, its nesting,
the digits of each number, the size of every exponent and the size of every intermediate
number, so that ``9**9**9**9`` or ``"1e999999"`` get a message at once instead of a hang.
Text may use ``I``, ``i`` or ``j`` for the imaginary unit (``2+3j``, ``2.5*exp(i*pi/3)``),
the Unicode minus and multiplication signs of a rendered page (``−``, ``×``, ``·``), ``π``,
Greek letters for names (``ω_4`` is ``omega_4``), ``e_{1,2}`` for ``e_1_2``, a percent sign
and a unit suffix (``"450 Hz"``, ``"2827 rad/s"``, ``"89.6 %"``).

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

__all__ = ["Reading", "Unreadable", "read", "read_text", "MAX_TEXT"]

MAX_TEXT = 400          # characters of an answer typed as text
MAX_DIGITS = 40         # digits of one number in the text
MAX_EXPONENT = 100      # |exponent| of a power, and of a number's e-notation
MAX_BITS = 20_000       # bits of any exact number met on the way (about 6000 digits)
MAX_DEPTH = 40          # nesting of parentheses
MAX_NODES = 3000        # nodes of a sympy expression given directly

UNICODE = {"\u2212": "-", "\u2013": "-", "\u2014": "-", "\u00d7": "*", "\u00b7": "*", "\u22c5": "*",
           "\u2217": "*", "\u00f7": "/", "\u2044": "/", "\u03c0": " pi ", "\u03c9": "omega", "\u03b7": "eta",
           "\u03b6": "zeta", "\u03b8": "theta", "\u03b3": "gamma", "\u03b1": "alpha", "\u03b2": "beta",
           "\u00a0": " ", "\u2009": " ", "\u202f": " ", "\u2032": "'", "\u00b2": "^2", "\u00b3": "^3",
           "\uff05": "%", "\u2030": " permille"}
_LATEX_SUB = re.compile(r"_\{\s*([A-Za-z0-9]+)\s*,\s*([A-Za-z0-9]+)\s*\}")
_LATEX_ONE = re.compile(r"_\{\s*([A-Za-z0-9]+)\s*\}")
_TOKEN = re.compile(
    r"\s*(?:(?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)(?P<imag>[ij](?![A-Za-z0-9_]))?"
    r"|(?P<name>[A-Za-z][A-Za-z0-9_']*)|(?P<op>\*\*|[-+*/^()%,=]))"
)
_FUNCTIONS = {"sqrt": sympy.sqrt, "exp": sympy.exp, "sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan,
              "atan": sympy.atan, "log": sympy.log, "ln": sympy.log, "abs": sympy.Abs, "re": sympy.re,
              "im": sympy.im, "arg": sympy.arg, "conjugate": sympy.conjugate}
_CONSTANTS = {"pi": sympy.pi, "I": sympy.I, "i": sympy.I, "j": sympy.I, "E": sympy.E, "e": sympy.E,
              "deg": sympy.pi / 180}
# unit suffixes: name -> (unit, factor to that unit)
UNITS = {
    "hz": ("Hz", 1), "1/s": ("Hz", 1), "s^-1": ("Hz", 1), "/s": ("Hz", 1), "khz": ("Hz", 1000),
    "rad/s": ("rad/s", 1), "rad s^-1": ("rad/s", 1), "rad/sec": ("rad/s", 1),
    "rpm": ("rpm", 1), "r/min": ("rpm", 1), "rev/min": ("rpm", 1), "1/min": ("rpm", 1), "min^-1": ("rpm", 1),
    "deg/s": ("deg/s", 1), "°/s": ("deg/s", 1),
    "mm": ("mm", 1), "cm": ("mm", 10), "m": ("mm", 1000),
}
_UNIT_SUFFIX = re.compile(r"^(?P<body>.*?\S)\s*(?P<unit>" + "|".join(
    re.escape(u) for u in sorted(UNITS, key=len, reverse=True)) + r")\s*$", re.IGNORECASE | re.S)


class Unreadable(Exception):
    """An answer that cannot be read; the message says why and what to write instead."""


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


# ----------------------------------------------------------------------------- the parser
class _Parser:
    def __init__(self, tokens, names_ok: bool):
        self.tokens = tokens
        self.pos = 0
        self.names_ok = names_ok
        self.literals: list[tuple[Fraction, Fraction]] = []  # (value, half unit of last digit)
        self.percent = False

    def peek(self):
        return self.tokens[self.pos] if self.pos < len(self.tokens) else (None, None, None)

    def take(self):
        tok = self.peek()
        self.pos += 1
        return tok

    def expect(self, op):
        kind, value, _ = self.take()
        if (kind, value) != ("op", op):
            raise Unreadable(f"expected '{op}' {'here' if value is None else 'before ' + repr(value)}")

    def parse(self):
        node = self.expr(0)
        kind, value, _ = self.peek()
        if kind is not None:
            if value == ",":
                raise Unreadable("this asks for a single value, not a list")
            if value == "=":
                raise Unreadable("give the value alone, without '='")
            raise Unreadable(f"unexpected {value!r}")
        return node

    def expr(self, depth):
        if depth > MAX_DEPTH:
            raise Unreadable("the expression is nested too deeply")
        node = self.term(depth)
        while self.peek()[0] == "op" and self.peek()[1] in "+-":
            op = self.take()[1]
            node = ("+", node, self.term(depth)) if op == "+" else ("-", node, self.term(depth))
        return node

    def term(self, depth):
        node = self.unary(depth)
        while True:
            kind, value, _ = self.peek()
            if kind == "op" and value in ("*", "/"):
                self.take()
                node = (value, node, self.unary(depth))
            elif kind in ("num", "name") or (kind == "op" and value == "("):
                if kind == "num" and node[0] in ("num", "lit", "neg"):
                    raise Unreadable("two numbers in a row: write an operator between them")
                node = ("*", node, self.unary(depth))
            else:
                return node

    def unary(self, depth):
        kind, value, _ = self.peek()
        if kind == "op" and value in "+-":
            self.take()
            inner = self.unary(depth + 1)
            return inner if value == "+" else ("neg", inner)
        return self.power(depth)

    def power(self, depth):
        base = self.postfix(depth)
        kind, value, _ = self.peek()
        if kind == "op" and value in ("^", "**"):
            self.take()
            return ("pow", base, self.unary(depth + 1))
        return base

    def postfix(self, depth):
        node = self.atom(depth)
        if self.peek()[:2] == ("op", "%"):
            self.take()
            self.percent = True
            node = ("%", node)
        return node

    def atom(self, depth):
        kind, value, extra = self.take()
        if kind == "num":
            digits = value.lower().split("e")[0].replace(".", "").lstrip("0")
            if len(digits) > MAX_DIGITS:
                raise Unreadable(f"a number with more than {MAX_DIGITS} digits")
            mantissa, _, exponent = value.lower().partition("e")
            if exponent and abs(int(exponent)) > MAX_EXPONENT:
                raise Unreadable(f"the exponent of {value} is too large")
            exact = Fraction(Decimal(value))
            if "." in mantissa or exponent.startswith("-"):
                places = len(mantissa.partition(".")[2]) - (int(exponent) if exponent else 0)
                half = Fraction(1, 2) * Fraction(10) ** (-places)
                self.literals.append((exact, half))
                node = ("lit", len(self.literals) - 1)
            else:
                node = ("num", sympy.Rational(exact.numerator, exact.denominator))
            return ("*", node, ("const", sympy.I)) if extra else node
        if kind == "name":
            if self.peek()[:2] == ("op", "("):
                if value not in _FUNCTIONS:
                    raise Unreadable(f"unknown function {value!r}")
                self.take()
                arg = self.expr(depth + 1)
                if self.peek()[:2] == ("op", ","):
                    raise Unreadable(f"{value}() takes one argument")
                self.expect(")")
                return ("call", value, arg)
            if value in _CONSTANTS:
                return ("const", _CONSTANTS[value])
            if value in _FUNCTIONS:
                raise Unreadable(f"{value} needs brackets: {value}(...)")
            if not self.names_ok:
                raise Unreadable(f"your answer uses the name {value!r}; give a number")
            return ("sym", value)
        if kind == "op" and value == "(":
            inner = self.expr(depth + 1)
            self.expect(")")
            return (")", inner)
        if kind is None:
            raise Unreadable("the expression ends too early")
        raise Unreadable(f"unexpected {value!r}")


def _bounded(x):
    """Refuse exact numbers too large to work with (their bits), and non-finite values."""
    if x.has(sympy.nan, sympy.zoo, sympy.oo, -sympy.oo):
        raise Unreadable("the answer is not a finite number (a division by zero?)")
    for atom in x.atoms(sympy.Rational):
        if max(abs(atom.p).bit_length(), atom.q.bit_length()) > MAX_BITS:
            raise Unreadable("a number in the answer is far too large")
    return x


def _size(x) -> float:
    """log10 of the size of a numeric sympy value (0 for symbols), cheaply."""
    if isinstance(x, sympy.Rational):
        return (max(abs(x.p), 1).bit_length() + x.q.bit_length()) * 0.302
    if x.is_number:
        try:
            v = abs(complex(sympy.N(x, 15)))
        except (TypeError, ValueError, OverflowError):
            return float("inf")
        return abs(math.log10(v)) if v else 0.0
    return 0.0


def _build(node, lits):
    tag = node[0]
    if tag == "num" or tag == "const":
        return node[1]
    if tag == "lit":
        v = lits[node[1]]
        return sympy.Rational(v.numerator, v.denominator)
    if tag == "sym":
        return sympy.Symbol(node[1])
    if tag == ")":
        return _build(node[1], lits)
    if tag == "neg":
        return -_build(node[1], lits)
    if tag == "%":
        return _build(node[1], lits) / 100
    if tag == "call":
        arg = _build(node[2], lits)
        if arg.is_number and _size(arg) > 6 and node[1] in ("exp", "sin", "cos", "tan"):
            raise Unreadable(f"the argument of {node[1]}() is far too large")
        return _bounded(_FUNCTIONS[node[1]](arg))
    a, b = _build(node[1], lits), _build(node[2], lits)
    if tag == "+":
        return _bounded(a + b)
    if tag == "-":
        return _bounded(a - b)
    if tag == "*":
        return _bounded(a * b)
    if tag == "/":
        if b == 0:
            raise Unreadable("the answer divides by zero")
        return _bounded(a / b)
    # a power: the exponent must be a modest number, and so must the result
    if b.is_number:
        if b.is_real is not True:
            if abs(complex(sympy.N(b, 15))) > 1e4 or (a.is_number and _size(a) > 6):
                raise Unreadable("an exponent in the answer is too large")
            return _bounded(a ** b)
        try:
            bf = float(b)
        except (TypeError, ValueError):
            raise Unreadable("cannot read that exponent") from None
        if abs(bf) > MAX_EXPONENT:
            raise Unreadable("an exponent in the answer is too large")
        if isinstance(b, sympy.Rational) and b.q > 100:
            raise Unreadable("an exponent in the answer has too large a denominator")
        if a.is_number and _size(a) * abs(bf) > 3000:
            raise Unreadable("a power in the answer is far too large")
        if a == 0 and bf < 0:
            raise Unreadable("the answer divides by zero")
        return _bounded(a ** b)
    if a.is_number and _size(a) > 6:
        raise Unreadable("a power in the answer is far too large")
    return a ** b


def _normalise(text: str) -> str:
    for k, v in UNICODE.items():
        text = text.replace(k, v)
    text = _LATEX_SUB.sub(r"_\1_\2", text)
    text = _LATEX_ONE.sub(r"_\1", text)
    return text.replace("\\cdot", "*").replace("\\times", "*").replace("\\pi", " pi ").strip()


def _tokens(text: str):
    pos, out = 0, []
    while pos < len(text):
        if text[pos:].strip() == "":
            break
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            bad = text[pos:].strip()[:12]
            raise Unreadable(f"cannot read {bad!r}; use numbers, + - * / ^ ( ), I or j, pi and the names given")
        kind = m.lastgroup if m.lastgroup != "imag" else "num"
        out.append((kind, m.group(kind), m.group("imag") if kind == "num" else None))
        pos = m.end()
    return out


def read_text(text: str, *, names: bool = False, units: bool = True) -> Reading:
    """Read *text* (see the module docstring); ``names=True`` lets symbols through."""
    if len(text) > MAX_TEXT:
        raise Unreadable(f"the answer is too long (more than {MAX_TEXT} characters)")
    raw = text
    text = _normalise(text)
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
    parser = _Parser(_tokens(text), names)
    if not parser.tokens:
        raise Unreadable("the answer is empty: type a value between the quotes")
    tree = parser.parse()
    exact = [v for v, _ in parser.literals]
    value = _build(tree, exact)
    spread: complex = 0
    if parser.literals:
        if not value.is_number:
            spread = 0  # decimals inside a symbolic answer are read exactly
        else:
            v0 = complex(sympy.N(value, 30))
            re_s = im_s = 0.0
            for k, (lit, half) in enumerate(parser.literals):
                moved = list(exact)
                moved[k] = lit + half
                d = complex(sympy.N(_build(tree, moved), 30)) - v0
                re_s += abs(d.real)
                im_s += abs(d.imag)
            spread = complex(re_s, im_s) if im_s else re_s
    if factor != 1:
        value = value * factor
        spread = spread * factor
    return Reading(value, spread, unit, 1, parser.percent, bool(parser.literals), raw)


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
        if isinstance(answer, (sympy.core.relational.Relational, sympy.logic.boolalg.Boolean)):
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
