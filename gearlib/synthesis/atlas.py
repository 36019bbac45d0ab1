"""The atlas of geared kinematic chains (GKCs), enumerated from the structural rules.

A geared kinematic chain is a mechanism with no link held. With ``n`` links and ``F``
degrees of freedom (once a link is held) it obeys the rules of Buchsbaum and Freudenstein
(1970) and Tsai (1987), which :func:`geared_chains` enumerates:

1. the turning pairs form a tree (``n - 1`` of them), each labelled with an axis; links
   joined by turning pairs with one label are *coaxial* and form a *coaxial group*;
2. there are ``n - 1 - F`` gear pairs, one per fundamental circuit; the two gears of a pair
   are coaxial with its carrier (transfer vertex) on two different axes;
3. every link is a gear or a carrier of some gear pair (it lies in a fundamental circuit);
4. no degenerate structure: with generic gear ratios no gear pair repeats the others and
   no two links are locked together (no rigid sub-chain).

Two chains are the same when a renumbering of the links and a renaming of the axis labels
turns one into the other. Which bearing carries which link inside a coaxial group does not
count (it changes neither the kinematics nor which links are coaxial), so
:func:`canonical_graph` encodes each coaxial group as one node. That is the *coaxial* level,
the displacement graphs of Tsai and Lin (1989) in canonical form. At the *kinematic* level
only the gear pairs and their carriers count (their rotation graphs: chains with the same
Willis equations are one), which is what :func:`gearlib.displacement_graph` draws.

A chain is *fractionated* when splitting one link separates it into two chains (for
example two planetary trains sharing a shaft). One-dof chains never are; the atlases the
papers use (Tsai and Lin 1989; Chen, Yao and Lee 2003) list only non-fractionated ones,
which is the default here.

>>> chains = gl.atlas.geared_chains(4, 1)
>>> [m.name for m in chains]
['GKC 4-1-1', 'GKC 4-1-2', 'GKC 4-1-3']
>>> len(gl.atlas.geared_chains(4, 1, level="kinematic"))
2
>>> gl.atlas.isomorphic(chains[0], chains[0].replace(name="copy"))
True
"""

from __future__ import annotations

import functools
import numbers

import sympy

from . import _chains
from .counts import (MAX_COUNT_LINKS, PUBLISHED_COUNTS, ChainCounts, CountRow, PublishedCount, StoredCounts,
                     chain_counts, count_table, stored_counts)
from .._common.topology import CoaxialGroups
from ..errors import DataFormatError
from ..mechanism.data import Mechanism

__all__ = [
    "geared_chains", "canonical_graph", "isomorphic", "is_fractionated", "chain_problems",
    "MAX_LINKS",
    # counted (up to nine links) and published: defined in counts, offered here too as gl.atlas.<name>
    "chain_counts", "ChainCounts", "MAX_COUNT_LINKS", "PublishedCount", "PUBLISHED_COUNTS", "CountRow",
    "count_table", "StoredCounts", "stored_counts",
]

MAX_LINKS = 8
LEVELS = ("coaxial", "kinematic")
_FRACTIONATED = (False, True, "only")


# ---------------------------------------------------------------- enumeration
def _check_args(n_links, dof, fractionated, level):
    for name, value, low in (("n_links", n_links, 2), ("dof", dof, 1)):
        if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < low:
            raise DataFormatError(f"{name} must be an integer of at least {low}, got {value!r}")
    if n_links > MAX_LINKS:
        raise DataFormatError(
            f"n_links={n_links} is too many to build as mechanisms (at most {MAX_LINKS}); "
            f"gl.synthesis.chain_counts counts the chains of up to {MAX_COUNT_LINKS} links"
        )
    if fractionated not in _FRACTIONATED or isinstance(fractionated, int) and not isinstance(fractionated, bool):
        raise DataFormatError(f"fractionated must be False, True or 'only', got {fractionated!r}")
    if level not in LEVELS:
        raise DataFormatError(f"level must be one of {', '.join(LEVELS)}, got {level!r}")


@functools.cache
def _catalogue(n: int, dof: int) -> tuple:
    """``(skeleton, fractionated, kinematic code)`` in the atlas order, links renumbered
    canonically: non-fractionated chains first, then by kinematic code, then the most
    coaxial arrangement (fewest coaxial groups) first, then by coaxial code."""
    if n - 1 - dof < 1:
        return ()
    rows = []
    for sk in _chains.skeletons(n, dof):
        code, perm = _chains.canonical(sk.n, sk.groups, sk.triples)
        groups, triples = code
        kin, _ = _chains.canonical(n, groups, triples, with_groups=False)
        frac = _chains.fractionated(n, triples, groups)
        rows.append((frac, kin, len(groups), code, _chains.Skeleton(n, groups, triples)))
    rows.sort(key=lambda r: r[:4])
    return tuple((sk, frac, kin) for frac, kin, _, _, sk in rows)


def _hub(group, triples):
    """The link that bears the others of a coaxial group: the one that carries most gears of it."""
    def score(v):
        return (-sum(1 for a, b, c in triples if c == v and (a in group or b in group)), v)
    return min(group, key=score)


def _to_mechanism(sk: _chains.Skeleton, n: int, dof: int, k: int, frac: bool) -> Mechanism:
    labels = "abcdefghijklmnopqrstuvwxyz"
    turning = []
    for g, group in enumerate(sk.groups):
        hub = _hub(group, sk.triples)
        turning += [(hub + 1, v + 1, labels[g]) for v in group if v != hub]
    pairs = [
        {"gears": [a + 1, b + 1], "ratio": sympy.Symbol(f"e_{a + 1}_{b + 1}"), "carrier": c + 1}
        for a, b, c in sk.triples
    ]
    circuits = ", ".join(f"({a + 1},{b + 1})({c + 1})" for a, b, c in sk.triples)
    coaxial = "; ".join("{" + ", ".join(str(v + 1) for v in g) + "}" for g in sk.groups)
    kind = "fractionated" if frac else "non-fractionated"
    return Mechanism(
        links=tuple(range(1, n + 1)),
        turning_pairs=tuple(turning),
        gear_pairs=tuple(pairs),
        name=f"GKC {n}-{dof}-{k}",
        description=f"{kind} {n}-link {dof}-dof geared kinematic chain; fundamental circuits {circuits}; "
                    f"coaxial groups {coaxial}",
        source=f"enumerated by gearlib.synthesis.geared_chains({n}, {dof}) from the structural rules of "
               "Buchsbaum and Freudenstein (1970) and Tsai (1987); gear ratios symbolic",
    )


@functools.cache
def _mechanism(n: int, dof: int, k: int) -> Mechanism:
    """Chain ``GKC n-dof-k``: row ``k - 1`` of the catalogue as a Mechanism (built when first asked for)."""
    sk, frac, _ = _catalogue(n, dof)[k - 1]
    return _to_mechanism(sk, n, dof, k, frac)


def geared_chains(n_links: int, dof: int = 1, *, fractionated=False, level: str = "coaxial") -> tuple[Mechanism, ...]:
    """Every geared kinematic chain with *n_links* links and *dof* degrees of freedom.

    Parameters
    ----------
    n_links : int, 2 to ``MAX_LINKS``.
    dof : int, at least 1: the freedoms once one link is held.
    fractionated : False (default), True or ``"only"``
        Leave out fractionated chains (the atlases of the literature), include them, or
        give only them. Non-fractionated chains always come first, so a chain's name does
        not depend on this option.
    level : ``"coaxial"`` (default) or ``"kinematic"``
        ``"coaxial"``: chains that differ only in which links are coaxial are different
        (Tsai and Lin's displacement graphs). ``"kinematic"``: one representative per set
        of gear pairs and carriers (their rotation graphs); it keeps its coaxial-level name.

    Returns
    -------
    tuple of :class:`gearlib.Mechanism`
        Links ``1..n``, symbolic ratios ``e_a_b``, explicit carriers, no ground; named
        ``"GKC n-dof-k"`` in a fixed order (canonical numbering, so the same on every run).
        Cached: the second call is instant.

    >>> planetary = gl.atlas.geared_chains(4, 1)[1]  # sun 2, ring 3, planet 4, carrier 1
    >>> [str(c) for c in gl.fundamental_circuits(planetary)]
    ['(2,4)(1)', '(3,4)(1)']
    >>> len(gl.atlas.geared_chains(7, 2)), len(gl.atlas.geared_chains(7, 2, level="kinematic"))
    (50, 20)
    """
    _check_args(n_links, dof, fractionated, level)
    return _select(int(n_links), int(dof), fractionated, level)


@functools.cache
def _kept(n: int, f: int, fractionated, level: str) -> tuple[int, ...]:
    """The numbers ``k`` of the chains ``GKC n-f-k`` that :func:`geared_chains` gives."""
    out, seen = [], set()
    for k, (_, frac, kin) in enumerate(_catalogue(n, f), start=1):
        if (fractionated is False and frac) or (fractionated == "only" and not frac):
            continue
        if level == "kinematic":
            if kin in seen:
                continue
            seen.add(kin)
        out.append(k)
    return tuple(out)


@functools.cache
def _select(n: int, f: int, fractionated, level: str) -> tuple:
    return tuple(_mechanism(n, f, k) for k in _kept(n, f, fractionated, level))


# ---------------------------------------------------------------- structure of a given mechanism
def _skeleton(mech: Mechanism):
    index = mech.index
    groups = CoaxialGroups([(*tp.links, tp.axis) for tp in mech.turning_pairs])
    gs = tuple(tuple(sorted(index[v] for v in g)) for g in groups.members)
    triples = tuple((index[gp.gears[0]], index[gp.gears[1]], index[gp.carrier]) for gp in mech.gear_pairs)
    return gs, triples


def _as_mechanism(mech, what="mechanism") -> Mechanism:
    if not isinstance(mech, Mechanism):
        raise DataFormatError(f"{what} must be a gl.Mechanism, got {type(mech).__name__}")
    return mech


def is_fractionated(mech: Mechanism) -> bool:
    """True when splitting one link separates *mech* into two geared chains.

    >>> gl.atlas.is_fractionated(gl.atlas.geared_chains(6, 2, fractionated="only")[0])
    True
    """
    mech = _as_mechanism(mech)
    groups, triples = _skeleton(mech)
    return _chains.fractionated(len(mech.links), triples, groups)


def chain_problems(mech: Mechanism) -> tuple[str, ...]:
    """Why *mech* is not a geared kinematic chain by the rules above (empty when it is).

    Its freedoms are ``len(turning_pairs) - len(gear_pairs)``.

    >>> gl.atlas.chain_problems(gl.catalog.load("cyl_gkc_5_7_2"))
    ()
    """
    mech = _as_mechanism(mech)
    n = len(mech.links)
    groups, triples = _skeleton(mech)
    out = []
    redundant = mech.redundant_turning_pairs
    if redundant:
        out.append("turning pairs " + ", ".join(str(tp.links) for tp in redundant)
                   + " close loops of coaxial bearings; a chain's turning pairs form a tree")
    used = {v for t in triples for v in t}
    idle = [mech.link_ids[i] for i in range(n) if i not in used]
    if idle:
        out.append(f"links {', '.join(map(str, idle))} are neither a gear nor a carrier (in no fundamental circuit)")
    rank, _ = _chains.generic_motion(n, triples)
    if rank < len(triples):
        out.append(f"only {rank} of the {len(triples)} gear pairs are independent for generic ratios")
    for locked in _chains.locked_sets(n, triples):
        names = ", ".join(str(mech.link_ids[i]) for i in locked)
        out.append(f"links {names} are locked together (a rigid sub-chain): the chain is degenerate")
    return tuple(out)


# ---------------------------------------------------------------- isomorphism
def canonical_graph(mech: Mechanism, *, ground=None, terminals=(), level: str = "coaxial"):
    """The graph that decides isomorphism: a networkx graph with link nodes
    ``("link", id)``, one node ``("axis", k)`` per coaxial group (level ``"coaxial"``) and one
    node ``("pair", i)`` per gear pair; edges of kind ``"axis"`` (link in group), ``"mesh"``
    (pair to its gears) and ``"carrier"`` (pair to its carrier). Axis labels disappear, so
    renaming them changes nothing. Links get a ``role``: ``"ground"``, ``"terminal"`` or
    ``"link"``, so that mechanisms with a chosen ground and terminals can be compared too.

    >>> g = gl.atlas.canonical_graph(gl.catalog.load("cyl_gkc_5_7_2"), ground=4, terminals=(5, 6, 7))
    >>> sorted(n for n, d in g.nodes(data=True) if d["role"] == "terminal")
    [('link', 5), ('link', 6), ('link', 7)]
    """
    import networkx as nx

    mech = _as_mechanism(mech)
    if level not in LEVELS:
        raise DataFormatError(f"level must be one of {', '.join(LEVELS)}, got {level!r}")
    ground = None if ground is None else mech.resolve(ground, "ground")
    terms = {mech.resolve(t, "terminal") for t in terminals}
    if ground is not None and ground in terms:
        raise DataFormatError(f"link {ground} cannot be both the ground and a terminal")
    g = nx.Graph(name=mech.name)
    for x in mech.link_ids:
        role = "ground" if x == ground else "terminal" if x in terms else "link"
        g.add_node(("link", x), kind="link", role=role)
    if level == "coaxial":
        for k, group in enumerate(CoaxialGroups([(*tp.links, tp.axis) for tp in mech.turning_pairs]).members):
            g.add_node(("axis", k), kind="axis", role="")
            for x in group:
                g.add_edge(("axis", k), ("link", x), kind="axis")
    for i, gp in enumerate(mech.gear_pairs):
        g.add_node(("pair", i), kind="gear_pair", role="")
        for x in gp.gears:
            g.add_edge(("pair", i), ("link", x), kind="mesh")
        g.add_edge(("pair", i), ("link", gp.carrier), kind="carrier")
    return g


def isomorphic(first, second, *, level: str = "coaxial") -> bool:
    """True when two mechanisms (or two graphs from :func:`canonical_graph`) have the same
    structure up to renumbering links and renaming axis labels.

    Gear ratios and tooth numbers are ignored: only links, coaxial groups, gear pairs and
    carriers count (and the roles, for graphs made with a ground and terminals).

    >>> a, b = gl.atlas.geared_chains(4, 1)[1:]
    >>> gl.atlas.isomorphic(a, b), gl.atlas.isomorphic(a, b, level="kinematic")
    (False, True)
    """
    import networkx as nx

    graphs = [x if isinstance(x, nx.Graph) else canonical_graph(_as_mechanism(x, "argument"), level=level)
              for x in (first, second)]
    g1, g2 = graphs
    if g1.number_of_nodes() != g2.number_of_nodes() or g1.number_of_edges() != g2.number_of_edges():
        return False
    return nx.is_isomorphic(
        g1, g2,
        node_match=lambda x, y: x.get("kind") == y.get("kind") and x.get("role") == y.get("role"),
        edge_match=lambda x, y: x.get("kind") == y.get("kind"),
    )
