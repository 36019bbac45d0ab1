"""Interactive widgets: thin wrappers that call a plot function when a slider moves.

Each widget has a *static twin*, a plot that shows the same relation without a kernel,
for the HTML book and for printing:

=========================  ===============================================
widget                     static twin
=========================  ===============================================
:func:`speed_explorer`     :func:`plot_speed_sweep`
=========================  ===============================================

A widget draws with a private matplotlib ``Figure`` (:class:`Canvas`, no pyplot state) into
an image, so a slider update is one computation and one small render, and the HTML book can
show the image without a kernel. ``ipywidgets`` is imported only
when a widget is made.
"""

from __future__ import annotations

import math
import struct
import zlib

import numpy as np

from .data import Mechanism
from .kinematics import speeds
from ._accept import takes_mechanism
from .sweep import plot_speed_sweep  # noqa: F401  (the static twin, offered here too)

__all__ = ["Canvas", "Explorer", "SpeedExplorer", "speed_explorer", "plot_speed_sweep", "render_png", "encode_png",
           "with_snapshot"]


class Canvas:
    """A private matplotlib figure that a widget redraws on every update (no pyplot, no
    global matplotlib state).

    :meth:`png` calls one ``draw(ax)`` per panel and returns the image as PNG bytes, ready
    for an ``ipywidgets.Image``. A slider move should cost tens of milliseconds, and most of a
    matplotlib frame is text: tick labels, axis labels, legends. So a frame is drawn in two
    layers (matplotlib's *blitting*):

    * the **background**: axes, ticks, tick and axis labels, spines, and a legend with a fixed
      place. It is rendered once and kept as pixels; it is rendered again only when
      something in it changes (limits, scale, tick positions or labels, axis labels, the
      legend's entries: see ``_background_key``);
    * the **data**: every patch, line, collection and text the draw function added, and the
      titles, drawn on top of the kept background each frame.

    Every frame is made this way, so the same state always gives the same pixels whether the
    background was kept or redrawn (``tests/test_widgets.py`` checks this for every widget).

    ``keep_axes=True`` removes only the drawn artists between frames instead of clearing
    the axes (tick objects survive: cheaper when the draw function does not restyle the
    axes). ``stable_limits=True`` keeps the previous frame's axis limits while the new data
    fit in them and fill at least half of them; data that outgrow them extend them, with
    half the span to spare; data that fill less than half start afresh. The axes stay
    still while a slider moves (which also shows the change better) and the background need
    not be redrawn.
    """

    def __init__(self, figsize=(6.0, 3.2), dpi=80, margins=(0.1, 0.98, 0.22, 0.9), *, panels: int = 1,
                 width_ratios=None, wspace=None, keep_axes: bool = False, stable_limits: bool = False):
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        self.figure = Figure(figsize=figsize, dpi=dpi)
        FigureCanvasAgg(self.figure)
        left, right, bottom, top = margins
        self.figure.subplots_adjust(left=left, right=right, bottom=bottom, top=top, wspace=wspace)
        if panels == 1:
            self.axes = [self.figure.add_subplot()]
        else:
            self.axes = list(self.figure.subplots(1, panels, width_ratios=width_ratios))
        self.ax = self.axes[0]
        self.keep_axes = keep_axes
        self.stable_limits = stable_limits
        self._limits: dict = {}
        self._key = None
        self._background = None
        self.backgrounds_drawn = 0  # how many frames had to render the background (for benchmarks)

    def png(self, *draws) -> bytes:
        """Draw panel *i* with ``draws[i](ax)`` and return the figure as PNG bytes."""
        for draw, ax in zip(draws, self.axes):
            if self.keep_axes:
                for artist in _drawn(ax):
                    artist.remove()
                if ax.get_legend() is not None:
                    ax.get_legend().remove()
                for title in _titles(ax):
                    title.set_text("")
                ax.containers.clear()  # bar containers: a legend would list the old bars again
                ax.relim()  # forget the removed data, so that autoscaling can shrink the limits
            else:
                ax.clear()
            draw(ax)
            if self.stable_limits:
                self._steady(ax)
        return self._render()

    def _steady(self, ax):
        for name in "xy":
            lo, hi = getattr(ax, f"get_{name}lim")()
            log = getattr(ax, f"get_{name}scale")() == "log" and lo > 0
            t = (lambda v: math.log10(v)) if log else (lambda v: v)
            inv = (lambda v: 10 ** v) if log else (lambda v: v)
            key = (id(ax), name, log)
            prev = self._limits.get(key)
            a, b = t(lo), t(hi)
            if prev is not None and lo < hi:
                pa, pb = prev
                ua, ub = min(a, pa), max(b, pb)
                if (b - a) >= 0.5 * (ub - ua):  # the data fill at least half of old and new together
                    grow = 0.5 * (b - a)
                    a, b = (ua - grow if a < pa else ua), (ub + grow if b > pb else ub)
            self._limits[key] = (a, b)
            if lo < hi:
                getattr(ax, f"set_{name}lim")(inv(a), inv(b), auto=None)  # autoscaling stays as it was

    def _render(self) -> bytes:
        canvas = self.figure.canvas
        data = []
        for ax in self.axes:
            legend = ax.get_legend()
            dynamic_legend = legend is not None and legend._loc == 0  # "best": placed by the data
            for artist in sorted(_drawn(ax) + ([legend] if dynamic_legend else []) + _titles(ax),
                                 key=lambda a: a.get_zorder()):
                artist.set_animated(True)
                data.append(artist)
        key = tuple(_background_key(ax) for ax in self.axes)
        if key != self._key or any(ax.images for ax in self.axes):
            canvas.draw()  # animated artists are left out: this is the background alone
            self._background = canvas.copy_from_bbox(self.figure.bbox)
            self._key = key
            self.backgrounds_drawn += 1
        else:
            canvas.restore_region(self._background)
            for ax in self.axes:
                ax.apply_aspect()  # a fixed aspect moves the axes when the limits change
        for artist in data:
            self.figure.draw_artist(artist)
        return encode_png(np.asarray(canvas.buffer_rgba()))


def encode_png(rgba) -> bytes:
    """An RGBA pixel array (height x width x 4, uint8) as PNG bytes: no row filters and
    fast zlib compression, three times faster than Pillow's adaptive filtering (a widget
    frame is sent once and thrown away, so speed beats size).

    >>> png = encode_png(np.zeros((2, 3, 4), dtype=np.uint8))
    >>> png[:8] == b"\\x89PNG\\r\\n\\x1a\\n", len(png) < 100
    (True, True)
    """
    height, width, _ = rgba.shape
    raw = np.empty((height, 4 * width + 1), dtype=np.uint8)
    raw[:, 0] = 0  # filter type "none" for every row
    raw[:, 1:] = rgba.reshape(height, -1)

    def chunk(tag: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)  # 8-bit RGBA, no interlace
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw.tobytes(), 1))
            + chunk(b"IEND", b""))


def _drawn(ax) -> list:
    """What a draw function added to *ax* (the data layer)."""
    return [*ax.patches, *ax.lines, *ax.texts, *ax.collections, *ax.images, *ax.artists, *ax.tables]


def _titles(ax) -> list:
    return [ax.title, ax._left_title, ax._right_title]


_FORMATTER_STATE = {"axis", "locs", "offset", "orderOfMagnitude", "format", "_sublabels"}


def _fingerprint(obj) -> tuple:
    """A locator's or formatter's settings (not what it computed in the last draw)."""
    items = []
    for k, v in sorted(vars(obj).items()):
        if k in _FORMATTER_STATE and not (k == "locs" and type(obj).__name__ == "FixedLocator"):
            continue
        items.append((k, tuple(np.ravel(v).tolist()) if isinstance(v, np.ndarray) else repr(v)))
    return type(obj).__name__, tuple(items)


def _artist_style(a) -> tuple:
    return tuple(repr(getattr(a, f"get_{p}")()) for p in ("facecolor", "edgecolor", "color", "linestyle",
                                                           "linewidth", "marker", "alpha") if hasattr(a, f"get_{p}"))


def _background_key(ax) -> tuple:
    """Everything the background layer of *ax* depends on; equal keys, equal pixels."""
    def axis(a):
        return (a.get_scale(), _fingerprint(a.get_major_locator()), _fingerprint(a.get_major_formatter()),
                _fingerprint(a.get_minor_locator()), _fingerprint(a.get_minor_formatter()), a.get_visible(),
                a.label.get_text(), a.label.get_fontsize(), a.label.get_position(), repr(a._major_tick_kw),
                repr(a._minor_tick_kw), a.get_label_position())

    legend = ax.get_legend()
    legend_key = None if legend is None else (
        legend._loc, legend._ncols, tuple(t.get_text() for t in legend.texts),
        tuple(_artist_style(h) for h in legend.legend_handles), legend.get_frame_on())
    if not ax.axison:  # no patch, spines, ticks or labels: the limits do not show
        return ax.get_position(original=True).bounds, False, repr(ax.get_aspect()), legend_key
    return (ax.get_position(original=True).bounds, ax.get_xlim(), ax.get_ylim(), axis(ax.xaxis), axis(ax.yaxis),
            ax.axison, ax.get_frame_on(), repr(ax.get_aspect()), ax.get_adjustable(), repr(ax.get_facecolor()),
            tuple((n, s.get_visible(), s.get_linewidth(), repr(s.get_edgecolor())) for n, s in ax.spines.items()),
            legend_key)


def render_png(draw, figsize=(6.0, 3.2), dpi=80, margins=(0.1, 0.98, 0.22, 0.9)) -> bytes:
    """Call ``draw(ax)`` on a fresh, private figure and return it as PNG bytes."""
    return Canvas(figsize, dpi, margins).png(draw)


class Explorer:
    """What every widget of the book shares.

    A subclass computes and redraws in ``update(...)``, which sets :attr:`image` (PNG bytes)
    and :attr:`text` and works without a browser (tests and benchmarks call it); it ends with
    :meth:`_show`. :attr:`widget` is the ipywidgets view, made on first use: the controls
    that :meth:`controls` returns, a line of text, and the picture. Displaying the object
    in JupyterLab shows the view.
    """

    html_text = False  # the text line is HTML (colours) rather than plain text

    def _start(self):
        self.image = b""
        self.text = ""
        self._widget = None
        self._canvas = None

    def _show(self):
        """Push :attr:`image` and :attr:`text` to the view, if it exists."""
        if self._widget is not None:
            self._image_widget.value = self.image
            self._label.value = self.text

    def controls(self, w) -> list:
        """The ipywidgets controls above the text and picture (*w* is ``ipywidgets``)."""
        return []

    def _slider_rows(self, w, sliders: dict, per_row: int = 2) -> list:
        """Rows of *sliders* (name -> slider); moving any calls ``update`` with all their values."""
        self._sliders = sliders
        for s in sliders.values():
            s.observe(lambda change: self.update(**{k: v.value for k, v in self._sliders.items()}), "value")
        items = list(sliders.values())
        return [w.HBox(items[i:i + per_row]) for i in range(0, len(items), per_row)]

    @property
    def widget(self):
        """The ipywidgets view (made on first use)."""
        if self._widget is None:
            import ipywidgets as w

            self.update()
            self._image_widget = w.Image(value=self.image, format="png")
            self._label = (w.HTML if self.html_text else w.Label)(value=self.text)
            self._widget = w.VBox([*self.controls(w), self._label, self._image_widget])
        return self._widget

    def _repr_mimebundle_(self, **kwargs):
        return with_snapshot(self.widget._repr_mimebundle_(**kwargs), self.image)


def with_snapshot(bundle: dict | None, image: bytes) -> dict | None:
    """A widget's display data with its current picture added as ``image/png``: what shows
    where no widget manager runs (the PDF book, nbconvert, a notebook viewer). Frontends
    and the HTML book that render widgets prefer the widget view; the text repr stays last.

    >>> sorted(with_snapshot({"text/plain": "VBox()"}, b"\\x89PNG"))
    ['image/png', 'text/plain']
    """
    if bundle is None or not image:
        return bundle
    import base64

    return {**bundle, "image/png": base64.b64encode(image).decode("ascii")}


class SpeedExplorer(Explorer):
    """Sliders for tooth numbers; shows every link's speed (:func:`gearlib.plot_speeds`).

    One slider per gear (:func:`~gearlib.mechanism.gears`: a planet meshing sun and ring has
    one tooth number), none for a ring that must follow its sun and planet so that the planet
    fits (:func:`~gearlib.mechanism.followers`); the text line gives its tooth number. Use
    :meth:`update` to compute and redraw without a browser (this is what a slider calls), and
    display the object (or its ``widget``) in JupyterLab.
    """

    def __init__(self, mech: Mechanism, ground=None, inputs=None, *, pairs=None, links=None, max_teeth: int = 120):
        from .teeth import followers, gears

        self.mechanism = mech
        self.ground = mech.ground if ground is None else ground
        self.inputs = inputs if inputs is not None else {x: 1 for x in mech.inputs}
        self.followers = followers(mech, pairs)
        self.gears = [g for g in gears(mech, pairs) if g.key not in self.followers]
        self.links = links
        self.max_teeth = max_teeth
        self._start()

    def keys(self) -> list[str]:
        """Slider names: ``N_<gear>`` for each gear (``N_<gear>_in_<a>_<b>`` on a link with several)."""
        return [g.key for g in self.gears]

    def current(self) -> dict:
        return {g.key: g.teeth for g in self.gears}

    def mechanism_for(self, **teeth) -> Mechanism:
        """The mechanism with these tooth numbers (keys of :meth:`keys`); followers follow."""
        from .teeth import set_teeth

        values = self.current() | {k: int(v) for k, v in teeth.items()}
        changed = {k: v for k, v in values.items() if self.current()[k] != v}
        for sun, planet in self.followers.values():  # a ring follows its sun and planet together
            if sun in changed or planet in changed:
                changed |= {sun: values[sun], planet: values[planet]}
        return set_teeth(self.mechanism, changed) if changed else self.mechanism

    def update(self, **teeth) -> bytes:
        """Recompute the speeds for these tooth numbers and redraw; returns the PNG. Tooth numbers
        that cannot be built are named in the text line, and the picture stays as it was."""
        from ..errors import ToothNumberError
        from .plot import plot_speeds
        from .teeth import gears

        try:
            mech = self.mechanism_for(**teeth)
        except ToothNumberError as err:
            self.text = str(err)
            self._show()
            return self.image
        sol = speeds(mech, self.ground, self.inputs)
        inputs = ", ".join(f"ω{k} = {v}" for k, v in self.inputs.items())
        self.text = f"inputs {inputs}; link {self.ground} fixed"
        now = {g.key: g.teeth for g in gears(mech)}
        for ring, (sun, planet) in self.followers.items():
            self.text += f"; {ring} = {sun} + 2 {planet} = {now[ring]} (so that the planet fits)"
        if self._canvas is None:
            self._canvas = Canvas(margins=(0.17, 0.98, 0.22, 0.9), keep_axes=True, stable_limits=True)
        self.image = self._canvas.png(lambda ax: plot_speeds(sol, ax=ax, links=self.links))
        self._show()
        return self.image

    def controls(self, w) -> list:
        return self._slider_rows(w, {g.key: w.IntSlider(value=g.teeth, min=5, max=self.max_teeth,
                                                        description=g.key.split("_in_")[0] + (
                                                            f" ({g.key.split('_in_')[1].replace('_', ',')})"
                                                            if "_in_" in g.key else ""),
                                                        continuous_update=False, tooltip=f"teeth of gear {g.link}",
                                                        style={"description_width": "initial"})
                                     for g in self.gears})


@takes_mechanism
def speed_explorer(mech: Mechanism, ground=None, inputs=None, *, pairs=None, links=None,
                   max_teeth: int = 120) -> SpeedExplorer:
    """A widget: tooth-number sliders for the gears of ``pairs`` (default: all) and a bar chart
    of the speeds of ``links`` (default: every link). Static twin: :func:`plot_speed_sweep`."""
    return SpeedExplorer(mech, ground, inputs, pairs=pairs, links=links, max_teeth=max_teeth)
