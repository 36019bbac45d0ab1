"""Checks for the exercises of chapter 7, Davies' method beyond gear trains
(``exercises/07_davies_beyond_gear_trains.ipynb``).

Efficiencies are checked as efficiencies (the other port driving, a misread logarithm, the
factor pi forgotten); the slider-crank model of 7.4 by what it does (:class:`LinkageModel`:
its efficiency over a turn and its slider's stroke, whatever link ids and reference pose the
reader chose); the design of 7.5 by its conditions.
"""

from __future__ import annotations

import functools
import math

import sympy

from ._choice import Choice
from ._core import Prediction, register
from ._design import Condition, Design
from ._linkage_model import LinkageModel
from ._value import Mistake, Symbolic, Value

__all__ = ["linkage_crank_efficiency", "linkage_slider_efficiency", "linkage_offset_speed", "linkage_model_offset",
           "linkage_design_crank", "linkage_concept_place", "linkage_concept_annuli", "linkage_mistake_motion",
           "linkage_predict_pins", "linkage_virtual_work", "linkage_explore_limb", "linkage_concept_torques"]


def _g(a1, a2) -> float:
    return math.log((a1 + a2) / (a2 - a1))


def _crank_params(rng) -> dict:
    a1 = rng.randint(3, 8) * 10
    return {"a1": a1, "a2": a1 * rng.randint(20, 30) // 10, "mu": rng.randint(18, 30) / 100}


# ----------------------------------------------------------------------------- 7.1, 7.2
@register(
    "linkage_crank_efficiency", exercise="7.1", title="A slider-crank by hand", stars=1, minutes=10, kind="compute",
    question="A slider-crank like the chapter's has a crank of a1 = {a1} mm and a coupler of a2 = {a2} mm; the "
             "slide has a Coulomb coefficient mu = {mu}. The crank drives with constant torque and speed. What is "
             "its efficiency over one turn?",
    data={"a1": 40, "a2": 90, "mu": 0.25}, params=_crank_params,
    answer=Value("efficiency", figures=4, mistakes=[
        Mistake(lambda e, p: math.pi / (math.pi + p["mu"] * _g(p["a1"], p["a2"])), "That is the efficiency with the "
                "slider driving: here the crank drives, and the loss is taken from the output."),
        Mistake(lambda e, p: 1 - p["mu"] * _g(p["a1"], p["a2"]), "The loss over a turn is the integral divided by "
                "the turn's 2 pi: a factor pi is missing."),
        Mistake(lambda e, p: 1 - p["mu"] / math.pi * math.log(p["a2"] / p["a1"]), "Check the logarithm: its argument "
                "is (a1 + a2)/(a2 - a1)."),
    ], generic="Put the lengths and mu into the efficiency with the crank as the input; only the ratio a2/a1 "
               "matters."),
)
def linkage_crank_efficiency(a1, a2, mu):
    from ..linkages.catalogue import slider_crank_efficiency

    return slider_crank_efficiency(a1, a2, mu)


@register(
    "linkage_slider_efficiency", exercise="7.2", title="The same slider-crank driven by its slider", stars=1,
    minutes=10, kind="compute",
    question="The slider-crank of exercise 7.1 (a1 = {a1} mm, a2 = {a2} mm, mu = {mu}) is now driven by its slider; "
             "the crank takes a constant torque out at constant speed. What is its efficiency over one turn?",
    data={"a1": 40, "a2": 90, "mu": 0.25}, params=_crank_params,
    answer=Value("efficiency", figures=4, mistakes=[
        Mistake(lambda e, p: 1 - p["mu"] / math.pi * _g(p["a1"], p["a2"]), "That is the efficiency with the crank "
                "driving. With the slider driving, the output is fixed and the friction loss is added to the input."),
        Mistake(lambda e, p: 1 / (1 + p["mu"] * _g(p["a1"], p["a2"])), "A factor pi is missing: the input over a turn "
                "is 2 pi T_A t_A plus the loss."),
    ], generic="With the slider as the input the output work over a turn is fixed; write the input work as the "
               "output plus the friction loss."),
)
def linkage_slider_efficiency(a1, a2, mu):
    from ..linkages.catalogue import slider_crank_efficiency

    return slider_crank_efficiency(a1, a2, mu, input="slider")


# ----------------------------------------------------------------------------- 7.3
_A1, _A2, _H, _TH = sympy.symbols("a1 a2 h theta")


def _offset_speed(h):
    s = _A1 * sympy.sin(_TH) - h
    return -_A1 * sympy.sin(_TH) - _A1 * sympy.cos(_TH) * s / sympy.sqrt(_A2 ** 2 - s ** 2)


@register(
    "linkage_offset_speed", exercise="7.3", title="The slider's speed with an offset slide", stars=2, minutes=20,
    kind="derive",
    question="Move the slide line of the slider-crank to the height h above the crank's centre A (C = (C_x, h)). "
             "With the crank at the angle theta, turning at unit speed, derive the slider's speed along x, "
             "dC_x/dtheta, in a1, a2, h and theta.",
    answer=Symbolic(("a1", "a2", "h", "theta"), mistakes=[
        Mistake(lambda e, p: _offset_speed(0), "That is the speed without the offset: the coupler's vertical span is "
                "a1 sin(theta) - h, not a1 sin(theta)."),
        Mistake(lambda e, p: _offset_speed(-_H), "The offset has the wrong sign: C is at the height h, so the coupler "
                "spans a1 sin(theta) - h vertically."),
        Mistake(lambda e, p: -_A1 * sympy.sin(_TH), "That is the crank pin's speed along x alone: the coupler's "
                "horizontal span changes too (differentiate the square root)."),
    ], generic="Write C_x = B_x + sqrt(a2^2 - (B_y - h)^2) with B = a1 (cos theta, sin theta) and differentiate "
               "with respect to theta."),
)
def linkage_offset_speed():
    return _offset_speed(_H)


# ----------------------------------------------------------------------------- 7.4
def _offset_model(e):
    """The reference: the offset slider-crank as data (crank 1, coupler 3, slide at height e)."""
    a1, a2 = 1.0, 3.0
    cx = a1 + math.sqrt(a2 ** 2 - e ** 2)
    return {"space": "planar", "links": {0: "frame", 1: "crank", 2: "coupler", 3: "slider"}, "ground": 0,
            "joints": [{"name": "A", "kind": "revolute", "links": [0, 1], "point": [0, 0]},
                       {"name": "B", "kind": "revolute", "links": [1, 2], "point": [a1, 0]},
                       {"name": "C", "kind": "revolute", "links": [2, 3], "point": [cx, e]},
                       {"name": "D", "kind": "prismatic", "links": [3, 0], "point": [cx, e], "axis": [1, 0],
                        "friction": {"mu": 0.1}}],
            "ports": [{"name": "A", "joint": "A", "role": "input"}, {"name": "D", "joint": "D", "role": "output"}]}


@register(
    "linkage_model_offset", exercise="7.4", title="Model an offset slider-crank", stars=2, minutes=25, kind="model",
    question="Write as data (for gl.linkages.Linkage.from_dict) a slider-crank with a crank of 1 turning in the "
             "frame at A (the origin), a coupler of 3, and a slider whose slide line runs along x at the height "
             "h = {h} above A, Coulomb friction mu = 0.1 in the slide only. Name the crank's revolute joint 'A' and "
             "the slide's prismatic joint 'D'; put an input port on A and an output port on D. Any link ids and "
             "any drawn pose will do.",
    data={"h": 0.5}, params=lambda rng: {"h": rng.choice([0.2, 0.3, 0.4, 0.6, 0.7, 0.8])},
    answer=LinkageModel(),
)
def linkage_model_offset(h):
    return _offset_model(h)


# ----------------------------------------------------------------------------- 7.5
def _eta_crank(d, p):
    return 1 - p["mu"] / math.pi * _g(d["a1"], d["a2"])


@register(
    "linkage_design_crank", exercise="7.5", title="Design a slider-crank for an efficiency", stars=2, minutes=20,
    kind="design",
    question="Choose the crank a1 and the coupler a2 (in m) of a slider-crank like the chapter's with a stroke of "
             "{stroke} m and a coupler no longer than {longest} m, whose efficiency over a turn with the crank "
             "driving is at least {target} when the slide's Coulomb coefficient is {mu}.",
    data={"stroke": 0.1, "longest": 0.6, "target": 0.985, "mu": 0.15},
    answer=Design({"a1": "number", "a2": "number"}, [
        Condition("the stroke", lambda d, p: abs(2 * d["a1"] - p["stroke"]) <= 1e-6 * p["stroke"],
                  lambda d, p: "the slider travels 2 a1 between its dead centres; choose a1 for the stroke asked"),
        Condition("a full turn", lambda d, p: d["a2"] > d["a1"] > 0,
                  "the crank turns round only when the coupler is longer than the crank"),
        Condition("the length", lambda d, p: d["a2"] <= p["longest"] + 1e-12,
                  "the coupler is longer than the space allows"),
        Condition("the efficiency", lambda d, p: _eta_crank(d, p) >= p["target"],
                  "its efficiency is below the target: the loss grows with a1/a2, so lengthen the coupler"),
    ], example=lambda p: {"a1": p["stroke"] / 2, "a2": p["longest"]}),
)
def linkage_design_crank(stroke, longest, target, mu):
    return None


# ----------------------------------------------------------------------------- 7.6, 7.7, 7.12
def _asked(lead: str, choice: Choice) -> str:
    """A multiple-choice question: its lead, then the options as the choice lists them,
    ``(A) ...; (B) ....``, so that the statement and the check cannot drift apart."""
    return lead + " " + "; ".join(f"({key}) {text}" for key, text in choice.options.items()) + "."


_PLACE = Choice({
    "A": "the moments of the vertical forces at C and D cancel: D carries no torque and only mode 1 can occur",
    "B": "the circuit matrix then has only ones",
    "C": "the friction force at D must pass through the pin C to do any work",
    "D": "the slider-crank would otherwise have two degrees of freedom",
}, synonyms={"A": ["torque", "mode 1", "moments cancel"], "B": ["circuit"], "C": ["work"], "D": ["degrees"]},
    wrong={"B": "The circuit matrix depends on the graph and the edges' directions, not on where D sits.",
           "C": "A friction force along the slide does work on the slider wherever its line lies; its place changes "
                "only the torques it balances.",
           "D": "The degrees of freedom come from the joints and their kinds; the place of D's point changes none."})


@register(
    "linkage_concept_place", exercise="7.6", title="Why the thesis puts D at C", stars=1, minutes=5, kind="concept",
    question=_asked("The thesis places the slider's prismatic coupling D at the same point as the revolute C. Why?",
                    _PLACE),
    answer=_PLACE,
)
def linkage_concept_place():
    return "A"


_ANNULI = Choice({
    "A": "two square annuli would lock an undetermined torque about the axis in the loop they close",
    "B": "a square annulus cannot carry the actuator's force",
    "C": "two square annuli would let the rod turn about its axis",
    "D": "Coulomb friction does not apply to a square annulus",
}, synonyms={"A": ["locked torque", "undetermined torque"], "B": ["actuator"], "C": ["turn"], "D": ["coulomb"]},
    wrong={"B": "Any coupling that allows the translation can carry a force along it; the thesis puts the actuator "
                "in the round annulus only by choice.",
           "C": "A square annulus stops the turning about the axis; one is enough, two do it twice.",
           "D": "Both annuli have Coulomb friction from their normal forces (eq. 129)."})


@register(
    "linkage_concept_annuli", exercise="7.7", title="One square and one round annulus", stars=1, minutes=5,
    kind="concept",
    question=_asked("Each prismatic pair of the 3-UPU is split into a square annulus and a round one. Why not two "
                    "square annuli?", _ANNULI),
    answer=_ANNULI,
)
def linkage_concept_annuli():
    return "A"


_TORQUES = Choice({
    "A": "it leaves out the normal forces that the pair's transmitted torques cause at its two bushings",
    "B": "it puts the prismatic coupling at the wrong place on the limb",
    "C": "it leaves out the friction in the universal joints",
    "D": "it has fewer signs to find",
}, synonyms={"A": ["torques", "bushings", "normal forces"], "B": ["place", "location"], "C": ["universal"],
             "D": ["signs"]},
    wrong={"B": "The thesis tried both ends and the middle: the efficiency is the same wherever the coupling is.",
           "C": "Both models have the same universal joints with the same friction.",
           "D": "The number of unknown signs changes how the equations are solved, not what they say."})


@register(
    "linkage_concept_torques", exercise="7.12", title="Why one coupling per prismatic pair is too optimistic",
    stars=2, minutes=10, kind="concept",
    question=_asked("Modelling each prismatic pair of the 3-UPU by one coupling, with friction from the forces it "
                    "transmits, gives an efficiency close to 1 for the lift. Why is that too optimistic?", _TORQUES),
    answer=_TORQUES,
)
def linkage_concept_torques():
    return "A"


# ----------------------------------------------------------------------------- 7.8
def _tb(a1, a2, deg):
    th = math.radians(deg)
    bx = a1 * math.cos(th)
    cx = bx + math.sqrt(a2 ** 2 - (a1 * math.sin(th)) ** 2)
    return cx, bx


@register(
    "linkage_mistake_motion", exercise="7.8", title="A printed motion matrix turned backwards", stars=2, minutes=15,
    kind="mistake",
    question="The thesis' eq. (102) prints the motion matrix of the slider-crank with the factor t_A/(C_x - B_x). "
             "For a1 = {a1}, a2 = {a2} and the crank at {deg} degrees it gives the coupling A the motion (-t_A; 0, 0): "
             "the crank turning backwards. Correct it from the null space of the motion equations: what is t_B, the "
             "rotation speed of coupling B, per unit t_A?",
    data={"a1": 2, "a2": 5, "deg": 70},
    params=lambda rng: {"a1": 2, "a2": rng.choice([4, 5, 6, 7]), "deg": rng.choice([20, 40, 110, 130, 150])},
    answer=Value("number", figures=4, standard=False, mistakes=[
        Mistake(lambda e, p: -e, "That is what the printed factor gives: with it, coupling A turns backwards. Take "
                "the factor from the null vector, t_A/(B_x - C_x)."),
        Mistake(lambda e, p: 1 / e, "You have the reciprocal: t_B per unit t_A."),
        Mistake(lambda e, p: _tb(p["a1"], p["a2"], p["deg"])[1] / (_tb(p["a1"], p["a2"], p["deg"])[0]
                - _tb(p["a1"], p["a2"], p["deg"])[1]), "That is t_C, the coupling between coupler and slider."),
    ], generic="Take the null vector of the motion matrix with t_A = 1: its second entry is t_B, with B_x = a1 cos "
               "theta and C_x = B_x + sqrt(a2^2 - a1^2 sin^2 theta)."),
)
def linkage_mistake_motion(a1, a2, deg):
    cx, bx = _tb(a1, a2, deg)
    return cx / (bx - cx)


# ----------------------------------------------------------------------------- 7.9
_PINS = Choice(["it drops by less than one point", "it drops by one to five points",
                "it drops by more than five points"],
               synonyms={"it drops by less than one point": ["less than one point", "less than 1", "small"],
                         "it drops by one to five points": ["one to five", "1 to 5"],
                         "it drops by more than five points": ["more than five", "more than 5", "large"]})


@functools.lru_cache(maxsize=16)
def _half_lift(mu_pin):
    from ..linkages.io import load
    from ..linkages.rating import run

    return run(load("laus_3upu", parameters={"mu_pin": mu_pin}), "lift_half", keep_poses=False).efficiency


def _pins_truth(reference, p):
    drop = 100 * (_half_lift(0.11) - float(reference))
    return ("it drops by less than one point" if drop < 1 else
            "it drops by one to five points" if drop <= 5 else "it drops by more than five points")


@register(
    "linkage_predict_pins", exercise="7.9", title="Predict, then compute: worse pins", stars=2, minutes=15,
    kind="predict",
    question="In the 3-UPU's half lift (task 'lift_half'), the universal joints' pins get a Coulomb coefficient of "
             "{mu_pin} instead of 0.11; the annuli keep 0.11. First predict what happens to the efficiency "
             "(percentage points): 'it drops by less than one point', 'it drops by one to five points' or 'it drops "
             "by more than five points'. Then compute it: gl.linkages.load('laus_3upu', parameters={{'mu_pin': "
             "{mu_pin}}}).",
    data={"mu_pin": 0.22}, params=lambda rng: {"mu_pin": rng.choice([0.16, 0.18, 0.2, 0.25, 0.3])},
    answer=Value("efficiency", figures=4, mistakes=[
        Mistake(lambda e, p: _half_lift(0.11), "That is the efficiency with the pins at 0.11: change the pins' "
                "coefficient (the parameter mu_pin) and run the task again."),
    ], generic="Load the robot with the pins' coefficient changed, run the task 'lift_half', and read its "
               "efficiency."),
    predict=Prediction(_PINS, _pins_truth, "The pins lose little: their friction torques are small (a 15 mm pin) "
                       "and they turn slowly. Almost all of the loss is in the annuli."),
)
def linkage_predict_pins(mu_pin):
    return _half_lift(mu_pin)


# ----------------------------------------------------------------------------- 7.10
def _limb_forces(mx, my, mz, weight=10_000.0):
    import numpy as np

    rows = []
    for al in (0.0, 2 * math.pi / 3, -2 * math.pi / 3):
        v = np.array([mx - 0.5 * math.cos(al), my - 0.5 * math.sin(al), mz])
        rows.append(v / np.linalg.norm(v))
    return np.linalg.solve(np.array(rows).T, [0.0, 0.0, weight])


@register(
    "linkage_virtual_work", exercise="7.10", title="Holding the payload without friction", stars=2, minutes=20,
    kind="compute",
    question="Without friction, the 3-UPU of the chapter (r_b = 1 m, r_t = 0.5 m, limb 1 at angle 0) holds its "
             "payload of 10 kN at M = ({mx}, {my}, {mz}) m. What force (in N, positive when it pushes the limb "
             "longer) does limb 1's actuator exert? Use virtual work: the platform translates, and each limb "
             "lengthens at e2_hat . dM/dt.",
    data={"mx": 0.0, "my": 0.25, "mz": 0.8},
    params=lambda rng: {"mx": rng.choice([-0.2, -0.1, 0.05, 0.15]), "my": rng.choice([-0.15, 0.1, 0.2]),
                        "mz": rng.choice([0.6, 0.7, 0.85])},
    answer=Value("number", figures=4, mistakes=[
        Mistake(lambda e, p: [float(x) for x in _limb_forces(p["mx"], p["my"], p["mz"])[1:]], "That is another "
                "limb's force: limb 1 is the one whose base joint is at (1, 0, 0)."),
        Mistake(lambda e, p: 10_000.0 / 3, "The payload is not shared equally: the limbs lean differently, so solve "
                "J^T f = W with the limbs' unit vectors."),
    ], generic="Write the three limbs' unit vectors e2_hat = (M + (r_t - r_b)(cos a, sin a, 0))/|...| as the rows of "
               "J and solve J^T f = (0, 0, 10000)."),
)
def linkage_virtual_work(mx, my, mz):
    return float(_limb_forces(mx, my, mz)[0])


# ----------------------------------------------------------------------------- 7.11
@functools.lru_cache(maxsize=1)
def _limb_losses():
    from ..linkages.io import load
    from ..linkages.rating import run

    shares = run(load("laus_3upu"), "lift", keep_poses=False).loss_shares("joint")
    return {"1": shares["BC"], "2": shares["FG"], "3": shares["JK"]}


@register(
    "linkage_explore_limb", exercise="7.11", title="Which limb loses most", stars=2, minutes=15, kind="explore",
    question="In the 3-UPU's lift (task 'lift'), which limb's prismatic pair dissipates the most energy: 1, 2 or 3? "
             "Use the result's loss_shares(by='joint'): the pairs are BC (limb 1), FG (limb 2) and JK (limb 3).",
    answer=Choice(["1", "2", "3"], synonyms={"1": ["limb 1", "BC"], "2": ["limb 2", "FG"], "3": ["limb 3", "JK"]},
                  generic="Not that limb: run the lift and compare the three pairs' shares of the losses."),
)
def linkage_explore_limb():
    losses = _limb_losses()
    return max(losses, key=losses.get)
