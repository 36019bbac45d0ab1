"""A kinematic sketch put together: units side by side, the main axis's members routed.

Private to :mod:`gearlib.mechanism.sketch`, which wraps what :func:`build` returns (plain
tuples) in its public classes. The ports (where each member's spokes start) and the routing
are here; :mod:`._sketch_emit` turns the result into lines, blocks, symbols and labels.
"""

from __future__ import annotations

import math

from ..errors import GeometryError
from ._sketch_blocks import build as build_units
from ._sketch_emit import Emitter
from ._sketch_parts import Parts
from ._sketch_route import Port, Router

__all__: list = []

INF = math.inf


def build(mech) -> dict:
    return _Builder(mech).result()


class _Builder(Emitter):
    def __init__(self, mech):
        self.mech = mech
        self.p = parts = Parts(mech)
        self.g = geom = build_units(parts)
        self.half = geom.mode != "fixed"
        self.S = geom.scale
        self.pitch = 0.11 * self.S
        self.step = 0.075 * self.S
        self.gap = 0.035 * self.S
        self.root = parts.axes[parts.root]
        self.ground = mech.ground
        self.axis_units: dict = {}
        for u in geom.units:
            for a in u.axes:
                self.axis_units.setdefault(a, []).append(u.index)
        self.out = {k: [] for k in ("blocks", "lines", "axes", "symbols", "labels")}
        self._route()
        self._emit()

    # ------------------------------------------------------------------ routing
    def _root_gear_ports(self):
        ports = []
        for u in self.g.units:
            for k, poly, _ in u.blocks:
                gear = self.p.gears[k]
                if gear.group != self.p.root:
                    continue
                ys = [q[1] for q in poly]
                if u.kind == "spur":
                    cx = (min(q[0] for q in poly) + max(q[0] for q in poly)) / 2
                    at = {"out": (cx, max(ys))} if gear.ring else {"in": (cx, min(ys))}
                else:
                    lo, hi = min(poly, key=lambda q: q[1]), max(poly, key=lambda q: q[1])
                    at = {}
                    if self._clear(u, k, lo, down=True):
                        at["in"] = lo
                    if self._clear(u, k, hi, down=False):
                        at["out"] = hi
                    at = at or {"in": lo}
                ports.append(Port(gear.link, "gear", at, unit=u.index))
        return ports

    @staticmethod
    def _clear(u, k, point, down) -> bool:
        x, y = point
        for j, poly, _ in u.blocks:
            if j == k:
                continue
            ys = _cut(poly, x)
            if ys is None:
                continue
            lo, hi = ys
            if (down and lo < y - 1e-9) or (not down and hi > y + 1e-9):
                if down and hi <= 0:
                    continue
                return False
        return True

    def _lanes_near(self, members, ends=True) -> tuple:
        n = len(self.g.units)
        units = set()
        for m in members:
            units |= self.member_units.get(m, set())
        lanes = {0, n} if ends or not units else set()
        for i in units:
            lanes |= {i, i + 1}
        return tuple(sorted(lanes))

    def _route(self):
        parts, mech = self.p, self.mech
        root_links = list(self.root.links) if self.half else []
        ports = self._root_gear_ports() if self.half else []
        self.member_units = {}
        for p in ports:
            self.member_units.setdefault(p.member, set()).add(p.unit)
        gear_members = {p.member for p in ports}
        self.frame = self.half and self.ground in root_links and self.ground not in gear_members
        members = [x for x in root_links if not (self.frame and x == self.ground)]
        self.routed = set(members)
        for m in root_links:
            for a_id in parts.children.get(m, []):
                a = parts.axes[a_id]
                if a_id in self.g.lower_axes:
                    continue
                kind = "toframe" if m not in self.routed else "arm"
                if a.inclined:
                    u = next(u for u in self.g.units if a_id in u.pins)
                    end = u.pins[a_id][1]
                    ports.append(Port(m, kind, {"out": end}, unit=u.index, axis=a_id))
                else:
                    us = self.axis_units[a_id]
                    at = {"out": (None, a.offset)} if kind == "toframe" else {"in": (None, a.offset),
                                                                              "out": (None, a.offset)}
                    ports.append(Port(m, kind, at, lanes=(min(us), max(us) + 1), axis=a_id))
                self.member_units.setdefault(m, set()).update(self.axis_units.get(a_id, []))
        for a_id, a in parts.axes.items():   # arms of carriers that turn off the main axis
            if a.parent is not None and a.parent not in root_links and a.parent != self.ground:
                us = self.axis_units[a_id]
                ports.append(Port(a.parent, "item", {"-": (None, a.offset)}, lanes=(min(us),), axis=a_id))
        for e in mech.shift_elements:
            if e.kind == "brake":
                m = e.links[0]
                if m in self.routed:
                    ports.append(Port(m, "brake", {"auto": (None, INF)}, lanes=self._lanes_near([m]), name=e.name))
                else:
                    us = self._units_of_link(m)
                    ports.append(Port(m, "item", {"-": (None, 0.0)}, lanes=(max(us) + 1,), name=e.name))
            else:
                u, v = e.links
                if mech.coaxial(u, v) is None:
                    raise GeometryError(f"clutch {e.name!r} joins links {u} and {v}, which do not turn about one axis; "
                                        "a clutch joins two coaxial members")
                if u in self.routed and v in self.routed:
                    ports.append(Port(u, "clutch", {"auto": (None, 0.0)}, lanes=self._lanes_near([u, v]), name=e.name,
                                      other=v))
                else:
                    us = self._units_of_link(u) + self._units_of_link(v)
                    ports.append(Port(u, "item", {"-": (None, 0.0)}, lanes=(max(us) + 1,), name=e.name, other=v))
        for m in members:   # where a member's shaft and drum would be joined, if it needs both
            ports.append(Port(m, "riser", {"-": (None, 0.0)}, lanes=self._lanes_near([m], ends=False)))
        ends = {}
        for i, x in enumerate(mech.inputs):
            if x in self.routed:
                ends.setdefault(x, []).append("left" if i == 0 else "near")
        if mech.output is not None and mech.output in self.routed:
            ends.setdefault(mech.output, []).append("right")
        nested = [tp.links for tp in mech.turning_pairs
                  if tp.links[0] in self.routed and tp.links[1] in self.routed]
        blocks = [q for u in self.g.units for _, poly, _ in u.blocks for q in poly]
        lows = [q[1] for q in blocks if q[1] > 1e-9]
        for p in ports:
            if "in" in p.at and p.kind == "gear" and p.at["in"][1] > 1e-9:
                lows.append(p.at["in"][1])
        inner_top = 0.85 * min(lows, default=self.S)
        tops = [q[1] for q in blocks] + [q[1] for u in self.g.units for pin in u.pins.values() for q in pin]
        tops += [a.offset + 0.3 * self.S for a in parts.axes.values() if a.parent is not None and not a.inclined
                 and not self.axis_units.get(a.group)]
        outer = max(tops, default=self.S) + 0.6 * self.step
        widths = [u.width for u in self.g.units]
        placed = []
        for u in self.g.units:
            for k, poly, _ in u.blocks:
                xs_, ys_ = [q[0] for q in poly], [q[1] for q in poly]
                placed.append((u.index, min(xs_), max(xs_), min(ys_), max(ys_), self.p.gears[k].group))
        self.behind = self._partners()
        flippable = [u.index for u in self.g.units if u.kind == "spur" and self.half
                     and any(b[1] > 1e-9 or b[2] < u.width - 1e-9 for b in placed if b[0] == u.index)]
        self.router = Router(ports, widths, members, self.pitch, inner_top, outer, self.step, ends, nested,
                             self.ground if self.ground in self.routed else None, placed, self.behind, flippable,
                             self._blocks_of(self.ground) if self.ground in self.routed else ())
        self.route = self.router.solve()
        for u in self.g.units:   # units drawn mirrored: their planes in the other order
            if u.index in self.route.flipped:
                u.blocks = [(k, tuple((u.width - x, y) for x, y in poly), m) for k, poly, m in u.blocks]
        drums = [y for (m, z), y in self.route.levels.items() if z == "out"]
        has_brakes = any(p.kind == "brake" for p in ports)
        self.top = max(drums + [outer]) + self.step * (2.6 if has_brakes else 1.2)

    def _blocks_of(self, link) -> list:
        """(unit, x0, x1) of every gear block of *link*, in unit coordinates."""
        out = []
        for u in self.g.units:
            for k, poly, _ in u.blocks:
                if self.p.gears[k].link == link:
                    out.append((u.index, min(q[0] for q in poly), max(q[0] for q in poly)))
        return out

    def _partners(self) -> dict:
        """axis -> the axes of the pinions that mesh its own on the same carrier (a double-pinion
        set): they stand at another angle about the main axis, so its pin passes behind them."""
        out: dict = {}
        axes, gears = self.p.axes, self.p.gears
        for ia, ib in self.p.pair_gears:
            a, b = axes[gears[ia].group], axes[gears[ib].group]
            if a.group != b.group and a.parent is not None and a.parent == b.parent and not (a.inclined or b.inclined):
                out.setdefault(a.group, set()).add(b.group)
                out.setdefault(b.group, set()).add(a.group)
        return out

    def _units_of_link(self, link) -> list:
        found = [u.index for u in self.g.units for k, _, _ in u.blocks if self.p.gears[k].link == link]
        return found or [len(self.g.units) - 1]

    def result(self) -> dict:
        self.out["mode"] = self.g.mode
        self.out["crossings"] = self.route.crossings
        self.out["notes"] = tuple(self.p.notes)
        self.out["scale"] = self.S
        return self.out


def _cut(poly, x):
    """The y interval where the vertical line at *x* meets a convex polygon, or None."""
    ys = []
    n = len(poly)
    for i in range(n):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % n]
        if (x0 - x) * (x1 - x) <= 0 and x0 != x1:
            ys.append(y0 + (y1 - y0) * (x - x0) / (x1 - x0))
        elif x0 == x1 == x:
            ys += [y0, y1]
    return (min(ys), max(ys)) if len(ys) >= 2 else None
