"""Kinematic units: the building blocks a geared mechanism is made of.

Liu, Chen and Chang (2004, Sec. 2) split a geared mechanism into **kinematic units** (KUs): a
carrier with the gears it holds. Their four steps, for any mechanism given as data:

1. the *displacement graph*: gears joined by heavy edges labelled with their carrier
   (:func:`gearlib.displacement_graph`);
2. separate it into sub-graphs with one carrier label each: the connected pieces of the
   gear pairs that share a carrier (two separate gear trees on one carrier are two units, as
   in their Fig. 3(a), so every unit has one degree of freedom relative to its carrier);
3. add the carrier vertex and a thin edge (gear-carrier, *g-c*) from it to each gear,
   labelled with the gear's axis on the carrier;
4. links that several units share are *common links*; common gears that are coaxial on the
   carrier are joined by a gear-gear (*g-g*) thin edge (coaxial re-arrangement), which
   replaces one of their g-c edges.

Units share links through *common linkages*: a **2-link chain** (two units share two
coaxial links) or a **coaxial triangle** (three units, each two sharing one link, the three
links coaxial). Each unit is classified against the catalogue of units with up to five links
(:mod:`gearlib.units.catalogue`). Derived in chapter 2.

>>> import gearlib as gl
>>> frac = gl.kinematic_units(gl.catalog.load("liu_chen_fig1"))
>>> for unit in frac.units:
...     print(unit)
KU1 (K3-1): carrier 5, gears 4, 1
KU2 (K4-1S): carrier 3, gears 5, 2, 1
>>> print(frac.linkages[0])
2-link chain 1-5 (axis a) between KU1 and KU2
"""

from __future__ import annotations
from collections import defaultdict
from dataclasses import dataclass
from functools import cached_property
from itertools import combinations
from .._common.nogc import no_gc
from .._common.topology import UnionFind
from ..mechanism.elements import GearPair
from ..mechanism.data import Mechanism
from .unit import CommonLinkage, KinematicUnit, _key, _replace, _thin_edges
from ..mechanism._accept import takes_mechanism

__all__ = ['Fractionation', 'kinematic_units', 'separated_displacement_graph']


@dataclass(frozen=True, eq=False)
class Fractionation:
    """The kinematic units of a mechanism and the common linkages between them."""

    mechanism: Mechanism
    units: tuple
    linkages: tuple
    outside: tuple = ()

    @cached_property
    def _by_link(self) -> dict:
        out = defaultdict(list)
        for unit in self.units:
            for x in unit.links:
                out[x].append(unit)
        return out

    @cached_property
    def _by_pair(self) -> dict:
        return {id(gp): unit for unit in self.units for gp in unit.gear_pairs + unit.redundant_pairs}

    def units_with(self, link) -> tuple:
        """The units that contain *link*."""
        return tuple(self._by_link.get(self.mechanism.resolve(link), ()))

    def unit_of(self, pair: GearPair) -> KinematicUnit:
        """The unit a gear pair belongs to."""
        return self._by_pair[id(pair)]

    def unit(self, name) -> KinematicUnit:
        """A unit by index (1, 2, ...) or name (``"KU2"``)."""
        text = str(name).removeprefix("KU")
        if not text.isdigit() or not 1 <= int(text) <= len(self.units):
            from ..errors import InputError

            raise InputError(f"no unit {name!r} in {self.mechanism.name!r}; its units are KU1 to KU{len(self.units)}")
        return self.units[int(text) - 1]

    def types(self) -> dict:
        """``{label: count}`` of the units' types."""
        out: dict = {}
        for u in self.units:
            out[u.label] = out.get(u.label, 0) + 1
        return out

    def table(self) -> list[tuple]:
        """Rows ``(name, type, carrier, gears, shared links)``."""
        return [(u.name, u.label, u.carrier, ", ".join(map(str, u.gears)), ", ".join(map(str, u.shared)))
                for u in self.units]

    def to_json(self) -> dict:
        """Plain data: units and common linkages (the command line's ``--json``)."""
        return {
            "mechanism": self.mechanism.name,
            "units": [{"name": u.name, "type": u.type, "links": u.size, "carrier": u.carrier, "gears": list(u.gears),
                       "gear_pairs": [list(gp.gears) for gp in u.gear_pairs], "shared": list(u.shared),
                       "thin_edges": [{"links": list(e.links), "axis": e.axis, "kind": e.kind} for e in u.thin_edges]}
                      for u in self.units],
            "common_linkages": [{"kind": c.kind, "units": [f"KU{i}" for i in c.units], "links": list(c.links),
                                 "axis": c.axis} for c in self.linkages],
            "outside": list(self.outside),
        }

    def __str__(self) -> str:
        lines = [f"kinematic units of {self.mechanism.name!r}:"]
        lines += [f"  {u}" + (f"; shares {', '.join(map(str, u.shared))}" if u.shared else "") for u in self.units]
        if self.linkages:
            lines.append("common linkages:")
            lines += [f"  {c}" for c in self.linkages]
        if self.outside:
            lines.append(f"links in no unit: {', '.join(map(str, self.outside))}")
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        rows = "".join(f"<tr>{''.join(f'<td>{c}</td>' for c in r)}</tr>" for r in self.table())
        links = "".join(f"<li>{c}</li>" for c in self.linkages)
        return (f"<table><caption>Kinematic units of {self.mechanism.name}</caption><tr><th>unit</th><th>type</th>"
                f"<th>carrier</th><th>gears</th><th>shared</th></tr>{rows}</table>"
                + (f"<p>Common linkages:</p><ul>{links}</ul>" if links else ""))

    def plot(self, ax=None, **kwargs):
        """Draw the mechanism with its units and common linkages (:func:`gearlib.draw_units`)."""
        from ._draw import draw_units

        return draw_units(self, ax=ax, **kwargs)


# ------------------------------------------------------------------------------ steps 1-4
def separated_displacement_graph(mech: Mechanism) -> list[tuple]:
    """Step 2: the displacement graph cut into sub-graphs with one carrier each.

    Returns ``[(carrier, (gear pairs...)), ...]``: the connected pieces of the gear pairs that
    share a carrier, in the order of ``mech.gear_pairs``.
    """
    uf = UnionFind()
    order = []
    for gp in mech.gear_pairs:
        a, b = gp.gears
        ka, kb = (gp.carrier, a), (gp.carrier, b)
        uf.add(ka)
        uf.add(kb)
        uf.union(ka, kb)
    pieces: dict = {}
    for gp in mech.gear_pairs:
        root = uf.find((gp.carrier, gp.gears[0]))
        if root not in pieces:
            pieces[root] = []
            order.append(root)
        pieces[root].append(gp)
    return [(pieces[r][0].carrier, tuple(pieces[r])) for r in order]


def _unit_from_pairs(mech: Mechanism, index: int, carrier, pairs) -> KinematicUnit:
    gears: list = []
    seen = set()
    kept, redundant = [], []
    uf = UnionFind()
    for gp in pairs:
        for g in gp.gears:
            if g not in seen:
                seen.add(g)
                gears.append(g)
                uf.add(g)
        (kept if uf.union(*gp.gears) else redundant).append(gp)
    label = mech._groups.coaxial_label  # ids are already resolved: skip Mechanism.axis_of's parsing
    axes = tuple((g, label(g, carrier)) for g in gears)
    return KinematicUnit(index, carrier, tuple(gears), tuple(kept), axes, redundant_pairs=tuple(redundant))


def _linkages(mech: Mechanism, units) -> tuple:
    by_link = defaultdict(list)
    for u in units:
        for x in u.links:
            by_link[x].append(u.index)
    shared: dict = defaultdict(list)
    for x, idx in by_link.items():
        for i, j in combinations(sorted(idx), 2):
            shared[(i, j)].append(x)
    out, covered = [], set()
    singles = {}
    for (i, j), links in shared.items():
        if len(links) == 2 and mech.coaxial(*links):
            links = sorted(links, key=_key)
            out.append(CommonLinkage("2-link chain", (i, j), tuple(links), mech.coaxial(*links)))
            covered.add((i, j))
        elif len(links) == 1:
            singles[(i, j)] = links[0]
    # coaxial triangles: three units, each two sharing one link, the three links coaxial
    neighbours = defaultdict(set)
    for i, j in singles:
        neighbours[i].add(j)
        neighbours[j].add(i)
    for (i, j), a in sorted(singles.items()):
        for k in sorted(neighbours[i] & neighbours[j]):
            if k <= j:
                continue
            b, c = singles[(j, k)], singles[(i, k)]
            if len({a, b, c}) == 3 and mech.coaxial(a, b) and mech.coaxial(a, b) == mech.coaxial(b, c) \
                    and mech.coaxial(a, c):
                links = tuple(sorted((a, b, c), key=_key))
                out.append(CommonLinkage("coaxial triangle", (i, j, k), links, mech.coaxial(a, b)))
                covered |= {(i, j), (j, k), (i, k)}
    for pair, links in sorted(shared.items()):
        if pair not in covered:
            out.append(CommonLinkage("other", pair, tuple(sorted(links, key=_key))))
    return tuple(out)


@no_gc
@takes_mechanism
def kinematic_units(mech: Mechanism) -> Fractionation:
    """Fractionate *mech* into kinematic units (steps 1-4), classify each against the catalogue
    of units with up to five links, and find the common linkages between them.

    The result is cached on the mechanism (mechanisms are immutable). Runs in time linear in the
    number of gear pairs (plus a small isomorphism test for units of up to five links).
    """
    cached = mech.__dict__.get("_kinematic_units")
    if cached is not None:
        return cached
    from .catalogue import classify

    pieces = separated_displacement_graph(mech)
    units = [_unit_from_pairs(mech, i + 1, c, pairs) for i, (c, pairs) in enumerate(pieces)]
    count: dict = defaultdict(int)
    for u in units:
        for x in u.links:
            count[x] += 1
    done = []
    for u in units:
        shared = tuple(x for x in u.links if count[x] > 1)
        u = KinematicUnit(u.index, u.carrier, u.gears, u.gear_pairs, u.axes, shared, (), None, None, u.redundant_pairs)
        u = _replace(u, thin_edges=_thin_edges(u))
        name, base = classify(u)
        done.append(_replace(u, type=name, base_type=base))
    outside = tuple(x for x in mech.link_ids if count.get(x, 0) == 0)
    frac = Fractionation(mech, tuple(done), _linkages(mech, done), outside)
    mech.__dict__["_kinematic_units"] = frac  # a cache on an immutable object, like functools.cached_property
    return frac
