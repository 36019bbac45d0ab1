"""Assembly conditions of the planetary sets of a mechanism: can the planets be built in?

The kinematics never looks at whether a planetary set can be put together: the ratios follow
from the tooth numbers alone. A designer must check three things for every set (the sets are
found from the graph: a planet on a carrier meshing two central gears coaxial with that carrier,
or two meshing planets each meshing one central gear):

* **concentricity**: the centre distances of a planet's meshes must be equal. For a simple set
  of sun ``s``, planet ``p`` and ring ``r`` with one module this is ``Z_r - Z_s - 2 Z_p = 0``;
  profile shift can offset a small difference (give the pairs' ``profile_shift``: the working
  centre distances are then compared); for two meshing planets (a double-planet set) the
  three centre distances must close a triangle;
* **equal spacing** of ``N`` planets (``planets:`` in the file): ``N`` must divide
  ``Z_1 - s Z_2``, where ``s`` is the sign of the gear ratio from one central gear to the other
  with the carrier held: ``(Z_s + Z_r) / N`` for a simple set, ``(Z_r - Z_s) / N`` for a
  double-planet set;
* **neighbour clearance**: the tips of neighbouring planets must not touch,
  ``2 a sin(pi / N) > d_a`` for planets of tip diameter ``d_a`` at centre distance ``a``.

Lengths are in the unit of the modules (or pitch radii) when every pair of a set gives them,
otherwise in modules (one module for the set). Tip diameters use the standard addendum, one (normal) module plus the
profile shift. These are reported, not enforced: :func:`~gearlib.assembly_conditions` lists them,
:func:`~gearlib.mechanism.check_assembly` issues a :class:`gearlib.AssemblyWarning` for each one that fails, and
:func:`gearlib.load` and :func:`gearlib.shift_table` call it.

>>> import gearlib as gl
>>> m = gl.catalog.simple_planetary(sun=30, ring=66, planet=24)
>>> [c.condition for c in gl.assembly_conditions(m) if not c.ok]
['concentricity']
>>> print(gl.assembly_conditions(m)[0].message)
sun 1, planet 2, ring 3 on carrier 4: Z_r - Z_s - 2 Z_p = 66 - 30 - 2*24 = -12: the centre distances differ (27 and 21 modules); the planet does not fit, unless profile shift offsets a small difference (give the pairs' profile_shift)
"""

from __future__ import annotations

import math
import warnings
from collections import Counter
from dataclasses import dataclass

from ..errors import AssemblyWarning, InputError
from .data import requires_mechanism

__all__ = ["PlanetarySet", "AssemblyCondition", "planetary_sets", "assembly_conditions", "check_assembly",
           "with_concentric_teeth"]

TOLERANCE = 1e-3
"""Centre distances that agree to this fraction of a module count as equal."""


@dataclass(frozen=True)
class PlanetarySet:
    """A planetary set found in a mechanism: central gears coaxial with a carrier, joined through
    one planet (``kind`` ``"simple"``; ``"stepped"`` when the planet's two meshes use different
    tooth numbers) or through two meshing planets (``"double"``). ``pairs`` are the gear pairs
    along the chain from the first central gear to the second; ``count`` the number of planets."""

    carrier: object
    centrals: tuple
    planets: tuple
    pairs: tuple
    kind: str
    count: int

    @property
    def label(self) -> str:
        names = []
        for g, gp in ((self.centrals[0], self.pairs[0]), (self.centrals[1], self.pairs[-1])):
            names.append(f"{'ring' if gp.kind == 'internal' and _teeth(gp, g) > _other_teeth(gp, g) else 'sun'} {g}")
        pl = ", ".join(f"planet {p}" for p in self.planets)
        return f"{names[0]}, {pl}, {names[1]} on carrier {self.carrier}"


@dataclass(frozen=True)
class AssemblyCondition:
    """One assembly condition of one set: its name, whether it holds, the number behind it and
    a one-line explanation."""

    set: PlanetarySet
    condition: str
    ok: bool
    value: float
    message: str

    def __str__(self) -> str:
        return f"{'ok  ' if self.ok else 'FAIL'} {self.condition}: {self.message}"


def _teeth(gp, gear) -> int:
    return gp.teeth[gp.gears.index(gear)]


def _other_teeth(gp, gear) -> int:
    return gp.teeth[1 - gp.gears.index(gear)]


def _shift(gp, gear) -> float:
    return 0.0 if gp.profile_shift is None else gp.profile_shift[gp.gears.index(gear)]


@requires_mechanism
def planetary_sets(mech) -> tuple:
    """Every planetary set of *mech* (see the module documentation); bevel pairs and pairs given
    by a ratio without teeth are left out.

    On each carrier, an axis shared by two or more gears is a central axis; a gear alone on its
    axis is a planet. A planet meshing two gears of one central axis makes a simple (or stepped)
    set; two meshing planets, each meshing a gear of the same central axis, a double-planet set."""
    by_carrier: dict = {}
    for gp in mech.gear_pairs:
        if gp.kind != "bevel" and gp.teeth is not None:
            by_carrier.setdefault(gp.carrier, []).append(gp)
    found = []
    for c, pairs in by_carrier.items():
        coaxial = mech._groups.coaxial_label  # ids are the mechanism's own: no need to resolve them
        label = {g: coaxial(g, c) for gp in pairs for g in gp.gears}
        counts = Counter(label.values())
        shared = {lab for lab, n in counts.items() if n > 1}
        meshes: dict = {}
        for gp in pairs:
            a, b = gp.gears
            meshes.setdefault(a, []).append((b, gp))
            meshes.setdefault(b, []).append((a, gp))
        planets = {g: None for g in meshes if label[g] not in shared}  # ordered, and fast to test
        for p in planets:
            cs = [(g, gp) for g, gp in meshes[p] if label[g] in shared]
            for i, (g1, gp1) in enumerate(cs):
                for g2, gp2 in cs[i + 1:]:
                    if label[g1] == label[g2]:
                        kind = "simple" if _teeth(gp1, p) == _teeth(gp2, p) else "stepped"
                        found.append(PlanetarySet(c, (g1, g2), (p,), (gp1, gp2), kind, mech.planet_count(p)))
        for gp in pairs:
            p1, p2 = gp.gears
            if p1 not in planets or p2 not in planets:
                continue
            for g1, gp1 in meshes[p1]:
                for g2, gp2 in meshes[p2]:
                    if label[g1] in shared and label[g1] == label[g2] and g1 != g2:
                        found.append(PlanetarySet(c, (g1, g2), (p1, p2), (gp1, gp, gp2), "double",
                                                  mech.planet_count(p1)))
    return tuple(found)


# ----------------------------------------------------------------------------- geometry
def _inv(a: float) -> float:
    return math.tan(a) - a


def _inv_inverse(v: float) -> float:
    a = (3 * v) ** (1 / 3) if v > 0 else 1e-6
    for _ in range(60):
        step = (_inv(a) - v) / math.tan(a) ** 2
        a -= step
        if abs(step) < 1e-15:
            break
    return a


def _angles(gp) -> tuple[float, float]:
    """``(normal, transverse)`` pressure angles of a pair."""
    alpha = math.radians(20) if gp.pressure_angle is None else float(gp.pressure_angle)
    beta = 0.0 if gp.helix_angle is None else float(gp.helix_angle)
    return alpha, math.atan(math.tan(alpha) / math.cos(beta))


def _modules(gp) -> tuple[float, float]:
    """``(transverse, normal)`` module of a pair: from its module, or from its pitch radii, or 1."""
    radii = gp.pitch_radii
    m_t = 2 * radii[0] / gp.teeth[0] if radii is not None else 1.0
    if gp.normal_module is not None:
        return m_t, gp.normal_module
    beta = 0.0 if gp.helix_angle is None else float(gp.helix_angle)
    return m_t, m_t * math.cos(beta)


def centre_distance(gp) -> float:
    """The (working) centre distance of a spur or helical pair, with its profile shift: the sum
    of the pitch radii for an external pair, their difference for an internal one (in the unit of
    the module or the radii; in modules when the pair gives neither)."""
    m_t, _ = _modules(gp)
    z1, z2 = sorted(gp.teeth)
    internal = gp.kind == "internal"
    a0 = m_t * ((z2 - z1) if internal else (z1 + z2)) / 2
    if gp.profile_shift is None:
        return a0
    small = gp.gears[gp.teeth.index(z1)] if z1 != z2 else gp.gears[0]
    big = gp.gears[1 - gp.gears.index(small)]
    x1, x2 = _shift(gp, small), _shift(gp, big)
    if x1 == x2 == 0:
        return a0
    alpha_n, alpha_t = _angles(gp)
    xs, zs = ((x2 - x1), (z2 - z1)) if internal else ((x1 + x2), (z1 + z2))
    inv_w = _inv(alpha_t) + 2 * math.tan(alpha_n) * xs / zs
    alpha_w = _inv_inverse(inv_w)
    return a0 * math.cos(alpha_t) / math.cos(alpha_w)


def _tip_radius(gp, gear) -> float:
    m_t, m_n = _modules(gp)
    return m_t * _teeth(gp, gear) / 2 + m_n * (1 + _shift(gp, gear))


def _fmt(x: float) -> str:
    return f"{x:.6g}"


# ----------------------------------------------------------------------------- conditions
@requires_mechanism
def assembly_conditions(mech) -> tuple:
    """Every assembly condition of every planetary set of *mech* (:class:`AssemblyCondition`):
    concentricity (or the pinion triangle of a double-planet set), and, with more than one
    planet, equal spacing and neighbour clearance."""
    out, seen = [], set()
    for s in planetary_sets(mech):
        unit = all(gp.pitch_radii is not None for gp in s.pairs)
        u = "" if unit else " modules"
        if s.kind in ("simple", "stepped"):
            out.append(_concentric(s, u))
        else:
            out.append(_triangle(s, u))
        if s.count > 1:
            out.append(_spacing(s, mech))
            for c, key in _clearance(s, u):
                if (s.carrier, key) not in seen:  # planets shared by two sets are checked once
                    seen.add((s.carrier, key))
                    out.append(c)
    return tuple(out)


def _concentric(s, u) -> AssemblyCondition:
    (g1, g2), p = s.centrals, s.planets[0]
    gp1, gp2 = s.pairs
    a1, a2 = centre_distance(gp1), centre_distance(gp2)
    ok = abs(a1 - a2) <= TOLERANCE * _modules(gp1)[0]
    shifted = gp1.profile_shift is not None or gp2.profile_shift is not None
    z1, z2, zp = _teeth(gp1, g1), _teeth(gp2, g2), _teeth(gp1, p)
    ring = [g for g, gp in ((g1, gp1), (g2, gp2)) if gp.kind == "internal"]
    if s.kind == "simple" and len(ring) == 1 and not shifted:
        zr, zs = (z2, z1) if ring[0] == g2 else (z1, z2)
        value = zr - zs - 2 * zp
        text = f"Z_r - Z_s - 2 Z_p = {zr} - {zs} - 2*{zp} = {value}"
    else:
        value = a1 - a2
        text = f"centre distances {_fmt(a1)} and {_fmt(a2)}{u}" + (" (working, with profile shift)" if shifted else "")
    if ok:
        message = f"{s.label}: {text}: the planet fits"
    elif shifted:
        message = (f"{s.label}: {text} differ by {_fmt(abs(a1 - a2))}{u}: the profile shifts given do not make "
                   "the planet fit; adjust them")
    else:
        message = (f"{s.label}: {text}: the centre distances differ ({_fmt(a1)} and {_fmt(a2)}{u}); the planet "
                   "does not fit, unless profile shift offsets a small difference (give the pairs' profile_shift)")
    return AssemblyCondition(s, "concentricity", ok, value, message)


def _triangle_sides(s):
    gp1, gp12, gp2 = s.pairs
    return centre_distance(gp1), centre_distance(gp2), centre_distance(gp12)


def _triangle(s, u) -> AssemblyCondition:
    a1, a2, d = _triangle_sides(s)
    ok = abs(a1 - a2) < d < a1 + a2
    value = d - abs(a1 - a2) if d <= a1 + a2 else a1 + a2 - d
    text = (f"centre distances {_fmt(a1)}, {_fmt(a2)} and {_fmt(d)}{u} (planet {s.planets[0]}, planet "
            f"{s.planets[1]} and between the planets)")
    message = f"{s.label}: {text}: " + ("the planets can be placed" if ok else
                                        "they cannot close a triangle, so the two planets cannot both mesh")
    return AssemblyCondition(s, "pinion geometry", ok, value, message)


def _spacing(s, mech) -> AssemblyCondition:
    n = s.count
    counts = {mech.planet_count(p) for p in s.planets}
    if len(counts) > 1:
        return AssemblyCondition(s, "equal spacing", False, 0,
                                 f"{s.label}: the planets are counted differently ({sorted(counts)}); "
                                 "give each the same count in `planets`")
    if s.kind == "stepped":
        return AssemblyCondition(s, "equal spacing", True, 0,
                                 f"{s.label}: not checked for a stepped planet (it depends on how the two steps "
                                 "are indexed to each other)")
    g1, g2 = s.centrals
    sign = 1
    for gp in s.pairs:
        sign *= 1 if gp.kind == "internal" else -1
    z1, z2 = _teeth(s.pairs[0], g1), _teeth(s.pairs[-1], g2)
    total = abs(z1 - sign * z2)
    text = f"{z1} + {z2} = {total}" if sign < 0 else f"|{z1} - {z2}| = {total}"
    ok = total % n == 0
    message = (f"{s.label}: ({text}) / {n} planets = {_fmt(total / n)}: "
               + ("equally spaced planets mesh" if ok else f"not a whole number, so {n} equally spaced planets "
                  "cannot all mesh; change the teeth or the number of planets"))
    return AssemblyCondition(s, "equal spacing", ok, total / n, message)


def _clearance(s, u) -> list:
    n = s.count
    chord = 2 * math.sin(math.pi / n)
    out = []
    if s.kind in ("simple", "stepped"):
        p = s.planets[0]
        a = centre_distance(s.pairs[0])
        tip = max(_tip_radius(gp, p) for gp in s.pairs)
        checks = [(f"planets {p}", a * chord, 2 * tip, (p,))]
    else:
        (p1, p2), (gp1, gp12, gp2) = s.planets, s.pairs
        a1, a2, d = _triangle_sides(s)
        t1 = max(_tip_radius(gp1, p1), _tip_radius(gp12, p1))
        t2 = max(_tip_radius(gp2, p2), _tip_radius(gp12, p2))
        checks = [(f"planets {p1}", a1 * chord, 2 * t1, (p1,)), (f"planets {p2}", a2 * chord, 2 * t2, (p2,))]
        cos_phi = (a1 * a1 + a2 * a2 - d * d) / (2 * a1 * a2)
        if abs(cos_phi) <= 1:
            phi = math.acos(cos_phi)
            gap = min(math.sqrt(a1 * a1 + a2 * a2 - 2 * a1 * a2 * math.cos(phi + k * 2 * math.pi / n))
                      for k in (-1, 1))
            checks.append((f"planet {p1} and the next {p2}", gap, t1 + t2, (p1, p2)))
    for what, distance, needed, key in checks:
        ok = distance > needed
        message = (f"{s.label}: neighbouring {what}: centres {_fmt(distance)} apart, tips need {_fmt(needed)}{u}: "
                   + ("they clear" if ok else f"the tips of {n} planets collide; use fewer or smaller planets"))
        out.append((AssemblyCondition(s, "neighbour clearance", ok, distance - needed, message), key))
    return out


def check_assembly(mech, *, where: str | None = None, stacklevel: int = 2) -> tuple:
    """Issue an :class:`gearlib.AssemblyWarning` for every assembly condition of *mech* that fails
    (the message starts with *where*, a file name, or the mechanism's name); return the failing
    conditions."""
    failed = tuple(c for c in assembly_conditions(mech) if not c.ok)
    head = where if where is not None else repr(mech.name)
    for c in failed:
        warnings.warn(f"{head}: planetary set {c.message}", AssemblyWarning, stacklevel=stacklevel + 1)
    return failed


def with_concentric_teeth(mech, teeth: dict, *, min_planet_teeth: int = 1):
    """*mech* with new tooth numbers for central gears (suns and rings), each planet of a simple
    set on them resized so that the set stays concentric: ``Z_p = (Z_r - Z_s) / 2``.

    *teeth* maps a central gear to its number of teeth. A gear that is not a central gear of a
    simple set, a ring and a sun whose tooth numbers differ by an odd number (the planet would
    need half a tooth), a planet left with fewer than *min_planet_teeth*, or a planet shared by two sets
    that ask for different sizes raises :class:`~gearlib.InputError`. Equal spacing and tip
    clearance are not enforced: :func:`~gearlib.assembly_conditions` reports them.

    >>> import gearlib as gl
    >>> m = gl.with_concentric_teeth(gl.catalog.simple_planetary(sun=24, ring=60), {3: 72})
    >>> [gp.teeth for gp in m.gear_pairs]
    [(24, 24), (24, 72)]
    """
    sets = [s for s in planetary_sets(mech) if s.kind == "simple"]
    centrals = {g for s in sets for g in s.centrals}
    new = {}
    for gear, z in teeth.items():
        g = mech.resolve(gear)
        if g not in centrals:
            raise InputError(f"gear {g} is not the sun or the ring of a simple planetary set of {mech.name!r}; "
                             f"give the teeth of one of {', '.join(map(str, sorted(centrals, key=str)))} "
                             "(a planet follows its sun and ring)")
        if isinstance(z, bool) or int(z) != z or z < 1:
            raise InputError(f"gear {g}: a number of teeth is a positive whole number, got {z!r}")
        new[g] = int(z)
    planets: dict = {}
    for s in sets:
        if not new.keys() & set(s.centrals):
            continue
        (g1, g2), p = s.centrals, s.planets[0]
        kinds = {g: gp.kind for g, gp in zip((g1, g2), s.pairs)}
        if sorted(kinds.values()) != ["external", "internal"]:
            continue   # not a sun, a planet and a ring
        ring = g1 if kinds[g1] == "internal" else g2
        sun = g2 if ring == g1 else g1
        z_ring = new.get(ring, _teeth(s.pairs[(g1, g2).index(ring)], ring))
        z_sun = new.get(sun, _teeth(s.pairs[(g1, g2).index(sun)], sun))
        if (z_ring - z_sun) % 2:
            raise InputError(f"ring {ring} ({z_ring} teeth) and sun {sun} ({z_sun} teeth) differ by an odd number: "
                             f"planet {p} would need {(z_ring - z_sun) / 2} teeth; change one of them by one tooth")
        z_p = (z_ring - z_sun) // 2
        if z_p < max(1, min_planet_teeth):
            raise InputError(f"ring {ring} ({z_ring} teeth) around sun {sun} ({z_sun} teeth) leaves planet {p} "
                             f"{max(z_p, 0)} teeth, fewer than {max(1, min_planet_teeth)}: give the ring more teeth "
                             "or the sun fewer")
        if planets.get(p, z_p) != z_p:
            raise InputError(f"planet {p} would need {planets[p]} teeth in one set and {z_p} in another; "
                             "change the teeth of its central gears together")
        planets[p] = z_p
    sizes = {**new, **planets}
    out = mech
    for gp in mech.gear_pairs:
        if gp.teeth is None or not sizes.keys() & set(gp.gears):
            continue
        changed = tuple(sizes.get(g, z) for g, z in zip(gp.gears, gp.teeth))
        if changed != gp.teeth:
            out = out.with_gear_pair(gp.gears, teeth=changed)
    return out
