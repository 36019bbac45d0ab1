"""Checks for chapter 4's exercises on complex weights, gear-mesh and bearing lines
(``exercises/04_complex_adjacency.ipynb``): 4.1 to 4.4, 4.9, 4.10 and 4.14. The fault-table
exercises (4.5 to 4.8, 4.11 to 4.13) are in :mod:`gearlib.check.faults`.

Exercises 4.2 to 4.4 share a planetary gearbox the chapter does not show: sun 1 (30 teeth by
default), planet 2 (30), ring 3 (held), carrier 4; the sun turns at 20 Hz. A ball bearing
(D_m = 40 mm, d_b = 6 mm, Z = 9, no contact angle) carries the planet on the carrier's pin:
inner ring on 4, outer ring in 2. Exercises 4.9 and 4.10 assign Penaud's angles to bevel
gears whose axes are given by their directions in the plane of the axes. Variants draw other
teeth, speeds and shaft angles. Exercise 4.14 puts a shaft in a housing on a ball bearing the
chapter does not use.
"""

from __future__ import annotations

import cmath
import math
from fractions import Fraction

from ._choice import Parts
from ._compare import numeric
from ._core import register
from ._design import Condition, Design
from ._model import Model, Scenario
from ._spec import Verdict
from ._value import Hint, Mistake, Value

__all__ = ["adjacency_planet_ratio", "adjacency_mesh_frequency", "adjacency_planet_tooth_frequency",
           "adjacency_outer_ring_frequency", "adjacency_bevel_angles", "adjacency_bevel_model",
           "adjacency_shaft_bearing"]

_BOX = {"sun": 30, "planet": 30, "f_sun": 20}


def _box(rng) -> dict:
    return {"sun": rng.randint(18, 40), "planet": rng.randint(18, 40), "f_sun": rng.choice((10, 12, 15, 20, 24, 25,
                                                                                              30, 40, 50))}


def _speeds(sun, planet, f_sun) -> dict:
    """Carrier, planet (absolute) and planet relative to the carrier, in Hz, by the classic
    formulas (ring held)."""
    ring = sun + 2 * planet
    f_c = Fraction(f_sun) * Fraction(sun, sun + ring)
    rel_sun = Fraction(f_sun) - f_c
    rel_planet = -Fraction(sun, planet) * rel_sun
    return {"ring": ring, "carrier": f_c, "rel_sun": rel_sun, "planet": f_c + rel_planet, "rel_planet": rel_planet}


def _table(sun, planet, f_sun, bearing: bool = False):
    from ..adjacency.frequencies import frequency_table
    from ..catalog import simple_planetary
    from ..mechanism.elements import Bearing

    mech = simple_planetary(sun=sun, ring=sun + 2 * planet, planet=planet)
    bearings = [((4, 2), Bearing(pitch_diameter=40, ball_diameter=6, balls=9, inner=4, name="planet bearing"))] \
        if bearing else None
    return frequency_table(mech, ground=3, inputs={1: f_sun}, bearings=bearings, unit="Hz")


def _same_size(a, e):
    return abs(abs(numeric(a)) - abs(numeric(e))) <= 1e-3 * abs(numeric(e))


# ----------------------------------------------------------------------------- 4.1
def _penaud(ring, planet):
    from ..catalog import load
    from ..mechanism.data import Mechanism

    data = load("penaud_example_1").to_dict()
    for gp in data["gear_pairs"]:
        if gp["gears"] == [2, 3]:
            gp["teeth"] = [ring, planet]
    return Mechanism.from_dict(data)


@register(
    "adjacency_planet_ratio", exercise="4.1", title="A bevel planet on fixed axes", stars=2, minutes=20,
    kind="compute",
    question="Penaud and Alazard's bevel planet (example 1, gl.catalog.load('penaud_example_1'): sun 1, ring 2, "
             "planet 3, carrier 4) with a ring of {ring} teeth and a planet of {planet} (the angles unchanged), "
             "now with the carrier held and the ring driven. Build the constraint row C that holds link 4, stack it "
             "under M, take the null space and normalise it to the ring: give omega_3/omega_2, a complex number.",
    data={"ring": 25, "planet": 10},
    params=lambda rng: {"ring": rng.randint(20, 40), "planet": rng.randint(8, 16)},
    answer=Value("ratio", mistakes=[
        Hint(lambda a, e, p: _same_size(a, e) and abs(numeric(a).imag) < 1e-9, "The size is right, but a real "
             "number cannot point along the planet's axis: keep the phase of the complex gear ratio."),
        Hint(lambda a, e, p: _same_size(a, e), "The size is right; the direction is not. The phase of e_(2,3) = "
             "-T(2,3)/T(3,2) is pi + theta_2 - theta_3."),
        Mistake(lambda e, p: 1 / e, "You have the reciprocal, the ring over the planet: the question asks for "
                "omega_3/omega_2, the planet over the ring."),
        Hint(lambda a, e, p: abs(abs(numeric(a)) - 1) < 1e-9, "A speed ratio of size 1 means the whole train turns "
             "as one body: did you forget the constraint row that holds the carrier?"),
    ], standard=False, generic="Stack M with C = [0 0 0 1], take the null space (one column) and divide it by its "
                               "entry for link 2."),
)
def adjacency_planet_ratio(ring, planet):
    from ..mechanism.kinematics import ratio

    return ratio(_penaud(ring, planet), output=3, input=2, ground=4)  # exact: the weights are algebraic


# ----------------------------------------------------------------------------- 4.2 to 4.4
_GEARBOX = ("A planetary gearbox: sun 1 with {sun} teeth, planet 2 with {planet}, ring 3 held (the teeth that "
            "fit), carrier 4 the output; the sun turns at {f_sun} Hz.")


@register(
    "adjacency_mesh_frequency", exercise="4.2", title="The mesh frequency of a planetary", stars=1, minutes=10,
    kind="compute",
    question=_GEARBOX + " How many teeth come into mesh per second between the sun and the planet? Give the mesh "
                        "frequency in Hz.",
    data=_BOX, params=_box,
    answer=Value("frequency", mistakes=[
        Mistake(lambda e, p: p["sun"] * p["f_sun"], "You multiplied the sun's teeth by the sun's speed relative to "
                "the frame. Teeth come into mesh at the speed relative to the carrier, and the carrier turns."),
        Mistake(lambda e, p: p["planet"] * abs(_speeds(**p)["planet"]), "You used the planet's speed relative to "
                "the frame; use its speed relative to the carrier, which holds the planet's axis."),
        Mistake(lambda e, p: _speeds(**p)["ring"] * p["f_sun"], "That is the ring's teeth times the sun's speed; "
                "the ring is held, but the carrier is not."),
    ], generic="Find the carrier's speed first (ring held), then multiply a gear's teeth by its speed relative to "
               "the carrier."),
)
def adjacency_mesh_frequency(sun, planet, f_sun):
    return _table(sun, planet, f_sun).select(kind="mesh", pair=(1, 2))[0].frequency


@register(
    "adjacency_planet_tooth_frequency", exercise="4.3", title="A chipped planet tooth", stars=1, minutes=10,
    kind="compute",
    question=_GEARBOX + " One tooth of the planet is chipped. How many times per second does that tooth meet the "
                        "sun? Give the frequency in Hz.",
    data=_BOX, params=_box,
    answer=Value("frequency", mistakes=[
        Mistake(lambda e, p: abs(_speeds(**p)["planet"]), "That is the planet's speed relative to the frame. The "
                "defective tooth meets the sun once per turn of the planet relative to the carrier."),
        Mistake(lambda e, p: p["sun"] * _speeds(**p)["rel_sun"], "That is the mesh frequency: every tooth, not the "
                "one defective tooth."),
        Mistake(lambda e, p: _speeds(**p)["carrier"], "That is the carrier's speed; the planet turns relative to "
                "the carrier too."),
        Mistake(lambda e, p: p["f_sun"], "That is the sun's speed relative to the frame."),
        Mistake(lambda e, p: 2 * e, "That counts the ring as well: the question asks how often the tooth meets the "
                "sun alone."),
    ], generic="The defect meets the sun once per revolution of the planet relative to the carrier."),
)
def adjacency_planet_tooth_frequency(sun, planet, f_sun):
    return _table(sun, planet, f_sun).select(kind="tooth", pair=(1, 2), link=2)[0].frequency


def _bpfo(f_r, inner=False, factor=True):
    z, d, big = 9, Fraction(6), Fraction(40)
    return Fraction(z, 2) * ((1 + d / big) if inner else (1 - d / big) if factor else 1) * f_r


@register(
    "adjacency_outer_ring_frequency", exercise="4.4", title="A defect on a planet bearing's outer ring", stars=2,
    minutes=15, kind="compute",
    question=_GEARBOX + " The planet turns on a ball bearing on the carrier's pin: inner ring on the pin (link 4), "
                        "outer ring in the planet (link 2); D_m = 40 mm, d_b = 6 mm, Z = 9 balls, no contact angle. "
                        "At what frequency (Hz) does a defect on the outer ring repeat?",
    data=_BOX, params=_box,
    answer=Value("frequency", mistakes=[
        Mistake(lambda e, p: _bpfo(abs(_speeds(**p)["planet"])), "You used the planet's speed relative to the "
                "frame. The bearing only sees the speed of its inner ring relative to its outer ring: planet "
                "relative to carrier."),
        Mistake(lambda e, p: _bpfo(abs(_speeds(**p)["rel_planet"]), inner=True), "That is the inner-ring "
                "frequency, (Z/2)(1 + d/D) f_r; the outer ring has (1 - d/D)."),
        Mistake(lambda e, p: _bpfo(abs(_speeds(**p)["rel_planet"]), factor=False), "You left out the factor "
                "(1 - d cos(alpha)/D_m): the cage carrying the balls does not turn at exactly half the relative "
                "speed."),
        Mistake(lambda e, p: 9 * abs(_speeds(**p)["rel_planet"]), "Z f_r counts every ball passing at the full "
                "relative speed; the cage carries the balls along at its own speed."),
    ], generic="Take f_r = |omega_inner - omega_outer| and the standard BPFO = (Z/2)(1 - d cos(alpha)/D_m) f_r."),
)
def adjacency_outer_ring_frequency(sun, planet, f_sun):
    return _table(sun, planet, f_sun, bearing=True).select(kind="outer ring", pair=(4, 2))[0].frequency


# ----------------------------------------------------------------------------- 4.9
def _turn(x: float) -> float:
    """An angle in radians reduced to (-pi, pi]."""
    return math.atan2(math.sin(x), math.cos(x))


def _phase_ok(d, p) -> bool:
    want = math.radians(p["shaft"])  # the angle from a's axis to b's, both pointing away from the apex
    return abs(_turn(d["theta_a"] - d["theta_b"] - want)) <= 2e-3


def _phase_message(d, p) -> str:
    got = math.degrees(_turn(math.pi + d["theta_a"] - d["theta_b"])) % 360
    return (f"with these angles e_(a,b) has the phase pi + theta_a - theta_b, {got:.1f} degrees: gear b's angular "
            "velocity (relative to the frame) would point that far round from gear a's. Draw both angular "
            "velocities at the pitch point: two bevel gears whose axes point away from the apex turn in opposite "
            "senses about those axes")


def _bevel_conditions():
    return [
        Condition("tooth numbers", lambda d, p: all(12 <= d[k] <= 120 for k in ("N_a", "N_b")),
                  "a bevel gear here needs 12 to 120 teeth"),
        Condition("ratio", lambda d, p: abs(Fraction(d["N_b"], d["N_a"]) / p["reduction"] - 1) <= Fraction(2, 100),
                  lambda d, p: f"your reduction N_b/N_a is {d['N_b'] / d['N_a']:.4g}; the target is {p['reduction']} "
                               "within 2 %"),
        Condition("direction", _phase_ok, _phase_message),
    ]


def _bevel_example(p) -> dict:
    n_a = 20
    return {"N_a": n_a, "N_b": round(n_a * p["reduction"]), "theta_a": math.radians(p["shaft"]), "theta_b": 0.0}


@register(
    "adjacency_bevel_angles", exercise="4.9", title="Penaud's angles for a new bevel pair", stars=2, minutes=20,
    kind="design",
    question="A bevel pinion a drives a bevel wheel b; both turn in a frame, which is their carrier. Their axes meet at "
             "the apex O and lie in the plane of the complex numbers: a's axis points from O along the angle 0, b's "
             "along the angle {shaft} degrees (both pointing from O towards the gear). Choose the teeth N_a and N_b "
             "(12 to 120) for a reduction N_b/N_a of {reduction} within 2 %, and Penaud's angles theta_a and theta_b "
             "(radians) so that e_(a,b) = -(N_a/N_b) exp(i (theta_a - theta_b)) gives gear b's angular velocity, "
             "as a complex number, in the right direction.",
    data={"shaft": 90, "reduction": 3},
    params=lambda rng: {"shaft": rng.choice((60, 75, 90, 105, 120, 135)), "reduction": rng.choice((2, 3, 4))},
    answer=Design({"N_a": "teeth", "N_b": "teeth", "theta_a": "number", "theta_b": "number"}, _bevel_conditions(),
                  example=_bevel_example),
)
def adjacency_bevel_angles(shaft, reduction):
    return None


# ----------------------------------------------------------------------------- 4.10
_ROLES = ("left gear", "right gear", "planet", "case")


def _differential(side, planet):
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict({
        "links": {1: "left gear", 2: "right gear", 3: "planet", 4: "case"},
        "turning_pairs": [[4, 1, "a"], [4, 2, "a"], [4, 3, "b"]],
        "gear_pairs": [{"gears": [1, 3], "teeth": [side, planet], "type": "bevel", "angles": ["pi", "-pi/2"]},
                       {"gears": [2, 3], "teeth": [side, planet], "type": "bevel", "angles": [0, "-pi/2"]}],
    })


class _BevelModel(Model):
    """A :class:`Model` that says when the speeds have the right sizes but point the wrong way."""

    def judge(self, answer, reference, params) -> Verdict:
        verdict = super().judge(answer, reference, params)
        if verdict.passed or not ("another speed" in verdict.message or "wrong way" in verdict.message):
            return verdict
        from ._model import _mechanism

        mech, roles = _mechanism(answer)
        roles = self._roles(mech, roles)
        for scenario, (_, ref) in zip(self.scenarios, reference["runs"]):
            _, got = self._speeds(mech, roles, scenario)
            for role in self.compare:
                a, e = got[role], ref[role]
                if abs(abs(a) - abs(e)) <= 1e-9 * max(1.0, abs(e)) and abs(a - e) > 1e-9 * max(1.0, abs(e)):
                    turn = math.degrees(_turn(cmath.phase(a) - cmath.phase(e)))
                    return Verdict(False, f"With the {scenario.ground} held, the {role} turns at the right rate but "
                                   f"its angular velocity points {abs(turn):.0f} degrees away from where it should: "
                                   "check Penaud's angles of the pairs on its path (the phase of e_(i,j) is pi + "
                                   "theta_i - theta_j)")
        return verdict


@register(
    "adjacency_bevel_model", exercise="4.10", title="A bevel differential as data, with Penaud's angles", stars=3,
    minutes=30, kind="model",
    question="A bevel differential: a left side gear and a right side gear ({side} teeth each) turn in the case about "
             "the axle; a planet ({planet} teeth) turns on a pin of the case and meshes both. All axes meet at the "
             "apex O and lie in the plane of the complex numbers: the left gear's axis points from O along the "
             "angle pi, the right gear's along 0, the planet's along pi/2 (each pointing from O towards its gear). "
             "Write it as data for gl.Mechanism.from_dict, with bevel pairs given by their teeth and Penaud's "
             "angles, and the links named 'left gear', 'right gear', 'planet' and 'case'.",
    data={"side": 30, "planet": 18},
    params=lambda rng: {"side": rng.randint(24, 40), "planet": rng.randint(12, 22)},
    answer=_BevelModel(_ROLES, [Scenario("case", {"left gear": 1}), Scenario("left gear", {"case": 1}),
                                Scenario("right gear", {"left gear": 1})]),
)
def adjacency_bevel_model(side, planet):
    return _differential(side, planet)


# ----------------------------------------------------------------------------- 4.14
def _shaft(p):
    """A shaft 1 in a housing 0 on the exercise's ball bearing (inner ring on the shaft)."""
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict({"links": {0: "housing", 1: "shaft"}, "turning_pairs": [{
        "links": [0, 1], "axis": "a", "bearings": [{"name": "shaft bearing", "pitch_diameter": p["D"],
                                                    "ball_diameter": p["d"], "balls": p["Z"], "inner": 1}]}]})


def _rings(p) -> dict:
    """The classic lines by hand: f_r, BPFI, BPFO, the cage relative to either ring."""
    f_r, g = Fraction(p["rpm"], 60), Fraction(p["d"]) / Fraction(p["D"])
    return {"f_r": f_r, "bpfi": Fraction(p["Z"], 2) * (1 + g) * f_r, "bpfo": Fraction(p["Z"], 2) * (1 - g) * f_r,
            "ftf": (1 - g) / 2 * f_r, "ftf_inner": (1 + g) / 2 * f_r}


def _shaft_params(rng) -> dict:
    d = rng.randint(6, 14)
    return {"Z": rng.randint(8, 14), "d": d, "D": rng.randint(4 * d, 6 * d), "rpm": rng.choice((1450, 1750, 2900, 3550))}


_RINGS = Parts({
    "bpfi": ("BPFI", Value("frequency", mistakes=[
        Mistake(lambda e, p: _rings(p)["bpfo"], "That is the outer race's line, (Z/2)(1 - g) f_r: the inner race "
                "meets the balls faster, (Z/2)(1 + g) f_r."),
        Mistake(lambda e, p: p["Z"] * _rings(p)["f_r"] / 2, "That leaves out g = d_b cos(alpha)/D_m: the cage does "
                "not turn at exactly half the shaft's speed."),
    ], generic="Take f_r, the inner ring's speed relative to the outer ring; a defect on the inner race meets the Z "
               "balls once per turn of the inner ring relative to the cage.")),
    "ftf": ("FTF", Value("frequency", mistakes=[
        Mistake(lambda e, p: _rings(p)["ftf_inner"], "That is the cage's speed relative to the inner ring; FTF is "
                "the cage relative to the outer ring, (1 - g) f_r / 2."),
        Mistake(lambda e, p: _rings(p)["f_r"] / 2, "That leaves out g: the ball's centre moves at the mean of its two "
                "contact points' speeds, which are at D_m (1 - g)/2 and D_m (1 + g)/2 from the axis."),
    ], generic="The cage turns with the balls' centres, at the mean speed of their two contact points; FTF is its "
               "speed relative to the outer ring.")),
    "sideband": ("the sideband", Value("frequency", mistakes=[
        Mistake(lambda e, p: _rings(p)["bpfi"] - _rings(p)["f_r"], "That is the lower sideband; the question asks "
                "for the first one above BPFI."),
        Mistake(lambda e, p: _rings(p)["bpfi"] + _rings(p)["ftf"], "That sideband is spaced by the cage's speed: an "
                "inner-race defect passes through the load zone once per turn of the shaft."),
        Mistake(lambda e, p: _rings(p)["bpfi"], "That is BPFI itself."),
    ], generic="The load zone modulates an inner-race defect once per turn of the shaft: the sidebands are BPFI "
               "plus and minus multiples of the shaft's speed.")),
})


@register(
    "adjacency_shaft_bearing", exercise="4.14", title="An inner-race defect and its sidebands", stars=2,
    minutes=15, kind="compute",
    question="A motor shaft at {rpm} rpm runs in a deep-groove ball bearing in the housing: Z = {Z} balls of d_b = {d} "
             "mm on a pitch diameter D_m = {D} mm, no contact angle, inner ring on the shaft. Give, in Hz, (a) BPFI, "
             "(b) FTF, and (c) the first sideband above BPFI (an inner-race defect passes through the load zone, "
             "fixed in the housing, once per turn of the shaft).",
    data={"Z": 10, "d": 9, "D": 46, "rpm": 1750}, params=_shaft_params,
    answer=_RINGS,
)
def adjacency_shaft_bearing(Z, d, D, rpm):
    from ..adjacency.monitoring import fault_table

    p = {"Z": Z, "d": d, "D": D, "rpm": rpm}
    table = fault_table(_shaft(p), ground=0, inputs={1: f"{rpm}rpm"}, sidebands=1)
    (bpfi,) = table.select(kind="BPFI", fundamental=True)
    (ftf,) = table.select(kind="FTF", fundamental=True)
    (upper,) = [r for r in table.select(family="inner race", kind="sideband") if r.sideband == 1]
    return {"bpfi": bpfi.frequency, "ftf": ftf.frequency, "sideband": upper.frequency}
