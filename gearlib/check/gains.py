"""Checks for the exercises 3.1 to 3.7 and 3.11 of chapter 3, unit-by-unit gains
(``exercises/03_unit_gains.ipynb``); the others are in :mod:`gearlib.check.transmissions`.

The chapter computes Liu and Chen's examples with the catalogue's teeth; the exercises give
other teeth (3.1, 3.2, 3.7), a shift the chapter does not make (3.3: link 5 held, link 4
driven), a robot whose lines the chapter does not show (3.4, :data:`EXERCISE_ROBOT`) and a
Wolfrom reducer the reader models (3.5) and analyses with the rules (3.6), and the same robot
with numbers for its joint torques (3.11).
"""

from __future__ import annotations

import re
from fractions import Fraction

import sympy

from ._choice import Choice, Parts
from ._core import register
from ._design import Matrix
from ._model import Model, Scenario
from ._value import Mistake, Symbolic, Value

__all__ = ["gain_rule2", "propagation_fig1", "third_gear", "structure_matrix", "gains_model_wolfrom",
           "gains_wolfrom_rule", "gains_simpson_first", "gains_robot_torque", "EXERCISE_ROBOT"]


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


# ----------------------------------------------------------------------------- 3.5
def _wolfrom(sun, big, small, fixed, output):
    """The Wolfrom reducer of exercises 3.5 and 3.6 (the reference; the reader writes it)."""
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict({
        "name": "Wolfrom reducer",
        "links": {0: "housing", 1: "sun", 2: "planet", 4: "carrier", 5: "output ring"},
        "turning_pairs": [[0, 1, "a"], [1, 4, "a"], [4, 2, "b"], [0, 5, "a"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [sun, big]},
                       {"gears": [2, 0], "teeth": [big, fixed], "type": "internal"},
                       {"gears": [2, 5], "teeth": [small, output], "type": "internal"}],
    })


def _wolfrom_teeth(rng) -> dict:
    while True:
        sun, big = rng.randint(15, 30), rng.randint(20, 36)
        small = big - rng.randint(2, 9)
        fixed, output = sun + 2 * big, sun + big + small
        if small >= 14 and fixed * small != big * output:
            return {"sun": sun, "big": big, "small": small, "fixed": fixed, "output": output}


_WOLFROM_STATEMENT = (
    "A Wolfrom reducer: the input sun ({sun} teeth) turns in the housing, on the central axis; a carrier turns "
    "freely about the same axis, on the sun's shaft; it holds a stepped planet whose larger gear ({big} teeth) "
    "meshes the sun and a ring of {fixed} teeth cut in the housing, and whose smaller gear ({small} teeth, keyed "
    "to the same shaft) meshes the output ring ({output} teeth, internal), which turns in the housing on the "
    "central axis.")


@register(
    "gains_model_wolfrom", exercise="3.5", title="From a description to data: a Wolfrom reducer", stars=2,
    minutes=20, kind="model",
    question=_WOLFROM_STATEMENT + " Write it as data for gl.Mechanism.from_dict, with the links named 'housing', "
                                  "'sun', 'planet', 'carrier' and 'output ring'.",
    data={"sun": 18, "big": 27, "small": 24, "fixed": 72, "output": 69},
    params=_wolfrom_teeth,
    answer=Model(("housing", "sun", "planet", "carrier", "output ring"),
                 [Scenario("housing", {"sun": 1}), Scenario("carrier", {"sun": 1}),
                  Scenario("sun", {"output ring": 1})]),
)
def gains_model_wolfrom(sun, big, small, fixed, output):
    return _wolfrom(sun, big, small, fixed, output)


# ----------------------------------------------------------------------------- 3.6
def _wolfrom_rule1(p) -> Fraction:
    return Fraction(-p["sun"], p["big"]) * Fraction(p["small"], p["output"])


def _wolfrom_plain(p) -> Fraction:
    return (Fraction(p["fixed"], p["output"]) - 1) / (Fraction(-p["fixed"], p["sun"]) - 1)


@register(
    "gains_wolfrom_rule", exercise="3.6", title="The Wolfrom ratio by the rules", stars=2, minutes=20,
    kind="compute",
    question=_WOLFROM_STATEMENT + " The reducer is one kinematic unit; with the housing held, its local input is "
                                  "theta_(sun,housing) and its local output theta_(output ring,housing). Which of "
                                  "the chapter's rules (1 to 5) gives theta_(output ring,housing)/theta_(sun,housing), "
                                  "and what is it?",
    data={"sun": 18, "big": 27, "small": 24, "fixed": 72, "output": 69},
    params=_wolfrom_teeth,
    answer=Parts({"rule": ("the rule", _RULES), "gain": ("the gain", Value("ratio", mistakes=[
        Mistake(lambda e, p: _wolfrom_rule1(p), "That is the output ring's turn over the sun's relative to the "
                "carrier (Rule 1): here the carrier turns, and both the input and the output are measured from the "
                "housing, a gear of the unit."),
        Mistake(lambda e, p: _wolfrom_plain(p), "The planet is stepped: the output ring meshes its smaller gear, "
                "so the path from the housing's ring to the output ring has two different planet gears."),
    ], generic="Write each gear's turn relative to the carrier as a multiple of the housing's (path products E "
               "through the planet), then subtract the housing's turn from the output ring's and from the sun's."))}),
)
def gains_wolfrom_rule(sun, big, small, fixed, output):
    from ..gains.local import local_gain
    from ..gains.rules import match_rule
    from ..units.fractionation import kinematic_units

    (unit,) = kinematic_units(_wolfrom(sun, big, small, fixed, output)).units
    return {"rule": str(match_rule(unit, (5, 0), (1, 0)).rule), "gain": local_gain(unit, output=(5, 0), input=(1, 0))}


# ----------------------------------------------------------------------------- 3.7
def _simpson(sun, p1, r1, p2, r2):
    from ..catalog import simpson

    m = simpson()
    m = m.with_gear_pair((1, 5), teeth=(sun, p1)).with_gear_pair((5, 2), teeth=(p1, r1))
    return m.with_gear_pair((1, 6), teeth=(sun, p2)).with_gear_pair((6, 3), teeth=(p2, r2))


def _simpson_teeth(rng) -> dict:
    sun, p1, p2 = rng.randint(24, 40), rng.randint(17, 30), rng.randint(17, 30)
    return {"sun": sun, "p1": p1, "r1": sun + 2 * p1, "p2": p2, "r2": sun + 2 * p2}


@register(
    "gains_simpson_first", exercise="3.7", title="A brake makes first gear: the Simpson set", stars=2, minutes=20,
    kind="compute",
    question="The Simpson gear set of the chapter (gl.catalog.simpson(): common sun 1, front ring 2, front carrier "
             "and rear ring 3, rear carrier 4, housing 0) gets other teeth: sun {sun}, front planets {p1}, front "
             "ring {r1}, rear planets {p2}, rear ring {r2}. In first gear a brake holds the rear carrier 4, the "
             "front ring 2 drives and link 3 is the output. Find omega_3/omega_2 unit by unit: the rear unit first "
             "(its carrier held), then the front unit.",
    data={"sun": 34, "p1": 19, "r1": 72, "p2": 22, "r2": 78},
    params=_simpson_teeth,
    answer=Value("ratio", mistakes=[
        Mistake(lambda e, p: Fraction(p["r1"], p["r1"] + p["sun"]), "That is second gear, with the sun held: in "
                "first gear the sun turns, driven backwards through the rear unit."),
        Mistake(lambda e, p: Fraction(-p["sun"], p["r2"]), "That is the rear unit alone (omega_3 over the sun's "
                "speed); the front unit then gives the output from the front ring's speed and the sun's."),
        Mistake(lambda e, p: Fraction(p["r1"], p["r1"] + p["sun"] - p["r2"]), "The sun turns the other way: with "
                "the rear carrier held, the sun and the rear ring turn in opposite directions."),
    ], generic="Start in the rear unit, whose carrier is held: an ordinary train from the sun to the rear ring "
               "gives the sun's speed from the output's. Then write the front unit's Willis equation relative to its "
               "carrier 3 and eliminate the sun's speed."),
)
def gains_simpson_first(sun, p1, r1, p2, r2):
    from ..mechanism.kinematics import ratio

    return ratio(_simpson(sun, p1, r1, p2, r2), output=3, input=2, ground=0, held=[4])


# ----------------------------------------------------------------------------- 3.11
_RATIOS = ("e_4_5", "e_5_7", "e_7_3", "e_8_9", "e_9_3")


def _robot_numbers(values: dict):
    from ..mechanism.data import Mechanism

    data = dict(EXERCISE_ROBOT)
    data["gear_pairs"] = [dict(gp, ratio=values[gp["ratio"]]) for gp in EXERCISE_ROBOT["gear_pairs"]]
    return Mechanism.from_dict(data)


def _torque_parts(p) -> dict:
    e = {k: Fraction(p[k]) for k in _RATIOS}
    line4 = 1 / (e["e_4_5"] * e["e_5_7"] * e["e_7_3"])
    line8 = 1 / (e["e_8_9"] * e["e_9_3"])
    return {"e": e, "line4": line4, "line8": line8}


def _torque_params(rng) -> dict:
    while True:
        out = {k: str(Fraction(rng.choice((-1, 1)) * rng.randint(12, 48), rng.randint(12, 48))) for k in _RATIOS}
        if any("/" not in v for k, v in out.items() if k in _RATIOS):
            continue
        out.update(xi1=rng.randint(2, 30), xi4=rng.randint(2, 30), xi8=rng.randint(2, 30))
        t = _torque_parts(out)
        if abs(t["line4"] * out["xi4"] + t["line8"] * out["xi8"]) > Fraction(1, 2):
            return out


def _transpose_row3(p) -> Fraction:
    e = _torque_parts(p)["e"]
    return p["xi1"] + p["xi4"] / e["e_8_9"] + p["xi8"] / (e["e_8_9"] * e["e_9_3"])


def _lc_gains(p) -> Fraction:
    e = _torque_parts(p)["e"]
    return p["xi4"] * e["e_4_5"] * e["e_5_7"] * e["e_7_3"] + p["xi8"] * e["e_8_9"] * e["e_9_3"]


def _no_idler(p) -> Fraction:
    e = _torque_parts(p)["e"]
    return p["xi4"] / (e["e_4_5"] * e["e_7_3"]) + p["xi8"] / (e["e_8_9"] * e["e_9_3"])


class _Torque(Value):
    """A torque: a number, optionally followed by N m (or Nm, N*m, N.m)."""

    @staticmethod
    def _number(answer):
        if isinstance(answer, str) and len(answer) < 200:
            return re.sub(r"\s*(N\s*[\u00b7*.]?\s*m)\s*$", "", answer.strip())
        return answer

    def check_form(self, answer) -> None:
        super().check_form(self._number(answer))

    def judge(self, answer, reference, params):
        return super().judge(self._number(answer), reference, params)


@register(
    "gains_robot_torque", exercise="3.11", title="Joint torques of a geared robot: tau = A xi", stars=2,
    minutes=20, kind="compute",
    question="The robot of exercise 3.4 (gl.check.gains.EXERCISE_ROBOT) gets numbers: e_4_5 = {e_4_5}, e_5_7 = "
             "{e_5_7}, e_7_3 = {e_7_3}, e_8_9 = {e_8_9}, e_9_3 = {e_9_3}. Its actuators 1, 4 and 8 apply the "
             "torques xi_1 = {xi1}, xi_4 = {xi4} and xi_8 = {xi8} N m. What torque tau_3, in N m, results at the "
             "joint of the end-effector 3? Give the number.",
    data={"e_4_5": "-5/4", "e_5_7": "-3/4", "e_7_3": "6/5", "e_8_9": "-4/5", "e_9_3": "5/3", "xi1": 8, "xi4": 7,
          "xi8": 5},
    params=_torque_params,
    answer=_Torque("number", unit=None, mistakes=[
        Mistake(lambda e, p: _transpose_row3(p), "That is row 3 of A^T xi: the torques follow tau = A xi (rows of "
                "A: joints; columns: actuators), the transpose of the map from joint angles to actuator angles."),
        Mistake(lambda e, p: _lc_gains(p), "Those are Liu and Chen's ratios, output over input: Chen's forward "
                "gains run the other way (the unit's input over its output)."),
        Mistake(lambda e, p: _no_idler(p), "The idler 5 is missing: actuator 4 reaches gear 7 through it, so its "
                "line's first unit has two meshes."),
        Mistake(lambda e, p: [_torque_parts(p)["line4"] * p["xi4"], _torque_parts(p)["line8"] * p["xi8"]],
                "That is one actuator's share: both actuators 4 and 8 reach joint 3."),
    ], generic="Row 3 of A holds the running products of each line's forward gains up to joint 3: tau_3 = "
               "A_3,1 xi_1 + A_3,4 xi_4 + A_3,8 xi_8."),
)
def gains_robot_torque(e_4_5, e_5_7, e_7_3, e_8_9, e_9_3, xi1, xi4, xi8):
    from ..gains.robots import geared_robot

    values = {k: sympy.Rational(v) for k, v in zip(_RATIOS, (e_4_5, e_5_7, e_7_3, e_8_9, e_9_3))}
    robot = geared_robot(_robot_numbers(values), end_effector=3)
    return robot.joint_torques([xi1, xi4, xi8], method="exact")[2]
