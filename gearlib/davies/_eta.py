"""Checks of the efficiency arguments before any analysis: ordinary efficiencies (one number
or ``{(a, b): value}`` per gear pair) and the input torque and speed.

A key that names no gear pair is an error, not a value silently left unused, and every
number must be finite (a NaN torque would make every result NaN).
"""

from __future__ import annotations

import math
import numbers

import sympy

from .._common.parse import parse_expr, shown
from ..errors import DataFormatError, InputError

__all__ = ["check_eta", "check_number"]


def check_number(value, what: str, *, exact: bool = False):
    """A finite number (float, or an exact sympy number/expression when *exact*)."""
    if isinstance(value, bool) or value is None:
        raise DataFormatError(f"{what}: expected a finite number, got {value!r}")
    if isinstance(value, numbers.Real) and not isinstance(value, sympy.Basic):
        if not math.isfinite(float(value)):
            raise DataFormatError(f"{what}: expected a finite number, got {shown(value)}")
        return sympy.nsimplify(value, rational=True) if exact and isinstance(value, float) else value
    expr = parse_expr(value, what)
    if expr.free_symbols:
        if exact:
            return expr
        raise InputError(f"{what}: {shown(value)} is symbolic; give a number (or symbolic=True)")
    if not exact:
        z = complex(sympy.N(expr, 20))
        if z.imag:
            raise DataFormatError(f"{what}: expected a real number, got {shown(value)}")
        return z.real
    return expr


def _check_value(value, what, symbolic):
    if symbolic and not isinstance(value, (bool, numbers.Real)) and value is not None:
        return  # symbols allowed; read later
    if isinstance(value, numbers.Real) and not isinstance(value, (bool, sympy.Basic)):
        v = float(value)  # NaN and infinity fail the range test below
    else:
        v = check_number(value, what)
    if not 0 < v <= 1:
        raise InputError(f"{what}: an ordinary efficiency must be in (0, 1], got {shown(value)}")


def check_eta(mech, eta, *, symbolic=False, names=()) -> None:
    """Refuse an ``eta`` that names no gear pair, or whose values are not efficiencies.

    *names* are the coupling names a key may also be (Davies' network: ``"a"``, ``"b"``, ...)."""
    if eta is None:
        return
    if not isinstance(eta, dict):
        _check_value(eta, "eta", symbolic)
        return
    for key, value in eta.items():
        if isinstance(key, str) and key in names:
            where = f"eta[{key!r}]"
        elif isinstance(key, (tuple, list)) and len(key) == 2:
            a, b = (mech.resolve(x, "eta gear") for x in key)
            try:
                mech.gear_pair(a, b)
            except Exception:  # noqa: BLE001 - the library's UnknownLinkError, re-worded
                pairs = ", ".join(f"({gp.gears[0]}, {gp.gears[1]})" for gp in mech.gear_pairs[:12])
                raise InputError(f"eta: {mech.name!r} has no gear pair between {a} and {b}; its gear pairs are "
                                 f"{pairs}{', ...' if len(mech.gear_pairs) > 12 else ''}") from None
            where = f"eta[({a}, {b})]"
        else:
            raise DataFormatError(f"eta: a key must be a gear pair (a, b){' or a coupling name' if names else ''}, "
                                  f"got {shown(key)}")
        _check_value(value, where, symbolic)
