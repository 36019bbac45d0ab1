"""Drawing primitives for kinematic units (chapters 2 and 3): nodes, heavy and thin edges,
one unit, and a fractionation already computed.

:meth:`Fractionation.plot <gearlib.Fractionation.plot>` and :mod:`gearlib.gains.drawing` draw
with these; the public drawings, which may fractionate a mechanism first, are in
:mod:`gearlib.units.drawing`. Convention of Liu, Chen and Chang: heavy edges are gear pairs,
thin edges turning pairs labelled with their axis, a g-g thin edge (two coaxial gears after
coaxial re-arrangement) is a double line. Common links are drawn with a coloured ring.
"""

from __future__ import annotations
import math
from .unit import KinematicUnit

__all__ = ['draw_unit', 'draw_units', 'unit_colors']


_PALETTE = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink",
            "tab:olive", "tab:cyan", "tab:gray")


def unit_colors(n: int) -> list:
    """The colour of each of *n* units (cycled)."""
    return [_PALETTE[i % len(_PALETTE)] for i in range(n)]


def _axes(ax, figsize=(5.0, 4.0)):
    if ax is not None:
        from ..mechanism.plot import _axes as checked

        return checked(ax)
    import matplotlib.pyplot as plt

    _, ax = plt.subplots(figsize=figsize)
    return ax


def _edge(ax, p, q, *, rad=0.0, lw=1.2, color="black", double=False, zorder=1, label=None, font=9, batch=None):
    """One edge; a straight one goes into *batch* (``{(lw, color, zorder): segments}``, drawn
    by :func:`_flush` as one collection per style) when given, else it is a Line2D."""
    from matplotlib.patches import FancyArrowPatch

    style = dict(arrowstyle="-", connectionstyle=f"arc3,rad={rad}", shrinkA=0, shrinkB=0)
    if rad == 0 and not double and batch is not None:
        batch.setdefault((lw, color, zorder), []).append((p, q))
    elif rad == 0 and not double:  # a straight line: a plain Line2D draws faster than a patch
        ax.plot([p[0], q[0]], [p[1], q[1]], linewidth=lw, color=color, zorder=zorder, solid_capstyle="butt")
    elif double:
        ax.add_patch(FancyArrowPatch(p, q, linewidth=lw + 3.0, color=color, zorder=zorder, **style))
        ax.add_patch(FancyArrowPatch(p, q, linewidth=lw + 0.6, color="white", zorder=zorder + 0.1, **style))
    else:
        ax.add_patch(FancyArrowPatch(p, q, linewidth=lw, color=color, zorder=zorder, **style))
    if label is not None:
        (x0, y0), (x1, y1) = p, q
        dx, dy = x1 - x0, y1 - y0
        norm = math.hypot(dx, dy) or 1.0
        mx, my = (x0 + x1) / 2 + rad / 2 * dy, (y0 + y1) / 2 - rad / 2 * dx  # the arc's midpoint
        off = 0.08 if rad == 0 else -0.08 * (1 if rad > 0 else -1)
        ax.text(mx - dy / norm * off, my + dx / norm * off, label, fontsize=font, ha="center", va="center",
                style="italic", color=color if color != "white" else "black", zorder=5)


def _flush(ax, batch) -> None:
    """Draw the straight edges gathered by :func:`_edge`: one LineCollection per style (a
    widget redraws a graph per frame, and each Line2D costs more than its drawing)."""
    from matplotlib.collections import LineCollection

    for (lw, color, zorder), segments in batch.items():
        ax.add_collection(LineCollection(segments, linewidths=lw, colors=color, zorder=zorder, capstyle="butt"),
                          autolim=True)
    batch.clear()


def _node(ax, xy, text, *, face="white", edge="black", ring=None, marker="o", size=380, font=10):
    x, y = xy
    if ring:
        ax.scatter([x], [y], s=size * 2.2, marker=marker, facecolor=ring, edgecolor="none", alpha=0.45, zorder=2)
    ax.scatter([x], [y], s=size, marker=marker, facecolor=face, edgecolor=edge, linewidth=1.5, zorder=3)
    ax.text(x, y, str(text), ha="center", va="center", fontsize=font, zorder=4,
            color="white" if face == "black" else "black")


def _finish(ax, pos, title):
    xs = [p[0] for p in pos.values()] or [0]
    ys = [p[1] for p in pos.values()] or [0]
    pad = 0.45
    ax.set_xlim(min(xs) - pad, max(xs) + pad)
    ax.set_ylim(min(ys) - pad, max(ys) + pad)
    ax.set_aspect("equal")
    ax.axis("off")
    if title is not None:
        ax.set_title(title, fontsize=10)
    return ax


def _unit_layout(unit: KinematicUnit, origin=(0.0, 0.0), width=None):
    """Carrier on top, gears in a row ordered along the gear tree."""
    adj: dict = {}
    for gp in unit.gear_pairs + unit.redundant_pairs:
        a, b = gp.gears
        adj.setdefault(a, []).append(b)
        adj.setdefault(b, []).append(a)
    leaves = [g for g in unit.gears if len(adj.get(g, ())) <= 1]
    start = leaves[0] if leaves else unit.gears[0]
    order, stack, seen = [], [start], set()
    while stack:
        g = stack.pop()
        if g in seen:
            continue
        seen.add(g)
        order.append(g)
        stack.extend(sorted((h for h in adj.get(g, ()) if h not in seen), key=lambda h: -len(adj.get(h, ())))[::-1])
    n = len(order)
    step = 1.0 if width is None else width / max(n - 1, 1)
    x0, y0 = origin
    pos = {g: (x0 + (i - (n - 1) / 2) * step, y0) for i, g in enumerate(order)}
    pos[unit.carrier] = (x0, y0 + 1.3)
    return pos


def _draw_unit_at(ax, unit, pos, color, *, carrier=True, shared=True, font=9):
    heavy = {frozenset(gp.gears) for gp in unit.gear_pairs + unit.redundant_pairs}
    xs = {g: pos[g][0] for g in unit.gears}
    for pair in heavy:
        a, b = sorted(pair, key=lambda g: xs[g])  # left to right: arcs bend below the row
        adjacent = abs(xs[a] - xs[b]) < 1.01 * min((abs(xs[u] - xs[v]) for u in xs for v in xs if u != v),
                                                    default=1.0)
        _edge(ax, pos[a], pos[b], rad=0.0 if adjacent else 0.35, lw=4.0, color=color, zorder=1)
        if not carrier:
            (x0, y0), (x1, y1) = pos[a], pos[b]
            ax.text((x0 + x1) / 2, (y0 + y1) / 2 - (0.22 if adjacent else 0.5), str(unit.carrier),
                    fontsize=font, ha="center", color=color)
    if carrier:
        for e in unit.thin_edges:
            u, v = e.links
            if e.kind == "g-g":
                u, v = sorted((u, v), key=lambda g: pos[g][0])
                _edge(ax, pos[u], pos[v], rad=0.5, lw=1.0, double=True, label=e.axis, font=font)
            else:
                _edge(ax, pos[u], pos[v], lw=1.0, label=e.axis, font=font)
    shared_set = set(unit.shared) if shared else set()
    for x in unit.links:
        if x == unit.carrier and not carrier:
            continue
        _node(ax, pos[x], x, ring=color if x in shared_set else None, size=300, font=font)


def draw_unit(unit, ax=None, *, color="tab:blue", title=None, font_size=9):
    """Draw one kinematic unit (or a catalogue entry): carrier on top, gears below, heavy gear
    pairs, thin g-c edges and double g-g edges labelled with their axis; common links ringed."""
    from .catalogue import CatalogueEntry

    if isinstance(unit, CatalogueEntry):
        unit = unit.unit()
    ax = _axes(ax, (3.0, 2.6))
    pos = _unit_layout(unit)
    _draw_unit_at(ax, unit, pos, color, font=font_size)
    return _finish(ax, pos, f"{unit.name} ({unit.label})" if title is None else title)


def draw_units(frac, ax=None, *, pos=None, title=None, ground=None, linkages=True, legend=True, font_size=10):
    """The graph of a mechanism with its kinematic units in colour and the common linkages
    marked: a broad band for a 2-link chain, a shaded triangle for a coaxial triangle.

    *frac* is a :class:`~gearlib.Fractionation` (:func:`gearlib.draw_units` also takes a
    mechanism).
    """
    from matplotlib.patches import Patch, Polygon

    from ..mechanism.plot import graph_layout

    mech = frac.mechanism
    ax = _axes(ax)
    pos = dict(pos or graph_layout(mech))
    colors = unit_colors(len(frac.units))
    ground = mech.ground if ground is None else mech.resolve(ground)
    if linkages:
        for c in frac.linkages:
            pts = [pos[x] for x in c.links]
            if c.kind == "coaxial triangle":
                ax.add_patch(Polygon(pts, closed=True, facecolor="gold", alpha=0.35, edgecolor="goldenrod",
                                     linewidth=1.0, zorder=0))
            elif c.kind == "2-link chain":
                ax.plot(*zip(*pts), color="gold", linewidth=14, alpha=0.45, solid_capstyle="round", zorder=0)
    seen: dict = {}
    batch: dict = {}
    for tp in mech.turning_pairs:
        u, v = tp.links
        k = seen.get(frozenset((u, v)), 0)
        seen[frozenset((u, v))] = k + 1
        _edge(ax, pos[u], pos[v], rad=0.25 * k, lw=1.1, label=tp.axis, font=font_size - 1, batch=batch)
    unit_of = {}
    for i, unit in enumerate(frac.units):
        for gp in unit.gear_pairs + unit.redundant_pairs:
            u, v = gp.gears
            k = seen.get(frozenset((u, v)), 0)
            seen[frozenset((u, v))] = k + 1
            _edge(ax, pos[u], pos[v], rad=0.25 * k, lw=4.0, color=colors[i], zorder=1, batch=batch)
        for x in unit.links:
            unit_of.setdefault(x, []).append(i)
    _flush(ax, batch)
    # markers as Line2D (one per style): a scatter collection finds the extent of its Bezier
    # circles by solving polynomials at every draw, which cost a widget frame a quarter of its time
    ringed: dict = {}
    for x in mech.link_ids:
        if len(unit_of.get(x, [])) > 1:
            ringed.setdefault(colors[unit_of[x][0]], []).append(pos[x])
    for color, pts in ringed.items():
        ax.plot(*zip(*pts), linestyle="none", marker="o", markersize=math.sqrt(420 * 2.2), markerfacecolor=color,
                markeredgecolor="none", alpha=0.45, zorder=2)
    for marker, face, group in (("o", "white", [x for x in mech.link_ids if x != ground]),
                                ("s", "0.75", [x for x in mech.link_ids if x == ground])):
        if group:
            ax.plot([pos[x][0] for x in group], [pos[x][1] for x in group], linestyle="none", marker=marker,
                    markersize=math.sqrt(420), markerfacecolor=face, markeredgecolor="black", markeredgewidth=1.5,
                    zorder=3)
    for x in mech.link_ids:
        ax.text(*pos[x], str(x), ha="center", va="center", fontsize=font_size, zorder=4)
    handles = [Patch(color=colors[i], label=f"{u.name} {u.label}") for i, u in enumerate(frac.units)]
    if handles and legend:
        ax.legend(handles=handles, fontsize=max(8, font_size - 2), loc="upper center", bbox_to_anchor=(0.5, 0.02),
                  ncols=min(2, len(handles)), frameon=False)
    return _finish(ax, pos, mech.name if title is None else title)
