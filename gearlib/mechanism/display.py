"""Numbers for prose: exact fractions as fractions, floats rounded, complex in polar form
(``r∠phi°``, the angle in degrees, as every table of the book writes it).

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
>>> gl.number(28.14 - 2.81j, 4)
28.28∠-5.703°
"""

from __future__ import annotations

from fractions import Fraction

import sympy

from .._common.matview import polar_latex, polar_text

__all__ = ["Number", "number"]


class Number:
    """A value with a short text form (``repr``) and a LaTeX form (``_repr_latex_``)."""

    def __init__(self, value, digits: int = 6):
        self.value = value
        self.digits = digits

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
        return polar_text(z, d), polar_latex(z, d)

    def __repr__(self) -> str:
        return self._parts()[0]

    __str__ = __repr__

    def _repr_latex_(self) -> str:
        return f"${self._parts()[1]}$"


def number(value, digits: int = 6) -> Number:
    """Wrap *value* for display in prose (see the module documentation)."""
    return Number(value, digits)
