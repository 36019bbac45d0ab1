"""Checks for the exercises of chapter 3, unit-by-unit gains (``exercises/03_unit_gains.ipynb``)."""

from __future__ import annotations

import sympy

from .. import catalog
from ._core import Hint, close, register


@register(
    "gain_rule2",
    chapter="03",
    question="theta_{5,2} / theta_{2,4} in KU1 of Liu and Chen's transmission (catalogue teeth).",
    hints=[
        Hint(lambda a, e: close(a, e + 1), "That is theta_{5,4}/theta_{2,4} (rule 1): the output is measured "
             "relative to gear 2, not to the carrier."),
        Hint(lambda a, e: close(a, -(e + 1)), "Check the sign of each mesh: 3 meshes 5 internally."),
    ],
    generic_hint="Write theta_{5,2} = theta_{5,4} - theta_{2,4} and use theta_{5,4} = E_{2,5} theta_{2,4}.",
)
def gain_rule2():
    from ..gains.local import local_gain
    from ..units.fractionation import kinematic_units

    unit = kinematic_units(catalog.load("liu_chen_transmission")).unit(1)
    return local_gain(unit, output=(5, 2), input=(2, 4))


def _fig1_parts():
    from ..gains.local import local_gain
    from ..units.fractionation import kinematic_units

    frac = kinematic_units(catalog.load("liu_chen_fig1"))
    return local_gain(frac.unit(1), (1, 5), (4, 5)), local_gain(frac.unit(2), (3, 5), (1, 5))


@register(
    "propagation_fig1",
    chapter="03",
    question="theta_{3,5} / theta_{4,5} of Liu and Chen's Fig. 1 (catalogue teeth), unit by unit.",
    hints=[
        Hint(lambda a, e: close(a, _fig1_parts()[0]), "That is the gain of KU1 alone: multiply by KU2's gain."),
        Hint(lambda a, e: close(a, _fig1_parts()[1]), "That is the gain of KU2 alone: multiply by KU1's gain."),
    ],
    generic_hint="KU1 turns theta_{4,5} into theta_{1,5} (rule 1); KU2 turns theta_{1,5} into theta_{3,5}.",
)
def propagation_fig1():
    a, b = _fig1_parts()
    return a * b


def _third(subs=None):
    from ..gains.relation import propagate

    prop = propagate(catalog.load("liu_chen_transmission"), 8, [4], ground=1)
    return next(iter(prop.symbolic().values()))


def _first_gear():
    e = sympy.Symbol
    return e("e_1_7") * e("e_7_8") / (e("e_1_6") * e("e_6_2"))


@register(
    "third_gear",
    chapter="03",
    question="theta_{8,1} / theta_{4,1} of the transmission's third gear, in the symbols e_a_b.",
    hints=[
        Hint(lambda a, e: close(a, _first_gear()), "That is the first gear's E_{2,8}: in third gear link 1 is held "
             "and link 4 drives."),
        Hint(lambda a, e: close(a, (_first_gear() * sympy.Symbol("e_1_6") * sympy.Symbol("e_6_2") - 1)
                                / (sympy.Symbol("e_1_6") * sympy.Symbol("e_6_2") - 1)),
             "That is the second gear (input 2): here the input is link 4, the carrier of KU1."),
    ],
    generic_hint="theta_{4,1} = theta_{4,2} + theta_{2,1}: the first term lies in KU1, the second in KU2, both "
    "driven by theta_{2,5}.",
)
def third_gear():
    return _third()


def _exercise_robot():
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict({
        "name": "exercise robot",
        "links": list(range(10)),
        "turning_pairs": [[0, 1, "a"], [0, 4, "a"], [0, 8, "a"], [1, 2, "b"], [1, 5, "b"], [1, 7, "b"],
                          [1, 9, "b"], [7, 6, "d"], [2, 3, "c"]],
        "gear_pairs": [{"gears": [1, 6], "ratio": "e_1_6", "carrier": 7},
                       {"gears": [6, 5], "ratio": "e_6_5", "carrier": 7},
                       {"gears": [5, 4], "ratio": "e_5_4", "carrier": 1},
                       {"gears": [3, 7], "ratio": "e_3_7", "carrier": 2},
                       {"gears": [9, 8], "ratio": "e_9_8", "carrier": 1},
                       {"gears": [3, 9], "ratio": "e_3_9", "carrier": 2}],
        "ground": 0,
        "inputs": [1, 4, 8],
    })


@register(
    "structure_matrix",
    chapter="03",
    question="The structure matrix A (rows joints 1-3, columns inputs 1, 4, 8) of the exercise robot.",
    hints=[
        Hint(lambda a, e: isinstance(a, sympy.MatrixBase) and close(a, e.T), "That is A^T: in A each column "
             "belongs to one input and each row to one joint."),
    ],
    generic_hint="Cut each input's transmission line into units, find each unit's gain q_{x,p}/q_{y,p}, and fill "
    "column k with the running products of its line's gains.",
    standard_hints=False,
)
def structure_matrix():
    from ..gains.robots import geared_robot

    return geared_robot(_exercise_robot(), end_effector=3).structure_matrix()
