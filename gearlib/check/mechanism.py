"""Checks for the exercises 1.1 to 1.8 of chapter 1, graph representation
(``exercises/01_graph_representation.ipynb``): graphs, carriers, models, Willis equations and
degrees of freedom (:mod:`gearlib.mechanism`). Exercises 1.9 to 1.13 (speeds and ratios)
are in :mod:`gearlib.check.ratios`.

The trains of the exercises are not the chapter's: a planetary whose planet meshes a ring in
the housing and an output ring (exercises 1.1 and 1.3), a stepped-planet reducer (1.2), an
idler (1.5), a planetary with three planets (1.8).
"""

from __future__ import annotations

from fractions import Fraction

import sympy

from ._choice import Choice, LinkId, Parts
from ._core import Prediction, register
from ._design import Matrix
from ._model import Model, Scenario
from ._value import Mistake, Value

__all__ = ["graph_carrier", "graph_model_stepped", "graph_willis_matrix", "graph_compound_ratio", "graph_idler",
           "graph_mistake_derivation", "graph_dof_simpson", "graph_three_planets", "RING_TRAIN"]

RING_TRAIN = {
    "links": {0: "housing", 1: "sun", 2: "planet", 4: "carrier", 5: "output ring"},
    "turning_pairs": [[0, 1, "a"], [1, 4, "a"], [4, 2, "b"], [0, 5, "a"]],
    "gear_pairs": [{"gears": [1, 2], "teeth": [15, 30]},
                   {"gears": [2, 0], "teeth": [30, 75], "type": "internal"},
                   {"gears": [2, 5], "teeth": [30, 78], "type": "internal"}],
}
"""The train of exercises 1.1 and 1.3: the planet meshes the sun, a ring in the housing and
an output ring; no gear pair names its carrier."""


def _mech(data):
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict(data)


# ----------------------------------------------------------------------------- 1.1
@register(
    "graph_carrier", exercise="1.1", title="The carrier of a gear pair", stars=1, minutes=10, kind="compute",
    question="In the train gl.check.mechanism.RING_TRAIN (housing 0 with a ring gear, sun 1, planet 2, link 4, "
             "output ring 5; turning pairs [0, 1, a], [1, 4, a], [4, 2, b], [0, 5, a]), which link is the carrier "
             "of the gear pair (2, 5)?",
    answer=LinkId(links=lambda p: [0, 1, 2, 4, 5], wrong={
        2: "That link is one of the two gears of the pair; the carrier is a third link.",
        5: "That link is one of the two gears of the pair; the carrier is a third link.",
        0: "The housing holds gear 5 on axis a, but not the planet: no path of thin edges with one label joins it "
           "to link 2.",
        1: "Link 1 turns about axis a like gear 5, but it does not hold the planet's axis."},
        generic="The carrier is coaxial with one gear on one axis and with the other gear on another axis."),
)
def graph_carrier():
    gp, _ = _mech(RING_TRAIN).gear_pair(2, 5)
    return gp.carrier


# ----------------------------------------------------------------------------- 1.2
def _stepped(sun, big, small, ring):
    return _mech({
        "links": {1: "sun", 2: "planet", 3: "ring", 4: "carrier"},
        "turning_pairs": [[4, 1, "a"], [4, 3, "a"], [4, 2, "b"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [sun, big]},
                       {"gears": [2, 3], "teeth": [small, ring], "type": "internal"}],
    })


def _stepped_teeth(rng) -> dict:
    while True:
        sun, big, small = rng.randint(15, 30), rng.randint(28, 45), rng.randint(12, 24)
        if big > small + 5:
            return {"sun": sun, "big": big, "small": small, "ring": sun + big + small}


@register(
    "graph_model_stepped", exercise="1.2", title="From a description to data: a stepped planet", stars=2,
    minutes=20, kind="model",
    question="A reducer has a sun (input, {sun} teeth) and a carrier (output) on the central axis, and a ring of "
             "{ring} teeth (internal) in the housing, held. The carrier holds a stepped planet: its larger gear "
             "({big} teeth) meshes the sun, its smaller gear ({small} teeth, keyed to the same shaft) meshes the "
             "ring. Write it as data for gl.Mechanism.from_dict, with the links named 'sun', 'planet', 'ring' and "
             "'carrier'.",
    data={"sun": 18, "big": 36, "small": 15, "ring": 69},
    params=_stepped_teeth,
    answer=Model(("sun", "planet", "ring", "carrier"),
                 [Scenario("carrier", {"sun": 1}), Scenario("ring", {"sun": 1}), Scenario("sun", {"ring": 1})]),
)
def graph_model_stepped(sun, big, small, ring):
    return _stepped(sun, big, small, ring)


# ----------------------------------------------------------------------------- 1.3
_E12, _E20, _E25 = sympy.symbols("e_1_2 e_2_0 e_2_5")


@register(
    "graph_willis_matrix", exercise="1.3", title="The Willis equations as a matrix", stars=2, minutes=15,
    kind="derive",
    question="For the train of exercise 1.1, write one Willis equation per gear pair in the form "
             "a_0 omega_0 + a_1 omega_1 + a_2 omega_2 + a_4 omega_4 + a_5 omega_5 = 0, with the gear ratios as "
             "symbols e_1_2, e_2_0 and e_2_5, and give the coefficients as a matrix: one row per gear pair (any "
             "order, any non-zero multiple), columns for links 0, 1, 2, 4, 5.",
    answer=Matrix(rows_free=True, row_scale=True, symbols=("e_1_2", "e_2_0", "e_2_5"), rows="gear pairs",
                  columns="links 0, 1, 2, 4, 5",
                  generic="Each row is omega_b - omega_c - e_a_b (omega_a - omega_c) for a pair (a, b) on "
                          "carrier c: find each pair's carrier first."),
)
def graph_willis_matrix():
    from ..mechanism.equations import willis_matrix

    return willis_matrix(_mech(RING_TRAIN))


# ----------------------------------------------------------------------------- 1.4
def _compound(stages):
    from ..catalog import compound_train

    return compound_train(stages)


def _two_stages(rng) -> dict:
    return {"a": rng.randint(12, 24), "b": rng.randint(40, 72), "c": rng.randint(12, 24), "d": rng.randint(36, 72)}


@register(
    "graph_compound_ratio", exercise="1.4", title="A compound train by hand", stars=1, minutes=5, kind="compute",
    question="A two-stage compound train on a frame: gear 1 ({a} teeth) drives a gear of {b} teeth on shaft 2; a "
             "gear of {c} teeth on the same shaft drives gear 3 ({d} teeth); all meshes external. Give "
             "omega_3 / omega_1, sign included.",
    data={"a": 18, "b": 54, "c": 12, "d": 48},
    params=_two_stages,
    answer=Value("ratio", mistakes=[
        Mistake(lambda e, p: -e, "Two external meshes reverse the direction twice."),
        Mistake(lambda e, p: [Fraction(-p["a"], p["b"]), Fraction(-p["c"], p["d"])],
                "That is one stage alone: the output turns through both meshes, one after the other."),
    ], generic="Each stage multiplies the speed by -N_driver/N_driven; the intermediate shaft carries both gears."),
)
def graph_compound_ratio(a, b, c, d):
    from ..mechanism.kinematics import ratio

    return ratio(_compound(((a, b), (c, d))), output=3, input=1, ground=0)


# ----------------------------------------------------------------------------- 1.5
_IDLER = Choice(["the size changes", "the sign changes", "both change", "neither changes"], synonyms={
    "the size changes": ["size", "magnitude"], "the sign changes": ["sign", "direction", "it reverses"],
    "both change": ["both"], "neither changes": ["neither", "nothing", "no change"]})


@register(
    "graph_idler", exercise="1.5", title="Predict, then compute: an idler gear", stars=1, minutes=10,
    kind="predict",
    question="Gear 1 ({n1} teeth) drives gear 3 ({n3} teeth) on a frame. An idler gear 2 of {n2} teeth, on its "
             "own shaft in the frame, is put between them (1 meshes 2, 2 meshes 3). First predict what happens to "
             "omega_3 / omega_1 ('the size changes', 'the sign changes', 'both change', 'neither changes') and "
             "record it; then compute omega_3 / omega_1 with the idler.",
    data={"n1": 24, "n2": 31, "n3": 40},
    params=lambda rng: {"n1": rng.randint(14, 30), "n2": rng.randint(17, 45), "n3": rng.randint(32, 80)},
    answer=Value("ratio", mistakes=[
        Mistake(lambda e, p: -e, "That is the ratio without the idler: the idler adds one external mesh."),
        Mistake(lambda e, p: [Fraction(-p["n1"], p["n2"]), Fraction(-p["n2"], p["n3"])],
                "That is one mesh alone: gear 3 is driven through both meshes."),
    ]),
    predict=Prediction(_IDLER, lambda ref, p: "the sign changes",
                       "The idler's teeth cancel: (-N_1/N_2)(-N_2/N_3) = N_1/N_3. It only adds an external mesh, "
                       "which reverses the direction."),
)
def graph_idler(n1, n2, n3):
    from ..mechanism.kinematics import ratio

    return ratio(_mech({"links": [0, 1, 2, 3], "turning_pairs": [[0, 1, "a"], [0, 2, "b"], [0, 3, "c"]],
                        "gear_pairs": [{"gears": [1, 2], "teeth": [n1, n2]}, {"gears": [2, 3], "teeth": [n2, n3]}]}),
                 output=3, input=1, ground=0)


# ----------------------------------------------------------------------------- 1.6
def _derivation(sun, planet, ring) -> dict:
    wrong = Fraction(sun, ring)
    return {"sun": sun, "planet": planet, "ring": ring, "E_printed": wrong, "result_printed": wrong / (wrong - 1)}


def _derivation_teeth(rng) -> dict:
    s, p = rng.randint(16, 30), rng.randint(18, 36)
    return _derivation(s, p, s + 2 * p)


_STEPS = Choice(["1", "2", "3", "4", "5"], wrong={
    "1": "Step 1 is right: an external mesh has a negative ratio.",
    "3": "Step 3 is right: relative to the carrier the two meshes are in series.",
    "4": "Step 4 is right algebra: solve -omega_4 = E (omega_1 - omega_4) for omega_4 again.",
    "5": "Step 5 only puts numbers into step 4; the numbers it is given are already wrong."})


@register(
    "graph_mistake_derivation", exercise="1.6", title="Find the mistake in a derivation", stars=2, minutes=15,
    kind="mistake",
    question="A student derives omega_4/omega_1 for a planetary (sun 1 of {sun} teeth, planet 2 of {planet}, ring "
             "3 of {ring}, carrier 4), ring held. (1) e_(1,2) = -N_1/N_2. (2) e_(2,3) = -N_2/N_3. (3) Relative to "
             "the carrier, omega_3 - omega_4 = e_(1,2) e_(2,3) (omega_1 - omega_4). (4) With omega_3 = 0, "
             "omega_4/omega_1 = E/(E - 1), E = e_(1,2) e_(2,3). (5) E = {E_printed}, so omega_4/omega_1 = "
             "{result_printed}: the carrier turns backwards. Which step is wrong, and what is the right "
             "omega_4/omega_1?",
    data=_derivation(22, 28, 78),
    params=_derivation_teeth,
    answer=Parts({"step": ("the wrong step", _STEPS), "ratio": ("the ratio", Value("ratio", mistakes=[
        Mistake(lambda e, p: p["result_printed"], "That is the derivation's own result: correct the wrong step "
                "first."),
        Mistake(lambda e, p: Fraction(p["sun"], p["ring"]), "That is N_sun/N_ring, the size of the ring's ratio to the "
                "sun with the carrier held; with the ring held the carrier turns, and step 4 still applies."),
    ]))}),
)
def graph_mistake_derivation(sun, planet, ring, E_printed, result_printed):
    from ..mechanism.kinematics import ratio

    from .introduction import _planetary

    return {"step": "2", "ratio": ratio(_planetary(sun, planet, ring), output=4, input=1, ground=3)}


# ----------------------------------------------------------------------------- 1.7
_TRUST = {
    "A": "The turning pairs form a tree and no gear pair repeats the Willis equation of another.",
    "B": "The planar formula and the pair rule give the same number.",
    "C": "Every gear pair has a carrier.",
    "D": "All the gears are spur gears.",
}


@register(
    "graph_dof_simpson", exercise="1.7", title="Degrees of freedom of the Simpson set", stars=2, minutes=15,
    kind="concept",
    question="The Simpson gear set (gl.catalog.simpson(): housing 0, common sun 1, front ring 2, front carrier "
             "and rear ring 3, rear carrier 4, planets 5 and 6). Count its degrees of freedom with the housing "
             "held by the pair rule F = J_R - J_G, and say why the count can be trusted here (reason 'A', 'B', "
             "'C' or 'D').",
    answer=Parts({"dof": ("the degrees of freedom", Value("count", generic="Count the links, the turning pairs "
                                                          "and the gear pairs of the data, then use F = J_R - J_G.")),
                  "reason": ("the reason", Choice(_TRUST, wrong={
                      "B": "The two counts agree whenever the turning pairs form a tree: they are then the same "
                           "formula, and both can be wrong together (as for three planets).",
                      "C": "Every gear pair needs a carrier in any mechanism; that says nothing about redundant "
                           "equations.",
                      "D": "A count of bevel gears can be right, and a count of spur gears wrong; what matters is "
                           "whether the equations are independent."}))}),
)
def graph_dof_simpson():
    from ..catalog import simpson
    from ..mechanism.mobility import dof

    return {"dof": dof(simpson(), 0).rank, "reason": "A"}


# ----------------------------------------------------------------------------- 1.8
def _three_planets(sun, planet):
    ring = sun + 2 * planet
    planets = (5, 6, 7)
    return _mech({
        "links": {1: "sun", 3: "ring", 4: "carrier", 5: "planet A", 6: "planet B", 7: "planet C"},
        "turning_pairs": [[4, 1, "a"], [4, 3, "a"], [4, 5, "b"], [4, 6, "c"], [4, 7, "d"]],
        "gear_pairs": [{"gears": [1, k], "teeth": [sun, planet]} for k in planets]
        + [{"gears": [k, 3], "teeth": [planet, ring], "type": "internal"} for k in planets],
    })


_WHY = {
    "A": "Each extra planet brings one link, one turning pair and two gear pairs, but only one new independent "
         "equation: its second mesh repeats the relation between sun, ring and carrier.",
    "B": "The turning pairs of the planets do not form a tree.",
    "C": "The counting rule does not hold for internal gears.",
    "D": "Three planets lock the train.",
}


@register(
    "graph_three_planets", exercise="1.8", title="Three planets: the count against the rank", stars=2, minutes=20,
    kind="concept",
    question="A planetary has a sun 1, a ring 3 (held), a carrier 4 and three planets 5, 6 and 7, each on its own "
             "pin of the carrier and each meshing the sun and the ring. Give (a) the pair rule's count "
             "F = J_R - J_G, (b) the degrees of freedom from the rank of the Willis equations, and (c) the reason "
             "they differ ('A', 'B', 'C' or 'D').",
    answer=Parts({
        "count": ("the count", Value("number", standard=False, generic="Count the turning pairs (one per link "
                                     "on the carrier) and the gear pairs (two per planet).")),
        "rank": ("the rank's answer", Value("count", generic="Write the six Willis equations and find how many "
                                            "are independent: F = m - 1 - rank W.")),
        "reason": ("the reason", Choice(_WHY, wrong={
            "B": "They do: every turning pair joins the carrier to one link, a tree.",
            "C": "Internal meshes give Willis equations like external ones, with a positive ratio.",
            "D": "The train turns: identical planets share the motion the first one already has."}))}),
)
def graph_three_planets():
    from ..mechanism.mobility import dof

    m = dof(_three_planets(21, 24), 3)
    return {"count": m.count, "rank": m.rank, "reason": "A"}
