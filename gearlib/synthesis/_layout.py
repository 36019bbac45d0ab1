"""A drawing layout for geared chains with as few edge crossings as the graph allows.

The default layout of :func:`gearlib.draw_graph` (Kamada-Kawai from a circle) often draws a
planar chain with an edge or two crossing, or a vertex on an edge it does not belong to.
Here, for a planar graph, Tutte's barycentric embedding is made with each face of a planar
embedding in turn as the outer polygon: it has no crossing (for a 3-connected graph; for the
others it may put a vertex on an edge). Each candidate, and the default layout, is then
relaxed towards the graph distances (stress majorization) one vertex at a time, a move being
kept only when it adds no crossing and brings no vertex closer to an edge than *clearance*.
The candidate with the fewest crossings, then the fewest vertices on edges, then the lowest
stress is kept. Deterministic: no random state is used.
"""

from __future__ import annotations

import functools
import itertools
import math

CLEARANCE = 0.16  # the least distance of a vertex from an edge it is not an end of, per drawing size
SPACING = 0.26  # the least distance between two vertices, per drawing size


def _orient(a, b, c) -> float:
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def _cross(p, q, r, s) -> bool:
    """Segments pq and rs cross properly (no shared end point is passed in)."""
    return _orient(r, s, p) * _orient(r, s, q) < 0 and _orient(p, q, r) * _orient(p, q, s) < 0


def _distance_to_segment(p, a, b) -> float:
    dx, dy = b[0] - a[0], b[1] - a[1]
    length = dx * dx + dy * dy
    t = 0.0 if length == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length))
    return math.hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1])


def _size(pos: dict) -> float:
    xs = [p[0] for p in pos.values()]
    ys = [p[1] for p in pos.values()]
    return max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)


def crossings(pos: dict, edges) -> int:
    """The number of pairs of edges (with four different end vertices) whose segments cross."""
    return sum(1 for (a, b), (c, d) in itertools.combinations(edges, 2)
               if len({a, b, c, d}) == 4 and _cross(pos[a], pos[b], pos[c], pos[d]))


def _clashes(pos: dict, edges, clearance: float) -> int:
    """Vertices nearer than *clearance* (times the drawing's size) to an edge they are not an
    end of, and pairs of vertices nearer than *SPACING* times the size."""
    r = clearance * _size(pos)
    near = sum(1 for v, p in pos.items() for a, b in edges
               if v not in (a, b) and _distance_to_segment(p, pos[a], pos[b]) < r)
    close = sum(1 for u, v in itertools.combinations(pos, 2) if math.dist(pos[u], pos[v]) < r * SPACING / clearance)
    return near + close


def _local(pos: dict, edges, v, r: float, incident: dict) -> tuple:
    """(crossings, clashes) that involve vertex *v*, a clash being nearer than *r* (a vertex to
    a foreign edge) or ``r * SPACING / CLEARANCE`` (two vertices)."""
    mine = incident[v]
    p = pos[v]
    crossed = sum(1 for (a, b) in mine for (x, y) in edges
                  if len({a, b, x, y}) == 4 and _cross(pos[a], pos[b], pos[x], pos[y]))
    near = sum(1 for a, b in edges if v not in (a, b) and _distance_to_segment(p, pos[a], pos[b]) < r)
    near += sum(1 for a, b in mine for u, q in pos.items()
                if u not in (a, b) and _distance_to_segment(q, pos[a], pos[b]) < r)
    spacing = r * SPACING / CLEARANCE
    near += sum(1 for u, q in pos.items() if u != v and math.dist(p, q) < spacing)
    return crossed, near


def _faces(embedding) -> list:
    seen: set = set()
    out = []
    for u, v in embedding.edges():
        if (u, v) not in seen:
            out.append(embedding.traverse_face(u, v, mark_half_edges=seen))
    return out


def _tutte(graph, outer) -> dict:
    """Outer face on a regular polygon, every other vertex at the mean of its neighbours."""
    import numpy as np

    k = len(outer)
    pos = {v: (math.cos(2 * math.pi * i / k + math.pi / 2), math.sin(2 * math.pi * i / k + math.pi / 2))
           for i, v in enumerate(outer)}
    inner = [v for v in graph if v not in pos]
    if inner:
        index = {v: i for i, v in enumerate(inner)}
        a = np.zeros((len(inner), len(inner)))
        b = np.zeros((len(inner), 2))
        for v in inner:
            for w in graph.neighbors(v):
                a[index[v], index[v]] += 1
                if w in pos:
                    b[index[v]] += pos[w]
                else:
                    a[index[v], index[w]] -= 1
        x = np.linalg.solve(a, b)
        pos.update({v: (float(x[index[v], 0]), float(x[index[v], 1])) for v in inner})
    return pos


def _stress(pos: dict, dist: dict) -> float:
    """Stress after the best uniform scaling of the drawing: sum of (s |p_u - p_v| - d)^2 / d^2."""
    pairs = [(math.dist(pos[u], pos[v]), d) for (u, v), d in dist.items()]
    num = sum(x / d for x, d in pairs)
    den = sum(x * x / (d * d) for x, d in pairs) or 1.0
    s = num / den
    return sum((s * x - d) ** 2 / (d * d) for x, d in pairs)


def _relax(pos: dict, edges, dist: dict, clearance: float, rounds: int = 40) -> dict:
    """Stress majorization, one vertex at a time, keeping a move only when it makes no more
    crossings or clashes at that vertex than before."""
    pos = dict(pos)
    size = _size(pos)
    scale = sum(dist.values()) / len(dist)
    pos = {v: (x / size * scale * 2, y / size * scale * 2) for v, (x, y) in pos.items()}
    nodes = sorted(pos, key=str)
    incident = {v: [e for e in edges if v in e] for v in nodes}
    for _ in range(rounds):
        moved = 0.0
        r = clearance * _size(pos)
        for v in nodes:
            x = y = wsum = 0.0
            for u in nodes:
                if u == v:
                    continue
                d = dist[(u, v) if (u, v) in dist else (v, u)]
                w = 1.0 / (d * d)
                px, py = pos[v][0] - pos[u][0], pos[v][1] - pos[u][1]
                norm = math.hypot(px, py) or 1e-9
                x += w * (pos[u][0] + d * px / norm)
                y += w * (pos[u][1] + d * py / norm)
                wsum += w
            target = (x / wsum, y / wsum)
            before = _local(pos, edges, v, r, incident)
            old = pos[v]
            for step in (1.0, 0.5, 0.25):
                pos[v] = (old[0] + step * (target[0] - old[0]), old[1] + step * (target[1] - old[1]))
                if _local(pos, edges, v, r, incident) <= before:
                    moved = max(moved, math.dist(old, pos[v]))
                    break
            else:
                pos[v] = old
        if moved < 1e-3 * scale:
            break
    return pos


def _repair(pos: dict, edges, dist: dict, clearance: float, passes: int = 6) -> dict:
    """Move single vertices (16 directions, four distances) while that removes a crossing or
    a clash; of the moves that remove the most, the one of lowest stress."""
    pos = dict(pos)
    incident = {v: [e for e in edges if v in e] for v in pos}
    for _ in range(passes):
        size = _size(pos)
        r = clearance * size
        best = None
        for v in sorted(pos, key=str):
            old = pos[v]
            before = _local(pos, edges, v, r, incident)
            if before == (0, 0):
                continue
            for k in range(16):
                for step in (0.12, 0.2, 0.3, 0.45):
                    a = 2 * math.pi * k / 16
                    pos[v] = (old[0] + step * size * math.cos(a), old[1] + step * size * math.sin(a))
                    after = _local(pos, edges, v, r, incident)
                    gain = (before[0] - after[0], before[1] - after[1])
                    if gain > (0, 0) and after[0] <= before[0]:
                        cand = ((-gain[0], -gain[1]), _stress(pos, dist), v, pos[v])
                        if best is None or cand[:2] < best[:2]:
                            best = cand
            pos[v] = old
        if best is None:
            break
        pos[best[2]] = best[3]
        pos = _relax(pos, edges, dist, clearance)
    return pos


@functools.lru_cache(maxsize=128)
def layout(nodes: tuple, edges: tuple, start: tuple = (), clearance: float = CLEARANCE) -> tuple:
    """Positions ``((node, (x, y)), ...)`` for the graph (*nodes*, *edges*); *start* is one
    more layout to consider (the default one)."""
    import networkx as nx

    graph = nx.Graph()
    graph.add_nodes_from(nodes)
    edges = tuple({frozenset(e): tuple(e) for e in edges if e[0] != e[1]}.values())
    graph.add_edges_from(edges)
    if len(nodes) <= 2:
        return tuple((n, (float(i), 0.0)) for i, n in enumerate(nodes))
    lengths = dict(nx.all_pairs_shortest_path_length(graph))
    far = max((d for row in lengths.values() for d in row.values()), default=1) + 1
    dist = {(u, v): float(lengths[u].get(v, far)) for u, v in itertools.combinations(nodes, 2)}
    candidates = [dict(start)] if start else []
    planar, embedding = nx.check_planarity(graph)
    if planar and nx.is_connected(graph):
        candidates += [_tutte(graph, face) for face in _faces(embedding) if len(set(face)) == len(face) >= 3]
    if not candidates:
        candidates = [{v: (math.cos(2 * math.pi * i / len(nodes)), math.sin(2 * math.pi * i / len(nodes)))
                       for i, v in enumerate(nodes)}]
    def key(pos):
        return crossings(pos, edges), _clashes(pos, edges, clearance), _stress(pos, dist)

    ranked = sorted((key(p), i, p) for i, p in enumerate(_relax(p, edges, dist, clearance) for p in candidates))
    if ranked[0][0][:2] != (0, 0):  # repair the two best, keep the best repaired
        repaired = [_repair(p, edges, dist, clearance) for _, _, p in ranked[:2]]
        ranked = sorted((key(p), i, p) for i, p in enumerate(repaired))
    pos = ranked[0][2]
    # centred, the longer side of width 2
    cx = (max(p[0] for p in pos.values()) + min(p[0] for p in pos.values())) / 2
    cy = (max(p[1] for p in pos.values()) + min(p[1] for p in pos.values())) / 2
    size = _size(pos) / 2
    return tuple((n, ((pos[n][0] - cx) / size, (pos[n][1] - cy) / size)) for n in nodes)
