"""Drawing a frequency table as a line spectrum (used by :func:`gearlib.plot_spectrum`)."""

from __future__ import annotations

COLORS = {"mesh": "tab:blue", "tooth": "tab:green", "inner ring": "tab:red", "outer ring": "tab:red",
          "ball spin": "tab:purple", "ball": "tab:purple", "cage": "tab:orange"}
HEIGHT = {"mesh": 1.0, "tooth": 0.55, "inner ring": 0.8, "outer ring": 0.8, "ball spin": 0.65, "ball": 0.65,
          "cage": 0.45}
SHORT = {"mesh": "mesh", "tooth": "tooth", "inner ring": "BPFI", "outer ring": "BPFO", "ball spin": "BSF",
         "ball": "ball", "cage": "FTF"}
LEGEND = {"mesh": "gear mesh", "tooth": "tooth defect", "inner ring": "ring defect", "outer ring": "ring defect",
          "ball spin": "ball", "ball": "ball", "cage": "cage"}


def short_label(r) -> str:
    """``mesh 2-7``, ``tooth 5``, ``BPFI bearing 1``: a few characters for one row."""
    if r.kind == "mesh":
        return f"mesh {r.pair[0]}-{r.pair[1]}"
    if r.kind == "tooth":
        return f"tooth {r.link}"
    return f"{SHORT[r.kind]} {r.bearing}" if r.bearing else SHORT[r.kind]


def group_label(rows) -> str:
    """The contacts of one spectral line, grouped by kind: ``mesh 3-5, 3-6; tooth 7``."""
    parts: dict[str, list] = {}
    for r in rows:
        if r.kind == "mesh":
            item = f"{r.pair[0]}-{r.pair[1]}"
        elif r.kind == "tooth":
            item = str(r.link)
        else:
            item = r.bearing or ""
        items = parts.setdefault(SHORT[r.kind], [])
        if item not in items:
            items.append(item)
    out = []
    for kind, items in parts.items():
        items = [i for i in items if i]
        if kind not in ("mesh", "tooth") and len(items) > 1:
            out.append(f"{kind} ({len(items)} bearings)")
        else:
            out.append(f"{kind} {', '.join(items)}".strip())
    return "; ".join(out)


def spectral_lines(table, kinds=None, tol=1e-9) -> list[tuple[float, list]]:
    """``[(frequency, rows)]``, one entry per distinct non-zero frequency, in increasing order."""
    rows = [r for r in table.rows if (kinds is None or r.kind in kinds) and float(r.frequency) > tol]
    groups: list[list] = []
    for r in sorted(rows, key=lambda r: float(r.frequency)):
        f = float(r.frequency)
        if groups and abs(f - float(groups[-1][0].frequency)) <= tol * max(1.0, f):
            groups[-1].append(r)
        else:
            groups.append([r])
    return [(float(g[0].frequency), g) for g in groups]


def spectrum_key(lines) -> list[str]:
    """One line per spectral line of :func:`spectral_lines`: number, frequency, contacts."""
    return [f"{n:>2}  {f:.4g}  {group_label(rows)}" for n, (f, rows) in enumerate(lines, start=1)]


def plot_spectrum(table, ax=None, *, log=None, kinds=None, key: bool = True, title=None, fontsize: float = 8):
    """The frequency table as a line spectrum.

    One vertical line per distinct frequency, coloured by the kind of its tallest contact
    (mesh, tooth, bearing) and numbered. A line's height shows its kind only (meshes tallest,
    then ring defects, balls, teeth, the cage), never an amplitude: the table predicts where
    lines fall, not how strong they are. With ``key=True`` a key beside the axes names the
    contacts of each line. Lines at zero frequency (contacts that do not move relative to
    each other) are left out. ``log`` uses a logarithmic axis (default: when the
    frequencies span more than a factor 30). Returns the axes.
    """
    import math

    from matplotlib.collections import LineCollection
    from matplotlib.transforms import offset_copy

    from ..mechanism.plot import _axes

    ax = _axes(ax, figsize=(7.5, 3.2))
    lines = spectral_lines(table, kinds)
    freqs = [f for f, _ in lines]
    if log is None:
        log = bool(freqs) and max(freqs) / min(freqs) > 30
    if log and freqs:
        lo, hi = math.log10(min(freqs) / 1.6), math.log10(max(freqs) * 1.6)
        from matplotlib.ticker import NullLocator

        ax.set_xscale("log")
        ax.xaxis.set_minor_locator(NullLocator())  # decades only: fewer ticks, faster redraws
        ax.set_xlim(10**lo, 10**hi)

        def where(f):
            return (math.log10(f) - lo) / (hi - lo)
    else:
        hi = max(freqs) * 1.1 if freqs else 1.0
        ax.set_xlim(0, hi)

        def where(f):
            return f / hi

    by_name: dict = {}  # legend name -> (colour, [(f, h)]): one vlines per name, in order of first use
    last_x = [-1.0, -1.0, -1.0]
    for n, (f, rows) in enumerate(lines, start=1):
        top = max(rows, key=lambda r: HEIGHT[r.kind])
        h = HEIGHT[top.kind]
        by_name.setdefault(LEGEND[top.kind], (COLORS[top.kind], []))[1].append((f, h))
        x = where(f)
        level = next((k for k in range(3) if x - last_x[k] > 0.025), 0)
        last_x[level] = x
        # a text shifted by points (what annotate does, for a third of the drawing time)
        ax.text(f, h, str(n), transform=offset_copy(ax.transData, fig=ax.figure, y=2 + 8 * level, units="points"),
                ha="center", va="bottom", fontsize=fontsize)
    for name, (color, fh) in by_name.items():  # what ax.vlines makes, without its unit and limit handling
        ax.add_collection(LineCollection([[(f, 0.0), (f, h)] for f, h in fh], colors=color, linewidths=2, label=name),
                          autolim=False)
    legend_done = list(by_name)
    entries = spectrum_key(lines)
    ax.set_ylim(0, 1.75)
    ax.set_yticks([])
    ax.set_ylabel("height: kind of line\n(not an amplitude)", fontsize=fontsize)
    ax.set_xlabel(f"frequency ({table.unit})")
    if legend_done:
        ax.legend(fontsize=fontsize, loc="upper left", ncols=min(3, len(legend_done)), frameon=False)
    if key and entries:
        ax.text(1.01, 1.0, "\n".join(entries), transform=ax.transAxes, va="top", ha="left", fontsize=fontsize,
                family="monospace")
    ax.set_title(title if title is not None else f"contact frequencies, {table.mechanism.name}")
    return ax
