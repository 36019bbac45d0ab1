"""Speeds with their unit: ``"1480rpm"``, ``"24.7Hz"``, ``"155rad/s"`` (used by :mod:`.monitoring`).

A speed given as text may end with a unit; a bare number takes the default unit the caller
names. Every speed is turned into revolutions per second (Hz) with its exact factor:
1/60 for rpm, 1/(2 pi) for rad/s.
"""

from __future__ import annotations

import math
import re
from fractions import Fraction

from .._common.parse import parse_expr, to_fraction
from ..errors import DataFormatError, InputError

UNITS = ("Hz", "rpm", "rad/s")
"""The units a speed may carry."""

_ALIASES = {"hz": "Hz", "rps": "Hz", "1/s": "Hz", "rev/s": "Hz", "rpm": "rpm", "r/min": "rpm", "rev/min": "rpm",
            "1/min": "rpm", "min^-1": "rpm", "cpm": "rpm", "rad/s": "rad/s", "rad/sec": "rad/s", "rad s^-1": "rad/s"}
_SUFFIX = re.compile(r"^(?P<value>.*?)\s*(?P<unit>" + "|".join(
    re.escape(a) for a in sorted(_ALIASES, key=len, reverse=True)) + r")\s*$", re.IGNORECASE)


def unit_name(unit: str, where: str = "unit") -> str:
    """The canonical name (``Hz``, ``rpm``, ``rad/s``) of a unit written any usual way."""
    if not isinstance(unit, str) or unit.strip().lower() not in _ALIASES:
        raise InputError(f"{where}: unknown speed unit {unit!r}; use Hz, rpm or rad/s")
    return _ALIASES[unit.strip().lower()]


def to_hz(unit: str):
    """The factor that turns a speed in *unit* into Hz: 1, 1/60 (exact) or 1/(2 pi) (a float)."""
    unit = unit_name(unit)
    return {"Hz": Fraction(1), "rpm": Fraction(1, 60), "rad/s": 1 / (2 * math.pi)}[unit]


def split_speed(value, where: str = "speed"):
    """``(number, unit)`` from ``"1480rpm"``, ``"24.7 Hz"``, ``"-155rad/s"``, ``26`` or ``"26"``.

    The number is a Fraction when it is rational (``"1480/60"``, ``"24.7"``), else a float;
    *unit* is None when the value carries none.

    >>> split_speed("1480rpm"), split_speed("24.7 Hz"), split_speed(26)
    ((Fraction(1480, 1), 'rpm'), (Fraction(247, 10), 'Hz'), (Fraction(26, 1), None))
    """
    unit = None
    if isinstance(value, str):
        m = _SUFFIX.match(value.strip())
        if m and m.group("value").strip():
            value, unit = m.group("value").strip(), _ALIASES[m.group("unit").lower()]
        elif (tail := re.search(r"[A-Za-z][A-Za-z/^]*$", value.strip())) and tail.group(0) not in ("pi", "E"):
            tail = tail.group(0)
            if tail.lower() in ("inf", "infinity", "nan"):
                raise InputError(f"{where} {value!r} is not a number; a speed must be finite")
            raise InputError(f"{where} {value!r}: unknown unit {tail!r}; write the speed as 1480rpm, 24.7Hz or "
                             "155rad/s (or a bare number)")
    try:
        expr = parse_expr(value, where)
    except DataFormatError as err:
        raise InputError(str(err)) from None
    if expr.free_symbols:
        raise InputError(f"{where} {value!r}: a speed must be a number, optionally with its unit "
                         "(1480rpm, 24.7Hz, 155rad/s)")
    exact = to_fraction(expr)
    if exact is not None:
        return exact, unit
    try:
        z = complex(expr.evalf(30))
    except (TypeError, ValueError):
        raise InputError(f"{where} {value!r} is not a number") from None
    if z.imag != 0 or not math.isfinite(z.real):
        raise InputError(f"{where} {value!r} must be a finite real speed")
    return z.real, unit


def convert_inputs(inputs, default_unit=None):
    """Inputs with units, made ready for ``gl.speeds``.

    Returns ``(values, unit, factor)``: ``values`` the inputs as numbers in one unit
    ``unit``, and ``factor`` the multiplier that turns that unit into Hz. When every input
    has the same unit (or carries none and *default_unit* names it), the speeds are solved
    in that unit, exactly; mixed units are converted to Hz. A bare non-zero number beside
    speeds that carry a unit needs *default_unit*, so that ``1=1480rpm, 4=10`` is not read
    silently as 10 rad/s.
    """
    if inputs is None:
        return None, unit_name(default_unit) if default_unit else "rad/s", to_hz(default_unit or "rad/s")
    if not hasattr(inputs, "items"):
        return inputs, unit_name(default_unit) if default_unit else "rad/s", to_hz(default_unit or "rad/s")
    default = unit_name(default_unit, "unit") if default_unit is not None else None
    parsed = {k: split_speed(v, f"input {k}") for k, v in inputs.items()}
    carried = {u for _, u in parsed.values() if u is not None}
    if not carried:
        unit = default or "rad/s"
        return {k: v for k, (v, _) in parsed.items()}, unit, to_hz(unit)
    for k, (v, u) in parsed.items():
        if u is None and v != 0 and default is None:
            raise InputError(f"input {k} = {inputs[k]!r} has no unit while other inputs do; write it as "
                             f"{inputs[k]}rpm, {inputs[k]}Hz or {inputs[k]}rad/s")
    units = carried | ({default} if default and any(u is None and v != 0 for v, u in parsed.values()) else set())
    if len(units) == 1:
        unit = units.pop()
        return {k: v for k, (v, _) in parsed.items()}, unit, to_hz(unit)
    out = {}
    for k, (v, u) in parsed.items():
        f = to_hz(u or default or "Hz")
        out[k] = v * f if isinstance(f, Fraction) and isinstance(v, Fraction) else float(v) * float(f)
    return out, "Hz", Fraction(1)
