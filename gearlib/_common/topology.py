"""Coaxial groups, transfer vertices (carriers) and connectivity, on plain ids.

Two links are *coaxial* when a path of turning pairs (thin edges) with a single axis
label joins them (Tsai's rule). For each label the thin edges carrying it fall into
connected *coaxial groups*; a link belongs to at most one group per label.

A gear pair's *carrier* (transfer vertex) is the link coaxial with one gear on some axis
and with the other gear on a different axis. Used by :mod:`gearlib.mechanism` while it
validates, and by the graph functions.
"""

from __future__ import annotations

from collections import defaultdict


class UnionFind:
    """Disjoint sets over hashable items (path halving, union by size)."""

    def __init__(self, items=()):
        self.parent = {x: x for x in items}
        self.size = dict.fromkeys(self.parent, 1)

    def add(self, x):
        if x not in self.parent:
            self.parent[x] = x
            self.size[x] = 1

    def find(self, x):
        parent = self.parent
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    def union(self, a, b) -> bool:
        ra, rb = self.find(a), self.find(b)
        if ra == rb:
            return False
        if self.size[ra] < self.size[rb]:
            ra, rb = rb, ra
        self.parent[rb] = ra
        self.size[ra] += self.size[rb]
        return True

    def groups(self) -> list[list]:
        out = defaultdict(list)
        for x in self.parent:
            out[self.find(x)].append(x)
        return list(out.values())


class CoaxialGroups:
    """The coaxial groups of a set of turning pairs ``(a, b, label)``.

    Attributes
    ----------
    membership : dict
        ``membership[link][label]`` is the id (a small int) of the group of *link* on *label*.
    members : list of frozenset
        ``members[g]`` are the links of group ``g``; ``labels[g]`` its axis label.
    redundant : list of int
        Indices of turning pairs that close a loop inside one group (redundant coaxial bearings).
    """

    def __init__(self, turning_pairs):
        by_label = defaultdict(UnionFind)
        self.redundant = []
        for i, (a, b, label) in enumerate(turning_pairs):
            uf = by_label[label]
            uf.add(a)
            uf.add(b)
            if not uf.union(a, b):
                self.redundant.append(i)
        self.members: list[frozenset] = []
        self.labels: list[str] = []
        self.membership: dict = defaultdict(dict)
        for label in sorted(by_label, key=str):
            for group in by_label[label].groups():
                gid = len(self.members)
                self.members.append(frozenset(group))
                self.labels.append(label)
                for link in group:
                    self.membership[link][label] = gid

    def coaxial_label(self, u, v):
        """The axis label on which *u* and *v* are coaxial, or None."""
        mu, mv = self.membership.get(u, {}), self.membership.get(v, {})
        for label, gid in mu.items():
            if mv.get(label) == gid:
                return label
        return None

    def carrier_candidates(self, a, b) -> list[tuple]:
        """Every ``(carrier, label_a, label_b)`` with *a* coaxial to the carrier on ``label_a``
        and *b* on a different ``label_b``."""
        out = []
        ma, mb = self.membership.get(a, {}), self.membership.get(b, {})
        for la, ga in ma.items():
            for lb, gb in mb.items():
                if la == lb:
                    continue
                for k in self.members[ga] & self.members[gb]:
                    if k != a and k != b:
                        out.append((k, la, lb))
        return out

    def mixed_loop(self):
        """A list of links on a loop of turning pairs that uses more than one axis label,
        or None. Such a loop is rigid or mislabelled."""
        uf = UnionFind()
        for link, groups in self.membership.items():
            node = ("link", link)
            uf.add(node)
            for gid in groups.values():
                g = ("group", gid)
                uf.add(g)
                if not uf.union(node, g):
                    # the loop passes through this link and group; name the group's links
                    return sorted(self.members[gid] | {link}, key=str)
        return None


def components(nodes, edges) -> list[list]:
    """Connected components (lists of nodes, in the order of *nodes*) of an undirected graph."""
    uf = UnionFind(nodes)
    for a, b in edges:
        uf.union(a, b)
    order = {x: i for i, x in enumerate(nodes)}
    comps = [sorted(g, key=order.__getitem__) for g in uf.groups()]
    comps.sort(key=lambda g: order[g[0]])
    return comps
