"""Random valid geared mechanisms, for property tests, benchmarks and exercises.

A mechanism is grown one link at a time, the way one would build it: each new link is
pivoted on an existing link (a new turning pair, on a new axis or on an axis that link
already has) and, unless it is a free carrier, meshes with a gear that shares a carrier
with it on a different axis. Each such step adds one link and one independent Willis
equation, so the degrees of freedom stay where they were; a step that adds a link
without a gear pair adds one degree of freedom. The turning pairs form a tree, so every
gear pair has exactly one carrier.

>>> import numpy as np, gearlib as gl
>>> m = gl.random_mechanism(12, dof=1, rng=np.random.default_rng(1))
>>> len(m.links), len(m.gear_pairs), int(gl.dof(m))
(12, 10, 1)
"""

from __future__ import annotations

import numpy as np

from .._common.parse import MAX_TEETH, iterable, parse_count, parse_probability, parse_teeth, shown
from ..errors import DataFormatError, InputError
from .data import Mechanism

MAX_LINKS = 200_000
"""The largest mechanism the generators build (a 100,000-link train takes seconds to analyse)."""

__all__ = ["random_mechanism", "serial_train"]


def random_mechanism(n_links: int, dof: int = 1, *, rng=None, bevel: float = 0.0, internal: float = 0.3,
                     max_teeth: int = 90, name: str | None = None) -> Mechanism:
    """A random valid mechanism with *n_links* links and *dof* degrees of freedom (link 0 held).

    Parameters
    ----------
    n_links : int, at least ``dof + 1``.
    dof : int, degrees of freedom with link 0 as the ground.
    rng : numpy Generator (or seed); the only source of randomness.
    bevel : probability that a gear pair is a bevel pair with complex (Penaud) weights.
    internal : probability that a spur pair is internal.
    """
    dof = parse_count(dof, "random_mechanism: dof", 1, MAX_LINKS - 1)
    n_links = parse_count(n_links, "random_mechanism: n_links", dof + 1, MAX_LINKS)
    bevel, internal = parse_probability(bevel, "random_mechanism: bevel"), \
        parse_probability(internal, "random_mechanism: internal")
    max_teeth = parse_count(max_teeth, "random_mechanism: max_teeth", 12, MAX_TEETH)
    if name is not None and not isinstance(name, str):
        raise DataFormatError(f"random_mechanism: name must be text, got {shown(name)}")
    try:
        rng = np.random.default_rng(rng)
    except (TypeError, ValueError):
        raise DataFormatError(f"random_mechanism: rng must be a seed (a whole number), a numpy Generator or None; "
                              f"got {shown(rng)}") from None
    axes_of: dict[int, list[str]] = {0: ["a"]}  # axis labels on each link
    group: dict[tuple[str, int], int] = {("a", 0): 0}  # (label, link) -> coaxial group id
    members: dict[int, list[int]] = {0: [0]}
    turning, gears = [], []
    labels = iter(f"x{k}" for k in range(1, 10 * n_links + 10))
    free_left = dof - 1  # freedoms still to add as gearless links (link 1 is the first)

    def sample_option(parent, label):
        """A gear g and carrier c such that a new link pivoted on `parent` about `label` can mesh g."""
        gid = group.get((label, parent))
        carriers = members[gid] if gid is not None else [parent]
        for _ in range(12):
            c = carriers[int(rng.integers(len(carriers)))]
            others = [lab for lab in axes_of[c] if lab != label]
            if not others:
                continue
            lab = others[int(rng.integers(len(others)))]
            gs = [g for g in members[group[(lab, c)]] if g != c]
            if gs:
                return gs[int(rng.integers(len(gs)))], c
        return None

    def attach(link, parent, label):
        key = (label, parent)
        if key not in group:
            group[key] = len(members)
            members[group[key]] = [parent]
            axes_of[parent].append(label)
        gid = group[key]
        members[gid].append(link)
        group[(label, link)] = gid
        axes_of[link] = [label]
        turning.append([parent, link, label])

    attach(1, 0, "a")
    for link in range(2, n_links):
        remaining = n_links - link  # links still to add, this one included
        free = free_left > 0 and (rng.random() < 0.3 or remaining <= free_left)
        choice = None
        for _ in range(40):
            parent = int(rng.integers(link))
            own = axes_of[parent]
            label = next(labels) if (rng.random() < 0.5 or not own) else own[int(rng.integers(len(own)))]
            option = None if free else sample_option(parent, label)
            if free or option is not None:
                choice = (parent, label, option)
                break
        if choice is None:  # fall back to a free carrier-like link on the ground
            if free_left <= 0:
                raise InputError("random_mechanism: no place to add a gear; try another seed")
            choice, free = (0, next(labels), None), True
        parent, label, option = choice
        attach(link, parent, label)
        if free:
            free_left -= 1
            continue
        g, c = option
        na, nb = (int(x) for x in rng.integers(12, max_teeth + 1, size=2))
        pair = {"gears": [g, link], "teeth": [na, nb], "carrier": c}
        if rng.random() < bevel:
            th = rng.integers(-2, 3, size=2)
            pair.update(type="bevel", angles=[f"{int(th[0])}*pi/4", f"{int(th[1])}*pi/4"])
        elif rng.random() < internal:
            pair["type"] = "internal"
        gears.append(pair)
    if free_left > 0:
        raise InputError(f"random_mechanism: could not reach dof={dof} with {n_links} links; try another seed")
    data = {
        "name": name or f"random {n_links}-link {dof}-dof mechanism",
        "links": list(range(n_links)),
        "turning_pairs": turning,
        "gear_pairs": gears,
        "ground": 0,
    }
    return Mechanism.from_dict(data)


def serial_train(n_pairs: int, *, teeth=(20, 40), name: str | None = None) -> Mechanism:
    """A compound train of *n_pairs* gear pairs in series on one frame (link 0).

    Link ``k`` meshes with link ``k + 1``; every shaft turns on the frame about its own axis.
    The ratio from link 1 to link ``n_pairs + 1`` is ``(-teeth[0]/teeth[1]) ** n_pairs``.
    """
    n_pairs = parse_count(n_pairs, "serial_train: n_pairs", 1, MAX_LINKS - 2)
    if isinstance(teeth, (str, bytes)) or not iterable(teeth) or len(list(teeth)) != 2:
        raise DataFormatError(f"serial_train: teeth must be two tooth numbers (driver, driven), got {shown(teeth)}")
    a, b = (parse_teeth(t, "serial_train: teeth") for t in teeth)
    turning = [[0, k, f"s{k}"] for k in range(1, n_pairs + 2)]
    gears = [{"gears": [k, k + 1], "teeth": [a, b], "carrier": 0} for k in range(1, n_pairs + 1)]
    return Mechanism.from_dict({
        "name": name or f"serial train of {n_pairs} gear pairs",
        "links": list(range(n_pairs + 2)),
        "turning_pairs": turning,
        "gear_pairs": gears,
        "ground": 0,
        "inputs": [1],
    })
