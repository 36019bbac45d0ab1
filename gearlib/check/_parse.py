"""The parser behind :mod:`gearlib.check._read`: text into sympy, one operation at a time.

A small precedence parser (sums, products, implicit products after a number or a bracket,
unary signs, right-associative powers, a postfix percent sign, calls of a few functions)
builds each node with sympy only once its operands are known to be small: a number has at
most :data:`MAX_DIGITS` digits, an exponent at most :data:`MAX_EXPONENT`, every exact
number at most :data:`MAX_BITS` bits, nesting at most :data:`MAX_DEPTH`. Nothing is passed
to ``eval``. Decimal numbers are kept as *literals*, so that the reader can move each by half
a unit of its last digit and find the precision of the whole answer.
"""

from __future__ import annotations

import math
import re
from decimal import Decimal
from fractions import Fraction

import sympy

__all__ = ["Unreadable", "parse", "MAX_TEXT", "MAX_DIGITS", "MAX_EXPONENT", "MAX_BITS", "MAX_DEPTH", "MAX_NODES"]

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
class Unreadable(Exception):
    """An answer that cannot be read; the message says why and what to write instead."""


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
            if self.peek()[:2] == ("op", "(") and not (self.names_ok and "_" in value and value not in _FUNCTIONS):
                # a subscripted name before a bracket ("e_1_4 (e_3_8 - e_6_8)") is a product, not a call
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


def parse(text: str, names: bool):
    """``(tree, literals, percent)`` of normalised *text*; :func:`build` turns a tree into sympy."""
    parser = _Parser(_tokens(text), names)
    if not parser.tokens:
        raise Unreadable("the answer is empty: type a value between the quotes")
    tree = parser.parse()
    return tree, parser.literals, parser.percent


build = _build
normalise = _normalise
