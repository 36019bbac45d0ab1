"""Checks for the exercises 2.8 to 2.11 of chapter 2, kinematic units
(``exercises/02_kinematic_units.ipynb``); 2.1 to 2.7 are in :mod:`gearlib.check.units`.

2.8 treats the second unit of the two-stage reducer (:data:`gearlib.check.units.SERIES_TRAIN`)
as a block, 2.9 plans a propagation through the gear set the reader models in exercise 2.5,
2.10 types the ring train of exercise 1.1 and 2.11 fractionates the planetary with three
planets of exercise 1.8.
"""

from __future__ import annotations

import functools
from fractions import Fraction

import sympy

from ._choice import Choice, Parts
from ._core import register
from ._design import Condition, Design
from ._value import Mistake, Symbolic, Value
from .units import CRCR_ROLES, _crcr_units, _type_choice, _unit_name

__all__ = ["units_block_derive", "units_plan_design", "units_star_type", "units_three_planets"]


# ----------------------------------------------------------------------------- 2.8
_W0, _W3, _E34, _E40 = sympy.symbols("omega_0 omega_3 e_3_4 e_4_0")
_E = _E34 * _E40


@register(
    "units_block_derive", exercise="2.8", title="A unit as a block: two coaxial links fix the third", stars=2,
    minutes=15, kind="derive",
    question="In the reducer of exercise 2.1 take the unit whose carrier is 5: the sun 3, the planet 4 and the "
             "ring 0 (in the housing). Relative to its carrier the unit has one degree of freedom, so the speeds of "
             "two of its coaxial links fix the third. Derive the carrier's speed omega_5 in terms of omega_3, "
             "omega_0 and the gear ratios e_3_4 and e_4_0, without assuming that the housing is held.",
    answer=Symbolic(("omega_0", "omega_3", "e_3_4", "e_4_0"),
                    values=lambda p: {"e_3_4": -1, "e_4_0": Fraction(24, 72)}, mistakes=[
        Mistake(lambda e, p: (_W3 - _E * _W0) / (1 - _E), "The sun and the ring have changed places: relative to "
                "the carrier the ring turns E = e_3_4 e_4_0 times as fast as the sun, so E multiplies the sun's "
                "term."),
        Mistake(lambda e, p: (_E * _W0 - _W3) / (_E - 1), "E is the ring's speed over the sun's, both relative to "
                "the carrier, not the sun's over the ring's."),
        Mistake(lambda e, p: -_E * _W3 / (1 - _E), "That holds with the housing held (omega_0 = 0); the question "
                "keeps omega_0, so that the formula also serves when the housing turns."),
        Mistake(lambda e, p: _E * _W3, "That is the ring's speed relative to the carrier; the carrier's own speed "
                "follows from omega_0 - omega_5 = E (omega_3 - omega_5)."),
    ], generic="Write omega_4 - omega_5 = e_3_4 (omega_3 - omega_5) and omega_0 - omega_5 = e_4_0 (omega_4 - "
               "omega_5), eliminate omega_4 and solve for omega_5."),
)
def units_block_derive():
    w4, w5 = sympy.symbols("omega_4 omega_5")
    sol = sympy.solve([w4 - w5 - _E34 * (_W3 - w5), _W0 - w5 - _E40 * (w4 - w5)], [w4, w5], dict=True)[0]
    return sol[w5]


# ----------------------------------------------------------------------------- 2.9
_CENTRAL = ("S1", "S2", "A", "B")


def _role(x):
    """The name of exercise 2.5 that *x* gives, or None."""
    return next((r for r in CRCR_ROLES if str(x).strip().upper() == r), None)


@functools.lru_cache(maxsize=1)
def _crcr_unit_roles() -> tuple:
    """Each unit of the set of exercise 2.5 as the set of its links' names."""
    frac = _crcr_units()
    mech = frac.mechanism
    return tuple(frozenset(mech.link(x).name for x in u.links) for u in frac.units)


def _first_units(d) -> list:
    held, inp = _role(d["held"]), _role(d["input"])
    return [u for u in _crcr_unit_roles() if held in u and inp in u]


_PLAN_CONDITIONS = [
    Condition("the names", lambda d, p: all(_role(d[k]) for k in ("held", "input", "output")),
              "give each link by its name in exercise 2.5: S1, P1, A, B, P2 or S2."),
    Condition("central links", lambda d, p: all(_role(d[k]) in _CENTRAL for k in ("held", "input", "output")),
              "a planet turns about its own axis on a carrier: a brake in the housing cannot hold it, and no shaft "
              "on the central axis can drive it or take its motion out. Choose among the links on the central "
              "axis."),
    Condition("three links", lambda d, p: len({_role(d[k]) for k in ("held", "input", "output")}) == 3,
              "the held link, the input and the output must be three different links."),
    Condition("no unknown", lambda d, p: bool(_first_units(d)),
              "no unit holds both the held link and the input, so no unit can be solved first: the plan would need "
              "an unknown across the common linkage (chapter 3's third gear does that). Choose a held link and an "
              "input that one unit shares."),
    Condition("across the chain", lambda d, p: not any(_role(d["output"]) in u for u in _first_units(d)),
              "the held link, the input and the output all belong to one unit, so the motion never leaves it. "
              "Choose an output that only the other unit holds."),
]


@register(
    "units_plan_design", exercise="2.9", title="Plan a propagation through both units", stars=2, minutes=20,
    kind="design",
    question="In the gear set of exercise 2.5 a brake can hold one link, a shaft can drive another and a third "
             "can be the output. Choose them, by the names of exercise 2.5, so that (a) one unit can be solved "
             "first from the held link and the input, with no unknown, and (b) the motion must then cross the "
             "common linkage into the other unit to reach the output. Give {'held': ..., 'input': ..., "
             "'output': ...}.",
    answer=Design({"held": "link", "input": "link", "output": "link"}, _PLAN_CONDITIONS,
                  example=lambda p: {"held": "A", "input": "S1", "output": "S2"}),
)
def units_plan_design():
    return None


# ----------------------------------------------------------------------------- 2.10
def _star_choice():
    base = _type_choice()
    wrong = {}
    for n in base.options:
        if n.startswith("K5") and n[-1] in "SD":
            wrong[n] = ("A mechanism that is one unit has no common links, so step 4 adds no g-g edge: no S or D "
                        "mark.")
        elif n in ("K5-1", "K5-2", "K5-3", "K5-4"):
            wrong[n] = "Look at the gear tree again: does one gear mesh all the others, or do the gears form a chain?"
        elif n.startswith("K5"):
            wrong[n] = "Right tree; now count which of the outer gears share an axis of the carrier."
        else:
            wrong[n] = "Count the unit's links: its carrier and every gear that meshes on it."
    return Choice(base.options, wrong=wrong, normaliser=_unit_name, generic=base.generic)


@register(
    "units_star_type", exercise="2.10", title="The type of a one-unit train", stars=1, minutes=10, kind="compute",
    question="The ring train of exercise 1.1 (gl.check.mechanism.RING_TRAIN: a planet 2 on link 4 meshing the "
             "sun 1, the ring of the housing 0 and the output ring 5) is a single kinematic unit. Which catalogue "
             "type is it? Answer with a name such as 'K5-2' or 'K4-1S'.",
    answer=_star_choice(),
)
def units_star_type():
    from ..mechanism.data import Mechanism
    from ..units.fractionation import kinematic_units
    from .mechanism import RING_TRAIN

    (unit,) = kinematic_units(Mechanism.from_dict(RING_TRAIN)).units
    return unit.type


# ----------------------------------------------------------------------------- 2.11
_LOOP_REASONS = {
    "A": "Relative to the carrier every planet repeats the first one's motion: all the gears turn in fixed "
         "proportion, so they form one unit; its meshes close loops, so it is none of the catalogue's trees.",
    "B": "Each planet with the sun and the ring is a unit of its own, and the three units share the sun, the ring "
         "and the carrier.",
    "C": "The planets turn about different axes of the carrier, so no unit can hold two of them.",
    "D": "Identical planets count once: the set is one catalogue unit with a single planet.",
}


@register(
    "units_three_planets", exercise="2.11", title="Three planets: one unit or three?", stars=2, minutes=10,
    kind="concept",
    question="Fractionate the planetary of exercise 1.8 (a sun 1, a ring 3 and three planets 5, 6, 7 on the one "
             "carrier 4, each planet meshing the sun and the ring). Give (a) the number of kinematic units and "
             "(b) the reason ('A', 'B', 'C' or 'D').",
    answer=Parts({
        "units": ("the number of units", Value("count", mistakes=[
            Mistake(lambda e, p: 3, "That is one unit per planet: units are cut per carrier and connected tree of "
                    "meshes, not per planet."),
        ], generic="Run step 2: how many pieces do the gear pairs on carrier 4 make?")),
        "reason": ("the reason", Choice(_LOOP_REASONS, wrong={
            "B": "Step 2 cuts the gear pairs by carrier and keeps a piece whole while its meshes connect: the sun "
                 "and the ring join the three planets into one piece.",
            "C": "Relative to its carrier every axis of a unit is fixed; its gears may turn about as many axes as "
                 "they need (a compound train has three).",
            "D": "Nothing is merged: the library keeps every planet, and their extra meshes are equations that "
                 "repeat the others. Is a set of meshes that closes a loop one of the catalogue's trees?"}))}),
)
def units_three_planets():
    from ..units.fractionation import kinematic_units
    from .mechanism import _three_planets

    return {"units": len(kinematic_units(_three_planets(21, 24)).units), "reason": "A"}
