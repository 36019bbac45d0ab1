"""Widgets for kinematic units (chapter 2) and unit-by-unit gains (chapter 3).

Like :mod:`gearlib.widgets`, each is a thin wrapper that draws with a plot function on a
private matplotlib figure into an image; :meth:`update` computes and redraws without a
browser. Static twins:

=============================  ====================================================
widget                         static twin
=============================  ====================================================
:func:`unit_explorer`          :func:`gearlib.unit_plot.draw_units_gallery`
:func:`transmission_explorer`  :func:`gearlib.transmission.plot_mode_sweep`
=============================  ====================================================
"""

from __future__ import annotations


from .mechanism import Mechanism
from .widgets import Explorer

__all__ = ["UnitExplorer", "unit_explorer", "TransmissionExplorer", "transmission_explorer"]


def _graph_canvas(figsize):
    """A canvas for graph drawings: no margins, and the axes kept between frames."""
    from .widgets import Canvas

    return Canvas(figsize, dpi=72, margins=(0.0, 1.0, 0.0, 1.0), keep_axes=True)


def _geared_names() -> list[str]:
    from . import catalog

    return [n for n in catalog.names() if catalog.load(n).gear_pairs]


class UnitExplorer(Explorer):
    """Pick a catalogue mechanism; see its graph with the kinematic units in colour and the
    common linkages marked (:func:`gearlib.unit_plot.draw_units`), and a list of the units."""

    html_text = True  # the units are named in their colours

    def __init__(self, names=None, *, start=None):
        self.names = list(names) if names is not None else _geared_names()
        self.name = start or ("liu_chen_fig1" if "liu_chen_fig1" in self.names else self.names[0])
        self._start()
        self._pos: dict = {}

    def update(self, name: str | None = None) -> bytes:
        """Fractionate the mechanism *name* and redraw; returns the PNG."""
        from . import catalog
        from .unit_plot import draw_units
        from .units import kinematic_units

        if name is not None:
            catalog.path(name)  # a clear error for an unknown name
            self.name = name
        frac = kinematic_units(catalog.load(self.name))
        from .unit_plot import unit_colors

        colors = unit_colors(len(frac.units))
        units = "; ".join(f"<span style='color:{c.replace('tab:', '')}'>{u.name}</span> {u.label}"
                          for u, c in zip(frac.units, colors))
        links = "; ".join(str(c) for c in frac.linkages) or "no common linkage"
        self.text = f"{frac.mechanism.name}: {units}. {links}."
        if self._canvas is None:
            self._canvas = _graph_canvas(figsize=(4.6, 3.4))
        if self.name not in self._pos:
            from .plot import graph_layout

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
    Static twin: :func:`gearlib.unit_plot.draw_units_gallery`."""
    return UnitExplorer(names, start=start)


class TransmissionExplorer(Explorer):
    """Choose a gear (operating mode) and tooth numbers; see the propagation path and the ratio
    by units, beside the null-space value."""

    def __init__(self, mech: Mechanism, modes, *, pairs=None, max_teeth: int = 120):
        from .transmission import operating_modes

        self.mechanism = mech
        self.modes = {m.name: m for m in operating_modes(modes)}
        self.mode = next(iter(self.modes))
        chosen = mech.gear_pairs if pairs is None else [mech.gear_pair(*p)[0] for p in pairs]
        self.pairs = [gp for gp in chosen if gp.teeth is not None]
        self.max_teeth = max_teeth
        self.teeth = {f"N_{g}_in_{gp.gears[0]}_{gp.gears[1]}": t for gp in self.pairs for g, t in zip(gp.gears, gp.teeth)}
        self._start()
        self.ratio = None

    def mechanism_for(self, **teeth) -> Mechanism:
        values = self.teeth | teeth
        mech = self.mechanism
        for gp in self.pairs:
            a, b = gp.gears
            new = (int(values[f"N_{a}_in_{a}_{b}"]), int(values[f"N_{b}_in_{a}_{b}"]))
            if new != gp.teeth:
                mech = mech.with_gear_pair(gp.gears, teeth=new)
        return mech

    def update(self, mode: str | None = None, **teeth) -> bytes:
        """Recompute the chosen gear's propagation for these tooth numbers and redraw."""
        from .relation import propagate
        from .kinematics import format_value
        from .unit_plot import draw_propagation

        if mode is not None:
            if mode not in self.modes:
                from .errors import InputError

                raise InputError(f"no operating mode {mode!r}; modes are {', '.join(self.modes)}")
            self.mode = mode
        unknown = set(teeth) - set(self.teeth)
        if unknown:
            from .errors import InputError

            raise InputError(f"unknown tooth number {sorted(unknown)[0]!r}; use {', '.join(self.teeth)}")
        self.teeth.update(teeth)
        m = self.modes[self.mode]
        prop = propagate(self.mechanism_for(), m.output, [m.input], ground=m.ground, held=m.held, joined=m.joined)
        self.ratio = prop.ratio
        path = " then ".join(f"{s.unit.name}" for s in prop.steps)
        self.text = f"{m}: ratio {format_value(self.ratio, 8)} through {path}"
        if self._canvas is None:
            self._canvas = _graph_canvas(figsize=(5.4, 2.4))
        self.image = self._canvas.png(lambda ax: draw_propagation(prop, ax=ax, title=""))
        self._show()
        return self.image

    def controls(self, w) -> list:
        pick = w.ToggleButtons(options=list(self.modes), value=self.mode, description="gear")
        pick.observe(lambda change: self.update(change["new"]), "value")
        sliders = {key: w.IntSlider(value=value, min=8, max=self.max_teeth, description=key.split("_in_")[0],
                                    continuous_update=False) for key, value in self.teeth.items()}
        return [pick, *self._slider_rows(w, sliders, per_row=3)]


def transmission_explorer(mech: Mechanism, modes, *, pairs=None, max_teeth: int = 120) -> TransmissionExplorer:
    """A widget: choose a gear and tooth numbers, see the propagation path and the ratio.
    Static twin: :func:`gearlib.transmission.plot_mode_sweep`."""
    return TransmissionExplorer(mech, modes, pairs=pairs, max_teeth=max_teeth)
