"""Where the members on the main axis run in a half section: nested shafts and drums.

Private to :mod:`gearlib.mechanism.sketch`. Each link that turns about the main axis is drawn
as horizontal lines (a *shaft* inside the gears, nearer the axis, and/or a *drum* outside
them) with vertical pieces to what it carries: *spokes* to its gears, *arms* to the pins of the
planets it carries (on one side of the planet, or on both, as a bracket: the pin then joins the
two arms, so an arm from the shaft with one from the drum joins them), its brakes (up to the
housing) and clutches (between two members' lines), and a *riser* where its shaft and drum must
otherwise be joined. Arms, brakes, clutches and risers stand in *lanes*, the gaps between the
units; a unit of several planes may be drawn mirrored (its planes in the other order).

Chosen here: which line each piece starts from, in which lane it stands and where in the lane,
which shaft is inside which (and which drum outside which), and which units are mirrored. The
drawing is scored exactly, on the geometry the emitter draws: first the *crossings* (a vertical
piece across another member's line or pin, a pin through another gear; a pin may pass behind
the other pinion of its double-pinion set, which stands at another angle), then the nesting the
data ask for (members joined by a turning pair next to each other, the frame outside, few
risers and brackets), then the total length of the lines. The search is deterministic: a
descent that, while crossings remain, tries every change of the pieces, lines and units
involved in one, and then perturbations from a fixed seed, each followed by a descent, within a
fixed budget of evaluations; the drawing never changes from run to run. A sun's spoke can only
go inwards and a ring's outwards; the order of the units along the axis is kept; an input and
an output leave at the ends of the drawing on a shaft.
"""

from __future__ import annotations

from bisect import bisect_left, bisect_right
from dataclasses import dataclass, field

from ._sketch_nest import Nesting
from ._sketch_search import Search

__all__: list = []

TOP = 1e12       # the housing, above every line


@dataclass
class Port:
    member: object
    kind: str            # "gear", "arm", "brake", "clutch", "toframe" (an arm of the frame, up to its
                         # housing), "riser" (joins a member's shaft and drum, if it has both),
                         # "item" (takes a lane, joins no line)
    at: dict             # zone ("in"/"out": which of the member's lines the piece starts from) -> (x, y):
                         # x in unit coordinates (with ``unit``) or None for a lane to choose; y where it ends
    unit: int | None = None
    lanes: tuple = ()
    name: str = ""
    other: object = None            # a clutch's second member
    axis: int | None = None         # an arm: the axis it holds


@dataclass
class Route:
    lane_x: list          # x of each lane's start
    unit_x: list          # x of each unit's start
    ports: list           # (port, x, y, zone, other zone), one per piece (a bracket's two arms: two)
    levels: dict          # (member, zone) -> y of its line
    spans: dict           # (member, zone) -> (x0, x1)
    risers: dict          # member -> x of the piece joining its shaft and drum
    pins: dict            # axis -> (x0, x1) of its pin (arms of parallel axes)
    flipped: tuple        # units drawn mirrored
    crossings: int
    left: float
    right: float
    penalty: int = 0
    length: float = 0.0
    culprits: set = field(default_factory=set)   # decisions (indices) involved in a crossing


_ZONES = ("in", "out")


class Router(Nesting, Search):
    """One drawing scored (:meth:`evaluate`); the search is :class:`._sketch_search.Search`."""

    def __init__(self, ports, units, members, pitch, inner_top, outer_bottom, step, ends, nested=(), held=None,
                 blocks=(), behind=None, flippable=(), held_blocks=()):
        self.ports = ports
        self.units = units                # unit widths, in order
        self.members = members            # routed members, in order
        self.index = {m: i for i, m in enumerate(members)}
        self.nested = tuple((u, v) for u, v in nested if u in self.index and v in self.index)
        self.held = held                  # the frame, when it is a routed member: wanted outside
        self.held_blocks = tuple(held_blocks)   # (unit, x0, x1) of its gears: its hatched lines span them
        self.pitch = pitch
        self.inner_top = inner_top
        self.outer_bottom = outer_bottom
        self.step = step
        self.ends = ends                  # member -> ("left"/"right"/"near", ...): ends it reaches on a shaft
        self.n_lanes = len(units) + 1
        self.flippable = tuple(flippable)  # units that may be drawn mirrored
        self.options = [self._options(p) for p in ports] + [(False, True)] * len(self.flippable)
        self.n_ports = len(ports)
        self._prepare(blocks, behind or {})
        self._partners: dict = {}
        for u, v in self.nested:
            self._partners.setdefault(u, set()).add(v)
            self._partners.setdefault(v, set()).add(u)
        self._seen: dict = {}
        self.evaluations = 0

    # ------------------------------------------------------------------ decisions
    def _options(self, p) -> list:
        """Every way to draw port *p*: tuples of pieces ``(lane, zone, other zone)`` (lane None: a
        fixed place in a unit)."""
        if p.kind == "gear":
            return [((None, z, None),) for z in p.at]
        if p.kind == "item":
            return [((p.lanes[0], None, None),)]
        if p.kind == "riser":
            return [((lane, "in", "out"),) for lane in p.lanes]
        if p.kind == "toframe":
            if p.unit is not None:
                return [((None, None, None),)]
            return [((lane, None, None),) for lane in p.lanes]
        if p.kind == "arm":
            if p.unit is not None:   # the end of an inclined pin
                return [((None, z, None),) for z in p.at]
            out = [((lane, z, None),) for z in _ZONES for lane in p.lanes]
            if len(p.lanes) == 2 and p.lanes[0] != p.lanes[1]:
                out += [((p.lanes[0], z0, None), (p.lanes[1], z1, None)) for z0 in _ZONES for z1 in _ZONES]
            return out
        if p.kind == "brake":   # from its member's drum if it has one, else from its shaft
            return [((lane, "*", None),) for lane in p.lanes]
        # a clutch: between lines its members have, in the zone it prefers where both have one
        return [((lane, "*" + z, "*" + z),) for z in _ZONES for lane in p.lanes]

    def _prepare(self, blocks, behind):
        """Per port and option, what it adds: zones of members, pieces in lanes (with the class
        that orders a lane: arms whose pin runs left first, those whose pin runs right last)."""
        idx = self.index
        self._adds, self._pieces, self._linked = [], [], []
        for p, opts in zip(self.ports, self.options):
            adds, pieces, linked = [], [], []
            for opt in opts:
                a, pc = [], []
                for part, (lane, z0, z1) in enumerate(opt):
                    if p.kind not in ("item", "toframe", "riser") and z0 is not None and z0[0] != "*":
                        a.append((p.member, z0))
                    if lane is not None:
                        cls = (2 if lane == p.lanes[0] else 0) if p.kind in ("arm", "toframe") and len(p.lanes) == 2 else 1
                        pc.append((lane, cls, part, z0, z1))
                    else:
                        pc.append((None, 1, part, z0, z1))
                adds.append(tuple(a))
                pieces.append(tuple(pc))
                linked.append(len(opt) == 2 and opt[0][1] != opt[1][1])
            self._adds.append(adds)
            self._pieces.append(pieces)
            self._linked.append(linked)
        self._auto = [k for k, p in enumerate(self.ports) if p.kind in ("brake", "clutch")]
        self._mid = [idx.get(p.member, -2) if p.kind != "toframe" else -3 for p in self.ports]
        self._oid = [idx.get(p.other, -2) for p in self.ports]
        self._pin_y = [p.at[next(iter(p.at))][1] if p.at else 0.0 for p in self.ports]
        flip_of = {u: i for i, u in enumerate(self.flippable)}
        self._flip_slot = {u: self.n_ports + i for u, i in flip_of.items()}
        self._pin_blocks = {}
        for k, p in enumerate(self.ports):
            if p.kind in ("arm", "toframe") and p.unit is None:
                own = [b for b in blocks if b[5] == p.axis]
                units = {b[0] for b in own}
                see = behind.get(p.axis, ())
                others = [b for b in blocks if b[0] in units and b[5] != p.axis and b[5] not in see
                          and b[3] < self._pin_y[k] < b[4]]
                self._pin_blocks[k] = (own, others)

    # ------------------------------------------------------------------ one drawing
    def evaluate(self, choice, rank) -> Route:
        key = (tuple(choice), tuple(rank))
        found = self._seen.get(key)
        if found is None:
            found = self._seen[key] = self._evaluate(choice, rank)
        return found

    def _evaluate(self, choice, rank) -> Route:   # noqa: C901 (one pass over the drawing, kept flat for speed)
        self.evaluations += 1
        ports, n_ports = self.ports, self.n_ports
        zones: dict = {}
        linked = set()
        for k in range(n_ports):
            c = choice[k]
            for key in self._adds[k][c]:
                zones.setdefault(key[0], set()).add(key[1])
            if self._linked[k][c]:
                linked.add(ports[k].member)
        for m in self.ends:
            zones.setdefault(m, set()).add("in")
        chosen = [self._pieces[k][choice[k]] for k in range(n_ports)]
        for k in self._auto:   # brakes and clutches: from the lines their members have
            p = ports[k]
            (lane, cls, part, z0, z1), = chosen[k]
            if p.kind == "brake":
                have = zones.setdefault(p.member, set())
                z = "out" if "out" in have else "in"
                have.add(z)
                chosen[k] = ((lane, cls, part, z, None),)
                continue
            want = z0[1:]
            zu, zv = zones.setdefault(p.member, set()), zones.setdefault(p.other, set())
            common = zu & zv
            if common:
                a = b = want if want in common else next(iter(common))
            else:
                a = want if want in zu or not zu else next(iter(zu))
                b = want if want in zv or not zv else next(iter(zv))
            zu.add(a)
            zv.add(b)
            chosen[k] = ((lane, cls, part, a, b),)
        flipped = tuple(u for u in self.flippable if choice[self._flip_slot[u]])
        # pieces in lanes, in slot order
        in_lane = [[] for _ in range(self.n_lanes)]
        for k in range(n_ports):
            p = ports[k]
            if p.kind == "riser" and (len(zones.get(p.member, ())) < 2 or p.member in linked):
                continue
            for lane, cls, part, _z0, _z1 in chosen[k]:
                if lane is not None:
                    in_lane[lane].append((cls, rank[k], part, k))
        lane_x, unit_x, slot = [], [], {}
        x, pitch = 0.0, self.pitch
        for j in range(self.n_lanes):
            lane_x.append(x)
            items = in_lane[j]
            items.sort()
            for i, item in enumerate(items):
                slot[item[3], item[2]] = x + (i + 1) * pitch
            x += (len(items) + 1) * pitch
            if j < len(self.units):
                unit_x.append(x)
                x += self.units[j]
        left, right = -pitch, x + pitch
        widths = self.units
        pieces = []     # (port index, x, y, zone, other zone)
        xs: dict = {}
        risers = {}
        for k in range(n_ports):
            p = ports[k]
            for lane, _cls, part, z0, z1 in chosen[k]:
                if lane is None:
                    zone = z0 if z0 is not None else next(iter(p.at))
                    xr, py = p.at[zone]
                    u = p.unit
                    px = unit_x[u] + (widths[u] - xr if u in flipped else xr)
                else:
                    px = slot.get((k, part))
                    if px is None:   # a riser not needed
                        continue
                    py = self._pin_y[k]
                if p.kind == "riser":
                    risers[p.member] = px
                    xs.setdefault((p.member, "in"), []).append(px)
                    xs.setdefault((p.member, "out"), []).append(px)
                    continue
                pieces.append((k, px, py, z0, z1))
                if p.kind in ("item", "toframe"):
                    continue
                xs.setdefault((p.member, z0), []).append(px)
                if z1 is not None:
                    xs.setdefault((p.other, z1), []).append(px)
        for m in self.ends:
            xs.setdefault((m, "in"), [])
        spans = {}
        middle = (left + right) / 2
        stub = 0.8 * pitch
        for key, vals in xs.items():
            m, zone = key
            lo, hi = (min(vals), max(vals)) if vals else (None, None)
            if zone == "in" and m in self.ends:
                ends = self.ends[m]
                if "near" in ends:
                    ends = ("left",) if vals and (lo + hi) / 2 < middle else ("right",)
                if "left" in ends:
                    lo, hi = left, left if hi is None else hi
                if "right" in ends:
                    lo, hi = right if lo is None else lo, right
            if m == self.held and self.held_blocks:   # the frame's lines span its gears
                for u, bx0, bx1 in self.held_blocks:
                    bx0, bx1 = (widths[u] - bx1, widths[u] - bx0) if u in flipped else (bx0, bx1)
                    lo, hi = min(lo, unit_x[u] + bx0), max(hi, unit_x[u] + bx1)
            if hi - lo < stub:   # a member with one piece: a stub of shaft or drum
                if hi >= right - 1e-9 and lo > left + 1e-9:
                    lo = hi - stub
                else:
                    hi = lo + stub
            spans[key] = (lo, hi)
        levels = {}
        for zone, keys in self._order(spans, pieces, risers).items():
            n = len(keys)
            for i, k in enumerate(keys):
                levels[k] = self.inner_top * i / n if zone == "in" else self.outer_bottom + (i + 1) * self.step
        # the geometry: vertical pieces against horizontal lines and pins
        index = self.index
        vert = []       # (x, low, high, member, other member, decision)
        arms: dict = {}
        length = 0.0
        for k, px, py, z0, z1 in pieces:
            p = ports[k]
            kind = p.kind
            if kind == "item":
                continue
            m = self._mid[k]
            if kind == "toframe":
                a, b = py, TOP
            elif kind == "brake":
                a, b = levels[p.member, z0], TOP
            elif kind == "clutch":
                a, b = levels[p.member, z0], levels[p.other, z1]
            else:
                a, b = levels[p.member, z0], py
            if a > b:
                a, b = b, a
            vert.append((px, a, b, m, self._oid[k] if kind == "clutch" else m, k))
            if b < TOP:
                length += b - a
            if k in self._pin_blocks:
                arms.setdefault(k, []).append(px)
        for m, px in risers.items():
            a, b = levels[m, "in"], levels[m, "out"]
            vert.append((px, a, b, index[m], index[m], self.riser_of[m]))
            length += b - a
        horiz = []      # (x0, x1, y, member, decision or line key)
        pins = {}
        bad = 0
        culprits = set()
        for k, at in arms.items():
            p = ports[k]
            own, others = self._pin_blocks[k]
            py = self._pin_y[k]
            edges = []
            for b in own:
                u = b[0]
                x0b, x1b = (widths[u] - b[2], widths[u] - b[1]) if u in flipped else (b[1], b[2])
                edges += (unit_x[u] + x0b, unit_x[u] + x1b)
            if len(at) == 2:
                x0, x1 = min(at), max(at)
            else:
                far = max(edges) if max(edges) - at[0] >= at[0] - min(edges) else min(edges)
                x0, x1 = min(at[0], far), max(at[0], far)
            pins[p.axis] = (x0, x1)
            horiz.append((x0, x1, py, self._mid[k], k))
            length += x1 - x0
            for b in others:
                u = b[0]
                x0b, x1b = (widths[u] - b[2], widths[u] - b[1]) if u in flipped else (b[1], b[2])
                if unit_x[u] + x0b < x1 - 1e-9 and unit_x[u] + x1b > x0 + 1e-9:
                    bad += 1
                    culprits.add(k)
                    if u in self._flip_slot:
                        culprits.add(self._flip_slot[u])
        for key, (x0, x1) in spans.items():
            horiz.append((x0, x1, levels[key], index.get(key[0], -2), key))
            length += x1 - x0
        if vert and horiz:
            vert.sort()
            vx = [v[0] for v in vert]
            eps = 1e-9 * (abs(right) + 1.0)
            for x0, x1, y, m, what in horiz:
                for i in range(bisect_right(vx, x0 + eps), bisect_left(vx, x1 - eps)):
                    _x, a, b, vm, vo, k = vert[i]
                    if a < y - eps and y < b - eps and vm != m and vo != m:
                        bad += 1
                        culprits.add(k)
                        if isinstance(what, int):
                            culprits.add(what)
                        else:
                            culprits.update(self.of_member.get(what[0], ()))
        pieces_out = [(ports[k], px, py, z0, z1) for k, px, py, z0, z1 in pieces]
        route = Route(lane_x, unit_x, pieces_out, levels, spans, risers, pins, flipped, bad, left, right)
        route.penalty = self._penalty(levels, risers, choice)
        route.length = length
        route.culprits = culprits
        return route

    def _penalty(self, levels, risers, choice) -> int:
        """Nesting the data ask for: members joined by a turning pair next to each other, the
        frame outside; one line per member where it can, brackets only where they help."""
        out = 2 * len(risers) + sum(self._linked[k][choice[k]] or len(self._pieces[k][choice[k]]) == 2
                                    for k in self._arm_ports)
        if self.nested:
            rank = {}
            for zone in _ZONES:
                keys = sorted((k for k in levels if k[1] == zone), key=levels.get)
                rank.update({k: i for i, k in enumerate(keys)})
            for u, v in self.nested:
                for zone in _ZONES:
                    if (u, zone) in rank and (v, zone) in rank:
                        out += abs(rank[u, zone] - rank[v, zone]) - 1
        if self.held is not None and (self.held, "in") in levels:
            out += 3
        return out
