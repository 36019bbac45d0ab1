"""Condition monitoring: the fault frequencies a vibration engineer reads off a gearbox.

:func:`~gearlib.fault_table` turns a mechanism at one operating point into the lines a
spectrum may show, per *fault* rather than per contact, in Hz, rpm (cycles per minute) and
orders of a reference shaft:

* **shaft** lines, 1x each link relative to the housing (the ground);
* **gear mesh** frequencies ``GMF = N_i |omega_i - omega_k|`` (relative to the carrier
  ``k``), their harmonics and sidebands +/- k x each gear's speed relative to the carrier;
* per **planetary set** (:func:`~gearlib.planetary_sets`): the planet-pass frequency
  ``N |omega_c|``, the local fault frequencies of the sun ``N |omega_s - omega_c|``, of a
  planet on one flank ``|omega_p - omega_c|`` and on both flanks ``2 |omega_p - omega_c|``,
  of the ring ``N |omega_r - omega_c|``, each with the sidebands it puts around the mesh.
  With the ring fixed, McFadden and Smith (1985) showed that at a sensor on the ring only
  multiples of the planet-pass frequency survive: the planet-pass sidebands are that comb,
  and a mesh harmonic ``m GMF`` itself cancels unless ``N`` divides ``m Z_ring``;
* **hunting-tooth** ``GMF / lcm(Z1, Z2)`` and **assembly-phase** ``GMF / gcd(Z1, Z2)``
  frequencies from the tooth numbers' common factors;
* **bearing** defect lines, convention named: BPFO, BPFI, FTF (cage relative to the outer
  race), BSF (ball spin; MATLAB's ``Fb``) and 2 x BSF, the rolling-element defect rate (a
  ball defect strikes both races once per spin: the "rolling element" multiplier bearing
  rigs publish, 4.7135 for the SKF 6205 of the Case Western Reserve data). The ring that
  turns relative to the load (the shaft's ring in a housing, a planet's outer ring on its
  pin) carries sidebands +/- k x f_r, the rolling element +/- k x the cage speed.

Speeds carry their unit: ``inputs={1: "1480rpm"}``, ``"24.7Hz"``, ``"155rad/s"``.

>>> import gearlib as gl
>>> table = gl.fault_table(gl.catalog.load("planetary_stage"), inputs={1: "1480rpm"})
>>> [(r.name, round(r.frequency, 3)) for r in table.select(family="sun fault")]
[('sun 1 local fault', 62.965)]
>>> round(table.reference_hz, 4), table.input_unit
(24.6667, 'rpm')
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass, field

from . import _faults
from ._faults import FAMILIES
from ._units import convert_inputs, to_hz, unit_name
from .bearings import with_bearings
from .planetary import planetary_sets
from ..errors import DataFormatError, InputError
from ..mechanism.data import Mechanism
from ..mechanism._accept import as_mechanism

__all__ = ["FaultLine", "FaultTable", "fault_table", "plot_fault_map", "FAMILIES"]



@dataclass(frozen=True)
class FaultLine:
    """One line of a :class:`~gearlib.FaultTable`.

    ``family`` is one of ``gl.adjacency.FAMILIES``; ``kind`` names the line (``GMF``, ``BPFO``,
    ``2xBSF``, ``sideband``, ...); ``frequency`` is in Hz and ``order`` in orders of the
    reference shaft; ``harmonic`` is ``m`` of ``m x`` the fundamental; a sideband has
    ``sideband`` = ``k`` (negative below), ``spacing`` (Hz) and ``centre``, the name of the
    line it sits beside; a centre line lists in ``modulation`` the ``(name, spacing)`` of
    the sidebands it carries.
    """

    family: str
    kind: str
    name: str
    label: str
    frequency: float
    order: float
    harmonic: int = 1
    sideband: int = 0
    spacing: float | None = None
    centre: str | None = None
    modulation: tuple = ()
    links: tuple = ()
    bearing: str | None = None
    note: str = ""

    @property
    def rpm(self) -> float:
        """The frequency in cycles per minute."""
        return 60.0 * self.frequency

    @property
    def is_fundamental(self) -> bool:
        return self.harmonic == 1 and self.sideband == 0 and self.kind != "sideband"

    def to_dict(self, tolerance: float = 0.0) -> dict:
        return {"family": self.family, "kind": self.kind, "name": self.name, "hz": self.frequency, "rpm": self.rpm,
                "order": self.order, "harmonic": self.harmonic, "sideband": self.sideband,
                "spacing_hz": self.spacing, "centre": self.centre,
                "modulation": [{"name": n, "spacing_hz": s} for n, s in self.modulation],
                "links": list(self.links), "bearing": self.bearing, "note": self.note,
                "low_hz": self.frequency * (1 - tolerance), "high_hz": self.frequency * (1 + tolerance)}


CSV_COLUMNS = ("family", "kind", "name", "hz", "rpm", "order", "harmonic", "sideband", "spacing_hz", "centre",
               "links", "bearing", "low_hz", "high_hz", "note")


@dataclass(frozen=True)
class FaultTable:
    """The fault frequencies of a mechanism at one operating point (see the module text).

    ``lines`` are :class:`FaultLine` rows; ``shafts`` are ``(link, name, Hz, order)`` of
    every link relative to the ground; ``sets`` the :class:`~gearlib.PlanetarySet` found.
    """

    mechanism: Mechanism
    lines: tuple
    shafts: tuple
    sets: tuple
    ground: object
    reference: object
    reference_hz: float
    input_unit: str
    harmonics: int = 1
    sidebands: int = 0
    convention: str = "standard"
    tolerance: float = 0.0
    inputs: tuple = field(default=(), repr=False)

    def __len__(self) -> int:
        return len(self.lines)

    def __iter__(self):
        return iter(self.lines)

    def __getitem__(self, i) -> FaultLine:
        return self.lines[i]

    def select(self, *, family=None, kind=None, link=None, bearing=None, fundamental=None) -> tuple:
        """Lines of one ``family`` or ``kind`` (or a tuple of them), naming ``link``, of one
        ``bearing``; ``fundamental=True`` keeps harmonic 1 without sidebands."""
        fams = (family,) if isinstance(family, str) else family
        kinds = (kind,) if isinstance(kind, str) else kind
        link = None if link is None else self.mechanism.resolve(link)
        return tuple(r for r in self.lines
                     if (fams is None or r.family in fams) and (kinds is None or r.kind in kinds)
                     and (link is None or link in r.links) and (bearing is None or r.bearing == bearing)
                     and (fundamental is None or r.is_fundamental == fundamental))

    def frequencies(self):
        """Every line's frequency in Hz, as a numpy array."""
        import numpy as np

        return np.array([r.frequency for r in self.lines])

    # --------------------------------------------------------------- output
    def to_json(self) -> dict:
        """Plain data: operating point, shafts, planetary sets and lines (the CLI's ``--json``)."""
        return {
            "mechanism": self.mechanism.name, "ground": self.ground, "reference": {
                "link": self.reference, "hz": self.reference_hz, "rpm": 60 * self.reference_hz},
            "input_unit": self.input_unit, "inputs": {str(k): str(v) for k, v in self.inputs},
            "harmonics": self.harmonics, "sidebands": self.sidebands, "convention": self.convention,
            "tolerance": self.tolerance,
            "shafts": [{"link": x, "name": n, "hz": f, "rpm": 60 * f, "order": o} for x, n, f, o in self.shafts],
            "planetary_sets": [{"carrier": s.carrier, "planets": [list(p) for p in s.planets],
                                "central": [{"link": c, "role": r} for c, r in s.roles],
                                "planet_pass_multiple": s.passing, "notes": list(s.notes)} for s in self.sets],
            "lines": [r.to_dict(self.tolerance) for r in self.lines],
        }

    def to_csv(self) -> str:
        """One row per line, with a header (columns ``CSV_COLUMNS``)."""
        out = io.StringIO()
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(CSV_COLUMNS)
        for r in self.lines:
            d = r.to_dict(self.tolerance)
            d["links"] = " ".join(map(str, r.links))
            writer.writerow(["" if d[c] is None else (f"{d[c]:.10g}" if isinstance(d[c], float) else d[c])
                             for c in CSV_COLUMNS])
        return out.getvalue()

    def header(self) -> str:
        ref = f"link {self.reference}" if "/" not in str(self.reference) else str(self.reference)
        return (f"fault frequencies of {self.mechanism.name!r}: {ref} at {self.reference_hz * 60:.6g} rpm = "
                f"{self.reference_hz:.6g} Hz (inputs in {self.input_unit}), ground {self.ground}; orders of {ref}; "
                f"bearings: {self._convention_text()}")

    def _convention_text(self) -> str:
        if self.convention == "paper":
            return "Penaud and Alazard's Table A convention"
        return "BPFO, BPFI, FTF, BSF and 2 x BSF (the rolling-element defect rate)"

    def table(self) -> list[tuple]:
        """Rows as text ``(family, line, Hz, rpm, order, sidebands)``."""
        rows = []
        for r in self.lines:
            mods = ", ".join(f"+/-{s:.5g} ({n})" for n, s in r.modulation)
            if r.spacing is not None:
                mods = f"spacing {r.spacing:.5g}"
            rows.append((r.family, r.name, f"{r.frequency:.5g}", f"{r.rpm:.5g}", f"{r.order:.5g}", mods))
        return rows

    def __str__(self) -> str:
        lines = [self.header(), "", "shaft speeds"]
        w = max([4] + [len(str(x)) for x, *_ in self.shafts])
        n = max([4] + [len(nm) for _, nm, *_ in self.shafts])
        lines.append(f"  {'link':<{w}}  {'name':<{n}}  {'Hz':>10}  {'rpm':>10}  {'order':>9}")
        for x, nm, f, o in self.shafts:
            lines.append(f"  {str(x):<{w}}  {nm:<{n}}  {f:>10.5g}  {60 * f:>10.5g}  {o:>9.5g}")
        if self.sets:
            lines += ["", "planetary sets"] + [f"  {s}" + "".join(f"\n    {t}" for t in s.notes) for s in self.sets]
        rows = self.table()
        head = ("family", "line", "Hz", "rpm", "order", "sidebands")
        widths = [max(len(h), *(len(r[i]) for r in rows)) if rows else len(h) for i, h in enumerate(head)]
        align = "<<>>><"
        lines += ["", "  ".join(f"{h:{a}{wd}}" for h, a, wd in zip(head, align, widths)).rstrip()]
        lines += ["  ".join(f"{c:{a}{wd}}" for c, a, wd in zip(r, align, widths)).rstrip() for r in rows]
        return "\n".join(lines)

    def __repr__(self) -> str:
        return f"<FaultTable {self.mechanism.name!r}: {len(self.lines)} lines, reference {self.reference_hz:.6g} Hz>"

    def _repr_html_(self) -> str:
        import html

        body = "".join("<tr>" + "".join(f"<td style='text-align:{a}'>{html.escape(x)}</td>" for x, a in
                                         zip(r, ("left", "left", "right", "right", "right", "left"))) + "</tr>"
                       for r in self.table())
        return (f"<table><caption>{html.escape(self.header())}</caption><tr><th>family</th><th>line</th>"
                f"<th>Hz</th><th>rpm</th><th>order</th><th>sidebands</th></tr>{body}</table>")

    def plot(self, ax=None, **kwargs):
        """The spectrum map, see :func:`~gearlib.plot_fault_map`."""
        return plot_fault_map(self, ax=ax, **kwargs)


def _count(value, what) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= 50:
        raise InputError(f"{what} must be a whole number from 0 to 50, got {value!r}")
    return value


def fault_table(mech, speeds=None, *, ground=None, inputs=None, unit=None, reference=None, bearings=None,
                harmonics: int = 1, sidebands: int = 0, convention: str = "standard", tolerance: float = 0.0,
                method: str = "exact", held=(), joined=()) -> FaultTable:
    """The fault frequencies of *mech* at one operating point (see the module documentation).

    Parameters
    ----------
    mech : Mechanism, or a :class:`~gearlib.Solution` (its mechanism and speeds are used)
    speeds : Solution, optional
        Speeds already solved, in *unit*; by default they are solved from *inputs*.
    ground, inputs, method, held, joined
        As for :func:`gearlib.speeds`; an input may carry its unit (``"1480rpm"``,
        ``"24.7Hz"``, ``"155rad/s"``).
    unit : {"Hz", "rpm", "rad/s"}, optional
        The unit of bare numbers (default rad/s, the unit of the speeds elsewhere in gearlib).
    reference : link id or ``"u/v"``, optional
        The shaft whose orders are given (default: the first input).
    bearings : bearings to use instead of the mechanism's (see :func:`~gearlib.with_bearings`).
    harmonics : int
        Harmonics ``1..harmonics`` of every fundamental line.
    sidebands : int
        Sidebands ``+/- 1..sidebands`` around every harmonic that carries a modulation.
    convention : {"standard", "paper"}
        Bearing lines: BPFO, BPFI, FTF, BSF and 2 x BSF, or Penaud and Alazard's Table A.
    tolerance : float
        Relative speed uncertainty; each line gets a band ``f (1 +/- tolerance)``.
    """
    from ..mechanism.kinematics import Solution, speeds as solve

    if isinstance(mech, Solution):
        mech, speeds = mech.mechanism, mech if speeds is None else speeds
    if not isinstance(mech, Mechanism):
        mech = as_mechanism(mech)
    if convention not in ("standard", "paper"):
        raise DataFormatError(f"convention must be standard or paper, got {convention!r}")
    harmonics = max(1, _count(harmonics, "harmonics"))
    sidebands = _count(sidebands, "sidebands")
    if isinstance(tolerance, bool) or not isinstance(tolerance, (int, float)) or not 0 <= tolerance < 1:
        raise InputError(f"tolerance must be a fraction from 0 to 1 (0.02 for +/- 2 %), got {tolerance!r}")
    if bearings is not None:
        mech = with_bearings(mech, bearings)
    if speeds is None:
        values, unit, factor = convert_inputs(inputs if inputs is not None else None, unit)
        if values is not None and not isinstance(values, dict):
            raise InputError("inputs must be a mapping {link: speed}, e.g. {1: '1480rpm'}")
        speeds = solve(mech, ground, values, method=method, held=held, joined=joined)
    else:
        if not isinstance(speeds, Solution):
            raise DataFormatError("speeds must be a gl.speeds(...) solution; give inputs= for anything else")
        unit = unit_name(unit) if unit is not None else "rad/s"
        factor = to_hz(unit)
    if speeds.mechanism.link_ids != mech.link_ids:
        raise InputError(f"the solution belongs to {speeds.mechanism.name!r}, not to {mech.name!r}")
    ground = speeds.constraints.ground
    f = float(factor)
    from .frequencies import _complex

    w = {x: _complex(v, x) * f for x, v in speeds.items()}
    ref, ref_hz = _reference(mech, speeds, w, reference)
    sets = planetary_sets(mech, w, ground)
    em = _faults._Emitter(FaultLine, ref_hz, harmonics, sidebands)
    _faults.shaft_lines(em, mech, w, ground, sets)
    _faults.mesh_lines(em, mech, w, ground, sets)
    _faults.planetary_lines(em, mech, w, ground, sets)
    _faults.bearing_lines(em, mech, w, ground, convention)
    order = {fam: i for i, fam in enumerate(FAMILIES)}
    lines = sorted(em.lines, key=lambda r: order.get(r.family, len(order)))
    shafts = tuple((x, _faults.name_of(mech, x), abs(w[x] - w[ground]), abs(w[x] - w[ground]) / ref_hz)
                   for x in mech.link_ids if x != ground)
    given = tuple((f"{u}" if v == ground else f"{u}/{v}", val) for u, v, val in speeds.constraints.inputs)
    return FaultTable(mech, tuple(lines), shafts, sets, ground, ref, ref_hz, unit, harmonics, sidebands, convention,
                      float(tolerance), given)


def _reference(mech, sol, w, reference):
    ground = sol.constraints.ground
    if reference is None:
        if not sol.constraints.inputs:
            raise InputError("no input to take orders of; give reference=LINK")
        u, v, _ = sol.constraints.inputs[0]
        label = u if v == ground else f"{u}/{v}"
    else:
        text = str(reference)
        if "/" in text and text not in map(str, mech.link_ids):
            a, b = text.split("/", 1)
            u, v = mech.resolve(a.strip(), "reference"), mech.resolve(b.strip(), "reference")
            label = f"{u}/{v}"
        else:
            u, v = mech.resolve(reference, "reference"), ground
            label = u
    hz = abs(w[u] - w[v])
    if not hz > 1e-12:
        raise InputError(f"reference {label} does not turn at this operating point; choose another shaft for the "
                         "orders (--reference LINK)")
    return label, hz


def plot_fault_map(table: FaultTable, ax=None, *, families=None, fmin=None, fmax=None, xscale=None, labels=True,
                   title=None, fontsize: float = 7):
    """The spectrum map of a :class:`~gearlib.FaultTable`: one lane per family, a tick per line
    (fundamentals full height, harmonics shorter, sidebands shortest), each sideband
    family's band shaded, labels that never overlap (lines whose label finds no room are
    numbered and named in a key under the axes). The vertical axis carries the families,
    not amplitudes. Returns the axes.

    ``families`` keeps some families; ``fmin``/``fmax`` limit the frequency range (Hz);
    ``xscale`` is ``"log"`` or ``"linear"`` (default: log when the lines span more than a
    factor 30).
    """
    from ._faultmap import plot_fault_map as draw

    return draw(table, ax=ax, families=families, fmin=fmin, fmax=fmax, xscale=xscale, labels=labels, title=title,
                fontsize=fontsize)
