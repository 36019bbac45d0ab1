"""Readable matrices: labelled rows and columns, complex entries as ``N e^(i theta)`` or ``r∠phi°``.

The book writes a complex speed in polar form in one way everywhere: ``r∠phi°``, the modulus
``r`` and the direction ``phi`` in **degrees**, always with the degree sign
(:func:`polar_text`; its LaTeX twin :func:`polar_latex`). The exponential form
``r e^(i theta)`` keeps ``theta`` in radians, as Penaud and Alazard write it.
"""

from __future__ import annotations

import cmath
import html
import math
import re
from dataclasses import dataclass

import sympy

__all__ = ["MatrixView", "format_entry", "polar_text", "polar_latex", "exp_text", "PAD"]

PAD = "padding: 0.15em 0.45em"
"""The cell padding of gearlib's HTML tables: entries never run into each other."""
NOWRAP = "; white-space: nowrap"  # a short row label such as "(2, 7)/1" stays on one line


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


def _polar_parts(z: complex, digits: int) -> tuple[str, str] | None:
    """``(modulus, degrees)`` as text, or None when *z* is real (to the tolerance)."""
    scale = max(1.0, abs(z))
    if abs(z.imag) <= 1e-12 * scale:
        return None
    return _number(abs(z), digits), _number(math.degrees(cmath.phase(z)), digits)


def polar_text(z, digits: int = 4) -> str:
    """A complex number as ``r∠phi°`` (angle in degrees, with its sign); a real one as a plain
    number; zero as ``0``.

    >>> polar_text(0.5 + 0.7j)
    '0.8602∠54.46°'
    >>> polar_text(-1.4j, 6), polar_text(-2.5 + 0j)
    ('1.4∠-90°', '-2.5')
    """
    z = complex(z)
    if abs(z) <= 1e-12 * max(1.0, abs(z)):
        return "0"
    parts = _polar_parts(z, digits)
    return _number(z.real, digits) if parts is None else f"{parts[0]}∠{parts[1]}°"


def exp_text(z, digits: int = 4) -> str:
    """A complex number in Penaud and Alazard's exponential form ``r e^(phi i)``, the angle in
    radians (to compare with the paper's printed values); a real one as a plain number.

    >>> exp_text(0.5 - 0.7j)
    '0.8602 e^(-0.9505i)'
    """
    z = complex(z)
    if abs(z) <= 1e-12 * max(1.0, abs(z)) or abs(z.imag) <= 1e-12 * max(1.0, abs(z)):
        return polar_text(z, digits)
    return f"{_number(abs(z), digits)} e^({_number(cmath.phase(z), digits)}i)"


def polar_latex(z, digits: int = 4) -> str:
    """The LaTeX of :func:`polar_text`: ``r\\angle phi^\\circ``.

    >>> print(polar_latex(1.4j))
    1.4\\angle 90^\\circ
    """
    z = complex(z)
    parts = _polar_parts(z, digits)
    if parts is None:
        return polar_text(z, digits)
    return rf"{parts[0]}\angle {parts[1]}^\circ"


def format_entry(value, *, style: str = "exact", digits: int = 4) -> str:
    """One matrix entry as short text.

    >>> import sympy
    >>> format_entry(15 * sympy.exp(sympy.I * sympy.pi / 4))
    '15e^(iπ/4)'
    >>> format_entry(-15 * sympy.exp(sympy.I * sympy.pi / 4) - 10 * sympy.exp(-sympy.I * sympy.pi / 12))
    '-15e^(iπ/4) - 10e^(-iπ/12)'
    >>> format_entry(0.5 + 0.7j, style="polar")
    '0.8602∠54.46°'
    >>> format_entry(0.5 + 0.7j, style="exp")           # the paper's form, radians
    '0.8602 e^(0.9505i)'
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
    if style == "exp":
        return exp_text(complex(value), digits)
    return polar_text(complex(value), digits)


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

        head = "".join(f"<th style='{PAD}'>{html.escape(c)}</th>" for c in self.cols)
        body = "".join(
            f"<tr><th style='{PAD}{NOWRAP if len(r) <= 16 else ''}'>{html.escape(r)}</th>"
            + "".join(f"<td style='{PAD}; text-align: center'>{cell(v)}</td>" for v in row)
            + "</tr>"
            for r, row in zip(self.rows, self.entries)
        )
        caption = f"<caption>{html.escape(self.title)}</caption>" if self.title else ""
        return f"<table>{caption}<tr><th style='{PAD}'></th>{head}</tr>{body}</table>"
