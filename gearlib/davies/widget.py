"""A widget: tooth numbers and ordinary efficiencies -> overall efficiency and power flows.

A thin wrapper over :func:`gearlib.davies.efficiency` and
:func:`gearlib.davies.plot_power_flow` in the style of :mod:`gearlib.mechanism.widgets`: a private
matplotlib figure rendered into an ``ipywidgets.Image``; :meth:`EfficiencyExplorer.update`
computes and redraws without a browser. Its static twin is
:func:`gearlib.davies.plot_efficiency_sweep`.
"""

from __future__ import annotations

import sympy

from ..mechanism.data import Mechanism
from ..mechanism.plot import _axes
from ..mechanism.widgets import Explorer
from .overall import efficiency
from ..mechanism._accept import takes_mechanism

__all__ = ["EfficiencyExplorer", "efficiency_explorer", "with_teeth", "plot_efficiency_sweep"]


def with_teeth(mech: Mechanism, pair, gear, teeth: int) -> Mechanism:
    """*mech* with gear *gear* of *pair* given *teeth* teeth; its pitch radius follows at the
    pair's module (radius per tooth), so radii stay proportional to tooth numbers."""
    gp, _ = mech.gear_pair(*pair)
    gear = mech.resolve(gear)
    k = gp.gears.index(gear)
    teeth_new = list(gp.teeth)
    teeth_new[k] = int(teeth)
    changes = {"teeth": tuple(teeth_new)}
    if gp.radii is not None:
        module = gp.radii[0] / gp.teeth[0]
        changes["radii"] = tuple(module * t for t in teeth_new)
    if gp.kind == "bevel" and gp.ratio is not None:
        changes["ratio"] = sympy.sign(gp.ratio) * sympy.Rational(teeth_new[0], teeth_new[1])
    return mech.with_gear_pair(gp.gears, **changes)


class EfficiencyExplorer(Explorer):
    """Sliders for tooth numbers and ordinary efficiencies; shows the power flows
    (:func:`gearlib.davies.plot_power_flow`) and the overall efficiency.

    Slider labels name gears: ``N_1`` for the teeth of the gear on link 1 and ``η 1-3`` for the
    ordinary efficiency of the mesh of gears 1 and 3 (either gear driving). *gears* renames
    the gears of a mesh as :func:`gearlib.davies.by_gears` does (``{(2, 3): (2, 4)}``: in the
    mesh of links 2 and 3, link 3's gear is gear 4); a link with gears in two meshes and no
    such names gets the mesh in its label (``N_3 (1-3)``, ``N_3 (2-3)``)."""

    def __init__(self, mech: Mechanism, ground, input, output, *, pairs=None, eta=0.98, max_teeth: int = 120,
                 gears=None):
        self.mechanism = mech
        self.gears = {tuple(mech.resolve(x) for x in k): tuple(v) for k, v in (gears or {}).items()}
        self.ground, self.input, self.output = ground, input, output
        chosen = mech.gear_pairs if pairs is None else [mech.gear_pair(*p)[0] for p in pairs]
        self.pairs = [gp for gp in chosen if gp.teeth is not None]
        self.eta = {gp.gears: float(eta if not isinstance(eta, dict) else eta.get(gp.gears, 0.98))
                    for gp in mech.gear_pairs}
        self.max_teeth = max_teeth
        self._start()
        self.result = None

    def keys(self) -> list[str]:
        """Slider names: ``N_<gear>_in_<a>_<b>`` for teeth and ``eta_<a>_<b>`` for each mesh."""
        teeth = [f"N_{g}_in_{gp.gears[0]}_{gp.gears[1]}" for gp in self.pairs for g in gp.gears]
        return teeth + [f"eta_{a}_{b}" for a, b in self.eta]

    def current(self) -> dict:
        out = {f"N_{g}_in_{gp.gears[0]}_{gp.gears[1]}": t for gp in self.pairs for g, t in zip(gp.gears, gp.teeth)}
        out.update({f"eta_{a}_{b}": v for (a, b), v in self.eta.items()})
        return out

    def mechanism_for(self, **values) -> Mechanism:
        values = self.current() | values
        mech = self.mechanism
        for gp in self.pairs:
            for g, t in zip(gp.gears, gp.teeth):
                new = int(values[f"N_{g}_in_{gp.gears[0]}_{gp.gears[1]}"])
                if new != t:
                    mech = with_teeth(mech, gp.gears, g, new)
        return mech

    def update(self, **values) -> bytes:
        """Recompute for these tooth numbers and ordinary efficiencies and redraw; returns the PNG."""
        from .drawing import plot_power_flow

        merged = self.current() | values
        mech = self.mechanism_for(**values)
        eta = {pair: float(merged[f"eta_{pair[0]}_{pair[1]}"]) for pair in self.eta}
        try:
            self.result = efficiency(mech, self.ground, self.input, self.output, eta=eta)
            self.text = f"overall efficiency η = {float(self.result.value):.5f}"
            if self._canvas is None:
                from ..mechanism.widgets import Canvas

                self._canvas = Canvas(margins=(0.1, 0.98, 0.12, 0.88), keep_axes=True, stable_limits=True)
            self.image = self._canvas.png(lambda ax: plot_power_flow(self.result, ax=ax))
        except ValueError as err:  # a GearlibError: say it, keep the last picture
            self.text = f"cannot compute: {err}"
        self._show()
        return self.image

    def gear_name(self, pair, link) -> str:
        """The name of the gear on *link* in the mesh *pair* (its link id unless renamed)."""
        for (a, b), (ga, gb) in self.gears.items():
            if {a, b} == set(pair):
                return str(ga if link == a else gb)
        return str(link)

    def labels(self) -> dict:
        """``{slider key: label}``: ``N_<gear>`` and ``η <gear>-<gear>``, every label different."""
        teeth = [(f"N_{g}_in_{gp.gears[0]}_{gp.gears[1]}", f"N_{self.gear_name(gp.gears, g)}", gp.gears)
                 for gp in self.pairs for g in gp.gears]
        names = [label for _, label, _ in teeth]
        # one link's gears in two meshes and not renamed: say which mesh
        out = {key: label + (f" ({a}-{b})" if names.count(label) > 1 else "") for key, label, (a, b) in teeth}
        for a, b in self.eta:
            out[f"eta_{a}_{b}"] = f"η {self.gear_name((a, b), a)}-{self.gear_name((a, b), b)}"
        return out

    def controls(self, w) -> list:
        sliders = {}
        labels = self.labels()
        style = {"description_width": "initial"}
        for key, value in self.current().items():
            if key.startswith("N_"):
                sliders[key] = w.IntSlider(value=value, min=5, max=self.max_teeth, description=labels[key],
                                           continuous_update=False, style=style)
            else:
                sliders[key] = w.FloatSlider(value=value, min=0.9, max=1.0, step=0.001, description=labels[key],
                                             continuous_update=False, readout_format=".3f", style=style)
        return self._slider_rows(w, sliders)


@takes_mechanism
def efficiency_explorer(mech: Mechanism, ground, input, output, *, pairs=None, eta=0.98,
                        max_teeth: int = 120, gears=None) -> EfficiencyExplorer:
    """A widget: sliders for the tooth numbers of *pairs* (default all) and the ordinary
    efficiency of every mesh; shows the overall efficiency and the power flows. *gears* names
    the gears of a compound link (see :class:`EfficiencyExplorer`). Static twin:
    :func:`gearlib.davies.plot_efficiency_sweep`."""
    return EfficiencyExplorer(mech, ground, input, output, pairs=pairs, eta=eta, max_teeth=max_teeth, gears=gears)


@takes_mechanism
def plot_efficiency_sweep(mech, ground, input, output, *, pair, gear, values, etas=(0.97, 0.98, 0.99), ax=None,
                          mark=None):
    """Efficiency against the tooth number of *gear* in gear *pair*, for every ordinary
    efficiency in *etas* (the same for all meshes). Trains whose radii no longer close a loop
    are laid out kinematically, which leaves the efficiency unchanged."""
    ax = _axes(ax, (5.5, 3.4))
    values = list(values)
    for e in etas:
        ys = []
        for v in values:
            try:
                m = with_teeth(mech, pair, gear, int(v))
                ys.append(float(efficiency(m, ground, input, output, eta=e).value))
            except ValueError:
                ys.append(float("nan"))
        ax.plot(values, ys, marker=".", label=f"η_ij = {e}")
    if mark is not None:
        ax.axvline(mark, color="0.5", ls=":")
    ax.set_xlabel(f"teeth of gear {gear} in pair {tuple(pair)}")
    ax.set_ylabel("overall efficiency η")
    ax.legend(fontsize=8, frameon=False)
    return ax
