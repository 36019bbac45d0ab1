"""The engine behind :mod:`gearlib.synthesis.atlas`: geared kinematic chains as plain integers.

A chain skeleton has links ``0 .. n-1``, *coaxial groups* (sets of at least two links that
turning pairs with one axis label join) and *triples* ``(a, b, c)``: a gear pair between
gears ``a < b`` on the carrier ``c``. The turning pairs form a tree, so the bipartite graph
"link belongs to group" is a tree too (a *hypertree*, see ``_trees``); the tree of
bearings inside a group does not change the kinematics and is not part of a skeleton.

Enumeration (:func:`skeletons`), for each hypertree: the candidate gear pairs are the pairs of
links that share a carrier on two different axes (links two groups apart in the tree); a
depth-first search picks ``n - 1 - dof`` of them in increasing order and abandons a partial
choice as soon as no completion can pass: a gear pair that repeats the others (generic rank
short) or links locked together stay so when pairs are added, a link that no later candidate
reaches stays idle, and a choice that an automorphism of the tree maps onto a
lexicographically smaller one has only completions that are not the smallest of their orbit.
So each chain is reached once, as the smallest choice of its orbit, without a canonical form.
Generic (random) gear ratios in the field of integers modulo the prime ``2**61 - 1`` stand
for symbolic ones in the rank tests; a false answer would need a random ratio to hit a
root of a non-zero polynomial, with probability below ``1e-15``.
"""

from __future__ import annotations

import functools
import itertools
import operator
import random
from dataclasses import dataclass

from ._canon import automorphisms, canonical
from ._trees import shapes

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

    >>> fractionated(5, [(1, 2, 0), (3, 4, 0)], [(0, 1), (0, 2), (0, 3), (0, 4)])  # two pairs on one carrier
    True
    """
    every = (1 << n) - 1
    circuits = [sum(1 << v for v in t) for t in triples]
    axes = [sum(1 << v for v in g) for g in groups]
    for x in range(n):
        bit = 1 << x
        rest = every & ~bit
        sets = [m & ~bit for m in circuits] + [m for m in axes if not m & bit]
        reach = rest & -rest  # the lowest link but x; grow what joins it
        grown = True
        while grown:
            grown = False
            for m in sets:
                if m & reach and m & ~reach:
                    reach |= m
                    grown = True
        if reach != rest:
            return True
    return False
# ---------------------------------------------------------------- enumeration
__all__ = ["Skeleton", "generic_motion", "locked_sets", "degenerate", "fractionated", "skeletons",
           "automorphisms", "canonical"]


@functools.cache
def _hypertrees(n: int) -> tuple:
    """``(groups, automorphisms)`` for every non-isomorphic hypertree on *n* links, groups as
    frozensets (cached). :func:`skeletons` computes automorphisms only for the trees that
    have enough candidate gear pairs."""
    return tuple((tuple(frozenset(g) for g in groups), automorphisms(n, groups)) for groups in shapes(n))


def _candidates(n: int, groups) -> list[tuple]:
    """Every gear pair ``(a, b, c)`` the tree allows: ``a`` and ``c`` in one group, ``b`` and
    ``c`` in another (links two groups apart, ``c`` between them), sorted."""
    member = {i: [g for g in groups if i in g] for i in range(n)}
    out = []
    for c in range(n):
        for g1, g2 in itertools.combinations(member[c], 2):
            for a in set(g1) - {c}:
                for b in set(g2) - {c}:
                    out.append((min(a, b), max(a, b), c))
    return sorted(out)


@functools.cache
def _ratios(n: int) -> dict:
    """A generic gear ratio (a random integer modulo :data:`PRIME`) for every triple of links."""
    rnd = random.Random(2003)
    return {t: rnd.randrange(2, PRIME - 1) for t in itertools.product(range(n), repeat=3)}


def _tree_chains(n: int, groups, picks: int) -> list[tuple]:
    """The chains on one hypertree: each a tuple of *picks* triples, the smallest of its orbit
    under the tree's automorphisms (see the module's docstring)."""
    cands = _candidates(n, groups)
    m = len(cands)
    if m < picks:
        return []
    index = {t: i for i, t in enumerate(cands)}
    weight = [1 << (m - 1 - i) for i in range(m)]  # a set's lexicographic rank, reversed: smaller is larger
    moves = [p for p in automorphisms(n, groups) if any(p[i] != i for i in range(n))]
    # moved[i][k]: weight of the image of candidate i under automorphism k
    image = [[index[(min(p[a], p[b]), max(p[a], p[b]), p[c])] for p in moves] for a, b, c in cands]
    moved = [[weight[j] for j in row] for row in image]
    ratios = _ratios(n)
    gears = [(a, b, c, ratios[(a, b, c)]) for a, b, c in cands]
    reach = [(1 << a) | (1 << b) | (1 << c) for a, b, c in cands]
    later = [0] * (m + 1)  # links that candidates i.. reach
    for i in range(m - 1, -1, -1):
        later[i] = later[i + 1] | reach[i]
    every = (1 << n) - 1
    out, chosen = [], []
    add = operator.add

    def search(start, basis, covered, rank, images):
        depth = len(chosen)
        for i in range(start, m - (picks - depth) + 1):
            cov = covered | reach[i]
            idle = every & ~cov
            if idle & ~later[i + 1] or idle.bit_count() > 3 * (picks - depth - 1):
                continue  # some link can no longer be reached
            a, b, c, e = gears[i]
            f = e - 1
            dots = [(u[b] - e * u[a] + f * u[c]) % PRIME for u in basis]
            j = next((j for j, d in enumerate(dots) if d), None)
            if j is None:
                continue  # the Willis row of this pair repeats the others
            pivot, dj = basis[j], dots[j]
            new = [u if not d else [(dj * x - d * y) % PRIME for x, y in zip(u, pivot)]
                   for k, (u, d) in enumerate(zip(basis, dots)) if k != j]
            if len(set(zip(*new))) < n:
                continue  # two links turn together for generic ratios: locked
            r2 = rank + weight[i]
            if moves:
                imgs = list(map(add, images, moved[i]))
                if max(imgs) > r2:
                    continue  # an automorphism maps the choice onto a smaller one
            else:
                imgs = images
            chosen.append(i)
            if depth + 1 == picks:
                out.append(tuple(cands[k] for k in chosen))
            else:
                search(i + 1, new, cov, r2, imgs)
            chosen.pop()

    identity = [[int(i == j) for i in range(n)] for j in range(n)]
    search(0, identity, 0, 0, [0] * len(moves))
    return out


def skeletons(n: int, dof: int) -> list[Skeleton]:
    """Every non-isomorphic, non-degenerate chain with *n* links and *dof* freedoms
    (fractionated ones included), hypertree by hypertree in a fixed order.

    >>> [len(skeletons(k, 1)) for k in range(3, 7)]
    [1, 3, 13, 81]
    """
    picks = n - 1 - dof
    if picks < 1:
        return []
    out = []
    for groups in shapes(n):
        sorted_groups = tuple(sorted(groups))
        out += [Skeleton(n, sorted_groups, triples) for triples in _tree_chains(n, groups, picks)]
    return out
