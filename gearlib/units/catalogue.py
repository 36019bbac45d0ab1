"""The catalogue of kinematic units with up to five links, rebuilt from first principles.

Liu, Chen and Chang's Tables 1-3 (the drawings of the units) are lost from the source text, so
the catalogue is reconstructed here. A unit with *g* gears is a tree of *g - 1* gear pairs on
one carrier in which meshing gears turn about different axes of the carrier; two gears that
do not mesh may share an axis (they are *coaxial*). Up to isomorphism (renaming links and
axis labels) this gives:

* 3 links, one gear pair: **K3-1**;
* 4 links, a path x-m-y: **K4-1** (x and y coaxial: sun, planet, ring) and **K4-2** (three
  axes: an ordinary compound train);
* 5 links, a path a-b-c-d: **K5-1** (four axes), **K5-2** (a and c coaxial), **K5-3** (a and d
  coaxial), **K5-4** (a, c coaxial and b, d coaxial); a star (b meshing a, c, d):
  **K5-5** (four axes), **K5-6** (two outer gears coaxial), **K5-7** (three outer gears coaxial).

That is 1 + 2 + 7 = 10 types, the paper's "10 distinct KUs". Common gears that are coaxial
get g-g thin edges: one gives an **S** variant, two a **D** variant. The variants the paper
names (K4-1S, K5-2S, K5-3S, K5-4S, K5-6S, K5-7S, K5-4D, K5-7D) are exactly the ones that
exist, which fixes which types have coaxial gears. The order of the numbers within a size
is a reconstruction: forced for K4-1/K4-2, K5-4 and K5-7 (the D variants), and for K5-1,
K5-5 (no S variant); a guess for K5-2 versus K5-3.

Classification is by graph isomorphism (networkx) of a graph with the carrier, the gears,
one vertex per axis of the carrier, heavy edges, and a mark on common coaxial gears.

>>> import gearlib as gl
>>> [e.name for e in gl.ku_catalogue()]
['K3-1', 'K4-1', 'K4-2', 'K5-1', 'K5-2', 'K5-3', 'K5-4', 'K5-5', 'K5-6', 'K5-7']
>>> [e.name for e in gl.ku_catalogue(variants=True) if e.gg_edges]
['K4-1S', 'K5-2S', 'K5-3S', 'K5-4S', 'K5-4D', 'K5-6S', 'K5-7S', 'K5-7D']
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from itertools import product

__all__ = ["CatalogueEntry", "ku_catalogue", "classify", "structure_graph"]

LABELS = "abcd"


@dataclass(frozen=True)
class CatalogueEntry:
    """One type of kinematic unit: gears ``1..g`` on carrier ``"k"``.

    ``pairs`` are the gear pairs, ``axes[i]`` the axis label of gear ``i + 1``, ``common``
    the gears joined by g-g thin edges in this variant.
    """

    name: str
    base: str
    pairs: tuple
    axes: tuple
    common: tuple = ()

    @property
    def gears(self) -> int:
        return len(self.axes)

    @property
    def links(self) -> int:
        return self.gears + 1

    @property
    def gg_edges(self) -> int:
        count = 0
        for label in set(self.axes):
            n = sum(1 for g in self.common if self.axes[g - 1] == label)
            count += max(0, n - 1)
        return count

    def mechanism(self):
        """The unit as a :class:`~gearlib.Mechanism` (carrier ``"k"``, symbolic gear ratios)."""
        from ..mechanism.data import Mechanism

        return Mechanism.from_dict({
            "name": self.name,
            "links": ["k", *range(1, self.gears + 1)],
            "turning_pairs": [["k", g, self.axes[g - 1]] for g in range(1, self.gears + 1)],
            "gear_pairs": [{"gears": [a, b], "ratio": f"e_{a}_{b}", "carrier": "k"} for a, b in self.pairs],
        })

    def unit(self):
        """The unit as a :class:`~gearlib.KinematicUnit`, with this variant's common gears."""
        from .unit import KinematicUnit, _thin_edges

        mech = self.mechanism()
        u = KinematicUnit(1, "k", tuple(range(1, self.gears + 1)), mech.gear_pairs,
                          tuple((g, self.axes[g - 1]) for g in range(1, self.gears + 1)), tuple(self.common),
                          type=self.name, base_type=self.base)
        import dataclasses

        return dataclasses.replace(u, thin_edges=_thin_edges(u))

    def __str__(self) -> str:
        axes = ", ".join(f"{g}:{a}" for g, a in enumerate(self.axes, 1))
        return f"{self.name}: gear pairs {list(self.pairs)}, axes {axes}"


def structure_graph(carrier, gears, pairs, axes, marked=()):
    """The graph that classification compares: vertices for the carrier (``t="k"``), gears
    (``t="g"``, or ``"g*"`` when marked as a common coaxial gear) and axes (``t="axis"``);
    heavy edges between meshing gears, and each axis joined to the carrier and its gears."""
    import networkx as nx

    g = nx.Graph()
    g.add_node(("link", carrier), t="k")
    marked = set(marked)
    for x in gears:
        g.add_node(("link", x), t="g*" if x in marked else "g")
    for a, b in pairs:
        g.add_edge(("link", a), ("link", b))
    for x, label in axes:
        g.add_node(("axis", label), t="axis")
        g.add_edge(("axis", label), ("link", carrier))
        g.add_edge(("axis", label), ("link", x))
    return g


def _match(a, b) -> bool:
    return a["t"] == b["t"]


def _partitions(n, pairs):
    """Restricted growth strings of length n with meshing gears in different blocks."""
    adj = {i: set() for i in range(n)}
    for a, b in pairs:
        adj[a - 1].add(b - 1)
        adj[b - 1].add(a - 1)

    def grow(prefix):
        if len(prefix) == n:
            yield tuple(prefix)
            return
        i = len(prefix)
        for block in range(max(prefix, default=-1) + 2):
            if all(prefix[j] != block for j in adj[i] if j < i):
                yield from grow(prefix + [block])

    yield from grow([])


def _base_name(pairs, axes) -> str:
    g = len(axes)
    if g == 2:
        return "K3-1"
    coaxial = [(i, j) for i in range(1, g + 1) for j in range(i + 1, g + 1) if axes[i - 1] == axes[j - 1]]
    if g == 3:
        return "K4-1" if coaxial else "K4-2"
    degree = {i: 0 for i in range(1, g + 1)}
    for a, b in pairs:
        degree[a] += 1
        degree[b] += 1
    if max(degree.values()) == 3:  # star
        return {0: "K5-5", 1: "K5-6", 3: "K5-7"}[len(coaxial)]
    if not coaxial:
        return "K5-1"
    if len(coaxial) == 2:
        return "K5-4"
    ends = [i for i, d in degree.items() if d == 1]
    (i, j), = coaxial
    return "K5-3" if {i, j} == set(ends) else "K5-2"


@functools.cache
def _entries() -> tuple:
    import networkx as nx

    bases, graphs = [], []
    for g in (2, 3, 4):
        for tree in nx.nonisomorphic_trees(g):
            pairs = tuple(sorted((a + 1, b + 1) for a, b in tree.edges()))
            for part in _partitions(g, pairs):
                axes = tuple(LABELS[p] for p in part)
                sg = structure_graph("k", range(1, g + 1), pairs, list(zip(range(1, g + 1), axes)))
                if any(nx.is_isomorphic(sg, h, node_match=_match) for h in graphs):
                    continue
                graphs.append(sg)
                name = _base_name(pairs, axes)
                bases.append(CatalogueEntry(name, name, pairs, axes))
    bases.sort(key=lambda e: (e.links, e.name))
    variants = []
    for e in bases:
        found = []
        classes = {}
        for gear, label in enumerate(e.axes, 1):
            classes.setdefault(label, []).append(gear)
        options = []
        for members in classes.values():
            subsets = [()]
            if len(members) >= 2:
                subsets += [tuple(m for k, m in enumerate(members) if mask >> k & 1)
                            for mask in range(1, 2 ** len(members)) if bin(mask).count("1") >= 2]
            options.append(subsets)
        for choice in product(*options):
            common = tuple(sorted(x for part in choice for x in part))
            if not common:
                continue
            v = CatalogueEntry("", e.base, e.pairs, e.axes, common)
            if v.gg_edges > 2:
                continue
            sg = structure_graph("k", range(1, e.gears + 1), e.pairs, list(zip(range(1, e.gears + 1), e.axes)), common)
            if any(nx.is_isomorphic(sg, h, node_match=_match) for h in found):
                continue
            found.append(sg)
            variants.append(CatalogueEntry(e.base + ("S" if v.gg_edges == 1 else "D"), e.base, e.pairs, e.axes, common))
    return tuple(bases), tuple(variants)


def ku_catalogue(*, variants: bool = False) -> list[CatalogueEntry]:
    """The ten types of kinematic unit with up to five links; with ``variants=True`` each
    followed by its S and D variants (g-g thin edges between common coaxial gears)."""
    bases, extra = _entries()
    if not variants:
        return list(bases)
    out = []
    for e in bases:
        out.append(e)
        out.extend(sorted((v for v in extra if v.base == e.name), key=lambda v: v.gg_edges))
    return out


@functools.cache
def _graphs():
    import networkx as nx  # noqa: F401

    out = []
    for e in ku_catalogue(variants=True):
        g = list(range(1, e.gears + 1))
        out.append((e, structure_graph("k", g, e.pairs, list(zip(g, e.axes)), e.common)))
    return out


def classify(unit) -> tuple[str | None, str | None]:
    """``(name, base name)`` of a :class:`~gearlib.KinematicUnit` in the catalogue, or
    ``(None, None)`` when it has more than five links or a loop of gears."""
    import networkx as nx

    if unit.size > 5 or unit.redundant_pairs:
        return None, None
    shared = set(unit.shared)
    marked = []
    by_axis: dict = {}
    for g, label in unit.axes:
        by_axis.setdefault(label, []).append(g)
    for gears in by_axis.values():
        common = [g for g in gears if g in shared]
        if len(common) >= 2:
            marked += common
    sg = structure_graph(unit.carrier, unit.gears, [gp.gears for gp in unit.gear_pairs], unit.axes, marked)
    for entry, h in _graphs():
        if entry.gears == len(unit.gears) and nx.is_isomorphic(sg, h, node_match=_match):
            return entry.name, entry.base
    return None, None
