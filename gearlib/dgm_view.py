"""Drawings and a widget for differential synthesis (chapter 6).

Widget: :func:`gearlib.dgm_explorer`. Static twin: :func:`gearlib.plot_identification` (every
assignment of a chain at once) beside :func:`gearlib.plot_dgm`.

:func:`gearlib.plot_dgm` draws a chain with its ground (grey square), terminals (black squares)
and redundant links (orange) and writes the constraint under it; the widget redraws it
for the chain, ground and terminals a reader picks.
"""

from __future__ import annotations

import re

from .mechanism import Mechanism
from .plot import _axes, draw_graph
from .synthesis import Identification, TerminalConstraint, adjacency, terminal_constraint

__all__ = ["plot_dgm", "plot_identification", "DGMExplorer", "dgm_explorer", "equation_text"]


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


class DGMExplorer:
    """Choose a chain, a ground and terminals; see the constraint and the redundant links.

    :meth:`update` computes and redraws without a browser (what the controls call).
    """

    def __init__(self, chains, n_terminals: int = 3):
        chains = [chains] if isinstance(chains, Mechanism) else list(chains)
        if not chains:
            from .errors import InputError

            raise InputError("give at least one chain to explore")
        self.chains = {m.name: m for m in chains}
        self.n_terminals = n_terminals
        first = chains[0]
        ground = max(first.link_ids, key=lambda x: len(adjacency(first)[x]))
        self.state = {"chain": first.name, "ground": ground,
                      "terminals": adjacency(first)[ground][:n_terminals]}
        self.constraint = None
        self.text = ""
        self.image = b""
        self._widget = None
        self._canvas = None

    def update(self, chain=None, ground=None, terminals=None) -> bytes:
        """Recompute for this choice (unchanged parts keep their value); returns the PNG."""
        from .widgets import Canvas

        if chain is not None and chain != self.state["chain"]:
            mech = self.chains[chain]
            g = max(mech.link_ids, key=lambda x: len(adjacency(mech)[x]))
            self.state.update(chain=chain, ground=g, terminals=adjacency(mech)[g][:self.n_terminals])
        mech = self.chains[self.state["chain"]]
        if ground is not None and ground != self.state["ground"]:
            self.state.update(ground=mech.resolve(ground), terminals=adjacency(mech)[mech.resolve(ground)][:self.n_terminals])
        if terminals is not None:
            self.state["terminals"] = tuple(terminals)
        terms = tuple(self.state["terminals"])
        if terms:
            self.constraint = terminal_constraint(mech, terms, ground=self.state["ground"])
            c = self.constraint
            self.text = f"{equation_text(c)}   [{_verdict(c)}]"
        else:
            self.constraint, self.text = None, "choose terminals"
        if self._canvas is None:
            self._canvas = Canvas(figsize=(5.0, 4.2), margins=(0.02, 0.98, 0.06, 0.86), keep_axes=True)
        if self.constraint is not None:
            title = f"{mech.name}\nground {self.state['ground']}, terminals {', '.join(map(str, terms))}"
            self.image = self._canvas.png(lambda ax: plot_dgm(self.constraint, ax, equation=False, title=title))
        if self._widget is not None:
            self._sync()
        return self.image

    def _sync(self):
        mech = self.chains[self.state["chain"]]
        adj = adjacency(mech)
        self._busy = True
        self._ground.options = [x for x in mech.link_ids if adj[x]]
        self._ground.value = self.state["ground"]
        self._terms.options = list(adj[self.state["ground"]])
        self._terms.value = tuple(self.state["terminals"])
        self._busy = False
        self._label.value = self.text
        self._image.value = self.image

    @property
    def widget(self):
        """The ipywidgets view (made on first use)."""
        if self._widget is None:
            import ipywidgets as w

            self._busy = False
            self._chain = w.Dropdown(options=list(self.chains), value=self.state["chain"], description="chain")
            self._ground = w.Dropdown(description="ground")
            self._terms = w.SelectMultiple(description="terminals", rows=4)
            self._label = w.Label()
            self._image = w.Image(format="png")
            self._chain.observe(lambda ch: self.update(chain=ch["new"]), "value")
            self._ground.observe(lambda ch: None if self._busy else self.update(ground=ch["new"]), "value")
            self._terms.observe(lambda ch: None if self._busy else self.update(terminals=ch["new"]), "value")
            self._widget = w.VBox([w.HBox([self._chain, self._ground]), self._terms, self._label, self._image])
            self.update()
        return self._widget

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)


def dgm_explorer(chains, n_terminals: int = 3) -> DGMExplorer:
    """A widget: pick a chain, a ground and terminals and see the constraint equation and
    the redundant links. Static twin: :func:`gearlib.plot_identification` with :func:`gearlib.plot_dgm`."""
    return DGMExplorer(chains, n_terminals)
