"""Checks for the exercises 3.8 to 3.10, 3.12 and 3.13 of chapter 3, unit-by-unit gains
(``exercises/03_unit_gains.ipynb``); the others are in :mod:`gearlib.check.gains`.

Two stages in series swapped (3.8, the reducer of exercise 2.1 with other teeth), a coaxial
triangle with a sign lost (3.9, Liu and Chen's Fig. 3(a) with other teeth), a Simpson set
designed for two ratios (3.10), two combinations of a Simpson three-speed's shift elements
(3.12, :data:`SIMPSON_3SPEED`) and the lever of a power-split planetary (3.13). The joint
torques of 3.11 are in :mod:`gearlib.check.gains`, beside the robot of exercise 3.4.
"""

from __future__ import annotations

import math
from fractions import Fraction

import sympy

from ._choice import Choice, Parts
from ._core import Prediction, register
from ._design import Condition, Design
from ._value import Mistake, Value

__all__ = ["gains_series_predict", "gains_triangle_mistake", "gains_simpson_design", "gains_shift_combinations",
           "gains_lever_split", "SIMPSON_3SPEED"]


def _mech(data):
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict(data)


# ----------------------------------------------------------------------------- 3.8
def _swapped_series(s1, p1, r1, s2, p2, r2):
    """The reducer of exercise 2.1 built the other way round: the second stage's teeth first."""
    return _mech({
        "links": {0: "housing", 1: "input sun", 2: "first planet", 3: "first carrier and second sun",
                  4: "second planet", 5: "output carrier"},
        "turning_pairs": [[0, 1, "a"], [0, 3, "a"], [0, 5, "a"], [3, 2, "b"], [5, 4, "c"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [s2, p2]}, {"gears": [2, 0], "teeth": [p2, r2], "type": "internal"},
                       {"gears": [3, 4], "teeth": [s1, p1]}, {"gears": [4, 0], "teeth": [p1, r1], "type": "internal"}],
    })


def _series_teeth(rng) -> dict:
    s1, p1, s2, p2 = rng.randint(15, 36), rng.randint(17, 40), rng.randint(15, 36), rng.randint(17, 40)
    return {"s1": s1, "p1": p1, "r1": s1 + 2 * p1, "s2": s2, "p2": p2, "r2": s2 + 2 * p2}


_SWAP = Choice(["it grows", "it shrinks", "it stays the same", "it changes sign"], synonyms={
    "it grows": ["grows", "larger", "bigger", "increases"], "it shrinks": ["shrinks", "smaller", "decreases"],
    "it stays the same": ["same", "stays the same", "unchanged", "no change"],
    "it changes sign": ["changes sign", "sign", "reverses"]})


@register(
    "gains_series_predict", exercise="3.8", title="Predict, then compute: two stages swapped", stars=1, minutes=10,
    kind="predict",
    question="The reducer of exercise 2.1 with other teeth: the first stage has a sun of {s1} teeth, planets of "
             "{p1} and a ring of {r1}; the second a sun of {s2}, planets of {p2} and a ring of {r2}; both rings "
             "are in the housing. Now build it the other way round: the second stage's sun is the input, and its "
             "carrier drives the first stage's sun, whose carrier is the output. First predict what the swap does "
             "to the overall ratio omega_out/omega_in ('it grows', 'it shrinks', 'it stays the same' or 'it "
             "changes sign') and record it; then compute omega_out/omega_in of the swapped reducer, unit by unit.",
    data={"s1": 21, "p1": 30, "r1": 81, "s2": 28, "p2": 19, "r2": 66},
    params=_series_teeth,
    answer=Value("ratio", mistakes=[
        Mistake(lambda e, p: [Fraction(p["s1"], p["s1"] + p["r1"]), Fraction(p["s2"], p["s2"] + p["r2"])],
                "That is one stage alone: the output unit receives, through the 2-link chain, what the input unit "
                "gives."),
        Mistake(lambda e, p: [Fraction(p["s1"], p["r1"]) * Fraction(p["s2"], p["r2"]),
                              Fraction(p["s1"] * p["s2"], (p["r1"] - p["s1"]) * (p["r2"] - p["s2"]))],
                "Each stage's gain is the carrier's speed over the sun's with the ring held, "
                "N_sun/(N_sun + N_ring); check the formula of one stage."),
    ], generic="Each stage is one unit with its ring held: its gain is the carrier's speed over the sun's. The "
               "2-link chain passes the first unit's output to the second as its input: multiply."),
    predict=Prediction(_SWAP, lambda ref, p: "it stays the same",
                       "Each unit's gain depends only on its own teeth (its ring is held, its sun is the input the "
                       "chain passes on), and a product does not depend on the order of its factors. The order "
                       "matters for the torques and sizes of the stages, not for the ratio."),
)
def gains_series_predict(s1, p1, r1, s2, p2, r2):
    from ..mechanism.kinematics import ratio

    return ratio(_swapped_series(s1, p1, r1, s2, p2, r2), output=5, input=1, ground=0)


# ----------------------------------------------------------------------------- 3.9
def _fig3a(n1, n2, n3, n5, n6):
    from ..catalog import load

    m = load("liu_chen_fig3a")
    m = m.with_gear_pair((1, 2), teeth=(n1, n2)).with_gear_pair((6, 5), teeth=(n6, n5))
    return m.with_gear_pair((2, 3), teeth=(n2, n3))


def _triangle(n1, n2, n3, n5, n6, w1, w6) -> dict:
    t24 = Fraction(-n1, n2) * w1
    t54 = Fraction(-n6, n5) * w6
    wrong = Fraction(-n2, n3) * (t24 + t54)
    return {"n1": n1, "n2": n2, "n3": n3, "n5": n5, "n6": n6, "w1": w1, "w6": w6, "t24_printed": t24,
            "t54_printed": t54, "sum_printed": t24 + t54, "result_printed": wrong}


def _triangle_params(rng) -> dict:
    """Teeth and speeds whose intermediate values are whole numbers of rad/s, as a student's
    working would show them (the answer may be a fraction)."""
    while True:
        n1, n2, n3 = rng.randint(15, 40), rng.randint(15, 40), rng.randint(15, 40)
        n5, n6 = rng.randint(30, 60), rng.randint(15, 30)
        step1, step6 = n2 // math.gcd(n1, n2), n5 // math.gcd(n6, n5)  # whole theta_(2,4) and theta_(5,4)
        if step1 > 30 or step6 > 30:
            continue
        w1, w6 = step1 * rng.randint(1, 30 // step1), step6 * rng.randint(1, 30 // step6)
        d = _triangle(n1, n2, n3, n5, n6, w1, w6)
        right = Fraction(-n2, n3) * (d["t24_printed"] - d["t54_printed"])
        if (d["t24_printed"].denominator == d["t54_printed"].denominator == 1 and right.denominator <= 4
                and d["result_printed"].denominator <= 4 and abs(right) >= 1 and d["t24_printed"] != d["t54_printed"]
                and min(w1, w6) >= 4):
            return d


_TRIANGLE_STEPS = Choice(["1", "2", "3", "4", "5"], wrong={
    "1": "Step 1 is right: KU1 is the pair (1, 2) on its held carrier 4.",
    "2": "Step 2 is right: KU2 is the pair (6, 5) on the same carrier 4.",
    "4": "Step 4 is right: KU3 is the pair (2, 3) on its carrier 5, and theta_(2,5) is measured from that carrier.",
    "5": "Step 5 only puts the numbers of the steps before into step 4."})


@register(
    "gains_triangle_mistake", exercise="3.9", title="Find the mistake: a sign lost in a coaxial triangle", stars=2,
    minutes=15, kind="mistake",
    question="Liu and Chen's Fig. 3(a) (gl.catalog.load('liu_chen_fig3a')) with other teeth: pair (1, 2) with "
             "{n1} and {n2} teeth on carrier 4, pair (6, 5) with {n6} and {n5} on carrier 4, pair (2, 3) with {n2} "
             "and {n3} on carrier 5, all external. Link 4 is held, theta_(1,4) = {w1} rad/s and theta_(6,4) = {w6} "
             "rad/s. A student writes: (1) KU1: theta_(2,4) = e_(1,2) theta_(1,4) = {t24_printed}; (2) KU2: "
             "theta_(5,4) = e_(6,5) theta_(6,4) = {t54_printed}; (3) coaxial triangle 2-4-5: theta_(2,5) = "
             "theta_(2,4) + theta_(5,4) = {sum_printed}; (4) KU3: theta_(3,5) = e_(2,3) theta_(2,5); (5) so "
             "theta_(3,5) = {result_printed} rad/s. Which step is wrong, and what is the right theta_(3,5) in "
             "rad/s?",
    data=_triangle(24, 36, 18, 45, 20, 12, 9),
    params=_triangle_params,
    answer=Parts({"step": ("the step", _TRIANGLE_STEPS), "speed": ("theta_(3,5)", Value("speed", mistakes=[
        Mistake(lambda e, p: p["result_printed"], "That is the student's own result: correct the wrong step "
                "first."),
        Mistake(lambda e, p: p["sum_printed"], "That is theta_(2,5), the input of KU3; go on through the pair "
                "(2, 3)."),
    ], generic="Check each step against the definition theta_(u,v) = omega_u - omega_v: write every relative "
               "speed as a difference of absolute speeds."))}),
)
def gains_triangle_mistake(n1, n2, n3, n5, n6, w1, w6, t24_printed, t54_printed, sum_printed, result_printed):
    from ..mechanism.kinematics import speeds

    sol = speeds(_fig3a(n1, n2, n3, n5, n6), ground=4, inputs={1: w1, 6: w6})
    return {"step": "3", "speed": sol[3] - sol[5]}


# ----------------------------------------------------------------------------- 3.10
def _first(d) -> Fraction:
    return 1 + Fraction(d["sun"] + d["rear_ring"], d["front_ring"])


def _second(d) -> Fraction:
    return 1 + Fraction(d["sun"], d["front_ring"])


def _clear(sun, planet) -> bool:
    return planet + 2 < (sun + planet) * math.sin(math.pi / 3)


_TEETH = ("sun", "front_planet", "front_ring", "rear_planet", "rear_ring")
_SIMPSON_CONDITIONS = [
    Condition("tooth numbers", lambda d, p: all(17 <= d[k] <= 150 for k in _TEETH),
              "every gear needs at least 17 teeth (no undercut) and at most 150."),
    Condition("front set concentric", lambda d, p: d["front_ring"] == d["sun"] + 2 * d["front_planet"],
              "with one module the front planets fit between the sun and the front ring only when N_ring = N_sun "
              "+ 2 N_planet."),
    Condition("rear set concentric", lambda d, p: d["rear_ring"] == d["sun"] + 2 * d["rear_planet"],
              "with one module the rear planets fit between the common sun and the rear ring only when N_ring = "
              "N_sun + 2 N_planet."),
    Condition("second gear", lambda d, p: abs(_second(d) / Fraction(p["second"]) - 1) <= Fraction(1, 100),
              lambda d, p: f"your second gear (sun held) reduces by {float(_second(d)):.4g}; the target is "
                           f"{p['second']} within 1 %."),
    Condition("first gear", lambda d, p: abs(_first(d) / Fraction(p["first"]) - 1) <= Fraction(1, 100),
              lambda d, p: f"your first gear (rear carrier held) reduces by {float(_first(d)):.4g}; the target is "
                           f"{p['first']} within 1 %."),
    Condition("equal spacing", lambda d, p: (d["sun"] + d["front_ring"]) % 3 == 0 and (d["sun"] + d["rear_ring"]) % 3 == 0,
              "three planets can be spaced equally in a set only when (N_sun + N_ring)/3 is a whole number, in both "
              "sets."),
    Condition("clearance", lambda d, p: _clear(d["sun"], d["front_planet"]) and _clear(d["sun"], d["rear_planet"]),
              "neighbouring planets would touch: their tips need N_planet + 2 < (N_sun + N_planet) sin 60 degrees."),
]


def _simpson_example(p):
    ok = _SIMPSON_CONDITIONS
    for sun in range(17, 117):
        for p1 in range(17, (150 - sun) // 2 + 1):
            d = {"sun": sun, "front_planet": p1, "front_ring": sun + 2 * p1, "rear_planet": 17, "rear_ring": sun + 34}
            if not (ok[3].test(d, p) and (sun + d["front_ring"]) % 3 == 0 and _clear(sun, p1)):
                continue
            for p2 in range(17, (150 - sun) // 2 + 1):
                d = dict(d, rear_planet=p2, rear_ring=sun + 2 * p2)
                if all(c.test(d, p) for c in ok):
                    return d
    return None


def _simpson_targets(rng) -> dict:
    while True:
        sun, p1, p2 = rng.randint(24, 60), rng.randint(17, 40), rng.randint(17, 45)
        d = {"sun": sun, "front_planet": p1, "front_ring": sun + 2 * p1, "rear_planet": p2, "rear_ring": sun + 2 * p2}
        if max(d.values()) <= 150 and (sun + d["front_ring"]) % 3 == 0 and (sun + d["rear_ring"]) % 3 == 0 \
                and _clear(sun, p1) and _clear(sun, p2):
            return {"first": f"{float(_first(d)):.2f}", "second": f"{float(_second(d)):.2f}"}


@register(
    "gains_simpson_design", exercise="3.10", title="Design a Simpson set for two gears", stars=3, minutes=40,
    kind="design",
    question="Choose the teeth of a Simpson gear set (a common sun; front planets and front ring; rear planets and "
             "rear ring; three planets in each set, equally spaced) so that with the front ring driving and the "
             "front carrier as output, first gear (rear carrier held) reduces the speed by {first} and second gear "
             "(sun held) by {second}, each within 1 %. Every gear has 17 to 150 teeth, each set has one module "
             "(concentric), and neighbouring planets must not touch. Give {'sun': ..., 'front_planet': ..., "
             "'front_ring': ..., 'rear_planet': ..., 'rear_ring': ...}.",
    data={"first": "2.74", "second": "1.54"},
    params=_simpson_targets,
    answer=Design({k: "teeth" for k in _TEETH}, _SIMPSON_CONDITIONS, example=_simpson_example),
)
def gains_simpson_design(first, second):
    return None


# ----------------------------------------------------------------------------- 3.12
SIMPSON_3SPEED = {
    "name": "Simpson three-speed",
    "links": {0: "housing", 1: "sun", 2: "front ring", 3: "front carrier, rear ring and output", 4: "rear carrier",
              5: "front planet", 6: "rear planet", 7: "input shaft"},
    "turning_pairs": [[0, 1, "a"], [0, 2, "a"], [0, 3, "a"], [0, 4, "a"], [0, 7, "a"], [3, 5, "b"], [4, 6, "c"]],
    "gear_pairs": [{"gears": [1, 5], "teeth": [33, 21]}, {"gears": [5, 2], "teeth": [21, 75], "type": "internal"},
                   {"gears": [1, 6], "teeth": [33, 18]}, {"gears": [6, 3], "teeth": [18, 69], "type": "internal"}],
    "ground": 0, "inputs": [7], "output": 3,
    "shift_elements": [{"name": "F", "type": "clutch", "links": [7, 2]}, {"name": "D", "type": "clutch", "links": [7, 1]},
                       {"name": "B", "type": "brake", "link": 1}, {"name": "L", "type": "brake", "link": 4}],
    "schedule": [{"gear": "1st", "engaged": ["F", "L"]}, {"gear": "2nd", "engaged": ["F", "B"]},
                 {"gear": "3rd", "engaged": ["F", "D"]}, {"gear": "R", "engaged": ["D", "L"]}],
}
"""The Simpson three-speed of exercise 3.12: forward clutch F (input to front ring), direct
clutch D (input to sun), band B (holds the sun) and low brake L (holds the rear carrier)."""

_KIND = Choice(["gear", "tie-up", "output held", "under-constrained", "over-constrained"], synonyms={
    "tie-up": ["tie up", "tieup", "locked", "lock-up"]},
    generic="Not that one: write which links each element holds or joins, and follow the two sets.")
_COMBO_REASONS = {
    "A": "D joins the input to the sun and B holds the sun, so the input is held.",
    "B": "Both elements act on the front set, so the rear set is free and the output is not determined.",
    "C": "The sun is held twice, so one element adds nothing.",
    "D": "The output stands still while the input turns idle.",
}


@register(
    "gains_shift_combinations", exercise="3.12", title="Two elements too many: tie-up or idle?", stars=2,
    minutes=15, kind="concept",
    question="The Simpson three-speed gl.check.transmissions.SIMPSON_3SPEED has an input shaft 7 and four shift "
             "elements: clutch F joins 7 to the front ring 2, clutch D joins 7 to the sun 1, brake B holds the sun, "
             "brake L holds the rear carrier 4; link 3 is the output. Its gears engage F+L, F+B, F+D and D+L. What "
             "is each of the combinations D+B and B+L ('gear', 'tie-up', 'output held', 'under-constrained' or "
             "'over-constrained'), and why is D+B what it is (reason 'A', 'B', 'C' or 'D')?",
    answer=Parts({
        "D+B": ("D+B", Choice(_KIND.options, synonyms={"tie-up": ["tie up", "tieup", "locked"]}, wrong={
            "gear": "Which links does D join, and which does B hold? Can the input shaft still turn?",
            "under-constrained": "Count again: with the sun fixed, each set has one free motion left at most; "
                                 "but first ask whether the input can turn.",
            "over-constrained": "Each element adds a constraint here; the question is what the two together do to "
                                "the input.",
            "output held": "That would leave the input turning idle; can the input turn at all here?"})),
        "B+L": ("B+L", Choice(_KIND.options, synonyms={"tie-up": ["tie up", "tieup", "locked"]}, wrong={
            "gear": "Neither B nor L touches the input shaft: is the input connected to the gear set at all?",
            "tie-up": "That would lock the input; here neither element touches the input shaft.",
            "under-constrained": "The input shaft is free, but the gear set itself: with the sun and the rear "
                                 "carrier held, can link 3 turn?",
            "over-constrained": "Each element adds a constraint; look at what they do to the output."})),
        "reason": ("the reason for D+B", Choice(_COMBO_REASONS, wrong={
            "B": "D does not act on the front set only: it joins the input shaft to the common sun.",
            "C": "B holds the sun once; D joins it to the input. Together they hold the input.",
            "D": "That is what happens when no element touches the input."}))}),
)
def gains_shift_combinations():
    from ..gains.schedule import classify

    kinds = {c.label: c.kind for c in classify(_mech(SIMPSON_3SPEED), 2)}
    return {"D+B": kinds["D+B"], "B+L": kinds["B+L"], "reason": "A"}


# ----------------------------------------------------------------------------- 3.13
def _split(p) -> Fraction:
    zs, zr = p["sun"], p["ring"]
    return Fraction((zs + zr) * p["engine"] - zr * p["wheels"], zs)


def _split_params(rng) -> dict:
    while True:
        sun, planet = rng.randint(24, 40), rng.randint(18, 30)
        p = {"sun": sun, "planet": planet, "ring": sun + 2 * planet, "engine": 10 * rng.randint(80, 300),
             "wheels": 10 * rng.randint(0, 300) + rng.randint(1, 9)}
        if abs(_split(p)) > 50:
            return p


@register(
    "gains_lever_split", exercise="3.13", title="A lever for a power-split hybrid", stars=1, minutes=10,
    kind="compute",
    question="In a power-split hybrid the engine drives the carrier of a simple planetary, the ring ({ring} teeth) "
             "turns with the wheels, and the sun ({sun} teeth, planets of {planet}) drives a generator. The engine "
             "turns at {engine} rpm and the ring at {wheels} rpm. With the lever diagram (or the Willis equation), "
             "how fast does the sun turn, in rpm?",
    data={"sun": 30, "planet": 24, "ring": 78, "engine": 1650, "wheels": 1213},
    params=_split_params,
    answer=Value("speed", unit="rpm", standard=False, mistakes=[
        Mistake(lambda e, p: -e, "The size is right but the sign is not: on the lever the sun and the ring lie on "
                "opposite sides of the carrier."),
        Mistake(lambda e, p: Fraction((p["sun"] + p["ring"]) * p["engine"] - p["sun"] * p["wheels"], p["ring"]),
                "The lever arms are swapped: the sun's distance from the carrier is proportional to the ring's "
                "teeth, and the ring's distance to the sun's teeth."),
        Mistake(lambda e, p: Fraction(p["sun"] * p["engine"] + p["ring"] * p["wheels"], p["sun"] + p["ring"]),
                "That is a weighted mean of the two speeds, which puts the sun between the carrier and the ring; on "
                "the lever the carrier is the middle node."),
        Mistake(lambda e, p: e * 2 * sympy.pi / 60, "That number is the speed in rad/s; the question asks for rpm "
                "(or write the unit after the number, as in '... rad/s')."),
    ], generic="On the lever the carrier is the middle node, the sun at a distance N_ring from it and the ring at "
               "N_sun on the other side; the speeds end on one straight line."),
)
def gains_lever_split(sun, planet, ring, engine, wheels):
    from ..gains.lever import lever_diagram

    mech = _mech({"links": {0: "frame", 1: "sun", 2: "planet", 3: "ring", 4: "carrier"},
                  "turning_pairs": [[0, 1, "a"], [0, 3, "a"], [0, 4, "a"], [4, 2, "b"]],
                  "gear_pairs": [{"gears": [1, 2], "teeth": [sun, planet]},
                                 {"gears": [2, 3], "teeth": [planet, ring], "type": "internal"}]})
    return lever_diagram(mech).speeds({"ground": 0, "inputs": {4: engine, 3: wheels}})[1]
