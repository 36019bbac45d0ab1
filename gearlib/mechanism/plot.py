"""Drawings: the graph of a mechanism in the papers' convention, and speeds.

Every function takes ``ax=`` (a new figure is made when it is None), draws, and returns
the axes; none calls ``plt.show()``. Nothing here changes matplotlib's global settings:
:func:`style` is a context manager for the book's look.

Graph convention (Freudenstein; Tsai; Liu and Chen): links are vertices, gear pairs heavy
edges, turning pairs thin edges labelled with their axis. The ground is drawn as a grey
square, input links as black squares, other links as circles.
"""

from __future__ import annotations

import contextlib
import functools
import json
import math
import pathlib
import textwrap

import numpy as np

from .._common.matview import polar_text
from .._common.parse import shown as _show
from ..errors import DataFormatError
from ._accept import takes_mechanism
from .data import Mechanism
from .graph import to_networkx

__all__ = ["style", "graph_layout", "draw_graph", "plot_speeds", "plot_ratio_sweep"]


_STYLE = {
    "figure.figsize": (6.0, 4.0),
    "figure.dpi": 100,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "font.size": 10,
}


@contextlib.contextmanager
def style():
    """The book's plotting style, as a context: ``with gl.plot.style(): ...``."""
    import matplotlib

    with matplotlib.rc_context(_STYLE):
        yield


def _axes(ax, figsize=(5.0, 4.0)):
    if ax is not None:
        if not (hasattr(ax, "add_artist") and hasattr(ax, "figure")):
            raise DataFormatError(f"ax: expected matplotlib Axes (fig, ax = plt.subplots()) or None, got {_show(ax)}")
        return ax
    import matplotlib.pyplot as plt

    _, ax = plt.subplots(figsize=figsize)
    return ax


def graph_layout(mech: Mechanism) -> dict:
    """Vertex positions: the mechanism's own ``layout`` when it has one, else a
    deterministic Kamada-Kawai layout of its graph."""
    if mech.layout:
        return dict(mech.layout)
    return dict(_kamada_kawai(tuple(mech.link_ids), _edges(mech)))


LAYOUTS = pathlib.Path(__file__).with_name("layouts.json")
"""Kamada-Kawai layouts of the catalogue's graphs, stored (:func:`store_layouts`): the
optimisation costs a widget's first frame of a mechanism more than the drawing, and many times
more when a loaded machine's BLAS threads fight over it."""


@functools.cache
def _stored_layouts() -> dict:
    try:
        return json.loads(LAYOUTS.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}


def _layout_key(nodes: tuple, edges: tuple) -> str:
    return repr((nodes, edges))


@functools.lru_cache(maxsize=64)
def _kamada_kawai(nodes: tuple, edges: tuple) -> tuple:
    """The layout of one graph (deterministic, so a widget redrawing a chain reuses it)."""
    stored = _stored_layouts().get(_layout_key(nodes, edges))
    if stored is not None and len(stored) == len(nodes):
        return tuple((n, (float(x), float(y))) for n, (x, y) in zip(nodes, stored))
    return _compute_kamada_kawai(nodes, edges)


def _compute_kamada_kawai(nodes: tuple, edges: tuple) -> tuple:
    import networkx as nx

    g = nx.Graph()
    g.add_nodes_from(nodes)
    g.add_edges_from(edges)
    if len(g) <= 2:
        return tuple((n, (float(i), 0.0)) for i, n in enumerate(nodes))
    # start from a circle so the result does not depend on any random state
    start = {n: (math.cos(2 * math.pi * i / len(g)), math.sin(2 * math.pi * i / len(g))) for i, n in enumerate(nodes)}
    pos = nx.kamada_kawai_layout(g, pos=start)
    return tuple((n, (float(x), float(y))) for n, (x, y) in pos.items())


def store_layouts(names=None) -> int:
    """Compute the Kamada-Kawai layout of every catalogue graph without a ``layout`` of its own
    (or of *names*) and store them in :data:`LAYOUTS`; returns how many. Run it after adding a
    catalogue entry: ``python -c "from gearlib.mechanism.plot import store_layouts; store_layouts()"``."""
    from ._accept import catalogue_names, load_catalogue

    out = {}
    for name in names or catalogue_names():
        mech = load_catalogue(name)
        if mech.layout:
            continue
        nodes, edges = tuple(mech.link_ids), _edges(mech)
        out[_layout_key(nodes, edges)] = [[round(x, 4), round(y, 4)] for _, (x, y) in
                                          _compute_kamada_kawai(nodes, edges)]
    lines = (f"{json.dumps(k)}: {json.dumps(v)}" for k, v in sorted(out.items()))
    LAYOUTS.write_text("{\n" + ",\n".join(lines) + "\n}\n", encoding="utf-8")
    _stored_layouts.cache_clear()
    _kamada_kawai.cache_clear()
    return len(out)


def _edges(mech) -> tuple:
    return tuple(tp.links for tp in mech.turning_pairs) + tuple(gp.gears for gp in mech.gear_pairs)


@takes_mechanism
def draw_graph(mech: Mechanism, ax=None, *, ground=None, inputs=None, pos=None, highlight=(),
               highlight_color="tab:orange", title=None, node_size=420, font_size=10):
    """Draw the graph of *mech*: heavy edges for gear pairs, thin labelled edges for turning pairs.

    Parameters
    ----------
    ground, inputs : link ids drawn as a grey square and black squares (default: the
        mechanism's own ``ground`` and ``inputs``).
    pos : dict link -> (x, y), optional; default :func:`gearlib.mechanism.graph_layout`.
    highlight : links or gear pairs (2-tuples of gears) drawn in ``highlight_color``.
    """
    from matplotlib.patches import FancyArrowPatch

    ax = _axes(ax)
    pos = dict(pos or graph_layout(mech))
    ground = mech.ground if ground is None else mech.resolve(ground)
    inputs = set(mech.inputs if inputs is None else (mech.resolve(x) for x in inputs))
    hl = set()
    for h in highlight or ():
        hl.add(frozenset(h) if isinstance(h, tuple) else h)
    g = to_networkx(mech)
    seen: dict = {}
    for u, v, data in g.edges(data=True):
        key = frozenset((u, v))
        k = seen.get(key, 0)
        seen[key] = k + 1
        rad = 0.0 if k == 0 else 0.25 * (1 if k % 2 else -1) * ((k + 1) // 2)
        heavy = data["kind"] == "heavy"
        color = highlight_color if key in hl else "black"
        patch = FancyArrowPatch(
            pos[u], pos[v], arrowstyle="-", connectionstyle=f"arc3,rad={rad}",
            linewidth=4.0 if heavy else 1.2, color=color, zorder=1, shrinkA=0, shrinkB=0,
        )
        ax.add_artist(patch)  # not add_patch: the limits are set below, so no curve extents are needed
        if not heavy:
            (x0, y0), (x1, y1) = pos[u], pos[v]
            mx, my = (x0 + x1) / 2, (y0 + y1) / 2
            dx, dy = x1 - x0, y1 - y0
            norm = math.hypot(dx, dy) or 1.0
            off = 0.06 + rad * 0.5
            ax.text(mx - dy / norm * off, my + dx / norm * off, data["axis"], fontsize=font_size - 1,
                    ha="center", va="center", style="italic", color=color, zorder=3)
    nodes: dict = {}  # marker -> (positions, faces, edges): one scatter per marker
    for link in mech.link_ids:
        x, y = pos[link]
        marker, face = "o", "white"
        if link == ground:
            marker, face = "s", "0.75"
        elif link in inputs:
            marker, face = "s", "black"
        group = nodes.setdefault(marker, ([], [], []))
        group[0].append((x, y))
        group[1].append(face)
        group[2].append(highlight_color if link in hl else "black")
        ax.text(x, y, str(link), ha="center", va="center", fontsize=font_size,
                color="white" if face == "black" else "black", zorder=4)
    for marker, (xy, faces, edges) in nodes.items():
        ax.scatter(*zip(*xy), s=node_size, marker=marker, facecolor=faces, edgecolor=edges, linewidth=1.5, zorder=2)
    xs = [p[0] for p in pos.values()]
    ys = [p[1] for p in pos.values()]
    pad = 0.15 * max(max(xs) - min(xs), max(ys) - min(ys), 1.0)
    ax.set_xlim(min(xs) - pad, max(xs) + pad)
    ax.set_ylim(min(ys) - pad, max(ys) + pad)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(title if title is not None else mech.name)
    return ax


def _shown(mech, ground, links):
    """``(link, reference or None, label)`` per link: a tilted link (a bevel planet,
    :func:`~gearlib.mechanism.tilted_links`) is shown by its speed relative to the link it
    turns on, which is an angular velocity; its own Willis-equation value is not."""
    from .graph import tilted_links

    tilted = tilted_links(mech, ground)
    out = []
    for x in links:
        name = mech.link(x).name
        if x in tilted:
            ref = tilted[x]
            out.append((x, ref, f"{x}/{ref}" + (f" {name}" if name else "")))
        else:
            out.append((x, None, f"{x} {name}" if name else str(x)))
    return out


def _values(z, mech, shown):
    return np.array([z[mech.index[x]] - (z[mech.index[ref]] if ref is not None else 0) for x, ref, _ in shown])


def _is_real(z) -> bool:
    return abs(z.imag) <= 1e-12 * max(1.0, abs(z))


def plot_speeds(solution, ax=None, *, links=None, title=None, unit="rad/s"):
    """Bar chart of link speeds (relative to the ground) from a :class:`~gearlib.Solution`.

    A link whose axis is tilted to the ground's (a bevel planet:
    :func:`~gearlib.mechanism.tilted_links`) is shown by its speed relative to the link it
    turns on, labelled ``2/6``: that is its spin about its own axis, where its value in the
    Willis equations adds rates about different axes. A complex speed (Penaud and Alazard's
    weights, chapter 4) is drawn by its magnitude, its angle written on the bar (in radians,
    as the x-axis says).
    """
    if not hasattr(solution, "as_complex"):
        hint = " (solve first: gl.speeds(mech, ground=..., inputs={...}))" if isinstance(solution, Mechanism) else ""
        raise DataFormatError(f"solution: expected the result of gl.speeds(...), got {_show(solution)}{hint}")
    ax = _axes(ax, figsize=(6.0, 3.2))
    mech = solution.mechanism
    ground = solution.constraints.ground
    links = list(mech.link_ids if links is None else (mech.resolve(x) for x in links))
    shown = _shown(mech, ground, links)
    values = _values(solution.as_complex(), mech, shown)
    heights = np.array([z.real if _is_real(z) else abs(z) for z in values])
    # names wrapped to the width of a bar slot (about 70 characters across at this size)
    width = max(8, 70 // max(1, len(links)))
    names = [textwrap.fill(label, width) for _, _, label in shown]
    colors = ["0.6" if x == ground else ("tab:orange" if ref is not None else "tab:blue") for x, ref, _ in shown]
    bars = ax.bar(range(len(links)), heights, color=colors)
    ax.set_xticks(range(len(links)), names, fontsize=8)
    ax.axhline(0, color="black", linewidth=0.8)
    ax.set_ylabel(f"angular velocity ({unit})" if unit else "angular velocity")
    if any(not _is_real(z) for z in values):
        ax.set_xlabel("r∠φ: magnitude r, angle φ in degrees", fontsize=8)
    angled = False
    for bar, z, h in zip(bars, values, heights):
        text = f"{h:.3g}"
        if not _is_real(z):
            text, angled = polar_text(z, 3).replace("∠", "\n∠"), True
        ax.annotate(text, (bar.get_x() + bar.get_width() / 2, h), ha="center",
                    va="bottom" if h >= 0 else "top", fontsize=8, xytext=(0, 2 if h >= 0 else -2),
                    textcoords="offset points")
    ax.margins(y=0.2 if angled else 0.12)  # room for the value labels under the title
    ax.set_title(title if title is not None else _title(ground, shown))
    return ax


def _title(ground, shown) -> str:
    rel = [(x, ref) for x, ref, _ in shown if ref is not None]
    text = f"speeds, link {ground} fixed"
    if rel:
        refs = {ref for _, ref in rel}
        text += "; " + ", ".join(f"{x}/{ref}" for x, ref in rel) + ": relative to " + (
            f"{refs.pop()}" if len(refs) == 1 else "the link each turns on")
    return text


def plot_ratio_sweep(xs, ratios, ax=None, *, xlabel="", ylabel="speed ratio", marks=(), title=None):
    """Line plot of a speed ratio against a design parameter (the static twin of a slider).

    ``marks`` are x values to highlight (for example the settings a widget starts at).
    """
    ax = _axes(ax, figsize=(5.0, 3.2))
    xs = np.asarray(xs, dtype=float)
    ys = np.asarray([float(r) for r in ratios])
    ax.plot(xs, ys, marker="o", markersize=3)
    for x in marks:
        i = int(np.argmin(np.abs(xs - x)))
        ax.plot([xs[i]], [ys[i]], marker="o", markersize=8, color="tab:orange")
        ax.annotate(f"{ys[i]:.4g}", (xs[i], ys[i]), xytext=(5, 5), textcoords="offset points")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title)
    return ax
