"""Automatic transmissions: every gear's ratio by unit-by-unit propagation.

An operating mode (a *gear* of the transmission) says which link is held (the ground, or
brakes), which links a clutch joins, the input and the output. :func:`shift_table` finds each
mode's ratio ``theta_out / theta_in`` by propagation through the kinematic units
(:func:`gearlib.propagate`), in numbers and in the ratio symbols, and checks it against
Penaud and Alazard's null-space solver. Liu, Chen and Chang's three gears of Hsieh and Tsai's
transmission are :data:`LIU_CHEN_MODES` (their eqs. (23)-(29), corrected: LC-E5, -E6, -E7).
Derived in chapter 3.

>>> import gearlib as gl
>>> table = gl.shift_table(gl.catalog.load("liu_chen_transmission"), gl.transmission.LIU_CHEN_MODES)
>>> [(row.mode.name, row.ratio) for row in table.rows]
[('1st', Fraction(5, 6)), ('2nd', Fraction(15, 17)), ('3rd', Fraction(9, 5))]
>>> all(row.agrees for row in table.rows)
True
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property

from ..errors import DataFormatError
from .relation import Propagation, propagate
from ..mechanism.kinematics import format_value
from ..mechanism.data import Mechanism
from ..mechanism._accept import takes_mechanism

__all__ = ["OperatingMode", "ModeResult", "ShiftTable", "operating_modes", "shift_table", "plot_mode_sweep",
           "LIU_CHEN_MODES"]

LIU_CHEN_MODES = {"1st": (5, 2, 8), "2nd": (1, 2, 8), "3rd": (1, 4, 8)}
"""Liu, Chen and Chang's gears of the transmission, as ``[ground, input, output]``."""


@dataclass(frozen=True)
class OperatingMode:
    """One gear: ground, input and output (links or pairs ``(u, v)``), brakes and clutches."""

    name: str
    ground: object
    input: object
    output: object
    held: tuple = ()
    joined: tuple = ()

    def __str__(self) -> str:
        extra = ""
        if self.held:
            extra += f", brakes {', '.join(map(str, self.held))}"
        if self.joined:
            extra += f", clutches {', '.join(f'{u}-{v}' for u, v in self.joined)}"
        return f"{self.name}: ground {self.ground}, input {self.input}, output {self.output}{extra}"


def operating_modes(modes) -> list[OperatingMode]:
    """Read modes given as ``{name: [G, I, O]}``, ``{name: {"ground": .., "input": .., "output": ..,
    "held": [..], "joined": [[u, v], ..]}}`` or a list of such mappings with a ``name``."""
    if isinstance(modes, Mapping):
        items = list(modes.items())
    elif isinstance(modes, Sequence) and not isinstance(modes, (str, bytes)):
        items = []
        for i, m in enumerate(modes):
            if isinstance(m, OperatingMode):
                items.append((m.name, m))
            elif isinstance(m, Mapping):
                items.append((m.get("name", f"mode {i + 1}"), m))
            else:
                raise DataFormatError(f"operating mode {i + 1}: expected a mapping with ground, input, output")
    else:
        raise DataFormatError(f"operating modes must be a mapping or a list, got {type(modes).__name__}")
    out = []
    for name, m in items:
        if isinstance(m, OperatingMode):
            out.append(m)
        elif isinstance(m, Mapping):
            unknown = set(m) - {"name", "ground", "input", "output", "held", "joined"}
            if unknown:
                raise DataFormatError(f"operating mode {name!r}: unknown field {sorted(unknown)[0]!r}; "
                                      "use ground, input, output, held, joined")
            for key in ("ground", "input", "output"):
                if key not in m:
                    raise DataFormatError(f"operating mode {name!r}: missing {key!r}")
            joined = tuple(tuple(p) for p in m.get("joined", ()))
            out.append(OperatingMode(str(name), m["ground"], m["input"], m["output"], tuple(m.get("held", ())),
                                     joined))
        elif isinstance(m, Sequence) and len(m) == 3 and not isinstance(m, str):
            out.append(OperatingMode(str(name), *m))
        else:
            raise DataFormatError(f"operating mode {name!r}: expected [ground, input, output] or a mapping, got {m!r}")
    return out


@dataclass(frozen=True, eq=False)
class ModeResult:
    """One row of a shift table: the mode, its propagation and the null-space check."""

    mode: OperatingMode
    propagation: Propagation

    @property
    def ratio(self):
        return self.propagation.ratio

    @cached_property
    def expression(self):
        """The ratio in the gear-ratio symbols ``e_a_b``."""
        return next(iter(self.propagation.symbolic().values()))

    @cached_property
    def nullspace(self) -> complex:
        return complex(next(iter(self.propagation.reference("nullspace").values())))

    @property
    def agrees(self) -> bool:
        """Propagation and null space agree to 1e-9 (relative)."""
        r = complex(self.ratio)
        return abs(r - self.nullspace) <= 1e-9 * max(1.0, abs(r))


@dataclass(frozen=True, eq=False)
class ShiftTable:
    """Every operating mode's ratio, by propagation and by the null space."""

    mechanism: Mechanism
    rows: tuple

    def to_json(self) -> dict:
        return {"mechanism": self.mechanism.name, "modes": [
            {"name": r.mode.name, "ground": r.mode.ground, "input": r.mode.input, "output": r.mode.output,
             "ratio": str(r.ratio), "nullspace": r.nullspace.real, "expression": str(r.expression)}
            for r in self.rows]}

    def __str__(self) -> str:
        lines = [f"operating modes of {self.mechanism.name!r}:"]
        for r in self.rows:
            lines.append(f"  {r.mode}: ratio {format_value(r.ratio, 10)} (null space {r.nullspace.real:.10g})")
        return "\n".join(lines)

    def _repr_pretty_(self, p, cycle):
        """IPython's text/plain (the PDF book, a terminal): the table of :meth:`__str__`, not the
        dataclass fields."""
        p.text(str(self))

    def _repr_html_(self) -> str:
        body = "".join(
            f"<tr><td>{r.mode.name}</td><td>{r.mode.ground}</td><td>{r.mode.input}</td><td>{r.mode.output}</td>"
            f"<td>{format_value(r.ratio, 8)}</td><td>{r.nullspace.real:.8g}</td>"
            f"<td>{'yes' if r.agrees else 'NO'}</td></tr>" for r in self.rows)
        return ("<table><tr><th>gear</th><th>ground</th><th>input</th><th>output</th><th>ratio (units)</th>"
                f"<th>ratio (null space)</th><th>agree</th></tr>{body}</table>")


@takes_mechanism
def shift_table(mech: Mechanism, modes=None, **options):
    """The shift table of a transmission.

    Without *modes*: the gears of the mechanism's own ``schedule`` (its brakes, clutches and
    gears as data), with ratios, steps and spread, link and slip speeds, efficiencies and power
    flow, and every combination of elements classified: a
    :class:`~gearlib.gains.ScheduleTable` (options ``eta``, ``k``, ``efficiency``, ``ground``,
    ``input``, ``output``: see :func:`gearlib.gains.schedule_table`).

    With *modes* (each a ground, input, output and optional held and joined links, as Liu,
    Chen and Chang give their gears): each mode's ratio ``theta_out / theta_in`` by unit-by-unit
    propagation, with the null-space solution beside it (see the module documentation), a
    :class:`~gearlib.gains.ShiftTable`.
    """
    if modes is None:
        from .schedule import schedule_table

        unknown = [k for k in options if k not in ("eta", "k", "efficiency", "ground", "input", "output")]
        if unknown:
            raise DataFormatError(f"shift_table: unknown option {unknown[0]!r}; the options are eta, k, efficiency, "
                                  "ground, input, output")
        return schedule_table(mech, **options)
    if options:
        raise DataFormatError(f"shift_table with operating modes takes no options; got {', '.join(options)}")
    rows = []
    for m in operating_modes(modes):
        prop = propagate(mech, m.output, [m.input], ground=m.ground, held=m.held, joined=m.joined)
        rows.append(ModeResult(m, prop))
    return ShiftTable(mech, tuple(rows))


@takes_mechanism
def plot_mode_sweep(mech: Mechanism, modes, *, pair, gear, values, ax=None, title=None, concentric: bool = False):
    """Every mode's ratio as the tooth number of one gear varies: the static twin of
    :func:`gearlib.gains.transmission_explorer`. ``pair`` names a gear pair, ``gear``
    the gear of that pair whose tooth number takes each of ``values``. Tooth numbers with
    which a planetary set cannot be assembled (:func:`gearlib.assembly_conditions`) are drawn
    as open markers. With ``concentric=True`` the gear is a sun or a ring and its planets follow
    it (:func:`gearlib.with_concentric_teeth`), so that every set stays concentric."""
    from ..mechanism.assembly import assembly_conditions
    from ..mechanism.plot import _axes

    ax = _axes(ax, figsize=(6.0, 3.4))
    gp, _ = mech.gear_pair(*pair)
    gear = mech.resolve(gear)
    values = list(values)
    modes = operating_modes(modes)
    curves = {m.name: [] for m in modes}
    fits = []
    for n in values:
        if concentric:
            from ..mechanism.assembly import with_concentric_teeth

            variant = with_concentric_teeth(mech, {gear: n})
        else:
            teeth = (n, gp.teeth[1]) if gear == gp.gears[0] else (gp.teeth[0], n)
            variant = mech.with_gear_pair(gp.gears, teeth=teeth)
        fits.append(all(c.ok for c in assembly_conditions(variant)))
        table = shift_table(variant, modes)
        for row in table.rows:
            curves[row.mode.name].append(float(row.ratio))
    for name, ys in curves.items():
        line, = ax.plot(values, ys, marker="o", markersize=3, label=name)
        bad = [(x, y) for x, y, ok in zip(values, ys, fits) if not ok]
        if bad:
            ax.plot(*zip(*bad), linestyle="none", marker="o", markersize=5, markerfacecolor="white",
                    markeredgecolor=line.get_color())
    if not all(fits):
        ax.plot([], [], linestyle="none", marker="o", markersize=5, markerfacecolor="white", markeredgecolor="0.3",
                label="does not assemble")
    ax.axvline(gp.teeth[gp.gears.index(gear)], color="0.6", linestyle=":", linewidth=1)
    ax.axhline(0, color="black", linewidth=0.8)
    ax.set_xlabel(f"teeth of gear {gear} in pair {gp.label}" + (" (its planets follow)" if concentric else ""))
    ax.set_ylabel("ratio output / input")
    ax.legend(fontsize=8)
    ax.set_title(title if title is not None else f"gears of {mech.name}", fontsize=10)
    return ax
