"""The transmission explorer (chapter 3): a gear's propagation as tooth numbers change.

Like :mod:`gearlib.mechanism.widgets`, a thin wrapper that draws with a plot function on a
private matplotlib figure into an image; :meth:`TransmissionExplorer.update` computes and
redraws without a browser. Static twin: :func:`gearlib.gains.plot_mode_sweep`.
"""

from __future__ import annotations
from ..mechanism.data import Mechanism
from ..mechanism.widgets import Explorer
from ..units.widget import _graph_canvas
from ..mechanism._accept import takes_mechanism

__all__ = ['TransmissionExplorer', 'transmission_explorer']


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
        from ..mechanism.kinematics import format_value
        from .drawing import draw_propagation

        if mode is not None:
            if mode not in self.modes:
                from ..errors import InputError

                raise InputError(f"no operating mode {mode!r}; modes are {', '.join(self.modes)}")
            self.mode = mode
        unknown = set(teeth) - set(self.teeth)
        if unknown:
            from ..errors import InputError

            raise InputError(f"unknown tooth number {sorted(unknown)[0]!r}; use {', '.join(self.teeth)}")
        self.teeth.update(teeth)
        from ..mechanism.assembly import assembly_conditions

        m = self.modes[self.mode]
        mech = self.mechanism_for()
        prop = propagate(mech, m.output, [m.input], ground=m.ground, held=m.held, joined=m.joined)
        self.ratio = prop.ratio
        path = " then ".join(f"{s.unit.name}" for s in prop.steps)
        self.text = f"{m}: ratio {format_value(self.ratio, 8)} through {path}"
        failed = [c for c in assembly_conditions(mech) if not c.ok]
        if failed:  # the kinematics holds, but the set could not be built: say so beside the ratio
            self.text += f" (does not assemble: {failed[0].set.label}, {failed[0].condition})"
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


@takes_mechanism
def transmission_explorer(mech: Mechanism, modes, *, pairs=None, max_teeth: int = 120) -> TransmissionExplorer:
    """A widget: choose a gear and tooth numbers, see the propagation path and the ratio.
    Static twin: :func:`gearlib.gains.plot_mode_sweep`."""
    return TransmissionExplorer(mech, modes, pairs=pairs, max_teeth=max_teeth)
