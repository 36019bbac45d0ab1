"""Checks for the exercises of chapter 3, unit-by-unit gains (``exercises/03_unit_gains.ipynb``).

The chapter computes Liu and Chen's examples with the catalogue's teeth; the exercises give
other teeth (3.1, 3.2), a shift the chapter does not make (3.3: link 5 held, link 4 driven)
and a robot whose lines the chapter does not show (3.4, :data:`EXERCISE_ROBOT`).
"""

from __future__ import annotations

import sympy

from ._choice import Choice, Parts
from ._core import register
from ._design import Matrix
from ._value import Mistake, Symbolic, Value

__all__ = ["gain_rule2", "propagation_fig1", "third_gear", "structure_matrix", "EXERCISE_ROBOT"]


def _transmission(sun=30, planet=24, ring=78):
    from ..catalog import load

    m = load("liu_chen_transmission")
    return m.with_gear_pair((2, 3), teeth=(sun, planet)).with_gear_pair((3, 5), teeth=(planet, ring))


def _ku1_teeth(rng) -> dict:
    sun, planet = rng.randint(18, 40), rng.randint(16, 36)
    return {"sun": sun, "planet": planet, "ring": sun + 2 * planet}


_RULES = Choice(["1", "2", "3", "4", "5"], synonyms={k: [f"rule {k}", f"Rule {k}"] for k in "12345"},
                generic="Not that rule: look at where the unit's local input and output sit (g-c or g-g edges, "
                        "and which gears they touch).")


@register(
    "gain_rule2", exercise="3.1", title="A local gain and its rule", stars=1, minutes=10, kind="compute",
    question="In KU1 of Liu and Chen's transmission (gl.catalog.load('liu_chen_transmission')), give the sun 2 "
             "{sun} teeth, the planet 3 {planet} teeth and the ring 5 {ring} teeth (internal), all on carrier 4. "
             "What is the local gain theta_(5,2)/theta_(2,4), and which of the chapter's rules (1 to 5) gives "
             "it?",
    data={"sun": 34, "planet": 22, "ring": 78},
    params=_ku1_teeth,
    answer=Parts({"gain": ("the gain", Value("ratio", mistakes=[
        Mistake(lambda e, p: e + 1, "That is theta_(5,4)/theta_(2,4) (rule 1): the output is measured relative to "
                "gear 2, not to the carrier."),
        Mistake(lambda e, p: -(e + 1), "Check the sign of each mesh: the planet meshes the ring internally."),
    ], generic="Write theta_(5,2) = theta_(5,4) - theta_(2,4) and use theta_(5,4) = E_(2,5) theta_(2,4).")),
        "rule": ("the rule", _RULES)}),
)
def gain_rule2(sun, planet, ring):
    from ..gains.local import local_gain
    from ..units.fractionation import kinematic_units

    unit = kinematic_units(_transmission(sun, planet, ring)).unit(1)
    return {"gain": local_gain(unit, output=(5, 2), input=(2, 4)), "rule": "2"}


def _fig1(n4, n1a, n2, n1b, n5):
    from ..catalog import load

    m = load("liu_chen_fig1")
    m = m.with_gear_pair((4, 1), teeth=(n4, n1a))
    return m.with_gear_pair((2, 1), teeth=(n2, n1b)).with_gear_pair((5, 2), teeth=(n5, n2))


def _fig1_teeth(rng) -> dict:
    n1b, n2 = rng.randint(24, 48), rng.randint(15, 30)
    return {"n4": rng.randint(15, 30), "n1a": rng.randint(36, 60), "n2": n2, "n1b": n1b, "n5": n1b + 2 * n2}


def _fig1_parts(n4, n1a, n2, n1b, n5):
    from ..gains.local import local_gain
    from ..units.fractionation import kinematic_units

    frac = kinematic_units(_fig1(n4, n1a, n2, n1b, n5))
    return local_gain(frac.unit(1), (1, 5), (4, 5)), local_gain(frac.unit(2), (3, 5), (1, 5))


@register(
    "propagation_fig1", exercise="3.2", title="Two units in series: Fig. 1 with other teeth", stars=2, minutes=15,
    kind="compute",
    question="Liu and Chen's five-link train of Fig. 1 (gl.catalog.load('liu_chen_fig1')) gets new gears: pair "
             "(4, 1) on carrier 5 with {n4} and {n1a} teeth, pair (2, 1) on carrier 3 with {n2} and {n1b}, and "
             "the ring 5 meshing the planet 2 with {n5} teeth (internal). Compute the two local gains along the "
             "path from theta_(4,5) to theta_(3,5) by hand and give theta_(3,5)/theta_(4,5).",
    data={"n4": 18, "n1a": 45, "n2": 21, "n1b": 36, "n5": 78},
    params=_fig1_teeth,
    answer=Value("ratio", mistakes=[
        Mistake(lambda e, p: _fig1_parts(**p)[0], "That is the gain of KU1 alone: multiply by KU2's gain."),
        Mistake(lambda e, p: _fig1_parts(**p)[1], "That is the gain of KU2 alone: multiply by KU1's gain."),
    ], generic="KU1 turns theta_(4,5) into theta_(1,5) (rule 1); KU2 turns theta_(1,5) into theta_(3,5)."),
)
def propagation_fig1(n4, n1a, n2, n1b, n5):
    a, b = _fig1_parts(n4, n1a, n2, n1b, n5)
    return a * b


_SYMBOLS = ("e_1_6", "e_6_2", "e_1_7", "e_7_8", "e_2_3", "e_3_5")
_e = sympy.Symbol


@register(
    "third_gear", exercise="3.3", title="A shift the chapter does not make", stars=3, minutes=30, kind="derive",
    question="In Liu and Chen's transmission hold link 5 (the carrier of KU2) and drive link 4 (the carrier of "
             "KU1); the output is link 8. Derive theta_(8,5)/theta_(4,5) unit by unit, in the gear-ratio symbols "
             "e_1_6, e_6_2, e_1_7, e_7_8, e_2_3, e_3_5.",
    answer=Symbolic(_SYMBOLS, values=lambda p: {str(gp.symbol): gp.e for gp in _transmission().gear_pairs},
                    mistakes=[
        Mistake(lambda e, p: _e("e_1_7") * _e("e_7_8") / (_e("e_1_6") * _e("e_6_2")), "That is E_(2,8) of KU2 "
                "alone: link 2 is driven through KU1, whose carrier is the input."),
        Mistake(lambda e, p: 1 - _e("e_2_3") * _e("e_3_5"), "That is KU1 alone, theta_(2,5)/theta_(4,5) "
                "inverted: go on through KU2 to link 8."),
    ], generic="In KU1 (carrier 4, gear 5 held) find theta_(2,5) from theta_(4,5); in KU2 (its carrier 5 held) "
               "theta_(8,5) = E_(2,8) theta_(2,5)."),
)
def third_gear():
    from ..gains.relation import propagate

    prop = propagate(_transmission(), 8, [4], ground=5)
    return next(iter(prop.symbolic().values()))


EXERCISE_ROBOT = {
    "name": "exercise robot",
    "links": [0, 1, 2, 3, 4, 5, 7, 8, 9],
    "turning_pairs": [[0, 1, "a"], [0, 4, "a"], [0, 8, "a"], [1, 2, "b"], [1, 5, "d"], [1, 7, "b"],
                      [1, 9, "b"], [2, 3, "c"]],
    "gear_pairs": [{"gears": [4, 5], "ratio": "e_4_5", "carrier": 1},
                   {"gears": [5, 7], "ratio": "e_5_7", "carrier": 1},
                   {"gears": [7, 3], "ratio": "e_7_3", "carrier": 2},
                   {"gears": [8, 9], "ratio": "e_8_9", "carrier": 1},
                   {"gears": [9, 3], "ratio": "e_9_3", "carrier": 2}],
    "ground": 0,
    "inputs": [1, 4, 8],
}
"""The robot of exercise 3.4: joints 1 (axis a), 2 (b), 3 (c); actuator 4 reaches gear 7 through
an idler 5 on link 1, actuator 8 reaches gear 9 directly."""


def _robot():
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict(EXERCISE_ROBOT)


@register(
    "structure_matrix", exercise="3.4", title="The structure matrix of a geared robot", stars=2, minutes=25,
    kind="compute",
    question="The three-dof robot gl.check.gains.EXERCISE_ROBOT (base 0, joints 1, 2, 3 about axes a, b, c; "
             "actuator 1 drives link 1 directly, actuator 4 drives gear 7 on link 1 through the idler 5, "
             "actuator 8 drives gear 9; 7 and 9 mesh the end-effector 3 on carrier 2). Give its structure matrix "
             "A (rows: joints 1, 2, 3; columns: actuators 1, 4, 8) as a list of rows, in the symbols e_a_b of the "
             "data (Chen's gains, input over output).",
    answer=Matrix(symbols=("e_4_5", "e_5_7", "e_7_3", "e_8_9", "e_9_3"), rows="joints 1, 2, 3",
                  columns="actuators 1, 4, 8", mistakes=[
        Mistake(lambda e, p: e.applyfunc(lambda x: 1 / x if x != 0 else 0), "Your entries are the reciprocals: "
                "Chen's forward gain is the unit's input over its output, q_(x,p)/q_(y,p), the other way round "
                "from Liu and Chen's ratios.")],
                  generic="Cut each actuator's transmission line into units, find each unit's forward gain "
                          "q_(x,p)/q_(y,p) (input over output), and fill its column with the running products."),
)
def structure_matrix():
    from ..gains.robots import geared_robot

    return geared_robot(_robot(), end_effector=3).structure_matrix()
