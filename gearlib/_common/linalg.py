"""Exact sparse elimination, used for rational, algebraic and symbolic gear ratios.

Rows are dicts ``{column: coefficient}``. :class:`Echelon` takes them one at a time and
keeps a reduced basis, so that when a row adds nothing new it can say *which* row that
was: the library uses this to name a redundant gear pair or an input that is not
independent instead of printing "singular matrix".

Coefficients may be :class:`fractions.Fraction` (the fast path for tooth numbers), or
elements of a sympy polynomial domain (algebraic numbers such as ``exp(i*pi/3)``, or
rational functions of symbolic gear ratios ``e_a_b``), see :func:`domain_for`.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import sympy
from sympy.polys.constructor import construct_domain


@dataclass
class Field:
    """Arithmetic of the coefficients: how to convert, test for zero and convert back."""

    convert: callable
    is_zero: callable
    to_sympy: callable
    inv: callable
    zero: object
    name: str
    domain: object = None  # the sympy domain, when there is one


FRACTIONS = Field(
    convert=lambda x: x if isinstance(x, Fraction) else Fraction(x),
    is_zero=lambda x: x == 0,
    to_sympy=lambda x: sympy.Rational(x.numerator, x.denominator),
    inv=lambda x: 1 / x,
    zero=Fraction(0),
    name="QQ",
)


def domain_for(exprs) -> tuple[Field, list]:
    """Choose the smallest exact sympy domain holding every expression in *exprs*.

    Returns the :class:`Field` and the converted elements (in order).
    """
    exprs = [sympy.expand_complex(sympy.sympify(e)) if not sympy.sympify(e).free_symbols else sympy.sympify(e)
             for e in exprs]
    try:
        dom, elems = construct_domain(exprs, field=True, extension=True)
    except (NotImplementedError, ValueError, TypeError):
        dom, elems = construct_domain(exprs, field=True)
    field = Field(
        convert=dom.convert,
        is_zero=lambda x, d=dom: d.is_zero(x) if not d.is_EX else sympy.simplify(d.to_sympy(x)) == 0,
        to_sympy=dom.to_sympy,
        inv=lambda x, d=dom: d.quo(d.one, x),
        zero=dom.zero,
        name=str(dom),
        domain=dom,
    )
    return field, list(elems)


class Echelon:
    """Incremental row echelon form over an exact field.

    ``add(row, rhs, tag)`` reduces the row against the basis; it returns True when the row
    was independent, else records ``tag`` in :attr:`dependent` (and in :attr:`inconsistent`
    when its right-hand side did not reduce to zero).
    """

    def __init__(self, field: Field = FRACTIONS, weight=None):
        self.field = field
        self.weight = weight or {}  # column -> number of rows it appears in (pivot on rare columns)
        self.pivots: dict = {}  # pivot column -> (row dict with 1 at the pivot, rhs)
        self.order: list = []  # pivot columns in insertion order
        self.dependent: list = []
        self.inconsistent: list = []
        self.tags: list = []

    @property
    def rank(self) -> int:
        return len(self.order)

    def reduce(self, row: dict, rhs):
        """*row* and *rhs* with every pivot column eliminated (the row is copied)."""
        is_zero = self.field.is_zero
        row = dict(row)
        pivots = self.pivots
        # eliminate pivot columns; new fill-in can only be non-pivot columns or later pivots
        stack = [c for c in row if c in pivots]
        while stack:
            c = stack.pop()
            coef = row.get(c)
            if coef is None or is_zero(coef):
                row.pop(c, None)
                continue
            prow, prhs = pivots[c]
            for col, val in prow.items():
                new = row[col] - coef * val if col in row else self.field.zero - coef * val
                if col in row or not is_zero(new):
                    row[col] = new
                if col != c and col in pivots and col not in stack:
                    stack.append(col)
            rhs = rhs - coef * prhs
            row.pop(c, None)
        return {c: v for c, v in row.items() if not is_zero(v)}, rhs

    def add(self, row: dict, rhs=0, tag=None) -> bool:
        field = self.field
        row = {c: field.convert(v) for c, v in row.items()}
        rhs = field.convert(rhs)
        row, rhs = self.reduce(row, rhs)
        if not row:
            self.dependent.append(tag)
            if not field.is_zero(rhs):
                self.inconsistent.append(tag)
            return False
        weight = self.weight
        col = min(row, key=lambda c: (weight.get(c, 0), -c))  # rarest column first: least fill-in
        inv = field.inv(row[col])
        row = {c: v * inv for c, v in row.items()}
        self.pivots[col] = (row, rhs * inv)
        self.order.append(col)
        self.tags.append(tag)
        return True

    def solve(self, n: int) -> list:
        """The unique solution, once the rank equals the number of unknowns *n*."""
        if self.rank != n:
            raise ValueError(f"rank {self.rank} < {n} unknowns")
        x = {}
        for col in reversed(self.order):
            row, rhs = self.pivots[col]
            value = rhs
            for c, v in row.items():
                if c != col:
                    value = value - v * x[c]
            x[col] = value
        return [x[i] for i in range(n)]

    def free_columns(self, n: int) -> list:
        return [c for c in range(n) if c not in self.pivots]
