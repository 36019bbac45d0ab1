"""Axis labels of turning pairs left out, inferred from the carriers of the gear pairs.

Penaud and Alazard's tables mark a turning pair with a bare "p": no axis. When every gear pair
names its carrier, the labels follow: the turning pairs on the path from a gear to its
carrier all turn about the gear's axis (one label), a loop of turning pairs is coaxial (one
label), and the two gears of a pair lie on different axes of their carrier. Each class of
turning pairs tied together this way gets one label: the label given to one of them, or a new
one (``p1``, ``p2``, ...). Private helper of :class:`gearlib.Mechanism`.
"""

from __future__ import annotations

from collections import deque

from .._common.topology import UnionFind
from ..errors import AxisError, CarrierError

__all__ = ["infer_axes"]


def _tree(ids, tps):
    """A spanning forest of the turning pairs: ``parent[link] = (parent link, pair index)``,
    depth, and the pairs left out of it (each closes a loop)."""
    adj: dict = {x: [] for x in ids}
    for i, tp in enumerate(tps):
        a, b = tp.links
        adj[a].append((b, i))
        adj[b].append((a, i))
    parent, depth, used = {}, {}, set()
    for root in ids:
        if root in depth:
            continue
        depth[root], parent[root] = 0, None
        queue = deque([root])
        while queue:
            x = queue.popleft()
            for y, i in adj[x]:
                if y not in depth:
                    depth[y], parent[y] = depth[x] + 1, (x, i)
                    used.add(i)
                    queue.append(y)
    return parent, depth, [i for i in range(len(tps)) if i not in used]


def _path(parent, depth, u, v):
    """Indices of the turning pairs on the tree path from *u* to *v*, or None (not joined)."""
    out = []
    while u != v:
        if depth[u] >= depth[v]:
            if parent[u] is None:
                return None
            u, i = parent[u]
        else:
            if parent[v] is None:
                return None
            v, i = parent[v]
        out.append(i)
    return out


def infer_axes(ids, tps, gps, make):
    """*tps* with every missing label filled in (``make(tp, label)`` builds the new pair)."""
    missing = [tp for tp in tps if tp.axis is None]
    if not missing:
        return tps
    without = next((gp for gp in gps if gp.carrier is None), None)
    if without is not None:
        a, b = missing[0].links
        raise AxisError(
            f"turning pair ({a}, {b}) has no axis label, and gear pair {without.label} no `carrier`: give the "
            "turning pairs their labels, or give every gear pair its carrier so that the labels can be inferred")
    parent, depth, loops = _tree(ids, tps)
    uf = UnionFind(range(len(tps)))
    for i in loops:  # a loop of turning pairs turns about one axis
        a, b = tps[i].links
        for j in _path(parent, depth, a, b):
            uf.union(i, j)
    sides = []
    for gp in gps:
        ends = []
        for g in gp.gears:
            path = _path(parent, depth, g, gp.carrier)
            if not path:
                raise CarrierError(f"gear pair {gp.label}: no turning pairs join gear {g} to its carrier "
                                   f"{gp.carrier}; add the turning pair that holds it")
            for j in path[1:]:
                uf.union(path[0], j)
            ends.append(path[0])
        sides.append((gp, ends))
    label_of: dict = {}
    for i, tp in enumerate(tps):
        if tp.axis is not None:
            root = uf.find(i)
            if label_of.setdefault(root, tp.axis) != tp.axis:
                raise AxisError(f"turning pair {tp.links} is labelled {tp.axis!r}, but the carriers put it on the "
                                f"axis labelled {label_of[root]!r}; fix one label or leave it out")
    taken = {tp.axis for tp in tps if tp.axis is not None}
    fresh = (f"p{k}" for k in range(1, 10 * len(tps) + 10) if f"p{k}" not in taken)
    for i in range(len(tps)):
        root = uf.find(i)
        if root not in label_of:
            label_of[root] = next(fresh)
    for gp, (i, j) in sides:
        if uf.find(i) == uf.find(j):
            raise AxisError(f"gear pair {gp.label}: with carrier {gp.carrier} both gears would turn about one axis "
                            "(the turning pairs join them on one path); check the carrier or the turning pairs")
    return tuple(tp if tp.axis is not None else make(tp, label_of[uf.find(i)]) for i, tp in enumerate(tps))
