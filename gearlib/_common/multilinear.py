"""Fast factoring of multilinear polynomials, the kind gear trains produce.

Each gear ratio ``e_a_b`` appears in exactly one Willis equation, that is in one row of the
Willis matrix, so every minor of that matrix, and by Cramer's rule the numerator and the
denominator of every speed ratio, has degree at most one in each ratio: it is
*multilinear*. A multilinear polynomial factors into multilinear factors on disjoint sets
of variables, and two variables ``x``, ``y`` lie in different factors exactly when

    f * d2f/dxdy == df/dx * df/dy

(write ``f = A x y + B x + C y + D``; the difference is ``A D - B C``, which vanishes exactly
when ``A f = (A x + C)(A y + B)``). So the variable sets of the factors are the connected
components of the graph joining the variables that fail this test, and each factor is
``f`` with the other variables set to numbers. This costs a few polynomial products instead
of a general multivariate factorization (Wang's algorithm), which is most of the time of a
symbolic ratio. Anything that is not multilinear goes to sympy's ``factor_list``.
"""

from __future__ import annotations

import random
from itertools import combinations

__all__ = ["factor_list"]


def factor_list(p):
    """``(constant, [(factor, multiplicity), ...])`` of a sympy ``PolyElement`` over ZZ, like
    ``p.factor_list()``: primitive factors with positive leading coefficients."""
    ring = p.ring
    if p.is_ground or not ring.domain.is_ZZ:
        return p.factor_list()
    # a monomial factor first (unreduced fractions carry powers of the ratios): x**k each
    shift = tuple(min(e) for e in zip(*p.itermonoms()))
    if any(shift):
        p = ring({tuple(e - k for e, k in zip(m, shift)): c for m, c in p.iterterms()})
    monomial = [(ring.gens[i], k) for i, k in enumerate(shift) if k]
    if p.is_ground:
        return ring.domain.convert(p.LC), monomial
    monoms = list(p.itermonoms())
    if any(e > 1 for m in monoms for e in m):
        constant, factors = p.factor_list()
        return constant, monomial + factors
    used = [i for i in range(ring.ngens) if any(m[i] for m in monoms)]
    gens = ring.gens
    parent = {v: v for v in used}

    def find(v):
        while parent[v] != v:
            parent[v] = parent[parent[v]]
            v = parent[v]
        return v

    first = {v: p.diff(gens[v]) for v in used}
    for a, b in combinations(used, 2):
        if find(a) != find(b) and p * first[a].diff(gens[b]) != first[a] * first[b]:
            parent[find(a)] = find(b)
    groups: dict = {}
    for v in used:
        groups.setdefault(find(v), []).append(v)
    factors = []
    for group in groups.values():
        others = [v for v in used if v not in group]
        factor = _restrict(p, gens, others)
        if factor is None:
            constant, factors = p.factor_list()
            return constant, monomial + factors
        factors.append(factor)
    product = ring.one
    for f in factors:
        product *= f
    constant, remainder = p.div(product)
    if remainder or not constant.is_ground:  # cannot happen for a multilinear p; be safe
        constant, factors = p.factor_list()
        return constant, monomial + factors
    return ring.domain.convert(constant.LC), monomial + [(f, 1) for f in factors]


def _restrict(p, gens, others):
    """The factor of *p* in the variables not in *others*: *p* with *others* set to small
    integers where the rest of *p* does not vanish, made primitive with a positive leading
    coefficient."""
    for attempt in range(8):
        pick = random.Random(attempt)  # fixed points, not in arithmetic progression
        q = p.subs([(gens[v], pick.randint(2, 10**6)) for v in others]) if others else p
        if q:
            _, q = q.primitive()
            return -q if q.LC < 0 else q
    return None
