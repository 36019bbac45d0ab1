"""Drawings for differential synthesis (chapter 6).

:func:`~gearlib.plot_dgm` draws a chain with its ground (grey square), terminals (black squares)
and redundant links (orange) and writes the constraint under it; :func:`~gearlib.plot_identification`
charts every assignment of a chain at once, the static twin of
:func:`gearlib.dgm_explorer`.
"""

from __future__ import annotations
import re
from ..mechanism.plot import _axes, draw_graph
from .dgm import Identification, TerminalConstraint

__all__ = ['plot_dgm', 'plot_identification', 'equation_text']


def equation_text(constraint: TerminalConstraint) -> str:
    """The constraint as short text: ``e51·ω5 - e21·e62·ω6 + ... = 0``."""
    if constraint.equation is None:
        return f"{constraint.count} constraints among the terminals"
    text = str(constraint.equation).replace("**", "^").replace("*", "·")
    text = re.sub(r"omega_(\w+)", r"ω\1", text)
    return re.sub(r"e_(\w+?)_(\w+)", r"e\1,\2", text) + " = 0"


def _verdict(constraint: TerminalConstraint) -> str:
    return "admissible" if constraint.admissible else "; ".join(constraint.reasons)


def plot_dgm(constraint: TerminalConstraint, ax=None, *, pos=None, title=None, equation: bool = True,
             width: int = 60):
    """Draw the chain of *constraint* as a DGM: ground, terminals, redundant links, and the
    constraint equation below (wrapped at *width* characters).

    >>> c = gl.synthesis.terminal_constraint(gl.catalog.load("cyl_gkc_5_7_2"), (5, 6, 7), ground=4)
    >>> ax = gl.plot_dgm(c)
    >>> ax.get_title()
    'GKC 5-7-2 (Chen-Yao-Lee Fig. 2): ground 4, terminals 5, 6, 7'
    """
    ax = _axes(ax, figsize=(5.0, 4.4))
    mech = constraint.mechanism
    terms = ", ".join(map(str, constraint.terminals))
    draw_graph(mech, ax, ground=constraint.ground, inputs=constraint.terminals, pos=pos,
               highlight=constraint.redundant,
               title=title if title is not None else f"{mech.name}: ground {constraint.ground}, terminals {terms}")
    if equation:
        import textwrap

        lines = textwrap.wrap(equation_text(constraint), width) + textwrap.wrap(_verdict(constraint), width)
        ax.text(0.5, -0.02, "\n".join(lines), transform=ax.transAxes, ha="center", va="top", fontsize=8)
    return ax


def plot_identification(ident: Identification, ax=None, *, title=None):
    """Every (ground, terminals) assignment of a chain in one chart, one row each, as CYL's
    Table 1: G ground, T terminal, R redundant link, · other link; the right column gives
    the result. The static twin of :func:`gearlib.dgm_explorer`.

    >>> ident = gl.synthesis.identify(gl.catalog.load("cyl_gkc_5_7_2"))
    >>> ax = gl.plot_identification(ident)
    >>> len(ax.get_yticks())
    16
    """
    import numpy as np

    rows = list(ident.candidates)
    links = list(ident.chain.link_ids)
    ax = _axes(ax, figsize=(0.5 * len(links) + 3.5, 0.3 * len(rows) + 1.2))
    colour = np.ones((len(rows), len(links), 3))
    shades = {"G": (0.6, 0.6, 0.6), "T": (0.15, 0.15, 0.15), "R": (1.0, 0.65, 0.25)}
    for i, c in enumerate(rows):
        for j, x in enumerate(links):
            mark = "G" if x == c.ground else "T" if x in c.terminals else "R" if x in c.redundant else "·"
            if mark in shades:
                colour[i, j] = shades[mark]
            ax.text(j, i, mark, ha="center", va="center", fontsize=8, color="white" if mark == "T" else "black")
        result = ident.result(c)
        ax.text(len(links) - 0.3, i, "  " + ("admissible" if result == "admissible" else result if result != "—"
                                               else "; ".join(c.reasons)),
                ha="left", va="center", fontsize=7, color="tab:green" if result == "admissible" else "0.3")
    ax.imshow(colour, aspect="auto")
    ax.set_xticks(range(len(links)), [str(x) for x in links])
    ax.set_yticks(range(len(rows)), [f"{c.ground} | {', '.join(map(str, c.terminals))}" for c in rows], fontsize=7)
    ax.set_xlabel("link")
    ax.set_ylabel("ground | terminals")
    ax.set_xlim(-0.5, len(links) + 5.5)
    for side in ("top", "right", "bottom"):
        ax.spines[side].set_visible(False)
    ax.set_title(title if title is not None else f"{ident.chain.name}: every ground and {ident.n_terminals} terminals")
    return ax
