"""Fundamental geared entities (Chatterjee and Tsai), to compare with kinematic units.

Hsieh and Tsai analyse an automatic transmission by its *fundamental geared entities* (FGEs):
each sun-planet-ring set with its carrier. Liu, Chen and Chang point out that FGEs follow the
structure rather than the kinematics: two FGEs on one carrier are one kinematic unit, which
is why their transmission has three FGEs but two units. Derived in chapter 2.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass

from .._common.topology import UnionFind
from ..mechanism.data import Mechanism
from .fractionation import kinematic_units
from ..mechanism._accept import takes_mechanism

__all__ = ["FundamentalGearedEntity", "fundamental_geared_entities"]


@dataclass(frozen=True)
class FundamentalGearedEntity:
    """Chatterjee and Tsai's fundamental geared entity: a carrier, a cluster of planet gears and
    the central (coaxial) gears they mesh with."""

    carrier: object
    planets: tuple
    central: tuple

    @property
    def links(self) -> tuple:
        return (self.carrier, *self.central, *self.planets)

    def __str__(self) -> str:
        return (f"carrier {self.carrier}, planet{'s' if len(self.planets) > 1 else ''} "
                f"{', '.join(map(str, self.planets))}, central gears {', '.join(map(str, self.central))}")


@takes_mechanism
def fundamental_geared_entities(mech: Mechanism) -> list[FundamentalGearedEntity]:
    """Chatterjee and Tsai's fundamental geared entities (FGEs), for comparison with units.

    In each unit the *central* gears are those on the axis that holds most gears (at least
    two); every cluster of meshing non-central gears (the planets) with the central gears it
    meshes forms one FGE. A unit without two coaxial gears is an ordinary train, not an
    epicyclic one, and is returned whole as one entity.

    >>> import gearlib as gl
    >>> [str(f) for f in gl.fundamental_geared_entities(gl.catalog.load("liu_chen_transmission"))]
    ['carrier 4, planet 3, central gears 2, 5', 'carrier 5, planet 6, central gears 1, 2', \
'carrier 5, planet 7, central gears 1, 8']
    """
    out = []
    for unit in kinematic_units(mech).units:
        by_axis: dict = defaultdict(list)
        for g, label in unit.axes:
            by_axis[label].append(g)
        label, central = max(by_axis.items(), key=lambda kv: len(kv[1]))
        if len(central) < 2:
            out.append(FundamentalGearedEntity(unit.carrier, unit.gears, ()))
            continue
        central_set = set(central)
        uf = UnionFind(g for g in unit.gears if g not in central_set)
        for gp in unit.gear_pairs + unit.redundant_pairs:
            a, b = gp.gears
            if a not in central_set and b not in central_set:
                uf.union(a, b)
        clusters: dict = {}
        for g in unit.gears:
            if g not in central_set:
                clusters.setdefault(uf.find(g), []).append(g)
        for planets in clusters.values():
            ps = set(planets)
            meshed = [c for c in central if any(set(gp.gears) & ps and c in gp.gears
                                                  for gp in unit.gear_pairs + unit.redundant_pairs)]
            out.append(FundamentalGearedEntity(unit.carrier, tuple(planets), tuple(meshed)))
    return out
