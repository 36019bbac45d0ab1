"""Checks for chapter 4's condition-monitoring exercises (``exercises/04_complex_adjacency.ipynb``):
4.5 to 4.8 and 4.11 to 4.13, the lines of :func:`gearlib.fault_table`.

The trains are not the chapter's (its planetary stage has 17, 40 and 97 teeth and three
planets at 1480 rpm): a stage with four planets (4.5), a stage with three (4.6, 4.7), a
parallel pair whose teeth share a factor (4.8), a stage to design (4.11), an angular-contact
ball bearing (4.12). Frequencies are in Hz; rpm and rad/s are converted when the answer
carries its unit, and a number in rad/s without its unit is diagnosed.
"""

from __future__ import annotations

import math
from fractions import Fraction

import sympy

from ._choice import Choice, Parts
from ._core import Prediction, register
from ._design import Condition, Design
from ._value import Mistake, Symbolic, Value

__all__ = ["adjacency_planetary_lines", "adjacency_ring_fault", "adjacency_sun_fault_formula",
           "adjacency_hunting_tooth", "adjacency_quiet_planetary", "adjacency_ball_line",
           "adjacency_bearing_placement"]

_RPM = (900, 1000, 1200, 1450, 1500, 1800, 2400, 3000)


def _stage(sun, planet, ring, planets):
    """Housing 0 with the ring, sun 1 (input), planet link 2 standing for *planets* planets, carrier 3."""
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict({
        "links": {0: "housing and ring", 1: "sun", 2: "planet", 3: "carrier"},
        "turning_pairs": [[0, 1, "a"], [0, 3, "a"], [3, 2, "b"]],
        "gear_pairs": [{"gears": [1, 2], "teeth": [sun, planet]},
                       {"gears": [2, 0], "teeth": [planet, ring], "type": "internal"}],
        "planets": {2: planets},
    })


def _line(table, **kw) -> float:
    (row,) = table.select(fundamental=True, **kw)
    return row.frequency


def _faults(sun, planet, ring, planets, rpm, **options):
    from ..adjacency.monitoring import fault_table

    return fault_table(_stage(sun, planet, ring, planets), ground=0, inputs={1: f"{rpm}rpm"}, **options)


def _stage_teeth(rng, planets=(3, 4, 5)) -> dict:
    while True:
        n, s, p = rng.choice(planets), rng.randint(16, 30), rng.randint(18, 40)
        r = s + 2 * p
        if (s + r) % n == 0:
            return {"sun": s, "planet": p, "ring": r, "planets": n}


def _hz(p) -> dict:
    """The classic speeds in Hz (ring held): sun, carrier, sun relative to the carrier."""
    f_s = Fraction(p["rpm"], 60)
    f_c = f_s * Fraction(p["sun"], p["sun"] + p["ring"])
    return {"sun": f_s, "carrier": f_c, "rel": f_s - f_c}


# ----------------------------------------------------------------------------- 4.5
_PP = Value("frequency", planets=lambda p: p["planets"], mistakes=[
    Mistake(lambda e, p: p["planets"] * _hz(p)["rel"], "That is the sun's local-fault line: the planets pass a "
            "point of the housing at the carrier's speed, not at the sun's speed relative to the carrier."),
    Mistake(lambda e, p: p["planets"] * _hz(p)["sun"], "That uses the sun's speed; the planets travel with the "
            "carrier."),
], generic="The planets travel with the carrier: count how many pass a point of the housing per turn of the "
           "carrier, and find the carrier's speed with the ring held.")
_SUN = Value("frequency", planets=lambda p: p["planets"], mistakes=[
    Mistake(lambda e, p: p["planets"] * _hz(p)["sun"], "You used the sun's speed relative to the housing. A sun "
            "tooth meets the planets as the sun turns relative to the carrier, which turns too."),
    Mistake(lambda e, p: p["sun"] * _hz(p)["rel"], "That is the mesh frequency, every tooth of the sun; the "
            "question follows one damaged tooth."),
    Mistake(lambda e, p: p["planets"] * _hz(p)["carrier"], "That is the planet-pass frequency: the damaged tooth "
            "is on the sun, which turns relative to the carrier at another speed."),
], generic="Find the sun's speed relative to the carrier; per turn of it, one sun tooth meets every planet once.")


@register(
    "adjacency_planetary_lines", exercise="4.5", title="Planet pass and a cracked sun tooth", stars=2, minutes=15,
    kind="compute",
    question="A planetary stage: the motor drives the sun ({sun} teeth) at {rpm} rpm; {planets} equally spaced "
             "planets ({planet} teeth) roll in the ring ({ring} teeth) of the housing; the carrier is the output. "
             "Give (a) the planet-pass frequency and (b) the local-fault frequency of a cracked sun tooth, both in "
             "Hz.",
    data={"sun": 19, "planet": 29, "ring": 77, "planets": 4, "rpm": 1200},
    params=lambda rng: {**_stage_teeth(rng), "rpm": rng.choice(_RPM)},
    answer=Parts({"planet_pass": ("the planet-pass frequency", _PP), "sun_fault": ("the sun-fault frequency", _SUN)}),
)
def adjacency_planetary_lines(sun, planet, ring, planets, rpm):
    table = _faults(sun, planet, ring, planets, rpm)
    return {"planet_pass": _line(table, family="planet pass"), "sun_fault": _line(table, family="sun fault")}


# ----------------------------------------------------------------------------- 4.6
_HIGHER = Choice(["the sun's line is higher", "the ring's line is higher", "they are at the same frequency"],
                 synonyms={"the sun's line is higher": ["sun", "the sun's", "sun higher"],
                           "the ring's line is higher": ["ring", "the ring's", "ring higher"],
                           "they are at the same frequency": ["same", "equal", "the same"]})


def _orders(p, what) -> Fraction:
    s, r, n = p["sun"], p["ring"], p["planets"]
    return {"ring": Fraction(n * s, s + r), "sun": Fraction(n * r, s + r)}[what]


@register(
    "adjacency_ring_fault", exercise="4.6", title="Predict, then compute: a pitted ring tooth", stars=1, minutes=10,
    kind="predict",
    question="A planetary stage with a sun of {sun} teeth (the input), {planets} planets of {planet} teeth and a "
             "ring of {ring} teeth fixed in the housing. First predict how the local-fault line of a pitted ring "
             "tooth compares with that of a cracked sun tooth ('the sun's line is higher', 'the ring's line is "
             "higher', 'they are at the same frequency') and record it; then compute the ring tooth's line in "
             "orders of the input shaft.",
    data={"sun": 21, "planet": 27, "ring": 75, "planets": 3},
    params=_stage_teeth,
    answer=Value("number", unit="orders", mistakes=[
        Mistake(lambda e, p: _orders(p, "sun"), "That is the sun tooth's line: a ring tooth stands still, and the "
                "planets pass it as the carrier turns."),
        Mistake(lambda e, p: [e / p["planets"], e * p["planets"]], "That is off by the number of planets: one ring "
                "tooth meets every planet once per turn of the carrier."),
        Mistake(lambda e, p: Fraction(p["ring"], p["planets"]) * e, "That is the mesh frequency in orders: every "
                "tooth of the ring, not one pitted tooth."),
        Mistake(lambda e, p: -e, "An order counts events per turn of the input shaft: give its size."),
    ], standard=False, generic="Find the carrier's speed in orders of the sun (the ring held); per turn of the "
                               "carrier relative to the ring, a ring tooth meets every planet once."),
    predict=Prediction(_HIGHER, lambda ref, p: "the sun's line is higher",
                       lambda p: f"Relative to the carrier the sun turns N_ring/N_sun = {p['ring']}/{p['sun']} times "
                                 "as fast as the ring, and both teeth meet every planet once per relative turn: the "
                                 "sun's line is higher by that factor. With the ring held, its line is the "
                                 "planet-pass frequency."),
)
def adjacency_ring_fault(sun, planet, ring, planets):
    table = _faults(sun, planet, ring, planets, 60)
    (row,) = table.select(family="ring fault", fundamental=True)
    return row.order


# ----------------------------------------------------------------------------- 4.7
_N, _ZS, _ZR, _FS = sympy.symbols("N Z_s Z_r f_s")


@register(
    "adjacency_sun_fault_formula", exercise="4.7", title="The sun-fault line in symbols", stars=2, minutes=15,
    kind="derive",
    question="A simple planetary stage with the ring held: a sun of Z_s teeth turning at f_s (Hz), N equally "
             "spaced planets, a ring of Z_r teeth. Derive the local-fault frequency of one damaged sun tooth in "
             "terms of N, Z_s, Z_r and f_s.",
    answer=Symbolic(("N", "Z_s", "Z_r", "f_s"), values=lambda p: {"N": 3, "Z_s": 21, "Z_r": 75, "f_s": 20},
                    standard=False, mistakes=[
        Mistake(lambda e, p: _N * _ZS * _FS / (_ZS + _ZR), "That is N times the carrier's speed, the planet-pass "
                "frequency; the sun tooth meets the planets at the sun's speed relative to the carrier."),
        Mistake(lambda e, p: _N * _FS, "That uses the sun's speed relative to the housing; the planets it meets "
                "move with the carrier."),
        Mistake(lambda e, p: _ZR * _FS / (_ZS + _ZR), "That is one planet's share: the tooth meets each of the N "
                "planets once per turn relative to the carrier."),
        Mistake(lambda e, p: _ZS * _ZR * _FS / (_ZS + _ZR), "That is the mesh frequency, every tooth of the sun."),
        Mistake(lambda e, p: _N * _ZS * _ZR * _FS / (_ZS + _ZR), "That counts every tooth of the sun: the question "
                "follows one damaged tooth."),
        Mistake(lambda e, p: -e, "A frequency is a number of events per second, never negative: check the sign of "
                "the sun's speed relative to the carrier."),
    ], generic="Write Willis' equation of the two meshes with the ring held to find the carrier's speed, then the "
               "sun's speed relative to the carrier; one sun tooth meets N planets per relative turn."),
)
def adjacency_sun_fault_formula():
    f_c, f_p, z_p = sympy.symbols("f_c f_p Z_p")
    sol = sympy.solve([f_p - f_c + _ZS / z_p * (_FS - f_c),   # sun-planet: e = -Z_s/Z_p
                       0 - f_c - z_p / _ZR * (f_p - f_c)],    # planet-ring, the ring held: e = Z_p/Z_r
                      [f_p, f_c], dict=True)[0]
    return sympy.factor(_N * (_FS - sol[f_c]))


# ----------------------------------------------------------------------------- 4.8
def _pair(z1, z2):
    from ..mechanism.data import Mechanism

    return Mechanism.from_dict({"links": {0: "frame", 1: "pinion shaft", 2: "wheel shaft"},
                                "turning_pairs": [[0, 1, "a"], [0, 2, "b"]],
                                "gear_pairs": [{"gears": [1, 2], "teeth": [z1, z2]}]})


def _pair_hz(p) -> dict:
    f1 = Fraction(p["rpm"], 60)
    return {"pinion": f1, "wheel": f1 * Fraction(p["z1"], p["z2"]), "mesh": f1 * p["z1"],
            "n_a": math.gcd(p["z1"], p["z2"])}


def _pair_teeth(rng) -> dict:
    while True:
        z1, z2 = rng.randint(17, 32), rng.randint(50, 120)
        if math.gcd(z1, z2) >= 2 and z2 % z1:
            return {"z1": z1, "z2": z2, "rpm": rng.choice(_RPM)}


_HUNT = Parts({
    "assembly": ("the assembly-phase frequency", Value("frequency", mistakes=[
        Mistake(lambda e, p: [_pair_hz(p)["pinion"], _pair_hz(p)["wheel"]], "That is a shaft speed. The mesh pattern "
                "repeats when a tooth comes back to the same set of mating teeth: every n_a = gcd(N_1, N_2) meshes."),
        Mistake(lambda e, p: _pair_hz(p)["mesh"] * _pair_hz(p)["n_a"], "You multiplied by the common factor; the "
                "pattern repeats n_a times more slowly than the teeth mesh."),
    ])),
    "hunting": ("the hunting-tooth frequency", Value("frequency", mistakes=[
        Mistake(lambda e, p: _pair_hz(p)["mesh"] / (p["z1"] * p["z2"]), "That is f_m/(N_1 N_2): with a common "
                "factor the same two teeth meet again sooner, after lcm(N_1, N_2) meshes."),
        Mistake(lambda e, p: [_pair_hz(p)["pinion"], _pair_hz(p)["wheel"]], "That is a shaft speed: the same two "
                "teeth meet again only when both gears have come back to the same pair of teeth."),
    ])),
    "sideband": ("the sideband", Value("frequency", mistakes=[
        Mistake(lambda e, p: _pair_hz(p)["mesh"] - _pair_hz(p)["pinion"], "That sideband is spaced by the pinion "
                "shaft's speed; the question asks for the one spaced by the wheel shaft's."),
        Mistake(lambda e, p: _pair_hz(p)["mesh"] + _pair_hz(p)["wheel"], "That is the upper sideband; the question "
                "asks for the first one below the mesh frequency."),
        Mistake(lambda e, p: _pair_hz(p)["mesh"], "That is the mesh frequency itself."),
    ])),
})


@register(
    "adjacency_hunting_tooth", exercise="4.8", title="Hunting tooth, assembly phases and a sideband", stars=2,
    minutes=20, kind="compute",
    question="A parallel helical stage: a pinion of {z1} teeth on the motor shaft at {rpm} rpm drives a wheel of "
             "{z2} teeth. Give, in Hz, (a) the assembly-phase frequency, (b) the hunting-tooth frequency, and (c) the "
             "first sideband below the mesh frequency spaced by the wheel shaft's speed (an eccentric wheel "
             "modulates the mesh once per turn).",
    data={"z1": 24, "z2": 90, "rpm": 1500},
    params=_pair_teeth,
    answer=_HUNT,
)
def adjacency_hunting_tooth(z1, z2, rpm):
    from ..adjacency.monitoring import fault_table

    table = fault_table(_pair(z1, z2), ground=0, inputs={1: f"{rpm}rpm"}, sidebands=1)
    (lower,) = [r for r in table.select(family="mesh", kind="sideband") if r.sideband == -1 and "wheel" in r.name]
    return {"assembly": _line(table, family="assembly phase"), "hunting": _line(table, family="hunting tooth"),
            "sideband": lower.frequency}


# ----------------------------------------------------------------------------- 4.11
def _gmf(d, p) -> float:
    f_s = p["rpm"] / 60
    return d["sun"] * f_s * d["ring"] / (d["sun"] + d["ring"])


def _quiet_conditions():
    return [
        Condition("tooth numbers", lambda d, p: all(17 <= d[k] <= 150 for k in ("sun", "planet", "ring")),
                  "every gear needs 17 to 150 teeth"),
        Condition("concentric", lambda d, p: d["ring"] == d["sun"] + 2 * d["planet"],
                  "with one module the planet fits between sun and ring only when N_ring = N_sun + 2 N_planet"),
        Condition("equal spacing", lambda d, p: (d["sun"] + d["ring"]) % p["planets"] == 0,
                  lambda d, p: f"{p['planets']} planets can be spaced equally only when (N_sun + N_ring)/"
                               f"{p['planets']} is a whole number"),
        Condition("reduction", lambda d, p: p["low_ratio"] <= 1 + d["ring"] / d["sun"] <= p["high_ratio"],
                  lambda d, p: f"your reduction sun/carrier is {1 + d['ring'] / d['sun']:.4g}; it must lie between "
                               f"{p['low_ratio']} and {p['high_ratio']}"),
        Condition("resonance", lambda d, p: not p["band_low"] <= _gmf(d, p) <= p["band_high"],
                  lambda d, p: f"your mesh frequency is {_gmf(d, p):.4g} Hz, inside the housing's resonance band "
                               f"({p['band_low']} to {p['band_high']} Hz)"),
        Condition("hunting tooth", lambda d, p: math.gcd(d["sun"], d["planet"]) == 1 == math.gcd(d["planet"],
                                                                                                   d["ring"]),
                  "the planet shares a factor with the sun or the ring, so a damaged tooth keeps meeting the same "
                  "few teeth of its mate: choose tooth numbers without a common factor"),
    ]


def _quiet_example(p):
    conditions = _quiet_conditions()
    for sun in range(17, 80):
        for planet in range(17, 67):
            d = {"sun": sun, "planet": planet, "ring": sun + 2 * planet}
            if all(c.test(d, p) for c in conditions):
                return d
    return None


def _quiet_params(rng) -> dict:
    while True:
        lo = rng.choice((3.5, 4, 4.5, 5))
        low = rng.randrange(250, 600, 10)
        p = {"rpm": rng.choice(_RPM[2:]), "planets": rng.choice((3, 4)), "low_ratio": lo, "high_ratio": lo + 1.5,
             "band_low": low, "band_high": low + rng.randrange(60, 121, 10)}
        if _quiet_example(p) is not None:
            return p


@register(
    "adjacency_quiet_planetary", exercise="4.11", title="Design a stage whose mesh misses a resonance", stars=3,
    minutes=30, kind="design",
    question="Choose the teeth of a planetary stage (ring held, sun in at {rpm} rpm, carrier out, {planets} planets "
             "equally spaced, one module) with a reduction sun/carrier between {low_ratio} and {high_ratio}, whose "
             "mesh frequency stays out of the housing's resonance band from {band_low} to {band_high} Hz, and whose "
             "planet shares no factor with the sun or the ring (a hunting-tooth design). Every gear has 17 to 150 "
             "teeth. Give {'sun': ..., 'planet': ..., 'ring': ...}.",
    data={"rpm": 1500, "planets": 3, "low_ratio": 4, "high_ratio": 5.5, "band_low": 380, "band_high": 460},
    params=_quiet_params,
    answer=Design({"sun": "teeth", "planet": "teeth", "ring": "teeth"}, _quiet_conditions(), example=_quiet_example),
)
def adjacency_quiet_planetary(rpm, planets, low_ratio, high_ratio, band_low, band_high):
    return None


# ----------------------------------------------------------------------------- 4.12
def _ball(p, convention="standard", radians=False) -> float:
    from ..adjacency.bearings import bearing_frequencies
    from ..mechanism.elements import Bearing

    angle = p["alpha"] if radians else sympy.pi * p["alpha"] / 180
    brg = Bearing(pitch_diameter=p["D"], ball_diameter=p["d"], balls=p["Z"],
                  contact_angle=angle if float(angle) < math.pi / 2 else 0)
    f = bearing_frequencies(brg, omega_inner=p["rpm"] / 60, omega_outer=0)
    return f.paper_ball if convention == "paper" else f.ball_defect if convention == "standard" else f.ball_spin


def _ball_data(Z, D, d, alpha, rpm) -> dict:
    p = {"Z": Z, "D": D, "d": d, "alpha": alpha, "rpm": rpm}
    return {**p, "x_printed": round(_ball(p, "paper"), 1)}


def _ball_params(rng) -> dict:
    d = rng.choice((7, 8, 9, 10, 11, 12))
    return _ball_data(rng.randint(10, 16), rng.randint(5 * d, 7 * d), d, rng.choice((15, 20, 25, 30, 40)),
                      rng.choice(_RPM))


_STEPS = Choice(["1", "2", "3", "4"], wrong={
    "1": "Step 1 is right: a bearing sees only the speed of one ring relative to the other.",
    "2": "Step 2 is right: g = d_b cos(alpha)/D_m sets the cage's speed and the races' lines.",
    "4": "Step 4 is right: a defect on a ball strikes the inner and the outer race once per spin."})


@register(
    "adjacency_ball_line", exercise="4.12", title="Find the mistake: the ball line of Table A", stars=2, minutes=20,
    kind="mistake",
    question="An angular-contact ball bearing: Z = {Z} balls of d_b = {d} mm on a pitch diameter D_m = {D} mm, "
             "contact angle {alpha} degrees; the inner ring turns with a shaft at {rpm} rpm, the outer ring is "
             "fixed. A report computes the rolling-element defect line: (1) f_r = |f_inner - f_outer|; (2) "
             "g = d_b cos(alpha)/D_m; (3) BSF = D_m/(2 d_b cos(alpha)) (1 - g^2) f_r; (4) the line is 2 BSF = "
             "{x_printed} Hz. Which step is wrong, and where is the line (Hz)?",
    data=_ball_data(13, 62, 11, 25, 1800),
    params=_ball_params,
    answer=Parts({"step": ("the step", _STEPS), "frequency": ("the frequency", Value("frequency", mistakes=[
        Mistake(lambda e, p: p["x_printed"], "That is the report's value: correct the wrong step first."),
        Mistake(lambda e, p: _ball(p, "spin"), "That is the ball's spin, BSF: a defect on a ball strikes both "
                "races each spin."),
        Mistake(lambda e, p: _ball(p, radians=True), "That reads the contact angle in radians: it is given in "
                "degrees."),
        Mistake(lambda e, p: _ball({**p, "alpha": 0}), "That leaves the contact angle out of g."),
    ]))}),
)
def adjacency_ball_line(Z, D, d, alpha, rpm, x_printed):
    return {"step": "3", "frequency": _ball({"Z": Z, "D": D, "d": d, "alpha": alpha, "rpm": rpm})}


# ----------------------------------------------------------------------------- 4.13
_SPEEDS = {
    "A": "the sun relative to the carrier",
    "B": "the carrier relative to the housing",
    "C": "the sun relative to the housing",
    "D": "the sun relative to the planet",
}
_WHY = {
    "A": "The data say the sun turns on the carrier, so that is where its bearing is.",
    "B": "A bearing's lines depend only on the speed of one of its rings relative to the other, and its rings sit "
         "in the links it physically joins; the turning pair [4, 1, a] of the data only says that sun and carrier "
         "are coaxial.",
    "C": "The carrier carries the load, so its speed sets every bearing line.",
    "D": "The sun's load comes from the planets, so the bearing sees the planets' speed.",
}


@register(
    "adjacency_bearing_placement", exercise="4.13", title="Which speed does the sun's bearing see?", stars=2,
    minutes=10, kind="concept",
    question="gl.catalog.simple_planetary() (sun 1, planet 2, ring 3 held, carrier 4) lists the sun as turning on "
             "the carrier (turning pair [4, 1, a]). In the real gearbox the sun's shaft runs in a ball bearing in "
             "the housing, which is the ring 3. An engineer attaches that bearing to the turning pair (4, 1) of the "
             "data. Which relative speed should set the bearing's lines (option 'A', 'B', 'C' or 'D' of the "
             "exercise), and why (reason 'A', 'B', 'C' or 'D')?",
    answer=Parts({"speed": ("the speed", Choice(_SPEEDS, wrong={
        "A": "That is the speed the data's turning pair gives, not the speed between the rings of the real bearing.",
        "B": "The carrier's own bearings see that speed; the sun's bearing has the sun in its inner ring.",
        "D": "The sun and the planet do not share a bearing: they mesh."})),
        "reason": ("the reason", Choice(_WHY, wrong={
            "A": "A turning pair of the data is a statement about axes (which links are coaxial), and the same "
                 "kinematics can be written with the sun on the housing; it does not place a bearing.",
            "C": "Each bearing has its own two rings; the load sets which ring carries sidebands, not the speed.",
            "D": "A bearing's frequencies come from the relative speed of its rings, not from the load's source."}))}),
)
def adjacency_bearing_placement():
    return {"speed": "C", "reason": "B"}
