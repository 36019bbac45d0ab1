"""Contact frequencies: gear meshes, tooth defects and rolling bearings (Penaud and Alazard, Sec. 2.2).

A defect in a contact of a transmission repeats at a frequency fixed by the speeds of
the links in contact; vibration monitoring looks for those lines in the spectrum.

* **Gear pair** ``(i, j)`` on carrier ``k``: the mesh frequency is
  ``|T(i,j)| |omega_i - omega_k| = |T(j,i)| |omega_j - omega_k|`` (teeth meshing per unit
  time), and a defect on one tooth of gear ``i`` meets gear ``j`` at ``|omega_i - omega_k|``,
  with ``N_i`` independent sources. Every speed is taken **relative to the carrier**,
  whatever the carrier is doing: in a planetary gearbox the carrier turns.
* **Rolling bearing** in a turning pair: with ``g = d_b cos(alpha) / D_m`` and
  ``f_r = |omega_i - omega_e|`` the speed of the inner ring relative to the outer ring, the
  cage turns at ``omega_c = ((1 - g) omega_i + (1 + g) omega_e) / 2`` and

  - inner-ring defect (BPFI) ``Z |omega_i - omega_c| = (Z/2)(1 + g) f_r``,
  - outer-ring defect (BPFO) ``Z |omega_e - omega_c| = (Z/2)(1 - g) f_r``,
  - ball spin (BSF) ``(D_m / 2 d_b)(1 - g^2) f_r``; a ball defect strikes both rings, at 2 BSF,
  - cage (FTF) ``|omega_c - omega_e| = (1 - g) f_r / 2``, relative to the outer ring.

  Penaud and Alazard's Table A (``convention="paper"``) lists the ball line as
  ``(D_m / (d_b cos alpha))(1 - g^2) f_r``: ``d_b`` replaced by ``d_b cos alpha`` in the
  prefactor too, 3.5 % above the standard 2 BSF for their bearing (erratum PA-E4).

Frequencies are in the unit of the speeds (rad/s, or Hz when the speeds are in Hz).
Derived in chapter 4.

>>> import gearlib as gl
>>> diff = gl.catalog.car_differential()
>>> table = gl.frequency_table(diff, ground=1, inputs={3: 26, 4: 30})
>>> [(r.kind, gl.number(r.frequency), r.sources) for r in table.select(pair=(2, 7))]
[('mesh', 1820, None), ('tooth', 140, 13), ('tooth', 28, 65)]
>>> [str(gl.number(r.frequency, 4)) for r in table.select(pair=(1, 7))][:5]
['381.3', '318.7', '150', '300', '12.75']
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np
import sympy

from .bearings import BearingFrequencies, bearing_frequencies, load_bearings, read_bearings, with_bearings
from .._common.parse import to_fraction
from ..errors import ConstraintError, DataFormatError, InputError
from ..mechanism.elements import Bearing
from ..mechanism.data import Mechanism
from ..mechanism._accept import as_mechanism

__all__ = [
    "FrequencyRow",
    "FrequencyTable",
    "BearingFrequencies",
    "bearing_frequencies",
    "gear_frequencies",
    "frequency_table",
    "plot_spectrum",
    "load_bearings",
    "read_bearings",
    "with_bearings",
    "CONVENTIONS",
]

CONVENTIONS = ("standard", "paper")


# ---------------------------------------------------------------------------- rows
@dataclass(frozen=True)
class FrequencyRow:
    """One line of a frequency table.

    ``kind`` is ``"mesh"``, ``"tooth"``, ``"inner ring"``, ``"outer ring"``, ``"ball spin"``,
    ``"ball"`` or ``"cage"``; ``sources`` is the number of independent sources of the line
    (teeth of the gear, balls of the bearing), None for a mesh; ``link`` is the gear (or the
    link carrying the ring) the line belongs to; ``bearing`` the bearing's name.
    """

    pair: tuple
    kind: str
    frequency: float | Fraction
    description: str
    sources: int | None = None
    link: object = None
    bearing: str | None = None

    def to_dict(self) -> dict:
        return {"pair": list(self.pair), "kind": self.kind, "frequency": float(self.frequency),
                "description": self.description, "sources": self.sources, "link": self.link,
                "bearing": self.bearing}


# ---------------------------------------------------------------------------- speeds
def _speed_map(mech: Mechanism, speeds) -> tuple[dict, bool]:
    """``{link: speed}`` from a Solution, a mapping or a sequence; and whether it came from
    a Solution (which satisfies the Willis equations by construction)."""
    from ..mechanism.kinematics import Solution

    if isinstance(speeds, Solution):
        if speeds.mechanism.link_ids != mech.link_ids:
            raise InputError(f"the solution belongs to {speeds.mechanism.name!r}, not to {mech.name!r}")
        return dict(zip(mech.link_ids, speeds.values)), True
    if isinstance(speeds, Mapping):
        out = {}
        for k, v in speeds.items():
            out[mech.resolve(k, "speed of link")] = v
        missing = [x for x in mech.link_ids if x not in out]
        if missing:
            raise InputError(f"speeds: no speed for link {missing[0]}; give every link's speed "
                             f"(links are {', '.join(map(str, mech.link_ids))}) or pass gl.speeds(...)")
        return out, False
    if isinstance(speeds, (Sequence, np.ndarray)) and not isinstance(speeds, (str, bytes)):
        values = list(np.asarray(speeds).ravel()) if isinstance(speeds, np.ndarray) else list(speeds)
        if len(values) != len(mech.links):
            raise InputError(f"speeds: {len(values)} values for the {len(mech.links)} links of {mech.name!r}; "
                             "give one per link, in the order of mech.link_ids")
        return dict(zip(mech.link_ids, values)), False
    raise DataFormatError(f"speeds must be a gl.speeds(...) solution, a mapping link -> speed or a list, "
                          f"got {type(speeds).__name__}")


def _exact(v):
    if isinstance(v, Fraction):
        return v
    if isinstance(v, (int, np.integer)) and not isinstance(v, bool):
        return Fraction(int(v))
    if isinstance(v, sympy.Basic):
        return to_fraction(v)
    return None


def _complex(v, link) -> complex:
    try:
        if isinstance(v, sympy.Basic):
            if v.free_symbols:
                raise ConstraintError(f"the speed of link {link} is symbolic ({v}); give numbers")
            return complex(v.evalf(30))
        z = complex(v)
    except (TypeError, ValueError):
        raise DataFormatError(f"the speed of link {link} is not a number: {v!r}") from None
    if not (math.isfinite(z.real) and math.isfinite(z.imag)):
        raise DataFormatError(f"the speed of link {link} is not finite: {v!r}")
    return z


def _abs_diff(w: dict, u, v):
    """``|omega_u - omega_v|``: a Fraction when both speeds are rational, else a float."""
    a, b = _exact(w[u]), _exact(w[v])
    if a is not None and b is not None:
        return abs(a - b)
    return abs(_complex(w[u], u) - _complex(w[v], v))


def _name(mech, link) -> str:
    name = mech.link(link).name
    return f"link {link} ({name})" if name else f"link {link}"


# ---------------------------------------------------------------------------- gear pairs
def gear_frequencies(mech: Mechanism, speeds, *, check: bool = True) -> tuple[FrequencyRow, ...]:
    """Mesh and tooth-defect lines of every gear pair, relative to the pair's carrier.

    *speeds* is a :class:`~gearlib.Solution`, a mapping ``{link: speed}`` or a list in the
    order of ``mech.link_ids``. Speeds given by hand are checked against each pair's Willis
    equation (``check=False`` skips that). A pair given only by its ratio has no mesh line
    (its tooth numbers are unknown).
    """
    w, from_solution = _speed_map(mech, speeds)
    rows = []
    for gp in mech.gear_pairs:
        a, b = gp.gears
        k = gp.carrier
        if check and not from_solution:
            za, zb, zk = (_complex(w[x], x) for x in (a, b, k))
            lhs, rhs = zb - zk, complex(gp.e_value) * (za - zk)
            if abs(lhs - rhs) > 1e-9 * max(1.0, abs(za - zk), abs(zb - zk)):
                raise ConstraintError(
                    f"the speeds do not satisfy the Willis equation of gear pair {gp.label} on carrier {k}; "
                    "compute them with gl.speeds(...)"
                )
        fa, fb = _abs_diff(w, a, k), _abs_diff(w, b, k)
        if gp.teeth is not None:
            na, nb = gp.teeth
            mesh = na * fa
            rows.append(FrequencyRow(gp.gears, "mesh", mesh, f"mesh of gear pair {gp.label} (carrier {k})"))
        else:
            na = nb = None
        rows.append(FrequencyRow(gp.gears, "tooth", fa, f"defect on a tooth of {_name(mech, a)}", na, a))
        rows.append(FrequencyRow(gp.gears, "tooth", fb, f"defect on a tooth of {_name(mech, b)}", nb, b))
    return tuple(rows)


# ---------------------------------------------------------------------------- bearings
def _bearing_rows(mech, w, tp, brg: Bearing, index: int, convention: str) -> list[FrequencyRow]:
    u, v = tp.links
    inner = brg.inner if brg.inner is not None else u
    outer = v if inner == u else u
    name = brg.name or f"bearing {index}"
    f = bearing_frequencies(brg, _complex(w[inner], inner), _complex(w[outer], outer))
    ring = "" if brg.inner is not None else " (inner ring assumed on the first link of the pair)"
    rows = [
        FrequencyRow(tp.links, "inner ring", f.inner_ring,
                     f"defect on the inner ring of {name} ({_name(mech, inner)}){ring}", 1, inner, name),
        FrequencyRow(tp.links, "outer ring", f.outer_ring,
                     f"defect on the outer ring of {name} ({_name(mech, outer)})", 1, outer, name),
    ]
    if convention == "paper":
        rows.append(FrequencyRow(tp.links, "ball", f.paper_ball,
                                 f"defect on a ball of {name} (Table A convention)", brg.balls, None, name))
        return rows
    rows += [
        FrequencyRow(tp.links, "ball spin", f.ball_spin, f"ball spin of {name}", brg.balls, None, name),
        FrequencyRow(tp.links, "ball", f.ball_defect,
                     f"defect on a ball of {name} (2 x ball spin: it strikes both rings)", brg.balls, None, name),
        FrequencyRow(tp.links, "cage", f.cage, f"cage of {name}, relative to the outer ring", 1, None, name),
    ]
    return rows


# ---------------------------------------------------------------------------- the table
@dataclass(frozen=True)
class FrequencyTable:
    """Every contact frequency of a mechanism at one operating point (rows of
    :class:`FrequencyRow`), as data; ``print`` it, show it in a notebook, or ``plot`` it."""

    mechanism: Mechanism
    rows: tuple
    speeds: tuple = field(repr=False, default=())
    unit: str = "rad/s"
    convention: str = "standard"

    def __len__(self) -> int:
        return len(self.rows)

    def __iter__(self):
        return iter(self.rows)

    def __getitem__(self, i) -> FrequencyRow:
        return self.rows[i]

    def select(self, *, kind=None, pair=None, link=None) -> tuple[FrequencyRow, ...]:
        """Rows of one ``kind`` (or a tuple of kinds), one ``pair`` (either order), one ``link``."""
        kinds = (kind,) if isinstance(kind, str) else kind
        out = []
        for r in self.rows:
            if kinds is not None and r.kind not in kinds:
                continue
            if pair is not None and set(r.pair) != {self.mechanism.resolve(x) for x in pair}:
                continue
            if link is not None and r.link != self.mechanism.resolve(link):
                continue
            out.append(r)
        return tuple(out)

    def frequencies(self) -> np.ndarray:
        """The frequency of every row, as floats."""
        return np.array([float(r.frequency) for r in self.rows])

    def table(self, digits: int = 5) -> list[tuple[str, str, str, str]]:
        """Rows as text ``(pair, frequency, description, sources)``, the pair shown once per group."""
        out, last = [], None
        for r in self.rows:
            pair = f"({r.pair[0]}, {r.pair[1]})"
            f = r.frequency
            text = str(f) if isinstance(f, Fraction) and f.denominator == 1 else f"{float(f):.{digits}g}"
            out.append(("" if pair == last else pair, text, r.description, "" if r.sources is None else str(r.sources)))
            last = pair
        return out

    def to_json(self) -> dict:
        """``{"unit", "convention", "speeds": {link: [re, im]}, "rows": [...]}`` (the CLI's ``--json``)."""
        speeds = {str(k): [float(complex(z).real), float(complex(z).imag)]
                  for k, z in zip(self.mechanism.link_ids, self.speeds)}
        return {"unit": self.unit, "convention": self.convention, "speeds": speeds,
                "rows": [r.to_dict() for r in self.rows]}

    def __str__(self) -> str:
        rows = self.table()
        head = ("pair", f"frequency ({self.unit})", "description", "sources")
        widths = [max(len(h), *(len(r[i]) for r in rows)) if rows else len(h) for i, h in enumerate(head)]
        align = "<><>"

        def line(cells):
            return "  ".join(f"{c:{a}{w}}" for c, a, w in zip(cells, align, widths)).rstrip()

        lines = [self.title, line(head)]
        lines += [line(r) for r in rows]
        return "\n".join(lines)

    def __repr__(self) -> str:
        return str(self)

    @property
    def title(self) -> str:
        """``contact frequencies of <name>``, with the bearing convention when the table has
        bearing lines."""
        has_bearings = any(r.kind not in ("mesh", "tooth") for r in self.rows)
        return f"contact frequencies of {self.mechanism.name}" + (
            f" ({self.convention} bearing formulas)" if has_bearings else "")

    def _repr_html_(self) -> str:
        import html

        from .._common.matview import PAD

        body = "".join(
            "<tr>" + "".join(f"<td style='{PAD}; text-align: {a}{'; white-space: nowrap' if k == 0 else ''}'>"
                             f"{html.escape(x)}</td>" for k, (x, a) in
                             enumerate(zip(r, ("left", "right", "left", "right")))) + "</tr>"
            for r in self.table()
        )
        head = "".join(f"<th style='{PAD}'>{html.escape(h)}</th>"
                       for h in ("pair", f"frequency ({self.unit})", "description", "sources"))
        title = self.title
        return f"<table><caption>{html.escape(title[0].upper() + title[1:])}</caption><tr>{head}</tr>{body}</table>"

    def plot(self, ax=None, **kwargs):
        """The table as a spectrum, see :func:`plot_spectrum`."""
        from ._spectrum import plot_spectrum

        return plot_spectrum(self, ax=ax, **kwargs)


def frequency_table(mech: Mechanism, speeds=None, *, ground=None, inputs=None, bearings=None,
                    convention: str = "standard", unit: str = "rad/s", method: str = "exact") -> FrequencyTable:
    """Every contact frequency of *mech*: gear pairs first, then the bearings of each turning pair.

    Parameters
    ----------
    mech : Mechanism (or a :class:`~gearlib.Solution`, whose mechanism and speeds are used)
    speeds : a :class:`~gearlib.Solution`, a mapping ``{link: speed}`` or a list (link order),
        optional; by default they are computed with ``gl.speeds(mech, ground, inputs, method=method)``.
    bearings : bearings to use instead of those the mechanism's turning pairs hold, for the
        pairs they name: a list of ``(pair, Bearing)``, a list of mappings with a ``pair`` key,
        or a file name (see :func:`load_bearings`).
    convention : ``"standard"`` (inner ring, outer ring, ball spin, ball defect, cage) or
        ``"paper"`` (inner ring, outer ring and the ball line of Penaud and Alazard's Table A).
    unit : the unit of the speeds, used in labels.
    """
    from ..mechanism.kinematics import Solution, speeds as solve

    if isinstance(mech, Solution):
        mech, speeds = mech.mechanism, mech if speeds is None else speeds
    if not isinstance(mech, Mechanism):
        mech = as_mechanism(mech)
    if convention not in CONVENTIONS:
        raise DataFormatError(f"convention must be one of {', '.join(CONVENTIONS)}, got {convention!r}")
    if bearings is not None:
        mech = with_bearings(mech, bearings)
    if speeds is None:
        speeds = solve(mech, ground, inputs, method=method)
    rows = list(gear_frequencies(mech, speeds))
    w, _ = _speed_map(mech, speeds)
    for tp in mech.turning_pairs:
        for i, brg in enumerate(tp.bearings, start=1):
            rows += _bearing_rows(mech, w, tp, brg, i, convention)
    values = tuple(_complex(w[x], x) for x in mech.link_ids)
    return FrequencyTable(mech, tuple(rows), values, unit, convention)


def plot_spectrum(table: FrequencyTable, ax=None, *, log=None, kinds=None, key: bool = True, title=None,
                  fontsize: float = 7):
    """The frequency table as a line spectrum; returns the axes.

    One vertical line per distinct frequency, coloured by the kind of its tallest contact
    (mesh, tooth, bearing) and numbered; with ``key=True`` a key beside the axes names the
    contacts producing each line. Lines at zero frequency (contacts that do not move
    relative to each other) are left out. ``log`` uses a logarithmic axis (default: when
    the frequencies span more than a factor 30); ``kinds`` keeps only rows of these kinds.
    """
    from ._spectrum import plot_spectrum as draw

    return draw(table, ax=ax, log=log, kinds=kinds, key=key, title=title, fontsize=fontsize)
