"""Interactive widgets: thin wrappers that call a plot function when a slider moves.

Each widget has a *static twin*, a plot that shows the same relation without a kernel,
for the HTML book and for printing:

=========================  ===============================================
widget                     static twin
=========================  ===============================================
:func:`speed_explorer`     :func:`gearlib.plot.plot_speed_sweep`
=========================  ===============================================

A widget draws with a private matplotlib ``Figure`` (:class:`Canvas`, no pyplot state) into
an image, so a slider update is one computation and one small render, and the HTML book can
show the image without a kernel. ``ipywidgets`` is imported only
when a widget is made.
"""

from __future__ import annotations

import io

from .kinematics import speeds
from .mechanism import Mechanism

__all__ = ["Canvas", "Explorer", "SpeedExplorer", "speed_explorer", "render_png"]


class Canvas:
    """A private matplotlib figure that a widget redraws on every update (no pyplot, no
    global matplotlib state).

    Keeping one figure with a fixed layout is about twice as fast as making a new figure each
    time. :meth:`png` calls one ``draw(ax)`` per panel and returns the image as PNG bytes,
    ready for an ``ipywidgets.Image``. Between frames the axes are cleared, or, with
    ``keep_axes=True``, only the drawn artists are removed, which keeps the ticks (a third of
    a frame's time for graph drawings and fixed-range plots).
    """

    def __init__(self, figsize=(6.0, 3.2), dpi=80, margins=(0.1, 0.98, 0.22, 0.9), *, panels: int = 1,
                 width_ratios=None, wspace=None, keep_axes: bool = False):
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

    def png(self, *draws) -> bytes:
        """Draw panel *i* with ``draws[i](ax)`` and return the figure as PNG bytes."""
        for draw, ax in zip(draws, self.axes):
            if self.keep_axes:
                for artist in [*ax.patches, *ax.lines, *ax.texts, *ax.collections, *ax.images]:
                    artist.remove()
                if ax.get_legend() is not None:
                    ax.get_legend().remove()
                ax.set_title("")
            else:
                ax.clear()
            draw(ax)
        buf = io.BytesIO()
        self.figure.savefig(buf, format="png")
        return buf.getvalue()


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
        return self.widget._repr_mimebundle_(**kwargs)


class SpeedExplorer(Explorer):
    """Sliders for tooth numbers; shows every link's speed (:func:`gearlib.plot.plot_speeds`).

    Use :meth:`update` to compute and redraw without a browser (this is what a slider
    calls), and display the object (or its :attr:`widget`) in JupyterLab.
    """

    def __init__(self, mech: Mechanism, ground=None, inputs=None, *, pairs=None, max_teeth: int = 120):
        self.mechanism = mech
        self.ground = mech.ground if ground is None else ground
        self.inputs = inputs if inputs is not None else {x: 1 for x in mech.inputs}
        chosen = mech.gear_pairs if pairs is None else [mech.gear_pair(*p)[0] for p in pairs]
        self.pairs = [gp for gp in chosen if gp.teeth is not None]
        self.max_teeth = max_teeth
        self._start()

    def keys(self) -> list[str]:
        """Slider names: ``N_<gear>_in_<a>_<b>`` for each tooth number."""
        return [f"N_{g}_in_{gp.gears[0]}_{gp.gears[1]}" for gp in self.pairs for g in gp.gears]

    def current(self) -> dict:
        return {k: t for k, t in zip(self.keys(), (t for gp in self.pairs for t in gp.teeth))}

    def mechanism_for(self, **teeth) -> Mechanism:
        mech = self.mechanism
        values = self.current() | teeth
        for gp in self.pairs:
            a, b = gp.gears
            ta = values[f"N_{a}_in_{a}_{b}"]
            tb = values[f"N_{b}_in_{a}_{b}"]
            if (ta, tb) != gp.teeth:
                mech = mech.with_gear_pair(gp.gears, teeth=(int(ta), int(tb)))
        return mech

    def update(self, **teeth) -> bytes:
        """Recompute the speeds for these tooth numbers and redraw; returns the PNG."""
        from .plot import plot_speeds

        sol = speeds(self.mechanism_for(**teeth), self.ground, self.inputs)
        inputs = ", ".join(f"ω{k} = {v}" for k, v in self.inputs.items())
        self.text = f"inputs {inputs}; link {self.ground} fixed"
        if self._canvas is None:
            self._canvas = Canvas()
        self.image = self._canvas.png(lambda ax: plot_speeds(sol, ax=ax))
        self._show()
        return self.image

    def controls(self, w) -> list:
        return self._slider_rows(w, {key: w.IntSlider(value=value, min=5, max=self.max_teeth,
                                                      description=key.split("_in_")[0], continuous_update=False,
                                                      tooltip=key)
                                     for key, value in self.current().items()})

def speed_explorer(mech: Mechanism, ground=None, inputs=None, *, pairs=None, max_teeth: int = 120) -> SpeedExplorer:
    """A widget: tooth-number sliders for ``pairs`` (default: all) and a bar chart of every
    link's speed. Static twin: :func:`gearlib.plot.plot_speed_sweep`."""
    return SpeedExplorer(mech, ground, inputs, pairs=pairs, max_teeth=max_teeth)
