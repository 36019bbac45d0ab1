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

import re
from fractions import Fraction

import sympy

from .._common.matview import polar_latex, polar_text
from .._common.parse import parse_count, shown
from ..errors import DataFormatError

__all__ = ["Number", "number", "Formula", "formula"]


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
        return polar_text(z, d), polar_latex(z, d)

    def __repr__(self) -> str:
        return self._parts()[0]

    __str__ = __repr__

    def _repr_latex_(self) -> str:
        return f"${self._parts()[1]}$"


def number(value, digits: int = 6) -> Number:
    """Wrap *value* for display in prose (see the module documentation)."""
    return Number(value, digits)


_TWO_SUBSCRIPTS = re.compile(r"^([A-Za-z]+)_([^_]+)_([^_]+)$")


def _tex_name(name: str) -> str | None:
    m = _TWO_SUBSCRIPTS.match(name)
    if m is None:
        return None
    head, a, b = m.groups()
    head = {"theta": r"\theta", "omega": r"\omega"}.get(head, head)
    return f"{head}_{{{a},{b}}}"


class Formula:
    """A sympy expression (or matrix) shown as the book writes it: a symbol with two
    subscripts, such as the gear ratio ``e_4_1``, prints as :math:`e_{4,1}`, not sympy's
    :math:`e_{4 1}` (ambiguous once links reach 10). The text form is sympy's."""

    def __init__(self, expr):
        self.expr = expr

    def latex(self, **settings) -> str:
        """The LaTeX form; *settings* go to ``sympy.latex`` (``order="none"`` keeps the terms of
        an expression built with ``evaluate=False`` in the order written)."""
        expr = self.expr
        names = {s: t for s in getattr(expr, "free_symbols", ()) if (t := _tex_name(str(s))) is not None}
        return sympy.latex(expr, symbol_names=names, **settings)

    def __repr__(self) -> str:
        return str(self.expr)

    def _repr_latex_(self) -> str:
        return f"$\\displaystyle {self.latex()}$"


def formula(expr) -> Formula:
    """Wrap a sympy expression for display with the book's subscripts (see :class:`Formula`).

    >>> import sympy, gearlib as gl
    >>> e41, e52, e21 = sympy.symbols("e_4_1 e_5_2 e_2_1")
    >>> gl.formula(e41 / (1 - e52 * e21)).latex()
    '\\\\frac{e_{4,1}}{- e_{2,1} e_{5,2} + 1}'
    """
    return Formula(expr)
