"""Drawings for differential synthesis (chapter 6).

:func:`~gearlib.plot_dgm` draws a chain with its ground (grey square), terminals (black squares)
and redundant links (orange) and writes the constraint under it; :func:`~gearlib.plot_identification`
charts every assignment of a chain at once, the static twin of
:func:`gearlib.dgm_explorer`. :func:`gearlib.synthesis.chain_layout` places a chain's links so that its edges
cross as little as the graph allows (none for a planar chain).
"""

from __future__ import annotations
import re
from ..mechanism.plot import _axes, draw_graph
from .dgm import Identification, TerminalConstraint

__all__ = ['plot_dgm', 'plot_identification', 'equation_text', 'chain_layout']


def equation_text(constraint: TerminalConstraint) -> str:
    """The constraint as short text: ``e51·ω5 - e21·e62·ω6 + ... = 0``."""
    if constraint.equation is None:
        return f"{constraint.count} constraints among the terminals"
    text = str(constraint.equation).replace("**", "^").replace("*", "·")
    text = re.sub(r"omega_(\w+)", r"ω\1", text)
    return re.sub(r"e_(\w+?)_(\w+)", r"e\1,\2", text) + " = 0"


def chain_layout(mech) -> dict:
    """Positions of a chain's links for :func:`gearlib.draw_graph` (``pos=``) with as few
    crossing edges as the graph allows: none for a planar chain, and no link drawn on an edge
    it is not an end of where the search finds room. The mechanism's own ``layout`` wins when
    it has one. Deterministic, and cached per graph.

    For a planar graph the candidates are Tutte's barycentric drawings, one per face of a planar
    embedding as the outer polygon, and the default layout of :func:`gearlib.draw_graph`; each is
    relaxed towards the graph distances without adding a crossing, and the best is kept.

    >>> pos = gl.synthesis.chain_layout(gl.catalog.load("cyl_standard_differential"))
    >>> sorted(pos)
    [0, 1, 2, 3, 4, 5]
    """
    from ..mechanism.plot import graph_layout
    from ._layout import layout

    if mech.layout:
        return dict(mech.layout)
    edges = tuple(tp.links for tp in mech.turning_pairs) + tuple(gp.gears for gp in mech.gear_pairs)
    start = tuple(graph_layout(mech).items())
    return dict(layout(tuple(mech.link_ids), edges, start))


def _verdict(constraint: TerminalConstraint) -> str:
    return "admissible" if constraint.admissible else "; ".join(constraint.reasons)


def plot_dgm(constraint: TerminalConstraint, ax=None, *, pos=None, title=None, equation: bool = True,
             width: int = 60, fontsize: float = 8):
    """Draw the chain of *constraint* as a DGM: ground, terminals, redundant links, and the
    constraint equation below (wrapped at *width* characters, in *fontsize* points). The links
    are placed by *pos* (default :func:`gearlib.synthesis.chain_layout`).

    >>> c = gl.synthesis.terminal_constraint(gl.catalog.load("cyl_gkc_5_7_2"), (5, 6, 7), ground=4)
    >>> ax = gl.plot_dgm(c)
    >>> ax.get_title()
    'GKC 5-7-2 (Chen-Yao-Lee Fig. 2): ground 4, terminals 5, 6, 7'
    """
    ax = _axes(ax, figsize=(5.0, 4.4))
    mech = constraint.mechanism
    terms = ", ".join(map(str, constraint.terminals))
    draw_graph(mech, ax, ground=constraint.ground, inputs=constraint.terminals, pos=pos or chain_layout(mech),
               highlight=constraint.redundant,
               title=title if title is not None else f"{mech.name}: ground {constraint.ground}, terminals {terms}")
    if equation:
        import textwrap

        lines = textwrap.wrap(equation_text(constraint), width) + textwrap.wrap(_verdict(constraint), width)
        ax.text(0.5, -0.02, "\n".join(lines), transform=ax.transAxes, ha="center", va="top", fontsize=fontsize)
    return ax


def plot_identification(ident: Identification, ax=None, *, title=None, names=None, legend: bool = True):
    """Every (ground, terminals) assignment of a chain in one chart, one row each, as CYL's
    Table 1: G ground, T terminal, R redundant link, · other link; the right column gives
    the result. The static twin of :func:`gearlib.dgm_explorer`.

    Parameters
    ----------
    names : dict (ground, terminals) -> str, optional; a name for an admissible row (the
        paper's ``"ND3-7-1"``), written before "admissible" and after "isomorphic to ...".
    legend : bool; a key to the letters and colours under the chart.

    >>> ident = gl.synthesis.identify(gl.catalog.load("cyl_gkc_5_7_2"))
    >>> ax = gl.plot_identification(ident, names={(4, (5, 6, 7)): "ND3-7-1"})
    >>> len(ax.get_yticks()), [t.get_text().strip() for t in ax.texts if "ND3" in t.get_text()]
    (16, ['ND3-7-1 (admissible)'])
    """
    import numpy as np
    from matplotlib.patches import Patch

    rows = list(ident.candidates)
    links = list(ident.chain.link_ids)
    names = {(g, tuple(t)): str(n) for (g, t), n in (names or {}).items()}
    ax = _axes(ax, figsize=(0.42 * len(links) + 4.6, 0.28 * len(rows) + 1.9))
    colour = np.ones((len(rows), len(links), 3))
    for i, c in enumerate(rows):
        for j, x in enumerate(links):
            mark = "G" if x == c.ground else "T" if x in c.terminals else "R" if x in c.redundant else "·"
            if mark in _SHADES:
                colour[i, j] = _SHADES[mark]
            ax.text(j, i, mark, ha="center", va="center", fontsize=8, color="white" if mark == "T" else "black")
        result = ident.result(c)
        if result == "admissible":
            name = names.get((c.ground, tuple(c.terminals)))
            note = f"{name} (admissible)" if name else "admissible"
        elif (c.ground, tuple(c.terminals)) in ident.duplicates and ident.duplicates[(c.ground, tuple(c.terminals))] in names:
            note = f"{result}: {names[ident.duplicates[(c.ground, tuple(c.terminals))]]}"
        else:
            note = result if result != "—" else "; ".join(c.reasons)
        ax.text(len(links) - 0.3, i, "  " + note, ha="left", va="center", fontsize=8,
                color="tab:green" if result == "admissible" else "0.25",
                fontweight="bold" if result == "admissible" else "normal")
    ax.imshow(colour, aspect="auto")
    ax.xaxis.tick_top()
    ax.xaxis.set_label_position("top")
    ax.set_xticks(range(len(links)), [str(x) for x in links])
    ax.set_yticks(range(len(rows)), [f"{c.ground} | {', '.join(map(str, c.terminals))}" for c in rows], fontsize=8)
    ax.set_xlabel("link")
    ax.set_ylabel("ground | terminals")
    ax.set_xlim(-0.5, len(links) + 5.5)
    for side in ("top", "right", "bottom"):
        ax.spines[side].set_visible(False)
    ax.tick_params(axis="x", length=0)
    if legend:
        key = [Patch(facecolor=_SHADES[m], edgecolor="0.4", label=f"{m}  {what}") for m, what in
               (("G", "ground"), ("T", "terminal"), ("R", "redundant link"))]
        key.append(Patch(facecolor="white", edgecolor="0.4", label="·  other link"))
        ax.legend(handles=key, loc="upper left", bbox_to_anchor=(0.0, -0.01), ncol=4, frameon=False, fontsize=8,
                  handlelength=1.2, columnspacing=1.2, title="right: the result (green: admissible), or why not",
                  title_fontsize=8, alignment="left")
    ax.set_title(title if title is not None else f"{ident.chain.name}: every ground and {ident.n_terminals} terminals",
                 pad=10)
    return ax


_SHADES = {"G": (0.6, 0.6, 0.6), "T": (0.15, 0.15, 0.15), "R": (1.0, 0.65, 0.25)}
