"""The atlas of geared kinematic chains: counts against the literature, the structural rules
checked on every chain by the core (not by the enumeration), an independent brute-force
enumeration for small chains, and isomorphism up to renumbering and label renaming.

Published counts are typed from the sources: Tsai and Lin (1989, abstract): no
non-fractionated two-dof train with five or fewer links, 2 rotation graphs with six and 20
with seven links; Chen, Yao and Lee (2003): "50 two-DOF seven-link GKC"; Yang, Ding et al.
(2019, abstract): 27 and 152 rotation graphs, 81 and 647 displacement graphs with six and
seven links; Buchsbaum and Freudenstein (1970) as quoted: 2 four-link and 6 five-link trains.
"""

import datetime
import itertools
import json
import pathlib
import random

import numpy as np
import networkx as nx
import pytest
import sympy

import gearlib as gl
from gearlib.synthesis import _chains, _trees, atlas
import atlas_brute
from cli_tools import run


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


# --------------------------------------------------------------------- counting to nine links
# Yang, Ding et al. (2019, abstract): 81, 647, 6360 and 71,837 displacement graphs, 27, 152,
# 1070 and 8654 rotation graphs of one-dof trains with 6, 7, 8 and 9 links.
YANG_DING = {6: (81, 27), 7: (647, 152), 8: (6360, 1070), 9: (71837, 8654)}


@pytest.mark.parametrize("links", [6, 7, 8])
def test_chain_counts_match_yang_and_ding_up_to_eight_links(links):
    c = atlas.chain_counts(links)
    assert (c.links, c.dof, c.coaxial, c.kinematic) == (links, 1, *YANG_DING[links])
    assert (c.count("coaxial"), c.count("kinematic")) == YANG_DING[links]


@pytest.mark.parametrize(("links", "dof"), [(3, 1), (4, 1), (5, 1), (5, 2), (6, 1), (6, 2), (6, 3), (7, 2)])
def test_chain_counts_are_the_lengths_of_the_atlas(links, dof):
    """Counted without mechanisms (chain_counts) and built as mechanisms (geared_chains): one number."""
    for frac in (False, True, "only"):
        c = atlas.chain_counts(links, dof, fractionated=frac)
        assert c.coaxial == len(atlas.geared_chains(links, dof, fractionated=frac))
        assert c.kinematic == len(atlas.geared_chains(links, dof, fractionated=frac, level="kinematic"))


def test_count_table_reaches_eight_links_and_knows_nine():
    rows = atlas.count_table(8)
    by = {(r.links, r.dof, r.level, r.source): r for r in rows}
    assert by[(8, 1, "coaxial", "Yang, Ding et al. (2019)")].enumerated == 6360
    assert by[(8, 1, "kinematic", "Yang, Ding et al. (2019)")].enumerated == 1070
    assert {(p.links, p.level, p.count) for p in atlas.PUBLISHED_COUNTS if p.links == 9} == {
        (9, "coaxial", 71837), (9, "kinematic", 8654)}


def test_counts_in_two_processes_are_the_counts_in_one():
    one, two = atlas.chain_counts(7, 1), atlas.chain_counts(7, 1, workers=2)
    assert (one.coaxial, one.kinematic) == (two.coaxial, two.kinematic) == YANG_DING[7]


@pytest.mark.parametrize(
    ("kwargs", "words"),
    [({"n_links": 1}, "n_links"), ({"n_links": 10}, "n_links must be an integer from 2 to 9"),
     ({"n_links": 7.0}, "n_links"), ({"n_links": 6, "dof": 0}, "dof"), ({"n_links": 6, "dof": True}, "dof"),
     ({"n_links": 6, "fractionated": "yes"}, "fractionated"), ({"n_links": 6, "workers": 0}, "workers")],
)
def test_bad_count_arguments_give_clear_errors(kwargs, words):
    with pytest.raises(gl.DataFormatError, match=words):
        atlas.chain_counts(**kwargs)


def test_a_count_names_its_levels():
    with pytest.raises(gl.DataFormatError, match="level"):
        atlas.chain_counts(5).count("rotation")


# --------------------------------------------------------------------- the search, checked by networkx
def _skeleton_graph(groups, triples, with_groups=True):
    """A skeleton as a networkx graph, built here: link, group and gear-pair nodes."""
    g = nx.Graph()
    links = {v for t in triples for v in t} | {v for grp in groups for v in grp}
    g.add_nodes_from((("l", v) for v in links), kind="link")
    if with_groups:
        for k, grp in enumerate(groups):
            g.add_node(("g", k), kind="group")
            g.add_edges_from(((("g", k), ("l", v)) for v in grp), kind="axis")
    for k, (a, b, c) in enumerate(triples):
        g.add_node(("p", k), kind="pair")
        g.add_edges_from([(("p", k), ("l", a)), (("p", k), ("l", b))], kind="mesh")
        g.add_edge(("p", k), ("l", c), kind="carrier")
    return g


def _vf2_classes(graphs):
    """The isomorphism class of each graph (an index), by Weisfeiler-Lehman hash and VF2."""
    reps, out = {}, []
    same = {"node_match": lambda x, y: x["kind"] == y["kind"], "edge_match": lambda x, y: x["kind"] == y["kind"]}
    for g in graphs:
        bucket = reps.setdefault(nx.weisfeiler_lehman_graph_hash(g, node_attr="kind", edge_attr="kind"), [])
        for rep, label in bucket:
            if nx.is_isomorphic(g, rep, **same):
                out.append(label)
                break
        else:
            label = sum(len(b) for b in reps.values())
            bucket.append((g, label))
            out.append(label)
    return out


def _generic_triples(n, triples, seed=11):
    """Rank of the Willis rows and the null-space basis, numpy with random ratios (not gearlib's test)."""
    rnd = random.Random(seed)
    w = np.zeros((len(triples), n))
    for row, (a, b, c) in zip(w, triples):
        e = rnd.choice([-1, 1]) * rnd.uniform(0.3, 3.0)
        row[b] += 1
        row[a] -= e
        row[c] += e - 1
    _, s, vt = np.linalg.svd(w)
    rank = int((s > 1e-9).sum())
    return rank, vt[rank:].T


def _valid(n, triples):
    if {v for t in triples for v in t} != set(range(n)):
        return False
    rank, basis = _generic_triples(n, triples)
    return rank == len(triples) and all(np.abs(basis[i] - basis[j]).max() > 1e-6
                                        for i, j in itertools.combinations(range(n), 2))


@pytest.mark.parametrize(("links", "dof"), [(5, 1), (6, 1), (6, 2), (7, 2)])
def test_the_pruned_search_finds_each_chain_of_a_tree_once(links, dof):
    """On every hypertree: every choice of gear pairs (all combinations, filtered with numpy)
    falls into the VF2 isomorphism class of exactly one chain the search keeps."""
    picks = links - 1 - dof
    for groups in _trees.shapes(links):
        kept = _chains._tree_chains(links, groups, picks)
        cands = _chains._candidates(links, groups)
        every = [t for t in itertools.combinations(cands, picks) if _valid(links, t)]
        labels = _vf2_classes([_skeleton_graph(groups, t) for t in kept + every])
        assert len(set(labels[: len(kept)])) == len(kept), groups  # pairwise non-isomorphic
        assert set(labels[len(kept):]) == set(labels[: len(kept)]), groups  # and every chain is one of them
        assert all(_valid(links, t) for t in kept)


def _networkx_hypertrees(n):
    """Hypertrees from networkx's non-isomorphic trees (bipartite, groups of degree >= 2)."""
    out = []
    for k in range(1, n):
        for tree in nx.nonisomorphic_trees(n + k):
            colour = nx.bipartite.color(tree)
            for side in (0, 1):
                links = [v for v in tree if colour[v] == side]
                groups = [v for v in tree if colour[v] != side]
                if len(links) == n and all(tree.degree(g) >= 2 for g in groups):
                    out.append(tree)
    return out


@pytest.mark.parametrize("links", [3, 4, 5, 6, 7])
def test_hypertrees_grown_link_by_link_are_networkx_trees(links):
    ours = [nx.Graph((("l", v), ("g", k)) for k, g in enumerate(groups) for v in g) for groups in _trees.shapes(links)]
    for g in ours:
        nx.set_node_attributes(g, {node: node[0] for node in g}, "kind")
        assert nx.is_tree(g) and all(g.degree(x) >= 2 for x in g if x[0] == "g")
    theirs = _networkx_hypertrees(links)
    assert len(ours) == len(theirs)
    # pairwise non-isomorphic with links on links: every class once
    labels = _vf2_classes_plain(ours)
    assert len(set(labels)) == len(ours)


def _vf2_classes_plain(graphs):
    out, reps = [], []
    for g in graphs:
        for k, r in enumerate(reps):
            if nx.is_isomorphic(g, r, node_match=lambda x, y: x["kind"] == y["kind"]):
                out.append(k)
                break
        else:
            reps.append(g)
            out.append(len(reps) - 1)
    return out


@pytest.mark.parametrize("with_groups", [True, False])
def test_canonical_codes_decide_isomorphism_as_vf2_does(with_groups):
    sks = _chains.skeletons(7, 1) + _chains.skeletons(6, 2)
    codes = [_chains.canonical(sk.n, sk.groups, sk.triples, with_groups=with_groups)[0] for sk in sks]
    labels = _vf2_classes([_skeleton_graph(sk.groups, sk.triples, with_groups) for sk in sks])
    pairs = {(c, lab) for c, lab in zip(codes, labels)}
    assert len(pairs) == len(set(codes)) == len(set(labels))  # the same partition
    rnd = random.Random(5)
    for sk in rnd.sample(sks, 60):  # renumbered, pairs reordered and gears swapped: the same code
        p = list(range(sk.n))
        rnd.shuffle(p)
        groups = [tuple(p[v] for v in g) for g in sk.groups][::-1]
        triples = [(p[b], p[a], p[c]) for a, b, c in sk.triples]
        rnd.shuffle(triples)
        assert _chains.canonical(sk.n, groups, triples, with_groups=with_groups)[0] == codes[sks.index(sk)]


def _reference_canonical(n, groups, triples, with_groups):
    """The canonical search as gearlib wrote it when the atlas stopped at eight links (dicts and
    edge names, no pruning by automorphisms), kept here: the chains' names come from it."""
    adj, kind, node = {i: [] for i in range(n)}, dict.fromkeys(range(n), 0), n
    for g in groups if with_groups else ():
        adj[node], kind[node] = [("axis", v) for v in g], 1
        for v in g:
            adj[v].append(("axis", node))
        node += 1
    for a, b, c in triples:
        adj[node], kind[node] = [("mesh", a), ("mesh", b), ("carrier", c)], 2
        adj[a].append(("mesh", node))
        adj[b].append(("mesh", node))
        adj[c].append(("carrier", node))
        node += 1

    def refine(colour):
        count = len(set(colour.values()))
        while True:
            sig = {v: (colour[v], tuple(sorted((k, colour[u]) for k, u in adj[v]))) for v in adj}
            order = {s: i for i, s in enumerate(sorted(set(sig.values())))}
            colour = {v: order[sig[v]] for v in adj}
            if len(order) == count:
                return colour
            count = len(order)

    best = []

    def search(colour):
        colour = refine(colour)
        cells = {}
        for v in range(n):
            cells.setdefault(colour[v], []).append(v)
        open_cells = [c for c in sorted(cells) if len(cells[c]) > 1]
        if not open_cells:
            perm = {v: i for i, v in enumerate(sorted(range(n), key=colour.__getitem__))}
            g = tuple(sorted(tuple(sorted(perm[v] for v in grp)) for grp in groups)) if with_groups else ()
            t = tuple(sorted((min(perm[a], perm[b]), max(perm[a], perm[b]), perm[c]) for a, b, c in triples))
            best.append((g, t))
            return
        for v in cells[open_cells[0]]:
            search({u: 2 * c + (0 if u == v else 1) for u, c in colour.items()})

    search(dict(kind))
    return min(best)


@pytest.mark.parametrize(("links", "dof"), [(5, 1), (6, 1), (6, 2), (7, 1), (7, 2)])
def test_chain_names_are_the_numbering_they_always_had(links, dof):
    """Each chain of the catalogue is its own canonical form under the reference search, and the
    catalogue is in the order of those codes: GKC n-dof-k names the chain it always named."""
    cat = atlas._catalogue(links, dof)
    keys = []
    for sk, frac, kin in cat:
        code = _reference_canonical(links, sk.groups, sk.triples, True)
        assert code == (sk.groups, sk.triples)
        assert _reference_canonical(links, sk.groups, sk.triples, False) == kin
        keys.append((frac, kin, len(sk.groups), code))
    assert keys == sorted(keys) and len(set(keys)) == len(keys)


# --------------------------------------------------------------------- an enumeration that shares no code
def _shape_index(n, groups_list):
    """For each hypertree given by its groups, the index of the isomorphic one in _trees.shapes(n) (VF2)."""
    def graph(groups):
        g = nx.Graph((("l", v), ("g", k)) for k, grp in enumerate(groups) for v in grp)
        nx.set_node_attributes(g, {x: x[0] for x in g}, "kind")
        return g

    buckets = {}
    for k, shape in enumerate(_trees.shapes(n)):
        g = graph(shape)
        buckets.setdefault(nx.weisfeiler_lehman_graph_hash(g, node_attr="kind"), []).append((g, k))
    out = []
    for groups in groups_list:
        g = graph(groups)
        (k,) = [k for h, k in buckets.get(nx.weisfeiler_lehman_graph_hash(g, node_attr="kind"), [])
                if nx.is_isomorphic(g, h, node_match=lambda x, y: x["kind"] == y["kind"])]
        out.append(k)
    return out


@pytest.mark.parametrize("links", [6, 7])
def test_an_independent_enumeration_agrees_hypertree_by_hypertree(links):
    """tests/atlas_brute.py (networkx trees, every combination of gear pairs, the counting rule,
    VF2 orbits and isomorphism) against gearlib's search: the same number of displacement graphs
    on every hypertree, and the same partition into rotation graphs as gearlib's canonical codes."""
    trees = atlas_brute.displacement_graphs(links)
    index = _shape_index(links, [t["groups"] for t in trees])
    assert sorted(index) == list(range(len(_trees.shapes(links))))  # every hypertree once
    for t, k in zip(trees, index):
        groups = tuple(frozenset(g) for g in _trees.shapes(links)[k])
        assert len(_chains._tree_chains(links, groups, links - 2)) == len(t["chains"]), t["groups"]
    chains = [c for t in trees for c in t["chains"]]
    labels = atlas_brute.rotation_classes(links, chains)
    codes = [_chains.canonical(links, (), c, with_groups=False)[0] for c in chains]
    assert len(set(zip(codes, labels))) == len(set(codes)) == len(set(labels))
    assert (len(chains), len(set(labels))) == YANG_DING[links]


def test_nine_links_hypertree_by_hypertree_against_the_stored_independent_run():
    """The stored run of tests/atlas_brute.py at nine links lists its displacement graphs per
    hypertree: the hypertrees are gearlib's, one to one (VF2), and gearlib's search finds as many
    chains on each (about eight seconds for all of them). Its rotation-graph count is compared
    with gearlib's stored run by the test above."""
    brute = json.loads(BRUTE_9.read_text(encoding="utf-8"))
    assert brute["command"] == "python tests/atlas_brute.py 9 --save tests/data/atlas_brute_9.json"
    assert sum(t["coaxial"] for t in brute["hypertrees"]) == brute["coaxial"]
    index = _shape_index(9, [t["groups"] for t in brute["hypertrees"]])
    shapes = _trees.shapes(9)
    assert sorted(index) == list(range(len(shapes)))
    for t, k in zip(brute["hypertrees"], index):
        kept = _chains._tree_chains(9, tuple(frozenset(g) for g in shapes[k]), 7)
        assert len(kept) == t["coaxial"], t["groups"]


# --------------------------------------------------------------------- the stored nine-link run
def test_the_stored_run_says_how_it_was_made():
    stored = atlas.stored_counts()
    assert [(c.links, c.dof, c.fractionated) for c in stored.counts] == [(8, 1, False), (9, 1, False)]
    assert stored.command.startswith("python -m gearlib atlas --links 8 9 ")
    assert datetime.datetime.fromisoformat(stored.date).tzinfo is not None
    assert "CPUs" in stored.machine and stored.peak_memory_mb > 0
    assert all(c.seconds > 0 for c in stored.counts) and stored.seconds == sum(c.seconds for c in stored.counts)
    nine = {r.level: r for r in stored.rows if r.links == 9}
    assert {lv: (r.published, r.source) for lv, r in nine.items()} == {
        "coaxial": (YANG_DING[9][0], "Yang, Ding et al. (2019)"), "kinematic": (YANG_DING[9][1], "Yang, Ding et al. (2019)")}


def test_the_stored_eight_link_counts_are_the_literature_and_the_enumeration_now():
    (eight,) = [c for c in atlas.stored_counts().counts if c.links == 8]
    now = atlas.chain_counts(8)
    assert (eight.coaxial, eight.kinematic) == (now.coaxial, now.kinematic) == YANG_DING[8]


BRUTE_9 = pathlib.Path(__file__).with_name("data") / "atlas_brute_9.json"


def test_the_published_nine_link_counts_are_four_and_two_more_than_both_enumerations():
    """Yang, Ding et al. (2019) print 71,837 displacement and 8654 rotation graphs of nine links.
    gearlib's search and the independent enumeration of tests/atlas_brute.py (run once, stored
    in tests/data/atlas_brute_9.json; the next test compares them hypertree by hypertree) both
    find 71,833 and 8652, with the rules under which all three agree for six to eight links.
    The paper's surplus (4 and 2) cannot be named without its atlas, which was not available;
    PUBLISHED_COUNTS says so beside the two counts."""
    (nine,) = [c for c in atlas.stored_counts().counts if c.links == 9]
    brute = json.loads(BRUTE_9.read_text(encoding="utf-8"))
    assert (brute["links"], brute["dof"]) == (9, 1)
    assert (nine.coaxial, nine.kinematic) == (brute["coaxial"], brute["kinematic"])
    assert (YANG_DING[9][0] - nine.coaxial, YANG_DING[9][1] - nine.kinematic) == (4, 2)
    notes = {p.level: p.note for p in atlas.PUBLISHED_COUNTS if (p.links, p.dof) == (9, 1)}
    assert notes["coaxial"].startswith("4 more than") and notes["kinematic"].startswith("2 more than")


def test_a_broken_record_is_a_clear_error(tmp_path):
    missing = tmp_path / "none.json"
    with pytest.raises(gl.FileFormatError, match="none.json: cannot read"):
        atlas.stored_counts(missing)
    bad = tmp_path / "bad.json"
    bad.write_text('{"counts": [{"links": 9}]}')
    with pytest.raises(gl.FileFormatError, match="bad.json: not a record of chain counts"):
        atlas.stored_counts(bad)


# --------------------------------------------------------------------- the command line
def test_atlas_command_prints_the_counts_beside_the_published_ones(tmp_path):
    out = run("atlas", "--links", "6", "7")
    assert out.returncode == 0, out.stderr
    assert "81   published 81 (Yang, Ding et al. (2019)): agrees" in out.stdout
    assert "published 26 (Tsai (1987)): differs by +1" in out.stdout
    data = json.loads(run("atlas", "--links", "7", "--dof", "2", "--json").stdout)
    (seven,) = data["atlas"]
    assert {lv["level"]: lv["enumerated"] for lv in seven["levels"]} == {"coaxial": 50, "kinematic": 20}
    assert all(p["agrees"] for lv in seven["levels"] for p in lv["published"])
    path = tmp_path / "counts.json"
    assert run("atlas", "--links", "6", "--save", str(path)).returncode == 0
    stored = atlas.stored_counts(path)
    assert [(c.links, c.coaxial, c.kinematic) for c in stored.counts] == [(6, *YANG_DING[6])]
    assert stored.command == f"python -m gearlib atlas --links 6 --dof 1 --save {path}"


@pytest.mark.parametrize(("args", "words"), [(("--links", "10"), "--links must be from 2 to 9, got 10"),
                                             (("--links", "6", "--dof", "0"), "--dof must be at least 1"),
                                             (("--links", "6", "--workers", "0"), "--workers must be from 1 to 64")])
def test_atlas_command_errors_are_one_line(args, words):
    out = run("atlas", *args)
    assert out.returncode == 2 and out.stderr.strip().count("\n") == 0 and words in out.stderr


def _counting_rule(n, triples):
    """Every link in a gear pair, and no set of k >= 2 links holding k - 1 or more of the gear
    pairs (Grübler's count on every sub-chain: none rigid, none with a pair too many)."""
    if {v for t in triples for v in t} != set(range(n)):
        return False
    masks = [sum(1 << v for v in t) for t in triples]
    return not any(sum(1 for m in masks if m & sub == m) >= sub.bit_count() - 1
                   for sub in range(1 << n) if sub.bit_count() >= 2)


@pytest.mark.parametrize(("links", "dof"), [(6, 1), (7, 1), (7, 2)])
def test_generic_ratios_and_the_counting_rule_reject_the_same_choices(links, dof):
    """Every choice of gear pairs on every hypertree: degenerate for random ratios (numpy)
    exactly when some sub-chain has too many gear pairs."""
    picks = links - 1 - dof
    for groups in _trees.shapes(links):
        for triples in itertools.combinations(_chains._candidates(links, groups), picks):
            assert _valid(links, triples) == _counting_rule(links, triples), (groups, triples)


def _leaves(sk, with_groups):
    """How many leaves the canonical search visits on a skeleton (its symmetry, roughly)."""
    from gearlib.synthesis import _canon
    from unittest import mock

    seen = []
    real = _canon.code_of
    with mock.patch.object(_canon, "code_of", lambda *a: seen.append(1) or real(*a)):
        _canon.canonical(sk.n, sk.groups, sk.triples, with_groups=with_groups)
    return len(seen)


@pytest.mark.parametrize("with_groups", [True, False])
def test_canonical_codes_of_the_most_symmetric_chains_do_not_depend_on_the_numbering(with_groups):
    """The chains whose search tree branches most (many symmetric planets or gears): renumbered
    at random, each keeps its code; and chains of different codes are not isomorphic (VF2)."""
    sks = [_chains.Skeleton(n, tuple(sorted(g)), t) for n, axes in ((8, 6), (9, 8)) for g in _trees.shapes(n)
           if len(g) >= axes for t in _chains._tree_chains(n, g, n - 2)]  # many axes: many symmetric branches
    deep = [sk for sk in sks if _leaves(sk, with_groups) >= 6]
    assert len(deep) >= 20
    rnd = random.Random(3)
    codes = []
    for sk in deep:
        code = _chains.canonical(sk.n, sk.groups, sk.triples, with_groups=with_groups)[0]
        codes.append(code)
        for _ in range(4):
            p = list(range(sk.n))
            rnd.shuffle(p)
            triples = [(p[b], p[a], p[c]) if rnd.random() < 0.5 else (p[a], p[b], p[c]) for a, b, c in sk.triples]
            rnd.shuffle(triples)
            groups = [tuple(p[v] for v in g) for g in sk.groups]
            rnd.shuffle(groups)
            assert _chains.canonical(sk.n, groups, triples, with_groups=with_groups)[0] == code
    labels = _vf2_classes([_skeleton_graph(sk.groups, sk.triples, with_groups) for sk in deep])
    assert len({(c, lab) for c, lab in zip(codes, labels)}) == len(set(codes)) == len(set(labels))
