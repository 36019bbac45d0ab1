"""Kinematic units (chapter 2): Liu, Chen and Chang's examples, the catalogue, and properties.

Expected units and linkages are those the paper states (Sec. 2, 4.1, 5) for its reconstructed
figures (seed notes, section 5); the count of ten KU types is the paper's and is recounted here
by brute force, independently of the library's isomorphism test.
"""

import itertools
import json

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import gearlib as gl
from cli_tools import run


def units_of(name):
    return gl.kinematic_units(gl.catalog.load(name))


# --------------------------------------------------------------------- the paper's examples
def test_fig1_two_units_sharing_a_two_link_chain():
    frac = units_of("liu_chen_fig1")
    assert [(u.carrier, set(u.gears), u.type) for u in frac.units] == [(5, {4, 1}, "K3-1"), (3, {5, 2, 1}, "K4-1S")]
    (link,) = frac.linkages
    assert link.kind == "2-link chain" and set(link.links) == {1, 5} and set(link.units) == {1, 2}
    ku2 = frac.unit(2)
    gg = [e for e in ku2.thin_edges if e.kind == "g-g"]
    assert len(gg) == 1 and set(gg[0].links) == {1, 5} and gg[0].axis == "a"


def test_fig3a_three_k3_1_around_a_coaxial_triangle():
    frac = units_of("liu_chen_fig3a")
    assert [u.type for u in frac.units] == ["K3-1"] * 3
    assert sorted(u.carrier for u in frac.units) == [4, 4, 5]  # two units on one carrier
    (link,) = frac.linkages
    assert link.kind == "coaxial triangle" and set(link.links) == {2, 4, 5} and set(link.units) == {1, 2, 3}


def test_transmission_has_two_units_one_of_six_links_and_three_fges():
    frac = units_of("liu_chen_transmission")
    ku1, ku2 = frac.units
    assert ku1.carrier == 4 and set(ku1.gears) == {2, 3, 5} and ku1.type == "K4-1S"
    assert ku2.carrier == 5 and ku2.size == 6 and ku2.type is None and ku2.label == "6-link KU"
    (link,) = frac.linkages
    assert link.kind == "2-link chain" and set(link.links) == {2, 5}
    fges = gl.fundamental_geared_entities(frac.mechanism)
    assert {(f.carrier, frozenset(f.links)) for f in fges} == {
        (4, frozenset({4, 2, 3, 5})), (5, frozenset({5, 1, 6, 2})), (5, frozenset({5, 1, 7, 8}))}


def test_units_of_the_wrist_and_of_a_bevel_differential():
    frac = units_of("chen_wrist")
    assert [u.type for u in frac.units] == ["K3-1", "K3-1", "K4-1S"] and frac.outside == (0,)
    assert [c.kind for c in frac.linkages] == ["coaxial triangle"]
    diff = gl.kinematic_units(gl.catalog.car_differential())
    loop = diff.units[1]
    assert loop.type is None and len(loop.redundant_pairs) == 1 and "gear loop" in loop.label


# --------------------------------------------------------------------- the catalogue
def _brute_force_types(with_marks):
    """Orbits of (gear tree, axis partition[, common coaxial gears]) under renumbering, counted by
    taking the smallest relabelled form over all permutations (no networkx)."""
    found = {}
    for g in (2, 3, 4):
        for prufer in itertools.product(range(g), repeat=max(g - 2, 0)):
            # decode the Pruefer sequence into a labelled tree
            degree = [1] * g
            for x in prufer:
                degree[x] += 1
            edges, seq = [], list(prufer)
            for x in seq:
                leaf = min(i for i in range(g) if degree[i] == 1)
                edges.append((leaf, x))
                degree[leaf] -= 1
                degree[x] -= 1
            u, v = [i for i in range(g) if degree[i] == 1]
            edges.append((u, v))
            for labels in itertools.product(range(g), repeat=g):
                if any(labels[a] == labels[b] for a, b in edges):
                    continue
                classes = {}
                for i, lab in enumerate(labels):
                    classes.setdefault(lab, []).append(i)
                mark_options = [()]
                if with_marks:
                    mark_options = []
                    per_class = []
                    for members in classes.values():
                        subsets = [()] + [c for r in range(2, len(members) + 1)
                                          for c in itertools.combinations(members, r)]
                        per_class.append(subsets)
                    mark_options = [tuple(x for part in choice for x in part)
                                    for choice in itertools.product(*per_class)]
                for marks in mark_options:
                    gg = sum(max(0, sum(1 for m in marks if labels[m] == lab) - 1) for lab in set(labels))
                    forms = []
                    for perm in itertools.permutations(range(g)):
                        e = tuple(sorted(tuple(sorted((perm[a], perm[b]))) for a, b in edges))
                        part = tuple(sorted(tuple(sorted(perm[i] for i in c)) for c in classes.values()))
                        mk = tuple(sorted(perm[m] for m in marks))
                        forms.append((e, part, mk))
                    found[(g, min(forms))] = gg
    return found


def test_ten_types_up_to_five_links_counted_by_brute_force():
    bases = _brute_force_types(with_marks=False)
    sizes = [g + 1 for (g, _form) in bases]
    assert len(bases) == 10 and sizes.count(3) == 1 and sizes.count(4) == 2 and sizes.count(5) == 7
    catalogue = gl.ku_catalogue()
    assert len(catalogue) == 10
    assert [e.name for e in catalogue] == ["K3-1", "K4-1", "K4-2"] + [f"K5-{i}" for i in range(1, 8)]


def test_s_and_d_variants_are_exactly_those_the_paper_names():
    forms = _brute_force_types(with_marks=True)
    assert sum(1 for gg in forms.values() if gg == 1) == 6 and sum(1 for gg in forms.values() if gg == 2) == 2
    names = {e.name for e in gl.ku_catalogue(variants=True) if e.gg_edges}
    # Tables 2 and 3 of Liu, Chen and Chang
    assert names == {"K4-1S", "K5-2S", "K5-3S", "K5-4S", "K5-6S", "K5-7S", "K5-4D", "K5-7D"}


def _relabel(mech, mapping, axis_map):
    data = mech.to_dict()
    data["links"] = {mapping[k]: v for k, v in data["links"].items()}
    data["turning_pairs"] = [[mapping[a], mapping[b], axis_map.get(lab, lab)] for a, b, lab in data["turning_pairs"]]
    for gp in data["gear_pairs"]:
        gp["gears"] = [mapping[x] for x in gp["gears"]]
        gp.pop("carrier", None)
        gp.pop("ratio", None) if "teeth" in gp else None
    data.pop("layout", None)
    data["ground"] = mapping[data["ground"]]
    data.pop("inputs", None)
    return gl.Mechanism.from_dict(data)


@pytest.mark.parametrize("name", ["liu_chen_fig1", "liu_chen_fig3a", "liu_chen_transmission", "simpson"])
def test_classification_does_not_depend_on_link_numbers_or_axis_names(name):
    mech = gl.catalog.load(name)
    ids = list(mech.link_ids)
    mapping = dict(zip(ids, [100 + 7 * i for i in reversed(range(len(ids)))]))
    axes = sorted({tp.axis for tp in mech.turning_pairs})
    axis_map = dict(zip(axes, [f"z{i}" for i in range(len(axes))][::-1]))
    renamed = gl.kinematic_units(_relabel(mech, mapping, axis_map))
    original = gl.kinematic_units(mech)
    assert sorted(u.label for u in renamed.units) == sorted(u.label for u in original.units)
    assert sorted(c.kind for c in renamed.linkages) == sorted(c.kind for c in original.linkages)


def test_each_catalogue_entry_is_recognised_as_itself():
    for entry in gl.ku_catalogue(variants=True):
        unit = entry.unit()
        assert gl.ku_types.classify(unit) == (entry.name, entry.base)


# --------------------------------------------------------------------- the atlas
def test_every_one_dof_five_link_and_two_dof_six_link_chain_is_fractionated():
    types, full = set(), set()
    for n, f in ((5, 1), (6, 2)):
        chains = gl.atlas.geared_chains(n, f)
        assert chains
        for m in chains:
            frac = gl.kinematic_units(m)
            assert frac.units and all(u.type is not None for u in frac.units)
            types |= {u.base_type for u in frac.units}
            full |= {u.type for u in frac.units}
            if (n, f) == (6, 2):  # Liu and Chen, Fig. 3: three units around a coaxial triangle
                assert len(frac.units) == 3 and any(c.kind == "coaxial triangle" for c in frac.linkages)
    assert len(types) == 10  # "there are 10 distinct KUs", Liu, Chen and Chang Sec. 2
    assert types == {e.name for e in gl.ku_catalogue()}
    assert full > types


# --------------------------------------------------------------------- properties
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 10**6), st.integers(3, 14), st.integers(1, 3))
def test_units_partition_the_gear_pairs_and_each_has_one_carrier(seed, n, dof):
    try:
        m = gl.random_mechanism(n, dof=dof, rng=seed)
    except ValueError:
        return
    frac = gl.kinematic_units(m)
    seen = []
    for u in frac.units:
        pairs = u.gear_pairs + u.redundant_pairs
        assert {gp.carrier for gp in pairs} == {u.carrier}
        assert u.carrier not in u.gears
        assert len(u.gear_pairs) == len(u.gears) - 1  # a tree of gear pairs
        seen += [id(gp) for gp in pairs]
    assert sorted(seen) == sorted(id(gp) for gp in m.gear_pairs)
    for c in frac.linkages:
        if c.kind != "other":
            assert m.coaxial(*c.links[:2])


# --------------------------------------------------------------------- propagation structure
def test_propagation_graph_of_fig1_and_fig3a():
    g = gl.plan(gl.catalog.load("liu_chen_fig1"), ground=5, inputs=[4], output=3).graph()
    assert set(g.edges()) == {("theta_4,5", "KU1"), ("KU1", "KU2"), ("KU2", "theta_3,5")}
    assert g.edges["KU1", "KU2"]["kind"] == "2-link chain"
    g = gl.plan(gl.catalog.load("liu_chen_fig3a"), ground=4, inputs=[1, 6], output="3/5").graph()
    assert {("theta_1,4", "KU1"), ("theta_6,4", "KU2"), ("KU1", "KU3"), ("KU2", "KU3"), ("KU3", "theta_3,5")} \
        <= set(g.edges())
    assert g.edges["KU1", "KU3"]["kind"] == "coaxial triangle"
    # theta_2,5 = theta_2,4 + theta_4,5 = theta_2,4 - theta_5,4 (eq. 10): KU2's output arrives reversed
    assert (g.edges["KU1", "KU3"]["sign"], g.edges["KU2", "KU3"]["sign"]) == (1, -1)
    assert g.edges["KU2", "KU3"]["signal"] == "theta_5,4"


def test_third_gear_plan_tears_the_common_linkage():
    p = gl.plan(gl.catalog.load("liu_chen_transmission"), ground=1, inputs=[4], output=8)
    assert [s.source for s in p.steps] == ["tear", "2-link chain"] and p.n_tears == 1
    assert set(p.steps[0].input) == {2, 5} and p.steps[1].checks == (4,)
    g = p.graph()
    assert ("theta_4,1", "KU1") in g.edges and ("KU1", "KU2") in g.edges and ("KU2", "theta_8,1") in g.edges


def test_plan_errors_name_the_problem():
    m = gl.catalog.load("liu_chen_fig1")
    with pytest.raises(gl.InputError, match="choose a ground"):
        gl.plan(m.replace(ground=None), inputs=[4], output=3)
    with pytest.raises(gl.UnknownLinkError, match="9"):
        gl.plan(m, ground=5, inputs=[9], output=3)
    with pytest.raises(gl.InputError, match="relative to itself"):
        gl.plan(m, ground=5, inputs=["4/4"], output=3)


# --------------------------------------------------------------------- command line
def test_cli_units_json():
    out = run("units", "liu_chen_fig1", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert [u["type"] for u in data["units"]] == ["K3-1", "K4-1S"]
    assert data["common_linkages"] == [{"kind": "2-link chain", "units": ["KU1", "KU2"], "links": [1, 5], "axis": "a"}]
    bad = run("units", "nope.yaml")
    assert bad.returncode == 2 and "Traceback" not in bad.stderr and len(bad.stderr.strip().splitlines()) == 1


def test_catalogue_drawing_of_chosen_entries():
    """draw_ku_catalogue(names=...) draws those units, one per panel titled with its name, so
    that a chapter can split the eighteen panels into figures a reader can read."""
    import matplotlib.pyplot as plt

    names = ["K3-1", "K4-1", "K4-1S", "K4-2"]
    fig, axes = plt.subplots(1, 4)
    gl.units.draw_ku_catalogue(axes, names=names)
    assert [ax.get_title() for ax in axes] == names
    with pytest.raises(gl.InputError, match="K9-1"):
        gl.units.draw_ku_catalogue(axes, names=["K9-1"])
    plt.close(fig)
