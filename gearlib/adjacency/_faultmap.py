"""Drawing a fault table as a spectrum map (used by :func:`gearlib.plot_fault_map`).

One horizontal lane per family of lines; in each lane a tick per line (fundamental full
height, harmonics shorter, sidebands shortest), the band each sideband family covers shaded
behind its ticks, and the speed-tolerance band of each fundamental. The vertical axis names
the families: nothing on it reads as an amplitude. Labels are placed one by one, each on the
first of two levels of its lane where it overlaps no label already placed; a line that finds
no room is named in the key under the axes instead.
"""

from __future__ import annotations


TICK = {"fundamental": 0.45, "harmonic": 0.32, "sideband": 0.2}
WIDTH = {"fundamental": 1.6, "harmonic": 1.0, "sideband": 0.7}


def _lanes(table, families):
    from ._faults import FAMILIES

    present = [f for f in FAMILIES if any(r.family == f for r in table.lines)]
    present += sorted({r.family for r in table.lines} - set(present))
    if families is not None:
        wanted = (families,) if isinstance(families, str) else tuple(families)
        present = [f for f in present if f in wanted]
    return present


def map_size(table, families=None) -> tuple[float, float]:
    """The figure size (inches) the map of *table* is drawn at: page width, a lane a line."""
    return 7.5, 0.62 * max(len(_lanes(table, families)), 1) + 1.3


def _rank(r) -> str:
    return "sideband" if r.kind == "sideband" else "fundamental" if r.harmonic == 1 else "harmonic"


def plot_fault_map(table, ax=None, *, families=None, fmin=None, fmax=None, xscale=None, labels=True, title=None,
                   fontsize: float = 7):
    from matplotlib.collections import LineCollection
    from matplotlib.patches import Rectangle

    from ..mechanism.plot import _axes

    lanes = _lanes(table, families)
    ax = _axes(ax, figsize=map_size(table, families))
    y_of = {f: len(lanes) - 1 - i for i, f in enumerate(lanes)}
    rows = [r for r in table.lines if r.family in y_of and r.frequency > 0
            and (fmin is None or r.frequency >= fmin) and (fmax is None or r.frequency <= fmax)]
    freqs = [r.frequency for r in rows]
    lo, hi = (min(freqs), max(freqs)) if freqs else (1.0, 10.0)
    if xscale is None:
        xscale = "log" if hi / lo > 30 else "linear"
    if xscale == "log":
        ax.set_xscale("log")
        ax.set_xlim(lo / 1.5, hi * 1.5)
    else:
        pad = 0.05 * (hi - lo) if hi > lo else 0.1 * hi
        ax.set_xlim(max(0.0, lo - pad), hi + pad)
    colors = {f: f"C{i % 10}" for i, f in enumerate(lanes)}
    tol = table.tolerance
    # shaded bands: the span of each sideband family around its centre, the tolerance of each line
    spans: dict = {}
    for r in rows:
        if r.kind == "sideband":
            key = (r.family, r.centre, r.spacing)
            a, b = spans.get(key, (r.frequency, r.frequency))
            spans[key] = (min(a, r.frequency), max(b, r.frequency))
    for (fam, _, _), (a, b) in spans.items():
        y = y_of[fam]
        ax.add_patch(Rectangle((a, y - 0.45), b - a, 0.45, facecolor=colors[fam], alpha=0.12, lw=0, zorder=1))
    if tol > 0:
        for r in rows:
            if r.is_fundamental:
                y = y_of[r.family]
                ax.add_patch(Rectangle((r.frequency * (1 - tol), y - 0.45), 2 * tol * r.frequency, 0.45,
                                       facecolor=colors[r.family], alpha=0.25, lw=0, zorder=1))
    for fam in lanes:
        y = y_of[fam]
        for rank in ("sideband", "harmonic", "fundamental"):
            segs = [[(r.frequency, y - 0.45), (r.frequency, y - 0.45 + TICK[rank])] for r in rows
                    if r.family == fam and _rank(r) == rank]
            if segs:
                ax.add_collection(LineCollection(segs, colors=colors[fam], linewidths=WIDTH[rank], zorder=2,
                                                 label=fam if rank == "fundamental" else None), autolim=False)
    ax.set_ylim(-0.6, len(lanes) - 0.5)
    ax.set_yticks([y_of[f] - 0.2 for f in lanes], lanes, fontsize=fontsize + 1)
    ax.tick_params(axis="y", length=0)
    for y in range(len(lanes)):
        ax.axhline(y - 0.5, color="0.85", lw=0.6, zorder=0)
    ax.set_xlabel("frequency (Hz)")
    ref = table.reference_hz
    top = ax.secondary_xaxis("top", functions=(lambda f: f / ref, lambda o: o * ref))
    top.set_xlabel(f"orders of {'link ' if '/' not in str(table.reference) else ''}{table.reference}",
                   fontsize=fontsize + 1)
    top.tick_params(labelsize=fontsize)
    ax.tick_params(axis="x", labelsize=fontsize)
    ax.set_title(title if title is not None else
                 f"fault frequency map of the {table.mechanism.name}: "
                 f"{'link ' if '/' not in str(table.reference) else ''}{table.reference} at {60 * ref:.5g} rpm",
                 fontsize=9)
    if labels:
        _place_labels(ax, table, rows, y_of, fontsize)
    return ax


def _groups(rows):
    """Fundamentals of one lane at (almost) the same frequency share a label."""
    out = []
    for r in sorted((r for r in rows if r.is_fundamental), key=lambda r: (r.family, r.frequency)):
        if out and out[-1][0] == r.family and abs(r.frequency - out[-1][1]) <= 0.004 * r.frequency:
            out[-1][2].append(r)
        else:
            out.append((r.family, r.frequency, [r]))
    return out


def _text_of(group) -> str:
    names = []
    for r in group:
        if r.label not in names:
            names.append(r.label)
    return names[0] if len(names) == 1 else f"{names[0]} (+{len(names) - 1})"


def _levels(ax, renderer, fontsize):
    """Heights (data units above a lane's centre) of the label levels that fit in a lane."""
    probe = ax.text(0.5, 0.5, "Hg", fontsize=fontsize, transform=ax.transAxes)
    h_px = probe.get_window_extent(renderer).height * 1.12
    probe.remove()
    y0, y1 = ax.transData.inverted().transform([(0, 0), (0, h_px)])[:, 1]
    h = abs(y1 - y0)
    levels = [0.03]
    while levels[-1] + 2 * h <= 0.5:
        levels.append(levels[-1] + h)
    return levels


def _try(ax, renderer, placed, axes_box, f, y, levels, text, fontsize):
    for dy in levels:
        t = ax.text(f, y + dy, text, fontsize=fontsize, ha="center", va="bottom", zorder=3, gid="fault-label",
                    clip_on=False)
        box = t.get_window_extent(renderer).expanded(1.06, 1.05)
        if box.x0 >= axes_box.x0 and box.x1 <= axes_box.x1 and not any(box.overlaps(b) for b in placed):
            placed.append(box)
            return True
        t.remove()
    return False


def _place_labels(ax, table, rows, y_of, fontsize):
    """Labels first; a line whose label finds no room gets a number, named in the key; a
    line without room even for its number is named in the key with its frequency."""
    if not hasattr(ax.figure.canvas, "get_renderer"):  # a bare Figure: give it the Agg canvas to measure text
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        FigureCanvasAgg(ax.figure)
    renderer = ax.figure.canvas.get_renderer()
    levels = _levels(ax, renderer, fontsize)
    placed, numbered, unplaced = [], [], []
    axes_box = ax.get_window_extent(renderer)
    for fam, f, group in _groups(rows):
        if not _try(ax, renderer, placed, axes_box, f, y_of[fam], levels, _text_of(group), fontsize):
            numbered.append((fam, f, group))
    key = []
    for fam, f, group in numbered:
        n = len(key) + 1
        if _try(ax, renderer, placed, axes_box, f, y_of[fam], levels, str(n), fontsize):
            key.append(f"{n}: {_text_of(group)} ({f:.4g} Hz)")
        else:
            unplaced.append(f"{fam}: {_text_of(group)} ({f:.4g} Hz)")
    cells = key + ([f"no room: {c}" for c in unplaced])
    if cells:
        import textwrap

        text = "\n".join(textwrap.wrap(";  ".join(cells), width=150, break_on_hyphens=False))
        ax.text(0.0, -0.1, text, transform=ax.transAxes, ha="left", va="top", fontsize=fontsize - 0.5,
                gid="fault-key")
