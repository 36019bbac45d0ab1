"""How solve time grows with the size of a train: unit-by-unit propagation against the dense null space.

Propagation (chapter 3) visits each kinematic unit once, so its time grows linearly with the
number of gear pairs. The dense route assembles the whole Willis matrix and takes its null
space by a singular value decomposition, whose cost grows with the cube of the size. Both
are timed here on the same serial trains (:func:`gearlib.serial_train`), so a chapter and
the benchmark script (``make bench``) draw the same curves.

The dense baseline is written with numpy alone, from the gear pairs' basic ratios, and does
not use gearlib's solvers:

>>> import gearlib as gl
>>> from gearlib.gains.scaling import dense_nullspace_ratio
>>> m = gl.serial_train(3)                      # three stages of 20:40 teeth
>>> round(dense_nullspace_ratio(m, output=4, input=1, ground=0), 12)
-0.125

Times are wall-clock and depend on the machine; nothing here is a test.
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from ..errors import InputError, MechanismError
from ..mechanism.generate import serial_train
from ..mechanism.data import Mechanism

__all__ = ["ScalingCurve", "dense_nullspace_ratio", "scaling", "plot_scaling"]

METHODS = ("propagation", "dense null space")


def dense_nullspace_ratio(mech: Mechanism, output, input, *, ground) -> float:
    """Speed ratio ``output / input`` from the null space of the dense Willis matrix (floats).

    One row per gear pair ``(a, b)`` on carrier ``c``: ``w_b - e w_a + (e - 1) w_c = 0`` with
    ``e`` the basic ratio; the ground's column is dropped and the null vector is the last
    right singular vector. For a one-dof mechanism only.
    """
    ids = [k for k in mech.link_ids if k != ground]
    col = {k: j for j, k in enumerate(ids)}
    for name, link in (("output", output), ("input", input)):
        if link not in col:
            raise InputError(f"{name} link {link!r} is not a moving link of {mech.name or 'the mechanism'}; "
                             f"choose one of {', '.join(map(str, ids))}")
    A = np.zeros((len(mech.gear_pairs), len(ids)))
    for i, gp in enumerate(mech.gear_pairs):
        try:
            e = float(gp.e)
        except TypeError:
            raise MechanismError(f"gear pair {gp.gears}: the dense baseline needs a numeric ratio, "
                                 f"got {gp.e}; give tooth numbers") from None
        a, b = gp.gears
        for link, coef in ((b, 1.0), (a, -e), (gp.carrier, e - 1.0)):
            if link != ground:
                A[i, col[link]] += coef
    _, s, vt = np.linalg.svd(A, full_matrices=True)
    rank = int(np.sum(s > s.max() * 1e-10)) if s.size else 0
    if len(ids) - rank != 1:
        raise InputError(f"the dense baseline needs one degree of freedom; this mechanism has {len(ids) - rank}")
    v = vt[-1]
    return float(v[col[output]] / v[col[input]])


@dataclass(frozen=True)
class ScalingCurve:
    """Best-of-``repeat`` wall times of one method on serial trains of the given sizes."""

    method: str
    sizes: tuple[int, ...]
    seconds: tuple[float, ...]

    @property
    def per_pair(self) -> tuple[float, ...]:
        """Seconds per gear pair: flat for a linear method."""
        return tuple(t / n for n, t in zip(self.sizes, self.seconds))

    def exponent(self) -> float:
        """Slope of log(time) against log(size), fitted over the upper half of the sizes.

        About 1 for a linear method and about 3 for a dense factorisation once the sizes are
        large enough for the arithmetic to dominate the overheads.
        """
        k = max(2, len(self.sizes) // 2 + 1)
        x, y = np.log(self.sizes[-k:]), np.log(self.seconds[-k:])
        return float(np.polyfit(x, y, 1)[0])

    def extrapolate(self, n: int) -> float:
        """Time for size *n*, from the largest measured size and :meth:`exponent`."""
        return self.seconds[-1] * (n / self.sizes[-1]) ** self.exponent()


def _uncached(mech: Mechanism) -> Mechanism:
    """A copy of *mech* with nothing computed cached on it or on its gear pairs (propagation
    caches its plan on the mechanism), without validating it again as building a new one
    would: repeated timings then cost what one run costs, not a rebuild of the train."""
    keep_of: dict = {}  # class -> the attributes a fresh object has

    def strip(obj):
        cls = type(obj)
        keep = keep_of.get(cls)
        if keep is None:  # the fields, and _groups, which validation sets
            keep = keep_of[cls] = tuple(f.name for f in dataclasses.fields(cls)) + ("_groups",)
        new = object.__new__(cls)
        old = obj.__dict__
        new.__dict__.update({k: old[k] for k in keep if k in old})
        return new

    new = strip(mech)
    object.__setattr__(new, "gear_pairs", tuple(strip(gp) for gp in mech.gear_pairs))
    return new


def _time_one(method: str, n: int, repeat: int) -> float:
    best = math.inf
    train = serial_train(n)
    for _ in range(repeat):
        mech = _uncached(train)  # as if freshly built: nothing of an earlier run is reused
        if method == "propagation":
            from .relation import unit_ratio

            start = time.perf_counter()
            r = unit_ratio(mech, output=n + 1, input=1, ground=0)
            best = min(best, time.perf_counter() - start)
            expected = Fraction(-1, 2) ** n
        else:
            start = time.perf_counter()
            r = dense_nullspace_ratio(mech, output=n + 1, input=1, ground=0)
            best = min(best, time.perf_counter() - start)
            expected = None
        if expected is not None and r != expected:
            raise AssertionError(f"propagation gave {r} for a serial train of {n} pairs")  # pragma: no cover
    return best


def scaling(method: str, sizes, *, repeat: int = 3) -> ScalingCurve:
    """Time *method* (``"propagation"`` or ``"dense null space"``) on ``serial_train(n)`` for each size.

    Each time is the best of *repeat* runs, each on a freshly built train and excluding the
    building. Propagation's exact result is checked against ``(-1/2)**n`` on every run.
    """
    if method not in METHODS:
        raise InputError(f"unknown method {method!r}; choose one of {', '.join(map(repr, METHODS))}")
    sizes = tuple(int(n) for n in sizes)
    if not sizes or min(sizes) < 1:
        raise InputError(f"sizes must be positive numbers of gear pairs, got {sizes}")
    return ScalingCurve(method, sizes, tuple(_time_one(method, n, repeat) for n in sizes))


def plot_scaling(*curves: ScalingCurve, ax=None):
    """Log-log plot of time against number of gear pairs, one line per curve; returns the axes."""
    from ..mechanism.plot import _axes

    ax = _axes(ax, figsize=(6.0, 4.0))
    for curve, marker in zip(curves, "os^v"):
        ax.loglog(curve.sizes, curve.seconds, marker=marker,
                  label=f"{curve.method} (slope {curve.exponent():.1f})")
    ax.set_xlabel("gear pairs in the serial train")
    ax.set_ylabel("time to the output speed [s]")
    ax.legend(frameon=False)
    ax.grid(True, which="major", alpha=0.3)
    return ax
