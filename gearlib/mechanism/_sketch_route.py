"""Where the members on the main axis run in a half section: nested shafts and drums.

Private to :mod:`gearlib.mechanism.sketch`. Each link that turns about the main axis is drawn
as one horizontal line (a *shaft* inside the gears, nearer the axis, or a *drum* outside
them) with vertical *spokes* to what it carries: its gears, the arms of the planets it holds,
its brakes and clutches. Which shaft is inside which, on which side of a unit a carrier's arm
stands, and in which gap between units a brake or clutch sits are chosen here: a deterministic
local search that first lowers the number of spokes crossing another member's line, then the
length of the lines (ties keep the first option, so the drawing never changes from run to
run). A sun's spoke can only go inwards and a ring's outwards; the order of the units along
the axis and the nesting the turning pairs give (a carrier journalled on the output shaft)
are kept.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__: list = []


@dataclass
class Port:
    member: object
    kind: str            # "gear", "arm", "brake", "clutch", "toframe" (an arm of the frame, up to its
                         # housing), "riser" (joins a member's shaft and drum, if it has both),
                         # "item" (takes a lane, joins no line)
    at: dict             # zone ("in"/"out": which of the member's lines the spoke starts from) -> (x, y):
                         # x in unit coordinates (with ``unit``) or None for a lane to choose; y where it ends
    unit: int | None = None
    lanes: tuple = ()
    name: str = ""
    other: object = None            # a clutch's second member
    axis: int | None = None         # an arm: the axis it holds
    extra: dict | None = None       # lane -> gears its pin would pass through there (counted as crossings)


@dataclass
class Route:
    lane_x: list          # x of each lane's start
    unit_x: list          # x of each unit's start
    ports: list           # (port, x, y, zone, other zone)
    levels: dict          # (member, zone) -> y of its line
    spans: dict           # (member, zone) -> (x0, x1)
    risers: dict          # member -> x of the spoke joining its shaft and drum
    crossings: int
    left: float
    right: float


class Router:
    def __init__(self, ports, units, members, pitch, inner_top, outer_bottom, step, ends, nested=(), held=None):
        self.ports = ports
        self.nested = tuple(nested)       # turning pairs between members: wanted next to each other
        self.held = held                  # the frame, when it is a routed member: wanted outside
        self.units = units                # unit widths, in order
        self.members = members            # routed members, in order
        self.pitch = pitch
        self.inner_top = inner_top
        self.outer_bottom = outer_bottom
        self.step = step
        self.ends = ends                  # member -> "left"/"right" ends it reaches (input, output)
        self.options = [self._options(p) for p in ports]
        self._index = {m: i for i, m in enumerate(members)}
        self._seen: dict = {}

    @staticmethod
    def _options(p):
        out = []
        for zone, (x, _) in p.at.items():
            lanes = p.lanes if x is None else (None,)
            out += [(lane, zone, None) for lane in lanes]
        return out

    # ------------------------------------------------------------------ one arrangement
    def evaluate(self, choice, order=None) -> Route:
        if order is None:
            key = tuple(choice)
            found = self._seen.get(key)
            if found is None:
                found = self._seen[key] = self._evaluate(choice)
            return found
        return self._evaluate(choice, order)

    def _evaluate(self, choice, order=None) -> Route:
        opts = [self.options[k][c] for k, c in enumerate(choice)]
        zones: dict = {}
        lane_arm = {}
        for k, p in enumerate(self.ports):
            lane, zone, other = opts[k]
            if p.kind in ("gear", "arm"):
                zones.setdefault(p.member, set()).add(zone)
            if p.kind == "arm" and lane is not None:
                lane_arm.setdefault(p.member, k)
        auto = {}
        for k, p in enumerate(self.ports):   # a brake or a clutch starts from a line its member has
            if p.kind == "brake":
                mz = zones.get(p.member) or {"in"}
                auto[k] = ("out" if "out" in mz else "in", None)
            elif p.kind == "clutch":
                zu, zv = zones.get(p.member) or {"in"}, zones.get(p.other) or {"in"}
                common = zu & zv
                if common:
                    z = "in" if "in" in common else "out"
                    auto[k] = (z, z)
                else:
                    auto[k] = (min(zu), min(zv))
        for k, (zu, zv) in auto.items():
            lane = opts[k][0]
            opts[k] = (lane, zu, zv)
            zones.setdefault(self.ports[k].member, set()).add(zu)
            if zv is not None:
                zones.setdefault(self.ports[k].other, set()).add(zv)
        both = {m for m, z in zones.items() if len(z) == 2}
        n_lanes = len(self.units) + 1
        in_lane = [[] for _ in range(n_lanes)]
        for k, p in enumerate(self.ports):
            lane = opts[k][0]
            if lane is None or (p.kind == "riser" and (p.member not in both or p.member in lane_arm)):
                continue
            in_lane[lane].append(k)
        lane_x, unit_x, x = [], [], 0.0
        slot = {}
        for j in range(n_lanes):
            lane_x.append(x)
            items = in_lane[j]
            for i, k in enumerate(items):
                slot[k] = x + (i + 1) * self.pitch
            x += (len(items) + 1) * self.pitch
            if j < len(self.units):
                unit_x.append(x)
                x += self.units[j]
        left, right = -self.pitch, x + self.pitch
        placed = []
        xs: dict = {}
        risers = {}
        for k, p in enumerate(self.ports):
            lane, zone, other = opts[k]
            if p.kind == "riser":
                if p.member in both:
                    risers[p.member] = slot[lane_arm[p.member]] if p.member in lane_arm else slot[k]
                continue
            x_rel, py = p.at.get(zone) or p.at["auto"]
            px = slot[k] if lane is not None else unit_x[p.unit] + x_rel
            placed.append((p, px, py, zone, other))
            if p.kind in ("item", "toframe"):
                continue
            xs.setdefault((p.member, zone), []).append(px)
            if p.kind == "clutch":
                xs.setdefault((p.other, other), []).append(px)
        spans = {}
        middle = (left + right) / 2
        for key, vals in xs.items():
            lo, hi = min(vals), max(vals)
            m = key[0]
            if m in risers:
                lo, hi = min(lo, risers[m]), max(hi, risers[m])
            zones = [z for z in ("in", "out") if (m, z) in xs]
            if key[1] == zones[0]:  # an input or output leaves on its inner line (or its only one)
                ends = self.ends.get(m, ())
                if "near" in ends:
                    ends = ("left",) if (lo + hi) / 2 < middle else ("right",)
                if "left" in ends:
                    lo = left
                if "right" in ends:
                    hi = right
                if hi - lo < 0.8 * self.pitch:   # a member with one spoke: a stub of shaft or drum
                    hi = lo + 0.8 * self.pitch
            spans[key] = (lo, hi)
        levels = self._levels(spans, order)
        crossings = self._crossings(placed, risers, levels, spans)
        for k, (p, c) in enumerate(zip(self.ports, choice)):
            if p.extra:
                crossings += p.extra.get(self.options[k][c][0], 0)
        route = Route(lane_x, unit_x, placed, levels, spans, risers, crossings, left, right)
        route.penalty = self._penalty(route)
        return route

    def _penalty(self, route) -> int:
        """Nesting the data ask for: members joined by a turning pair next to each other, the
        frame outside; one line per member where it can."""
        rank = {}
        for zone in ("in", "out"):
            keys = sorted((k for k in route.levels if k[1] == zone), key=route.levels.get)
            rank.update({k: i for i, k in enumerate(keys)})
        out = 2 * len(route.risers)
        for u, v in self.nested:
            for zone in ("in", "out"):
                if (u, zone) in rank and (v, zone) in rank:
                    out += abs(rank[u, zone] - rank[v, zone]) - 1
        if self.held is not None and (self.held, "in") in route.levels:
            out += 3
        return out

    def _levels(self, spans, order=None) -> dict:
        """Shafts: the longest innermost; drums: the longest outermost (or a given order)."""
        levels = {}
        for zone in ("in", "out"):
            keys = [k for k in spans if k[1] == zone]
            if order is not None and zone in order:
                keys = [k for k in order[zone] if k in spans]
            else:
                keys.sort(key=lambda k: (-(spans[k][1] - spans[k][0]), self.members.index(k[0])))
                keys = self._nest(keys)
            n = len(keys)
            for i, k in enumerate(keys):
                if zone == "in":
                    levels[k] = self.inner_top * i / max(n, 1)
                else:
                    levels[k] = self.outer_bottom + (n - i) * self.step
        return levels

    def _nest(self, keys) -> list:
        """Neighbouring lines swapped while that puts more members joined by a turning pair next
        to each other (a bearing between two shafts)."""
        if not self.nested or len(keys) < 3:
            return keys

        def apart(seq):
            at = {k[0]: i for i, k in enumerate(seq)}
            return sum(abs(at[u] - at[v]) - 1 for u, v in self.nested if u in at and v in at)

        best = apart(keys)
        for _ in range(len(keys)):
            moved = False
            for i in range(len(keys) - 1):
                trial = keys[:i] + [keys[i + 1], keys[i]] + keys[i + 2:]
                t = apart(trial)
                if t < best:
                    keys, best, moved = trial, t, True
            if not moved:
                break
        return keys

    def _crossings(self, placed, risers, levels, spans) -> int:
        """Spokes (vertical) that cross another member's shaft or drum (horizontal)."""
        import numpy as np

        index = self._index
        vx, vlo, vhi, vm, vm2 = [], [], [], [], []
        for p, x, y, zone, other in placed:
            if p.kind == "item":
                continue
            if p.kind == "toframe":  # a fixed axis's arm, up to the frame's housing at the top
                ya, yb, m2 = y, np.inf, -1
            else:
                ya = levels[p.member, zone]
                yb, m2 = (levels[p.other, other], index[p.other]) if p.kind == "clutch" else (y, -1)
            vx.append(x)
            vlo.append(min(ya, yb))
            vhi.append(max(ya, yb))
            vm.append(index.get(p.member, -2))
            vm2.append(m2)
        for m, x in risers.items():
            vx.append(x)
            vlo.append(levels[m, "in"])
            vhi.append(levels[m, "out"])
            vm.append(index[m])
            vm2.append(-1)
        if not vx or not spans:
            return 0
        keys = list(spans)
        h = np.array([(spans[k][0], spans[k][1], levels[k], index[k[0]]) for k in keys])
        v = np.array([vx, vlo, vhi, vm, vm2]).T
        hit = ((h[None, :, 0] < v[:, None, 0]) & (v[:, None, 0] < h[None, :, 1])
               & (v[:, None, 1] < h[None, :, 2]) & (h[None, :, 2] < v[:, None, 2])
               & (h[None, :, 3] != v[:, None, 3]) & (h[None, :, 3] != v[:, None, 4]))
        return int(hit.sum())

    def _cost(self, route):
        length = sum(x1 - x0 for x0, x1 in route.spans.values())
        for p, _x, y, zone, _other in route.ports:
            if p.kind in ("gear", "arm"):
                length += abs(route.levels[p.member, zone] - y)
        for m in route.risers:
            length += abs(route.levels[m, "out"] - route.levels[m, "in"])
        return (route.crossings, route.penalty, round(length, 6))

    # ------------------------------------------------------------------ search
    def _start(self) -> list:
        """Each flexible spoke from the line its member needs anyway (a ring's drum, a sun's shaft)."""
        forced = {}
        for p, opts in zip(self.ports, self.options):
            zones = {o[1] for o in opts}
            if p.kind == "gear" and len(zones) == 1:
                forced.setdefault(p.member, set()).update(zones)
        choice = []
        for p, opts in zip(self.ports, self.options):
            if p.kind == "riser":
                choice.append(len(opts) // 2)
                continue
            want = forced.get(p.member, {"in"})
            choice.append(next((c for c, o in enumerate(opts) if o[1] in want), 0))
        return choice

    def _group(self, choice, m, zone):
        """*choice* with every flexible spoke of member *m* moved to its *zone* line (same lanes)."""
        trial = list(choice)
        for k, p in enumerate(self.ports):
            if p.member != m or p.kind in ("item", "riser"):
                continue
            lane = self.options[k][choice[k]][0]
            fits = [c for c, o in enumerate(self.options[k]) if o[1] == zone]
            same = [c for c in fits if self.options[k][c][0] == lane]
            if fits:
                trial[k] = (same or fits)[0]
        return trial

    def solve(self) -> Route:
        """Coordinate descent: each decision in turn set to its best option, then each member's
        spokes moved to one line at once, until nothing improves."""
        choice = self._start()
        best = self.evaluate(choice)
        cost = self._cost(best)
        for _ in range(8):
            improved = False
            for k in range(len(self.ports)):
                for c in range(len(self.options[k])):
                    if c == choice[k]:
                        continue
                    trial = choice[:k] + [c] + choice[k + 1:]
                    route = self.evaluate(trial)
                    tc = self._cost(route)
                    if tc < cost:
                        choice, best, cost, improved = trial, route, tc, True
            for m in self.members:
                riser = next((k for k, p in enumerate(self.ports) if p.kind == "riser" and p.member == m), None)
                for zone in ("in", "out"):
                    moved = self._group(choice, m, zone)
                    if moved == choice:
                        continue
                    trials = [moved] if riser is None else [
                        moved[:riser] + [c] + moved[riser + 1:] for c in range(len(self.options[riser]))]
                    for trial in trials:
                        route = self.evaluate(trial)
                        tc = self._cost(route)
                        if tc < cost:
                            choice, best, cost, improved = trial, route, tc, True
            if not improved:
                break
        return self._reorder(choice, best)

    def _reorder(self, choice, route) -> Route:
        """Swap neighbouring shafts (or drums) while that removes crossings."""
        order = {z: sorted((k for k in route.levels if k[1] == z), key=lambda k: route.levels[k],
                           reverse=(z == "out")) for z in ("in", "out")}
        best = route
        for _ in range(len(route.levels)):
            improved = False
            for z in ("in", "out"):
                seq = order[z]
                for i in range(len(seq) - 1):
                    trial = seq[:i] + [seq[i + 1], seq[i]] + seq[i + 2:]
                    r = self.evaluate(choice, {**order, z: trial})
                    if (r.crossings, r.penalty) < (best.crossings, best.penalty):
                        order[z], best, improved = trial, r, True
                        seq = trial
            if not improved:
                break
        return best
