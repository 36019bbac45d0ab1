"""A car differential on the road: wheel speeds from the car's speed and turn radius, every
link's speed, and the frequency spectrum; a widget and its static twin.

The wheels roll without slipping: a car at speed ``v`` turning about a centre at distance
``R`` from the middle of its driven axle (track ``t``, wheel radius ``r``) has wheel speeds
``omega = v (1 -+ t / 2R) / r``, the inner wheel slower. ``R > 0`` is a right turn,
``R < 0`` a left turn, ``R = inf`` straight ahead.

The defaults, ``r = 25/84 m`` (about 0.30 m) and ``t = 1.5 m``, are this book's
assumptions: Penaud and Alazard give only the result, ``omega_3 = 26`` and ``omega_4 = 30``
rad/s at 30 km/h in a right turn, which these values reproduce with ``R = 10.5 m``. Link 3
is then the right (inner) wheel and link 4 the left one. Derived in chapter 4.

>>> import gearlib as gl
>>> gl.wheel_speeds(30, 10.5)           # (left, right) in rad/s
(30.0, 26.0)
>>> gl.wheel_speeds(30)                 # straight ahead
(28.0, 28.0)
"""

from __future__ import annotations

import html
import math
import numbers

import numpy as np

from .matrix import speed_ratio_matrix
from .._common.matview import polar_text
from ..errors import DataFormatError, InputError
from ._spectrum import spectral_lines, spectrum_key
from .frequencies import FrequencyTable, frequency_table, plot_spectrum
from ..mechanism.data import Mechanism
from ..mechanism.widgets import Explorer

__all__ = ["wheel_speeds", "CorneringExplorer", "cornering_explorer", "plot_cornering", "WHEEL_RADIUS", "TRACK"]

WHEEL_RADIUS = 25 / 84
"""Wheel radius (m) that turns 30 km/h into a mean wheel speed of 28 rad/s, as in Penaud and Alazard."""
TRACK = 1.5
"""Track (m) between the driven wheels, this book's assumption."""

DARK = ("#1f4e9a", "#c0392b", "#2e7d32", "#e67e00", "#6a3d9a", "#8c564b", "#00838f", "#ad1457", "#222222",
        "#7a7a00")
"""Curve colours of the static twin: dark enough for thin lines and small labels on white."""


def _positive(value, what) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value) or value <= 0:
        raise InputError(f"{what} must be a positive number, got {value!r}")
    return float(value)


def wheel_speeds(speed, turn_radius=math.inf, *, wheel_radius: float = WHEEL_RADIUS,
                 track: float = TRACK) -> tuple[float, float]:
    """``(omega_left, omega_right)`` in rad/s for a car at *speed* km/h turning with *turn_radius* m.

    *turn_radius* is measured to the middle of the driven axle: positive for a right turn,
    negative for a left turn, ``math.inf`` (the default) for straight ahead. A radius
    smaller than half the track makes the inner wheel turn backwards.
    """
    if isinstance(speed, bool) or not isinstance(speed, numbers.Real) or not math.isfinite(speed):
        raise InputError(f"car speed must be a finite number of km/h, got {speed!r}")
    if isinstance(turn_radius, bool) or not isinstance(turn_radius, numbers.Real) or math.isnan(turn_radius):
        raise InputError(f"turn radius must be a number of metres (math.inf for straight ahead), got {turn_radius!r}")
    if turn_radius == 0:
        raise InputError("turn radius 0 would spin the car about its axle centre; give a non-zero radius in metres")
    r = _positive(wheel_radius, "wheel_radius")
    t = _positive(track, "track")
    mean = speed / 3.6 / r
    k = 0.0 if math.isinf(turn_radius) else t / (2 * turn_radius)
    return mean * (1 + k), mean * (1 - k)


def _plot_link_speeds(solution, ax, title=None):
    """Horizontal bars of every link's speed magnitude, labelled with the value (``r∠phi°``
    when the speed is complex): a compact view for the widget."""
    mech = solution.mechanism
    z = solution.as_complex()
    names = [f"{x} {mech.link(x).name}" if mech.link(x).name else str(x) for x in mech.link_ids]
    colors = ["0.6" if x == solution.constraints.ground else "tab:blue" for x in mech.link_ids]
    y = np.arange(len(names))[::-1]
    ax.barh(y, np.abs(z), color=colors)
    ax.set_yticks(y, names, fontsize=7)
    top = float(np.abs(z).max(initial=0.0)) or 1.0
    for yy, v in zip(y, z):
        text = polar_text(v if abs(v.imag) > 1e-9 * max(1.0, abs(v)) else v.real, 4)
        ax.text(abs(v) + 0.02 * top, yy, text, va="center", fontsize=7)
    ax.set_xlim(0, top * 1.45)
    ax.set_xlabel("|ω| (rad/s)")
    ax.set_title(title or "speeds")
    return ax


class CorneringExplorer(Explorer):
    """Car speed and turn radius -> wheel speeds -> every link's speed (Penaud's
    ``Omega = Omega_0 Lambda``) -> the frequency spectrum.

    :meth:`update` computes and redraws without a browser (it is what the sliders call);
    display the object (or its :attr:`widget`) in JupyterLab. Static twin: :func:`plot_cornering`.
    The key of the numbered spectral lines is in :attr:`text` (HTML), beside the picture.
    """

    html_text = True

    def __init__(self, mech: Mechanism | None = None, *, left=4, right=3, ground=1, wheel_radius=WHEEL_RADIUS,
                 track=TRACK, convention="standard"):
        from .. import catalog

        self.mechanism = catalog.car_differential() if mech is None else mech
        m = self.mechanism
        self.left, self.right, self.ground = m.resolve(left), m.resolve(right), m.resolve(ground)
        self.wheel_radius = _positive(wheel_radius, "wheel_radius")
        self.track = _positive(track, "track")
        self.convention = convention
        # Omega_0, normalised to the two wheels: every link's speed is Omega_0 @ [omega_right, omega_left]
        self.ratios = speed_ratio_matrix(m, zero_speed=[self.ground], normalize_to=[self.right, self.left])
        self._start()
        self.table: FrequencyTable | None = None
        self.speeds = None

    def compute(self, speed=30.0, turn_radius=10.5, turn="right"):
        """The solution (every link's speed) and the frequency table at one operating point."""
        from ..mechanism.kinematics import Constraints, Solution

        radius = self._signed_radius(turn_radius, turn)
        wl, wr = wheel_speeds(speed, radius, wheel_radius=self.wheel_radius, track=self.track)
        omega = self.ratios @ np.array([wr, wl])
        values = tuple(complex(z) if abs(z.imag) > 1e-12 * max(1.0, abs(z)) else float(z.real) for z in omega)
        cons = Constraints.build(self.mechanism, self.ground, {self.right: wr, self.left: wl})
        sol = Solution(self.mechanism, cons, values, "nullspace", self.ratios.shape[1])
        table = frequency_table(self.mechanism, sol, convention=self.convention)
        return sol, table

    @staticmethod
    def _signed_radius(turn_radius, turn):
        if turn not in ("left", "right", "straight"):
            raise InputError(f"turn must be 'left', 'right' or 'straight', got {turn!r}")
        if turn == "straight":
            return math.inf
        r = _positive(turn_radius, "turn radius")
        return r if turn == "right" else -r

    def update(self, speed=30.0, turn_radius=10.5, turn="right") -> bytes:
        """Recompute for this car speed (km/h), turn radius (m) and turn (left, right,
        straight) and redraw; returns the PNG."""
        sol, table = self.compute(speed, turn_radius, turn)
        self.speeds, self.table = sol, table
        wl, wr = sol[self.left], sol[self.right]
        where = "straight ahead" if turn == "straight" else f"{turn} turn, radius {turn_radius:g} m"
        summary = f"{speed:g} km/h, {where}: left wheel {wl:.4g} rad/s, right wheel {wr:.4g} rad/s"
        # the key of the numbered lines is text beside the picture (HTML), not drawn into it
        key = "\n".join(spectrum_key(spectral_lines(table)))
        # left-aligned: in the book the widget sits in a centred figure
        style = "font-size: 11px; line-height: 1.2; text-align: left"
        self.text = f"{html.escape(summary)}<pre style='{style}'>{html.escape(key)}</pre>"
        if self._canvas is None:
            from ..mechanism.widgets import Canvas

            self._canvas = Canvas((7.6, 3.6), dpi=72, margins=(0.145, 0.98, 0.15, 0.9), panels=2,
                                  width_ratios=[1, 1.5], wspace=0.25, keep_axes=True, stable_limits=True)
        self.image = self._canvas.png(lambda ax: _plot_link_speeds(sol, ax, "speeds, frame fixed"),
                                      lambda ax: plot_spectrum(table, ax=ax, key=False, title="contact frequencies"))
        self._show()
        return self.image

    def controls(self, w) -> list:
        self._speed = w.FloatSlider(value=30, min=0, max=130, step=5, description="km/h", continuous_update=False)
        self._radius = w.FloatLogSlider(value=10.5, base=10, min=0.6, max=3, step=0.02, description="radius (m)",
                                        continuous_update=False)
        self._turn = w.ToggleButtons(options=["left", "straight", "right"], value="right", description="turn")
        for s in (self._speed, self._radius, self._turn):
            s.observe(lambda change: self.update(self._speed.value, self._radius.value, self._turn.value), "value")
        return [w.HBox([self._speed, self._radius]), self._turn]


def cornering_explorer(mech: Mechanism | None = None, **kwargs) -> CorneringExplorer:
    """A widget: car speed and turn radius sliders; every link's speed and the frequency
    spectrum of the car differential. Static twin: :func:`plot_cornering`."""
    return CorneringExplorer(mech, **kwargs)


def plot_cornering(mech: Mechanism | None = None, *, speed=30.0, curvatures=None, what="frequencies", ax=None,
                   left=4, right=3, ground=1, wheel_radius=WHEEL_RADIUS, track=TRACK, mark=1 / 10.5,
                   convention="standard", title=None):
    """The widget's static twin: every frequency (``what="frequencies"``) or every link's
    speed magnitude (``what="speeds"``) against the curvature ``1/R`` of the turn at a fixed
    car speed; negative curvature is a left turn. Lines that coincide over the whole sweep
    are drawn once, with their labels joined. ``mark`` is a curvature to highlight."""
    from ._spectrum import group_label
    from ..mechanism.plot import _axes

    if what not in ("frequencies", "speeds"):
        raise DataFormatError(f"what must be 'frequencies' or 'speeds', got {what!r}")
    explorer = CorneringExplorer(mech, left=left, right=right, ground=ground, wheel_radius=wheel_radius,
                                 track=track, convention=convention)
    m = explorer.mechanism
    ks = np.linspace(-0.15, 0.15, 61) if curvatures is None else np.asarray(curvatures, dtype=float)
    columns, labels = [], None
    for k in ks:
        radius = math.inf if k == 0 else 1 / k
        wl, wr = wheel_speeds(speed, radius, wheel_radius=explorer.wheel_radius, track=explorer.track)
        omega = explorer.ratios @ np.array([wr, wl])
        if what == "speeds":
            columns.append(np.abs(omega))
            labels = labels or [f"{x} {m.link(x).name}" if m.link(x).name else str(x) for x in m.link_ids]
        else:
            table = frequency_table(m, omega, convention=convention)
            columns.append(table.frequencies())
            labels = labels or [[r] for r in table.rows]
    data = np.array(columns)
    ax = _axes(ax, figsize=(7.5, 4.2))
    drawn: list[tuple[np.ndarray, list]] = []
    for j, label in enumerate(labels):
        y = data[:, j]
        for yy, members in drawn:
            if np.allclose(y, yy, rtol=1e-9, atol=1e-9):
                members.append(label)
                break
        else:
            drawn.append((y, [label]))
    ends = []
    colors = DARK
    for y, members in drawn:
        if np.all(y < 1e-9):
            continue
        if what == "speeds":
            text = ", ".join(members)
        else:
            text = group_label([r for rows in members for r in rows])
        bearing = what == "frequencies" and members[0][0].kind not in ("mesh", "tooth")
        color = colors[len(ends) % len(colors)]
        shown = np.where(y > 1e-9, y, np.nan)
        ax.plot(ks, shown, color=color, linewidth=1.6, linestyle="--" if bearing else "-")
        end = int(np.nanargmax(np.where(np.isnan(shown), -np.inf, ks)))
        ends.append((ks[end], shown[end], text if len(text) < 40 else text[:39] + "…", color))
    if what == "frequencies":
        ax.set_yscale("log")
    if mark is not None:
        ax.axvline(mark, color="0.5", linestyle=":", linewidth=1)
        ax.annotate(f"R = {1 / mark:.3g} m", xy=(mark, 1.0), xycoords=("data", "axes fraction"), xytext=(2, -2),
                    textcoords="offset points", fontsize=8, color="0.35", ha="left", va="top")
    ax.set_xlabel("curvature 1/R of the turn (1/m); < 0 left, > 0 right")
    ax.set_ylabel("frequency (rad/s)" if what == "frequencies" else "|ω| (rad/s)")
    ax.set_title(title if title is not None else f"{what} of {m.name} at {speed:g} km/h"
                 + ("; dashed: bearing lines" if what == "frequencies" else ""), fontsize=10)
    _label_ends(ax, ends, fontsize=8)
    return ax


def _label_ends(ax, ends, fontsize=8.0):
    """Name every curve at its right end, in the margin beside the axes, the labels pushed
    apart so that none overlaps another (a thin leader joins a moved label to its curve)."""
    fig = ax.figure
    height_in = ax.get_position().height * fig.get_figheight()
    gap = 1.45 * fontsize / 72 / height_in  # one label's height and a little air, in axes fractions
    to_axes = ax.transAxes.inverted()
    spots = []
    for x, y, text, color in ends:
        _, fy = to_axes.transform(ax.transData.transform((x, y)))
        spots.append([fy, fy, text, color])
    spots.sort(key=lambda s: s[0])
    # push apart: upwards from the bottom, then back down from the top if the column overflows
    for k in range(1, len(spots)):
        spots[k][1] = max(spots[k][1], spots[k - 1][1] + gap)
    top = 1.0
    for k in range(len(spots) - 1, -1, -1):
        spots[k][1] = min(spots[k][1], top)
        top = spots[k][1] - gap
    for fy, ly, text, color in spots:
        ax.annotate(text, xy=(1.0, fy), xycoords="axes fraction", xytext=(1.06, ly), textcoords="axes fraction",
                    fontsize=fontsize, color=color, va="center", ha="left", annotation_clip=False,
                    arrowprops={"arrowstyle": "-", "color": color, "lw": 0.7, "shrinkA": 0, "shrinkB": 1})
