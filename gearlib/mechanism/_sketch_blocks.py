"""The gear blocks of a kinematic sketch, unit by unit, before the units are placed side by side.

Private to :mod:`gearlib.mechanism.sketch`. A *unit* is a set of gears in mesh (a planetary set,
a pair of gears on fixed axes) or, for bevel gears, the sets around one cone apex; units stand
side by side along the main axis. Inside a spur unit the meshes fall into *planes* (axial
slices): two gears share a plane unless they would overlap in the half section without being
in mesh (two suns, two rings, a planet over a gear it does not mesh). Two pinions in mesh (a
double-pinion set) stand at different angles about the main axis, so the section cannot show
them one above the other where their blocks would overlap: they are drawn side by side, in two
planes with no gap between them (a Ravigneaux set: the small sun and the short pinion in one
plane, the long pinion with the large sun and the ring in the next). A bevel unit is drawn about its cone apex: every
gear is a frustum whose pitch cone passes through the apex.

The drawing is a half section when the main axis holds a planetary (three or more links, or a
turning carrier): central gears above the axis only, suns from their shaft to the pitch radius,
rings from the pitch radius outwards. Trains of fixed parallel axes are drawn in full section,
each gear as a block centred on its axis. Two identical planets (the car differential's) are
drawn on both sides of the axis, and then the whole section is shown (``mode == "full"``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..errors import GeometryError

__all__: list = []


@dataclass
class Unit:
    index: int
    kind: str                      # "spur", "bevel" or "stub" (an axis without gears)
    gears: list
    pairs: list
    axes: set = field(default_factory=set)     # non-main axes with gears in the unit
    width: float = 0.0
    blocks: list = field(default_factory=list)  # (gear, polygon, mirror) in unit coordinates
    pins: dict = field(default_factory=dict)    # inclined axis -> (start, end) in unit coordinates
    x: float = 0.0                 # where the unit starts, once placed
    apex: tuple = (0.0, 0.0)       # a bevel unit: its cone apex, in unit coordinates


@dataclass
class Geometry:
    mode: str                      # "half", "full" or "fixed"
    scale: float
    units: list
    lower: dict                    # gear drawn below the axis (the second of two identical planets) -> its twin
    block_width: float
    gap: float
    lower_axes: set = field(default_factory=set)   # axes of such planets (their carrier's arm is mirrored)
    upper_axes: set = field(default_factory=set)   # axes of their twins


def _overlap(a, b, eps=1e-9) -> bool:
    return min(a[1], b[1]) - max(a[0], b[0]) > eps


def build(parts) -> Geometry:
    axes, gears, mech = parts.axes, parts.gears, parts.mech
    root = axes[parts.root]
    half = len(root.links) >= 3 or any(x != mech.ground and parts.children.get(x) for x in root.links)
    mode = "half" if half else "fixed"
    extents = [abs(axes[g.group].offset) + g.radius for g in gears] + [g.radius for g in gears]
    scale = max(extents, default=parts.nominal) or 1.0
    width, gap = 0.2 * scale, 0.07 * scale
    lower = _duplicates(parts) if half else {}
    if lower:
        mode = "full"
    upper_axes = {parts.gears[t].group for t in lower.values()}
    lower_axes = {parts.gears[k].group for k in lower} - upper_axes
    units = _units(parts)
    meshing = {frozenset((parts.pair_gears[i][0], parts.pair_gears[i][1])) for i in range(len(parts.pair_gears))}
    for u in units:
        if u.kind == "spur":
            _spur(parts, u, half, lower, meshing, width, gap, 0.14 * scale)
        elif u.kind == "bevel":
            _bevel(parts, u, lower, scale)
        else:
            u.width = width
    return Geometry(mode, scale, units, lower, width, gap, lower_axes, upper_axes)


def _duplicates(parts) -> dict:
    """``{gear: its twin}`` for the gears of a second planet identical to a first one (same carrier,
    size, place and partners): the second is drawn below the axis."""
    same: dict = {}
    for g in parts.gears:
        a = parts.axes[g.group]
        if a.parent is None or a.parent != g.carrier:   # only planets: gears on an axis their carrier holds
            continue
        key = (g.carrier, round(g.radius, 9), round(abs(a.offset), 9), a.inclined, round(a.angle, 9),
               round(g.h, 9), frozenset(o for _, o in g.meshes))
        same.setdefault(key, []).append(g)
    twins = {}
    for gs in same.values():
        links = list(dict.fromkeys(g.link for g in gs))
        if len(links) > 2:
            raise GeometryError(
                f"carrier {gs[0].carrier} holds three or more identical planets ({', '.join(map(str, links))}): a "
                "section shows two; describe one planet and count the copies with `planets: {link: n}`")
        if len(links) == 2:
            first = next(g for g in gs if g.link == links[0])
            for g in gs:
                if g.link == links[1]:
                    twins[g.index] = first.index
                    a = parts.axes[g.group]
                    if g.group != first.group and not a.inclined:
                        a.offset = -abs(a.offset)
    return twins


def _units(parts) -> list:
    gears = parts.gears
    parent = list(range(len(gears)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for ia, ib in parts.pair_gears:
        parent[find(ia)] = find(ib)
    by_axis = {}
    for g in gears:   # the gears around one inclined axis share its apex: one unit
        if parts.axes[g.group].inclined:
            first = by_axis.setdefault(g.group, g.index)
            parent[find(g.index)] = find(first)
    sets: dict = {}
    for g in gears:
        sets.setdefault(find(g.index), []).append(g.index)
    units = []
    for members in sets.values():
        pairs = sorted({i for k in members for i, _ in gears[k].meshes})
        axes = {gears[k].group for k in members if gears[k].group != parts.root}
        bevel = any(parts.axes[a].inclined for a in axes)
        units.append(Unit(0, "bevel" if bevel else "spur", sorted(members), pairs, axes))
    units.sort(key=lambda u: u.pairs[0])
    drawn = {a for u in units for a in u.axes}
    for gid, a in parts.axes.items():  # an axis without gears still shows its links
        if a.parent is not None and gid not in drawn:
            units.append(Unit(0, "stub", [], [], {gid}))
    order = _chain(parts, units)
    for k, u in enumerate(order):
        u.index = k
    for u in order:
        if u.kind == "bevel":
            tops = {parts.axes[a].parent_group for a in u.axes if parts.axes[a].inclined}
            if len(tops) > 1:
                raise GeometryError("bevel gears about one apex turn about axes on two different parent axes; "
                                    "a sketch in one plane cannot show them")
    return order


def _chain(parts, units) -> list:
    """Units in order along the main axis: by the order of the data, keeping the units that share
    a planet or a layshaft (a link off the main axis) next to each other."""
    links = []
    for u in units:   # the unit's gears off the main axis, and the links holding their axes
        s = {parts.gears[k].link for k in u.gears if parts.gears[k].group != parts.root}
        s |= {parts.axes[a].parent for a in u.axes if parts.axes[a].parent not in parts.axes[parts.root].links}
        links.append(s)
    n = len(units)
    near = [[j for j in range(n) if j != i and links[i] & links[j]] for i in range(n)]
    order, seen = [], set()
    for start in range(n):
        if start in seen:
            continue
        stack = [start]
        while stack:
            i = stack.pop()
            if i in seen:
                continue
            seen.add(i)
            order.append(units[i])
            stack.extend(sorted((j for j in near[i] if j not in seen), reverse=True))
    return order


def _radial(parts, g, half) -> tuple:
    """The radial interval a gear (with its spoke) occupies in the section."""
    a = parts.axes[g.group]
    if half and a.parent is None:
        return (g.radius, math.inf) if g.ring else (0.0, g.radius)
    y = a.offset
    return (y - g.radius, y + g.radius)


def _spur(parts, u, half, lower, meshing, width, gap, depth):
    gears = parts.gears
    planes: list[set] = []
    where: dict = {}
    touch: set = set()   # pairs of planes side by side with no gap: two pinions in mesh

    def pinions(j, k) -> bool:
        """Two planets in mesh (a double-pinion set) whose blocks would overlap in one plane: they
        stand at different angles about the main axis, so the section cannot show them one above
        the other; they are drawn side by side, in two planes that touch."""
        a, b = gears[j], gears[k]
        return (frozenset((j, k)) in meshing and a.group != b.group and parts.axes[a.group].parent is not None
                and parts.axes[b.group].parent is not None and j not in lower and k not in lower
                and _overlap(_radial(parts, a, half), _radial(parts, b, half), 1e-6 * (a.radius + b.radius)))

    def fits(p, new):
        for k in new:
            for j in planes[p]:
                if j == k or j in lower or k in lower:
                    continue
                if frozenset((j, k)) in meshing:
                    if pinions(j, k):
                        return False
                    continue
                if gears[j].link == gears[k].link or _overlap(_radial(parts, gears[j], half),
                                                              _radial(parts, gears[k], half)):
                    return False
        return True

    for i in u.pairs:
        ga, gb = parts.pair_gears[i]
        if pinions(ga, gb):
            placed = [k for k in (ga, gb) if k in where]
            first = placed[0] if placed else ga
            if not placed:
                planes.append({first})
                where[first] = {len(planes) - 1}
            other = gb if first == ga else ga
            if other not in where:
                p = next((q for q in range(len(planes)) if q not in where[first] and fits(q, {other})), None)
                if p is None:
                    planes.append(set())
                    p = len(planes) - 1
                planes[p].add(other)
                where[other] = {p}
            touch |= {frozenset((p, q)) for p in where[first] for q in where[other]}
            continue
        for p in sorted(where.get(ga, set()) | where.get(gb, set())):
            new = {ga, gb} - planes[p]
            if fits(p, new):
                planes[p] |= new
                break
        else:
            planes.append({ga, gb})
            p = len(planes) - 1
        for k in (ga, gb):
            where.setdefault(k, set()).add(p)
    # order the planes so that a gear's planes are neighbours (a chain through shared gears), and
    # planes whose pinions touch side by side
    def near(q, last):
        return len(planes[q] & planes[last]) + 2 * (frozenset((q, last)) in touch)

    order = [0]
    rest = set(range(1, len(planes)))
    while rest:
        last = order[-1]
        nxt = max(sorted(rest), key=lambda q: near(q, last))
        order.append(nxt)
        rest.remove(nxt)
    x, start = 0.0, {}
    for n, p in enumerate(order):
        if n:
            x += 0.0 if frozenset((p, order[n - 1])) in touch else gap
        start[p] = x
        x += width
    u.width = x
    for k in u.gears:
        g = gears[k]
        x0 = min(start[p] for p in where[k])
        x1 = max(start[p] for p in where[k]) + width
        a = parts.axes[g.group]
        if half and a.parent is None:
            d = min(depth, 0.45 * g.radius) if not g.ring else depth
            y0, y1 = (g.radius, g.radius + d) if g.ring else (g.radius - d, g.radius)
        else:
            y0, y1 = a.offset - g.radius, a.offset + g.radius
        u.blocks.append((k, ((x0, y0), (x1, y0), (x1, y1), (x0, y1)), False))


def _bevel(parts, u, lower, scale):
    """Blocks of a bevel unit about its apex (the origin, on the parent axis), then shifted so
    that the unit starts at x = 0."""
    gears = parts.gears
    face = 0.3
    blocks, pins = [], {}
    placed_central = set()
    for k in u.gears:
        g = gears[k]
        a = parts.axes[g.group]
        if not a.inclined:
            continue
        apex = (0.0, parts.axes[a.parent_group].offset)
        ux, uy = math.cos(a.angle), math.sin(a.angle)
        nx, ny = -uy, ux
        cx, cy = apex[0] + g.h * ux, apex[1] + g.h * uy
        ends = {s: (cx + s * g.radius * nx, cy + s * g.radius * ny) for s in (1, -1)}
        inner = {s: _towards(apex, e, 1 - face) for s, e in ends.items()}
        poly = (inner[1], ends[1], ends[-1], inner[-1])
        mirror = k in lower
        blocks.append((k, _flip(poly, apex[1]) if mirror else poly, False))
        hs = [g2.h for g2 in gears if g2.group == g.group]
        far, near = max(hs) * 1.22 + 0.1 * g.radius, 0.45 * min(hs)
        pin = ((apex[0] + near * ux, apex[1] + near * uy), (apex[0] + far * ux, apex[1] + far * uy))
        if not mirror:
            pins[a.group] = pin
        else:
            pins.setdefault(("lower", a.group), _flip(pin, apex[1]))
        for i, o in g.meshes:
            if i not in g.sides or o in placed_central or mirror:
                continue
            placed_central.add(o)
            e = ends[g.sides[i]]
            start = _towards(apex, e, 1 - face)
            dx, dy = e[0] - apex[0], e[1] - apex[1]
            length = math.hypot(dx, dy)
            mx, my = -dy / length, dx / length
            if (cx - apex[0]) * mx + (cy - apex[1]) * my > 0:  # the gear's body lies away from its partner
                mx, my = -mx, -my
            t = 0.32 * face * length
            central = (start, e, (e[0] + t * mx, e[1] + t * my), (start[0] + t * mx, start[1] + t * my))
            blocks.append((o, central, False))
    xs = [p[0] for _, poly, _ in blocks for p in poly] + [p[0] for pin in pins.values() for p in pin]
    x0 = min(xs) - 0.04 * scale
    u.width = max(xs) - x0 + 0.04 * scale
    u.blocks = [(k, tuple((x - x0, y) for x, y in poly), m) for k, poly, m in blocks]
    u.pins = {a: tuple((x - x0, y) for x, y in pin) for a, pin in pins.items()}
    u.apex = (-x0, 0.0)


def _towards(o, p, t):
    return (o[0] + t * (p[0] - o[0]), o[1] + t * (p[1] - o[1]))


def _flip(points, y0):
    return tuple((x, 2 * y0 - y) for x, y in points)
