"""Drawings of kinematic units and common linkages (chapter 2).

Every function takes ``ax=`` (or ``axes=`` for several panels), draws, and returns it; none
calls ``plt.show()`` or changes matplotlib's settings. Convention of Liu, Chen and Chang:
heavy edges are gear pairs, thin edges turning pairs labelled with their axis, a g-g thin edge
(two coaxial gears after coaxial re-arrangement) is a double line. Common links are drawn
with a coloured ring.
"""

from __future__ import annotations
import math
from ..mechanism.data import Mechanism
from .fractionation import kinematic_units
from . import _draw
from ._draw import _axes, _draw_unit_at, _edge, _finish, _node, _unit_layout, draw_unit, unit_colors
from ..mechanism._accept import takes_mechanism

__all__ = ['draw_unit', 'draw_units', 'unit_colors', 'draw_units_gallery', 'draw_displacement_graph', 'draw_fractionation', 'draw_ku_catalogue']


def draw_units(frac, ax=None, *, pos=None, title=None, ground=None, linkages=True, legend=True, font_size=10):
    """The graph of a mechanism with its kinematic units in colour and the common linkages
    marked: a broad band for a 2-link chain, a shaded triangle for a coaxial triangle.

    *frac* is a :class:`~gearlib.Fractionation` or a mechanism (fractionated first).
    """
    if isinstance(frac, Mechanism):
        frac = kinematic_units(frac)
    return _draw.draw_units(frac, ax=ax, pos=pos, title=title, ground=ground, linkages=linkages, legend=legend,
                            font_size=font_size)


def draw_units_gallery(names, axes=None, *, font_size=8):
    """:func:`~gearlib.draw_units` for several catalogue mechanisms (names or mechanisms) in a grid: the
    static twin of :func:`gearlib.unit_explorer`."""
    from .. import catalog

    mechs = [catalog.load(n) if isinstance(n, str) else n for n in names]
    if axes is None:
        import matplotlib.pyplot as plt

        cols = min(3, len(mechs))
        rows = math.ceil(len(mechs) / cols)
        _, axes = plt.subplots(rows, cols, figsize=(4.6 * cols, 4.0 * rows), squeeze=False)
    flat = list(getattr(axes, "flat", axes))
    for ax, m in zip(flat, mechs):
        draw_units(m, ax=ax, font_size=font_size)
    for ax in flat[len(mechs):]:
        ax.axis("off")
    return axes


@takes_mechanism
def draw_displacement_graph(mech: Mechanism, ax=None, *, pos=None, separated=False, title=None, font_size=10):
    """Step 1 (and, with ``separated=True``, step 2): the gears joined by heavy edges, each
    labelled with its carrier; separated, each unit's piece is drawn on its own."""
    from ..mechanism.plot import graph_layout

    ax = _axes(ax)
    frac = kinematic_units(mech)
    colors = unit_colors(len(frac.units))
    if separated:
        pos, x0 = {}, 0.0
        for i, unit in enumerate(frac.units):
            width = len(unit.gears) - 1
            lay = _unit_layout(unit, origin=(x0 + width / 2, 0.0))
            _draw_unit_at(ax, unit, lay, colors[i], carrier=False, shared=False, font=font_size - 1)
            pos.update({f"{i}:{g}": lay[g] for g in unit.gears})
            x0 += width + 1.6
        return _finish(ax, pos, "separated displacement graph" if title is None else title)
    pos = dict(pos or graph_layout(mech))
    gears = {g for gp in mech.gear_pairs for g in gp.gears}
    for unit in frac.units:
        for gp in unit.gear_pairs + unit.redundant_pairs:
            u, v = gp.gears
            _edge(ax, pos[u], pos[v], lw=4.0, color="black", label=f"{gp.carrier}", font=font_size - 1)
    for x in gears:
        _node(ax, pos[x], x, size=380, font=font_size)
    return _finish(ax, {g: pos[g] for g in gears}, "displacement graph" if title is None else title)


@takes_mechanism
def draw_fractionation(mech: Mechanism, axes=None, *, font_size=9):
    """The four steps of kinematic fractionation side by side: (a) the graph, (b) the
    displacement graph, (c) the separated displacement graph, (d) the units."""
    from ..mechanism.plot import draw_graph, graph_layout

    if axes is None:
        import matplotlib.pyplot as plt

        _, axes = plt.subplots(2, 2, figsize=(10, 7.4))
    axes_in = axes
    axes = list(getattr(axes, "flat", axes))
    frac = kinematic_units(mech)
    pos = graph_layout(mech)
    draw_graph(mech, ax=axes[0], pos=pos, title="(a) graph", font_size=font_size, node_size=300)
    draw_displacement_graph(mech, ax=axes[1], pos=pos, title="(b) displacement graph", font_size=font_size)
    draw_displacement_graph(mech, ax=axes[2], separated=True, title="(c) one carrier per piece",
                            font_size=font_size)
    ax = axes[3]
    colors = unit_colors(len(frac.units))
    allpos, x0 = {}, 0.0
    for i, unit in enumerate(frac.units):
        width = max(len(unit.gears) - 1, 1)
        lay = _unit_layout(unit, origin=(x0 + width / 2, 0.0))
        _draw_unit_at(ax, unit, lay, colors[i], font=font_size - 1)
        ax.text(x0 + width / 2, -0.75, f"{unit.name}\n{unit.label}", ha="center", va="top", fontsize=font_size - 1)
        allpos.update({f"{i}:{x}": p for x, p in lay.items()})
        x0 += width + 1.6
    allpos["_"] = (x0 / 2 - 0.8, -1.3)
    _finish(ax, allpos, "(d) kinematic units")
    return axes_in


def draw_ku_catalogue(axes=None, *, variants: bool = False, names=None, font_size=8):
    """The catalogue of kinematic units with up to five links (and their S and D variants);
    *names* (such as ``["K3-1", "K4-1", "K4-1S"]``) draws only those entries, in the
    catalogue's order."""
    from ..errors import InputError
    from .catalogue import ku_catalogue

    entries = ku_catalogue(variants=variants or any("S" in n or "D" in n for n in names or ()))
    if names is not None:
        known = {e.name for e in entries}
        unknown = [n for n in names if n not in known]
        if unknown:
            raise InputError(f"no unit {unknown[0]!r} in the catalogue; its names are {', '.join(sorted(known))}")
        entries = [e for e in entries if e.name in set(names)]
    if axes is None:
        import matplotlib.pyplot as plt

        cols = 6 if variants else 5
        rows = math.ceil(len(entries) / cols)
        _, axes = plt.subplots(rows, cols, figsize=(2.3 * cols, 2.3 * rows))
    flat = list(getattr(axes, "flat", axes))
    for ax, entry in zip(flat, entries):
        draw_unit(entry, ax=ax, title=entry.name, font_size=font_size,
                  color="tab:red" if entry.gg_edges else "tab:blue")
    for ax in flat[len(entries):]:
        ax.axis("off")
    return axes
