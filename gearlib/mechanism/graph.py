"""The graph of a geared mechanism, its fundamental circuits and its displacement graph.

Links are vertices; gear pairs are heavy edges and turning pairs thin edges labelled by
their axis (Freudenstein 1971; Tsai 1988). Each gear pair with its carrier (transfer
vertex) closes one *fundamental circuit*, written ``(a, b)(c)`` as in Chen, Yao and Lee.
The *displacement graph* keeps only the gears: each heavy edge labelled by its carrier.
Derived in chapter 1.

>>> import gearlib as gl
>>> m = gl.catalog.load("liu_chen_fig1")
>>> [str(c) for c in gl.fundamental_circuits(m)]
['(4,1)(5)', '(5,2)(3)', '(2,1)(3)']
>>> sorted(gl.displacement_graph(m).edges(data="carrier"))
[(1, 2, 3), (4, 1, 5), (5, 2, 3)]
"""

from __future__ import annotations

from dataclasses import dataclass

import networkx as nx

from .elements import GearPair
from .data import Mechanism
from ._accept import takes_mechanism

__all__ = ["to_networkx", "FundamentalCircuit", "fundamental_circuits", "displacement_graph", "tilted_links"]


@takes_mechanism
def to_networkx(mech: Mechanism) -> nx.MultiGraph:
    """A networkx multigraph: nodes are link ids (attribute ``name``); edges have
    ``kind`` ``"thin"`` (with ``axis``) or ``"heavy"`` (with ``carrier`` and ``pair``)."""
    g = nx.MultiGraph(name=mech.name)
    for lk in mech.links:
        g.add_node(lk.id, name=lk.name)
    for tp in mech.turning_pairs:
        g.add_edge(*tp.links, kind="thin", axis=tp.axis, pair=tp)
    for gp in mech.gear_pairs:
        g.add_edge(*gp.gears, kind="heavy", carrier=gp.carrier, pair=gp)
    return g


@dataclass(frozen=True)
class FundamentalCircuit:
    """The circuit closed by one gear pair: its gears, carrier and the two gear axes."""

    pair: GearPair
    axes: tuple[str, str]

    @property
    def gears(self) -> tuple:
        return self.pair.gears

    @property
    def carrier(self):
        return self.pair.carrier

    @property
    def links(self) -> tuple:
        return (*self.pair.gears, self.pair.carrier)

    def __str__(self) -> str:
        a, b = self.pair.gears
        return f"({a},{b})({self.pair.carrier})"


@takes_mechanism
def fundamental_circuits(mech: Mechanism) -> list[FundamentalCircuit]:
    """One fundamental circuit per gear pair, in the order of ``mech.gear_pairs``."""
    out = []
    for gp in mech.gear_pairs:
        a, b = gp.gears
        out.append(FundamentalCircuit(gp, (mech.axis_of(a, gp.carrier), mech.axis_of(b, gp.carrier))))
    return out


@takes_mechanism
def displacement_graph(mech: Mechanism) -> nx.MultiGraph:
    """The displacement graph: gear vertices joined by heavy edges labelled by their carrier
    (step 1 of the kinematic fractionation of Liu, Chen and Chang)."""
    g = nx.MultiGraph(name=f"displacement graph of {mech.name}")
    for gp in mech.gear_pairs:
        g.add_edge(*gp.gears, carrier=gp.carrier, pair=gp)
    return g


def tilted_links(mech: Mechanism, ground=None) -> dict:
    """``{link: the link it turns on}`` for every link whose axis is not parallel to the
    ground's: a bevel planet. Its speed in the Willis equations is no angular velocity about
    one axis (it adds the carrier's rate about the main axis to the planet's spin about its
    own); its speed relative to the link it turns on is one, about their common axis.

    Two axes are parallel when a spur or internal pair meshes gears on them (on its carrier);
    a link is *tilted* when the axes of the turning pairs between it and the ground are not
    all parallel. In a train of spur gears no link is tilted.

    >>> import gearlib as gl
    >>> gl.mechanism.tilted_links(gl.catalog.humpage())
    {2: 6}
    >>> gl.mechanism.tilted_links(gl.catalog.simple_planetary())
    {}
    """
    ground = mech.resolve(ground if ground is not None else (mech.ground if mech.ground is not None
                                                             else mech.link_ids[0]))
    parent = {}

    def find(a):
        while parent.get(a, a) != a:
            a = parent[a]
        return a

    for gp in mech.gear_pairs:
        if gp.kind != "bevel":
            a, b = (mech.axis_of(g, gp.carrier) for g in gp.gears)
            if a is not None and b is not None and find(a) != find(b):
                parent[find(a)] = find(b)
    thin = nx.Graph()
    thin.add_nodes_from(mech.link_ids)
    for tp in mech.turning_pairs:
        thin.add_edge(*tp.links, axis=tp.axis)
    out = {}
    for link, path in nx.single_source_shortest_path(thin, ground).items():
        classes = {find(thin.edges[u, v]["axis"]) for u, v in zip(path, path[1:])}
        if len(classes) > 1:
            out[link] = path[-2]
    return out
