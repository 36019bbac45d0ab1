"""The transmission explorer (chapter 3): a gear's propagation as tooth numbers change.

Like :mod:`gearlib.mechanism.widgets`, a thin wrapper that draws with a plot function on a
private matplotlib figure into an image; :meth:`TransmissionExplorer.update` computes and
redraws without a browser. Static twin: :func:`gearlib.gains.plot_mode_sweep`.
"""

from __future__ import annotations
from ..errors import InputError
from ..mechanism.data import Mechanism
from ..mechanism.widgets import Explorer
from ..units.widget import _graph_canvas
from ..mechanism._accept import takes_mechanism

__all__ = ['TransmissionExplorer', 'transmission_explorer']

MIN_PLANET_TEETH = 12
"""With ``concentric=True``, the fewest teeth a planet may be given (fewer would be badly undercut)."""


class TransmissionExplorer(Explorer):
    """Choose a gear (operating mode) and tooth numbers; see the propagation path and the ratio
    by units, beside the null-space value.

    With ``concentric=True`` the sliders set the suns and rings of the chosen pairs (``N_5``, in
    steps of two teeth) and every planet follows, ``Z_p = (Z_r - Z_s) / 2``
    (:func:`gearlib.with_concentric_teeth`), with at least :data:`MIN_PLANET_TEETH` teeth: each state
    shown is a set that can be built, and a state that is not is named in the text line."""

    def __init__(self, mech: Mechanism, modes, *, pairs=None, max_teeth: int = 120, concentric: bool = False):
        from .transmission import operating_modes

        self.mechanism = mech
        self.modes = {m.name: m for m in operating_modes(modes)}
        self.mode = next(iter(self.modes))
        chosen = mech.gear_pairs if pairs is None else [mech.gear_pair(*p)[0] for p in pairs]
        self.pairs = [gp for gp in chosen if gp.teeth is not None]
        self.max_teeth = max_teeth
        self.concentric = concentric
        if concentric:
            from ..mechanism.assembly import planetary_sets

            central = {g for s in planetary_sets(mech) if s.kind == "simple" for g in s.centrals}
            self.teeth = {f"N_{g}": t for gp in self.pairs for g, t in zip(gp.gears, gp.teeth) if g in central}
            self.planets = sorted({g for gp in self.pairs for g in gp.gears} - central, key=str)
        else:
            self.teeth = {f"N_{g}_in_{gp.gears[0]}_{gp.gears[1]}": t for gp in self.pairs
                          for g, t in zip(gp.gears, gp.teeth)}
        self._start()
        self.ratio = None

    def mechanism_for(self, **teeth) -> Mechanism:
        values = self.teeth | teeth
        mech = self.mechanism
        if self.concentric:
            from ..mechanism.assembly import with_concentric_teeth

            return with_concentric_teeth(mech, {mech.resolve(k[2:]): int(v) for k, v in values.items()},
                                         min_planet_teeth=MIN_PLANET_TEETH)
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
                raise InputError(f"no operating mode {mode!r}; modes are {', '.join(self.modes)}")
            self.mode = mode
        unknown = set(teeth) - set(self.teeth)
        if unknown:
            raise InputError(f"unknown tooth number {sorted(unknown)[0]!r}; use {', '.join(self.teeth)}")
        self.teeth.update(teeth)
        from ..mechanism.assembly import assembly_conditions

        m = self.modes[self.mode]
        try:
            mech = self.mechanism_for()
        except InputError as err:   # a ring too small for its sun: say so, keep the last picture
            self.text = f"{m}: no such set ({err})"
            self._show()
            return self.image
        prop = propagate(mech, m.output, [m.input], ground=m.ground, held=m.held, joined=m.joined)
        self.ratio = prop.ratio
        path = " then ".join(f"{s.unit.name}" for s in prop.steps)
        self.text = f"{m}: ratio {format_value(self.ratio, 8)} through {path}"
        if self.concentric and self.planets:
            teeth = {g: z for gp in mech.gear_pairs if gp.teeth for g, z in zip(gp.gears, gp.teeth)}
            self.text += "; planets " + ", ".join(f"{p}: {teeth[p]}" for p in self.planets) + " teeth"
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
        step = 2 if self.concentric else 1   # a sun and a ring keep the parity that fits a whole planet
        sliders = {key: w.IntSlider(value=value, min=8 + (value % 2 if self.concentric else 0), max=self.max_teeth,
                                    step=step, description=key.split("_in_")[0], continuous_update=False)
                   for key, value in self.teeth.items()}
        return [pick, *self._slider_rows(w, sliders, per_row=3)]


@takes_mechanism
def transmission_explorer(mech: Mechanism, modes, *, pairs=None, max_teeth: int = 120,
                          concentric: bool = False) -> TransmissionExplorer:
    """A widget: choose a gear and tooth numbers, see the propagation path and the ratio; with
    ``concentric=True`` the sliders move suns and rings and the planets follow, so that every
    set can be built. Static twin: :func:`gearlib.gains.plot_mode_sweep`."""
    return TransmissionExplorer(mech, modes, pairs=pairs, max_teeth=max_teeth, concentric=concentric)
