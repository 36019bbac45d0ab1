"""Hypertrees: the coaxial structures a chain's turning pairs can have.

The turning pairs of a chain form a tree; links joined by turning pairs with one axis label
form a coaxial group. Read as a bipartite graph (link - group it belongs to), the groups of
``n`` links form a tree whose group nodes have degree two or more and whose leaves are links:
a *hypertree*. Every hypertree with ``n >= 3`` links has a leaf link (in one group only), and
removing it (and its group, if only one other link is left in it) leaves a hypertree with
``n - 1`` links. So every hypertree is grown from a smaller one by adding a link to one of
its groups or a new two-link group at one of its links; :func:`shapes` grows them so and
keeps one per isomorphism class, told apart by the tree's canonical code (:func:`tree_code`,
Aho, Hopcroft and Ullman's encoding rooted at the tree's centre).
"""

from __future__ import annotations

import functools


def tree_code(n: int, groups) -> str:
    """A string equal for two hypertrees exactly when they are isomorphic (links to links).

    >>> tree_code(3, [{0, 1}, {1, 2}]) == tree_code(3, [{2, 0}, {0, 1}])
    True
    >>> tree_code(3, [{0, 1}, {1, 2}]) == tree_code(3, [{0, 1, 2}])
    False
    """
    groups = list(groups)
    size = n + len(groups)
    adj = [[] for _ in range(size)]
    for k, g in enumerate(groups):
        for v in g:
            adj[v].append(n + k)
            adj[n + k].append(v)
    degree = [len(a) for a in adj]
    leaves = [v for v in range(size) if degree[v] <= 1]
    removed = [False] * size
    left = size
    while left > 2:  # peel leaves down to the centre (one node or an edge)
        nxt = []
        for v in leaves:
            removed[v] = True
            left -= 1
            for u in adj[v]:
                if not removed[u]:
                    degree[u] -= 1
                    if degree[u] == 1:
                        nxt.append(u)
        leaves = nxt
    centre = [v for v in range(size) if not removed[v]]

    def code(v, parent):
        inner = "".join(sorted(code(u, v) for u in adj[v] if u != parent))
        return ("L(" if v < n else "G(") + inner + ")"

    if len(centre) == 1:
        return code(centre[0], -1)
    u, w = centre
    return "|".join(sorted((code(u, w), code(w, u))))


@functools.cache
def shapes(n: int) -> tuple:
    """One hypertree per isomorphism class on *n* links: tuples of groups (sorted tuples of
    links), in a fixed order (grown link by link, first found first).

    >>> [len(shapes(k)) for k in range(2, 8)]
    [1, 2, 4, 9, 22, 59]
    """
    if n < 2:
        return ()
    level = {tree_code(2, [(0, 1)]): ((0, 1),)}
    for m in range(2, n):  # add link m
        grown = {}
        for groups in level.values():
            children = [groups[:i] + (g + (m,),) + groups[i + 1:] for i, g in enumerate(groups)]
            children += [groups + ((x, m),) for x in range(m)]
            for child in children:
                grown.setdefault(tree_code(m + 1, child), child)
        level = grown
    return tuple(level.values())
