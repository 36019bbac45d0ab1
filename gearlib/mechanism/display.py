"""Numbers for prose: exact fractions as fractions, floats rounded, complex in polar form.

``gl.number(value)`` wraps a value so that a notebook (and myst-nb's ``glue``) shows it
as mathematics: ``2/7`` becomes :math:`\\tfrac{2}{7}`, ``0.9462068699`` becomes ``0.946207``.

>>> import gearlib as gl
>>> from fractions import Fraction
>>> gl.number(Fraction(2, 7))
2/7
>>> gl.number(0.94620686990)._repr_latex_()
'$0.946207$'
>>> gl.number(-140.0)
-140
"""

from __future__ import annotations

import cmath
from fractions import Fraction

import sympy

from .._common.parse import parse_count, shown
from ..errors import DataFormatError

__all__ = ["Number", "number"]


class Number:
    """A value with a short text form (``repr``) and a LaTeX form (``_repr_latex_``)."""

    def __init__(self, value, digits: int = 6):
        self.value = value
        self.digits = parse_count(digits, "number: digits", 1, 17)
        try:
            self._parts()
        except (TypeError, ValueError, OverflowError):
            raise DataFormatError(f"number: expected a number (int, float, complex, Fraction or a sympy number) "
                                  f"within a float's range, got {shown(value)}") from None

    def _parts(self):
        v = self.value
        if isinstance(v, Fraction):
            v = sympy.Rational(v.numerator, v.denominator)
        if isinstance(v, sympy.Basic):
            if v.is_Rational or v.free_symbols:
                return str(v), sympy.latex(v)
            v = complex(v.evalf(30))
        z = complex(v)
        d = self.digits
        if abs(z.imag) <= 1e-12 * max(1.0, abs(z)):
            text = f"{z.real:.{d}g}"
            return text, text.replace("e-", r"\times 10^{-").replace("e+", r"\times 10^{") + ("}" if "e" in text else "")
        r, phi = abs(z), cmath.phase(z)
        return f"{r:.{d}g}∠{phi:.{d}g}", rf"{r:.{d}g}\,e^{{{phi:.{d}g}\,i}}"

    def __repr__(self) -> str:
        return self._parts()[0]

    __str__ = __repr__

    def _repr_latex_(self) -> str:
        return f"${self._parts()[1]}$"


def number(value, digits: int = 6) -> Number:
    """Wrap *value* for display in prose (see the module documentation)."""
    return Number(value, digits)
