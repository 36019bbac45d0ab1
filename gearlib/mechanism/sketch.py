"""Kinematic sketches: a mechanism drawn as an engineer draws it, from its data alone.

:func:`~gearlib.draw_sketch` draws the conventional stick diagram of any mechanism given as data;
:func:`~gearlib.sketch_layout` computes the same drawing as geometry (:class:`~gearlib.Sketch`), with nothing
drawn, so that a test, or a reader, can check it.

What the drawing shows, and where it comes from in the data:

* the **axes**: one dash-dot line per coaxial group of turning pairs (links that are coaxial
  share one line); the *main axis*, the group with the most links, is horizontal;
* a train about a main axis (a planetary, an automatic transmission) is a **half section**:
  above the axis only, each link turning about it as a shaft (inside, nearer the axis) and/or
  a drum (outside the gears), shafts nested as their spans require, with spokes to its gears,
  arms to its planets' pins (on one side of a planet, or on both as a bracket), brakes and
  clutches; an input enters and an output leaves on a shaft at the ends. The routing
  looks for a drawing in which no line crosses another member's line,
  pin or gear, and reports what it could not avoid in ``Sketch.crossings``. A train of
  fixed parallel axes (a gear pair, a compound train) is a **full section**, the axes one above
  the other at their centre distances (the developed view), every shaft held by **bearings**
  in the frame;
* the **gears** as blocks whose heights follow the pitch radii (``radii``, or module and teeth;
  teeth alone are relative sizes within a set of gears in mesh, whose module the data leave
  free: such a set drawn under 40 % of the largest gear is drawn larger; a symbolic ratio takes
  a size that closes its centre distance): a sun from its shaft to its pitch radius, a ring
  outwards from its pitch radius,
  a planet centred on its axis, off the main axis on its carrier's **pin**; a compound
  (stepped) planet as two blocks on one pin, a double-pinion set as two pins, its pinions side
  by side where one above the other would overlap (they stand at different angles about the
  axis; a pin that passes behind the other pinion is drawn dashed); a profile-shifted pair
  (``profile_shift``) at its working centre distance, its gears at their working pitch radii;
  **bevel** gears
  as frustums about their common cone apex, inclined by their shaft angle (from the pitch radii
  when a bevel planet meets two gears, as in a differential or Humpage's reducer; else from
  Penaud's angles, or 90 degrees);
* the **frame** (the mechanism's ``ground``) hatched: a housing along the top when it carries
  no gear, the bearings of fixed axes, or the hatched line of a held member;
* **brakes** (a pair of plates under the hatched housing) and **clutches** (a pair of plates
  between two members), with the names the data gives them;
* each link's id once, on its largest block (or beside its lines), and each brake's and
  clutch's name: :func:`~gearlib.draw_sketch` places every label, on the page, clear of the lines, of
  the other links' blocks and of the other labels (with a dotted leader where it found room
  only away from its link).

A spatial train, with an axis held by a link that itself turns about an inclined axis, cannot
be drawn in one plane: :func:`~gearlib.sketch_layout` raises :class:`~gearlib.errors.GeometryError` and says
why, rather than draw something wrong. So do bevel gears whose pitch radii cannot meet.

>>> import gearlib as gl
>>> sk = gl.sketch_layout(gl.catalog.simple_planetary())
>>> sk.mode
'half'
>>> [(b.link, b.kind) for b in sk.blocks]
[(1, 'sun'), (2, 'planet'), (3, 'ring')]
>>> sorted(lb.link for lb in sk.labels)
[1, 2, 3, 4]
>>> ax = gl.draw_sketch(gl.catalog.simpson())   # draws on a new figure and returns its axes
"""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import DataFormatError
from .data import Mechanism
from ._accept import as_mechanism, takes_mechanism

__all__ = ["Block", "Line", "AxisLine", "Symbol", "Label", "Sketch", "sketch_layout", "draw_sketch", "figure_size"]


@dataclass(frozen=True)
class Block:
    """A gear: ``kind`` is ``"sun"``, ``"ring"`` (internal teeth), ``"planet"``, ``"gear"`` (on a
    fixed axis) or ``"bevel"``; ``polygon`` its corners; ``radius`` its pitch radius; ``axis``
    the label of the axis it turns about; ``copy`` marks the mirror image in a full section."""

    link: object
    kind: str
    polygon: tuple
    axis: str
    radius: float
    gear: int
    copy: bool = False


@dataclass(frozen=True)
class Line:
    """A straight piece of a link: ``"shaft"``, ``"drum"``, ``"spoke"``, ``"arm"``, ``"pin"``,
    ``"hidden"`` (the piece of a pin behind the other pinion of a double-pinion set, drawn
    dashed), ``"riser"`` (a shaft joined to a drum) or ``"housing"`` (the frame)."""

    link: object
    kind: str
    start: tuple
    end: tuple
    copy: bool = False


@dataclass(frozen=True)
class AxisLine:
    """The centre line of one axis: its label and every link that turns about it."""

    label: str
    links: tuple
    start: tuple
    end: tuple


@dataclass(frozen=True)
class Symbol:
    """A ``"brake"``, ``"clutch"``, ``"bearing"`` or ``"ground"`` symbol: its segments and the
    polygons drawn hatched; ``name`` is a shift element's name."""

    kind: str
    name: str
    links: tuple
    segments: tuple
    hatch: tuple
    anchor: tuple
    copy: bool = False


@dataclass(frozen=True)
class Label:
    """A link's id, where the drawing writes it."""

    link: object
    text: str
    xy: tuple


@dataclass(frozen=True)
class Sketch:
    """The geometry of a kinematic sketch (see the module docstring), in the units of the pitch
    radii. ``mode`` is ``"half"`` (a half section about the main axis), ``"full"`` (both halves,
    when two identical planets are shown) or ``"fixed"`` (fixed parallel axes); ``crossings``
    counts the vertical pieces (spokes, arms, brakes, clutches) that cross another member's line or
    pin, and the pins that pass through another link's gear; ``notes`` lists what the data leave
    inconsistent (a centre distance the pitch radii, or a profile shift's working distance, do not
    close, drawn as the first mesh gives it)."""

    name: str
    mode: str
    blocks: tuple
    lines: tuple
    axes: tuple
    symbols: tuple
    labels: tuple
    crossings: int
    notes: tuple
    scale: float

    def bounds(self) -> tuple:
        """``(xmin, xmax, ymin, ymax)`` of everything drawn."""
        pts = [q for b in self.blocks for q in b.polygon]
        pts += [q for ln in self.lines for q in (ln.start, ln.end)]
        pts += [q for a in self.axes for q in (a.start, a.end)]
        pts += [q for s in self.symbols for seg in s.segments for q in seg]
        pts += [q for s in self.symbols for h in s.hatch for q in h]
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        return min(xs), max(xs), min(ys), max(ys)

    def plot(self, ax=None, **kw):
        """Draw it: :func:`~gearlib.draw_sketch`."""
        return draw_sketch(self, ax=ax, **kw)


@takes_mechanism
def sketch_layout(mech: Mechanism) -> Sketch:
    """The kinematic sketch of *mech* as geometry (nothing is drawn): see the module docstring.

    Raises :class:`~gearlib.errors.GeometryError` when the mechanism cannot be drawn in one plane, or
    its bevel gears cannot meet.
    """
    from ._sketch_build import build

    if not isinstance(mech, Mechanism):
        raise DataFormatError(f"sketch_layout needs a gl.Mechanism, got {type(mech).__name__}")
    out = build(mech)
    return Sketch(
        name=mech.name, mode=out["mode"],
        blocks=tuple(Block(*b) for b in out["blocks"]),
        lines=tuple(Line(*ln) for ln in out["lines"]),
        axes=tuple(AxisLine(*a) for a in out["axes"]),
        symbols=tuple(Symbol(*s) for s in out["symbols"]),
        labels=tuple(Label(*lb) for lb in out["labels"]),
        crossings=out["crossings"], notes=out["notes"], scale=out["scale"],
    )


_PALETTE = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf",
            "#bcbd22", "#393b79", "#637939", "#8c6d31", "#843c39", "#7b4173")


def draw_sketch(mech, ax=None, *, title=None, names=False, font_size=8, colors=True):
    """Draw the kinematic sketch of *mech* (a :class:`~gearlib.Mechanism` or a :class:`~gearlib.Sketch`).

    Parameters
    ----------
    title : str, optional
        Default: the mechanism's name.
    names : bool
        Write each link's name after its id (``"1 sun"``).
    colors : bool
        One colour per link (the frame grey); ``False`` draws in black.

    Returns
    -------
    matplotlib.axes.Axes
        Each link is labelled with the id its graph uses, so that the sketch and
        :func:`~gearlib.draw_graph` can be read side by side.

    >>> import gearlib as gl
    >>> ax = gl.draw_sketch(gl.catalog.load("compound_train"))
    >>> sorted(t.get_text() for t in ax.texts if t.get_text().isdigit())
    ['0', '1', '2', '3']
    """
    from matplotlib.collections import LineCollection, PolyCollection
    from matplotlib.colors import to_rgba

    if not isinstance(mech, Sketch):
        mech = as_mechanism(mech)
    from ._sketch_labels import PAD, place

    sk = mech if isinstance(mech, Sketch) else sketch_layout(mech)
    link_names = {lk.id: lk.name for lk in mech.links} if isinstance(mech, Mechanism) else {}
    x0, x1, y0, y1 = _limits(sk)
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=figure_size(sk), facecolor="white")
    ground = mech.ground if isinstance(mech, Mechanism) else None
    order = list(dict.fromkeys([lb.link for lb in sk.labels]))
    color = {link: ("0.35" if link == ground else _PALETTE[i % len(_PALETTE)]) if colors else "black"
             for i, link in enumerate(order)}
    ax.add_collection(LineCollection([(a.start, a.end) for a in sk.axes], colors="0.55", linewidths=0.7,
                                     linestyles=[(0, (8, 3, 1.5, 3))], zorder=1, gid="axes"))
    thick = _line_width(ax, sk, (x0, x1, y0, y1))
    widths = {"pin": min(1.3, thick), "housing": 2.2, "hidden": 0.8}
    shown = [ln for ln in sk.lines if ln.kind != "hidden"]
    ax.add_collection(LineCollection([(ln.start, ln.end) for ln in shown],
                                     colors=[color.get(ln.link, "black") for ln in shown],
                                     linewidths=[widths.get(ln.kind, thick) for ln in shown], capstyle="butt",
                                     zorder=2, gid="lines"))
    hidden = [ln for ln in sk.lines if ln.kind == "hidden"]
    if hidden:   # a pin behind the other pinion of its set
        ax.add_collection(LineCollection([(ln.start, ln.end) for ln in hidden], linestyles=[(0, (2.5, 2))],
                                         colors=[color.get(ln.link, "black") for ln in hidden],
                                         linewidths=widths["hidden"], zorder=3.5, gid="hidden"))
    ax.add_collection(PolyCollection([b.polygon for b in sk.blocks], edgecolors="black", linewidths=0.8, zorder=3,
                                     gid="blocks",
                                     facecolors=[to_rgba(color.get(b.link, "black"), 0.3 if b.copy else 0.55)
                                                 for b in sk.blocks]))
    hatch = [h for sym in sk.symbols for h in sym.hatch]
    if hatch:
        ax.add_collection(PolyCollection(hatch, facecolors="white", edgecolors="0.3", hatch="////", linewidths=0.6,
                                         zorder=2, gid="frame"))
    ax.add_collection(LineCollection([seg for sym in sk.symbols for seg in sym.segments], colors="black",
                                     linewidths=1.6, capstyle="butt", zorder=4, gid="symbols"))
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    texts = [lb.text + (f" {link_names[lb.link]}" if names and link_names.get(lb.link) else "") for lb in sk.labels]
    named = [(sym, sym.name) for sym in sk.symbols if sym.name and not sym.copy]
    spots, name_spots, leaders = place(ax, sk, texts, named, font_size)
    if leaders:   # a label that found room only away from its link
        ax.add_collection(LineCollection([seg for _, seg in leaders], colors=[color.get(link, "black")
                                                                              for link, _ in leaders],
                                         linewidths=0.6, linestyles=[(0, (1, 1.5))], zorder=6, gid="leaders"))
    for lb, text, (x, y) in zip(sk.labels, texts, spots):
        ax.text(x, y, text, fontsize=font_size, ha="center", va="center", zorder=7,
                bbox=dict(boxstyle=f"square,pad={PAD / font_size:.3f}", facecolor="white",
                          edgecolor=color.get(lb.link, "black"), linewidth=0.8))
    for (_sym, text), (x, y) in zip(named, name_spots):
        ax.text(x, y, text, fontsize=font_size - 1, ha="center", va="center", style="italic", zorder=6,
                bbox=dict(boxstyle=f"square,pad={PAD / (font_size - 1):.3f}", facecolor="white", edgecolor="none"))
    ax.set_facecolor("white")
    ax.axis("off")
    ax.xaxis.set_visible(False)   # no ticks to lay out when the title is placed
    ax.yaxis.set_visible(False)
    ax.set_title(sk.name if title is None else title, fontsize=font_size + 2)
    return ax


def _line_width(ax, sk, limits) -> float:
    """Width (points) of the members' lines: 1.9, thinner where nested lines run closer than
    that would leave a gap."""
    x0, x1, y0, y1 = limits
    fig = ax.figure
    box = ax.get_position()
    w_in, h_in = fig.get_size_inches()
    per = min(box.width * w_in * 72 / (x1 - x0), box.height * h_in * 72 / (y1 - y0))
    flat = sorted((ln.start[1], min(ln.start[0], ln.end[0]), max(ln.start[0], ln.end[0]), ln.link)
                  for ln in sk.lines if ln.kind in ("shaft", "drum") and abs(ln.start[1] - ln.end[1]) < 1e-12)
    gap = min((b[0] - a[0] for i, a in enumerate(flat) for b in flat[i + 1:]
               if b[0] - a[0] > 1e-12 and a[3] != b[3] and a[1] < b[2] and b[1] < a[2]), default=None)
    return 1.9 if gap is None else max(0.7, min(1.9, 0.5 * gap * per))


def _limits(sk: Sketch) -> tuple:
    """The drawing's limits: everything drawn and a margin; a half section also keeps a strip
    under its axis, where labels find room."""
    x0, x1, y0, y1 = sk.bounds()
    pad = 0.05 * max(x1 - x0, y1 - y0)
    x0, x1, y0, y1 = x0 - pad, x1 + pad, y0 - pad, y1 + pad
    if sk.mode == "half":
        y0 = min(y0, -0.06 * (x1 - x0))
    return x0, x1, y0, y1


def figure_size(sk: Sketch) -> tuple:
    """``(width, height)`` in inches that shows *sk* at a readable scale on a page."""
    x0, x1, y0, y1 = _limits(sk)
    aspect = (y1 - y0) / max(x1 - x0, 1e-9)
    w = 6.4 if aspect < 1.1 else max(3.2, 6.0 / aspect)
    return (w, w * aspect + 0.5)
