"""Which shaft is inside which in a sketch, and which drum outside which.

Private to :mod:`gearlib.mechanism.sketch`: the nesting half of :class:`._sketch_route.Router`.
"""

from __future__ import annotations

__all__: list = []

_ZONES = ("in", "out")


class Nesting:
    def _order(self, spans, pieces, risers) -> dict:
        """Which shaft is inside which, and which drum outside which: each zone's lines from the
        axis outwards, in an order that keeps every line clear of the pieces that rise (or drop)
        from the lines on its inner (or outer) side where it can: a line that spans a piece rising
        from line *a* goes below *a*, a drum that spans a piece dropping from drum *a* (to a gear, a
        pin, a shaft) above it, and one that spans a brake rising from drum *a* below it. A
        topological order of these wishes (the fewest broken where they conflict), ties to an
        input or output innermost, then a member journalled on the one placed before, then the
        longer line innermost (drums: outermost)."""
        ports = self.ports
        ups = []       # (x, shaft it rises from, members)
        downs = []     # (x, drum it drops from, members)
        brakes = []    # (x, drum it rises from, members)
        for k, px, _py, z0, z1 in pieces:
            p = ports[k]
            kind = p.kind
            if kind == "item" or kind == "toframe":
                continue
            if kind == "clutch":
                if z0 == z1:
                    continue
                lo, hi = (p.member, p.other) if z0 == "in" else (p.other, p.member)
                ups.append((px, (lo, "in"), p.member, p.other))
                downs.append((px, (hi, "out"), p.member, p.other))
            elif z0 == "in":
                ups.append((px, (p.member, "in"), p.member, p.member))
            elif kind == "brake":
                brakes.append((px, (p.member, "out"), p.member, p.member))
            else:
                downs.append((px, (p.member, "out"), p.member, p.member))
        for m, px in risers.items():
            ups.append((px, (m, "in"), m, m))
            downs.append((px, (m, "out"), m, m))
        lines = {"in": [], "out": []}
        for key, (lo, hi) in spans.items():
            lines[key[1]].append((lo, hi, key, key[0]))
        before = {key: set() for key in spans}   # line -> lines wanted nearer the axis
        for x, a, m1, m2 in ups:
            for lo, hi, n, nm in lines["in"]:
                if lo < x < hi and nm != m1 and nm != m2:
                    before[a].add(n)
        for x, a, m1, m2 in downs:
            for lo, hi, n, nm in lines["out"]:
                if lo < x < hi and nm != m1 and nm != m2:
                    before[n].add(a)
        for x, a, m1, m2 in brakes:
            for lo, hi, n, nm in lines["out"]:
                if lo < x < hi and nm != m1 and nm != m2:
                    before[a].add(n)
        return {zone: self._sort([t[2] for t in lines[zone]], before, spans, zone) for zone in _ZONES}

    def _sort(self, keys, before, spans, zone) -> list:
        ends, partners, index = self.ends, self._partners, self.index
        inner = zone == "in"
        rest = sorted(keys, key=lambda k: (-(inner and k[0] in ends),
                                           (spans[k][0] - spans[k][1]) if inner else (spans[k][1] - spans[k][0]),
                                           index[k[0]]))
        order, placed = [], set()
        while rest:
            ready = [k for k in rest if before[k] <= placed]
            if not ready:   # wishes in a cycle: break the fewest
                fewest = min(len(before[k] - placed) for k in rest)
                ready = [k for k in rest if len(before[k] - placed) == fewest]
            if order and partners:
                near = partners.get(order[-1][0], ())
                ready = [k for k in ready if k[0] in near] or ready
            k = ready[0]
            order.append(k)
            placed.add(k)
            rest.remove(k)
        return order
