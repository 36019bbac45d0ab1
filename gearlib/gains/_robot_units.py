"""Chen's input and transmission units (Fig. 8, reconstructed): templates, gains, identification.

Private helpers of :mod:`gearlib.gains.robots`.
"""

from __future__ import annotations

import sympy

from ..errors import MechanismError
from ..mechanism.data import Mechanism

# Reconstructed Fig. 8: roles p (primary), x, y (connecting), 1, 2 (other secondary links).
# turning pairs (parent, child, axis) and gear pairs (a, b, carrier). Confidence: TU-7 high
# (its equations are in the text); IU-2..5, TU-2 and TU-6 medium (fixed by their gains and
# characteristics (11) and (13)); TU-3, TU-4, TU-5 share one gain, and which of the three
# ordinary three-mesh units carries which number is a guess. Each gear pair is oriented as
# Tables 1 and 2 write its ratio (e_{y,1} e_{1,x}, not 1/(e_{x,1} e_{1,y})), so that the
# derived gains read as the paper prints them.
UNIT_TYPES = {
    "IU-1": ((("p", "x", "a"),), ()),
    "IU-2": ((("p", "x", "a"), ("p", "y", "a"), ("p", "g1", "b")), (("g1", "x", "p"), ("y", "g1", "p"))),
    "IU-3": ((("p", "x", "a"), ("x", "y", "a"), ("x", "g1", "b")), (("p", "g1", "x"), ("g1", "y", "x"))),
    "IU-4": ((("p", "x", "a"), ("p", "y", "a"), ("p", "g1", "b"), ("p", "g2", "c")),
             (("g1", "x", "p"), ("g2", "g1", "p"), ("y", "g2", "p"))),
    "IU-5": ((("p", "x", "a"), ("x", "y", "a"), ("x", "g1", "b"), ("x", "g2", "c")),
             (("p", "g1", "x"), ("g1", "g2", "x"), ("g2", "y", "x"))),
    "TU-1": ((("p", "x", "a"), ("p", "y", "b")), (("y", "x", "p"),)),
    "TU-2": ((("p", "x", "a"), ("p", "y", "b"), ("p", "g1", "c")), (("g1", "x", "p"), ("y", "g1", "p"))),
    "TU-3": ((("p", "x", "a"), ("p", "y", "b"), ("p", "g1", "c"), ("p", "g2", "d")),
             (("g1", "x", "p"), ("g2", "g1", "p"), ("y", "g2", "p"))),
    "TU-4": ((("p", "x", "a"), ("p", "y", "b"), ("p", "g1", "b"), ("p", "g2", "c")),
             (("g1", "x", "p"), ("g2", "g1", "p"), ("y", "g2", "p"))),
    "TU-5": ((("p", "x", "a"), ("p", "y", "b"), ("p", "g1", "b"), ("p", "g2", "a")),
             (("g1", "x", "p"), ("g2", "g1", "p"), ("y", "g2", "p"))),
    "TU-6": ((("p", "x", "a"), ("p", "y", "b"), ("x", "g2", "a"), ("x", "g1", "c")),
             (("p", "g1", "x"), ("g1", "g2", "x"), ("y", "g2", "p"))),
    "TU-7": ((("p", "x", "a"), ("p", "y", "b"), ("p", "g1", "b"), ("g1", "g2", "c")),
             (("g1", "x", "p"), ("p", "g2", "g1"), ("g2", "y", "g1"))),
}
"""Chen's Fig. 8 as data: ``name -> (turning pairs, gear pairs)`` over the roles."""


def _unit_gain(mech, p, x, y, links, pairs):
    """q_{x,p} / q_{y,p} from the unit's circuit equations (p held, y turning at 1)."""
    if x == y:
        return sympy.Integer(1)
    om = {z: sympy.Symbol(f"omega_{z}") for z in links}
    om[p] = sympy.Integer(0)
    eqs = [sympy.Eq(om[gp.gears[1]] - om[gp.carrier], _e(gp) * (om[gp.gears[0]] - om[gp.carrier])) for gp in pairs]
    eqs.append(sympy.Eq(om[y], 1))
    unknowns = [om[z] for z in links if z != p]
    sol = sympy.solve(eqs, unknowns, dict=True)
    if len(sol) != 1 or om[x] not in sol[0]:
        raise MechanismError(f"the unit with primary link {p} between links {x} and {y} does not move as one "
                             "degree of freedom; Chen's decomposition does not apply")
    return sympy.factor(sympy.cancel(sol[0][om[x]]))


def _e(gp):
    return gp.symbol if not gp.e.free_symbols else gp.e


def _structure(mech, links, pairs, roles):
    """A graph of a unit for isomorphism: links with roles, circuits, coaxial classes."""
    import networkx as nx

    g = nx.Graph()
    for z in links:
        g.add_node(("l", z), t=roles.get(z, "s"))
    for i, (a, b, c) in enumerate(pairs):
        g.add_node(("c", i), t="circuit")
        g.add_edge(("c", i), ("l", a), t="gear")
        g.add_edge(("c", i), ("l", b), t="gear")
        g.add_edge(("c", i), ("l", c), t="carrier")
    seen = set()
    for u in links:
        for v in links:
            if u != v and (label := mech.coaxial(u, v)) and (label, mech._groups.membership[u][label]) not in seen:
                key = (label, mech._groups.membership[u][label])
                seen.add(key)
                g.add_node(("axis", key), t="axis")
                for z in links:
                    if mech._groups.membership.get(z, {}).get(label) == key[1]:
                        g.add_edge(("axis", key), ("l", z), t="on")
    return g


def _template_graph(name):
    tps, gps = UNIT_TYPES[name]
    roles = sorted({r for t in tps for r in t[:2]})
    data = {"links": roles, "turning_pairs": [list(t) for t in tps],
            "gear_pairs": [{"gears": [a, b], "ratio": f"e_{a}_{b}", "carrier": c} for a, b, c in gps]}
    m = Mechanism.from_dict(data)
    return _structure(m, roles, [(a, b, c) for a, b, c in gps], {"p": "p", "x": "x", "y": "y"})


def unit_gains() -> dict:
    """``{name: G_f}``: the forward gain ``q_{x,p} / q_{y,p}`` of each unit of the reconstructed
    Fig. 8, derived from the unit's own circuit equations (symbols ``e_a_b`` with the paper's
    names: p, x, y and the other secondary links 1, 2)."""
    out = {}
    for name, (tps, gps) in UNIT_TYPES.items():
        if name == "IU-1":
            out[name] = sympy.Integer(1)
            continue
        roles = sorted({r for t in tps for r in t[:2]})
        m = Mechanism.from_dict({"links": roles, "turning_pairs": [list(t) for t in tps],
                                 "gear_pairs": [{"gears": [a, b], "ratio": f"e_{a}_{b}", "carrier": c}
                                                for a, b, c in gps]})
        g = _unit_gain(m, "p", "x", "y", tuple(roles), m.gear_pairs)
        rename = {s: sympy.Symbol(s.name.replace("g1", "1").replace("g2", "2")) for s in g.free_symbols}
        out[name] = g.subs(rename)
    return out


def _identify(mech, p, x, y, links, pairs):
    import networkx as nx

    triples = [(gp.gears[0], gp.gears[1], gp.carrier) for gp in pairs]
    if x == y:
        return "IU-1", False
    match = {"node_match": lambda a, b: a["t"] == b["t"]}
    for backwards in (False, True):
        roles = {p: "p", x: "y" if backwards else "x", y: "x" if backwards else "y"}
        g = _structure(mech, links, triples, roles)
        for name in UNIT_TYPES:
            if name != "IU-1" and nx.is_isomorphic(g, _template_graph(name), **match):
                return name, backwards
    return None, False
