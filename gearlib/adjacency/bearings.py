"""Rolling bearings: defect frequencies, and bearings given apart from a mechanism.

:func:`~gearlib.bearing_frequencies` gives the standard defect frequencies of a bearing from the
speeds of its two rings (see :mod:`gearlib.adjacency.frequencies` for the formulas and Penaud and
Alazard's Table A convention).

A bearings file is YAML (or JSON) with a list of bearings, each a :class:`~gearlib.Bearing`
mapping plus the turning pair it sits in::

    bearings:
      - pair: [1, 7]            # the turning pair (either order)
        name: bearing 1
        pitch_diameter: 54      # D_m, any length unit
        ball_diameter: 5        # d_b, same unit
        balls: 25               # Z
        contact_angle: 15*deg   # radians unless written with deg
        inner: 7                # the link carrying the inner ring

The top level may also be the list itself. Bearings named for a pair replace the bearings
the mechanism holds in that pair; other pairs keep theirs.
"""

from __future__ import annotations

import cmath
import math
import pathlib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass


from .._common.files import parse_text, read_text
from ..errors import DataFormatError, FileFormatError, MechanismError, UnknownLinkError
from ..mechanism.elements import Bearing, TurningPair
from ..mechanism.data import Mechanism
from ..mechanism._accept import takes_mechanism

__all__ = ["BearingFrequencies", "bearing_frequencies", "read_bearings", "load_bearings", "with_bearings"]


def _speed(v, what) -> complex:
    try:
        z = complex(v.evalf(30)) if hasattr(v, "evalf") else complex(v)
    except (TypeError, ValueError):
        raise DataFormatError(f"the speed of the {what} is not a number: {v!r}") from None
    if not (cmath.isfinite(z)):
        raise DataFormatError(f"the speed of the {what} is not finite: {v!r}")
    return z



@dataclass(frozen=True)
class BearingFrequencies:
    """Characteristic frequencies of a rolling bearing for given ring speeds.

    Attributes
    ----------
    relative_speed : float
        ``f_r = |omega_i - omega_e|``, the inner ring relative to the outer ring.
    g : float
        ``d_b cos(alpha) / D_m``.
    balls : int
        The number ``Z`` of balls.
    inner_ring : float
        Defect on the inner ring (BPFI), ``Z |omega_i - omega_c| = (Z/2)(1 + g) f_r``.
    outer_ring : float
        Defect on the outer ring (BPFO), ``Z |omega_e - omega_c| = (Z/2)(1 - g) f_r``.
    ball_spin : float
        The ball's spin relative to the cage (BSF), ``(D_m / 2 d_b)(1 - g^2) f_r``.
    cage : float
        The cage relative to the outer ring (FTF), ``(1 - g) f_r / 2``.
    cage_inner : float
        The cage relative to the inner ring, ``(1 + g) f_r / 2``.
    paper_ball : float
        The ball line in Penaud and Alazard's Table A convention, ``(D_m / (d_b cos alpha))(1 - g^2) f_r``.
    cage_speed : complex
        The cage's own speed, ``((1 - g) omega_i + (1 + g) omega_e) / 2``.
    """

    relative_speed: float
    g: float
    balls: int
    inner_ring: float
    outer_ring: float
    ball_spin: float
    cage: float
    cage_inner: float
    paper_ball: float
    cage_speed: complex

    @property
    def ball_defect(self) -> float:
        """A defect on a ball strikes the inner and the outer ring once per spin: 2 BSF."""
        return 2 * self.ball_spin


def bearing_frequencies(bearing, omega_inner, omega_outer=0.0) -> BearingFrequencies:
    """Defect frequencies of a rolling bearing whose inner ring turns at *omega_inner* and
    outer ring at *omega_outer* (both relative to the same link; complex speeds allowed).

    >>> brg = gl.Bearing(pitch_diameter=40, ball_diameter=8, balls=9)
    >>> f = gl.bearing_frequencies(brg, omega_inner=30)
    >>> f.outer_ring, f.inner_ring, f.ball_spin, f.cage
    (108.0, 162.0, 72.0, 12.0)
    """
    if isinstance(bearing, Mapping):
        bearing = Bearing.from_dict(bearing)
    if not isinstance(bearing, Bearing):
        raise DataFormatError(f"bearing must be a gl.Bearing or a mapping of its fields, got {type(bearing).__name__}")
    wi, wo = _speed(omega_inner, "inner ring"), _speed(omega_outer, "outer ring")
    cos_a = math.cos(float(bearing.contact_angle))
    g = bearing.ball_diameter * cos_a / bearing.pitch_diameter
    fr = abs(wi - wo)
    z = bearing.balls
    cage_speed = ((1 - g) * wi + (1 + g) * wo) / 2
    ratio = bearing.pitch_diameter / bearing.ball_diameter
    return BearingFrequencies(
        relative_speed=fr,
        g=g,
        balls=z,
        inner_ring=z * abs(wi - cage_speed),
        outer_ring=z * abs(wo - cage_speed),
        ball_spin=ratio / 2 * (1 - g * g) * fr,
        cage=abs(cage_speed - wo),
        cage_inner=abs(cage_speed - wi),
        paper_ball=ratio / cos_a * (1 - g * g) * fr,
        cage_speed=cage_speed,
    )


def _pair(value, where):
    if isinstance(value, (str, bytes)) or not isinstance(value, Sequence) or len(value) != 2:
        raise DataFormatError(f"{where}: `pair` must be the two links of a turning pair, e.g. [1, 7]; got {value!r}")
    return tuple(value)


def read_bearings(data, *, where: str = "bearings") -> tuple[tuple[tuple, Bearing], ...]:
    """``((pair, Bearing), ...)`` from plain data (a list, or a mapping with a ``bearings`` list),
    or from ``(pair, Bearing)`` tuples."""
    if isinstance(data, Mapping):
        if "bearings" not in data:
            raise DataFormatError(f"{where}: expected a list of bearings or a mapping with `bearings: [...]`")
        data = data["bearings"]
    if isinstance(data, (str, bytes)) or not isinstance(data, Sequence):
        raise DataFormatError(f"{where}: expected a list of bearings, got {type(data).__name__}")
    out = []
    for i, item in enumerate(data, start=1):
        at = f"{where}, item {i}"
        if isinstance(item, tuple) and len(item) == 2 and isinstance(item[1], (Bearing, Mapping)):
            pair, brg = _pair(item[0], at), item[1]
            brg = brg if isinstance(brg, Bearing) else Bearing.from_dict(brg, at)
        elif isinstance(item, Mapping):
            if "pair" not in item:
                raise DataFormatError(f"{at}: missing `pair: [a, b]`, the turning pair that holds the bearing")
            pair = _pair(item["pair"], at)
            fields = {k: v for k, v in item.items() if k != "pair"}
            brg = Bearing.from_dict(fields, f"{at} (pair {list(pair)})")
        else:
            raise DataFormatError(f"{at}: expected a mapping with `pair` and the bearing's fields, got {item!r}")
        out.append((pair, brg))
    return tuple(out)


def load_bearings(path) -> tuple[tuple[tuple, Bearing], ...]:
    """Read a bearings file (YAML or JSON, format in the module documentation)."""
    path, text = read_text(path, "bearings file")
    data = parse_text(text, str(path)) if text.strip() else None
    if data is None:
        raise FileFormatError(f"{path}: the file is empty; it should list bearings")
    try:
        return read_bearings(data, where=str(path))
    except MechanismError as err:
        raise type(err)(str(err) if str(err).startswith(str(path)) else f"{path}: {err}") from None


@takes_mechanism
def with_bearings(mech: Mechanism, bearings) -> Mechanism:
    """A copy of *mech* whose turning pairs hold the given bearings: a list of
    ``(pair, Bearing)``, a list of mappings with a ``pair`` key, or the path of a bearings
    file (:func:`load_bearings`). The pairs named replace their bearings; the others keep theirs."""
    if isinstance(bearings, (str, pathlib.Path)):
        items = load_bearings(bearings)
    else:
        items = read_bearings(bearings)
    by_pair: dict = {}
    pairs = {frozenset(tp.links): tp for tp in mech.turning_pairs}
    for pair, brg in items:
        a, b = (mech.resolve(x, "link of a bearing's pair") for x in pair)
        key = frozenset((a, b))
        if key not in pairs:
            known = ", ".join(f"({u}, {v})" for u, v in (tp.links for tp in mech.turning_pairs))
            raise UnknownLinkError(
                f"bearing {brg.name + ' ' if brg.name else ''}is in pair ({a}, {b}), which is not a turning pair "
                f"of {mech.name!r}; its turning pairs are {known}"
            )
        if brg.inner is not None and brg.inner not in (a, b):
            raise UnknownLinkError(f"bearing {brg.name + ' ' if brg.name else ''}in pair ({a}, {b}): inner ring "
                                   f"on link {brg.inner}, which is not {a} or {b}")
        by_pair.setdefault(key, []).append(brg)
    tps = tuple(
        TurningPair(tp.links, tp.axis, tuple(by_pair[frozenset(tp.links)])) if frozenset(tp.links) in by_pair else tp
        for tp in mech.turning_pairs
    )
    return mech.replace(turning_pairs=tps)
