"""Canonical labelling and automorphisms of chain skeletons, by colour refinement.

A skeleton (links ``0 .. n-1``, coaxial groups, gear triples ``(a, b, carrier)``) is read as a
coloured graph: one node per link, per coaxial group (unless ``with_groups`` is false: the
kinematic level) and per gear triple, with edges of three kinds, ``axis`` (link in group),
``carrier`` and ``mesh`` (triple to its carrier and to its gears). Nodes and edge kinds are
small integers; kinds are numbered in the order of their names (axis, carrier, mesh), so that
colours are ranked exactly as when the signatures held the names.

:func:`canonical` is an individualise-and-refine search: refine the colours until stable,
then branch on each link of the first link cell with more than one link, and keep the
smallest code found at a leaf (all links told apart). Isomorphic skeletons reach the same set
of leaf codes, so they get the same smallest code; two skeletons with the same code are the
same skeleton relabelled, so the code decides isomorphism exactly.
"""

from __future__ import annotations

AXIS, CARRIER, MESH = 0, 1, 2  # edge kinds, in the order of their names
LINK, GROUP, PAIR = 0, 1, 2  # node kinds


def structure(n: int, groups, triples, with_groups: bool):
    """``(graph, kind)``: the skeleton's graph as :func:`refine` reads it, and the node kinds.

    Nodes ``0..n-1`` are the links, then one per group (if *with_groups*), then one per triple.
    ``graph`` is ``(size, general, pairs)``: ``general`` lists ``(node, [(edge kind * scale,
    neighbour), ...])`` for the links and groups, ``pairs`` lists ``(node, carrier, gear,
    gear)`` for the triples, whose three edges need no sorting.
    """
    adj = [[] for _ in range(n)]
    kind = [LINK] * n
    pairs = []
    if with_groups:
        for g in groups:
            node = len(adj)
            adj.append([(AXIS, v) for v in g])
            kind.append(GROUP)
            for v in g:
                adj[v].append((AXIS, node))
    for a, b, c in triples:
        node = len(adj)
        adj.append(None)
        kind.append(PAIR)
        pairs.append((node, c, a, b))
        adj[a].append((MESH, node))
        adj[b].append((MESH, node))
        adj[c].append((CARRIER, node))
    size = len(adj)
    scale = 4 * size + 4
    general = [(v, [(k * scale, u) for k, u in nbrs]) for v, nbrs in enumerate(adj) if nbrs is not None]
    return (size, general, pairs), kind


def refine(graph, colour: list) -> list:
    """Colour refinement: a node's new colour ranks (its colour, the sorted (edge kind,
    colour) of its neighbours) among all nodes'; repeated until no cell splits.

    Colours are non-negative integers below ``4 * size`` (the search's branch colours stay
    below that); the ranks come out ``0, 1, ...`` in the order of the signatures.
    """
    size, general, pairs = graph
    scale = 4 * size + 4
    on_carrier, on_gear = CARRIER * scale, MESH * scale
    count = len(set(colour))
    while True:
        sig = [None] * size
        for v, nbrs in general:
            sig[v] = (colour[v], *sorted([k + colour[u] for k, u in nbrs]))
        for v, c, a, b in pairs:
            x, y = colour[a], colour[b]
            if x > y:
                x, y = y, x
            sig[v] = (colour[v], on_carrier + colour[c], on_gear + x, on_gear + y)
        order = {s: i for i, s in enumerate(sorted(set(sig)))}
        colour = [order[s] for s in sig]
        if len(order) == count:
            return colour
        count = len(order)


def code_of(perm, groups, triples, with_groups: bool) -> tuple:
    """The skeleton relabelled by ``perm[old] = new``, groups and triples sorted."""
    g = tuple(sorted(tuple(sorted(perm[v] for v in grp)) for grp in groups)) if with_groups else ()
    t = tuple(sorted((min(perm[a], perm[b]), max(perm[a], perm[b]), perm[c]) for a, b, c in triples))
    return (g, t)


def canonical(n: int, groups, triples, *, with_groups: bool = True):
    """``(code, perm)``: the smallest code over an individualise-and-refine search, and the
    relabelling ``perm[old] = new`` (a dict over the links) that gives it. Isomorphic
    skeletons get equal codes, non-isomorphic ones different codes.

    >>> canonical(3, [(0, 1), (0, 2)], [(1, 2, 0)])[0]
    (((0, 1), (0, 2)), ((1, 2, 0),))
    """
    graph, kind = structure(n, groups, triples, with_groups)
    best = [None, None, ()]  # code, perm, the path of links individualised to reach it
    path = []

    def search(colour):
        """Explore below this node; return the depth to climb back to (None: go on)."""
        colour = refine(graph, colour)
        cells = {}
        for v in range(n):
            cells.setdefault(colour[v], []).append(v)
        if len(cells) == n:  # every link told apart: a leaf
            ranked = sorted(range(n), key=colour.__getitem__)
            perm = [0] * n
            for i, v in enumerate(ranked):
                perm[v] = i
            code = code_of(perm, groups, triples, with_groups)
            if best[0] is None or code < best[0]:
                best[0], best[1], best[2] = code, perm, tuple(path)
            elif code == best[0]:
                # The two leaves differ by an automorphism that fixes the colours where
                # their paths part and maps one branch there onto the other: the rest of
                # this branch repeats codes already seen.
                return next((d for d, (x, y) in enumerate(zip(path, best[2])) if x != y), len(path))
            return None
        cell = cells[min(c for c, vs in cells.items() if len(vs) > 1)]
        depth = len(path)
        for v in cell:
            path.append(v)
            back = search([2 * c + (u != v) for u, c in enumerate(colour)])
            path.pop()
            if back is not None and back < depth:
                return back
        return None

    search(kind)
    return best[0], dict(enumerate(best[1]))


def automorphisms(n: int, groups) -> tuple:
    """Every permutation ``p`` of the links (``p[i]``: the image of link ``i``) that maps the
    coaxial groups onto themselves: the automorphisms of the hypertree, which its groups'
    member sets determine (two groups of a tree share at most one link).

    Backtracking over the links in order, each tried only on the links of its colour after
    colour refinement, and a group checked as soon as its last member has an image.

    >>> automorphisms(3, [frozenset({0, 1}), frozenset({1, 2})])
    ((0, 1, 2), (2, 1, 0))
    """
    graph, kind = structure(n, groups, (), True)
    colour = refine(graph, kind)
    same = [[w for w in range(n) if colour[w] == colour[v]] for v in range(n)]
    group_set = {frozenset(g) for g in groups}
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
