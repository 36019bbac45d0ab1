"""Numbers and formulas for prose: exact fractions as fractions, floats rounded, complex in
polar form, symbols in the book's notation.

``gl.number(value)`` wraps a value so that a notebook (and myst-nb's ``glue``) shows it
as mathematics: ``2/7`` becomes :math:`\\tfrac{2}{7}`, ``0.9462068699`` becomes ``0.946207``.
``gl.formula(expr)`` shows a sympy expression, equation or matrix with gearlib's symbols
written as the book writes them: ``e_1_2`` as :math:`e_{1,2}` (sympy's own printer would
write :math:`e_{1 2}`, which reads as :math:`e_{12}` once links reach 10), ``omega_4`` as
:math:`\\omega_{4}` and ``omega_2_4`` as :math:`\\omega_{2/4}`. The symbols themselves keep
their names (``e_1_2``), which is how a reader types them.

>>> import gearlib as gl
>>> from fractions import Fraction
>>> gl.number(Fraction(2, 7))
2/7
>>> gl.number(0.94620686990)._repr_latex_()
'$0.946207$'
>>> gl.number(-140.0)
-140
>>> import sympy
>>> print(gl.formula(sympy.Symbol("e_1_12") / (1 - sympy.Symbol("e_12_3")))._repr_latex_())
$\\frac{e_{1,12}}{1 - e_{12,3}}$
"""

from __future__ import annotations

import cmath
import re
from fractions import Fraction

import sympy

__all__ = ["Number", "number", "formula", "latex"]

_NAMES = re.compile(r"(e|eta|omega)_([^_]+)(?:_([^_]+))?")


def _symbol_tex(name: str) -> str | None:
    m = _NAMES.fullmatch(name)
    if m is None:
        return None
    head, a, b = m.groups()
    if head == "omega":
        return rf"\omega_{{{a}}}" if b is None else rf"\omega_{{{a}/{b}}}"
    if b is None:
        return None
    return f"{'e' if head == 'e' else chr(92) + 'eta'}_{{{a},{b}}}"


def latex(expr) -> str:
    """LaTeX for a sympy expression, equation or matrix, gearlib's symbols in the book's
    notation (see the module documentation)."""
    names = {}
    for sym in getattr(expr, "free_symbols", ()):
        tex = _symbol_tex(sym.name) if isinstance(sym, sympy.Symbol) and type(sym) is sympy.Symbol else None
        if tex is not None:
            names[sym] = tex
    return sympy.latex(expr, symbol_names=names)


class Number:
    """A value with a short text form (``repr``) and a LaTeX form (``_repr_latex_``)."""

    def __init__(self, value, digits: int = 6):
        self.value = value
        self.digits = digits

    def _parts(self):
        v = self.value
        if isinstance(v, Fraction):
            v = sympy.Rational(v.numerator, v.denominator)
        if isinstance(v, sympy.MatrixBase):
            return str(v), latex(v)
        if isinstance(v, sympy.Basic):
            if v.is_Rational or v.free_symbols or isinstance(v, sympy.Eq):
                return str(v), latex(v)
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


def formula(expr) -> Number:
    """Wrap a sympy expression, equation or matrix for display in the book's notation
    (``e_{1,2}``; see the module documentation)."""
    return Number(expr)
