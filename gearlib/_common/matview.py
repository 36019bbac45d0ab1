"""Readable matrices: labelled rows and columns, complex entries as ``N e^(i theta)`` or ``r∠phi``."""

from __future__ import annotations

import cmath
import html
import re
from dataclasses import dataclass

import sympy

__all__ = ["MatrixView", "format_entry"]


def _exponent(theta) -> str:
    """``i theta`` as text: ``iπ/4``, ``-7iπ/12``, ``i0.3``."""
    c = sympy.nsimplify(theta / sympy.pi)
    if c.is_Rational:
        sign = "-" if c < 0 else ""
        p, q = abs(c.p), c.q
        return f"{sign}{'' if p == 1 else p}iπ" + ("" if q == 1 else f"/{q}")
    value = float(theta)
    return f"{'-' if value < 0 else ''}i{abs(value):.4g}"


def _exp_terms(expr):
    """``[(coefficient, angle)]`` when *expr* is a sum of terms ``c * exp(I * theta)``, else None."""
    terms = []
    for term in sympy.Add.make_args(sympy.sympify(expr)):
        coef, rest = term.as_coeff_Mul()
        if rest == 1:
            terms.append((coef, sympy.Integer(0)))
        elif isinstance(rest, sympy.exp):
            theta = sympy.simplify(rest.args[0] / sympy.I)
            if not theta.is_real:
                return None
            terms.append((coef, theta))
        elif rest == sympy.I:
            terms.append((coef, sympy.pi / 2))
        else:
            return None
    return terms


def _number(x: float, digits: int) -> str:
    text = f"{x:.{digits}g}"
    return "0" if text in ("0", "-0") else text


def _polar(z: complex, digits: int) -> str:
    scale = max(1.0, abs(z))
    if abs(z) <= 1e-12 * scale:
        return "0"
    if abs(z.imag) <= 1e-12 * scale:
        return _number(z.real, digits)
    return f"{_number(abs(z), digits)}∠{cmath.phase(z):.{digits}g}"


def format_entry(value, *, style: str = "exact", digits: int = 4) -> str:
    """One matrix entry as short text.

    >>> import sympy
    >>> format_entry(15 * sympy.exp(sympy.I * sympy.pi / 4))
    '15e^(iπ/4)'
    >>> format_entry(-15 * sympy.exp(sympy.I * sympy.pi / 4) - 10 * sympy.exp(-sympy.I * sympy.pi / 12))
    '-15e^(iπ/4) - 10e^(-iπ/12)'
    >>> format_entry(0.5 + 0.7j, style="polar")
    '0.8602∠0.9505'
    """
    if isinstance(value, str):
        return value
    if isinstance(value, sympy.Basic):
        if value.free_symbols:
            return str(value)
        if value.is_Rational:
            return str(value)
        terms = _exp_terms(value) if style == "exact" else None
        if terms is not None and all(c.is_Rational for c, _ in terms):
            parts = []
            for k, (c, theta) in enumerate(terms):
                mag = "" if abs(c) == 1 and theta != 0 else str(abs(c))
                body = mag if theta == 0 else f"{mag}e^({_exponent(theta)})"
                sign = "-" if c < 0 else "+"
                parts.append((sign if k or c < 0 else "") + body)
            return " ".join(parts).replace("+", "+ ").replace(" -", " - ").lstrip() if len(parts) > 1 else parts[0]
        value = complex(sympy.N(value, 20))
    return _polar(complex(value), digits)


@dataclass(frozen=True)
class MatrixView:
    """A matrix with row and column labels; prints as aligned text and shows as HTML."""

    title: str
    rows: list
    cols: list
    entries: list

    def __str__(self) -> str:
        lw = max((len(r) for r in self.rows), default=0)
        widths = [max([len(c)] + [len(row[j]) for row in self.entries]) for j, c in enumerate(self.cols)]
        head = " " * lw + "  " + "  ".join(c.rjust(w) for c, w in zip(self.cols, widths))
        lines = [head.rstrip()]
        for r, row in zip(self.rows, self.entries):
            lines.append((r.rjust(lw) + "  " + "  ".join(v.rjust(w) for v, w in zip(row, widths))).rstrip())
        return "\n".join(lines)

    def __repr__(self) -> str:
        return str(self)

    def _repr_html_(self) -> str:
        def cell(text):
            text = html.escape(text)
            return re.sub(r"e\^\(([^()]*)\)", r"e<sup>\1</sup>", text)

        head = "".join(f"<th>{html.escape(c)}</th>" for c in self.cols)
        body = "".join(
            f"<tr><th>{html.escape(r)}</th>" + "".join(f"<td style='text-align:center'>{cell(v)}</td>" for v in row)
            + "</tr>"
            for r, row in zip(self.rows, self.entries)
        )
        caption = f"<caption>{html.escape(self.title)}</caption>" if self.title else ""
        return f"<table>{caption}<tr><th></th>{head}</tr>{body}</table>"
