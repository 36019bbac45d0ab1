"""Drawing of lever diagrams (chapter 3): levers side by side, a state's speeds as arrows.

:func:`~gearlib.gains.lever_geometry` computes what :func:`~gearlib.draw_levers` draws (nodes, arrow tips, velocity
lines, brakes and clutches), so that a test can check it: each lever is a vertical bar, each
member a node at its place along it, each speed a horizontal arrow from its node, and the
arrows of one lever end on one straight line, the velocity line.
"""

from __future__ import annotations

from .lever import LeverDiagram, lever_diagram

__all__ = ["lever_geometry", "draw_levers"]

_GAP = 1.0      # between levers
_REACH = 0.38   # the longest arrow, as a fraction of the gap


def lever_geometry(levers, state=None) -> dict:
    """What :func:`~gearlib.draw_levers` draws, in drawing coordinates.

    Returns a mapping with ``nodes``, a list of ``(lever, link, role, x, y)``; ``speeds``,
    ``{link: speed}`` (floats, or empty without a state); ``tips``, ``(lever, link, x, y)`` where
    each arrow ends; ``lines``, ``(lever, (x0, y0), (x1, y1))`` the velocity line of each lever;
    ``links``, ``(link, (x0, y0), (x1, y1))`` joining a member's nodes on two levers; and
    ``elements``, ``(name, kind, links, engaged, points)`` for the brakes and clutches.
    """
    diag = levers if isinstance(levers, LeverDiagram) else lever_diagram(levers)
    mech = diag.mechanism
    span = max((max(n.position for n in lv.nodes) - min(n.position for n in lv.nodes) for lv in diag.levers),
               default=1) or 1
    nodes = []
    for i, lv in enumerate(diag.levers):
        for n in lv.nodes:
            nodes.append((i, n.link, n.role, i * _GAP, float(n.position / span)))
    speeds = {}
    engaged = set()
    held = set()
    if state is not None:
        from .lever import _solution

        sol = _solution(mech, state)
        speeds = {k: float(v) for k, v in sol.items()}
        held = {sol.constraints.ground, *sol.constraints.held}
        if isinstance(state, str):
            engaged = set(mech.gear_state(state).engaged)
    top = max((abs(speeds.get(link, 0.0)) for _, link, _, _, _ in nodes), default=0.0)
    k = _REACH * _GAP / top if top > 0 else 0.0
    tips = [(i, link, x + k * speeds[link], y) for i, link, _, x, y in nodes if link in speeds]
    lines = []
    for i in range(len(diag.levers)):
        pts = [(x, y) for j, _, x, y in tips if j == i]
        if len(pts) >= 2:
            (xa, ya), (xb, yb) = min(pts, key=lambda p: p[1]), max(pts, key=lambda p: p[1])
            lines.append((i, (xa, ya), (xb, yb)))
    where: dict = {}
    for _i, link, _, x, y in nodes:
        where.setdefault(link, []).append((x, y))
    joins = []
    for link, pts in where.items():
        for a, b in zip(pts, pts[1:]):
            joins.append((link, a, b))
    elements = []
    for e in mech.shift_elements:
        if e.kind == "brake":
            pts = tuple(where.get(e.links[0], ()))
        else:
            u, v = e.links
            pu, pv = where.get(u, ()), where.get(v, ())
            pts = tuple(min(((a, b) for a in pu for b in pv), key=lambda ab: abs(ab[0][0] - ab[1][0]) +
                            abs(ab[0][1] - ab[1][1]), default=()))
        elements.append((e.name, e.kind, e.links, e.name in engaged, pts))
    braked = {e.links[0] for e in mech.shift_elements if e.kind == "brake" and e.name in engaged}
    if state is None and mech.ground is not None:   # the housing is held in every state
        held = {mech.ground}
    for link in sorted(held - braked, key=str):   # held in this state (the ground, a held link)
        if link in where:
            elements.append(("", "brake", (link,), True, tuple(where[link])))
    return {"nodes": nodes, "speeds": speeds, "tips": tips, "lines": lines, "links": joins, "elements": elements,
            "scale": k}


def draw_levers(levers, ax=None, *, state=None, title=None, font_size=9):
    """Draw the lever diagram of a mechanism (or a :class:`~gearlib.gains.LeverDiagram`): one vertical
    lever per planetary set (or per combined set), each member a node labelled with its link id
    and role (``S`` sun, ``C`` carrier, ``R`` ring); brakes as hatched ground marks, clutches as
    dashed links between the members they join, both named.

    ``state`` (a gear of the schedule such as ``"1st"``, a mapping ``{"ground": ..., "inputs": ...,
    "held": ..., "joined": ...}``, or a :class:`~gearlib.Solution`) adds each member's speed as a
    horizontal arrow (to scale, the largest the longest) and each lever's velocity line through
    the arrow tips; in a gear of the schedule, the engaged elements are drawn solid.

    >>> import gearlib as gl
    >>> ax = gl.draw_levers(gl.catalog.simpson(), state={"ground": 0, "inputs": {2: 1}, "held": [4]})
    """
    from matplotlib.collections import LineCollection

    diag = levers if isinstance(levers, LeverDiagram) else lever_diagram(levers)
    geo = lever_geometry(diag, state)
    n = len(diag.levers)
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(min(9.0, 3.2 + 1.9 * n), 4.2), facecolor="white")
    for i in range(n):
        ys = [y for j, _, _, _, y in geo["nodes"] if j == i]
        ax.plot([i * _GAP] * 2, [min(ys), max(ys)], color="black", linewidth=3, solid_capstyle="round", zorder=2)
    for _link, a, b in geo["links"]:
        ax.plot([a[0], b[0]], [a[1], b[1]], color="0.6", linewidth=1.0, linestyle=":", zorder=1)
    last: dict = {}
    for i, link, role, x, y in sorted(geo["nodes"], key=lambda t: (t[0], t[4])):
        ax.plot([x], [y], marker="o", markersize=7, color="white", markeredgecolor="black", zorder=4)
        right = geo["speeds"].get(link, 0.0) < 0   # the label on the side its arrow leaves free
        ty = max(y, last.get((i, right), -1e9) + 0.055)   # two nodes close together: labels apart
        last[i, right] = ty
        ax.text(x + (0.06 if right else -0.06) * _GAP, ty, f"{link} {role}", ha="left" if right else "right",
                va="center", fontsize=font_size, zorder=5)
    for name, kind, _links, on, pts in geo["elements"]:
        style = dict(color="black" if on else "0.55", linewidth=1.6 if on else 1.0)
        if kind == "brake":   # a ground mark left of the node's label, named
            for x, y in pts:
                x0, x1 = x - 0.46 * _GAP, x - 0.36 * _GAP
                ax.plot([x0, x1], [y, y], **style, zorder=3)
                ax.plot([x1, x - 0.3 * _GAP], [y, y], color=style["color"], linewidth=0.8, linestyle=":")
                ax.add_collection(LineCollection([((x0 + 0.025 * t, y - 0.025), (x0 + 0.025 * t + 0.02, y))
                                                  for t in range(4)], colors=style["color"], linewidths=0.8))
                ax.text(x0, y + 0.012, name, ha="right", va="bottom", fontsize=font_size - 1, style="italic")
        elif len(pts) == 2:
            (xa, ya), (xb, yb) = pts
            ax.plot([xa, xb], [ya, yb], **style, linestyle="-" if on else "--", zorder=1)
            ax.text((xa + xb) / 2, (ya + yb) / 2, name, ha="center", va="bottom", fontsize=font_size - 1,
                    style="italic", bbox=dict(boxstyle="round,pad=0.1", facecolor="white", edgecolor="none"))
    if geo["speeds"]:
        for _i, link, _role, x, y in geo["nodes"]:
            w = geo["speeds"].get(link)
            if w is None:
                continue
            tip = x + geo["scale"] * w
            if abs(tip - x) > 1e-9:
                ax.annotate("", xy=(tip, y), xytext=(x, y), arrowprops=dict(arrowstyle="-|>", color="tab:blue",
                                                                          linewidth=1.4, shrinkA=0, shrinkB=0),
                            zorder=3)
        for _i, (xa, ya), (xb, yb) in geo["lines"]:
            ax.plot([xa, xb], [ya, yb], color="tab:red", linewidth=1.3, zorder=3)
    label = f"gear {state}" if isinstance(state, str) else ("speeds of the state given" if state is not None else "")
    name = diag.mechanism.name
    ax.set_title(title if title is not None else (f"{name}\nlever diagram" + (f", {label}" if label else "")),
                 fontsize=font_size + 1)
    ax.set_xlim(-0.6 * _GAP, (n - 1) * _GAP + 0.55 * _GAP)
    ys = [y for *_, y in geo["nodes"]]
    ax.set_ylim(min(ys) - 0.12, max(ys) + 0.12)
    ax.set_facecolor("white")
    ax.axis("off")
    return ax
