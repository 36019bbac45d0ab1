"""A linkage doing a task: every instant solved in turn, energies, efficiency, losses.

:func:`~gearlib.linkages.run` follows a :class:`~gearlib.linkages.Task` sample by sample: the pose from the
last pose (Newton), the motions, the actions by the thesis' Algorithm 2 continued from the
last instant's signs, the power of every port and friction column. The energies are the
integrals of those powers by the task's rule; the efficiency is the energy the outputs take
out over the energy the inputs put in, ``eta = E_out / E_in`` (Laus 2011, section 4.3.4.2);
the losses are the friction columns' energies, and :meth:`~gearlib.linkages.TaskResult.loss_shares` groups them
by coupling, joint or kind. :meth:`~gearlib.linkages.TaskResult.reversals` lists the instants at which a motion
changes sign (a friction force or torque turns round there), refined by Brent's method.

>>> import gearlib as gl
>>> res = gl.linkages.run(gl.linkages.load("laus_slider_crank"), "crank_drives")
>>> round(res.efficiency, 7)                  # eq. (120) with a1 = 1, a2 = 3, mu = 0.1
0.9779364
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import GearlibError, InputError
from .couplings import network as make_network
from .pose import Pose, extrapolate, solve_pose
from .solve import RAMP, instant, primaries, solve_motions
from .tasks import Task

__all__ = ["TaskResult", "Reversal", "run", "jump", "cycle"]


@dataclass(frozen=True)
class Reversal:
    """Motion variables that change sign at ``time`` (between two samples, refined)."""

    time: float
    variables: tuple


@dataclass(frozen=True)
class TaskResult:
    """The result of :func:`~gearlib.linkages.run` (see the module documentation)."""

    linkage: object
    task: Task
    times: np.ndarray = field(repr=False)
    weights: np.ndarray = field(repr=False)
    powers: np.ndarray = field(repr=False)      # samples x action columns
    actions: np.ndarray = field(repr=False)     # samples x action columns
    motions: np.ndarray = field(repr=False)     # samples x motion columns
    roles: dict = field(repr=False)
    stats: dict = field(default_factory=dict)

    @property
    def network(self):
        return make_network(self.linkage)

    def _energy(self, cols) -> float:
        return float(self.weights @ self.powers[:, cols].sum(axis=1)) if cols else 0.0

    def port_energy(self, port) -> float:
        """Energy that entered at *port* (negative when it left)."""
        return self._energy([k for k, a in enumerate(self.network.action_cols) if a.port == port])

    @property
    def energy_in(self) -> float:
        """Energy the input ports put in."""
        return sum(self.port_energy(p) for p, r in self.roles.items() if r == "input")

    @property
    def energy_out(self) -> float:
        """Energy the output ports took out."""
        return -sum(self.port_energy(p) for p, r in self.roles.items() if r == "output")

    @property
    def efficiency(self) -> float:
        return self.energy_out / self.energy_in

    def losses(self) -> dict:
        """``{friction column: energy it dissipated}`` (positive numbers)."""
        return {a.name: -self._energy([k]) for k, a in enumerate(self.network.action_cols) if a.role == "friction"}

    def loss_shares(self, by: str = "coupling") -> dict:
        """Shares of the lost energy by ``coupling``, ``joint`` or ``kind`` (of coupling:
        ``universal``, ``square annulus``, ...; ``prismatic pair`` when grouped by ``family``)."""
        net = self.network
        kinds = {c.name: c for c in net.couplings}
        out: dict = {}
        for k, a in enumerate(net.action_cols):
            if a.role != "friction":
                continue
            c = kinds[a.coupling]
            key = {"coupling": c.name, "joint": c.joint, "kind": c.kind,
                   "family": "prismatic pair" if c.kind in ("prismatic", "square annulus", "round annulus", "slider")
                   else c.kind}.get(by)
            if key is None:
                raise InputError(f"loss_shares by {by!r}: choose coupling, joint, kind or family")
            out[key] = out.get(key, 0.0) - self._energy([k])
        total = sum(out.values())
        return {k: v / total for k, v in out.items()} if total else out

    def port_series(self, port) -> np.ndarray:
        """The action of a port at every sample (a force or torque)."""
        cols = [k for k, a in enumerate(self.network.action_cols) if a.port == port]
        return self.actions[:, cols].sum(axis=1)

    def series(self, name) -> np.ndarray:
        """A motion or action variable at every sample."""
        net = self.network
        if name in net.motion_names():
            return self.motions[:, net.motion_names().index(name)]
        return self.actions[:, net.action_names().index(name)]

    def reversals(self, *, refine: bool = True, tol: float = 1e-9) -> list[Reversal]:
        """Instants at which a motion variable changes sign, with the variables that do (those
        that stay zero, such as the small rotations of a split pair's annuli, are left out)."""
        net = self.network
        events: list = []
        sign = np.sign(self.motions)
        size = np.abs(self.motions).max(axis=0)
        for k, m in enumerate(net.motion_cols):
            if size[k] <= 1e-8 * size.max():
                continue  # a freedom that never moves (a split annulus' small rotations): rounding, not motion
            for i in np.nonzero(sign[1:, k] * sign[:-1, k] < 0)[0]:
                t = self._root(k, self.times[i], self.times[i + 1], tol) if refine else self.times[i]
                events.append((t, m.name))
        events.sort()
        out: list = []
        for t, name in events:
            if out and abs(out[-1].time - t) < 1e3 * tol:
                out[-1] = Reversal(out[-1].time, out[-1].variables + (name,))
            else:
                out.append(Reversal(float(t), (name,)))
        return out

    def _root(self, k, a, b, tol):
        return _sign_change(lambda t: self._motion_at(t)[k], a, b, tol)

    def _motion_at(self, t):
        if self.task.samples is not None:
            raise InputError("reversals of a sampled trajectory are found between samples only (refine=False)")
        net = self.network
        inputs = self.task.inputs_at(t)
        pose = solve_pose(self.linkage, {k: v[0] for k, v in inputs.items()}, self._nearest_pose(t))
        md, _ = net.unit_screws(pose)
        return solve_motions(net, md, {k: v[1] for k, v in inputs.items()})

    def _nearest_pose(self, t):
        poses = self.stats.get("poses")
        if not poses:
            return None
        return poses[int(np.argmin(np.abs(self.times - t)))]

    def to_json(self) -> dict:
        return {"linkage": self.linkage.name, "task": self.task.name, "samples": len(self.times),
                "rule": self.task.rule, "energy_in": self.energy_in, "energy_out": self.energy_out,
                "efficiency": self.efficiency, "ports": {p: {"role": r, "energy": self.port_energy(p)}
                                                         for p, r in self.roles.items()},
                "losses": self.losses(), "loss_shares": self.loss_shares("coupling"),
                "loss_shares_by_kind": self.loss_shares("kind"),
                "solver": {k: v for k, v in self.stats.items() if k != "poses"}}

    def __str__(self) -> str:
        lines = [f"{self.linkage.name}, task {self.task.name}: {len(self.times)} samples, t = {self.task.start:g} to "
                 f"{self.task.stop:g} ({self.task.rule} rule)",
                 f"energy in  {self.energy_in:14.6g}", f"energy out {self.energy_out:14.6g}",
                 f"efficiency {self.efficiency:14.6f}", "losses by coupling:"]
        for name, share in sorted(self.loss_shares("coupling").items(), key=lambda kv: -kv[1]):
            lines.append(f"  {name:8s} {100 * share:8.3f} %")
        return "\n".join(lines)

    def plot(self, ax=None, **kw):
        """The ports' powers against time (:func:`gearlib.linkages.plot_task_powers`)."""
        from .drawing import plot_task_powers

        return plot_task_powers(self, ax=ax, **kw)


def _task(linkage, task) -> Task:
    if isinstance(task, Task):
        return task
    if isinstance(task, str):
        return linkage.task(task)
    raise InputError(f"a task is a Task or the name of one of {linkage.name!r}'s tasks, got {type(task).__name__}")


def run(linkage, task, *, ramp=RAMP, keep_poses: bool = True, positions=None) -> TaskResult:
    """Follow *task* (a :class:`~gearlib.linkages.Task` or the name of one of the linkage's
    tasks) sample by sample. The poses are solved from the motion inputs, or given by a
    position function ``positions(t) -> {link: (R, p)}`` (or a :class:`~gearlib.linkages.Pose`),
    checked against the joints."""
    task = _task(linkage, task)
    linkage.check_task(task)
    net = make_network(linkage)
    ports = {p.name: p for p in linkage.ports}
    roles = {p.name: p.role for p in linkage.ports}
    for name, role in task.roles:
        if name not in ports:
            raise InputError(f"task {task.name}: role for {name!r}, which is not a port")
        roles[name] = role
    primaries(net, [k for k, _ in task.motion])  # names checked before any work
    times = task.times()
    n, c = len(times), len(net.action_cols)
    powers, actions, motions = np.empty((n, c)), np.empty((n, c)), np.empty((n, len(net.motion_cols)))
    pose = before = earlier = state = None
    poses, restarts, solves, fallbacks, worst = [], 0, 0, 0, 0
    for i, t in enumerate(times):
        inputs = task.inputs_at(t, i)
        guess = pose
        if before is not None:
            ratio = (t - times[i - 1]) / (times[i - 1] - times[i - 2])
            even = earlier is not None and abs((times[i - 1] - times[i - 2]) - (times[i - 2] - times[i - 3])) < 1e-12
            guess = extrapolate(pose, before, 1.0 if abs(ratio - 1) < 1e-9 else ratio, earlier if even else None)
        if positions is not None:
            given = positions(t)
            given = given if isinstance(given, Pose) else Pose.from_frames(linkage, given, {k: v[0] for k, v in
                                                                                          inputs.items()})
            pose, before, earlier = given, pose, before
        else:
            pose, before, earlier = solve_pose(linkage, {k: v[0] for k, v in inputs.items()}, guess), pose, before
        now = instant(linkage, pose, speeds={k: v[1] for k, v in inputs.items()}, actions=task.actions_at(t),
                      state=state, time=t, ramp=ramp)
        state = now.state
        powers[i], actions[i], motions[i] = now.column_powers(), now.actions, now.psi
        restarts += now.stats.get("restarts", 0)
        solves += now.stats.get("solves", 0)
        fallbacks += bool(now.stats.get("fallback"))
        worst = max(worst, now.stats.get("solves", 0))
        if keep_poses:
            poses.append(pose)
    stats = {"solves": solves, "restarts": restarts, "most_solves_per_step": worst, "fallbacks": fallbacks,
             "tellegen": float(np.abs(powers.sum(axis=1)).max()), "poses": tuple(poses)}
    return TaskResult(linkage, task, times, task.weights(), powers, actions, motions, roles, stats)


def cycle(linkage, joint, actions: dict, *, panels: int = 8, roles: dict | None = None,
          start: float = -math.pi) -> TaskResult:
    """One turn of the revolute *joint* at unit speed with the known *actions* (``{port: value}``),
    integrated exactly enough for closed forms: a coarse pass finds the instants at which a
    motion reverses or a force in a friction law changes sign (where the powers have a kink),
    and each stretch between two of them, round the whole turn, gets *panels* panels of
    Gauss-Legendre nodes."""
    base = {"motion": {joint: "t"}, "actions": dict(actions), "roles": dict(roles or {})}
    # Gauss nodes never fall on a panel's end: the coarse pass steps over the dead centres
    coarse = run(linkage, Task.from_dict("cycle", {**base, "time": [start, start + 2 * math.pi], "steps": 12,
                                                   "rule": "gauss"}))
    cuts = {ev.time for ev in coarse.reversals()}
    net = coarse.network
    turn = 2 * math.pi
    moving = np.abs(coarse.motions).max(axis=0) > 1e-8 * np.abs(coarse.motions).max()
    first, last = coarse.times[0], coarse.times[-1]
    for k in np.nonzero(moving)[0]:  # the stretch from the last node round to the first
        if coarse.motions[-1, k] * coarse.motions[0, k] < 0:
            cuts.add(coarse._root(k, last - turn, first, 1e-9))
    forces = sorted({c for term in net.friction for _, cols, _ in term.groups for c in cols})
    values = coarse.actions[:, forces]
    wrapped = np.vstack([values[-1:], values])
    times = np.r_[last - turn, coarse.times]
    for k, col in enumerate(forces):
        for i in np.nonzero(np.sign(wrapped[1:, k]) * np.sign(wrapped[:-1, k]) < 0)[0]:
            cuts.add(_force_root(coarse, col, times[i], times[i + 1]))
    cuts = sorted({start + (t - start) % turn for t in cuts})
    # the turn starts at the first kink and ends there: every stretch runs from kink to kink
    edges = [*cuts, cuts[0] + turn] if cuts else [start, start + turn]
    parts = [run(linkage, Task.from_dict("cycle", {**base, "time": [a, b], "steps": panels, "rule": "gauss"}))
             for a, b in zip(edges[:-1], edges[1:]) if b - a > 1e-9]
    task = Task.from_dict("cycle", {**base, "time": [edges[0], edges[-1]], "steps": panels * len(parts),
                                    "rule": "gauss"})
    stats = {k: sum(p.stats[k] for p in parts) for k in ("solves", "restarts", "fallbacks")}
    stats.update(most_solves_per_step=max(p.stats["most_solves_per_step"] for p in parts),
                 tellegen=max(p.stats["tellegen"] for p in parts),
                 poses=tuple(x for p in parts for x in p.stats["poses"]), pieces=len(parts))
    cat = np.concatenate
    return TaskResult(linkage, task, cat([p.times for p in parts]), cat([p.weights for p in parts]),
                      cat([p.powers for p in parts]), cat([p.actions for p in parts]), cat([p.motions for p in parts]),
                      parts[0].roles, stats)


class _DeadCentre(Exception):
    """An instant at which no pose or no force can be solved (raised through brentq)."""

    def __init__(self, t):
        self.t = t


def _sign_change(f, a, b, tol):
    """The instant between *a* and *b* at which *f* (of opposite signs there) changes sign, to
    *tol*: where *f* passes through zero, or through infinity (a force at a dead centre). Brent's
    method (a bracket kept throughout: secant and inverse quadratic steps, bisection where they
    do not shrink it) on ``h = (f/s) / (1 + (f/s)^2)``, *s* the size of *f* at the ends: *h* has
    the sign of *f* and a simple zero at both kinds of sign change, so that about 8 instants are
    solved where bisection needs 30. An instant at which *f* cannot be evaluated at all (at a
    dead centre) is where the sign changes."""
    from scipy.optimize import brentq

    def g(t):
        try:
            return float(f(t))
        except GearlibError:
            raise _DeadCentre(t) from None

    try:
        fa, fb = g(a), g(b)
        if fa == 0.0 or fb == 0.0:
            return a if fa == 0.0 else b
        if np.sign(fa) == np.sign(fb):   # no sign change seen at the ends (rounding): the middle
            return (a + b) / 2
        scale = math.sqrt(abs(fa) * abs(fb))
        ends = {a: fa, b: fb}

        def h(t):
            x = (ends[t] if t in ends else g(t)) / scale
            return x / (1.0 + x * x) if math.isfinite(x) else 0.0

        return brentq(h, a, b, xtol=tol, rtol=4 * np.finfo(float).eps, maxiter=200, disp=False)
    except _DeadCentre as dead:
        return dead.t


def _force_root(res, col, a, b, tol=1e-10):
    """The instant between *a* and *b* at which the action column *col* changes sign (a friction
    law's absolute value has its kink there), on instants solved afresh."""
    def value(t):
        inputs = res.task.inputs_at(t)
        pose = solve_pose(res.linkage, {k: v[0] for k, v in inputs.items()}, res._nearest_pose(t))
        now = instant(res.linkage, pose, speeds={k: v[1] for k, v in inputs.items()}, actions=res.task.actions_at(t))
        return now.actions[col]

    return _sign_change(value, a, b, tol)


def jump(linkage, task, time: float, port, *, eps: float = 1e-7) -> float:
    """Relative change of *port*'s action across *time* (just before to just after, each side
    continued from the frictionless solution): the jump a motion reversal causes."""
    task = _task(linkage, task)
    values = []
    pose = None
    for t in (time - eps, time + eps):
        inputs = task.inputs_at(t)
        pose = solve_pose(linkage, {k: v[0] for k, v in inputs.items()}, pose)
        now = instant(linkage, pose, speeds={k: v[1] for k, v in inputs.items()}, actions=task.actions_at(t))
        values.append(sum(now.action(a.name) for a in now.network.action_cols if a.port == port))
    return (values[1] - values[0]) / abs(values[0])
