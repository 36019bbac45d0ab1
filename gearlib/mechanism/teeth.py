"""Tooth numbers as a designer changes them: one number per gear, planets that still fit.

The data give tooth numbers per gear *pair*, so a planet that meshes a sun and a ring appears
twice, once in each pair. Changing it in one pair only would give one planet two tooth
numbers; changing the ring alone would give a planet that no longer fits between sun and
ring. :func:`~gearlib.mechanism.gears` lists the gears of a mechanism, one entry per gear (a link that meshes
with the same tooth number in several pairs is one gear: a planet, an idler; a link with
different tooth numbers carries several gears: a stepped planet, a compound shaft).
:func:`~gearlib.mechanism.set_teeth` changes gears by their key and keeps every simple planetary set
concentric (see :mod:`gearlib.mechanism.assembly`): with one module for all gears,
``N_ring = N_sun + 2 N_planet``. Change the ring or the sun and the planet follows; change
the planet and the ring follows. The widgets of chapters 0 and 1 and their static twins use
it.

>>> import gearlib as gl
>>> m = gl.catalog.simple_planetary(sun=24, ring=60)
>>> [(g.key, g.teeth) for g in gl.mechanism.gears(m)]
[('N_1', 24), ('N_2', 18), ('N_3', 60)]
>>> bigger = gl.mechanism.set_teeth(m, {"N_3": 72})   # the planet follows: (72 - 24)/2
>>> [g.teeth for g in gl.mechanism.gears(bigger)]
[24, 24, 72]
>>> [g.teeth for g in gl.mechanism.gears(gl.mechanism.set_teeth(m, {"N_2": 20}))]  # the ring follows
[24, 20, 64]
"""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import DataFormatError, ToothNumberError
from .assembly import planetary_sets
from .data import Mechanism

__all__ = ["Gear", "gears", "set_teeth", "followers"]


@dataclass(frozen=True)
class Gear:
    """One gear: the link it is keyed to, its tooth number, the gear pairs it meshes in
    (their ``gears`` tuples) and its key, ``"N_<link>"`` when the link carries one gear, else
    ``"N_<link>_in_<a>_<b>"`` after its first pair."""

    link: object
    teeth: int
    pairs: tuple
    key: str


def gears(mech: Mechanism, pairs=None) -> tuple[Gear, ...]:
    """The gears of the gear pairs *pairs* (default: every pair with teeth), in the order of the
    links. A link meshing with one tooth number in several pairs is one gear."""
    chosen = mech.gear_pairs if pairs is None else [mech.gear_pair(*p)[0] for p in pairs]
    by_link: dict = {}
    for gp in mech.gear_pairs:  # every pair, so that a key says whether its link has other gears
        if gp.teeth is None:
            continue
        for g, t in zip(gp.gears, gp.teeth):
            by_link.setdefault(g, {}).setdefault(int(t), []).append(gp.gears)
    wanted = {(g, int(t)) for gp in chosen if gp.teeth is not None for g, t in zip(gp.gears, gp.teeth)}
    out = []
    for link in mech.link_ids:
        numbers = by_link.get(link, {})
        for t, meshes in numbers.items():
            if (link, t) not in wanted:
                continue
            key = f"N_{link}" if len(numbers) == 1 else f"N_{link}_in_{meshes[0][0]}_{meshes[0][1]}"
            out.append(Gear(link, t, tuple(meshes), key))
    return tuple(out)


def _simple_sets(mech: Mechanism) -> list:
    """``(sun, planet, ring)`` gears of every simple set with one internal mesh, no profile shift
    and concentric as given (a set that does not fit is left as it is)."""
    out = []
    for s in planetary_sets(mech):
        gp1, gp2 = s.pairs
        if s.kind != "simple" or (gp1.kind == "internal") == (gp2.kind == "internal"):
            continue
        if gp1.profile_shift is not None or gp2.profile_shift is not None:
            continue
        p = s.planets[0]
        (ring, ring_gp), (sun, sun_gp) = sorted(zip(s.centrals, s.pairs), key=lambda x: x[1].kind != "internal")
        zs = sun_gp.teeth[sun_gp.gears.index(sun)]
        zp = sun_gp.teeth[sun_gp.gears.index(p)]
        zr = ring_gp.teeth[ring_gp.gears.index(ring)]
        if zr == zs + 2 * zp:
            out.append(((sun, zs), (p, zp), (ring, zr)))
    return out


def followers(mech: Mechanism, pairs=None) -> dict:
    """``{key of a ring: (key of its sun, key of its planet)}`` for every simple planetary set
    among the gears of *pairs*: the ring that :func:`set_teeth` makes follow when the sun or the
    planet changes (so a widget shows no slider for it)."""
    keys = {(g.link, g.teeth): g.key for g in gears(mech, pairs)}
    out = {}
    for sun, planet, ring in _simple_sets(mech):
        if sun in keys and planet in keys and ring in keys:
            out[keys[ring]] = (keys[sun], keys[planet])
    return out


def set_teeth(mech: Mechanism, teeth: dict) -> Mechanism:
    """A copy of *mech* with the gears named by the keys of *teeth* (see :func:`gears`) given
    new tooth numbers in every pair they mesh in, each simple planetary set kept concentric:
    when its sun or ring changes the planet follows, when its planet changes the ring follows.
    A ring and sun that leave no whole planet raise :class:`~gearlib.ToothNumberError`."""
    every = {g.key: g for g in gears(mech)}
    unknown = [k for k in teeth if k not in every]
    if unknown:
        raise DataFormatError(f"set_teeth: no gear {unknown[0]!r} in {mech.name or 'the mechanism'}; its gears are "
                              f"{', '.join(every)}")
    new = {(every[k].link, every[k].teeth): int(v) for k, v in teeth.items()}
    for v in new.values():
        if v < 1:
            raise ToothNumberError(f"set_teeth: a gear needs at least one tooth, got {v}")
    for sun, planet, ring in _simple_sets(mech):
        if not {sun, planet, ring} & set(new):
            continue
        zs, zp, zr = (new.get(g, g[1]) for g in (sun, planet, ring))
        if planet in new and ring not in new:
            new[ring] = zs + 2 * zp
        elif planet not in new:
            if (zr - zs) % 2 or zr <= zs:
                raise ToothNumberError(
                    f"set_teeth: ring {ring[0]} with {zr} teeth and sun {sun[0]} with {zs} leave no whole planet "
                    f"(N_ring - N_sun = {zr - zs} must be even and positive, N_planet = (N_ring - N_sun)/2); "
                    "change the ring by two teeth at a time")
            new[planet] = (zr - zs) // 2
        elif zr != zs + 2 * zp:
            raise ToothNumberError(
                f"set_teeth: sun {zs}, planet {zp} and ring {zr} teeth: the planet does not fit "
                f"(N_ring = N_sun + 2 N_planet = {zs + 2 * zp}); give two of the three")
    for gp in mech.gear_pairs:
        if gp.teeth is None:
            continue
        changed = tuple(new.get((g, int(t)), int(t)) for g, t in zip(gp.gears, gp.teeth))
        if changed != tuple(int(t) for t in gp.teeth):
            mech = mech.with_gear_pair(gp.gears, teeth=changed)
    return mech
