"""The DGM explorer (chapter 6): pick a chain, a ground and terminals, and see the constraint.

It redraws :func:`gearlib.plot_dgm` for the reader's choice; its static twin is
:func:`gearlib.plot_identification`.
"""

from __future__ import annotations
from ..mechanism.data import Mechanism
from .dgm import adjacency, terminal_constraint
from .drawing import _verdict, equation_text, plot_dgm

__all__ = ['DGMExplorer', 'dgm_explorer']


class DGMExplorer:
    """Choose a chain, a ground and terminals; see the constraint and the redundant links.

    :meth:`update` computes and redraws without a browser (what the controls call).
    """

    def __init__(self, chains, n_terminals: int = 3):
        from .._common.parse import parse_count
        from ..errors import InputError
        from ..mechanism._accept import as_mechanism

        if chains is None or isinstance(chains, (Mechanism, str)):
            chains = [chains]
        chains = [as_mechanism(c, "chains") for c in chains]
        if not chains:
            raise InputError("give at least one chain to explore")
        n_terminals = parse_count(n_terminals, "n_terminals", 2, 12)
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
        from ..mechanism.widgets import Canvas

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
        from ..mechanism.widgets import with_snapshot

        return with_snapshot(self.widget._repr_mimebundle_(**kwargs), self.image)


def dgm_explorer(chains, n_terminals: int = 3) -> DGMExplorer:
    """A widget: pick a chain, a ground and terminals and see the constraint equation and
    the redundant links. Static twin: :func:`gearlib.plot_identification` with :func:`gearlib.plot_dgm`."""
    return DGMExplorer(chains, n_terminals)
