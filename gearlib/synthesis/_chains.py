"""The engine behind :mod:`gearlib.synthesis.atlas`: geared kinematic chains as plain integers.

A chain skeleton has links ``0 .. n-1``, *coaxial groups* (sets of at least two links that
turning pairs with one axis label join) and *triples* ``(a, b, c)``: a gear pair between
gears ``a < b`` on the carrier ``c``. The turning pairs form a tree, so the bipartite graph
"link belongs to group" is a tree too (a *hypertree*); the tree of bearings inside a group
does not change the kinematics and is not part of a skeleton.

Enumeration (:func:`skeletons`): every non-isomorphic bipartite tree with ``n`` link nodes
and group nodes of degree >= 2 (networkx's tree generator), every choice of
``n - 1 - dof`` gear pairs among the pairs of links that share a carrier on two different
axes, one choice per orbit of the tree's automorphisms, then the structural filters.
Generic (random) gear ratios in the field of integers modulo the prime ``2**61 - 1`` stand
for symbolic ones in the rank tests; a false answer would need a random ratio to hit a
root of a non-zero polynomial, with probability below ``1e-15``.
"""

from __future__ import annotations

import functools
import itertools
import random
from dataclasses import dataclass

PRIME = (1 << 61) - 1


@dataclass(frozen=True)
class Skeleton:
    """Links ``0..n-1``, coaxial groups (sorted tuples) and gear triples ``(a, b, carrier)``."""

    n: int
    groups: tuple
    triples: tuple


# ---------------------------------------------------------------- generic linear algebra
def _nullspace_mod_p(rows: list, n: int) -> tuple[int, list]:
    """Rank and a null-space basis of an integer matrix, modulo :data:`PRIME`."""
    rows = [list(r) for r in rows]
    pivots = []
    r = 0
    for c in range(n):
        pr = next((i for i in range(r, len(rows)) if rows[i][c]), None)
        if pr is None:
            continue
        rows[r], rows[pr] = rows[pr], rows[r]
        inv = pow(rows[r][c], PRIME - 2, PRIME)
        rows[r] = [x * inv % PRIME for x in rows[r]]
        for i in range(len(rows)):
            if i != r and rows[i][c]:
                f = rows[i][c]
                rows[i] = [(x - f * y) % PRIME for x, y in zip(rows[i], rows[r])]
        pivots.append(c)
        r += 1
    basis = []
    for free in (c for c in range(n) if c not in pivots):
        v = [0] * n
        v[free] = 1
        for i, pc in enumerate(pivots):
            v[pc] = (-rows[i][free]) % PRIME
        basis.append(v)
    return len(pivots), basis


def generic_motion(n: int, triples, seed: int = 2003) -> tuple[int, list]:
    """Rank of the Willis rows of *triples* with random ratios, and each link's speed
    vector over a basis of the motions (equal vectors = links locked together)."""
    rnd = random.Random(seed)
    rows = []
    for a, b, c in triples:
        e = rnd.randrange(2, PRIME - 1)
        row = [0] * n
        row[b] += 1
        row[a] -= e
        row[c] += e - 1
        rows.append([x % PRIME for x in row])
    rank, basis = _nullspace_mod_p(rows, n)
    return rank, [tuple(v[i] for v in basis) for i in range(n)]


def locked_sets(n: int, triples) -> list[list[int]]:
    """Sets of two or more links that generic ratios lock together (rigid sub-chains)."""
    _, speed = generic_motion(n, triples)
    by = {}
    for i, s in enumerate(speed):
        by.setdefault(s, []).append(i)
    return [v for v in by.values() if len(v) > 1]


def degenerate(n: int, triples) -> bool:
    """True when a gear pair repeats the others (generic rank short) or links lock together."""
    rank, speed = generic_motion(n, triples)
    return rank < len(triples) or len(set(speed)) < n


def fractionated(n: int, triples, groups=()) -> bool:
    """True when splitting one link separates the chain into two chains.

    After splitting link ``x``, two links stay joined when they share a gear pair's
    fundamental circuit (gears and carrier) or a coaxial group that does not contain ``x``
    (a group through ``x`` can always be borne on ``x``, so it splits with it).
    """
    for x in range(n):
        parent = {i: i for i in range(n) if i != x}
        sets = [[v for v in t if v != x] for t in triples]
        sets += [list(g) for g in groups if x not in g]
        for s in sets:
            for v in s[1:]:
                parent[_find(parent, v)] = _find(parent, s[0])
        if len({_find(parent, i) for i in parent}) > 1:
            return True
    return False


def _find(parent: dict, i):
    while parent[i] != i:
        parent[i] = parent[parent[i]]
        i = parent[i]
    return i


# ---------------------------------------------------------------- enumeration
@functools.cache
def _hypertrees(n: int) -> tuple:
    """``(groups, automorphisms)`` for every non-isomorphic hypertree on *n* links (cached:
    chains of every dof with *n* links start from the same trees)."""
    import networkx as nx

    out = []
    for k in range(1, n):
        for tree in nx.nonisomorphic_trees(n + k):
            colour = nx.bipartite.color(tree)
            for side in (0, 1):
                links = sorted(v for v in tree if colour[v] == side)
                group_nodes = [v for v in tree if colour[v] != side]
                if len(links) != n or any(tree.degree(g) < 2 for g in group_nodes):
                    continue
                idx = {v: i for i, v in enumerate(links)}
                groups = tuple(frozenset(idx[v] for v in tree[g]) for g in group_nodes)
                out.append((groups, automorphisms(n, groups)))
    return tuple(out)


def automorphisms(n: int, groups) -> tuple:
    """Every permutation ``p`` of the links (``p[i]``: the image of link ``i``) that maps the
    coaxial groups onto themselves: the automorphisms of the hypertree, which its groups'
    member sets determine (two groups of a tree share at most one link).

    Backtracking over the links in order, each tried only on the links of its colour after
    colour refinement, and a group checked as soon as its last member has an image.

    >>> automorphisms(3, [frozenset({0, 1}), frozenset({1, 2})])
    ((0, 1, 2), (2, 1, 0))
    """
    adj, kind = _structure(n, groups, (), True)
    colour = _refine(adj, dict(kind))
    same = [[w for w in range(n) if colour[w] == colour[v]] for v in range(n)]
    group_set = set(groups)
    closing = [[g for g in groups if max(g) == v] for v in range(n)]
    image, used, out = [0] * n, [False] * n, []

    def extend(v):
        if v == n:
            out.append(tuple(image))
            return
        for w in same[v]:
            if used[w]:
                continue
            image[v] = w
            if all(frozenset(image[u] for u in g) in group_set for g in closing[v]):
                used[w] = True
                extend(v + 1)
                used[w] = False

    extend(0)
    return tuple(out)


def _candidates(n: int, groups) -> list[tuple]:
    member = {i: [g for g in groups if i in g] for i in range(n)}
    out = []
    for c in range(n):
        for g1, g2 in itertools.combinations(member[c], 2):
            for a in g1 - {c}:
                for b in g2 - {c}:
                    out.append((min(a, b), max(a, b), c))
    return sorted(out)


def skeletons(n: int, dof: int) -> list[Skeleton]:
    """Every non-isomorphic, non-degenerate chain with *n* links and *dof* freedoms
    (fractionated ones included), in no particular order."""
    jg = n - 1 - dof
    out = []
    for groups, autos in _hypertrees(n):
        cands = _candidates(n, groups)
        index = {t: i for i, t in enumerate(cands)}
        for combo in itertools.combinations(range(len(cands)), jg):
            triples = [cands[i] for i in combo]
            if len({v for t in triples for v in t}) < n:  # a link that is neither gear nor carrier
                continue
            if any(
                tuple(sorted(index[(min(p[a], p[b]), max(p[a], p[b]), p[c])] for a, b, c in triples)) < combo
                for p in autos
            ):  # not the smallest of its orbit under the automorphisms
                continue
            if degenerate(n, triples):
                continue
            out.append(Skeleton(n, tuple(sorted(tuple(sorted(g)) for g in groups)), tuple(triples)))
    return out


# ---------------------------------------------------------------- canonical labelling
def _structure(n: int, groups, triples, with_groups: bool):
    """Adjacency ``{node: [(edge kind, node), ...]}`` and node kinds of the structure graph."""
    adj = {i: [] for i in range(n)}
    kind = dict.fromkeys(range(n), 0)
    node = n
    if with_groups:
        for g in groups:
            adj[node] = [("axis", v) for v in g]
            kind[node] = 1
            for v in g:
                adj[v].append(("axis", node))
            node += 1
    for a, b, c in triples:
        adj[node] = [("mesh", a), ("mesh", b), ("carrier", c)]
        kind[node] = 2
        adj[a].append(("mesh", node))
        adj[b].append(("mesh", node))
        adj[c].append(("carrier", node))
        node += 1
    return adj, kind


def _refine(adj, colour: dict) -> dict:
    count = len(set(colour.values()))
    while True:
        sig = {v: (colour[v], tuple(sorted((k, colour[u]) for k, u in adj[v]))) for v in adj}
        order = {s: i for i, s in enumerate(sorted(set(sig.values())))}
        colour = {v: order[sig[v]] for v in adj}
        if len(order) == count:
            return colour
        count = len(order)


def _code(perm, groups, triples, with_groups):
    g = tuple(sorted(tuple(sorted(perm[v] for v in grp)) for grp in groups)) if with_groups else ()
    t = tuple(sorted((min(perm[a], perm[b]), max(perm[a], perm[b]), perm[c]) for a, b, c in triples))
    return (g, t)


def canonical(n: int, groups, triples, *, with_groups: bool = True):
    """``(code, perm)``: the smallest code over an individualise-and-refine search, and the
    relabelling ``perm[old] = new`` that gives it. Isomorphic chains get equal codes."""
    adj, kind = _structure(n, groups, triples, with_groups)
    best = [None, None]

    def search(colour):
        colour = _refine(adj, colour)
        cells = {}
        for v in range(n):
            cells.setdefault(colour[v], []).append(v)
        open_cells = [c for c in sorted(cells) if len(cells[c]) > 1]
        if not open_cells:
            ranked = sorted(range(n), key=colour.__getitem__)
            perm = {v: i for i, v in enumerate(ranked)}
            code = _code(perm, groups, triples, with_groups)
            if best[0] is None or code < best[0]:
                best[0], best[1] = code, perm
            return
        cell = cells[open_cells[0]]
        for v in cell:
            branch = {u: 2 * c + (0 if u == v else 1) for u, c in colour.items()}
            search(branch)

    search(dict(kind))
    return best[0], best[1]
