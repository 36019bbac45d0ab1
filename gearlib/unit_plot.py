"""Drawings of kinematic units, common linkages and propagation paths (chapters 2 and 3).

Every function takes ``ax=`` (or ``axes=`` for several panels), draws, and returns it; none
calls ``plt.show()`` or changes matplotlib's settings. Convention of Liu, Chen and Chang:
heavy edges are gear pairs, thin edges turning pairs labelled with their axis, a g-g thin edge
(two coaxial gears after coaxial re-arrangement) is a double line. Common links are drawn
with a coloured ring.
"""

from __future__ import annotations

import math

from .mechanism import Mechanism
from .units import KinematicUnit, kinematic_units

__all__ = ["draw_unit", "draw_units", "draw_units_gallery", "draw_displacement_graph", "draw_fractionation",
           "draw_ku_catalogue", "draw_propagation", "unit_colors"]

_PALETTE = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink",
            "tab:olive", "tab:cyan", "tab:gray")


def unit_colors(n: int) -> list:
    """The colour of each of *n* units (cycled)."""
    return [_PALETTE[i % len(_PALETTE)] for i in range(n)]


def _axes(ax, figsize=(5.0, 4.0)):
    if ax is not None:
        return ax
    import matplotlib.pyplot as plt

    _, ax = plt.subplots(figsize=figsize)
    return ax


def _edge(ax, p, q, *, rad=0.0, lw=1.2, color="black", double=False, zorder=1, label=None, font=9):
    from matplotlib.patches import FancyArrowPatch

    style = dict(arrowstyle="-", connectionstyle=f"arc3,rad={rad}", shrinkA=0, shrinkB=0)
    if rad == 0 and not double:  # a straight line: a plain Line2D draws faster than a patch
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
    from .ku_types import CatalogueEntry

    if isinstance(unit, CatalogueEntry):
        unit = unit.unit()
    ax = _axes(ax, (3.0, 2.6))
    pos = _unit_layout(unit)
    _draw_unit_at(ax, unit, pos, color, font=font_size)
    return _finish(ax, pos, f"{unit.name} ({unit.label})" if title is None else title)


def draw_units(frac, ax=None, *, pos=None, title=None, ground=None, linkages=True, legend=True, font_size=10):
    """The graph of a mechanism with its kinematic units in colour and the common linkages
    marked: a broad band for a 2-link chain, a shaded triangle for a coaxial triangle.

    *frac* is a :class:`~gearlib.units.Fractionation` or a mechanism.
    """
    from matplotlib.patches import Patch, Polygon

    from .plot import graph_layout

    if isinstance(frac, Mechanism):
        frac = kinematic_units(frac)
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
    for tp in mech.turning_pairs:
        u, v = tp.links
        k = seen.get(frozenset((u, v)), 0)
        seen[frozenset((u, v))] = k + 1
        _edge(ax, pos[u], pos[v], rad=0.25 * k, lw=1.1, label=tp.axis, font=font_size - 1)
    unit_of = {}
    for i, unit in enumerate(frac.units):
        for gp in unit.gear_pairs + unit.redundant_pairs:
            u, v = gp.gears
            k = seen.get(frozenset((u, v)), 0)
            seen[frozenset((u, v))] = k + 1
            _edge(ax, pos[u], pos[v], rad=0.25 * k, lw=4.0, color=colors[i], zorder=1)
        for x in unit.links:
            unit_of.setdefault(x, []).append(i)
    ringed = [x for x in mech.link_ids if len(unit_of.get(x, [])) > 1]
    if ringed:
        ax.scatter([pos[x][0] for x in ringed], [pos[x][1] for x in ringed], s=420 * 2.2, zorder=2, alpha=0.45,
                   facecolor=[colors[unit_of[x][0]] for x in ringed], edgecolor="none")
    for marker, face, group in (("o", "white", [x for x in mech.link_ids if x != ground]),
                                ("s", "0.75", [x for x in mech.link_ids if x == ground])):
        if group:
            ax.scatter([pos[x][0] for x in group], [pos[x][1] for x in group], s=420, marker=marker,
                       facecolor=face, edgecolor="black", linewidth=1.5, zorder=3)
    for x in mech.link_ids:
        ax.text(*pos[x], str(x), ha="center", va="center", fontsize=font_size, zorder=4)
    handles = [Patch(color=colors[i], label=f"{u.name} {u.label}") for i, u in enumerate(frac.units)]
    if handles and legend:
        ax.legend(handles=handles, fontsize=8, loc="upper center", bbox_to_anchor=(0.5, 0.02),
                  ncols=min(3, len(handles)), frameon=False)
    return _finish(ax, pos, mech.name if title is None else title)


def draw_units_gallery(names, axes=None, *, font_size=8):
    """:func:`draw_units` for several catalogue mechanisms (names or mechanisms) in a grid: the
    static twin of :func:`gearlib.unit_widgets.unit_explorer`."""
    from . import catalog

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


def draw_displacement_graph(mech: Mechanism, ax=None, *, pos=None, separated=False, title=None, font_size=10):
    """Step 1 (and, with ``separated=True``, step 2): the gears joined by heavy edges, each
    labelled with its carrier; separated, each unit's piece is drawn on its own."""
    from .plot import graph_layout

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


def draw_fractionation(mech: Mechanism, axes=None, *, font_size=9):
    """The four steps of kinematic fractionation side by side: (a) the graph, (b) the
    displacement graph, (c) the separated displacement graph, (d) the units."""
    from .plot import draw_graph, graph_layout

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


def draw_ku_catalogue(axes=None, *, variants: bool = False, font_size=8):
    """The catalogue of kinematic units with up to five links (and their S and D variants)."""
    from .ku_types import ku_catalogue

    entries = ku_catalogue(variants=variants)
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


def draw_propagation(prop, ax=None, *, title=None, font_size=9):
    """The propagation structure from inputs to output: input nodes, units (with their type)
    and the output, arrows labelled with the local input they pass (a
    :class:`~gearlib.gains.Propagation` or a :class:`~gearlib.propagation.Plan`)."""
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
