"""One kinematic unit and the common linkages between units: the data of chapter 2.

A :class:`KinematicUnit` is a carrier with the gears it holds and their gear pairs, the
thin edges (g-c, and g-g between common coaxial gears) and its type in the catalogue of
units (:mod:`gearlib.units.catalogue`). Units are made by
:func:`gearlib.kinematic_units`; a :class:`CommonLinkage` records the
links two or three units share (Liu, Chen and Chang, 2004, Sec. 2).
"""

from __future__ import annotations
from collections import defaultdict
import dataclasses
from dataclasses import dataclass
from functools import cached_property

__all__ = ['ThinEdge', 'KinematicUnit', 'CommonLinkage']


def _key(x):
    return (isinstance(x, str), str(x) if isinstance(x, str) else x)


@dataclass(frozen=True)
class ThinEdge:
    """A thin edge of a kinematic unit: ``kind`` is ``"g-c"`` (gear and carrier) or ``"g-g"``
    (two coaxial gears, after coaxial re-arrangement)."""

    links: tuple
    axis: str
    kind: str

    def __str__(self) -> str:
        return f"{self.links[0]}-{self.links[1]} ({self.kind}, axis {self.axis})"


@dataclass(frozen=True)
class KinematicUnit:
    """One kinematic unit: a carrier, the gears on it and their gear pairs.

    Attributes
    ----------
    index : int
        1, 2, ...: the unit is called ``KU<index>``.
    carrier : link id
    gears : tuple
        Gear links, in the order they first appear in the gear pairs.
    gear_pairs : tuple of GearPair
    axes : tuple of (gear, axis label)
        The axis of each gear on the carrier.
    shared : tuple
        Links that other units contain too (common links).
    thin_edges : tuple of ThinEdge
        g-c edges, and g-g edges between common coaxial gears (step 4).
    type : str or None
        Catalogue name (``"K4-1S"``), or None for a unit outside the catalogue.
    base_type : str or None
        The name without the S/D mark (``"K4-1"``).
    redundant_pairs : tuple of GearPair
        Pairs that close a loop of gears (a duplicate planet): their equation follows from
        the others, and gains ignore them.
    """

    index: int
    carrier: object
    gears: tuple
    gear_pairs: tuple
    axes: tuple
    shared: tuple = ()
    thin_edges: tuple = ()
    type: str | None = None
    base_type: str | None = None
    redundant_pairs: tuple = ()

    @property
    def name(self) -> str:
        return f"KU{self.index}"

    @property
    def links(self) -> tuple:
        """The carrier, then the gears."""
        return (self.carrier, *self.gears)

    @property
    def size(self) -> int:
        """Number of links."""
        return 1 + len(self.gears)

    @property
    def label(self) -> str:
        """The catalogue name, or ``"6-link KU"`` for a unit outside the catalogue."""
        if self.type:
            return self.type
        return f"{self.size}-link KU" + (" with a gear loop" if self.redundant_pairs else "")

    @cached_property
    def _axis(self) -> dict:
        return dict(self.axes)

    def axis(self, gear):
        """The axis label of *gear* on the carrier."""
        return self._axis[gear]

    def __contains__(self, link) -> bool:
        return link == self.carrier or link in self._axis

    def coaxial(self, u, v) -> bool:
        """True when *u* and *v* turn about one axis of this unit (a gear and the carrier,
        or two gears with the same axis label)."""
        if u == v:
            return True
        if self.carrier in (u, v):
            return True
        return self._axis[u] == self._axis[v]

    def edge_kind(self, u, v) -> str | None:
        """``"g-c"``, ``"g-g"`` (coaxial gears) or None (not coaxial)."""
        if u == v or u not in self or v not in self or not self.coaxial(u, v):
            return None
        return "g-c" if self.carrier in (u, v) else "g-g"

    @property
    def gg_edges(self) -> tuple:
        return tuple(e for e in self.thin_edges if e.kind == "g-g")

    def __str__(self) -> str:
        return f"{self.name} ({self.label}): carrier {self.carrier}, gears {', '.join(map(str, self.gears))}"

    def __repr__(self) -> str:
        return f"<{self}>"


@dataclass(frozen=True)
class CommonLinkage:
    """The links that kinematic units share: ``kind`` is ``"2-link chain"``,
    ``"coaxial triangle"`` or ``"other"`` (any other interface, e.g. one shared link)."""

    kind: str
    units: tuple
    links: tuple
    axis: str | None = None

    def __str__(self) -> str:
        names = " and ".join(f"KU{i}" for i in self.units) if len(self.units) == 2 else ", ".join(
            f"KU{i}" for i in self.units)
        where = f" (axis {self.axis})" if self.axis else ""
        return f"{self.kind} {'-'.join(map(str, self.links))}{where} between {names}"


def _thin_edges(unit: KinematicUnit) -> tuple:
    """g-c edges to every gear; common coaxial gears chained by g-g edges (step 4)."""
    shared = set(unit.shared)
    by_axis: dict = defaultdict(list)
    for g, label in unit.axes:
        by_axis[label].append(g)
    edges = []
    for label, gears in by_axis.items():
        common = [g for g in gears if g in shared]
        if len(common) >= 2:
            edges.append(ThinEdge((unit.carrier, common[0]), label, "g-c"))
            for u, v in zip(common, common[1:]):
                edges.append(ThinEdge((u, v), label, "g-g"))
            rest = [g for g in gears if g not in common]
        else:
            rest = gears
        edges.extend(ThinEdge((unit.carrier, g), label, "g-c") for g in rest)
    order = {g: i for i, g in enumerate(unit.gears)}
    edges.sort(key=lambda e: (e.kind == "g-g", order.get(e.links[1], -1)))
    return tuple(edges)


def _replace(unit: KinematicUnit, **changes) -> KinematicUnit:
    return dataclasses.replace(unit, **changes)
