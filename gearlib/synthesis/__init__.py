"""Topological synthesis of differential geared mechanisms, and the atlas: chapter 6.

Chen, Yao and Lee (2003) find, in a geared kinematic chain (GKC), every choice of ground and
three terminals that makes a non-fractionated differential geared mechanism (DGM): one
constraint among the terminals' speeds and no redundant link. This package holds

* ``atlas`` - the atlas of one- and two-degree-of-freedom GKCs, enumerated from the
  structural rules, with the published counts (engine: ``_chains``);
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
    "atlas": ("geared_chains", "canonical_graph", "isomorphic", "is_fractionated", "chain_problems",
              "PublishedCount", "PUBLISHED_COUNTS", "CountRow", "count_table", "MAX_LINKS"),
    "drawing": ("plot_dgm", "plot_identification", "equation_text"),
    "widget": ("DGMExplorer", "dgm_explorer"),
}

TOP = ("atlas", "terminal_constraint", "identify", "plot_dgm", "plot_identification", "dgm_explorer")

__getattr__, __dir__, __all__ = lazy(__name__, EXPORTS)
