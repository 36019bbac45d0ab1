"""Topological synthesis of differential geared mechanisms, and the atlas: chapter 6.

Chen, Yao and Lee (2003) find, in a geared kinematic chain (GKC), every choice of ground and
three terminals that makes a non-fractionated differential geared mechanism (DGM): one
constraint among the terminals' speeds and no redundant link. This package holds

* ``atlas`` - the atlas of one- and two-degree-of-freedom GKCs, enumerated from the
  structural rules (engine: ``_chains``, ``_trees``, ``_canon``);
* ``counts`` - how many chains there are, up to nine links, beside the published counts,
  and the stored nine-link run;
* ``dgm`` - circuit matrices, the terminal constraint, the identification of every
  assignment, synthesis over the atlas, the proportional relation;
* ``drawing`` and ``widget`` - a DGM drawn with its constraint, the identification
  chart, and the DGM explorer.

Everything in ``EXPORTS`` is public; ``TOP`` is also ``gl.<name>``.
"""

from .._common.exports import lazy

EXPORTS = {
    "dgm": ("adjacency", "circuit_matrix", "terminal_constraint", "TerminalConstraint", "identify", "Identification",
            "synthesize", "proportional"),
    "atlas": ("geared_chains", "canonical_graph", "isomorphic", "is_fractionated", "chain_problems", "MAX_LINKS"),
    "counts": ("chain_counts", "ChainCounts", "MAX_COUNT_LINKS", "PublishedCount", "PUBLISHED_COUNTS", "CountRow",
               "count_table", "StoredCounts", "stored_counts"),
    "drawing": ("plot_dgm", "plot_identification", "equation_text", "chain_layout"),
    "widget": ("DGMExplorer", "dgm_explorer"),
}

TOP = ("atlas", "terminal_constraint", "identify", "plot_dgm", "plot_identification", "dgm_explorer")

__getattr__, __dir__, __all__ = lazy(__name__, EXPORTS)
