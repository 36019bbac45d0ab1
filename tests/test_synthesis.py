"""Differential synthesis reproduces Chen, Yao and Lee (2003): eqs. (3), (7), (8), (10),
(11) and (9) corrected (erratum CYL-E1), every row of Table 1, and the eight-link cases
1-7 of Section 4.1. Expected values are typed from the paper (gamma_{a,b} written e_a_b),
or computed independently with numpy from random numeric gear ratios.
"""

import itertools
import random

import numpy as np
import pytest
import sympy

import gearlib as gl
from gearlib.synthesis import dgm as synthesis

e = sympy.Symbol


def w(k):
    return sympy.Symbol(f"omega_{k}")


def coeffs(expr, terminals):
    expr = sympy.expand(expr)
    return [expr.coeff(w(t)) for t in terminals]


def same(constraint, printed):
    return synthesis.proportional(constraint.coefficients, coeffs(printed, constraint.terminals))


GKC7 = gl.catalog.load("cyl_gkc_5_7_2")
GKC8 = gl.catalog.load("cyl_gkc_8")
DIFF = gl.catalog.load("cyl_standard_differential")


# --------------------------------------------------------------------- equations of the paper
def test_eq_3_standard_differential():
    c = synthesis.terminal_constraint(DIFF, (1, 2, 3), ground=0)
    g32 = e("e_4_2") / e("e_4_3")  # eq. (4)
    printed = (g32 - 1) * w(1) + e("e_5_1") * w(2) - e("e_5_1") * g32 * w(3)
    assert c.count == 1 and same(c, printed) and c.admissible


def test_eq_2_circuit_matrix():
    A, cols = synthesis.circuit_matrix(DIFF, ground=0)
    g42, g43, g51 = e("e_4_2"), e("e_4_3"), e("e_5_1")
    printed = sympy.Matrix([[0, 1, 0, -g42, g42 - 1], [0, 0, 1, -g43, g43 - 1], [1, 0, 0, 0, -g51]])
    assert cols == (1, 2, 3, 4, 5) and A == printed


def test_eq_7_nd3_7_1():
    c = synthesis.terminal_constraint(GKC7, (5, 6, 7), ground=4)
    g = {k: e(f"e_{k[0]}_{k[1]}") for k in ("51", "62", "21", "73")}
    printed = g["51"] * w(5) - g["62"] * g["21"] * w(6) + g["73"] * (g["62"] * g["21"] - 1) * w(7)
    assert same(c, printed) and c.admissible and c.redundant == ()


def test_eq_8_terminals_1_3_6():
    c = synthesis.terminal_constraint(GKC7, (1, 3, 6), ground=4)
    p = e("e_6_2") * e("e_2_1")
    assert same(c, w(1) + (p - 1) * w(3) - p * w(6))
    assert c.redundant == (5, 7) and not c.admissible  # "links 5 and 7 are redundant"


G41, G50, G63, G74, G76 = (e(f"e_{k}") for k in ("4_1", "5_0", "6_3", "7_4", "7_6"))
MIDDLE = G41 * G50 * G74 - G41 * G63 * G74 + G41 * G63 * G76 - G50 * G63 * G76


def test_eq_9_corrected():
    c = synthesis.terminal_constraint(GKC8, (1, 2, 3), ground=0)
    corrected = G50 * G63 * G76 * w(1) + MIDDLE * w(2) - G41 * G50 * G74 * w(3)
    assert same(c, corrected) and c.admissible
    printed = G50 * G63 * e("e_7_2") * w(1) + MIDDLE * w(2) - G41 * G50 * G74 * w(3)  # CYL-E1: gamma_72
    assert not same(c, printed)
    assert not any(set(gp.gears) == {7, 2} for gp in GKC8.gear_pairs)


def test_eq_10_and_11():
    c10 = synthesis.terminal_constraint(GKC8, (0, 2, 3), ground=1)
    assert same(c10, (G41 * G63 * G74 - G41 * G63 * G76) * w(0) + MIDDLE * w(2) - G41 * G50 * G74 * w(3))
    c11 = synthesis.terminal_constraint(GKC8, (0, 1, 3), ground=2)
    assert same(c11, (G41 * G63 * G74 - G41 * G63 * G76) * w(0) + G50 * G63 * G76 * w(1) - G41 * G50 * G74 * w(3))


# --------------------------------------------------------------------- Table 1 and the procedure
TABLE_1 = [  # ground, terminals, redundant links, identification result (typed from CYL Table 1)
    (1, (3, 4, 6), (5, 7), "—"),
    (3, (1, 2, 4), (5, 6, 7), "—"),
    (3, (1, 2, 6), (4, 5, 7), "—"),
    (3, (1, 4, 6), (5, 7), "—"),
    (3, (2, 4, 6), (1, 5, 7), "—"),
    (4, (1, 3, 5), (2, 6, 7), "—"),
    (4, (1, 3, 6), (5, 7), "—"),
    (4, (1, 3, 7), (2, 5, 6), "—"),
    (4, (1, 5, 6), (2, 3, 7), "—"),
    (4, (1, 5, 7), (2, 3, 6), "—"),
    (4, (1, 6, 7), (5,), "—"),
    (4, (3, 5, 6), (7,), "—"),
    (4, (3, 5, 7), (1, 2, 6), "—"),
    (4, (3, 6, 7), (1, 2, 5), "—"),
    (4, (5, 6, 7), (), "admissible"),
    (6, (1, 3, 4), (5, 7), "—"),
]


def test_table_1_is_reproduced_row_by_row():
    ident = synthesis.identify(GKC7)
    assert ident.n_terminals == 3 and ident.grounds == (1, 3, 4, 6)  # Step 1
    rows = [(r["ground"], r["terminals"], r["redundant"], r["result"]) for r in ident.table()]
    assert rows == TABLE_1
    assert [(c.ground, c.terminals) for c in ident.admissible] == [(4, (5, 6, 7))]


def test_step_1_adjacency_of_gkc_5_7_2():
    adj = synthesis.adjacency(GKC7)
    assert adj[1] == (3, 4, 6) and adj[3] == (1, 2, 4, 6) and adj[4] == (1, 3, 5, 6, 7) and adj[6] == (1, 3, 4)


def test_n3_screening_implies_redundancy():
    for c in synthesis.identify(GKC7).candidates:
        assert set(c.n3_failures) <= set(c.redundant)


def test_eight_link_cases_1_to_7():
    ident = synthesis.identify(GKC8)
    assert ident.grounds == (0, 1, 2, 3, 4, 5, 6)  # "links 0, 1, 2, 3, 4, 5 and 6 can be selected as the ground"
    admissible = [(c.ground, c.terminals) for c in ident.candidates if c.admissible]
    assert admissible == [(0, (1, 2, 3)), (1, (0, 2, 3)), (2, (0, 1, 3)), (3, (0, 1, 2))]
    assert ident.duplicates == {(3, (0, 1, 2)): (1, (0, 2, 3))}  # case 4: isomorphic with ND3-8-19
    assert [(c.ground, c.terminals) for c in ident.admissible] == admissible[:3]
    by_ground = {g: [c for c in ident.candidates if c.ground == g] for g in ident.grounds}
    assert len(by_ground[2]) == 20  # case 3: "among the 20 sets of terminals"
    assert [c.terminals for c in by_ground[4]] == [(2, 5, 6)] and [c.terminals for c in by_ground[6]] == [(2, 4, 5)]
    # case 6 and erratum CYL-N1: 7 is pivoted on 5 too, so four triples; 4, 6, 7 gives two constraints
    assert [c.terminals for c in by_ground[5]] == [(2, 4, 6), (2, 4, 7), (2, 6, 7), (4, 6, 7)]
    assert next(c for c in by_ground[5] if c.terminals == (4, 6, 7)).count == 2
    for g in (4, 5, 6):  # cases 5-7: links 0, 1 and 3 are redundant
        assert all({0, 1, 3} <= set(c.redundant) for c in by_ground[g])


def test_seven_link_atlas_gives_nd3_7_1_among_its_dgms():
    found = synthesis.synthesize(7)
    assert len(found) == 4  # CYL Fig. 3 shows ND3-7-1 ... (at least ND3-7-4 is named); the figure is lost
    target = gl.atlas.canonical_graph(GKC7, ground=4, terminals=(5, 6, 7))
    hits = [chain.name for chain, c in found
            if gl.atlas.isomorphic(gl.atlas.canonical_graph(chain, ground=c.ground, terminals=c.terminals), target)]
    assert len(hits) == 1
    assert synthesis.synthesize(6) == ()


# --------------------------------------------------------------------- independent numeric cross-checks
def _numeric_terminal_space(mech, ground, terminals, ratios):
    """Basis of the terminal speeds of every motion (numpy SVD), for numeric ratios."""
    rows = []
    for gp in mech.gear_pairs:
        (a, b), c = gp.gears, gp.carrier
        r = np.zeros(len(mech.links))
        r[mech.index[b]] += 1
        r[mech.index[a]] -= ratios[gp.gears]
        r[mech.index[c]] += ratios[gp.gears] - 1
        rows.append(r)
    ground_row = np.zeros(len(mech.links))
    ground_row[mech.index[ground]] = 1
    m = np.array(rows + [ground_row])
    _, s, vt = np.linalg.svd(m)
    null = vt[int((s > 1e-10).sum()):].T
    return null[[mech.index[t] for t in terminals]]


@pytest.mark.parametrize(("mech", "ground"), [(GKC7, 4), (GKC7, 3), (GKC8, 2), (GKC8, 5), (DIFF, 0)])
def test_constraints_agree_with_numeric_motions(mech, ground):
    rnd = random.Random(3)
    ratios = {gp.gears: rnd.choice([-1, 1]) * rnd.uniform(0.3, 3) for gp in mech.gear_pairs}
    subs = {gp.symbol: ratios[gp.gears] for gp in mech.gear_pairs}
    for terms in itertools.combinations(synthesis.adjacency(mech)[ground], 3):
        c = synthesis.terminal_constraint(mech, terms, ground=ground)
        space = _numeric_terminal_space(mech, ground, terms, ratios)
        assert c.count == 3 - np.linalg.matrix_rank(space, tol=1e-9)  # independent constraints
        for row in c.rows:  # every motion satisfies every constraint
            vec = np.array([complex(sympy.sympify(v).subs(subs)) for v in row])
            assert np.abs(vec @ space).max() < 1e-8


@pytest.mark.parametrize(("ground", "terms"), [(4, (3, 5, 7)), (4, (1, 6, 7)), (3, (2, 4, 6)), (4, (5, 6, 7))])
def test_redundant_links_do_not_change_the_terminal_relation(ground, terms):
    rnd = random.Random(11)
    base = {gp.gears: rnd.choice([-1, 1]) * rnd.uniform(0.3, 3) for gp in GKC7.gear_pairs}
    c = synthesis.terminal_constraint(GKC7, terms, ground=ground)
    before = _numeric_terminal_space(GKC7, ground, terms, base)
    for x in c.non_terminals:
        changed = {k: (v * 1.7 if x in k or x == GKC7.gear_pair(*k)[0].carrier else v) for k, v in base.items()}
        after = _numeric_terminal_space(GKC7, ground, terms, changed)
        same_space = np.linalg.matrix_rank(np.hstack([before, after]), tol=1e-8) == np.linalg.matrix_rank(before, tol=1e-8)
        assert same_space == (x in c.redundant), x


def _sympy_primitive(values):
    """Coefficients cleared of denominators and common factors with sympy's own cancel, lcm,
    gcd and factor (the route gearlib's polynomial-ring version must reproduce exactly)."""
    values = [sympy.cancel(v) for v in values]
    den = sympy.lcm_list([sympy.fraction(v)[1] for v in values])
    nums = [sympy.cancel(v * den) for v in values]
    common = sympy.gcd_list([n for n in nums if n != 0])
    nums = [sympy.expand(sympy.cancel(n / common)) for n in nums]
    lead = next(n for n in nums if n != 0)
    if sympy.Poly(lead, *sorted(lead.free_symbols, key=str) or [sympy.Symbol("x")]).LC() < 0:
        nums = [-n for n in nums]
    return tuple(sympy.factor(n) for n in nums)


def _relabelled(mech, shift):
    """*mech* with every link id raised by *shift* (ratios renamed to match): with shift 95
    the names mix e_99_96 and e_102_101, which sort differently by name and by sympy."""
    d = mech.to_dict()
    d["links"] = {str(int(k) + shift): v for k, v in d["links"].items()}
    d["turning_pairs"] = [[a + shift, b + shift, axis] for a, b, axis in d["turning_pairs"]]
    d["gear_pairs"] = [{**g, "gears": [x + shift for x in g["gears"]], "carrier": g["carrier"] + shift,
                        "ratio": "e_{}_{}".format(*(x + shift for x in g["gears"]))} for g in d["gear_pairs"]]
    d["ground"] += shift
    d["inputs"] = [x + shift for x in d["inputs"]]
    return gl.Mechanism.from_dict(d)


@pytest.mark.parametrize("mech", [GKC7, GKC8, DIFF, _relabelled(GKC8, 95)], ids=lambda m: f"{m.name} {m.link_ids[0]}")
def test_coefficients_are_the_ones_sympy_factor_prints(mech):
    compared = 0
    for ground in mech.link_ids:
        rest = [x for x in mech.link_ids if x != ground]
        for terms in itertools.islice(itertools.combinations(rest, 3), 0, None, 3):
            c = synthesis.terminal_constraint(mech, terms, ground=ground)
            if c.count != 1:
                continue
            expected = _sympy_primitive(list(c.rows[0]))
            assert c.coefficients == expected and list(map(str, c.coefficients)) == list(map(str, expected))
            compared += 1
    assert compared >= 3


def test_proportional():
    a, b = e("e_1_2"), e("e_2_3")
    assert synthesis.proportional([a, 1, -b], [2 * a, 2, -2 * b])
    assert synthesis.proportional([a, 1, -b], [a / b, 1 / b, -1])
    assert not synthesis.proportional([a, 1, -b], [a, 1, b])
    assert not synthesis.proportional([0, 0], [0, 0]) and not synthesis.proportional([1, 2], [1, 2, 3])


# --------------------------------------------------------------------- bad input
def test_bad_terminals_and_grounds():
    with pytest.raises(gl.InputError, match="ground"):
        synthesis.terminal_constraint(GKC7, (4, 5, 6), ground=4)
    with pytest.raises(gl.InputError, match="twice"):
        synthesis.terminal_constraint(GKC7, (5, 5, 6), ground=4)
    with pytest.raises(gl.UnknownLinkError, match="terminal 9"):
        synthesis.terminal_constraint(GKC7, (5, 9), ground=4)
    with pytest.raises(gl.UnknownLinkError, match="ground"):
        synthesis.terminal_constraint(GKC7, (5, 6), ground=12)
    with pytest.raises(gl.InputError, match="at least one terminal"):
        synthesis.terminal_constraint(GKC7, (), ground=4)
    # a catalogue name stands for its mechanism (issue 25); anything else is refused by name
    assert synthesis.terminal_constraint("cyl_gkc_5_7_2", (5, 6, 7), ground=4).equation == \
        synthesis.terminal_constraint(gl.catalog.load("cyl_gkc_5_7_2"), (5, 6, 7), ground=4).equation
    with pytest.raises(gl.DataFormatError, match="mech: expected a Mechanism"):
        synthesis.terminal_constraint(None, (5, 6, 7), ground=4)


def test_identify_refuses_what_is_not_a_chain_or_the_wrong_dof():
    with pytest.raises(gl.InputError, match="not a geared kinematic chain: turning pairs"):
        synthesis.identify(gl.catalog.car_differential())
    with pytest.raises(gl.InputError, match="needs a chain of 3 dof"):
        synthesis.identify(GKC7, 4)
    with pytest.raises(gl.InputError, match="at least 2"):
        synthesis.identify(GKC7, True)


def test_single_terminal_constraint_and_grounds_option():
    c = synthesis.terminal_constraint(GKC7, 5, ground=4)  # one terminal of a 2-dof chain: free
    assert c.count == 0 and c.equation is None and not c.admissible
    ident = synthesis.identify(GKC7, grounds=[4])
    assert ident.grounds == (4,) and len(ident.candidates) == 10


# --------------------------------------------------------------------- command line, drawings, widget
def test_cli_dgm(capsys):
    from gearlib.cli import main

    assert main(["dgm", "cyl_gkc_8"]) == 0
    out = capsys.readouterr().out
    assert out.count("ground") == 4 and "ground 3" not in out.split("\n", 1)[1]
    assert main(["dgm", "cyl_gkc_5_7_2", "--all", "--json"]) == 0
    import json

    data = json.loads(capsys.readouterr().out)
    assert len(data["assignments"]) == 16 and data["grounds"] == [1, 3, 4, 6]
    assert [a["redundant"] for a in data["assignments"]] == [list(r[2]) for r in TABLE_1]
    assert main(["dgm", "cyl_gkc_5_7_2", "--terminals", "4"]) == 2
    assert "needs a chain of 3 dof" in capsys.readouterr().err


def test_drawings_and_widget():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ident = synthesis.identify(GKC7)
    fig, (ax1, ax2) = plt.subplots(1, 2)
    assert gl.plot_identification(ident, ax=ax1) is ax1
    assert gl.plot_dgm(ident.admissible[0], ax=ax2) is ax2
    assert "ground 4" in ax2.get_title()
    plt.close(fig)
    ex = gl.dgm_explorer([GKC7, GKC8])
    png = ex.update(chain=GKC7.name, ground=4, terminals=(5, 6, 7))
    assert png.startswith(b"\x89PNG") and "admissible" in ex.text
    ex.update(terminals=(1, 3, 6))
    assert "redundant links 5, 7" in ex.text
    ex.update(chain=GKC8.name)
    assert ex.state["chain"] == GKC8.name and ex.state["ground"] == 2


# ------------------------------------------------------------------ issue 25: no workarounds
def test_identification_says_what_it_left_out_and_offers_the_full_list():
    """CYL's eight-link chain: ground 3 with terminals 0, 1, 2 is the mirror image of ground 1
    with terminals 0, 2, 3 (links 1 <-> 3 and 4 <-> 6 exchanged); admissible leaves it out."""
    ident = synthesis.identify(GKC8)
    full = [(c.ground, c.terminals) for c in ident.all_admissible]
    kept = [(c.ground, c.terminals) for c in ident.admissible]
    assert full == [(0, (1, 2, 3)), (1, (0, 2, 3)), (2, (0, 1, 3)), (3, (0, 1, 2))]
    assert kept == full[:3]
    assert [((c.ground, c.terminals), twin) for c, twin in ident.repeats] == [((3, (0, 1, 2)), (1, (0, 2, 3)))]
    assert "1 isomorphic repeat left out" in repr(ident) and "all_admissible" in str(ident)
    assert "left out" not in repr(synthesis.identify(GKC7))


def test_the_constraint_in_numbers():
    """numeric(): the mechanism's own ratios put in, the smallest whole numbers; checked against
    gl.speeds on the same mechanism (an independent solve of every Willis equation)."""
    d = gl.catalog.load("cyl_standard_differential")
    c = synthesis.terminal_constraint(d, (1, 2, 3), ground=0)
    sol = gl.speeds(d, ground=0, inputs={2: 3, 3: 7})
    assert sum(a * sol[t] for a, t in zip(c.numeric(), (1, 2, 3))) == 0
    assert all(isinstance(a, sympy.Integer) for a in c.numeric()) and sympy.gcd_list(list(c.numeric())) == 1
    assert sympy.expand(c.numeric_equation() - sum(a * gl.omega(t) for a, t in zip(c.numeric(), (1, 2, 3)))) == 0
    # other values for some ratios: by symbol or by gear pair (either direction)
    e42 = sympy.Symbol("e_4_2")
    by_symbol, by_pair = c.numeric({e42: 2}), c.numeric({(2, 4): sympy.Rational(1, 2)})
    direct = [sympy.sympify(a).subs({gp.symbol: gp.e for gp in d.gear_pairs if gp.symbol != e42}).subs(e42, 2)
              for a in c.coefficients]
    assert by_symbol == by_pair and synthesis.proportional(by_symbol, direct)
    assert synthesis.terminal_constraint(GKC8, (1, 2, 4), ground=0).numeric() is None or \
        synthesis.terminal_constraint(GKC8, (1, 2, 4), ground=0).count == 1
# --------------------------------------------------------------------- drawing layout
def _segments_cross(p, q, r, s):
    """Proper crossing of segments pq and rs, by the signs of four cross products (computed
    here, independently of gearlib's layout code)."""
    def side(a, b, c):
        v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        return 0 if abs(v) < 1e-12 else (1 if v > 0 else -1)

    return side(p, q, r) * side(p, q, s) < 0 and side(r, s, p) * side(r, s, q) < 0


def _drawing_faults(pos, mech):
    """(pairs of edges that cross, vertices within 5 % of the drawing's size of an edge they
    are not an end of)."""
    edges = {frozenset(tp.links) for tp in mech.turning_pairs} | {frozenset(gp.gears) for gp in mech.gear_pairs}
    edges = [tuple(e) for e in edges]
    crossing = [(e, f) for e, f in itertools.combinations(edges, 2)
                if not set(e) & set(f) and _segments_cross(pos[e[0]], pos[e[1]], pos[f[0]], pos[f[1]])]
    pts = np.array([pos[v] for v in mech.link_ids], dtype=float)
    size = max(np.ptp(pts[:, 0]), np.ptp(pts[:, 1]))
    on_edge = []
    for v in mech.link_ids:
        p = np.array(pos[v], dtype=float)
        for a, b in edges:
            if v in (a, b):
                continue
            x, y = np.array(pos[a], dtype=float), np.array(pos[b], dtype=float)
            t = np.clip(np.dot(p - x, y - x) / np.dot(y - x, y - x), 0, 1)
            if np.linalg.norm(x + t * (y - x) - p) < 0.05 * size:
                on_edge.append((v, (a, b)))
    return crossing, on_edge


def test_chain_layout_draws_the_chapters_chains_without_crossings():
    """Every chain chapter 6 draws is planar (networkx says so), and chain_layout draws it with
    no crossing edge and no link on a foreign edge; the default layout crosses edges in the
    standard differential and in both of CYL's chains, so the test would see a regression."""
    import networkx as nx

    from gearlib.mechanism.plot import graph_layout

    seven = {m.name: m for m in gl.atlas.geared_chains(7, 2)}
    chains = [DIFF, GKC7, GKC8, *gl.atlas.geared_chains(4, 1), *gl.atlas.geared_chains(6, 2),
              *(seven[f"GKC 7-2-{k}"] for k in (7, 18, 24, 25, 49, 50))]
    for mech in chains:
        g = nx.Graph([tp.links for tp in mech.turning_pairs] + [gp.gears for gp in mech.gear_pairs])
        assert nx.check_planarity(g)[0], mech.name
        pos = gl.synthesis.chain_layout(mech)
        assert sorted(pos) == sorted(mech.link_ids)
        crossing, on_edge = _drawing_faults(pos, mech)
        assert crossing == [] and on_edge == [], (mech.name, crossing, on_edge)
        assert gl.synthesis.chain_layout(mech) == pos  # deterministic
    for mech in (DIFF, GKC7, GKC8):
        assert _drawing_faults(graph_layout(mech), mech)[0], mech.name


def test_chain_layout_on_a_non_planar_graph_and_a_given_layout():
    """K3,3 cannot be drawn without a crossing: the layout keeps at most the crossings of the
    layout it starts from. A mechanism's own layout is returned unchanged."""
    from gearlib.synthesis._layout import layout

    nodes = tuple(range(6))
    edges = tuple((a, b) for a in (0, 1, 2) for b in (3, 4, 5))
    start = tuple((v, (float(v % 3), float(v // 3) + 0.1 * v)) for v in nodes)

    def count(pos):
        return sum(1 for e, f in itertools.combinations(edges, 2)
                   if not set(e) & set(f) and _segments_cross(pos[e[0]], pos[e[1]], pos[f[0]], pos[f[1]]))

    pos = dict(layout(nodes, edges, start))
    assert 1 <= count(pos) <= count(dict(start))
    own = {x: (float(i), float(i % 2)) for i, x in enumerate(DIFF.link_ids)}
    assert gl.synthesis.chain_layout(DIFF.replace(layout=own)) == own
