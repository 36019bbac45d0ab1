"""Tasks: what a linkage is asked to do, as data.

A :class:`Task` gives the *motion inputs* as functions of the time ``t`` (a joint's angle or
displacement from the reference pose, or the position of a load port's point), the *actions*
known at the ports (the payload, the input torque), and the sampling of ``[start, stop]``:
``steps`` intervals, integrated by the ``rule`` named (``trapezoid``, ``simpson``, ``left``,
``right``, or ``gauss``: ``steps`` panels of four Gauss-Legendre nodes, which never fall on a
panel's ends). Expressions are text (``"0.5 + 0.4*t"``, ``"0.2*cos(2*pi*t)"``); their
derivatives give the speeds exactly. Samples read from a file (:meth:`~gearlib.linkages.Task.from_samples`)
get their speeds by finite differences.

>>> from gearlib.linkages.tasks import Task
>>> task = Task.from_dict("lift", {"time": [0, 1], "steps": 4, "motion": {"M": [0.1, 0.2, "0.5 + 0.4*t"]},
...                                "actions": {"M": 10000}})
>>> task.times().tolist()
[0.0, 0.25, 0.5, 0.75, 1.0]
>>> task.inputs_at(0.5)["M"]
([0.1, 0.2, 0.7], [0.0, 0.0, 0.4])
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
import sympy

from .._common.parse import parse_expr
from ..errors import DataFormatError, InputError

__all__ = ["Task", "RULES", "expression", "weights"]

RULES = ("trapezoid", "simpson", "left", "right", "gauss")
T = sympy.Symbol("t")
_GAUSS = np.polynomial.legendre.leggauss(4)
_TOKENS = re.compile(r"\d+\.?\d*(?:[eE][+-]?\d+)?|\*\*|[A-Za-z_]\w*|\S")


def _small_powers(text: str) -> bool:
    """No stacked powers (``9^9^9``, ``a^(b^c)``) and no exponent above 64: sympy would compute
    them for ever."""
    toks = ["^" if t == "**" else t for t in _TOKENS.findall(text)]
    for i, tok in enumerate(toks):
        if tok != "^":
            continue
        j = i + 1 + (i + 1 < len(toks) and toks[i + 1] in "+-")
        if j >= len(toks):
            continue
        if toks[j] == "(":
            depth, k = 0, j
            while k < len(toks):
                depth += {"(": 1, ")": -1}.get(toks[k], 0)
                if toks[k] == "^":
                    return False
                if depth == 0:
                    break
                k += 1
            j = k
        elif re.fullmatch(r"[\d.eE+-]+", toks[j]) and float(toks[j]) > 64:
            return False
        if j + 1 < len(toks) and toks[j + 1] == "^":
            return False
    return True


def expression(value, params: Mapping, where: str, *, time: bool = False) -> sympy.Expr:
    """A number or an expression read safely, with the ``parameters`` of the file put in; with
    ``time`` it may use ``t``."""
    if isinstance(value, str):
        if len(value) > 300:
            raise DataFormatError(f"{where}: the expression is too long (at most 300 characters)")
        if not _small_powers(value):
            raise DataFormatError(f"{where}: {value!r}: powers must be small and not stacked")
    expr = parse_expr(value, where)
    expr = expr.xreplace({sympy.Symbol(k): sympy.sympify(v) for k, v in params.items()})
    allowed = {T} if time else set()
    extra = sorted(str(s) for s in expr.free_symbols - allowed)
    if extra:
        known = ", ".join(sorted(params)) or "none"
        raise DataFormatError(f"{where}: unknown name {extra[0]!r} in {value!r}; parameters are: {known}"
                              + ("; the time is t" if time else ""))
    if not time:
        try:
            x = complex(expr.evalf(20))
        except (TypeError, ValueError):
            raise DataFormatError(f"{where}: {value!r} is not a number") from None
        if x.imag != 0 or not math.isfinite(x.real):
            raise DataFormatError(f"{where}: {value!r} is not a finite real number")
    return expr


def weights(times: np.ndarray, rule: str) -> np.ndarray:
    """Integration weights for equally or unequally spaced samples at *times* by *rule*
    (``trapezoid``, ``simpson`` (equal steps), ``left`` or ``right``)."""
    n = len(times) - 1
    if n < 1:
        return np.zeros(len(times))
    h = np.diff(times)
    w = np.zeros(len(times))
    if rule == "trapezoid":
        w[:-1] += h / 2
        w[1:] += h / 2
    elif rule == "left":
        w[:-1] += h
    elif rule == "right":
        w[1:] += h
    elif rule == "simpson":
        if n % 2:
            raise InputError(f"Simpson's rule needs an even number of steps, got {n}")
        step = h[0]
        w[0] = w[-1] = step / 3
        w[1:-1:2] = 4 * step / 3
        w[2:-1:2] = 2 * step / 3
    else:
        raise InputError(f"rule must be one of {', '.join(RULES)}, got {rule!r}")
    return w


@dataclass(frozen=True)
class Task:
    """A task (see the module documentation): ``motion`` maps a joint or a load port to its
    position(s) as expressions in ``t`` (or, with ``samples``, to arrays), ``actions`` maps a
    port to its known action (an expression in ``t``)."""

    name: str
    start: float
    stop: float
    steps: int
    motion: tuple
    actions: tuple
    rule: str = "trapezoid"
    description: str | None = None
    roles: tuple = ()
    samples: tuple | None = field(default=None, compare=False, repr=False)

    def __post_init__(self):
        where = f"task {self.name}"
        if not (math.isfinite(self.start) and math.isfinite(self.stop)) or self.stop <= self.start:
            raise DataFormatError(f"{where}: the time runs from start to a later stop, got [{self.start}, {self.stop}]")
        if isinstance(self.steps, bool) or not isinstance(self.steps, int) or not 1 <= self.steps <= 100_000:
            raise DataFormatError(f"{where}: steps must be a whole number from 1 to 100000, got {self.steps!r}")
        if self.rule not in RULES:
            raise DataFormatError(f"{where}: rule must be one of {', '.join(RULES)}, got {self.rule!r}")
        if self.rule == "simpson" and self.steps % 2:
            raise DataFormatError(f"{where}: Simpson's rule needs an even number of steps, got {self.steps}")
        if not self.motion:
            raise DataFormatError(f"{where}: give the motion inputs (`motion`: a joint's angle or a point's position)")
        if not self.actions:
            raise DataFormatError(f"{where}: give the known actions (`actions`: the load or the input torque)")

    # ------------------------------------------------------------------ building
    @classmethod
    def from_dict(cls, name: str, data: Mapping, params: Mapping | None = None) -> Task:
        params = dict(params or {})
        where = f"task {name}"
        if not isinstance(data, Mapping):
            raise DataFormatError(f"{where}: a task is a mapping with time, steps, motion and actions")
        unknown = set(data) - {"time", "steps", "motion", "actions", "rule", "description", "roles"}
        if unknown:
            raise DataFormatError(f"{where}: unknown field {sorted(map(str, unknown))[0]!r}; a task has time, steps, "
                                  "rule, motion, actions, roles and description")
        roles = data.get("roles") or {}
        if not isinstance(roles, Mapping) or any(v not in ("input", "output") for v in roles.values()):
            raise DataFormatError(f"{where}: roles maps ports to 'input' or 'output', got {roles!r}")
        time = data.get("time", [0, 1])
        if not isinstance(time, (list, tuple)) or len(time) != 2:
            raise DataFormatError(f"{where}: time is [start, stop], got {time!r}")
        start, stop = (float(expression(v, params, f"{where}: time")) for v in time)
        motion = []
        for key, value in _mapping(data.get("motion"), f"{where}: motion").items():
            values = value if isinstance(value, (list, tuple)) else [value]
            motion.append((str(key), tuple(expression(v, params, f"{where}: motion {key}", time=True)
                                           for v in values)))
        actions = tuple((str(k), expression(v, params, f"{where}: actions {k}", time=True))
                        for k, v in _mapping(data.get("actions"), f"{where}: actions").items())
        steps = data.get("steps", 200)
        return cls(str(name), start, stop, steps, tuple(motion), actions, str(data.get("rule", "trapezoid")),
                   data.get("description"), tuple((str(k), str(v)) for k, v in roles.items()))

    @classmethod
    def from_samples(cls, name: str, times, motion: Mapping, actions: Mapping, *, rule: str = "trapezoid",
                     roles: Mapping | None = None) -> Task:
        """A task from sampled positions (a trajectory file): ``motion`` maps a joint or load
        port to an array of positions (one row per time, one column per coordinate); speeds by
        second-order finite differences."""
        t = np.asarray(times, dtype=float)
        if t.ndim != 1 or len(t) < 3 or not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0):
            raise DataFormatError(f"trajectory {name}: the times must be at least three increasing finite numbers")
        samples = {}
        for key, value in motion.items():
            arr = np.asarray(value, dtype=float)
            arr = arr.reshape(len(t), -1) if arr.size % len(t) == 0 else None
            if arr is None or not np.all(np.isfinite(arr)):
                raise DataFormatError(f"trajectory {name}: {key} needs one finite value (or point) per time")
            samples[str(key)] = (arr, np.gradient(arr, t, axis=0, edge_order=2))
        acts = tuple((str(k), expression(v, {}, f"trajectory {name}: actions {k}", time=True))
                     for k, v in actions.items())
        return cls(name, float(t[0]), float(t[-1]), len(t) - 1, tuple((k, ()) for k in samples), acts, rule,
                   roles=tuple((roles or {}).items()), samples=(t, samples))

    # ------------------------------------------------------------------ sampling
    def times(self) -> np.ndarray:
        """The sample times."""
        if self.samples is not None:
            return self.samples[0]
        if self.rule == "gauss":
            edges = np.linspace(self.start, self.stop, self.steps + 1)
            x, _ = _GAUSS
            mid, half = (edges[1:] + edges[:-1]) / 2, (edges[1:] - edges[:-1]) / 2
            return (mid[:, None] + half[:, None] * x[None, :]).ravel()
        return np.linspace(self.start, self.stop, self.steps + 1)

    def weights(self) -> np.ndarray:
        """Integration weights of the sample times (energy = weights @ power)."""
        if self.rule == "gauss" and self.samples is None:
            edges = np.linspace(self.start, self.stop, self.steps + 1)
            _, w = _GAUSS
            half = (edges[1:] - edges[:-1]) / 2
            return (half[:, None] * w[None, :]).ravel()
        return weights(self.times(), "trapezoid" if self.rule == "gauss" else self.rule)

    def _functions(self):
        cached = self.__dict__.get("_fns")
        if cached is None:
            cached = {k: (sympy.lambdify(T, list(v), "math"), sympy.lambdify(T, [sympy.diff(e, T) for e in v], "math"))
                      for k, v in self.motion}
            cached["__actions__"] = {k: sympy.lambdify(T, v, "math") for k, v in self.actions}
            object.__setattr__(self, "_fns", cached)
        return cached

    def inputs_at(self, t: float, index: int | None = None) -> dict:
        """``{name: (positions, speeds)}`` at time *t* (the *index*-th sample for sampled tasks)."""
        if self.samples is not None:
            times, samples = self.samples
            k = int(index) if index is not None else int(np.argmin(np.abs(times - t)))
            return {name: (pos[k].tolist(), vel[k].tolist()) for name, (pos, vel) in samples.items()}
        fns = self._functions()
        out = {}
        for name, _ in self.motion:
            pos, vel = fns[name]
            out[name] = ([float(x) for x in pos(t)], [float(x) for x in vel(t)])
        return out

    def actions_at(self, t: float) -> dict:
        """``{port: value}`` of the known actions at time *t*."""
        return {name: float(f(t)) for name, f in self._functions()["__actions__"].items()}

    def replace(self, **changes) -> Task:
        import dataclasses

        return dataclasses.replace(self, **changes)

    def to_data(self) -> dict:
        if self.samples is not None:
            raise InputError(f"task {self.name} comes from samples; save the trajectory file instead")
        out: dict = {"time": [self.start, self.stop], "steps": self.steps}
        if self.rule != "trapezoid":
            out["rule"] = self.rule
        out["motion"] = {k: [_data(e) for e in v] if len(v) > 1 else _data(v[0]) for k, v in self.motion}
        out["actions"] = {k: _data(v) for k, v in self.actions}
        if self.roles:
            out["roles"] = dict(self.roles)
        if self.description:
            out["description"] = self.description
        return out


def _data(expr):
    if expr.is_number:
        value = float(expr)
        return int(value) if value.is_integer() and abs(value) < 2**53 else value
    return str(expr)


def _mapping(value, where) -> dict:
    if not isinstance(value, Mapping) or not value:
        raise DataFormatError(f"{where}: expected a mapping such as {{A: t}}, got {value!r}")
    return dict(value)
