"""The parts of a kinematic sketch: its axes, its gears and their pitch radii.

Private to :mod:`gearlib.mechanism.sketch`. Read from the data alone:

* **axes**: each coaxial group of turning pairs is one geometric axis. The groups and the links
  that belong to several of them form a tree (the data would be rejected otherwise); its root is
  the *main axis* (the group with the most links, then the one holding the ground). A child axis
  is fixed in its *parent link* (a carrier, or the frame), which turns about the parent axis;
* **gears**: a link carries one gear per carrier, axis, kind and pitch radius, so a planet that
  meshes a sun and a ring is one gear, a compound (stepped) planet two;
* **pitch radii**: ``radii``, or the module and the teeth (:attr:`GearPair.pitch_radii`); teeth
  alone are relative sizes (a common module); a pair with neither (a symbolic ratio) takes the
  size that closes its centre distance, or a nominal one. A profile-shifted pair
  (``profile_shift``) runs at its *working* centre distance (:func:`~gearlib.mechanism.assembly.centre_distance`,
  from inv(alpha_w) = inv(alpha) + 2 tan(alpha) (x1 + x2) / (z1 + z2)), not at the sum of its
  reference pitch radii: its axis is placed there and its gears drawn at their working pitch
  radii (the reference radii times a_w / a), the gear that meets a second mesh sized to close
  it, so the blocks touch;
* **where a child axis lies**: parallel to its parent at the centre distance of a spur mesh, or
  through a cone apex on its parent, inclined, for bevel meshes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from statistics import median

from ..errors import GeometryError
from ._sketch_cones import Cones
from .assembly import TOLERANCE, centre_distance

__all__: list = []


@dataclass
class Gear:
    index: int
    link: object
    carrier: object
    group: int              # the axis the gear turns about
    ring: bool              # internal teeth
    bevel: bool
    radius: float | None = None
    known: bool = False     # radius from the data (not assumed)
    meshes: list = field(default_factory=list)  # (pair index, other gear index)
    h: float = 0.0          # bevel gear on an inclined axis: distance of its pitch circle from the apex
    sides: dict = field(default_factory=dict)   # pair index -> +1/-1, which end of its pitch diameter meshes


@dataclass
class Axis:
    group: int
    label: str
    parent: object          # the link that holds this axis (None for the main axis)
    parent_group: int | None
    links: tuple            # the links that turn about it (the parent link excepted)
    depth: int = 0
    offset: float = 0.0     # a parallel axis: its distance from the main axis line (signed)
    inclined: bool = False
    angle: float = 0.0      # an inclined axis: its angle from the main axis, radians


def _close(a, b) -> bool:
    return abs(a - b) <= 1e-9 * max(abs(a), abs(b), 1.0)


class Parts(Cones):
    """Axes, gears and sizes of one mechanism (see the module docstring)."""

    def __init__(self, mech):
        self.mech = mech
        self.groups = mech._groups
        self.order = {x: i for i, x in enumerate(mech.link_ids)}
        self.notes: list[str] = []
        if not self.groups.members:
            raise GeometryError(f"{mech.name!r} has no turning pairs: a sketch needs at least one axis")
        self._axes_tree()
        self._gears()
        self._sizes()

    # ------------------------------------------------------------------ axes
    def _axes_tree(self):
        g, mech = self.groups, self.mech
        ground = mech.ground

        def rank(i):
            members = g.members[i]
            return (-len(members), ground not in members, min(self.order[x] for x in members))

        self.root = min(range(len(g.members)), key=rank)
        self.axes: dict[int, Axis] = {}
        self.turn: dict = {}   # link -> the axis it turns about
        queue = [(self.root, None, None, 0)]
        seen = {self.root}
        while queue:
            gid, plink, pgroup, depth = queue.pop(0)
            links = tuple(sorted((x for x in g.members[gid] if x != plink), key=self.order.get))
            self.axes[gid] = Axis(gid, g.labels[gid], plink, pgroup, links, depth)
            for x in links:
                self.turn.setdefault(x, gid)
            for x in links:
                for other in sorted(g.membership[x].values()):
                    if other not in seen:
                        seen.add(other)
                        queue.append((other, x, gid, depth + 1))
        missing = [x for x in mech.link_ids if x not in self.turn]
        if missing:
            raise GeometryError(f"link {missing[0]} of {mech.name!r} has no turning pair, so no axis to draw it on; "
                                "give it a turning pair")
        self.children: dict = {}   # link -> axes it holds
        for a in self.axes.values():
            if a.parent is not None:
                self.children.setdefault(a.parent, []).append(a.group)

    def axis_of_link(self, link) -> Axis:
        return self.axes[self.turn[link]]

    # ------------------------------------------------------------------ gears
    def _gears(self):
        mech = self.mech
        modules = [2 * gp.pitch_radii[0] / gp.teeth[0] for gp in mech.gear_pairs
                   if gp.pitch_radii is not None and gp.teeth is not None]
        module = median(modules) if modules else 1.0
        self.gears: list[Gear] = []
        self.pair_gears: list[tuple[int, int]] = []
        self.working: list[float] = []   # working / reference centre distance (1 without profile shift)
        self.ratios: list = []   # |r_b / r_a| when the pair gives a numeric ratio only, else None
        by_key: dict = {}
        relative: set = set()    # pairs sized by their teeth alone
        for i, gp in enumerate(mech.gear_pairs):
            a, b = gp.gears
            ga, gb = self._gear_groups(gp)
            radii = gp.pitch_radii
            if radii is None and gp.teeth is not None:
                radii = (module * gp.teeth[0] / 2, module * gp.teeth[1] / 2)
                relative.add(i)
            ra, rb = (float(radii[0]), float(radii[1])) if radii is not None else (None, None)
            self.ratios.append(self._ratio(gp) if radii is None else None)
            self.working.append(_working_factor(gp))
            ring_a = ring_b = False
            if gp.kind == "internal":
                ring_a = self._first_is_ring(gp, ga, gb, ra, rb)
                ring_b = not ring_a
            bevel = gp.kind == "bevel"
            ia = self._gear(by_key, a, gp.carrier, ga, ring_a, bevel, ra)
            ib = self._gear(by_key, b, gp.carrier, gb, ring_b, bevel, rb)
            self.gears[ia].meshes.append((i, ib))
            self.gears[ib].meshes.append((i, ia))
            self.pair_gears.append((ia, ib))
        self._enlarge(relative)

    def _enlarge(self, relative):
        """Teeth fix sizes within a set of gears in mesh (one module), not between sets that share
        no gear off the main axis: such a set, sized by teeth alone and drawn under 40 % of the
        largest gear, is drawn larger (a car differential's spider beside its crown wheel)."""
        parent = list(range(len(self.gears)))

        def find(i):
            while parent[i] != i:
                parent[i] = parent[parent[i]]
                i = parent[i]
            return i

        for ia, ib in self.pair_gears:
            parent[find(ia)] = find(ib)
        first: dict = {}
        for g in self.gears:   # a link off the main axis (a compound planet, a layshaft) ties its sets
            if g.group != self.root:
                parent[find(g.index)] = find(first.setdefault((g.link, self.turn[g.link]), g.index))
        sets: dict = {}
        for g in self.gears:
            sets.setdefault(find(g.index), []).append(g)
        sized = [g.radius for g in self.gears if g.radius is not None]
        if not sized or len(sets) < 2:
            return
        top = max(sized)
        for gs in sets.values():
            pairs = {i for g in gs for i, _ in g.meshes}
            radii = [g.radius for g in gs if g.radius is not None]
            if pairs <= relative and radii and max(radii) < 0.4 * top:
                k = 0.4 * top / max(radii)
                for g in gs:
                    g.radius *= k

    def _gear_groups(self, gp):
        a, b = gp.gears
        m = self.groups.membership
        for c, la, lb in self.groups.carrier_candidates(a, b):
            if c == gp.carrier:
                return m[a][la], m[b][lb]
        raise GeometryError(f"gear pair {gp.label}: no axes found for its gears on carrier {gp.carrier}")  # pragma: no cover

    @staticmethod
    def _ratio(gp):
        e = gp.e
        if e.free_symbols or not e.is_real:
            return None
        return abs(1 / float(e))

    def _first_is_ring(self, gp, ga, gb, ra, rb) -> bool:
        if ra is not None and not _close(ra, rb):
            return ra > rb
        if gp.teeth is not None and gp.teeth[0] != gp.teeth[1]:
            return gp.teeth[0] > gp.teeth[1]
        if gp.e.free_symbols == set() and gp.e.is_real and abs(float(gp.e)) != 1:
            return abs(float(gp.e)) < 1   # e = N_a / N_b: the ring has more teeth
        return self.axes[ga].depth <= self.axes[gb].depth

    def _gear(self, by_key, link, carrier, group, ring, bevel, radius) -> int:
        key = (link, carrier, group, ring, bevel)
        found = by_key.setdefault(key, [])
        if radius is not None:
            for i in found:
                if self.gears[i].radius is not None and _close(self.gears[i].radius, radius):
                    return i
            for i in found:
                if self.gears[i].radius is None:
                    self.gears[i].radius, self.gears[i].known = radius, True
                    return i
        elif found:
            return found[0]
        gear = Gear(len(self.gears), link, carrier, group, ring, bevel, radius, radius is not None)
        self.gears.append(gear)
        found.append(gear.index)
        return gear.index

    # ------------------------------------------------------------------ sizes and axis places
    def _sizes(self):
        known = [g.radius for g in self.gears if g.radius is not None]
        self.nominal = median(known) if known else 10.0
        self._done = {self.root}
        self._ref: dict = {}        # gear -> its reference pitch radius, where drawn at a working one
        self._fixed: set = set()    # gears whose drawn size a placed mesh already uses
        for gid in self.axes:
            a = self.axes[gid]
            if a.parent is None:
                continue
            parent = self.axes[a.parent_group]
            if parent.inclined:
                raise GeometryError(
                    f"axis {a.label!r} (links {', '.join(map(str, a.links))}) is held by link {a.parent}, which turns "
                    f"about the inclined axis {parent.label!r}: its direction leaves the plane of the other axes "
                    "(a spatial train), which a sketch in one plane cannot show; draw_graph shows its structure")
            meshes = self._meshes_to(a)
            bevel = [m for m in meshes if self.mech.gear_pairs[m[0]].kind == "bevel"]
            if bevel and len(bevel) < len(meshes):
                i = next(m[0] for m in meshes if self.mech.gear_pairs[m[0]].kind != "bevel")
                raise GeometryError(
                    f"the gears on axis {a.label!r} mesh by bevel pairs and by the spur pair "
                    f"{self.mech.gear_pairs[i].label}: a spur pair needs parallel axes, a bevel pair intersecting ones")
            if bevel:
                self._incline(a, bevel)
            else:
                self._place_parallel(a, meshes)
        for g in self.gears:
            if g.radius is None:
                g.radius = self.nominal

    def _meshes_to(self, a: Axis) -> list:
        """``(pair, gear on a, gear on a placed axis)`` for the meshes that place axis *a*: those
        with its parent axis first, then those with axes placed before it (held by the same link)."""
        out, later = [], []
        for i, (ia, ib) in enumerate(self.pair_gears):
            if self.mech.gear_pairs[i].carrier != a.parent:
                continue
            for mine, other in ((ia, ib), (ib, ia)):
                og = self.gears[other].group
                if self.gears[mine].group != a.group or og == a.group:
                    continue
                if og == a.parent_group:
                    out.append((i, mine, other))
                elif og in self._done:
                    later.append((i, mine, other))
        return out + later

    def _distance(self, i, mine, other):
        """The (working) centre distance of pair *i* from the gears' reference radii, or None."""
        g, o = self.gears[mine], self.gears[other]
        if g.radius is None or o.radius is None:
            return None
        rg, ro = self._ref.get(g.index, g.radius), self._ref.get(o.index, o.radius)
        return self.working[i] * (abs(rg - ro) if (g.ring or o.ring) else rg + ro)

    def _close_mesh(self, mesh, d):
        """Draw the gears of *mesh*, which the data make run at the centre distance *d* (a
        profile-shifted pair at its working one), so that their blocks touch: at their working
        pitch radii, or, where a gear's drawn size is already fixed by another mesh, the other one
        sized to close *d* (a ring outside, a sun or planet inside)."""
        i, mine, other = mesh
        g, o = self.gears[mine], self.gears[other]
        k = self.working[i]
        if g.index not in self._fixed and o.index not in self._fixed:
            for gear in (g, o):
                self._ref.setdefault(gear.index, gear.radius)
                gear.radius = self._ref[gear.index] * k
        elif g.index not in self._fixed or o.index not in self._fixed:
            have, need = (g, o) if g.index in self._fixed else (o, g)
            self._ref.setdefault(need.index, need.radius)
            need.radius = have.radius + d if need.ring else (have.radius - d if have.ring else d - have.radius)
        self._fixed |= {g.index, o.index}

    def _drawn(self, mesh) -> float:
        g, o = self.gears[mesh[1]], self.gears[mesh[2]]
        return abs(g.radius - o.radius) if (g.ring or o.ring) else g.radius + o.radius

    def _place_parallel(self, a: Axis, meshes):
        parent = self.axes[a.parent_group]
        if not meshes:
            ref, d = parent, 2 * self.nominal
        else:
            known = [k for k, m in enumerate(meshes) if self._distance(*m) is not None]
            first = meshes[known[0]] if known else meshes[0]
            if not known:
                self._assume(first)
            d = self._distance(*first)
            ref = self.axes[self.gears[first[2]].group]
        a.offset = ref.offset + math.copysign(d, ref.offset or 1.0)
        self._done.add(a.group)
        for m in meshes:
            q = self.axes[self.gears[m[2]].group]
            want = abs(a.offset - q.offset) if q.group in (ref.group, parent.group) else None
            dm = self._distance(*m)
            label = self.mech.gear_pairs[m[0]].label
            if dm is not None and want is not None and abs(dm - want) <= self._slack(m):
                self._close_mesh(m, want)   # (a profile-shifted pair: at its working centre distance)
                continue
            if dm is None:
                if want is None:
                    self._assume(m)
                else:
                    self._fill(m, want)
            elif want is not None and not _close(dm, want):
                self.notes.append(f"gear pair {label}: its pitch radii give the centre distance {dm:g}, drawn at "
                                  f"{want:g} (the distance its other meshes give)")
            elif want is None:
                ra, rq = abs(a.offset - parent.offset), abs(q.offset - parent.offset)
                if not abs(ra - rq) - 1e-9 <= dm <= ra + rq + 1e-9:
                    self.notes.append(f"gear pair {label}: no angle around axis {parent.label!r} gives its centre "
                                      f"distance {dm:g}")

    def _slack(self, mesh) -> float:
        """How far a pair's centre distance may differ from the one drawn and still close: for a
        profile-shifted pair the tolerance of the assembly conditions (10**-3 module), else a
        rounding error."""
        gp = self.mech.gear_pairs[mesh[0]]
        d = self._distance(*mesh)
        if gp.profile_shift is None:
            return 1e-9 * max(d, 1.0)
        z1, z2 = gp.teeth
        modules = (abs(z1 - z2) if gp.kind == "internal" else z1 + z2) / 2
        return TOLERANCE * d / self.working[mesh[0]] / modules if modules else 1e-9 * max(d, 1.0)

    def _assume(self, mesh):
        """Radii for the unknown gears of *mesh*: from its ratio where it gives one, else nominal."""
        i, mine, other = mesh
        g, o = self.gears[mine], self.gears[other]
        first = self.gears[self.pair_gears[i][0]]
        rho = self.ratios[i]  # r_b / r_a
        for gear in (g, o):
            if gear.radius is not None:
                continue
            partner = o if gear is g else g
            if partner.radius is not None and rho is not None:
                gear.radius = partner.radius / rho if gear is first else partner.radius * rho
            elif partner.radius is not None and (gear.ring or partner.ring):
                gear.radius = partner.radius * (3 if gear.ring else 1 / 3)
            else:
                gear.radius = self.nominal * (3 if gear.ring else 1)
        if (g.ring or o.ring) and _close(g.radius, o.radius):
            ring = g if g.ring else o
            ring.radius *= 3

    def _fill(self, mesh, d):
        """Give the unknown gears of *mesh* the radii that make its centre distance *d*."""
        i, mine, other = mesh
        g, o = self.gears[mine], self.gears[other]
        rho = self.ratios[i]  # r_b / r_a
        first = self.gears[self.pair_gears[i][0]]
        if g.ring or o.ring:
            ring, planet = (g, o) if g.ring else (o, g)
            if ring.radius is not None:
                planet.radius = ring.radius - d if ring.radius > d else ring.radius / 3
            elif planet.radius is not None:
                ring.radius = planet.radius + d
            else:
                k = None if rho is None else (rho if ring is not first else 1 / rho)  # ring / planet
                planet.radius = d / (k - 1) if k is not None and k > 1 else d / 2
                ring.radius = planet.radius + d
        elif g.radius is not None or o.radius is not None:
            have, need = (g, o) if g.radius is not None else (o, g)
            need.radius = d - have.radius if d > have.radius else d / 2
        else:
            r_first = d / (1 + rho) if rho is not None else d / 2
            first.radius = r_first
            (o if first is g else g).radius = d - r_first

    # ------------------------------------------------------------------ bevel (inclined) axes


def _working_factor(gp) -> float:
    """Working over reference centre distance of a profile-shifted spur or helical pair (1 for
    any other pair): cos(alpha) / cos(alpha_w), the factor that also scales its pitch radii."""
    if gp.profile_shift is None or gp.teeth is None or gp.kind == "bevel" or not any(gp.profile_shift):
        return 1.0
    z1, z2 = gp.teeth
    reference = abs(z1 - z2) if gp.kind == "internal" else z1 + z2
    if reference == 0:
        return 1.0
    radii = gp.pitch_radii
    m_t = 2 * float(radii[0]) / z1 if radii is not None else 1.0
    return centre_distance(gp) / (m_t * reference / 2)
