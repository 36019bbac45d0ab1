"""Willis (fundamental-circuit) equations, numeric and symbolic.

Each gear pair ``(a, b)`` with carrier ``c`` gives one equation, the Willis equation of
its fundamental circuit::

    omega_b - omega_c = e_{a,b} (omega_a - omega_c)

(Freudenstein and Yang's fundamental circuit equation; Chen-Yao-Lee eq. (2) writes the
same row as ``w_b - e w_a + (e - 1) w_c = 0``). Derived in chapter 1.

>>> import gearlib as gl
>>> m = gl.catalog.simple_planetary(sun=24, ring=60)
>>> for eq in gl.willis_equations(m):
...     print(eq)
omega_2 - omega_4 = e_1_2*(omega_1 - omega_4)
omega_3 - omega_4 = e_2_3*(omega_2 - omega_4)
>>> print(gl.willis_equations(m, symbolic=False)[1])
omega_3 - omega_4 = 3*(omega_2 - omega_4)/10
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy

from .._common.parse import parse_link_id
from .elements import GearPair
from .data import Mechanism
from ._accept import takes_mechanism

__all__ = ["omega", "WillisEquation", "willis_equations", "willis_matrix", "ratio_symbols"]


def omega(link, relative_to=None) -> sympy.Symbol:
    """The symbol ``omega_u`` (speed of link *u*), or ``omega_u_v`` (of *u* relative to *v*)."""
    for x, what in ((link, "link"), (relative_to, "relative_to")):
        if x is not None or what == "link":
            parse_link_id(x, f"omega: {what}")
    return sympy.Symbol(f"omega_{link}" if relative_to is None else f"omega_{link}_{relative_to}")


@dataclass(frozen=True)
class WillisEquation:
    """The Willis equation of one gear pair: ``lhs = rhs``."""

    pair: GearPair
    lhs: sympy.Expr
    rhs: sympy.Expr

    @property
    def carrier(self):
        return self.pair.carrier

    @property
    def eq(self) -> sympy.Eq:
        return sympy.Eq(self.lhs, self.rhs, evaluate=False)

    @property
    def residual(self) -> sympy.Expr:
        """``lhs - rhs``: zero for speeds that satisfy the equation."""
        return self.lhs - self.rhs

    def _repr_latex_(self) -> str:
        from .display import Formula

        return f"${Formula(self.lhs).latex()} = {Formula(self.rhs).latex()}$"

    def __str__(self) -> str:
        return f"{self.lhs} = {self.rhs}"


@takes_mechanism
def ratio_symbols(mech: Mechanism) -> dict:
    """``{e_a_b symbol: exact ratio}`` for every pair whose ratio is a number."""
    return {gp.symbol: gp.e for gp in mech.gear_pairs if not gp.e.free_symbols}


def _ratio(gp: GearPair, symbolic: bool):
    if symbolic and not gp.e.free_symbols:
        return gp.symbol
    return gp.e


@takes_mechanism
def willis_equations(mech: Mechanism, *, symbolic: bool = True) -> list[WillisEquation]:
    """One :class:`WillisEquation` per gear pair.

    With ``symbolic=True`` every numeric ratio is replaced by its symbol ``e_a_b``
    (ratios that are already expressions are kept).
    """
    out = []
    for gp in mech.gear_pairs:
        a, b = gp.gears
        c = gp.carrier
        e = _ratio(gp, symbolic)
        rhs = sympy.Mul(e, omega(a) - omega(c), evaluate=False) if e.is_number else e * (omega(a) - omega(c))
        out.append(WillisEquation(gp, omega(b) - omega(c), rhs))
    return out


@takes_mechanism
def willis_matrix(mech: Mechanism, *, symbolic: bool = True, ground=None) -> sympy.Matrix:
    """The coefficient matrix of the Willis equations, one row per gear pair.

    Columns follow ``mech.link_ids``; with ``ground`` given its column is deleted (the
    ground's speed is zero), which is Chen, Yao and Lee's matrix ``A`` of eq. (6).
    """
    cols = list(mech.link_ids)
    rows = []
    for gp in mech.gear_pairs:
        a, b = gp.gears
        e = _ratio(gp, symbolic)
        row = [sympy.Integer(0)] * len(cols)
        row[mech.index[b]] += 1
        row[mech.index[a]] += -e
        row[mech.index[gp.carrier]] += e - 1
        rows.append(row)
    matrix = sympy.Matrix(rows) if rows else sympy.zeros(0, len(cols))
    if ground is not None:
        matrix.col_del(mech.index[mech.resolve(ground, "ground")])
    return matrix
