"""An enumeration of one-dof geared kinematic chains that shares no code with gearlib's engine.

gearlib counts chains by growing hypertrees link by link, choosing gear pairs by a pruned
depth-first search (generic ratios modulo a prime, orbits of its own automorphisms) and
labelling rotation graphs canonically. This module counts the same objects another way, as
plainly as it can, so that the two can be compared hypertree by hypertree:

1. hypertrees from networkx's non-isomorphic trees: a tree on ``n + k`` nodes, bipartite, with
   ``n`` nodes on one side (the links) and the ``k`` others (the coaxial groups) of degree two
   or more;
2. gear pairs: every two links four edges apart in the tree (link, group, link, group, link),
   the middle link being the carrier;
3. every choice of ``n - 2`` of them (numpy, all combinations) that uses every link and obeys
   the counting rule: no set ``R`` of the chosen gear pairs touches ``|R| + 1`` links or fewer.
   (Generic Willis rows are independent and lock no two links exactly then: Rado's theorem on
   the subspaces span(e_a - e_c, e_b - e_c); the test suite checks the equivalence with numpy.)
   One-dof chains cannot be fractionated, so nothing else is left out;
4. displacement graphs: choices on one tree are the same chain exactly when an automorphism of
   the tree (networkx VF2, links onto links) maps one onto the other, and chains on
   non-isomorphic trees differ; so each orbit is one displacement graph;
5. rotation graphs: the displacement graphs' gear pairs and carriers alone (a graph of links
   and pairs, "mesh" and "carrier" edges), sorted into classes by Weisfeiler-Lehman hash and
   VF2.

Nine links take about a minute and a half for the displacement graphs and four to five more
for the rotation graphs. ``python tests/atlas_brute.py 9 --save FILE`` writes the record the
test suite compares gearlib with (tests/data/atlas_brute_9.json).
"""

from __future__ import annotations

import argparse
import datetime
import itertools
import json
import platform
import subprocess
import sys
import time

import networkx as nx
import numpy as np
from networkx.algorithms.isomorphism import GraphMatcher

_POPCOUNT = np.array([bin(i).count("1") for i in range(1 << 12)], dtype=np.int8)
_SAME_KIND = {"node_match": lambda x, y: x["kind"] == y["kind"], "edge_match": lambda x, y: x["kind"] == y["kind"]}


def hypertrees(n: int) -> list[nx.Graph]:
    """One tree per isomorphism class: nodes ``("l", i)`` (links ``0..n-1``) and ``("g", j)``
    (groups), attribute ``kind`` ``"l"`` or ``"g"``."""
    out = []
    for k in range(1, n):
        for tree in nx.nonisomorphic_trees(n + k):
            colour = nx.bipartite.color(tree)
            for side in (0, 1):
                links = sorted(v for v in tree if colour[v] == side)
                groups = sorted(v for v in tree if colour[v] != side)
                if len(links) == n and all(tree.degree(g) >= 2 for g in groups):
                    names = {v: ("l", i) for i, v in enumerate(links)} | {g: ("g", j) for j, g in enumerate(groups)}
                    t = nx.relabel_nodes(tree, names)
                    nx.set_node_attributes(t, {x: x[0] for x in t}, "kind")
                    out.append(t)
    return out


def groups_of(tree: nx.Graph) -> list[tuple]:
    """The coaxial groups of a hypertree, as sorted tuples of links, sorted."""
    return sorted(tuple(sorted(v[1] for v in tree[g])) for g in tree if g[0] == "g")


def gear_pairs(n: int, tree: nx.Graph) -> list[tuple]:
    """Every ``(a, b, carrier)`` with ``a < b`` four edges apart in the tree, sorted."""
    out = []
    for a in range(n):
        for (kind, b), path in nx.single_source_shortest_path(tree, ("l", a), cutoff=4).items():
            if kind == "l" and b > a and len(path) == 5:
                out.append((a, b, path[2][1]))
    return sorted(out)


def valid_choices(n: int, pairs: list, picks: int, batch: int = 400_000) -> np.ndarray:
    """Every choice (rows of indices into *pairs*) that uses every link and obeys the counting rule."""
    if len(pairs) < picks:
        return np.zeros((0, picks), dtype=np.int16)
    masks = np.array([(1 << a) | (1 << b) | (1 << c) for a, b, c in pairs], dtype=np.int32)
    every = (1 << n) - 1
    subsets = [list(s) for r in range(1, picks + 1) for s in itertools.combinations(range(picks), r)]
    kept = []
    combos = itertools.combinations(range(len(pairs)), picks)
    while True:
        flat = np.fromiter(itertools.chain.from_iterable(itertools.islice(combos, batch)), dtype=np.int16)
        if not flat.size:
            break
        rows = flat.reshape(-1, picks)
        mk = masks[rows]
        keep = np.bitwise_or.reduce(mk, axis=1) == every
        rows, mk = rows[keep], mk[keep]
        for s in subsets:  # |links(R)| >= |R| + 2 for every set R of the chosen pairs
            keep = _POPCOUNT[np.bitwise_or.reduce(mk[:, s], axis=1)] >= len(s) + 2
            rows, mk = rows[keep], mk[keep]
        kept.append(rows)
    return np.concatenate(kept)


def tree_automorphisms(n: int, tree: nx.Graph) -> list[tuple]:
    """Every permutation of the links that networkx's VF2 finds as an automorphism of the tree."""
    matcher = GraphMatcher(tree, tree, node_match=lambda x, y: x["kind"] == y["kind"])
    return [tuple(m[("l", v)][1] for v in range(n)) for m in matcher.isomorphisms_iter()]


def orbits(pairs: list, autos: list, choices: np.ndarray) -> list[tuple]:
    """One representative (the smallest sorted tuple of pairs) per orbit of the choices."""
    index = {t: i for i, t in enumerate(pairs)}
    seen, reps = set(), []
    for row in choices:
        key = tuple(sorted(int(i) for i in row))
        if key in seen:
            continue
        orbit = {tuple(sorted(index[(min(p[pairs[i][0]], p[pairs[i][1]]), max(p[pairs[i][0]], p[pairs[i][1]]),
                                     p[pairs[i][2]])] for i in key)) for p in autos}
        seen |= orbit
        reps.append(tuple(pairs[i] for i in min(orbit)))
    return reps


def displacement_graphs(n: int) -> list[dict]:
    """Per hypertree: its groups and one gear-pair choice per displacement graph on it."""
    out = []
    for tree in hypertrees(n):
        pairs = gear_pairs(n, tree)
        choices = valid_choices(n, pairs, n - 2)
        reps = orbits(pairs, tree_automorphisms(n, tree), choices) if len(choices) else []
        out.append({"groups": groups_of(tree), "chains": reps})
    return out


def pair_graph(n: int, triples) -> nx.Graph:
    """Links and gear pairs: a pair node joined to its gears ("mesh") and its carrier ("carrier")."""
    g = nx.Graph()
    g.add_nodes_from((("l", v) for v in range(n)), kind="link")
    for k, (a, b, c) in enumerate(triples):
        g.add_node(("p", k), kind="pair")
        g.add_edges_from([(("p", k), ("l", a)), (("p", k), ("l", b))], kind="mesh")
        g.add_edge(("p", k), ("l", c), kind="carrier")
    return g


def rotation_classes(n: int, chains: list) -> list[int]:
    """The rotation graph of each chain (gear-pair triples), as a class number, by WL hash and VF2."""
    buckets, out, count = {}, [], 0
    for triples in chains:
        g = pair_graph(n, triples)
        bucket = buckets.setdefault(nx.weisfeiler_lehman_graph_hash(g, node_attr="kind", edge_attr="kind"), [])
        for rep, label in bucket:
            if nx.is_isomorphic(g, rep, **_SAME_KIND):
                out.append(label)
                break
        else:
            bucket.append((g, count))
            out.append(count)
            count += 1
    return out


def count(n: int) -> dict:
    """Both levels for *n* links, with the number of displacement graphs on each hypertree."""
    start = time.perf_counter()
    trees = displacement_graphs(n)
    middle = time.perf_counter()
    labels = rotation_classes(n, [t for tree in trees for t in tree["chains"]])
    end = time.perf_counter()
    return {"links": n, "dof": 1, "coaxial": sum(len(t["chains"]) for t in trees), "kinematic": len(set(labels)),
            "seconds": {"coaxial": round(middle - start, 1), "kinematic": round(end - middle, 1)},
            "hypertrees": [{"groups": t["groups"], "coaxial": len(t["chains"])} for t in trees]}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("links", type=int)
    parser.add_argument("--save", metavar="FILE")
    args = parser.parse_args(argv)
    found = count(args.links)
    print(f"{args.links} links: {found['coaxial']} displacement graphs, {found['kinematic']} rotation graphs "
          f"({found['seconds']['coaxial']} s + {found['seconds']['kinematic']} s)")
    if args.save:
        try:
            commit = subprocess.run(["git", "rev-parse", "HEAD"], capture_output=True, text=True, check=True).stdout
        except (OSError, subprocess.SubprocessError):
            commit = ""
        record = {"about": "One-dof geared kinematic chains counted by tests/atlas_brute.py, an enumeration that "
                           "shares no code with gearlib's engine (networkx trees, all combinations of gear pairs, "
                           "the counting rule, VF2 automorphisms and isomorphisms).",
                  "command": f"python tests/atlas_brute.py {args.links} --save {args.save}",
                  "date": datetime.datetime.now(datetime.UTC).replace(microsecond=0).isoformat(),
                  "commit": commit.strip(),
                  "python": platform.python_version(), "networkx": nx.__version__, "numpy": np.__version__,
                  **found}
        trees = record.pop("hypertrees")
        text = json.dumps(record, indent=1)[:-2]  # one hypertree a line
        text += ',\n "hypertrees": [\n' + ",\n".join(f"  {json.dumps(t)}" for t in trees) + "\n ]\n}\n"
        with open(args.save, "w", encoding="utf-8") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
