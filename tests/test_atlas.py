"""The atlas of geared kinematic chains: counts against the literature, the structural rules
checked on every chain by the core (not by the enumeration), an independent brute-force
enumeration for small chains, and isomorphism up to renumbering and label renaming.

Published counts are typed from the sources: Tsai and Lin (1989, abstract): no
non-fractionated two-dof train with five or fewer links, 2 rotation graphs with six and 20
with seven links; Chen, Yao and Lee (2003): "50 two-DOF seven-link GKC"; Yang, Ding et al.
(2019, abstract): 27 and 152 rotation graphs, 81 and 647 displacement graphs with six and
seven links; Buchsbaum and Freudenstein (1970) as quoted: 2 four-link and 6 five-link trains.
"""

import itertools
import random

import numpy as np
import networkx as nx
import pytest
import sympy

import gearlib as gl
from gearlib.synthesis import _chains, atlas


# --------------------------------------------------------------------- published counts
@pytest.mark.parametrize(
    ("links", "dof", "level", "published"),
    [
        (3, 1, "kinematic", 1),  # one gear pair on its carrier
        (4, 1, "kinematic", 2),
        (5, 1, "kinematic", 6),
        (6, 1, "kinematic", 27),
        (6, 1, "coaxial", 81),
        (7, 1, "kinematic", 152),
        (7, 1, "coaxial", 647),
        (3, 2, "kinematic", 0),
        (4, 2, "kinematic", 0),
        (5, 2, "kinematic", 0),
        (6, 2, "kinematic", 2),
        (7, 2, "kinematic", 20),
        (7, 2, "coaxial", 50),
    ],
)
def test_counts_match_the_literature(links, dof, level, published):
    assert len(atlas.geared_chains(links, dof, level=level)) == published


def test_count_table_lists_sources_and_agrees():
    rows = atlas.count_table(7)
    assert {(r.links, r.dof, r.level) for r in rows} >= {(7, 2, "coaxial"), (6, 2, "kinematic"), (6, 1, "coaxial")}
    for r in rows:
        assert r.source
        if r.source == "Tsai (1987)":  # 26 printed, one short of the settled 27
            assert (r.published, r.enumerated) == (26, 27) and not r.agrees
        else:
            assert r.agrees, r


def test_one_dof_chains_are_never_fractionated_and_two_dof_ones_can_be():
    assert atlas.geared_chains(6, 1, fractionated="only") == ()
    every = atlas.geared_chains(6, 2, fractionated=True)
    non = atlas.geared_chains(6, 2)
    only = atlas.geared_chains(6, 2, fractionated="only")
    assert len(every) == len(non) + len(only) and len(non) == 3
    assert every[: len(non)] == non  # non-fractionated first: names do not depend on the option
    assert all(atlas.is_fractionated(m) for m in only)
    assert not any(atlas.is_fractionated(m) for m in non)


def test_a_fractionated_chain_is_two_one_dof_chains_sharing_a_link():
    # two simple planetaries whose carriers are one link (7 links, 4 gear pairs, 2 dof)
    m = gl.Mechanism.from_dict({
        "links": [1, 2, 3, 4, 5, 6, 7],
        "turning_pairs": [[1, 2, "a"], [1, 3, "a"], [1, 4, "b"], [1, 5, "c"], [1, 6, "c"], [1, 7, "d"]],
        "gear_pairs": [{"gears": [2, 4], "ratio": "e_2_4"}, {"gears": [4, 3], "ratio": "e_4_3"},
                       {"gears": [5, 7], "ratio": "e_5_7"}, {"gears": [7, 6], "ratio": "e_7_6"}],
    })
    assert atlas.is_fractionated(m)
    assert any(atlas.isomorphic(m, c) for c in atlas.geared_chains(7, 2, fractionated="only"))
    assert not any(atlas.isomorphic(m, c) for c in atlas.geared_chains(7, 2))


# --------------------------------------------------------------------- every chain obeys the rules
def _generic_speeds(mech, seed=7):
    """Null space of the Willis matrix with random numeric ratios (numpy, not gearlib's solvers)."""
    rnd = random.Random(seed)
    w = np.zeros((len(mech.gear_pairs), len(mech.links)))
    for row, gp in zip(w, mech.gear_pairs):  # omega_b - omega_c = e (omega_a - omega_c)
        e = rnd.choice([-1, 1]) * rnd.uniform(0.3, 3.0)
        (a, b), c = gp.gears, gp.carrier
        row[mech.index[b]] += 1
        row[mech.index[a]] -= e
        row[mech.index[c]] += e - 1
    _, s, vt = np.linalg.svd(w)
    rank = int((s > 1e-9).sum())
    return rank, vt[rank:].T


@pytest.mark.parametrize(("links", "dof"), [(3, 1), (4, 1), (5, 1), (6, 1), (6, 2), (7, 2)])
def test_every_chain_obeys_the_structural_rules(links, dof):
    chains = atlas.geared_chains(links, dof, fractionated=True)
    names = [m.name for m in chains]
    assert names == [f"GKC {links}-{dof}-{k}" for k in range(1, len(chains) + 1)]
    for m in chains:
        assert len(m.links) == links and len(m.turning_pairs) == links - 1
        assert len(m.gear_pairs) == links - 1 - dof
        assert m.redundant_turning_pairs == ()  # the turning pairs form a tree
        assert all(gp.e == gp.symbol for gp in m.gear_pairs)  # symbolic ratios e_a_b
        assert "enumerated" in m.source
        used = {x for gp in m.gear_pairs for x in (*gp.gears, gp.carrier)}
        assert used == set(m.link_ids)  # every link is a gear or a carrier
        rank, basis = _generic_speeds(m)
        assert rank == len(m.gear_pairs) and basis.shape[1] == dof + 1  # dof + the free rotation
        # no two links locked together (no rigid sub-chain)
        for i, j in itertools.combinations(range(links), 2):
            assert np.abs(basis[i] - basis[j]).max() > 1e-6, (m.name, i, j)
        assert int(gl.dof(m.replace(ground=1))) == dof if links <= 6 else True


def test_chains_are_pairwise_non_isomorphic():
    for links, dof in [(5, 1), (6, 1), (6, 2), (7, 2)]:
        chains = atlas.geared_chains(links, dof, fractionated=True)
        graphs = [atlas.canonical_graph(m) for m in chains]
        hashes = [nx.weisfeiler_lehman_graph_hash(g, node_attr="kind", edge_attr="kind") for g in graphs]
        for i, j in itertools.combinations(range(len(chains)), 2):
            if hashes[i] == hashes[j]:
                assert not atlas.isomorphic(graphs[i], graphs[j]), (chains[i].name, chains[j].name)


@pytest.mark.parametrize("links", [3, 4, 5, 6, 7])
def test_hypertree_automorphisms_are_networkx_isomorphisms(links):
    """The enumeration's orbit pruning uses each hypertree's automorphisms: compare them with
    every colour-preserving self-isomorphism networkx's VF2 finds on the same tree."""
    from networkx.algorithms.isomorphism import GraphMatcher

    trees = _chains._hypertrees(links)
    assert trees and any(len(autos) > 1 for _, autos in trees)
    for groups, autos in trees:
        tree = nx.Graph((("l", v), ("g", i)) for i, g in enumerate(groups) for v in g)
        nx.set_node_attributes(tree, {node: node[0] for node in tree}, "kind")  # link or group
        matcher = GraphMatcher(tree, tree, node_match=lambda x, y: x["kind"] == y["kind"])
        vf2 = {tuple(m[("l", v)][1] for v in range(links)) for m in matcher.isomorphisms_iter()}
        assert sorted(autos) == sorted(vf2), groups


def _brute_force(n, dof):
    """Independent enumeration: every labelled coaxial arrangement and every choice of gear
    pairs, validated by gl.Mechanism, filtered with numpy, deduplicated with networkx."""
    subsets = [frozenset(s) for r in range(2, n + 1) for s in itertools.combinations(range(1, n + 1), r)]
    found, chains = {}, []
    for k in range(1, n):
        for groups in itertools.combinations(subsets, k):
            if sum(len(g) - 1 for g in groups) != n - 1:
                continue
            g = nx.Graph()
            g.add_nodes_from(("l", i) for i in range(1, n + 1))
            for gi, grp in enumerate(groups):
                g.add_edges_from((("g", gi), ("l", x)) for x in grp)
            if not nx.is_tree(g):
                continue
            turning = [[min(grp), x, f"x{gi}"] for gi, grp in enumerate(groups) for x in sorted(grp) if x != min(grp)]
            pairs = [(a, b) for a, b in itertools.combinations(range(1, n + 1), 2)  # a carrier on two axes
                     if any(a in g1 and b in g2 and g1 & g2 - {a, b} for g1 in groups for g2 in groups if g1 != g2)
                     and not any(a in grp and b in grp for grp in groups)]
            for chosen in itertools.combinations(pairs, n - 1 - dof):
                try:
                    m = gl.Mechanism.from_dict({
                        "links": list(range(1, n + 1)), "turning_pairs": turning,
                        "gear_pairs": [{"gears": list(p), "ratio": f"e_{p[0]}_{p[1]}"} for p in chosen]})
                except gl.GearlibError:
                    continue  # no carrier, or a locked loop of gears
                if {x for gp in m.gear_pairs for x in (*gp.gears, gp.carrier)} != set(m.link_ids):
                    continue
                rank, basis = _generic_speeds(m)
                if rank < len(chosen) or any(np.abs(basis[i] - basis[j]).max() < 1e-6
                                             for i, j in itertools.combinations(range(n), 2)):
                    continue
                graph = atlas.canonical_graph(m)
                key = nx.weisfeiler_lehman_graph_hash(graph, node_attr="kind", edge_attr="kind")
                if not any(atlas.isomorphic(graph, other) for other in found.get(key, [])):
                    found.setdefault(key, []).append(graph)
                    chains.append(m)
    return chains


@pytest.mark.parametrize(("links", "dof"), [(4, 1), (5, 1), (5, 2)])
def test_brute_force_enumeration_agrees(links, dof):
    brute = _brute_force(links, dof)
    chains = atlas.geared_chains(links, dof, fractionated=True)
    assert len(brute) == len(chains)
    for m in brute:
        assert sum(atlas.isomorphic(m, c) for c in chains) == 1


def test_results_are_cached_and_deterministic():
    assert all(a is b for a, b in zip(atlas.geared_chains(6, 2), atlas.geared_chains(6, 2), strict=True))
    first = [m.to_dict() for m in atlas.geared_chains(5, 1)]
    atlas._select.cache_clear()
    atlas._mechanism.cache_clear()
    atlas._kept.cache_clear()
    atlas._catalogue.cache_clear()
    _chains._hypertrees.cache_clear()
    assert [m.to_dict() for m in atlas.geared_chains(5, 1)] == first


def test_kinematic_level_keeps_one_per_set_of_willis_equations():
    every = atlas.geared_chains(6, 1)
    reps = atlas.geared_chains(6, 1, level="kinematic")
    assert set(reps) <= set(every)
    for m in every:
        assert sum(atlas.isomorphic(m, r, level="kinematic") for r in reps) == 1


# --------------------------------------------------------------------- the paper's chains are in the atlas
def test_cyl_gkc_5_7_2_is_in_the_seven_link_atlas():
    m = gl.catalog.load("cyl_gkc_5_7_2")
    assert atlas.chain_problems(m) == ()
    assert not atlas.is_fractionated(m)
    assert sum(atlas.isomorphic(m, c) for c in atlas.geared_chains(7, 2)) == 1


def test_cyl_eight_link_gkc_is_a_valid_non_fractionated_chain():
    m = gl.catalog.load("cyl_gkc_8")
    assert atlas.chain_problems(m) == () and not atlas.is_fractionated(m)


# --------------------------------------------------------------------- isomorphism
def _relabel(mech, seed):
    rnd = random.Random(seed)
    ids = list(mech.link_ids)
    new = ids[:]
    rnd.shuffle(new)
    p = dict(zip(ids, [10 + x for x in new]))
    labels = {tp.axis for tp in mech.turning_pairs}
    q = dict(zip(sorted(labels), rnd.sample([f"axis{i}" for i in range(len(labels))], len(labels))))
    return gl.Mechanism.from_dict({
        "links": [p[x] for x in ids][::-1],
        "turning_pairs": [[p[b], p[a], q[t]] for (a, b), t in ((tp.links, tp.axis) for tp in mech.turning_pairs)],
        "gear_pairs": [{"gears": [p[gp.gears[1]], p[gp.gears[0]]], "ratio": 1 / gp.e} for gp in mech.gear_pairs],
    })


@pytest.mark.parametrize("seed", range(5))
def test_isomorphic_up_to_renumbering_and_label_renaming(seed):
    for m in atlas.geared_chains(7, 2)[::7]:
        assert atlas.isomorphic(m, _relabel(m, seed))


def test_bearings_inside_a_coaxial_group_do_not_count():
    m = gl.catalog.load("cyl_gkc_5_7_2")  # 1, 3, 6 borne on 4 about axis a
    chain = m.replace(turning_pairs=((4, 1, "a"), (1, 3, "a"), (3, 6, "a"), (3, 2, "b"), (4, 5, "c"), (4, 7, "d")))
    assert atlas.isomorphic(m, chain)
    # 5 and 7 on one axis of 4: the same Willis equations, another coaxial arrangement
    shared = m.replace(turning_pairs=((4, 1, "a"), (4, 3, "a"), (4, 6, "a"), (3, 2, "b"), (4, 5, "c"), (4, 7, "c")))
    assert not atlas.isomorphic(m, shared)
    assert atlas.isomorphic(m, shared, level="kinematic")


def test_roles_distinguish_ground_and_terminals():
    m = gl.catalog.load("cyl_gkc_8")
    g = atlas.canonical_graph
    # the automorphism 1<->3, 4<->6 (seed notes): ground 3 with 0, 1, 2 is ground 1 with 0, 3, 2 (ND3-8-19)
    assert atlas.isomorphic(g(m, ground=1, terminals=(0, 2, 3)), g(m, ground=3, terminals=(0, 1, 2)))
    assert not atlas.isomorphic(g(m, ground=1, terminals=(0, 2, 3)), g(m, ground=0, terminals=(1, 2, 3)))
    assert not atlas.isomorphic(g(m, ground=1, terminals=(0, 2, 3)), g(m, ground=1, terminals=(0, 2, 4)))


def _planetary(sun, ring):
    return gl.Mechanism.from_dict({
        "links": [1, 2, 3, 4], "turning_pairs": [[4, 1, "a"], [4, 3, "a"], [4, 2, "b"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [sun, (ring - sun) // 2]},
                       {"gears": [2, 3], "teeth": [(ring - sun) // 2, ring], "type": "internal"}]})


def test_numbers_and_ratios_are_ignored():
    m = _planetary(24, 60)
    assert atlas.isomorphic(m, _planetary(30, 72))
    assert atlas.isomorphic(m, atlas.geared_chains(4, 1)[1])


# --------------------------------------------------------------------- structural problems and bad input
def test_chain_problems_name_the_links():
    probs = atlas.chain_problems(gl.catalog.car_differential())  # two planets: a duplicate, locked generically
    assert any("close loops of coaxial bearings" in p for p in probs)
    assert any(p.startswith("links 3, 4, 5, 6, 7 are locked together") for p in probs)
    idle = gl.Mechanism.from_dict({
        "links": [1, 2, 3, 4, 5],
        "turning_pairs": [[4, 1, "a"], [4, 3, "a"], [4, 2, "b"], [4, 5, "c"]],
        "gear_pairs": [{"gears": [1, 2], "ratio": "e_1_2"}, {"gears": [2, 3], "ratio": "e_2_3"}]})
    assert atlas.chain_problems(idle) == ("links 5 are neither a gear nor a carrier (in no fundamental circuit)",)


@pytest.mark.parametrize(
    ("args", "kwargs", "words"),
    [
        ((1, 1), {}, "n_links"),
        ((5, 0), {}, "dof"),
        ((9, 1), {}, "too many"),
        (("5", 1), {}, "n_links"),
        ((5, 1.0), {}, "dof"),
        ((5, True), {}, "dof"),
        ((5, 1), {"fractionated": "yes"}, "fractionated"),
        ((5, 1), {"fractionated": 1}, "fractionated"),
        ((5, 1), {"level": "rotation"}, "level"),
    ],
)
def test_bad_arguments_give_clear_errors(args, kwargs, words):
    with pytest.raises(gl.DataFormatError, match=words):
        atlas.geared_chains(*args, **kwargs)


def test_bad_isomorphism_arguments():
    m = gl.catalog.load("cyl_gkc_5_7_2")
    with pytest.raises(gl.DataFormatError, match="both the ground and a terminal"):
        atlas.canonical_graph(m, ground=4, terminals=(4, 5))
    with pytest.raises(gl.UnknownLinkError, match="terminal 9"):
        atlas.canonical_graph(m, ground=4, terminals=(9,))
    with pytest.raises(gl.DataFormatError, match="gl.Mechanism"):
        atlas.isomorphic(m, {"links": [1]})
    with pytest.raises(gl.DataFormatError, match="level"):
        atlas.canonical_graph(m, level="x")
    with pytest.raises(gl.DataFormatError, match="max_links"):
        atlas.count_table(12)


def test_small_cases_have_no_gear_pairs_to_place():
    assert atlas.geared_chains(2, 1) == ()  # a lone turning pair has no gear pair
    assert len(atlas.geared_chains(3, 1)) == 1
    (m,) = atlas.geared_chains(3, 1)
    assert [str(c) for c in gl.fundamental_circuits(m)] == ["(2,3)(1)"]
    assert sympy.Symbol("e_2_3") == m.gear_pairs[0].e
