"""Placement of axis groups for :mod:`gearlib.davies.geometry` (private).

:class:`_Builder` places the coaxial groups breadth-first through the gear pairs: a spur pair
puts the next axis parallel at the centre distance (back-tracking over the side until every
loop of centre distances closes), a bevel pair puts it through the apex at the angle that
puts a gear meshing two others on one pitch cone (or at a right angle). A second, symbolic
pass repeats the same decisions with symbols for the radii.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import sympy

from ..errors import GeometryError
from .screws import cross2, dot2, perpendicular

__all__ = ["Axis", "MeshGeometry", "Builder", "intersection"]


@dataclass(frozen=True)
class Axis:
    """One axis line (a coaxial group of links): a point on it and a unit direction, in (y, z)."""

    group: int
    label: str
    links: frozenset
    point: tuple
    direction: tuple
    parent: int | None = None


@dataclass(frozen=True)
class MeshGeometry:
    """Geometry of one gear pair: its axes, radii, real gear ratio, apex and pitch point.

    ``direction`` points along the pitch line (the axis of the relative rotation): the unit
    axis direction for spur pairs, ``P - apex`` for bevel pairs (not normalised, so that exact
    work needs no square roots); ``scale`` is its length.
    """

    index: int
    gears: tuple
    carrier: object
    axes: tuple
    radii: tuple
    ratio: object
    kind: str
    pitch_point: tuple
    direction: tuple
    scale: object = 1
    apex: tuple | None = None



def _num(x) -> float:
    return float(x)


def _sign(x) -> int:
    v = _num(x)
    return (v > 0) - (v < 0)


class Builder:
    """Breadth-first placement of the axis groups through the gear pairs, with back-tracking
    over the side of each spur pair until every loop of centre distances closes."""

    def __init__(self, mech, groups, pairs, mode, exact, symbols=None, decisions=None):
        self.mech, self.groups, self.pairs, self.mode = mech, groups, pairs, mode
        self.exact = exact
        self.symbols = symbols
        self.decisions = decisions
        ground = mech.ground if mech.ground is not None else mech.link_ids[0]
        own = sorted(groups.membership.get(ground, {}).values())
        self.root = own[0] if own else 0
        self.n = len(groups.members)

    # -- helpers -------------------------------------------------------------------
    def value(self, x):
        return x if self.exact else _num(x)

    def radii(self, p):
        if self.symbols is not None:
            return self.symbols[p.gp.gears]
        return tuple(self.value(r) for r in p.radii)

    def ratio(self, p):
        if self.symbols is not None:
            ra, rb = self.symbols[p.gp.gears]
            return _sign(p.e) * ra / rb
        return self.value(p.e)

    # -- numeric pass ----------------------------------------------------------------
    def run(self):
        self.order = self._bfs_order()
        spur_tree = [(g, p) for g, (p, _) in self.order.items() if p is not None and p.spur]
        sigmas = {}
        best = None
        for combo in self._sign_combos(len(spur_tree)):
            sigmas = {g: s for (g, _), s in zip(spur_tree, combo)}
            self._place(sigmas, angles={})
            bad = self._spur_loop_errors()
            if not bad:
                best = sigmas
                break
            if best is None:
                best, first_bad = sigmas, bad
        else:
            if self.mode != "kinematic":
                raise GeometryError(first_bad[0])
        self.sigmas = best
        self._place(best, angles={})
        self.angles = self._solve_angles()
        self._place(best, self.angles)
        return self

    def _sign_combos(self, n):
        limit = min(n, 10)
        for k in range(2 ** limit):
            yield [(-1 if (k >> i) & 1 else 1) for i in range(limit)] + [1] * (n - limit)

    def _bfs_order(self):
        """``{group: (pair that placed it, placed from group)}`` in placement order."""
        adj = {g: [] for g in range(self.n)}
        for p in self.pairs:
            adj[p.ga].append((p.gb, p))
            adj[p.gb].append((p.ga, p))
        order = {self.root: (None, None)}
        queue = [self.root]
        while queue:
            g = queue.pop(0)
            for h, p in adj[g]:
                if h not in order:
                    order[h] = (p, g)
                    queue.append(h)
        for g in range(self.n):  # groups no gear pair reaches: put them beside the root axis
            if g not in order:
                order[g] = (None, self.root)
        return order

    def _place(self, sigmas, angles):
        pts, dirs = {}, {}
        for g, (p, parent) in self.order.items():
            if parent is None:
                zero, one = (sympy.Integer(0), sympy.Integer(1)) if self.exact else (0.0, 1.0)
                pts[g], dirs[g] = (zero, zero), (zero, one)
                continue
            d = dirs[parent]
            if p is None:  # unreachable group: parallel, one unit away
                pts[g] = tuple(pts[parent][i] + perpendicular(d)[i] for i in range(2))
                dirs[g] = d
                continue
            ra, rb = self.radii(p)
            if p.spur:
                r_par, r_child = (ra, rb) if p.ga == parent else (rb, ra)
                off = (r_par + r_child) if p.gp.kind == "external" else (r_par - r_child)
                n = perpendicular(d)
                s = sigmas.get(g, 1)
                pts[g] = (pts[parent][0] + s * off * n[0], pts[parent][1] + s * off * n[1])
                dirs[g] = d
            else:
                phi = angles.get(g)
                n = perpendicular(d)
                if phi is None:  # right angle
                    dirs[g] = n
                else:
                    c, s = phi
                    dirs[g] = (c * d[0] + s * n[0], c * d[1] + s * n[1])
                pts[g] = pts[parent]
        self.pts, self.dirs = pts, dirs

    def _spur_loop_errors(self):
        bad = []
        for p in self.pairs:
            if not p.spur or self.order[p.ga][0] is p or self.order[p.gb][0] is p:
                continue
            da, db = self.dirs[p.ga], self.dirs[p.gb]
            if abs(_num(cross2(da, db))) > 1e-9:
                bad.append(f"spur pair {p.gp.label} joins axes that are not parallel")
                continue
            ra, rb = p.radii
            want = abs(_num(ra + rb if p.gp.kind == "external" else ra - rb))
            n = perpendicular(da)
            got = abs(_num(dot2((self.pts[p.gb][0] - self.pts[p.ga][0], self.pts[p.gb][1] - self.pts[p.ga][1]), n)))
            if abs(got - want) > 1e-9 * max(1.0, want):
                bad.append(f"the centre distances around gear pair {p.gp.label} do not close a loop "
                           f"(its axes are {got:g} apart, the radii need {want:g})")
        return bad

    # -- bevel angles: one pitch cone per gear -----------------------------------------
    def _solve_angles(self):
        if self.mode != "physical":
            return {}
        angles = {}
        for g, (p, _parent) in self.order.items():
            if p is None or p.spur:
                continue
            cons = self._cone_constraints(g)
            if not cons:
                continue
            phi = self._root_of(g, cons, angles)
            angles[g] = (math.cos(phi), math.sin(phi))
        return angles

    def _cone_constraints(self, g):
        """Pairs of bevel meshes in which one gear on axis *g* (same link, same radius) meshes
        two gears on already placed axes."""
        seen: dict = {}
        for p in self.pairs:
            if p.spur or g not in (p.ga, p.gb):
                continue
            other = p.gb if p.ga == g else p.ga
            if list(self.order).index(other) > list(self.order).index(g):
                continue
            k = 0 if p.ga == g else 1
            key = (p.gp.gears[k], p.radii[k])
            seen.setdefault(key, []).append(p)
        return [ps for ps in seen.values() if len(ps) >= 2]

    def _cone_distance(self, p, dirs):
        ua, ub = dirs[p.ga], dirs[p.gb]
        e = _num(p.e)
        w = (e * ub[0] - ua[0], e * ub[1] - ua[1])
        ra = _num(p.radii[0])
        cr = abs(cross2(w, ua))
        return ra * math.hypot(*w) / cr if cr > 1e-12 else math.inf

    def _root_of(self, g, cons, angles):
        from scipy.optimize import brentq

        d = self.dirs[self.order[g][1]]
        n = perpendicular(d)

        def f(phi):
            dirs = dict(self.dirs)
            dirs[g] = (math.cos(phi) * d[0] + math.sin(phi) * n[0], math.cos(phi) * d[1] + math.sin(phi) * n[1])
            total = 0.0
            for ps in cons:
                ls = [self._cone_distance(p, dirs) for p in ps]
                total += ls[1] - ls[0]
            return total

        grid = [math.pi * (k + 0.5) / 720 for k in range(720)]
        vals = [f(x) for x in grid]
        for x0, x1, v0, v1 in zip(grid, grid[1:], vals, vals[1:]):
            if math.isfinite(v0) and math.isfinite(v1) and v0 * v1 <= 0:
                return brentq(f, x0, x1, xtol=1e-15, rtol=1e-15)
        gear = cons[0][0].gp.gears
        raise GeometryError(f"no axis direction puts the bevel gears of pairs {gear} ... on one pitch cone; "
                            "check their radii")

    # -- output ----------------------------------------------------------------------
    def axes_out(self):
        out = []
        for g in range(self.n):
            p, parent = self.order[g]
            out.append(Axis(g, self.groups.labels[g], self.groups.members[g], tuple(self.pts[g]),
                            tuple(self.dirs[g]), parent))
        return out

    def meshes_out(self):
        ref = self.decisions if self.symbols is not None else self
        out = []
        for p in self.pairs:
            ra, rb = self.radii(p)
            e = self.ratio(p)
            ua, ub = self.dirs[p.ga], self.dirs[p.gb]
            pa, pb = self.pts[p.ga], self.pts[p.gb]
            if p.spur:
                pitch = ((e * pb[0] - pa[0]) / (e - 1), (e * pb[1] - pa[1]) / (e - 1))
                out.append(MeshGeometry(p.index, p.gp.gears, p.gp.carrier, (p.ga, p.gb), (ra, rb), e, "spur",
                                        _simplify(pitch, self.exact), tuple(ua), 1, None))
                continue
            apex = intersection(pa, ua, pb, ub)
            w = (e * ub[0] - ua[0], e * ub[1] - ua[1])
            lam = ra / cross2(w, ua) * ref._bevel_side(p)
            vec = _simplify((lam * w[0], lam * w[1]), self.exact)
            pitch = _simplify((apex[0] + vec[0], apex[1] + vec[1]), self.exact)
            if self.exact:
                scale, direction = sympy.sqrt(sympy.expand(vec[0] ** 2 + vec[1] ** 2)), vec
            else:
                norm = math.hypot(*vec)
                scale, direction = 1.0, (vec[0] / norm, vec[1] / norm)
            out.append(MeshGeometry(p.index, p.gp.gears, p.gp.carrier, (p.ga, p.gb), (ra, rb), e, "bevel",
                                    pitch, direction, scale, apex))
        return out

    def _bevel_side(self, p) -> int:
        """+1 or -1: the pitch point lies on the side of the axis placed later (the planet's)."""
        placed = list(self.order)
        child = p.ga if placed.index(p.ga) > placed.index(p.gb) else p.gb
        ua, ub = self.dirs[p.ga], self.dirs[p.gb]
        e = _num(p.e)
        w = (e * _num(ub[0]) - _num(ua[0]), e * _num(ub[1]) - _num(ua[1]))
        lam = _num(p.radii[0]) / cross2(w, tuple(map(_num, ua)))
        return 1 if lam * dot2(w, tuple(map(_num, self.dirs[child]))) >= 0 else -1

    # -- symbolic pass ---------------------------------------------------------------
    def run_symbolic(self):
        num = self.decisions
        self.order = num.order
        self._place(num.sigmas, angles={})
        relations = {}
        for p in self.pairs:
            if not p.spur or self.order[p.ga][0] is p or self.order[p.gb][0] is p:
                continue
            ra, rb = self.radii(p)
            n = perpendicular(self.dirs[p.ga])
            gap = dot2((self.pts[p.gb][0] - self.pts[p.ga][0], self.pts[p.gb][1] - self.pts[p.ga][1]), n)
            want = (ra + rb) if p.gp.kind == "external" else (ra - rb)
            sign = _sign(dot2((num.pts[p.gb][0] - num.pts[p.ga][0], num.pts[p.gb][1] - num.pts[p.ga][1]),
                              perpendicular(num.dirs[p.ga]))) * _sign(p.radii[0] + p.radii[1]
                                                                      if p.gp.kind == "external"
                                                                      else p.radii[0] - p.radii[1])
            residual = sympy.expand((gap - sign * want).subs(relations))
            if residual != 0:
                sym = sorted(residual.free_symbols, key=lambda s: str(s))[-1]
                sol = sympy.solve(residual, sym)
                relations[sym] = sol[0]
        self.relations = relations
        if relations:
            self.symbols = {k: tuple(sympy.sympify(r).subs(relations) for r in v) for k, v in self.symbols.items()}
            self._place(num.sigmas, angles={})
        return self, relations


def _simplify(vec, exact):
    return tuple(sympy.cancel(v) for v in vec) if exact else tuple(vec)


def intersection(pa, ua, pb, ub):
    """The point where two in-plane lines meet (the apex of a bevel pair)."""
    den = cross2(ua, ub)
    if abs(_num(den)) < 1e-12:
        raise GeometryError("a bevel pair joins two parallel axes; use a spur pair (`type: external` or `internal`)")
    t = cross2((pb[0] - pa[0], pb[1] - pa[1]), ub) / den
    return (pa[0] + t * ua[0], pa[1] + t * ua[1])
