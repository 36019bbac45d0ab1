"""Bevel gears in a kinematic sketch: inclined axes through a cone apex on their parent axis.

Private to :mod:`gearlib.mechanism.sketch`: the bevel half of :class:`._sketch_parts.Parts`.
"""

from __future__ import annotations

import math

from ..errors import GeometryError

__all__: list = []


class Cones:
    def _incline(self, a, meshes):
        """Direction of an inclined axis and the place of each of its gears' pitch circles."""
        self._done.add(a.group)
        a.inclined = True
        for _, mine, other in meshes:
            for k in (mine, other):
                if self.gears[k].radius is None:
                    self.gears[k].radius = self.nominal
        on_axis = {}
        for i, mine, other in meshes:
            on_axis.setdefault(mine, []).append((i, other))
        phi = None
        for gi, central in on_axis.items():
            if len(central) > 2:
                names = ", ".join(str(self.gears[o].link) for _, o in central)
                raise GeometryError(f"bevel gear of link {self.gears[gi].link} meshes {names}: a bevel gear meets "
                                    "at most two gears on the axis it turns about (one at each end of its pitch diameter)")
            if len(central) == 2 and phi is None:
                phi = self._two_mesh_angle(gi, central)
        if phi is None:
            i, gi, _ = meshes[0]
            phi = self._shaft_angle(self.mech.gear_pairs[i])
        if abs(math.sin(phi)) < 1e-6:
            raise GeometryError(f"axis {a.label!r}: its bevel gears would turn about an axis parallel to their "
                                "partners'; give the pair's angles or make it a spur pair")
        a.angle = phi
        taken = []
        for gi, central in on_axis.items():
            g = self.gears[gi]
            if len(central) == 2:
                (i1, o1), (i2, o2) = central
                r1, r2 = self.gears[o1].radius, self.gears[o2].radius
                if abs((r1 - r2) - 2 * g.radius * math.cos(phi)) > 1e-6 * max(r1, r2):
                    raise GeometryError(
                        f"bevel gear of link {g.link} (pitch radius {g.radius:g}) cannot mesh both {self.gears[o1].link} "
                        f"and {self.gears[o2].link} about axis {a.label!r} with the direction its other gears give it")
                g.h = (r1 + r2) / (2 * math.sin(phi))
                g.sides = {i1: 1, i2: -1}
            else:
                (i1, o1), = central
                rc = self.gears[o1].radius
                options = []
                for s in (-1, 1):
                    h = (rc - s * g.radius * math.cos(phi)) / math.sin(phi)
                    if h > 0.05 * g.radius:
                        options.append((min((abs(h - t) for t in taken), default=0.0), -s, h, s))
                if not options:
                    raise GeometryError(f"bevel pair {self.mech.gear_pairs[i1].label}: no cone apex fits pitch radii "
                                        f"{g.radius:g} and {rc:g} at the axis angle {math.degrees(phi):.0f} degrees")
                _, _, g.h, s = max(options)
                g.sides = {i1: s}
            taken.append(g.h)

    def _two_mesh_angle(self, gi, central) -> float:
        g = self.gears[gi]
        (_, o1), (_, o2) = central
        r1, r2 = self.gears[o1].radius, self.gears[o2].radius
        c = (r1 - r2) / (2 * g.radius)
        if abs(c) > 1 + 1e-9:
            raise GeometryError(
                f"bevel gear of link {g.link} (pitch radius {g.radius:g}) cannot mesh both {self.gears[o1].link} and "
                f"{self.gears[o2].link}: their pitch radii ({r1:g}, {r2:g}) differ by more than its pitch diameter")
        return math.acos(max(-1.0, min(1.0, c)))

    @staticmethod
    def _shaft_angle(gp) -> float:
        """A bevel pair's shaft angle: from Penaud's angles when they give a direction, else 90 degrees."""
        if gp.angles is not None:
            sigma = abs(float(gp.angles[0] - gp.angles[1])) % (2 * math.pi)
            sigma = min(sigma, 2 * math.pi - sigma)
            if 1e-6 < sigma < math.pi - 1e-6:
                return sigma
        return math.pi / 2
