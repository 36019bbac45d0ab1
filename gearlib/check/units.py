"""Checks for the exercises of chapter 2, kinematic units (``exercises/02_kinematic_units.ipynb``).

The exercises fractionate a two-stage planetary reducer the chapter does not show
(:data:`SERIES_TRAIN`: the first carrier is the second sun, both rings are in the housing)
and count over the one-dof six-link chains of the atlas.
"""

from __future__ import annotations

import functools
import re

from ._choice import Choice, Groups, Parts
from ._core import register
from ._value import Hint, Mistake, Value

__all__ = ["units_series", "unit_type_series", "linkage_series", "atlas_single_unit_chains", "SERIES_TRAIN"]

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
