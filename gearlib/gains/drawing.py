"""Drawings of chapter 3: a propagation, from the inputs through the units to the output, and a
transmission's shift table.

:func:`~gearlib.gains.draw_propagation` draws a :class:`~gearlib.Propagation` or a
:class:`~gearlib.gains.Plan` (whose ``.plot()`` comes here); :func:`~gearlib.gains.plot_shift_table` and
:func:`~gearlib.gains.plot_gear_efficiency` draw a :class:`~gearlib.gains.ScheduleTable` (its ``.plot()``),
:func:`~gearlib.gains.plot_gear_power` the power flow of one of its gears.
Each takes ``ax=``, draws and returns it.
"""

from __future__ import annotations
from ..units._draw import _axes, _finish

__all__ = ['draw_propagation', 'plot_shift_table', 'plot_gear_efficiency', 'plot_gear_power']


def draw_propagation(prop, ax=None, *, title=None, font_size=9):
    """The propagation structure from inputs to output: input nodes, units (with their type)
    and the output, arrows labelled with the local input they pass (a
    :class:`~gearlib.Propagation` or a :class:`~gearlib.gains.Plan`). An output that a coaxial
    triangle receives reversed is labelled with its minus sign (``-theta_5,4`` in Liu and
    Chen's Fig. 3(a))."""
    import networkx as nx

    plan_ = getattr(prop, "plan", prop)
    g = plan_.graph()
    used = {s.unit.name for s in getattr(prop, "steps", plan_.steps)}
    drop = [n for n, d in g.nodes(data=True) if d.get("kind") == "unit" and n not in used]
    g.remove_nodes_from(drop)
    ax = _axes(ax, (6.0, 3.0))
    try:
        layers = list(nx.topological_generations(g))
    except nx.NetworkXUnfeasible:
        layers = [list(g)]
    pos = {}
    for i, layer in enumerate(layers):
        layer = sorted(layer, key=str)
        for j, n in enumerate(layer):
            pos[n] = (2.6 * i, 1.1 * (j - (len(layer) - 1) / 2))
    from matplotlib.patches import FancyArrowPatch

    def half_width(n):  # points from a box's centre to its side, from the length of its label
        d = g.nodes[n]
        if d.get("kind") != "unit":
            return 1.6 * font_size
        return 0.3 * font_size * max(len(d.get("label", "")), len(str(n))) + 7

    for u, v, d in g.edges(data=True):
        color = {"tear": "tab:red", "coaxial triangle": "goldenrod", "2-link chain": "tab:green"}.get(
            d.get("kind"), "black")
        ax.add_patch(FancyArrowPatch(pos[u], pos[v], arrowstyle="-|>", mutation_scale=12, shrinkA=half_width(u),
                                     shrinkB=half_width(v), color=color, linewidth=1.3, zorder=1))
        (x0, y0), (x1, y1) = pos[u], pos[v]
        ax.text((x0 + x1) / 2, (y0 + y1) / 2 + 0.18, _tex(d.get("signal", ""), d.get("sign", 1)),
                fontsize=font_size - 1, ha="center", color=color)
    for n, d in g.nodes(data=True):
        kind = d.get("kind")
        if kind == "unit":
            ax.text(*pos[n], f"{n}\n{d.get('label', '')}", ha="center", va="center", fontsize=font_size,
                    bbox=dict(boxstyle="round", facecolor="white", edgecolor="black"), zorder=3)
        else:
            ax.text(*pos[n], _tex(n), ha="center", va="center", fontsize=font_size + 1,
                    bbox=dict(boxstyle="square", facecolor="0.9" if kind == "input" else "#fde9c9",
                              edgecolor="black"), zorder=3)
    return _finish(ax, pos or {"_": (0, 0)}, title)


def _tex(name: str, sign: int = 1) -> str:
    """``theta_5,4`` as TeX; with ``sign`` -1, the reversed output of a coaxial triangle, ``-theta_5,4``."""
    if name.startswith("theta_"):
        return rf"${'-' if sign < 0 else ''}\theta_{{{name[6:]}}}$"
    return ("-" if sign < 0 else "") + name


def plot_shift_table(table, ax=None, *, title=None, font_size=8):
    """A transmission's shift table as a grid, gears by shift elements: engaged elements shaded,
    every open one with its slip speed per unit input speed (a brake at its link's speed, a
    clutch at the difference of its links' speeds), coloured by its size. *table* is a
    :class:`~gearlib.gains.ScheduleTable` (``gl.shift_table(mech)``)."""
    import numpy as np

    elements = [e.name for e in table.mechanism.shift_elements]
    gears = [g.name for g in table.gears]
    ax = _axes(ax, (1.2 + 0.9 * len(elements), 0.9 + 0.38 * len(gears)))
    slip = np.full((len(gears), len(elements)), np.nan)
    for i, g in enumerate(table.gears):
        for j, e in enumerate(elements):
            if e in g.slips:
                slip[i, j] = abs(float(g.slips[e]))
    top = np.nanmax(slip) if np.isfinite(slip).any() else 1.0
    ax.imshow(np.nan_to_num(slip, nan=0.0) / (top or 1.0), cmap="Oranges", vmin=0, vmax=1.6, aspect="auto")
    for i, g in enumerate(table.gears):
        for j, e in enumerate(elements):
            if e in g.engaged:
                ax.add_patch(_rect(j, i, "0.35"))
                ax.text(j, i, "engaged", ha="center", va="center", color="white", fontsize=font_size)
            else:
                ax.text(j, i, f"{float(g.slips[e]):+.2f}", ha="center", va="center", fontsize=font_size)
    ax.set_xticks(range(len(elements)), elements, fontsize=font_size + 1)
    ax.set_yticks(range(len(gears)), gears, fontsize=font_size + 1)
    ax.tick_params(length=0)
    for spine in ax.spines.values():
        spine.set_visible(False)
    ax.set_xlabel("shift element", fontsize=font_size + 1)
    ax.set_title(title if title is not None else f"{table.mechanism.name}: slip of the open elements "
                 "(per unit input speed)", fontsize=font_size + 1)
    return ax


def _rect(x, y, color):
    from matplotlib.patches import Rectangle

    return Rectangle((x - 0.5, y - 0.5), 1, 1, facecolor=color, edgecolor="white", linewidth=1.5)


def plot_gear_efficiency(table, ax=None, *, title=None, font_size=8, bottom=None):
    """Each gear's efficiency from a :class:`~gearlib.gains.ScheduleTable`, as bars labelled
    with their value; the reverse gear (negative ratio) drawn in grey."""
    names = [g.name for g in table.gears if g.efficiency is not None]
    values = [g.efficiency for g in table.gears if g.efficiency is not None]
    colors = ["0.6" if float(g.ratio) < 0 else "tab:blue" for g in table.gears if g.efficiency is not None]
    ax = _axes(ax, (6.0, 3.0))
    ax.bar(range(len(values)), values, color=colors)
    low = bottom if bottom is not None else max(0.0, min(values) - 0.02)
    ax.set_ylim(low, 1.0 + (1.0 - low) * 0.12)
    for k, v in enumerate(values):
        ax.text(k, v, f"{v:.4f}", ha="center", va="bottom", fontsize=font_size)
    ax.set_xticks(range(len(values)), names, fontsize=font_size + 1)
    ax.set_ylabel("efficiency", fontsize=font_size + 1)
    ax.axhline(1.0, color="black", linewidth=0.6)
    ax.set_title(title if title is not None else f"{table.mechanism.name}: efficiency of every gear",
                 fontsize=font_size + 1)
    return ax


def plot_gear_power(gear, ax=None, *, title=None, font_size=8):
    """The power flow of one gear of a shift table (a :class:`~gearlib.gains.GearResult`): for
    every mesh its real power (measured from the frame) and its rolling power (measured from its
    carrier, what its friction acts on), per unit input power; the dashed line is the input power."""
    import numpy as np

    meshes = list(gear.meshes)
    ax = _axes(ax, (6.4, 3.0))
    x = np.arange(len(meshes))
    ax.bar(x - 0.2, [abs(m.real) for m in meshes], 0.4, color="tab:blue", label="real (from the frame)")
    ax.bar(x + 0.2, [m.rolling for m in meshes], 0.4, color="tab:orange", label="rolling (from the carrier)")
    ax.axhline(1.0, color="black", linestyle="--", linewidth=0.8)
    labels = [f"{a}-{b}\n(carrier {m.carrier})" for m, (a, b) in ((m, m.gears) for m in meshes)]
    ax.set_xticks(x, labels, fontsize=font_size)
    ax.set_ylabel("|power| / input power", fontsize=font_size + 1)
    ax.legend(fontsize=font_size, frameon=False, loc="upper left")
    top = max([1.0] + [abs(m.real) for m in meshes] + [m.rolling for m in meshes])
    ax.set_ylim(0, top * 1.25)
    ax.set_title(title if title is not None else f"gear {gear.name}: power through every mesh", fontsize=font_size + 1)
    return ax
