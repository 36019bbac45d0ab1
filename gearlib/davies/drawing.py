"""Drawings for Davies' method: the coupling graph, the axes in their plane, powers and flows.

Every function takes ``ax=`` (a new figure when None), draws and returns the axes; none
changes matplotlib's global state.

* :func:`draw_coupling_graph` - links as vertices, couplings as directed edges; meshes carry
  a short stroke, ports (active couplings) are dashed, chords of the spanning tree grey;
* :func:`plot_layout` - the axis lines and pitch points in the plane ``x = 0``;
* :func:`plot_coupling_powers` - the power through every coupling (ports and losses);
* :func:`plot_power_flow` - power flows seen from the ground (real) and from each mesh's
  carrier (virtual): recirculation is the virtual bar far above the input power;
* :func:`plot_efficiency_sweep` - efficiency against one tooth number, for a few ordinary
  efficiencies (the static twin of :func:`gearlib.davies.efficiency_explorer`).
"""

from __future__ import annotations
import math
from ..mechanism.plot import _axes, graph_layout
from .power import coupling_powers, power_flow

__all__ = ['draw_coupling_graph', 'plot_layout', 'plot_coupling_powers', 'plot_power_flow']


def draw_coupling_graph(net, ax=None, *, pos=None, font_size=10, node_size=420):
    """Draw the coupling graph ``G_C`` of a :class:`~gearlib.davies.Network`."""
    from matplotlib.patches import FancyArrowPatch

    ax = _axes(ax, (4.5, 3.6))
    mech = net.mechanism
    pos = dict(pos or graph_layout(mech))
    seen: dict = {}
    chords = set(net.graph.chords)
    for c in net.couplings:
        key = frozenset((c.tail, c.head))
        k = seen.get(key, 0)
        seen[key] = k + 1
        rad = 0.0 if k == 0 else 0.3 * (1 if k % 2 else -1) * ((k + 1) // 2)
        color = "0.6" if c.name in chords else "black"
        style = "--" if c.role in ("input", "output") or c.kind == "virtual" else "-"
        arrow = FancyArrowPatch(pos[c.tail], pos[c.head], arrowstyle="-|>", mutation_scale=12,
                                connectionstyle=f"arc3,rad={rad}", linestyle=style, color=color, lw=1.4,
                                shrinkA=11, shrinkB=11, zorder=1)
        ax.add_patch(arrow)
        (x0, y0), (x1, y1) = pos[c.tail], pos[c.head]
        mx, my = (x0 + x1) / 2, (y0 + y1) / 2
        dx, dy = x1 - x0, y1 - y0
        norm = math.hypot(dx, dy) or 1.0
        nx_, ny_ = -dy / norm, dx / norm
        off = rad * norm / 2
        cx, cy = mx + nx_ * off, my + ny_ * off
        if c.kind == "mesh":  # the short stroke across a gear coupling
            s = 0.05 * norm
            ax.plot([cx - nx_ * s, cx + nx_ * s], [cy - ny_ * s, cy + ny_ * s], color=color, lw=2.2, zorder=2)
        label = c.name + (" (in)" if c.role == "input" else " (out)" if c.role == "output" else "")
        away = 0.15 if c.kind == "mesh" else 0.09  # clear of the stroke across a mesh
        ax.text(cx + nx_ * away * norm, cy + ny_ * away * norm, label, fontsize=font_size - 1, ha="center",
                va="center", color=color, zorder=3)
    for link in mech.link_ids:
        x, y = pos[link]
        face = "0.75" if link == net.ground else "white"
        ax.scatter([x], [y], s=node_size, marker="o", facecolor=face, edgecolor="black", zorder=4)
        ax.text(x, y, str(link), ha="center", va="center", fontsize=font_size, zorder=5)
    ax.set_aspect("equal")
    ax.margins(0.2)
    ax.set_axis_off()
    return ax


def plot_layout(lay, ax=None, *, font_size=9, title=None, legend: bool = True):
    """The axis lines (labelled with their links) and pitch points of a
    :class:`~gearlib.davies.Layout` (or of a network's layout) in the plane ``x = 0``: a side
    view of the train, every axis in the drawing plane. Grey lines are the axes, an arrow
    each axis's positive direction of rotation; red dots the pitch points, labelled with their
    gears; dotted red lines (bevel gears) the pitch lines from the cone apex to the pitch point.
    A legend says so unless ``legend=False``."""
    from matplotlib.lines import Line2D

    lay = getattr(lay, "layout", lay)
    ax = _axes(ax, (5.0, 4.0))
    pts = [tuple(map(float, m.pitch_point)) for m in lay.meshes] + [tuple(map(float, a.point)) for a in lay.axes]
    span = max([1.0] + [abs(c) for p in pts for c in p]) * 1.15
    for k, a in enumerate(lay.axes):
        py, pz = map(float, a.point)
        dy, dz = map(float, a.direction)
        n = math.hypot(dy, dz) or 1.0
        dy, dz = dy / n, dz / n
        ax.plot([py - span * dy, py + span * dy], [pz - span * dz, pz + span * dz], color="0.5", lw=1, zorder=1)
        ax.annotate("", xy=(py + 0.25 * span * dy, pz + 0.25 * span * dz), xytext=(py, pz),
                    arrowprops={"arrowstyle": "-|>", "color": "black"})
        tip = 0.3 + 0.15 * k  # stagger the labels of neighbouring axes
        links = ", ".join(map(str, sorted(a.links, key=str)))
        ax.text(py + tip * span * dy, pz + tip * span * dz, f" axis {a.label}: links {links}",
                fontsize=font_size, color="0.2", ha="left", va="center")
    bevel = False
    for m in lay.meshes:
        y, z = map(float, m.pitch_point)
        ax.plot([y], [z], "o", color="tab:red", zorder=3)
        ax.text(y, z, f"  {m.gears[0]}-{m.gears[1]}", fontsize=font_size, color="tab:red", va="bottom")
        if m.apex is not None:
            bevel = True
            ay, az = map(float, m.apex)
            ax.plot([ay, y], [az, z], color="tab:red", lw=0.8, ls=":", zorder=2)
    ax.set_xlabel("y")
    ax.set_ylabel("z")
    ax.set_aspect("equal")
    ax.set_xlim(-span, span)
    ax.set_ylim(-span, span)
    if legend:
        handles = [Line2D([], [], color="0.5", lw=1, label="axis (arrow: positive rotation)"),
                   Line2D([], [], color="tab:red", marker="o", ls="none", label="pitch point of a mesh")]
        if bevel:
            handles.append(Line2D([], [], color="tab:red", lw=0.8, ls=":", label="pitch line (from the apex)"))
        ax.legend(handles=handles, fontsize=font_size - 1, loc="upper left", bbox_to_anchor=(1.02, 1.0),
                  frameon=False)
    ax.set_title("side view in the plane x = 0" if title is None else title, fontsize=font_size + 1)
    return ax


def _port_input(mo, act):
    return coupling_powers(mo, act, roles=("input",))[mo.network.port("input").name]


def _per_unit(result):
    p_in = float(result.input_power)
    return p_in if p_in else 1.0


def plot_coupling_powers(result, ax=None):
    """Bars of the power through every coupling of an :class:`~gearlib.davies.Efficiency`,
    per unit input power: the input positive, the output and every loss negative."""
    ax = _axes(ax, (5.5, 3.2))
    powers = coupling_powers(result.motions, result.actions)
    p_in = _per_unit(result)
    names = list(powers)
    vals = [float(powers[n]) / p_in for n in names]
    colors = ["tab:green" if v > 0 else "tab:blue" if result.network.coupling(n).role == "output" else "tab:red"
              for n, v in zip(names, vals)]
    ax.bar(names, vals, color=colors)
    ax.axhline(0, color="black", lw=0.8)
    ax.set_ylabel("power / input power")
    ax.set_title(f"power through each coupling (η = {float(result.value):.4g})")
    return ax


def _what(c) -> str:
    """A coupling in a few characters under its letter: ``mesh 1-3``, ``5-1 in``, ``3-5``."""
    if c.kind == "mesh":
        return f"mesh {c.mesh.gears[0]}-{c.mesh.gears[1]}"
    role = {"input": " in", "output": " out"}.get(c.role, "")
    return f"{c.tail}-{c.head}{role}"


def plot_power_flow(result, ax=None, *, lossless: bool = True, title=True):
    """Power flow through every coupling of an :class:`~gearlib.davies.Efficiency`, per unit
    input power: seen from the ground (real flow) and, for meshes, from their carrier (virtual
    flow). A virtual bar above the dashed line at 1 is power recirculating inside the train.
    ``lossless`` (default, as Laus does) uses the actions without friction; ``False`` the lossy ones."""
    ax = _axes(ax, (6.0, 3.4))
    mo = result.motions
    act = result.lossless if lossless else result.actions
    net = result.network
    p_in = float(_port_input(mo, act)) or 1.0
    names, real, virtual = [], [], []
    for c in net.couplings:
        pt, ph = power_flow(mo, act, c.name, net.ground)
        real.append(max(abs(float(pt)), abs(float(ph))) / p_in)
        if c.kind == "mesh":
            vt, vh = power_flow(mo, act, c.name, c.carrier)
            virtual.append(max(abs(float(vt)), abs(float(vh))) / p_in)
        else:
            virtual.append(0.0)
        names.append(f"{c.name}\n{_what(c)}")
    x = list(range(len(names)))
    ax.bar([i - 0.2 for i in x], real, width=0.4, label="seen from the ground (real)", color="tab:blue")
    ax.bar([i + 0.2 for i in x], virtual, width=0.4, label="seen from the carrier (virtual)", color="tab:orange")
    ax.axhline(1.0, color="black", ls="--", lw=0.8)
    ax.set_xticks(x, names, fontsize=8)
    ax.set_ylabel("|power flow| / input power")
    ax.legend(fontsize=8, frameon=False)
    if title:
        peak = max(virtual) if virtual else 0.0
        kind = "lossless" if lossless else "with losses"
        ax.set_title(f"η = {float(result.value):.4g}; largest virtual flow {peak:.3g} × input ({kind})",
                     fontsize=9)
    return ax
