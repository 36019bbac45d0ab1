"""Random gear trains whose pitch radii fit their topology, for property tests and exercises.

:func:`gearlib.random_mechanism` makes topologically valid trains, but its tooth numbers
ignore centre distances, which Davies' geometry needs. :func:`random_train` builds trains
from radii instead: compound trains on fixed axes, simple and double-planet epicyclic trains
(sun and ring radii chosen so that the planet axis closes, ``r_ring = r_sun + 2 r_planet``),
Humpage-type and differential-type bevel trains (``|r1 - r5| < 2 r2`` so that the planet's two
meshes lie on one pitch cone), and fixed-axis bevel pairs. It returns the mechanism and a
ground, an input and an output link, all coaxial, for a one-degree-of-freedom train.

>>> import numpy as np, gearlib as gl
>>> case = gl.davies.random_train(np.random.default_rng(3), kind="planetary")
>>> case.mechanism.gear_pairs[0].kind, int(gl.dof(case.mechanism, case.ground))
('external', 1)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..mechanism.data import Mechanism

__all__ = ["TrainCase", "random_train", "KINDS"]

KINDS = ("compound", "planetary", "double_planet", "humpage", "differential", "bevel_pair")


@dataclass(frozen=True)
class TrainCase:
    """A random train with its ports: ``mechanism``, ``ground``, ``input``, ``output``."""

    mechanism: Mechanism
    ground: object
    input: object
    output: object


def _pair(gears, ta, tb, kind="external", ratio=None):
    out = {"gears": list(gears), "teeth": [int(ta), int(tb)], "radii": [ta / 2, tb / 2]}
    if kind != "external":
        out["type"] = kind
    if ratio is not None:
        out["ratio"] = ratio
    return out


def _ports(rng, members):
    order = [members[i] for i in rng.permutation(len(members))]
    return order[0], order[1], order[2]


def random_train(rng=None, kind: str | None = None) -> TrainCase:
    """A random one-degree-of-freedom train of the given *kind* (default: a random kind)."""
    rng = np.random.default_rng(rng)
    kind = kind or KINDS[int(rng.integers(len(KINDS)))]
    t = lambda lo, hi: int(rng.integers(lo, hi + 1))  # noqa: E731
    if kind == "compound":
        stages = t(1, 3)
        links = {0: "frame"} | {i: f"shaft {i}" for i in range(1, stages + 2)}
        turning = [[0, i, f"a{i}"] for i in range(1, stages + 2)]
        pairs = []
        for i in range(1, stages + 1):
            if rng.random() < 0.25:
                small, big = t(12, 30), t(45, 90)
                pairs.append(_pair((i, i + 1), small, big, "internal") if rng.random() < 0.5
                             else _pair((i, i + 1), big, small, "internal"))
            else:
                pairs.append(_pair((i, i + 1), t(12, 60), t(12, 60)))
        data = {"links": links, "turning_pairs": turning, "gear_pairs": pairs}
        ends = [1, stages + 1]
        if rng.random() < 0.5:
            ends = ends[::-1]
        return TrainCase(Mechanism.from_dict(data | {"name": "random compound"}), 0, ends[0], ends[1])
    if kind == "planetary":
        zs, zp = t(12, 40), t(10, 30)
        zr = zs + 2 * zp
        data = {"name": "random planetary", "links": {1: "sun", 2: "planet", 3: "ring", 4: "carrier"},
                "turning_pairs": [[1, 3, "a"], [1, 4, "a"], [4, 2, "b"]],
                "gear_pairs": [_pair((1, 2), zs, zp), _pair((2, 3), zp, zr, "internal")]}
        return TrainCase(Mechanism.from_dict(data), *_ports(rng, [1, 3, 4]))
    if kind == "double_planet":
        # central gears 1 and 2 (each a sun or an annulus), compound planet 3 (gears a, b), carrier 5
        za, zb = t(10, 30), t(10, 30)
        offset = t(8, 30)  # planet axis radius, in half-teeth
        first_ring, second_ring = rng.random() < 0.5, rng.random() < 0.5
        z1 = za + 2 * offset if first_ring else 2 * offset - za
        z2 = zb + 2 * offset if second_ring else 2 * offset - zb
        if z1 < 8 or z2 < 8 or z1 == z2 and first_ring == second_ring and za == zb:
            return random_train(rng, kind)
        pairs = [_pair((1, 3), z1, za, "internal" if first_ring else "external"),
                 _pair((2, 3), z2, zb, "internal" if second_ring else "external")]
        data = {"name": "random double planet", "links": {1: "central 1", 2: "central 2", 3: "planet", 5: "carrier"},
                "turning_pairs": [[1, 5, "a"], [1, 2, "a"], [3, 5, "b"]], "gear_pairs": pairs}
        m = Mechanism.from_dict(data)
        from ..mechanism.kinematics import speeds

        sol = speeds(m, 1, {5: 1})
        if sol[2] == 0 or sol[2] == 1:
            return random_train(rng, kind)
        return TrainCase(m, *_ports(rng, [1, 2, 5]))
    if kind in ("humpage", "differential"):
        r2 = t(15, 40)
        r1 = t(8, 50)
        lo, hi = max(6, r1 - 2 * r2 + 2), r1 + 2 * r2 - 2
        r5 = t(lo, hi)
        if kind == "differential":
            data = {"name": "random bevel differential", "links": {1: "side gear 1", 2: "planet", 4: "side gear 2",
                                                                  6: "carrier"},
                    "turning_pairs": [[6, 1, "z"], [6, 4, "z"], [2, 6, "p"]],
                    "gear_pairs": [_pair((1, 2), 2 * r1, 2 * r2, "bevel", f"{r1}/{r2}"),
                                   _pair((4, 2), 2 * r5, 2 * r2, "bevel", f"-{r5}/{r2}")]}
            return TrainCase(Mechanism.from_dict(data), *_ports(rng, [1, 4, 6]))
        r3, r4 = t(8, 40), t(8, 40)
        if r2 * r4 == r3 * r5:
            r4 += 1
        data = {"name": "random Humpage", "links": {1: "input", 2: "planet", 4: "output", 5: "frame", 6: "carrier"},
                "turning_pairs": [[5, 1, "z"], [5, 4, "z"], [4, 6, "z"], [2, 6, "p"]],
                "gear_pairs": [_pair((1, 2), 2 * r1, 2 * r2, "bevel", f"{r1}/{r2}"),
                               _pair((5, 2), 2 * r5, 2 * r2, "bevel", f"-{r5}/{r2}"),
                               _pair((2, 4), 2 * r3, 2 * r4, "bevel", f"-{r3}/{r4}")]}
        ports = [1, 4] if rng.random() < 0.5 else [4, 1]
        return TrainCase(Mechanism.from_dict(data), 5, ports[0], ports[1])
    if kind == "bevel_pair":
        za, zb = t(12, 60), t(12, 60)
        sign = "-" if rng.random() < 0.5 else ""
        data = {"name": "random bevel pair", "links": {0: "frame", 1: "pinion", 2: "gear"},
                "turning_pairs": [[0, 1, "a"], [0, 2, "b"]],
                "gear_pairs": [_pair((1, 2), za, zb, "bevel", f"{sign}{za}/{zb}")]}
        ends = [1, 2] if rng.random() < 0.5 else [2, 1]
        return TrainCase(Mechanism.from_dict(data), 0, ends[0], ends[1])
    raise InputError(f"kind must be one of {', '.join(KINDS)}, got {kind!r}")
