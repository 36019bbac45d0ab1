"""Comparing an answer with the reference: to the digits given, or exactly, or up to algebra.

* :func:`agreement`: how a number read from the answer (a :class:`~gearlib.check._read.Reading`)
  stands against the reference value: equal, within half a unit of its last digit, and to
  how many significant figures it is right.
* :func:`equivalent`: two expressions equal as functions of their symbols, by exact
  evaluation at random rational points (numerically, to 30 digits, when they hold ``pi``,
  ``I`` or functions), in bounded time.
* :func:`proportional`: two rows of expressions equal up to a non-zero factor.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass

import sympy

__all__ = ["Agreement", "agreement", "numeric", "equivalent", "proportional", "FLOOR"]

FLOOR = 1e-10
"""Relative tolerance below which two numbers are equal whatever the digits (float rounding)."""


def numeric(x) -> complex:
    """A sympy number as a Python complex, to 30 digits (``ValueError`` if it is not a number)."""
    x = sympy.sympify(x)
    try:
        z = complex(float(x)) if isinstance(x, sympy.Rational) else complex(sympy.N(x, 30))
    except (TypeError, ValueError, OverflowError) as err:
        raise ValueError(f"not a number: {err}") from None
    if not (math.isfinite(z.real) and math.isfinite(z.imag)):
        raise ValueError("not a finite number")
    return z


def _is_integer(x) -> bool:
    return isinstance(x, sympy.Integer) or (isinstance(x, sympy.Rational) and x.q == 1)


def _exactly_equal(a, b) -> bool:
    if isinstance(a, sympy.Rational) and isinstance(b, sympy.Rational):
        return a == b
    try:
        za, zb = numeric(a), numeric(b)
    except ValueError:
        return False
    return abs(za - zb) <= 1e-25 * max(1.0, abs(zb))


@dataclass(frozen=True)
class Agreement:
    """``equal``: exactly the reference; ``within``: inside the spread of its digits;
    ``given``: significant figures the answer states (``math.inf`` for an exact answer);
    ``right``: significant figures to which it agrees with the reference."""

    equal: bool
    within: bool
    given: float
    right: float


def _figures(size: float, err: float) -> float:
    if err <= 0:
        return math.inf
    if size <= 0:
        return 0
    return max(0, math.floor(math.log10(size / (2 * err))) + 1)


def agreement(reading, reference, *, floor: float = FLOOR) -> Agreement:
    """How the number *reading* stands against the number *reference* (see the module)."""
    value = reading.value
    if _exactly_equal(value, reference):  # exactly the answer, however it was written (2.5, 0.375, 5/2)
        return Agreement(True, True, math.inf, math.inf)
    a, e = numeric(value), numeric(reference)
    spread = complex(reading.spread)
    s_re, s_im = abs(spread.real), abs(spread.imag)
    if (reading.exact and _is_integer(sympy.sympify(value)) and not _is_integer(sympy.sympify(reference))
            and abs(a) >= 10):
        # a whole number of two digits or more given for a value that is not one ("2827" for
        # 2827.43): rounded to units; a single digit (1 for 0.625, 3 for 3.4) is taken as meant
        s_re = 0.5
    size = max(abs(a), abs(e))
    d = a - e
    tol = floor * size
    within = abs(d.real) <= s_re + tol and abs(d.imag) <= s_im + tol
    given = math.inf if (s_re == 0 and s_im == 0) else _figures(abs(a) if abs(a) else size, max(s_re, s_im))
    right = math.inf if abs(d) <= tol else _figures(abs(e) if abs(e) else size, abs(d))
    return Agreement(False, within, given, right)


# ----------------------------------------------------------------------------- algebra
def _points(symbols, rng, count):
    primes = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97]
    for _ in range(count):
        yield {s: sympy.Rational(rng.choice(primes) * rng.choice((1, -1)), rng.choice(primes[:12])) for s in symbols}


def _value_at(expr, point, exact: bool):
    v = expr.xreplace(point)
    if exact:
        if not isinstance(v, sympy.Rational):
            raise ValueError("undefined at this point")
        return v
    return numeric(v)


def _is_rational_function(expr) -> bool:
    return all(isinstance(a, (sympy.Rational, sympy.Symbol)) for a in expr.atoms()) and not expr.atoms(
        sympy.Function)


def equivalent(a, b, *, points: int = 5, seed: int = 20261122) -> bool:
    """True when expressions *a* and *b* agree at *points* random rational points of their
    symbols (exactly for rational functions, to 1e-20 otherwise). Points where either is
    undefined are skipped; ``False`` if too few points are defined."""
    a, b = sympy.sympify(a), sympy.sympify(b)
    symbols = sorted(a.free_symbols | b.free_symbols, key=str)
    exact = _is_rational_function(a) and _is_rational_function(b)
    rng = random.Random(seed)
    agreed = 0
    for point in _points(symbols, rng, 3 * points if symbols else 1):
        try:
            va, vb = _value_at(a, point, exact), _value_at(b, point, exact)
        except (ValueError, ZeroDivisionError, TypeError):
            continue
        if isinstance(va, sympy.Rational) and isinstance(vb, sympy.Rational):
            if va != vb:
                return False
        else:
            va, vb = complex(va), complex(vb)
            if abs(va - vb) > 1e-15 * max(1.0, abs(va), abs(vb)):
                return False
        agreed += 1
        if agreed >= (points if symbols else 1):
            return True
    return False


def proportional(row, ref, *, points: int = 4, seed: int = 7) -> bool:
    """True when *row* is a non-zero multiple of *ref* (lists of expressions of one length)."""
    row, ref = [sympy.sympify(x) for x in row], [sympy.sympify(x) for x in ref]
    if len(row) != len(ref):
        return False
    symbols = sorted(set().union(*(x.free_symbols for x in row + ref)), key=str)
    rng = random.Random(seed)
    agreed = 0
    for point in _points(symbols, rng, 3 * points if symbols else 1):
        try:
            a = [numeric(x.xreplace(point)) for x in row]
            b = [numeric(x.xreplace(point)) for x in ref]
        except (ValueError, ZeroDivisionError, TypeError):
            continue
        big = max(range(len(b)), key=lambda k: abs(b[k]))
        if abs(b[big]) == 0 or abs(a[big]) == 0:
            if any(abs(x) > 0 for x in a) or any(abs(x) > 0 for x in b):
                return False
            continue
        k = a[big] / b[big]
        scale = max(abs(x) for x in a)
        if any(abs(x - k * y) > 1e-9 * scale for x, y in zip(a, b)):
            return False
        agreed += 1
        if agreed >= (points if symbols else 1):
            return True
    return False
