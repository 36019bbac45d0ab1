"""Davies' two laws at one instant, with Coulomb friction: :func:`~gearlib.linkages.instant`.

**Motions.** ``M_N psi = 0`` (Laus 2011, eq. 1), with the motion inputs as primary variables:
a driven joint's rate, or the velocity of a load port's point (the thesis' ``u_M, v_M, w_M``).

**Actions.** ``A_N Psi = 0`` (eq. 2), with the known port actions as primary variables and
one *constitutive row* per friction column: ``F + c sign(motion) sum_k m_k |Q_k| = 0``
(eqs. (98), (127)-(129)), or with the resultant of the forces (eq. (133)). The absolute values
make the system nonlinear. It is linear once the signs of the forces are known, and the
thesis' Algorithm 2 finds them by *continuation*: start from the frictionless solution, take
its signs, raise the friction coefficients step by step (``ramp``), and whenever a solution
contradicts a sign, update the sign and start again; the next instant starts from the signs
of the last. A sign that keeps flipping (a force through zero exactly where it is needed) is
settled by a damped Newton step on the piecewise-linear system.

>>> import math, gearlib as gl
>>> crank = gl.linkages.load("laus_slider_crank")
>>> pose = gl.linkages.solve_pose(crank, {"A": [math.pi / 3]})
>>> now = gl.linkages.instant(crank, pose, speeds={"A": [1.0]}, actions={"A": 1.0})
>>> p = now.port_powers()
>>> round(p["A"], 12), round(-p["D"] / p["A"], 6)                # input power; instantaneous efficiency
(1.0, 0.969849)
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..errors import ConstraintError, InputError
from .couplings import network as make_network

__all__ = ["Instant", "instant", "solve_motions", "solve_actions", "primaries"]

RAMP = (0.25, 0.5, 0.75, 1.0)


def primaries(net, names) -> list[int]:
    """Motion columns fixed by the motion inputs *names* (joints or load ports)."""
    cols = []
    ports = {p.name: p for p in net.linkage.ports}
    joints = {j.name: j for j in net.linkage.joints}
    for name in names:
        p = ports.get(name)
        if p is not None and p.kind == "load":
            trans = [k for k, m in enumerate(net.motion_cols) if m.coupling == name and m.kind == "translation"]
            cols += trans
            continue
        j = joints.get(name) or joints.get(getattr(p, "joint", None))
        if j is None:
            raise InputError(f"motion input {name!r} is neither a joint nor a port")
        c = j.couplings[0]
        cols.append(next(k for k, m in enumerate(net.motion_cols) if m.coupling == c and m.kind ==
                         ("rotation" if j.kind == "revolute" else "translation")))
    return cols


def _motion_plan(net, names):
    plans = net.__dict__.setdefault("_motion_plans", {})
    key = tuple(names)
    if key not in plans:
        prim = primaries(net, names)
        plans[key] = (np.array(prim, dtype=int), np.setdiff1d(np.arange(len(net.motion_cols)), prim))
    return plans[key]


def solve_motions(net, md, speeds: dict) -> np.ndarray:
    """The motion magnitudes ``psi`` with the inputs' rates ``speeds`` (``{name: [rates]}``)."""
    prim, rest = _motion_plan(net, list(speeds))
    values = np.array([float(v) for vs in speeds.values() for v in vs])
    if len(values) != len(prim):
        raise InputError("each motion input needs one rate per coordinate")
    mn = net.M_N(md)
    a, b = mn[:, rest], -mn[:, prim] @ values
    x = None
    if a.shape[0] == a.shape[1]:
        try:
            x = np.linalg.solve(a, b)
        except np.linalg.LinAlgError:
            x = None
        if x is not None and not np.abs(x).max(initial=0.0) < 1e12 * max(1.0, np.abs(values).max()):
            x = None
    if x is None:
        x, _, rank, _ = np.linalg.lstsq(a, b, rcond=None)
        if rank < len(rest):
            raise InputError(f"{net.linkage.name}: the motion inputs {', '.join(speeds)} leave {len(rest) - rank} "
                             "motion(s) undetermined (a singular position, or too few inputs)")
        if a.size and np.abs(a @ x - b).max() > 1e-8 * max(1.0, np.abs(b).max()):
            raise InputError(f"{net.linkage.name}: the motion inputs {', '.join(speeds)} contradict each other")
    psi = np.empty(mn.shape[1])
    psi[prim], psi[rest] = values, x
    return psi


def _signs(values, tol):
    return np.where(values > tol, 1.0, np.where(values < -tol, -1.0, 0.0))


def _friction_plan(net):
    """Flat arrays of the friction laws: one entry per force that a friction column depends on."""
    plan = net.__dict__.get("_friction_plan")
    if plan is None:
        term, col, mult, group, resultant = [], [], [], [], []
        g = 0
        for t, ft in enumerate(net.friction):
            for m, cols, norm in ft.groups:
                for c in cols:
                    term.append(t)
                    col.append(c)
                    mult.append(m)
                    group.append(g)
                    resultant.append(norm == "resultant")
                g += 1
        plan = net.__dict__["_friction_plan"] = {
            "term": np.array(term, dtype=int), "col": np.array(col, dtype=int), "mult": np.array(mult),
            "group": np.array(group, dtype=int), "groups": g, "resultant": np.array(resultant, dtype=bool),
            "fcol": np.array([ft.column for ft in net.friction], dtype=int),
            "motion": np.array([ft.motion for ft in net.friction], dtype=int),
            "coef": np.array([ft.coef for ft in net.friction]),
        }
    return plan


class _Actions:
    """The action equations at one instant: ``A_N``, the known ports and the friction rows.
    The force directions of the friction laws are one flat array (``sum``: the signs of the
    forces; ``resultant``: the components of their unit resultant)."""

    def __init__(self, net, ad, psi, known: dict):
        self.net = net
        an = net.A_N(ad)
        ncol = an.shape[1]
        cols, vals = [], []
        for name, value in known.items():
            idx = [k for k, a in enumerate(net.action_cols) if a.port == name]
            if not idx:
                raise InputError(f"action {name!r} is not a port of {net.linkage.name!r}")
            cols += idx
            vals += [float(value)] * len(idx)
        self.plan = plan = _friction_plan(net)
        nf = len(plan["fcol"])
        self.rows = slice(an.shape[0], an.shape[0] + nf)
        self.a = np.zeros((an.shape[0] + nf + len(cols), ncol))
        self.a[:an.shape[0]] = an
        self.a[self.rows.start + np.arange(nf), plan["fcol"]] = 1.0
        self.a[self.rows.stop + np.arange(len(cols)), cols] = 1.0
        self.base = self.a[self.rows].copy()
        self.rhs = np.r_[np.zeros(an.shape[0] + nf), vals]
        self.terms = net.friction
        tol = 1e-12 * max(1.0, float(np.abs(psi).max()))
        msign = _signs(psi[plan["motion"]], tol) if nf else np.zeros(0)
        # the factor of each entry: coefficient, sign of the motion, multiplier of the face
        self.weight = (plan["coef"] * msign)[plan["term"]] * plan["mult"] if nf else np.zeros(0)

    def matrix(self, lam, dirs):
        rows = self.base.copy()
        np.add.at(rows, (self.plan["term"], self.plan["col"]), lam * self.weight * dirs)
        self.a[self.rows] = rows
        return self.a

    def solve(self, lam, dirs):
        a = self.matrix(lam, dirs)
        if a.shape[0] == a.shape[1]:
            try:
                x = np.linalg.solve(a, self.rhs)
                if np.all(np.isfinite(x)) and np.abs(x).max(initial=0.0) < 1e15 * max(1.0, np.abs(self.rhs).max()):
                    return x
            except np.linalg.LinAlgError:
                pass
        x, _, rank, _ = np.linalg.lstsq(a, self.rhs, rcond=None)
        if rank < a.shape[1] or np.abs(a @ x - self.rhs).max() > 1e-7 * max(1.0, np.abs(self.rhs).max()):
            free = a.shape[1] - rank
            raise ConstraintError(f"{self.net.linkage.name}: the actions are not determined ({free} left free, or no "
                                  "balance exists): give one known action per degree of freedom, away from a singular "
                                  "position (a dead centre)")
        return x

    def directions(self, x, old=None):
        """The sign of each force (``sum``) or the unit direction of the forces (``resultant``)."""
        plan = self.plan
        v = x[plan["col"]]
        tol = 1e-12 * max(1.0, float(np.abs(x).max()))
        d = _signs(v, tol)
        res = plan["resultant"]
        if res.any():
            norms = np.sqrt(np.bincount(plan["group"], v * v, minlength=plan["groups"]))[plan["group"]]
            d = np.where(res, v / np.where(norms > tol, norms, 1.0), d)
            if old is not None:
                d = np.where(res & (norms <= tol), old, d)
        if old is not None:
            d = np.where(~res & (d == 0), old, d)
        return d

    def residual(self, x):
        return self.matrix(1.0, self.directions(x)) @ x - self.rhs


def _flipped(system, new, old) -> tuple[bool, bool]:
    """(a sign changed, a resultant's direction moved)."""
    res = system.plan["resultant"]
    sign = bool(np.any((new != old) & ~res))
    move = bool(np.any(np.abs(new - old)[res] > 1e-13)) if res.any() else False
    return sign, move


def _damped(system, x):
    """Damped Newton on the piecewise-linear action equations (when signs keep flipping)."""
    r = np.linalg.norm(system.residual(x))
    for _ in range(100):
        y = system.solve(1.0, system.directions(x))
        step = 1.0
        while step > 1e-6:
            z = x + step * (y - x)
            rz = np.linalg.norm(system.residual(z))
            if rz < r:
                x, r = z, rz
                break
            step /= 2
        else:
            break
        if r < 1e-9 * max(1.0, np.abs(system.rhs).max()):
            break
    return x


def solve_actions(system, state=None, *, ramp=RAMP, limit: int = 60):
    """Algorithm 2 at one instant: ``(Psi, directions, stats)``. *state* is the last instant's
    directions (``None``: start from the frictionless solution and ramp the friction up)."""
    stats = {"solves": 0, "restarts": 0, "fallback": False}
    if not system.terms:
        stats["solves"] = 1
        return system.solve(1.0, np.zeros(0)), np.zeros(0), stats
    if state is None:
        x = system.solve(0.0, np.zeros(len(system.plan["col"])))
        stats["solves"] += 1
        dirs, lams = system.directions(x), tuple(ramp)
    else:
        dirs, lams = state, (1.0,)
    k = 0
    while k < len(lams):
        x = system.solve(lams[k], dirs)
        stats["solves"] += 1
        new = system.directions(x, dirs)
        sign, move = _flipped(system, new, dirs)
        dirs = new
        if sign:
            stats["restarts"] += 1
            if stats["restarts"] > limit:
                x = _damped(system, x)
                stats["fallback"] = True
                return x, system.directions(x, dirs), stats
            k = 0
            continue
        if move and stats["solves"] < 10 * limit:
            continue  # a resultant's direction: iterate at this friction level
        k += 1
    return x, dirs, stats


@dataclass(frozen=True)
class Instant:
    """Motions, actions and powers of every coupling at one instant."""

    network: object
    pose: object
    time: float
    md: np.ndarray = field(repr=False)
    ad: np.ndarray = field(repr=False)
    psi: np.ndarray = field(repr=False)
    actions: np.ndarray = field(repr=False)
    state: list = field(repr=False)
    stats: dict = field(default_factory=dict)

    def motion(self, name) -> float:
        return float(self.psi[self.network.motion_names().index(name)])

    def action(self, name) -> float:
        return float(self.actions[self.network.action_names().index(name)])

    def motion_screw(self, coupling) -> np.ndarray:
        """The motion screw of a coupling: its unit screws times their magnitudes."""
        return self.coupling_screws()[:, [c.name for c in self.network.couplings].index(coupling)]

    def coupling_screws(self) -> np.ndarray:
        """The motion screws of every coupling (one column each, in the network's order)."""
        net = self.network
        member = net.__dict__.get("_member")
        if member is None:
            member = net.__dict__["_member"] = (net._coupling_of_m[:, None] == np.arange(len(net.couplings))).astype(float)
        return (self.md * self.psi) @ member

    def column_powers(self) -> np.ndarray:
        """Power of every action column on its coupling's motion (constraints give zero)."""
        per = self.coupling_screws()[:, self.network._coupling_of_a]
        return self.actions * np.einsum("ij,ij->j", self.ad, per)

    def powers(self) -> dict:
        """``{column: power}`` of the ports and the friction columns."""
        p = self.column_powers()
        return {a.name: float(p[k]) for k, a in enumerate(self.network.action_cols) if a.role != "constraint"}

    def coupling_powers(self) -> dict:
        """``{coupling: power}``: what each coupling's ports and friction put in (negative: take
        out or dissipate); a coupling with neither gives zero."""
        p = self.column_powers()
        out = {c.name: 0.0 for c in self.network.couplings}
        for k, a in enumerate(self.network.action_cols):
            out[a.coupling] += float(p[k])
        return out

    def port_powers(self) -> dict:
        """``{port: power}``: positive when power enters the linkage there."""
        p = self.column_powers()
        out: dict = {}
        for k, a in enumerate(self.network.action_cols):
            if a.port is not None:
                out[a.port] = out.get(a.port, 0.0) + float(p[k])
        return out

    def tellegen(self) -> float:
        """Sum of every column's power: zero (Tellegen's theorem, D1.3), up to rounding."""
        return float(self.column_powers().sum())


def instant(linkage, pose, *, speeds: dict, actions: dict, state=None, time: float = 0.0, ramp=RAMP) -> Instant:
    """Motions and actions of *linkage* at *pose*: ``speeds`` are the motion inputs' rates
    (``{joint or load port: [rates]}``), ``actions`` the known port actions (``{port: value}``);
    *state* the last instant's force directions (see :func:`solve_actions`)."""
    net = make_network(linkage)
    md, ad = net.unit_screws(pose)
    speeds = {k: list(v) if isinstance(v, (list, tuple, np.ndarray)) else [v] for k, v in speeds.items()}
    psi = solve_motions(net, md, speeds)
    system = _Actions(net, ad, psi, actions)
    x, dirs, stats = solve_actions(system, state, ramp=ramp)
    return Instant(net, pose, float(time), md, ad, psi, x, dirs, stats)
