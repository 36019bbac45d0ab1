"""Checks for the exercises 2.1 to 2.7 of chapter 2, kinematic units
(``exercises/02_kinematic_units.ipynb``); 2.8 to 2.11 are in :mod:`gearlib.check.fractionation`.

The exercises use mechanisms the chapter does not show: a two-stage planetary reducer
(:data:`SERIES_TRAIN`: the first carrier is the second sun, both rings are in the housing;
2.1 to 2.3), the one-dof six-link chains of the atlas (2.4), a gear set of two planetaries in
which each carrier holds the other's ring (2.5 and 2.6; the reader models it, so its data are
not published here) and a set with two suns whose planets share one ring on one carrier
(:data:`DUAL_SUN`, 2.7).
"""

from __future__ import annotations

import functools
import re

from ._choice import Choice, Groups, Parts
from ._core import Prediction, register
from ._model import Model, Scenario
from ._value import Hint, Mistake, Value

__all__ = ["units_series", "unit_type_series", "linkage_series", "atlas_single_unit_chains", "units_model_crcr",
           "units_mistake_crcr", "units_fge_predict", "SERIES_TRAIN", "DUAL_SUN", "CRCR_ROLES"]

SERIES_TRAIN = {
    "name": "two-stage planetary reducer",
    "links": {0: "housing", 1: "input sun", 2: "first planet", 3: "first carrier and second sun",
              4: "second planet", 5: "output carrier"},
    "turning_pairs": [[0, 1, "a"], [0, 3, "a"], [0, 5, "a"], [3, 2, "b"], [5, 4, "c"]],
    "gear_pairs": [{"gears": [1, 2], "teeth": [18, 27]}, {"gears": [2, 0], "teeth": [27, 72], "type": "internal"},
                   {"gears": [3, 4], "teeth": [24, 24]}, {"gears": [4, 0], "teeth": [24, 72], "type": "internal"}],
}
"""The reducer of exercises 2.1 to 2.3: two planetary stages in series, both rings in the
housing 0, the first carrier 3 also the second stage's sun."""


@functools.lru_cache(maxsize=1)
def _fractionation():
    from ..mechanism.data import Mechanism
    from ..units.fractionation import kinematic_units

    return kinematic_units(Mechanism.from_dict(SERIES_TRAIN))


def _gears_only(groups, reference, params):
    frac = _fractionation()
    return set(groups) == {frozenset(u.gears) for u in frac.units}


@register(
    "units_series", exercise="2.1", title="Fractionate a two-stage reducer", stars=2, minutes=20, kind="compute",
    question="The two-stage planetary reducer gl.check.units.SERIES_TRAIN (housing 0 with both rings, input sun "
             "1, first planet 2 on carrier 3, which is also the second stage's sun, second planet 4 on the output "
             "carrier 5). Fractionate it by hand with the chapter's four steps and give its kinematic units as a "
             "list of sets of links, each set holding the carrier and the gears of one unit.",
    answer=Groups(what="kinematic units", hints=[
        Hint(_gears_only, "Each unit also contains its carrier (step 3 adds the carrier vertex)."),
        Hint(lambda g, r, p: any(0 not in u for u in g), "A ring in the housing is a gear: the housing belongs to "
             "every unit in which its ring meshes."),
    ], generic="A unit is a carrier with every gear that meshes on it; a link can belong to two units (a common "
               "link)."),
)
def units_series():
    return [u.links for u in _fractionation().units]


def _unit_name(text: str) -> str:
    """``"K4-1S"``, ``"k41s"``, ``"K4–1 S"`` and ``"K4_1S"`` all read as ``k41s``."""
    t = str(text).strip().upper().replace("\u2013", "-").replace("\u2212", "-").replace("_", "-")
    m = re.fullmatch(r"K\s*(\d)\s*-?\s*(\d{1,2})\s*([SD]?)", t)
    if m:
        return f"k{m.group(1)}-{m.group(2)}{m.group(3).lower()}"
    return re.sub(r"[^0-9a-z]", "", t.lower())


def _type_choice():
    from ..units.catalogue import ku_catalogue

    names = [e.name for e in ku_catalogue(variants=True)]
    wrong = {n: ("The structure is right; now apply step 4 to the unit's common links." if n == "K4-1" else
                 "Right size, but look again at which of the unit's gears share an axis of the carrier."
                 if n.startswith("K4") else "Count the unit's links: its carrier and every gear that meshes on it.")
             for n in names}
    return Choice(names, wrong=wrong, normaliser=_unit_name,
                  generic="Count the unit's links: its carrier and every gear that meshes on it.")


@register(
    "unit_type_series", exercise="2.2", title="The catalogue type of a unit", stars=2, minutes=10,
    kind="compute",
    question="In the reducer of exercise 2.1, which catalogue type (such as 'K5-2' or 'K5-2S') is the unit with "
             "carrier 5? Mind the common links: which of them are gears of this unit on one axis?",
    answer=_type_choice(),
)
def unit_type_series():
    return next(u for u in _fractionation().units if u.carrier == 5).type


_LINKAGE_REASONS = {
    "A": "Two units share two coaxial links, and the rotation of one relative to the other passes from one unit "
         "to the next.",
    "B": "Three units share one link each with the two others, and the three links are coaxial.",
    "C": "The two units share a single link.",
    "D": "The two units have the same carrier.",
}


@register(
    "linkage_series", exercise="2.3", title="The kind of common linkage, and why", stars=1, minutes=10,
    kind="concept",
    question="In the reducer of exercise 2.1, what kind of common linkage joins the units ('2-link chain' or "
             "'coaxial triangle'), and why (reason 'A', 'B', 'C' or 'D')?",
    answer=Parts({
        "kind": ("the kind", Choice(["2-link chain", "coaxial triangle"], synonyms={
            "2-link chain": ["two-link chain", "2 link chain", "two link chain", "chain"],
            "coaxial triangle": ["triangle"]},
            generic="Count the units that share links, and how many links each two of them share.")),
        "reason": ("the reason", Choice(_LINKAGE_REASONS, wrong={
            "B": "That describes three units; count the units of this reducer.",
            "C": "Count the links the two units share again: a carrier of one unit can be a gear of the other.",
            "D": "Each unit has its own carrier: that is how step 2 cuts the displacement graph."}))}),
)
def linkage_series():
    kinds = {c.kind for c in _fractionation().linkages}
    return {"kind": kinds.pop(), "reason": "A"}


@register(
    "atlas_single_unit_chains", exercise="2.4", title="Single-unit chains of the six-link atlas", stars=2,
    minutes=15, kind="explore",
    question="gl.atlas.geared_chains(6, 1) lists the non-isomorphic one-dof six-link geared chains. How many of "
             "them are a single kinematic unit (one carrier holding every gear pair)? Write a short loop with "
             "gl.kinematic_units.",
    answer=Value("count", mistakes=[
        Mistake(lambda e, p: _six_link_count(), "That counts every chain; keep those with a single unit."),
        Mistake(lambda e, p: _six_link_count() - e, "That counts the chains with two units or more."),
    ], generic="Fractionate every chain of gl.atlas.geared_chains(6, 1) and count those with one unit."),
)
def atlas_single_unit_chains():
    from ..synthesis import atlas
    from ..units.fractionation import kinematic_units

    return sum(1 for m in atlas.geared_chains(6, 1) if len(kinematic_units(m).units) == 1)


@functools.lru_cache(maxsize=1)
def _six_link_count() -> int:
    from ..synthesis import atlas

    return len(atlas.geared_chains(6, 1))


# ----------------------------------------------------------------------------- 2.5
CRCR_ROLES = ("S1", "P1", "A", "B", "P2", "S2")
"""The names of the links of the gear set of exercises 2.5, 2.6 and 2.9: front sun S1 and
front planets P1 on carrier A, which also carries the rear ring; rear sun S2 and rear planets
P2 on carrier B, which also carries the front ring."""


def _crcr(s1, p1, r1, s2, p2, r2):
    """The gear set of exercise 2.5 (the reference; the reader writes it)."""
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict({
        "name": "two planetaries, each carrier holding the other's ring",
        "links": {1: "S1", 2: "P1", 3: "A", 4: "B", 5: "P2", 6: "S2"},
        "turning_pairs": [[3, 1, "a"], [3, 4, "a"], [3, 6, "a"], [3, 2, "b"], [4, 5, "c"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [s1, p1]}, {"gears": [2, 4], "teeth": [p1, r1], "type": "internal"},
                       {"gears": [6, 5], "teeth": [s2, p2]}, {"gears": [5, 3], "teeth": [p2, r2], "type": "internal"}],
    })


def _crcr_teeth(rng) -> dict:
    s1, p1, s2, p2 = rng.randint(20, 40), rng.randint(17, 32), rng.randint(20, 40), rng.randint(17, 32)
    return {"s1": s1, "p1": p1, "r1": s1 + 2 * p1, "s2": s2, "p2": p2, "r2": s2 + 2 * p2}


@register(
    "units_model_crcr", exercise="2.5", title="From a description to data: two planetaries, carriers and rings "
    "crossed", stars=2, minutes=20, kind="model",
    question="A gear set of two simple planetaries in which each carrier holds the other's ring (a compound used in "
             "four-speed automatic transmissions). The front sun S1 ({s1} teeth) meshes the front planets P1 ({p1} "
             "teeth), which turn on the carrier A and mesh the front ring ({r1} teeth, internal). The front ring "
             "is one link, B, with the rear carrier. The rear sun S2 ({s2} teeth) meshes the rear planets P2 "
             "({p2} teeth), which turn on B and mesh the rear ring ({r2} teeth, internal), part of A. S1, S2, A "
             "and B turn about the central axis. Write the set as data for gl.Mechanism.from_dict (one planet "
             "of each set is enough), with the links named 'S1', 'P1', 'A', 'B', 'P2' and 'S2'.",
    data={"s1": 27, "p1": 24, "r1": 75, "s2": 33, "p2": 21, "r2": 75},
    params=_crcr_teeth,
    answer=Model(CRCR_ROLES, [Scenario("A", {"S1": 1}), Scenario("B", {"S2": 1}), Scenario("S2", {"S1": 1}),
                              Scenario("S1", {"A": 1})]),
)
def units_model_crcr(s1, p1, r1, s2, p2, r2):
    return _crcr(s1, p1, r1, s2, p2, r2)


# ----------------------------------------------------------------------------- 2.6
@functools.lru_cache(maxsize=1)
def _crcr_units():
    from ..units.fractionation import kinematic_units

    return kinematic_units(_crcr(27, 24, 75, 33, 21, 75))


def _crcr_type_choice():
    from ..units.catalogue import ku_catalogue

    names = [e.name for e in ku_catalogue(variants=True)]
    wrong = {}
    for n in names:
        if n.startswith("K4") and n.endswith("S"):
            wrong[n] = ("A g-g edge joins two common links that are both gears of the unit on one axis of its "
                        "carrier; look at the role link A plays in this unit.")
        elif n.startswith("K4"):
            wrong[n] = "Right size; now look at which gears of the unit share an axis of the carrier."
        else:
            wrong[n] = "Count the unit's links: its carrier and every gear that meshes on it."
    return Choice(names, wrong=wrong, normaliser=_unit_name,
                  generic="Count the unit's links: its carrier and every gear that meshes on it.")


_CRCR_STEPS = Choice(["1", "2", "3", "4", "5"], wrong={
    "1": "Step 1 is right: each gear pair appears as a heavy edge labelled with its carrier.",
    "2": "Step 2 is right: the heavy edges fall into two pieces, one per carrier label.",
    "3": "Step 3 is right: each piece gets its carrier back.",
    "5": "Step 5 only names the units step 4 built; the mistake is earlier."})


@register(
    "units_mistake_crcr", exercise="2.6", title="Find the mistake in a fractionation", stars=2, minutes=15,
    kind="mistake",
    question="A student fractionates the gear set of exercise 2.5: (1) displacement graph: heavy edges (S1, P1) "
             "and (P1, B) labelled with the carrier A, (S2, P2) and (P2, A) labelled B; (2) two pieces, one per "
             "carrier; (3) with their carriers: {A, S1, P1, B} and {B, S2, P2, A}; (4) the common links A and B "
             "are coaxial, so in each unit step 4 joins them by a g-g edge; (5) both units are therefore K4-1S. "
             "Which step is wrong, and what is the right catalogue type of the unit whose carrier is A?",
    answer=Parts({"step": ("the step", _CRCR_STEPS), "type": ("the type", _crcr_type_choice())}),
)
def units_mistake_crcr():
    unit = next(u for u in _crcr_units().units if u.carrier == 3)
    return {"step": "4", "type": unit.type}


# ----------------------------------------------------------------------------- 2.7
DUAL_SUN = {
    "name": "two suns, one ring",
    "links": {0: "housing", 1: "first sun", 2: "first planet", 3: "ring", 4: "carrier", 5: "second planet",
              6: "second sun"},
    "turning_pairs": [[0, 1, "a"], [0, 3, "a"], [0, 4, "a"], [0, 6, "a"], [4, 2, "b"], [4, 5, "c"]],
    "gear_pairs": [{"gears": [1, 2], "teeth": [30, 21]}, {"gears": [2, 3], "teeth": [21, 72], "type": "internal"},
                   {"gears": [6, 5], "teeth": [36, 18]}, {"gears": [5, 3], "teeth": [18, 72], "type": "internal"}],
}
"""The set of exercise 2.7: two suns, each meshing its own planets; both kinds of planet turn
on the one carrier 4 and mesh the one ring 3."""

_COUNT_OPTIONS = Choice(["more FGEs than units", "as many FGEs as units", "fewer FGEs than units"], synonyms={
    "more FGEs than units": ["more", "more FGEs"], "as many FGEs as units": ["as many", "equal", "the same"],
    "fewer FGEs than units": ["fewer", "less", "fewer FGEs"]})

_DUAL_REASONS = {
    "A": "Relative to the carrier the ring ties the two planet sets together: every gear of both sets turns in "
         "fixed proportion to any one of them, so they form one gear tree on one carrier; FGEs are cut one per "
         "planet set.",
    "B": "The two planet sets turn about different axes of the carrier, so each set is a unit of its own.",
    "C": "The housing holds the ring, which splits the set in two.",
    "D": "A unit holds at most five links, so a larger set must be cut.",
}


def _dual_truth(reference, params):
    f, u = reference["fges"], reference["units"]
    return "more FGEs than units" if f > u else "as many FGEs as units" if f == u else "fewer FGEs than units"


@register(
    "units_fge_predict", exercise="2.7", title="Predict, then count: entities against units", stars=2, minutes=15,
    kind="predict",
    question="The set gl.check.units.DUAL_SUN has a first sun 1 meshing planets 2 and a second sun 6 meshing "
             "planets 5; both kinds of planet turn on the one carrier 4 and mesh the one ring 3; the suns, the "
             "ring and the carrier turn in the housing 0. First predict whether it has more fundamental geared "
             "entities (FGEs) than kinematic units, as many, or fewer, and record it; then give (a) the number of "
             "FGEs, (b) the number of kinematic units and (c) the reason for the difference ('A', 'B', 'C' or "
             "'D').",
    answer=Parts({
        "fges": ("the number of FGEs", Value("count", generic="An FGE is one planet set with its carrier and the "
                                             "central gears its planets mesh: count the planet sets.")),
        "units": ("the number of units", Value("count", generic="A unit is a carrier with a connected tree of gear "
                                               "pairs on it: list the carrier of each gear pair, then see which "
                                               "meshes connect.")),
        "reason": ("the reason", Choice(_DUAL_REASONS, wrong={
            "B": "The planets' axes do not matter: relative to the carrier every axis is fixed, and what makes a "
                 "unit is a connected tree of gear pairs on one carrier.",
            "C": "The housing is not a gear of this set, and a held link splits nothing: fractionation looks at "
                 "the gear pairs and their carriers.",
            "D": "Units outside the five-link catalogue exist (the chapter's transmission has one): the catalogue "
                 "lists types, it does not cut units."}))}),
    predict=Prediction(_COUNT_OPTIONS, _dual_truth, "Entities are cut by structure, one per planet set; units by "
                       "kinematics, one per carrier and connected gear tree. Two planet sets that mesh one ring on "
                       "one carrier are two entities but one unit."),
)
def units_fge_predict():
    from ..mechanism.data import Mechanism
    from ..units.fge import fundamental_geared_entities
    from ..units.fractionation import kinematic_units

    mech = Mechanism.from_dict(DUAL_SUN)
    return {"fges": len(fundamental_geared_entities(mech)), "units": len(kinematic_units(mech).units),
            "reason": "A"}
