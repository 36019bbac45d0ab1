"""The static twin of the speed explorer: every link's speed as one gear's tooth number varies.

It computes (speeds of a set of buildable trains) before it draws, so it stands above both the
kinematics and the drawing modules (:mod:`gearlib.mechanism.plot` imports only the data).
"""

from __future__ import annotations

import numpy as np

from ..errors import DataFormatError
from ._accept import takes_mechanism
from .data import Mechanism
from .kinematics import speeds
from .plot import _axes, _is_real, _shown, _title, _values
from .teeth import gears, set_teeth

__all__ = ["plot_speed_sweep"]


@takes_mechanism
def plot_speed_sweep(mech: Mechanism, ground=None, inputs=None, *, gear, values, pair=None, links=None, ax=None,
                     title=None, unit="rad/s"):
    """Every link's speed as the tooth number of one gear varies: the static twin of
    :func:`~gearlib.mechanism.speed_explorer`.

    ``gear`` is the link whose gear takes each tooth number of ``values``; when the link
    carries several gears (a stepped planet), ``pair`` names the gear pair that says which.
    Each step changes the teeth with :func:`~gearlib.mechanism.set_teeth`, so a planetary
    set stays buildable: sweep its ring and the planet follows. Links are shown as in
    :func:`~gearlib.plot_speeds` (a tilted link relative to the link it turns on); a complex speed by
    its magnitude.
    """
    ax = _axes(ax, figsize=(6.0, 3.4))
    gear = mech.resolve(gear)
    ground = mech.ground if ground is None else mech.resolve(ground)
    inputs = inputs if inputs is not None else {x: 1 for x in mech.inputs}
    mine = [g for g in gears(mech) if g.link == gear]
    if pair is not None:
        gp, _ = mech.gear_pair(*pair)
        mine = [g for g in mine if gp.gears in g.pairs]
    if len(mine) != 1:
        raise DataFormatError(
            f"plot_speed_sweep: link {gear} carries {'no gear with teeth' if not mine else 'several gears'}"
            + ("" if not mine else f" ({', '.join(g.key for g in mine)}); name the gear pair with pair=(a, b)"))
    key = mine[0].key
    links = list(mech.link_ids if links is None else (mech.resolve(x) for x in links))
    shown = _shown(mech, ground, [x for x in links if x != ground])
    rows, followed = [], {}
    for n in values:
        changed = set_teeth(mech, {key: n})
        for g_old, g_new in zip(gears(mech), gears(changed)):
            if g_old.key != key and g_old.teeth != g_new.teeth:
                followed[g_old.link] = g_old.key
        rows.append(_values(speeds(changed, ground, inputs).as_complex(), mech, shown))
    rows = np.array(rows).reshape(len(rows), len(shown))
    xs = list(values)
    for j, (_, _, label) in enumerate(shown):
        col = rows[:, j]
        real = all(_is_real(z) for z in col)
        ax.plot(xs, col.real if real else np.abs(col), marker="o", markersize=3,
                label=label if real else f"|{label}|")
    ax.axhline(0, color="black", linewidth=0.8)
    ax.axvline(mine[0].teeth, color="0.6", linestyle=":", linewidth=1)
    def named(x):
        return f"{mech.link(x).name} {x}" if mech.link(x).name else f"gear {x}"

    what = f"teeth of {named(gear)}" + (f", meshing gear {[g for g in pair if g != gear][0]}"
                                         if "_in_" in key and pair else "")
    if followed:
        what += "\n(" + " and ".join(named(x) for x in followed) + (" follows" if len(followed) == 1 else " follow") \
            + ": N_ring = N_sun + 2 N_planet)"
    ax.set_xlabel(what)
    ax.set_ylabel(f"angular velocity ({unit})" if unit else "angular velocity")
    if len(shown) > 1:
        ax.legend(fontsize=8, ncols=2)
    ax.set_title(title if title is not None else _title(ground, shown))
    return ax
