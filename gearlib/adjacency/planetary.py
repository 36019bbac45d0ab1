"""Planetary sets found from the graph, and the tooth numbers' common factors.

A **planetary set** is a carrier with the gears it holds: *planets* on axes of their own
and *central gears* (suns, rings, the side gears of a differential) on the carrier's own
axis. The central axis is the carrier's axis shared with a link that is not one of its
gears (the housing, a shaft), or with the ground; failing that, the axis that holds most
of its gears. A planet link may stand for ``N`` identical, equally spaced planets
(``planets: {2: 3}`` in the mechanism, ``Mechanism.planet_count``); separate
planet links on one carrier (the differential's two planets) are taken as equally spaced
too. A carrier that does not turn relative to the ground and holds a single copy of each
gear is an ordinary train on fixed axes, not a planetary set.

Per relative turn (relative to the carrier) a tooth of a central gear meets every planet
that meshes with it, and a planet tooth meets each gear it meshes with (the sun on one
flank, the ring on the other): ``PlanetarySet.contacts``.

Two tooth numbers ``Z1, Z2`` with common factor ``n_a = gcd(Z1, Z2)`` mesh in ``n_a``
assembly phases: a tooth meets only every ``n_a``-th tooth of the other gear. The
assembly-phase frequency is ``f_m / n_a`` and the hunting-tooth frequency, at which one
pair of teeth meets again, ``f_m n_a / (Z1 Z2) = f_m / lcm(Z1, Z2)`` (``tooth_factors``).

>>> import gearlib as gl
>>> stage = gl.catalog.load("planetary_stage")
>>> [str(s) for s in gl.planetary_sets(stage)]
['carrier 3: 3 x planet 2 meshing sun 1 and ring 0 (planet pass: 3 planets)']
>>> gl.adjacency.tooth_factors(8, 42)
(2, 168)
"""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Mapping
from dataclasses import dataclass, field

from .._common.parse import shown
from ..errors import ConstraintError, DataFormatError
from ..mechanism.data import Mechanism
from ..mechanism._accept import takes_mechanism

__all__ = ["PlanetarySet", "planetary_sets", "tooth_factors"]


def tooth_factors(z1: int, z2: int) -> tuple[int, int]:
    """``(n_a, lcm)``: the number of assembly phases ``gcd(z1, z2)`` and ``lcm(z1, z2)``, the
    number of meshes after which the same two teeth meet again (``f_ht = f_m / lcm``)."""
    n_a = math.gcd(int(z1), int(z2))
    return n_a, int(z1) * int(z2) // n_a


@dataclass(frozen=True)
class PlanetarySet:
    """One carrier with its planets and central gears.

    Attributes
    ----------
    carrier : link id
    planets : tuple of (link, count)
        The planet links and how many equally spaced copies each stands for.
    central : tuple of link ids
        The central gears (coaxial with the carrier) that mesh with the planets.
    roles : tuple of (link, role)
        ``"sun"`` (external mesh), ``"ring"`` (internal mesh) or ``"central gear"`` (bevel).
    pairs : tuple of GearPair
        The gear pairs on this carrier.
    contacts : tuple of (link, int)
        Contacts of one tooth of the gear per turn relative to the carrier.
    passing : int
        How many planets pass a point fixed to a central gear (or to the housing) per
        relative turn of the carrier: the planet-pass multiple.
    notes : tuple of str
        Checks on the tooth numbers (equal spacing, phasing).
    """

    carrier: object
    planets: tuple
    central: tuple
    roles: tuple
    pairs: tuple = field(repr=False)
    contacts: tuple
    passing: int
    notes: tuple = ()

    def role(self, link) -> str:
        """``"sun"``, ``"ring"``, ``"central gear"`` or ``"planet"``."""
        return dict(self.roles).get(link, "planet" if link in dict(self.planets) else "")

    def contacts_of(self, link) -> int:
        return dict(self.contacts)[link]

    def teeth_of(self, link):
        """The tooth number of *link* in this set's meshes (the first mesh that names it)."""
        for gp in self.pairs:
            if gp.teeth is not None and link in gp.gears:
                return gp.teeth[gp.gears.index(link)]
        return None

    @property
    def ring(self):
        """The ring (the central gear of an internal mesh), or None."""
        return next((c for c, r in self.roles if r == "ring"), None)

    def __str__(self) -> str:
        planets = ", ".join(f"{n} x planet {p}" if n > 1 else f"planet {p}" for p, n in self.planets)
        central = " and ".join(f"{r} {c}" for c, r in self.roles)
        return f"carrier {self.carrier}: {planets} meshing {central} (planet pass: {self.passing} planets)"


def _axes_of(mech: Mechanism, k) -> dict:
    """``{label: set of links coaxial with k on it}``."""
    out: dict = defaultdict(set)
    for x in mech.link_ids:
        if x != k:
            label = mech.coaxial(x, k)
            if label is not None:
                out[label].add(x)
    return out


def _central_label(mech, k, pairs, gears, axes, ground):
    labels = {g: mech.axis_of(g, k) for g in gears}
    used = set(labels.values())
    if len(used) < 2:
        return None, labels
    shared = [lab for lab in used if any(x not in gears for x in axes[lab]) or ground in axes[lab]]
    if len(shared) == 1:
        return shared[0], labels
    counted = {labels[p] for p, n in mech.planets if p in gears and n > 1}
    pool = [lab for lab in (shared or used) if lab not in counted]
    if not pool:
        return None, labels
    rings = {labels[max(gp.gears, key=lambda g: gp.teeth[gp.gears.index(g)])] for gp in pairs
             if gp.kind == "internal" and gp.teeth is not None}
    size = {lab: sum(1 for g in gears if labels[g] == lab) for lab in pool}
    best = max(pool, key=lambda lab: (size[lab], lab in rings, -sorted(map(str, used)).index(str(lab))))
    return best, labels


@takes_mechanism
def planetary_sets(mech: Mechanism, speeds=None, ground=None) -> tuple[PlanetarySet, ...]:
    """Every planetary set of *mech*, found from its graph (see the module documentation).

    *speeds* (a ``{link: speed}`` mapping or a :class:`~gearlib.Solution`) and *ground*
    decide whether a carrier without planet counts turns; without them every carrier
    other than the ground (``mech.ground``) counts as turning.
    """
    ground = mech.ground if ground is None else mech.resolve(ground, "ground")
    if speeds is not None and hasattr(speeds, "constraints"):
        ground = speeds.constraints.ground
        speeds = dict(speeds.items())
    elif speeds is not None:
        if not isinstance(speeds, Mapping):
            raise DataFormatError(f"speeds: expected gl.speeds(...) or a mapping link -> speed, got {shown(speeds)}")
        speeds = {mech.resolve(k, "speeds"): v for k, v in speeds.items()}
        missing = [x for x in mech.link_ids if x not in speeds]
        if missing:
            raise DataFormatError(f"speeds: give the speed of every link; link {missing[0]} is missing")
    by_carrier: dict = defaultdict(list)
    for gp in mech.gear_pairs:
        by_carrier[gp.carrier].append(gp)
    out = []
    for k, pairs in by_carrier.items():
        gears = {g for gp in pairs for g in gp.gears}
        axes = _axes_of(mech, k)
        central_label, labels = _central_label(mech, k, pairs, gears, axes, ground)
        if central_label is None:
            continue
        planets = [g for g in mech.link_ids if g in gears and labels[g] != central_label]
        counts = {g: mech.planet_count(g) for g in gears}
        if speeds is not None:
            turning = complex(speeds[k]) != complex(speeds[ground]) if ground is not None else True
        else:
            turning = k != ground
        if not planets or not (turning or any(counts[p] > 1 for p in planets)):
            continue
        central, roles = [], []
        for g in sorted(mech.link_ids, key=lambda g: _role_rank(pairs, planets, g)):
            if g in gears and g not in planets:
                kinds = {gp.kind for gp in pairs if g in gp.gears and set(gp.gears) & set(planets)}
                if not kinds:
                    continue
                central.append(g)
                roles.append((g, "ring" if kinds == {"internal"} else "sun" if kinds == {"external"} else "central gear"))
        contacts = []
        for g in [*central, *planets]:
            total = 0
            for gp in pairs:
                if g not in gp.gears:
                    continue
                other = gp.gears[1 - gp.gears.index(g)]
                if counts[other] > counts[g]:
                    if counts[other] % counts[g]:
                        raise ConstraintError(
                            f"planets: link {g} stands for {counts[g]} copies and meshes with link {other}, which "
                            f"stands for {counts[other]}; meshing planet sets need matching counts")
                    total += counts[other] // counts[g]
                else:
                    total += 1
            contacts.append((g, total))
        passing = max((n for g, n in contacts if g in central), default=0)
        out.append(PlanetarySet(k, tuple((p, counts[p]) for p in planets), tuple(central), tuple(roles),
                                tuple(pairs), tuple(contacts), passing, tuple(_notes(central, roles, pairs, passing))))
    return tuple(out)


def _role_rank(pairs, planets, g) -> int:
    """Suns first, then bevel central gears, then rings (the order of a sentence)."""
    kinds = {gp.kind for gp in pairs if g in gp.gears and set(gp.gears) & set(planets)}
    return 2 if kinds == {"internal"} else 0 if kinds == {"external"} else 1


def _notes(central, roles, pairs, n) -> list[str]:
    """Equal spacing needs ``(Z_sun + Z_ring) / N`` whole; ``Z_ring mod N`` sets the phasing."""
    if n < 2:
        return []
    teeth = {}
    for gp in pairs:
        if gp.teeth is not None:
            for g, z in zip(gp.gears, gp.teeth):
                teeth.setdefault(g, z)
    role = dict(roles)
    suns = [c for c in central if role[c] == "sun" and c in teeth]
    rings = [c for c in central if role[c] == "ring" and c in teeth]
    notes = []
    for s in suns:
        for r in rings:
            if (teeth[s] + teeth[r]) % n:
                notes.append(f"sun {s} ({teeth[s]} teeth) and ring {r} ({teeth[r]}): {teeth[s] + teeth[r]} is not a "
                             f"multiple of {n}, so {n} planets cannot be equally spaced")
    for r in rings:
        phase = teeth[r] % n
        notes.append(f"ring {r}: {teeth[r]} teeth = {teeth[r] // n} x {n} + {phase}: the planets mesh "
                     + ("in phase" if phase == 0 else f"in sequence (phase step {phase}/{n} of a tooth)"))
    return notes
