"""Drawing of a propagation: from the inputs through the units to the output (chapter 3).

:func:`draw_propagation` takes ``ax=``, draws and returns it. It draws a
:class:`~gearlib.Propagation` or a :class:`~gearlib.gains.Plan` (whose ``.plot()``
comes here).
"""

from __future__ import annotations
from ..units._draw import _axes, _finish

__all__ = ['draw_propagation']


def draw_propagation(prop, ax=None, *, title=None, font_size=9):
    """The propagation structure from inputs to output: input nodes, units (with their type)
    and the output, arrows labelled with the local input they pass (a
    :class:`~gearlib.Propagation` or a :class:`~gearlib.gains.Plan`)."""
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
        ax.text((x0 + x1) / 2, (y0 + y1) / 2 + 0.18, _tex(d.get("signal", "")), fontsize=font_size - 1,
                ha="center", color=color)
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


def _tex(name: str) -> str:
    if name.startswith("theta_"):
        return rf"$\theta_{{{name[6:]}}}$"
    return name
