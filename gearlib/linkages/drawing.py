"""Drawings of linkages: a sketch at a pose, the coupling graph, the powers along a task.

Every function takes ``ax=`` (a new figure when None), draws and returns the axes; none
changes matplotlib's global state.

* :func:`~gearlib.linkages.draw_linkage` - a kinematic sketch: links as bars between their joints, revolute and
  universal joints as circles, a prismatic pair as a cylinder and its rod (a split pair shows
  its two annuli), the ground hatched, loads as arrows; spatial linkages in an oblique view;
* :func:`~gearlib.linkages.draw_linkage_graph` - the coupling graph: links as vertices, couplings as directed
  edges (a split pair's two couplings side by side, a virtual coupling dashed, the chords of
  the spanning tree grey);
* :func:`~gearlib.linkages.plot_task_powers` - the ports' powers and the friction losses against time.
"""

from __future__ import annotations

import math

import numpy as np

from ..mechanism.plot import _axes
from .couplings import network

__all__ = ["draw_linkage", "draw_linkage_graph", "plot_task_powers"]


def _projector(planar: bool, view):
    if planar:
        return lambda p: (float(p[0]), float(p[1]))
    az, el = (math.radians(v) for v in (view or (-25.0, 25.0)))
    # an oblique parallel projection: x right and back, y to the right, z up
    ex = np.array([math.cos(az), math.sin(az), 0.0])
    ey = np.array([-math.sin(az) * math.sin(el), math.cos(az) * math.sin(el), math.cos(el)])
    return lambda p: (float(np.dot(ex, p)), float(np.dot(ey, p)))


def draw_linkage(linkage, pose=None, ax=None, *, view=None, labels: bool = True, path=None, font_size=9,
                 color="black"):
    """A sketch of *linkage* at *pose* (default: the reference pose as drawn in the file).
    *view* ``(azimuth, elevation)`` in degrees for a spatial linkage; *path* a list of points
    (a task's trajectory) drawn dotted."""
    from .pose import _I3, Pose

    if pose is None:
        n = len(linkage.links)
        pose = Pose(linkage, np.tile(_I3, (n, 1, 1)), np.zeros((n, 3)), {k: i for i, k in enumerate(linkage.link_ids)})
    ax = _axes(ax, (5.0, 4.2))
    proj = _projector(linkage.planar, view)
    ground = linkage.ground
    points: dict = {}  # link -> list of joint points on it (world, at the pose)
    for j in linkage.joints:
        p = pose.point(j.tail, j.point)
        for link in j.links:
            points.setdefault(link, []).append((j, p))
    # links: a bar between consecutive joints (a polygon for three or more: a platform); the
    # tail of a prismatic pair (a cylinder) thick and grey, its head (a rod) black
    cylinders = {j.tail for j in linkage.joints if j.kind in ("prismatic", "cylindrical")}
    for link, items in points.items():
        if link == ground:
            continue
        pts = [proj(p) for j, p in items if j.kind != "prismatic"] + [proj(_prismatic_end(pose, j, link))
                                                                         for j, _ in items if j.kind == "prismatic"]
        if len(pts) >= 3:
            c = np.mean(pts, axis=0)
            pts = sorted(pts, key=lambda q: math.atan2(q[1] - c[1], q[0] - c[0]))
            xs, ys = zip(*(pts + pts[:1]))
            ax.fill(xs, ys, facecolor="0.9", edgecolor=color, lw=1.6, zorder=1)
        elif len(pts) == 2:
            (x0, y0), (x1, y1) = pts
            wide = link in cylinders
            ax.plot([x0, x1], [y0, y1], color="0.55" if wide else color, lw=6.0 if wide else 2.0,
                    solid_capstyle="round", zorder=2 if wide else 3)
    base = [proj(p) for j, p in points.get(ground, []) if j.kind != "prismatic"]
    if not linkage.planar and len(base) >= 3:  # the ground of a spatial linkage: its joints' polygon
        c = np.mean(base, axis=0)
        base = sorted(base, key=lambda q: math.atan2(q[1] - c[1], q[0] - c[0]))
        xs, ys = zip(*(base + base[:1]))
        ax.fill(xs, ys, facecolor="none", edgecolor="0.45", hatch="////", lw=1.0, zorder=0)
    for j in linkage.joints:
        p = pose.point(j.tail, j.point)
        x, y = proj(p)
        if j.kind == "prismatic" or j.kind == "cylindrical":
            _draw_prismatic(ax, pose, j, proj, ground, color, labels, font_size)
            if j.split is not None:
                continue
        else:
            ax.scatter([x], [y], s=60 if j.kind != "spherical" else 80, facecolor="white", edgecolor=color, lw=1.4,
                       zorder=5)
        if ground in j.links and linkage.planar:
            _ground_mark(ax, x, y)
        if labels:
            ax.annotate(j.name, (x, y), xytext=(5, 5), textcoords="offset points", fontsize=font_size, zorder=6)
    for port in linkage.ports:
        if port.kind == "load":
            p = pose.point(port.link, port.point)
            x, y = proj(p)
            d = np.array(port.force if port.force is not None else (0.0, 0.0, 0.0), dtype=float)
            d = np.r_[d, 0.0] if len(d) == 2 else d
            span = _span(linkage, pose)
            dx, dy = np.subtract(proj(p + 0.18 * span * d), (x, y))
            ax.annotate("", (x + dx, y + dy), (x, y), arrowprops={"arrowstyle": "-|>", "color": "0.25", "lw": 1.6},
                        zorder=6)
            ax.scatter([x], [y], s=25, color="0.25", zorder=6)
            if labels:
                ax.annotate(port.name, (x, y), xytext=(-12, 4), textcoords="offset points", fontsize=font_size)
    if path is not None:
        xs, ys = zip(*(proj(np.r_[q, 0.0] if len(q) == 2 else np.asarray(q)) for q in path))
        ax.plot(xs, ys, ":", color="0.35", lw=1.2, zorder=0)
    ax.set_aspect("equal")
    ax.margins(0.12)
    ax.set_axis_off()
    return ax


def _span(linkage, pose) -> float:
    pts = np.array([pose.point(j.tail, j.point) for j in linkage.joints])
    return float(np.ptp(pts, axis=0).max()) or 1.0


def _prismatic_end(pose, j, link):
    """The point where a prismatic pair meets *link* in a sketch: its split point on that link,
    or the joint's point."""
    if j.split is not None:
        for k, on in enumerate(j.split_in):
            if on == link:
                return pose.point(on, j.split[k])
    return pose.point(j.tail, j.point)


def _draw_prismatic(ax, pose, j, proj, ground, color, labels, font_size):
    if j.split is not None:
        (a, b) = (pose.point(on, j.split[k]) for k, on in enumerate(j.split_in))
        for k, q in enumerate((a, b)):
            x, y = proj(q)
            ax.scatter([x], [y], s=55, marker="s" if k == 0 else "o", facecolor="0.6", edgecolor=color, zorder=5)
            if labels:
                ax.annotate(j.split_names[k], (x, y), xytext=(5, -9), textcoords="offset points",
                            fontsize=font_size - 1, color="0.3", zorder=6)
        return
    p = pose.point(j.tail, j.point)
    d = pose.direction(j.tail, j.axis)
    length = 0.35
    (x0, y0), (x1, y1) = proj(p - length * d), proj(p + length * d)
    ax.plot([x0, x1], [y0, y1], color="0.5", lw=1.0, ls="--", zorder=0)
    x, y = proj(p)
    ax.scatter([x], [y], s=160, marker="s", facecolor="white", edgecolor=color, lw=1.4, zorder=5)
    if ground in j.links:
        n = np.array([-d[1], d[0], 0.0]) * 0.08
        for s in np.linspace(-length, length, 7):
            q = p + s * d - n
            qx, qy = proj(q)
            ex, ey = proj(q - n * 0.6 + 0.05 * d)
            ax.plot([qx, ex], [qy, ey], color="0.4", lw=0.8, zorder=0)


def _ground_mark(ax, x, y):
    """Hatching under a joint to the ground."""
    w = 0.12
    ax.plot([x - w, x + w], [y - 0.07, y - 0.07], color="0.3", lw=1.2, zorder=1)
    for k in range(5):
        sx = x - w + k * w / 2
        ax.plot([sx, sx - 0.05], [y - 0.07, y - 0.13], color="0.3", lw=0.8, zorder=1)


def draw_linkage_graph(linkage, ax=None, *, pos=None, font_size=10, node_size=420):
    """The coupling graph ``G_C`` of *linkage*: links as vertices (the ground grey), couplings
    as directed edges from tail to head, virtual couplings dashed, chords grey, ports marked
    ``(in)``/``(out)``."""
    from matplotlib.patches import FancyArrowPatch

    net = network(linkage)
    ax = _axes(ax, (4.6, 4.0))
    ids = list(linkage.link_ids)
    if pos is None:
        pos = dict(linkage.layout) if linkage.layout else {k: (math.cos(2 * math.pi * i / len(ids) + math.pi / 2),
                                                                math.sin(2 * math.pi * i / len(ids) + math.pi / 2))
                                                            for i, k in enumerate(ids)}
    roles = {p.joint: p.role for p in linkage.ports if p.joint is not None}
    roles.update({p.name: p.role for p in linkage.ports if p.kind == "load"})
    chords = set(net.graph.chords)
    seen: dict = {}
    for c in net.couplings:
        key = frozenset((c.tail, c.head))
        k = seen.get(key, 0)
        seen[key] = k + 1
        rad = 0.0 if k == 0 else 0.35 * (1 if k % 2 else -1) * ((k + 1) // 2)
        colour = "0.6" if c.name in chords else "black"
        style = "--" if c.kind == "virtual" else "-"
        ax.add_patch(FancyArrowPatch(pos[c.tail], pos[c.head], arrowstyle="-|>", mutation_scale=12,
                                     connectionstyle=f"arc3,rad={rad}", linestyle=style, color=colour, lw=1.4,
                                     shrinkA=11, shrinkB=11, zorder=1))
        (x0, y0), (x1, y1) = pos[c.tail], pos[c.head]
        dx, dy = x1 - x0, y1 - y0
        norm = math.hypot(dx, dy) or 1.0
        nx_, ny_ = -dy / norm, dx / norm
        off = rad * norm / 2 + 0.09 * norm * (1 if rad >= 0 else -1)
        role = roles.get(c.joint if c.kind != "virtual" else c.name)
        tag = {"input": " (in)", "output": " (out)"}.get(role, "") if (c.kind == "virtual" or c.name ==
                                                                         _drive_coupling(linkage, c.joint)) else ""
        ax.text((x0 + x1) / 2 + nx_ * off, (y0 + y1) / 2 + ny_ * off, c.name + tag, fontsize=font_size - 1,
                ha="center", va="center", color=colour, zorder=3)
    for link in ids:
        x, y = pos[link]
        ax.scatter([x], [y], s=node_size, facecolor="0.75" if link == linkage.ground else "white", edgecolor="black",
                   zorder=4)
        ax.text(x, y, str(link), ha="center", va="center", fontsize=font_size, zorder=5)
    ax.set_aspect("equal")
    ax.margins(0.18)
    ax.set_axis_off()
    return ax


def _drive_coupling(linkage, joint):
    """The coupling that carries a driven joint's actuator (the second of a split pair)."""
    if joint is None:
        return None
    j = linkage.joint(joint)
    return j.couplings[-1]


def plot_task_powers(result, ax=None, *, ports=None, losses: bool = True):
    """The powers of the ports (positive: entering) and, with *losses*, the total power lost to
    friction, against time, for a :class:`~gearlib.linkages.TaskResult`."""
    ax = _axes(ax, (6.0, 3.6))
    net = result.network
    names = ports if ports is not None else list(result.roles)
    for port in names:
        cols = [k for k, a in enumerate(net.action_cols) if a.port == port]
        ax.plot(result.times, result.powers[:, cols].sum(axis=1), lw=1.5,
                label=f"{port} ({result.roles.get(port, '')})")
    if losses:
        cols = [k for k, a in enumerate(net.action_cols) if a.role == "friction"]
        ax.plot(result.times, -result.powers[:, cols].sum(axis=1), color="0.3", ls="--", lw=1.5, label="friction losses")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("time")
    ax.set_ylabel("power")
    ax.legend(fontsize=8, frameon=False)
    return ax
