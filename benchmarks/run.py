"""Speed benchmarks for gearlib, each against a baseline measured in the same run.

    python benchmarks/run.py            # every case
    python benchmarks/run.py numeric    # cases whose name contains "numeric"

Prints one row per case: gearlib's time, the baseline's time, their ratio and the target.
Timings are the best of several repeats (wall clock, this machine). Nothing here is a
pass/fail test: the table is for people; keep timing out of the test suite.
"""

from __future__ import annotations

import subprocess
import sys
import time
from dataclasses import dataclass

import numpy as np

import gearlib as gl

CASES = []


@dataclass
class Row:
    case: str
    ours: float  # seconds
    base: float | None  # seconds (None: no baseline; inf: baseline timed out)
    baseline: str
    target: str
    ok: bool

    def line(self) -> str:
        def fmt(t):
            if t is None:
                return "-"
            if t == float("inf"):
                return "timeout"
            return f"{t * 1e3:10.2f} ms" if t < 10 else f"{t:10.1f} s "

        if self.base is None:
            ratio = "-"
        elif self.base == float("inf"):
            ratio = "> limit"
        else:
            ratio = f"{self.base / self.ours:8.1f}x"
        return (f"{self.case:46s} {fmt(self.ours):>13s} {fmt(self.base):>13s}  {ratio:>9s}  "
                f"{'ok  ' if self.ok else 'MISS'} {self.target}; baseline: {self.baseline}")


def case(fn):
    CASES.append(fn)
    return fn


def best(fn, repeat=5, min_time=0.2):
    """Best wall time of ``fn()`` over ``repeat`` rounds (more rounds for very fast calls)."""
    times = []
    start = time.perf_counter()
    while len(times) < repeat or (time.perf_counter() - start < min_time and len(times) < 200):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return min(times)


def timed_subprocess(code: str, limit: float) -> float:
    """Run python code in a fresh interpreter; its own measured time, or inf after *limit* s."""
    try:
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=limit,
                             check=True)
    except subprocess.TimeoutExpired:
        return float("inf")
    return float(out.stdout.strip().splitlines()[-1])


# ----------------------------------------------------------------------------- numeric speeds
LINSOLVE = """
import time, sympy, gearlib as gl
m = gl.random_mechanism({n}, dof=1, rng={seed})
w = {{k: sympy.Symbol(f"w{{k}}") for k in m.link_ids}}
eqs = [w[gp.gears[1]] - gp.e * w[gp.gears[0]] + (gp.e - 1) * w[gp.carrier] for gp in m.gear_pairs]
eqs += [w[0], w[1] - 1]
t = time.perf_counter()
sol = sympy.linsolve(eqs, list(w.values()))
print(time.perf_counter() - t)
"""


@case
def numeric_speeds():
    rows = []
    for n in (10, 100, 1000):
        m = gl.random_mechanism(n, dof=1, rng=n)
        ours = best(lambda m=m: gl.speeds(m, ground=0, inputs={1: 1}, method="numeric"))
        # floor: the bare LAPACK call on the already assembled matrix
        from gearlib.kinematics import Constraints, _numeric_matrix

        A, b = _numeric_matrix(m, Constraints.build(m, 0, {1: 1}))
        floor = best(lambda A=A, b=b: np.linalg.solve(A, b))
        rows.append(Row(f"numeric speeds, {n} links", ours, floor, "numpy.linalg.solve (LAPACK)",
                        "within 3x of LAPACK", ours <= 3 * floor))
        limit = 120.0
        lin = timed_subprocess(LINSOLVE.format(n=n, seed=n), limit)
        ok = lin == float("inf") and limit / ours >= 100 or lin / ours >= 100
        rows.append(Row(f"numeric speeds, {n} links", ours, lin, f"sympy.linsolve (limit {limit:.0f} s)",
                        ">= 100x faster than linsolve", ok))
    return rows


# ----------------------------------------------------------------------------- start-up
@case
def import_time():
    code_ours = "import time; t = time.perf_counter(); import gearlib; print(time.perf_counter() - t)"
    code_base = "import time; t = time.perf_counter(); import numpy; print(time.perf_counter() - t)"
    ours = min(timed_subprocess(code_ours, 60) for _ in range(3))
    base = min(timed_subprocess(code_base, 60) for _ in range(3))
    return [Row("import gearlib", ours, base, "import numpy alone", "under 1 s", ours < 1.0)]


# ----------------------------------------------------------------------------- widgets
@case
def widget_callbacks():
    rows = []
    ex = gl.widgets.speed_explorer(gl.catalog.simple_planetary(), ground=3, inputs={1: 1})
    ex.update()
    k = ex.keys()[0]
    values = iter(range(10, 10**6))
    ours = best(lambda: ex.update(**{k: 10 + next(values) % 60}), repeat=10)
    rows.append(Row("widget: speed explorer update", ours, None, "-", "under 50 ms", ours < 0.05))
    return rows


def main(argv):
    pattern = argv[1] if len(argv) > 1 else ""
    print(f"{'case':46s} {'gearlib':>13s} {'baseline':>13s}  {'ratio':>9s}  target")
    misses = 0
    for fn in CASES:
        if pattern not in fn.__name__:
            continue
        for row in fn():
            print(row.line(), flush=True)
            misses += not row.ok
    print(f"\n{misses} target(s) missed")


if __name__ == "__main__":
    main(sys.argv)
