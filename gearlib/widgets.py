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

__all__ = ["Canvas", "SpeedExplorer", "speed_explorer", "render_png"]


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


class SpeedExplorer:
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
        self.image = b""
        self.text = ""
        self._widget = None
        self._canvas = None

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
        if self._widget is not None:
            self._image_widget.value = self.image
            self._label.value = self.text
        return self.image

    @property
    def widget(self):
        """The ipywidgets view (made on first use)."""
        if self._widget is None:
            import ipywidgets as w

            self.update()
            self._image_widget = w.Image(value=self.image, format="png")
            self._label = w.Label(value=self.text)
            sliders = []
            for key, value in self.current().items():
                s = w.IntSlider(value=value, min=5, max=self.max_teeth, description=key.split("_in_")[0],
                                continuous_update=False, tooltip=key)
                s.observe(lambda change: self.update(**self._slider_values()), "value")
                sliders.append((key, s))
            self._sliders = dict(sliders)
            self._widget = w.VBox([w.HBox([s for _, s in sliders[i:i + 2]]) for i in range(0, len(sliders), 2)]
                                  + [self._label, self._image_widget])
        return self._widget

    def _slider_values(self) -> dict:
        return {k: s.value for k, s in self._sliders.items()}

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)


def speed_explorer(mech: Mechanism, ground=None, inputs=None, *, pairs=None, max_teeth: int = 120) -> SpeedExplorer:
    """A widget: tooth-number sliders for ``pairs`` (default: all) and a bar chart of every
    link's speed. Static twin: :func:`gearlib.plot.plot_speed_sweep`."""
    return SpeedExplorer(mech, ground, inputs, pairs=pairs, max_teeth=max_teeth)
