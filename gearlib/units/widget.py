"""The kinematic-unit explorer (chapter 2).

Like :mod:`gearlib.mechanism.widgets`, a thin wrapper that draws with a plot function on a
private matplotlib figure into an image; :meth:`UnitExplorer.update` computes and redraws
without a browser. Static twin: :func:`gearlib.units.draw_units_gallery`.
"""

from __future__ import annotations
from ..errors import UnknownLinkError
from ..mechanism.widgets import Explorer

__all__ = ['UnitExplorer', 'unit_explorer']


def _graph_canvas(figsize):
    """A canvas for graph drawings: no margins, and the axes kept between frames."""
    from ..mechanism.widgets import Canvas

    return Canvas(figsize, dpi=72, margins=(0.0, 1.0, 0.0, 1.0), keep_axes=True)


def _geared_names() -> list[str]:
    from .. import catalog

    return [n for n in catalog.names() if catalog.load(n).gear_pairs]


class UnitExplorer(Explorer):
    """Pick a catalogue mechanism; see its graph with the kinematic units in colour and the
    common linkages marked (:func:`gearlib.draw_units`), and a list of the units."""

    html_text = True  # the units are named in their colours

    def __init__(self, names=None, *, start=None):
        from .. import catalog

        if isinstance(names, str):
            names = [names]
        self.names = list(names) if names is not None else _geared_names()
        for name in self.names + ([start] if start is not None else []):
            catalog.path(name)  # a clear error for a name that is not in the catalogue
        if not self.names:
            raise UnknownLinkError("unit_explorer: give at least one catalogue name (gl.catalog.names())")
        self.name = start or ("liu_chen_fig1" if "liu_chen_fig1" in self.names else self.names[0])
        self._start()
        self._pos: dict = {}

    def update(self, name: str | None = None) -> bytes:
        """Fractionate the mechanism *name* and redraw; returns the PNG."""
        from .. import catalog
        from ._draw import draw_units
        from .fractionation import kinematic_units

        if name is not None:
            catalog.path(name)  # a clear error for an unknown name
            self.name = name
        frac = kinematic_units(catalog.load(self.name))
        from ._draw import unit_colors

        colors = unit_colors(len(frac.units))
        units = "; ".join(f"<span style='color:{c.replace('tab:', '')}'>{u.name}</span> {u.label}"
                          for u, c in zip(frac.units, colors))
        links = "; ".join(str(c) for c in frac.linkages) or "no common linkage"
        self.text = f"{frac.mechanism.name}: {units}. {links}."
        if self._canvas is None:
            self._canvas = _graph_canvas(figsize=(4.6, 3.4))
        if self.name not in self._pos:
            from ..mechanism.plot import graph_layout

            self._pos[self.name] = graph_layout(frac.mechanism)
        pos = self._pos[self.name]
        self.image = self._canvas.png(lambda ax: draw_units(frac, ax=ax, pos=pos, font_size=9, legend=False, title=""))
        self._show()
        return self.image

    def controls(self, w) -> list:
        pick = w.Dropdown(options=self.names, value=self.name, description="mechanism")
        pick.observe(lambda change: self.update(change["new"]), "value")
        return [pick]


def unit_explorer(names=None, *, start=None) -> UnitExplorer:
    """A widget: choose a catalogue mechanism and see its kinematic units.
    Static twin: :func:`gearlib.units.draw_units_gallery`."""
    return UnitExplorer(names, start=start)
