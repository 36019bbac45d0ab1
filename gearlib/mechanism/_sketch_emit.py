"""The drawn pieces of a kinematic sketch: blocks, lines, symbols, axis lines and labels.

Private to :mod:`gearlib.mechanism.sketch`: :class:`Emitter` is the half of the sketch
builder (:mod:`._sketch_build`) that, once the units are placed and the main axis's members
routed, emits every piece as a plain tuple.
"""

from __future__ import annotations

import math

__all__: list = []


def _mirror_pt(p):
    return (p[0], -p[1])


def _stack(spans) -> list:
    """Rows (0, 1, -1, 2, ...) for shafts on one axis, in the order given: shafts whose spans
    overlap sit side by side."""
    rows, out = [], []
    for s in spans:
        level = 0
        while any(lv == level and not (s[2] < lo or s[1] > hi) for lv, lo, hi in rows):
            level = -level if level > 0 else 1 - level
        rows.append((level, s[1], s[2]))
        out.append(level)
    return out


def _rows(spans, offset, delta, axes) -> list:
    """The rows of the shafts on one axis, in the order (of the few there are) whose arms, up or
    down to the axes they hold, cross the fewest other shafts; the first such order."""
    from itertools import permutations

    best = None
    for order in permutations(range(len(spans))) if len(spans) <= 6 else [range(len(spans))]:
        levels = dict(zip(order, _stack([spans[i] for i in order])))
        ys = {i: offset + levels[i] * delta for i in levels}
        bad = 0
        for i, (_link, _lo, _hi, _b, arms) in enumerate(spans):
            for p, x in arms:
                y0, y1 = sorted((ys[i], axes[p.axis].offset))
                bad += sum(1 for j, t in enumerate(spans) if j != i and t[1] < x < t[2] and y0 < ys[j] < y1)
        if best is None or bad < best[0]:
            best = (bad, [levels[i] for i in range(len(spans))])
        if bad == 0:
            break
    return best[1]


class Emitter:
    # ------------------------------------------------------------------ drawing primitives
    def _line(self, link, kind, a, b, copy=False):
        self.out["lines"].append((link, kind, a, b, copy))

    def _symbol(self, kind, name, links, segments, hatch, anchor, copy=False):
        self.out["symbols"].append((kind, name, links, tuple(segments), tuple(hatch), anchor, copy))

    def _emit(self):
        r, parts = self.route, self.p
        ux = r.unit_x
        self.placed_blocks = []
        for u in self.g.units:
            for k, poly, _ in u.blocks:
                gear = parts.gears[k]
                a = parts.axes[gear.group]
                poly = tuple((x + ux[u.index], y) for x, y in poly)
                if a.parent is None:
                    kind = "ring" if gear.ring else ("bevel" if gear.bevel else ("sun" if self.half else "gear"))
                else:
                    kind = "bevel" if gear.bevel else ("planet" if self.half else "gear")
                self.out["blocks"].append((gear.link, kind, poly, a.label, gear.radius, k, False))
                self.placed_blocks.append((k, poly, u.index))
                if self.g.mode == "full" and a.parent is None:
                    self.out["blocks"].append((gear.link, kind, tuple(map(_mirror_pt, poly)), a.label, gear.radius, k, True))
        self._emit_routes()
        self._emit_axis_members()
        self._emit_axes()
        self._emit_labels()

    def _blocks_on(self, axis) -> list:
        return [poly for k, poly, _ in self.placed_blocks if self.p.gears[k].group == axis]

    def _emit_routes(self):
        r, parts = self.route, self.p
        lv = r.levels
        full = self.g.mode == "full"
        start = len(self.out["lines"])
        start_sym = len(self.out["symbols"])
        for (m, zone), (x0, x1) in r.spans.items():
            if m == self.ground:   # a held member: its line spans its gears at least, and is hatched
                xs = [q[0] for k, poly, _ in self.placed_blocks if parts.gears[k].link == m for q in poly]
                x0, x1 = min([x0] + xs), max([x1] + xs)
                y = lv[m, zone]
                side = self.gap if zone == "out" else -self.gap
                self._symbol("ground", "", (m,), (), [((x0, y), (x1, y), (x1, y + side), (x0, y + side))], (x0, y))
            self._line(m, "shaft" if zone == "in" else "drum", (x0, lv[m, zone]), (x1, lv[m, zone]))
        for m, x in r.risers.items():
            self._line(m, "riser", (x, lv[m, "in"]), (x, lv[m, "out"]))
        mirrored_axes = set(self.g.upper_axes)
        pinned = set()
        for p, x, y, zone, other in r.ports:
            if p.kind == "gear":
                self._line(p.member, "spoke", (x, lv[p.member, zone]), (x, y))
            elif p.kind in ("arm", "toframe"):
                y0 = lv[p.member, zone] if p.kind == "arm" else self.top
                self._line(p.member, "arm", (x, y0), (x, y))
                if p.kind == "toframe":
                    self._symbol("ground", "", (p.member,), (), [], (x, self.top))
                if full and p.axis in mirrored_axes:
                    self._line(p.member, "arm", _mirror_pt((x, y0)), _mirror_pt((x, y)), True)
                if p.axis in pinned:   # the second arm of a bracket: its pin is drawn
                    continue
                pinned.add(p.axis)
                if p.axis in r.pins:
                    pin = ((r.pins[p.axis][0], y), (r.pins[p.axis][1], y))
                    self._pin_line(p.axis, pin)
                else:
                    pin = self._pin(p.axis, x, y)
                if full and p.axis in mirrored_axes:
                    self._line(p.member, "pin", _mirror_pt(pin[0]), _mirror_pt(pin[1]), True)
            elif p.kind == "brake":
                self._brake(p, x, lv[p.member, zone])
            elif p.kind == "clutch":
                self._clutch(p, x, lv[p.member, zone], lv[p.other, other])
        if self.frame:
            left, right = r.left - self.pitch, r.right + self.pitch
            self._line(self.ground, "housing", (left, self.top), (right, self.top))
            self._symbol("ground", "", (self.ground,), (),
                         [((left, self.top), (right, self.top), (right, self.top + self.gap), (left, self.top + self.gap))],
                         (left, self.top))
        if full:  # the lower half of the section: the same members, mirrored
            for link, kind, a, b, _ in list(self.out["lines"][start:]):
                if kind not in ("arm", "pin", "housing"):
                    self._line(link, kind, _mirror_pt(a), _mirror_pt(b), True)
            for kind, name, links, segs, hatch, anchor, _ in list(self.out["symbols"][start_sym:]):
                if kind in ("brake", "clutch") or (kind == "ground" and links[0] != self.ground) or not self.frame:
                    self._symbol(kind, name, links, [tuple(map(_mirror_pt, s)) for s in segs],
                                 [tuple(map(_mirror_pt, h)) for h in hatch], _mirror_pt(anchor), True)

    def _pin_line(self, axis, pin):
        """A pin, drawn dashed (hidden) where it passes behind the other pinion of its set."""
        owner = self.p.axes[axis].parent
        (x0, y), (x1, _) = pin
        cuts = []
        for k, poly, _u in self.placed_blocks:
            if self.p.gears[k].group in self.behind.get(axis, ()):
                xs, ys = [q[0] for q in poly], [q[1] for q in poly]
                if min(ys) < y < max(ys) and min(xs) < x1 and max(xs) > x0:
                    cuts.append((max(min(xs), x0), min(max(xs), x1)))
        at = x0
        for a, b in sorted(cuts):
            if a > at:
                self._line(owner, "pin", (at, y), (a, y))
            self._line(owner, "hidden", (a, y), (b, y))
            at = max(at, b)
        if at < x1:
            self._line(owner, "pin", (at, y), (x1, y))

    def _pin(self, axis, x, y):
        a = self.p.axes[axis]
        if a.inclined:
            u = next(u for u in self.g.units if axis in u.pins)
            (x0, y0), (x1, y1) = u.pins[axis]
            pin = ((x0 + self.route.unit_x[u.index], y0), (x1 + self.route.unit_x[u.index], y1))
        else:
            xs = [q[0] for poly in self._blocks_on(axis) for q in poly] or [x]
            far = max(xs) if abs(max(xs) - x) >= abs(min(xs) - x) else min(xs)
            pin = ((x, y), (far, y))
        self._line(a.parent, "pin", *pin)
        return pin

    def _brake(self, p, x, y0):
        w, g, top = 0.36 * self.pitch, self.gap, self.top
        plate = top - 2.2 * g
        self._line(p.member, "spoke", (x, y0), (x, plate))
        segs = [((x - w, plate), (x + w, plate)), ((x - w, plate + g), (x + w, plate + g)),
                ((x - w, plate + g), (x - w, top)), ((x + w, plate + g), (x + w, top))]
        hatch = [] if self.frame else [((x - 1.4 * w, top), (x + 1.4 * w, top), (x + 1.4 * w, top + g),
                                        (x - 1.4 * w, top + g))]
        self._symbol("brake", p.name, (p.member,), segs, hatch, (x + w, plate + 0.5 * g))

    def _clutch(self, p, x, y1, y2):
        (lo_m, lo), (hi_m, hi) = sorted([(p.member, y1), (p.other, y2)], key=lambda t: t[1])
        w, g = 0.36 * self.pitch, min(self.gap, 0.4 * (hi - lo))   # plates between the two lines
        mid = (lo + hi) / 2
        self._line(lo_m, "spoke", (x, lo), (x, mid - g / 2))
        self._line(hi_m, "spoke", (x, hi), (x, mid + g / 2))
        segs = [((x - w, mid - g / 2), (x + w, mid - g / 2)), ((x - w, mid + g / 2), (x + w, mid + g / 2))]
        self._symbol("clutch", p.name, (p.member, p.other), segs, (), (x + w, mid))

    # ------------------------------------------------------------------ links off the main axis
    def _emit_axis_members(self):
        parts, r = self.p, self.route
        items = {}
        for p, x, _y, _zone, _other in r.ports:
            if p.kind == "item":
                items.setdefault(p.member, []).append((p, x))
        delta = 0.045 * self.S
        for a_id, a in parts.axes.items():
            if a.inclined or (self.half and a.parent is None):
                continue
            held_by_ground = not self.half and (a.parent == self.ground or (a.parent is None and self.ground in a.links))
            spans = []
            for link in a.links:
                xs = [q[0] for k, poly, _ in self.placed_blocks if parts.gears[k].link == link
                      and parts.gears[k].group == a_id for q in poly]
                arms = [(p, x) for p, x in items.get(link, []) if p.axis is not None]
                xs += [x for _, x in arms]
                xs += [x for p, x in items.get(link, []) if p.axis is None]
                if not xs:
                    us = self.axis_units.get(a_id)
                    x0 = r.unit_x[us[0]] if us else r.right
                    xs = [x0, x0 + self.g.block_width]
                lo, hi = min(xs), max(xs)
                if self.mech.inputs and link == self.mech.inputs[0] and not self.half:
                    lo = r.left
                if link == self.mech.output and not self.half:
                    hi = r.right
                bearing = held_by_ground and link != self.ground
                if bearing:
                    lo, hi = lo - 0.35 * self.pitch, hi + 0.35 * self.pitch
                spans.append([link, lo, hi, bearing, arms])
            for s, level in zip(spans, _rows(spans, a.offset, delta, parts.axes)):
                y = a.offset + level * delta
                link, lo, hi, bearing, arms = s
                if link == self.ground:
                    continue
                n_blocks = sum(1 for k, _, _ in self.placed_blocks if self.p.gears[k].link == link
                               and self.p.gears[k].group == a_id)
                if bearing or arms or n_blocks != 1 or items.get(link) or (not self.half and link in (
                        self.mech.output, *self.mech.inputs[:1])):
                    self._line(link, "shaft", (lo, y), (hi, y))
                if bearing:
                    for xb in (lo, hi):
                        self._bearing(link, xb, y)
                for p, x in arms:
                    child = parts.axes[p.axis]
                    self._line(link, "arm", (x, y), (x, child.offset))
                    self._pin(p.axis, x, child.offset)
                for p, x in items.get(link, []):
                    if p.axis is None and p.other is None:
                        self._axis_brake(p, link, x, y)
                    elif p.axis is None:
                        self._axis_clutch(p, x, y)

        for a_id, a in parts.axes.items():   # a compound bevel planet: its gears joined along its axis
            if not a.inclined:
                continue
            u = next(u for u in self.g.units if a_id in u.pins)
            ox, oy = u.apex[0] + r.unit_x[u.index], parts.axes[a.parent_group].offset
            c, s_ = math.cos(a.angle), math.sin(a.angle)
            for link in a.links:
                hs = [g.h for g in parts.gears if g.link == link and g.group == a_id and g.index not in self.g.lower]
                if len(hs) > 1:
                    self._line(link, "shaft", (ox + min(hs) * c, oy + min(hs) * s_), (ox + max(hs) * c, oy + max(hs) * s_))

    def _bearing(self, link, x, y):
        b, c = 0.22 * self.pitch, 0.4 * self.gap
        hatch = [((x - b, y + c), (x + b, y + c), (x + b, y + c + b), (x - b, y + c + b)),
                 ((x - b, y - c), (x + b, y - c), (x + b, y - c - b), (x - b, y - c - b))]
        segs = [((x - b, y + c), (x + b, y + c)), ((x - b, y - c), (x + b, y - c))]
        self._symbol("bearing", "", (link, self.ground), segs, hatch, (x, y))

    def _axis_brake(self, p, link, x, y):
        w, g = 0.5 * self.pitch, self.gap
        self._line(link, "shaft", (x - self.pitch, y), (x, y))
        segs = [((x, y - w), (x, y + w)), ((x + g, y - w), (x + g, y + w))]
        hatch = [((x + g, y - 1.4 * w), (x + 2 * g, y - 1.4 * w), (x + 2 * g, y + 1.4 * w), (x + g, y + 1.4 * w))]
        self._symbol("brake", p.name, (link,), segs, hatch, (x + 2 * g, y + w))

    def _axis_clutch(self, p, x, y):
        w, g = 0.5 * self.pitch, self.gap
        segs = [((x, y - w), (x, y + w)), ((x + g, y - w), (x + g, y + w))]
        self._symbol("clutch", p.name, (p.member, p.other), segs, (), (x + g, y + w))

    # ------------------------------------------------------------------ axes and labels
    def _emit_axes(self):
        parts, r = self.p, self.route
        for a_id, a in parts.axes.items():
            links = tuple(sorted(self.p.groups.members[a_id], key=parts.order.get))
            if a.parent is None:
                self.out["axes"].append((a.label, links, (r.left - self.pitch, 0.0), (r.right + self.pitch, 0.0)))
                continue
            pts = [q for poly in self._blocks_on(a_id) for q in poly]
            pts += [q for link, kind, s, e, _ in self.out["lines"] if kind in ("pin", "shaft")
                    and link in links and self._on(a, s) for q in (s, e)]
            if a.inclined:
                u = next(u for u in self.g.units if a_id in u.pins)
                ox, oy = u.apex[0] + r.unit_x[u.index], self.p.axes[a.parent_group].offset
                ux_, uy_ = math.cos(a.angle), math.sin(a.angle)
                ts = [(q[0] - ox) * ux_ + (q[1] - oy) * uy_ for q in pts] or [0.0]
                t1 = max(ts) + 0.25 * self.pitch
                self.out["axes"].append((a.label, links, (ox, oy), (ox + t1 * ux_, oy + t1 * uy_)))
            else:
                xs = [q[0] for q in pts] or [0.0]
                y = a.offset
                self.out["axes"].append((a.label, links, (min(xs) - 0.3 * self.pitch, y), (max(xs) + 0.3 * self.pitch, y)))

    def _on(self, a, point) -> bool:
        return abs(point[1] - a.offset) < 0.2 * self.S if not a.inclined else False

    def _emit_labels(self):
        mech = self.mech
        done = set()
        for link, _kind, poly, *rest in self.out["blocks"]:
            if link in done or rest[-1]:
                continue
            done.add(link)
            cx = sum(q[0] for q in poly) / len(poly)
            cy = sum(q[1] for q in poly) / len(poly)
            self.out["labels"].append((link, self._text(link), (cx, cy)))
        for link, kind, a, b, copy in self.out["lines"]:
            if link in done or link is None or copy:
                continue
            if kind in ("arm", "riser", "spoke", "housing", "drum", "shaft"):
                done.add(link)
                t = 0.5 if kind != "housing" else 0.04
                self.out["labels"].append((link, self._text(link), (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))))
        for kind, _name, links, _segs, _hatch, anchor, _copy in self.out["symbols"]:
            for link in links:
                if link not in done and link == self.ground:
                    done.add(link)
                    below = 3.2 * self.gap if kind == "bearing" else 0.0   # under its bearing mark
                    self.out["labels"].append((link, self._text(link), (anchor[0], anchor[1] - below)))
        missing = [x for x in mech.link_ids if x not in done]
        if missing:   # nothing else drew it (a frame with nothing fixed to it): a bearing symbol
            for link in missing:
                x, y = self.route.left, 0.0
                self._symbol("ground", "", (link,), (), [((x, -self.gap), (x + self.pitch, -self.gap),
                                                          (x + self.pitch, 0.0), (x, 0.0))], (x, y))
                self.out["labels"].append((link, self._text(link), (x + 0.5 * self.pitch, -2 * self.gap)))

    def _text(self, link) -> str:
        n = self.mech.planet_count(link)
        return f"{link}" if n == 1 else f"{link} (×{n})"

