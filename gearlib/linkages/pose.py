"""Poses: where every link is, solved from the joints' constraints and the motion inputs.

Each moving link has a frame ``(R, p)``: a point ``c`` of the link drawn at ``c`` in the
reference pose is at ``R c + p``, a direction ``a`` along ``R a``. Each joint asks for some
scalar equations (a revolute: its two copies of the point coincide and its axis stays one
line; a universal joint: the point, and its two axes perpendicular; a prismatic: the head's
point on the tail's line and no turning; ...); each motion input adds its own (a joint's
angle or displacement from the reference pose, a load port's point at a position).
:func:`~gearlib.linkages.solve_pose` solves them by Newton's method with the exact Jacobian, starting from a
*guess* (the reference pose, or the previous pose of a trajectory), and falls back on
smaller steps of the inputs when a step is too large. A linkage that cannot close (a coupler
too short to reach, an input out of range) raises a :class:`~gearlib.GeometryError` naming
the joint that stays apart.

The same Jacobian at the reference pose gives the degrees of freedom (:func:`~gearlib.linkages.mobility`).

>>> import gearlib as gl
>>> crank = gl.linkages.load("laus_slider_crank")
>>> pose = gl.linkages.solve_pose(crank, {"A": [3.141592653589793 / 2]})
>>> [round(float(x), 6) for x in pose.point(3, crank.joint("C").point)]   # C on the slide line
[2.828427, 0.0, 0.0]
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import GeometryError, InputError

__all__ = ["Pose", "solve_pose", "mobility", "extrapolate"]

_I3 = np.eye(3)
_Z = np.array([0.0, 0.0, 1.0])


def _v3(x) -> np.ndarray:
    x = np.asarray(x, dtype=float)
    return np.r_[x, 0.0] if x.shape[0] == 2 else x


def _basis(a) -> tuple:
    """Two unit vectors ``(u, w)`` making ``(a, u, w)`` right-handed and orthonormal."""
    a = np.asarray(a, dtype=float)
    hint = _I3[int(np.argmin(np.abs(a)))]
    u = hint - np.dot(hint, a) * a
    u /= np.linalg.norm(u)
    return u, np.cross(a, u)


def _perpendicular(out, g, a, b):
    """The rows of a ⟂ b (a fixed in link g["t"], b in link g["h"], one joint per row of a and
    b): the residual a . b and its derivatives, rotations only, for both links."""
    zero = np.zeros_like(a)
    out.append((np.einsum("ja,ja->j", a, b), g["t"], np.hstack([_cross(a, b), zero]), g["h"],
                np.hstack([_cross(b, a), zero]), g["names"]))


def _cross(a, b):
    """Row-wise cross products of two ``(m, 3)`` arrays (faster than np.cross on small arrays)."""
    return np.stack([a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1], a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2],
                     a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]], axis=-1)


def _skew_rows(r, k):
    """Row *k* of the cross-product matrix ``[r]x`` for each row of *r* (``(m, 3)``)."""
    z = np.zeros(len(r))
    return np.stack([(z, -r[:, 2], r[:, 1]), (r[:, 2], z, -r[:, 0]), (-r[:, 1], r[:, 0], z)][k], axis=1)


def _rotations(phi):
    """``exp([phi]x)`` for each row of *phi* (Rodrigues)."""
    th = np.linalg.norm(phi, axis=1)
    safe = np.where(th < 1e-15, 1.0, th)
    k = phi / safe[:, None]
    kx = np.zeros((len(phi), 3, 3))
    kx[:, 0, 1], kx[:, 0, 2], kx[:, 1, 2] = -k[:, 2], k[:, 1], -k[:, 0]
    kx[:, 1, 0], kx[:, 2, 0], kx[:, 2, 1] = k[:, 2], -k[:, 1], k[:, 0]
    s, c = np.sin(th)[:, None, None], (1 - np.cos(th))[:, None, None]
    out = _I3 + s * kx + c * (kx @ kx)
    out[th < 1e-15] = _I3
    return out


@dataclass(frozen=True)
class Pose:
    """The frames of every link (the ground's is the identity) and the inputs they were solved
    for; ``R[k]``, ``P[k]`` belong to the link ``index[k]``."""

    linkage: object
    R: np.ndarray = field(repr=False)
    P: np.ndarray = field(repr=False)
    index: dict = field(repr=False)
    inputs: dict = field(default_factory=dict)

    @classmethod
    def from_frames(cls, linkage, frames: dict, inputs: dict | None = None, *, tol: float = 1e-8) -> Pose:
        """A pose from a position function's frames ``{link: (R, p)}`` (links left out keep the
        identity), checked against the joints: a pose that does not close raises a
        :class:`~gearlib.GeometryError` naming the joint."""
        sys_ = _system(linkage)
        n = len(sys_.links)
        R, P = np.tile(_I3, (n, 1, 1)), np.zeros((n, 3))
        for link, (r, p) in frames.items():
            if link not in sys_.index:
                raise InputError(f"the position function gives a frame for {link!r}, which is not a link")
            R[sys_.index[link]], P[sys_.index[link]] = np.asarray(r, dtype=float), _v3(p)
        r, _, names = sys_.assemble(sys_.blocks(R, P))
        if r.size and float(np.abs(r).max()) > tol:
            k = int(np.argmax(np.abs(r)))
            raise GeometryError(f"{linkage.name}: the given pose does not close joint {names[k]} ({abs(r[k]):.3g} apart)")
        return cls(linkage, R, P, sys_.index, dict(inputs or {}))

    def frame(self, link) -> tuple:
        k = self.index[link]
        return self.R[k], self.P[k]

    def point(self, link, c) -> np.ndarray:
        """Where the point drawn at *c* in the reference pose, fixed in *link*, is now."""
        k = self.index[link]
        return self.R[k] @ _v3(c) + self.P[k]

    def direction(self, link, a) -> np.ndarray:
        """Where the direction drawn as *a* in the reference pose, fixed in *link*, points now."""
        return self.R[self.index[link]] @ _v3(a)


class _System:
    """The constraint equations of a linkage, vectorized by kind of equation."""

    def __init__(self, linkage):
        self.linkage = linkage
        self.planar = linkage.planar
        self.links = list(linkage.link_ids)
        self.index = {k: i for i, k in enumerate(self.links)}
        self.ground = self.index[linkage.ground]
        width = 3 if self.planar else 6
        keep = [i for i in range(len(self.links)) if i != self.ground]
        cols = [6 * i + c for i in keep for c in ((2, 3, 4) if self.planar else range(6))]
        self.cols = np.array(cols, dtype=int)
        self.n = width * len(keep)
        self.groups = {}
        js = linkage.joints
        ix = self.index

        def arrays(sel, **extra):
            if not sel:
                return None
            g = {"names": [j.name for j in sel], "t": np.array([ix[j.tail] for j in sel]),
                 "h": np.array([ix[j.head] for j in sel]), "c": np.array([_v3(j.point) for j in sel])}
            g.update({k: np.array([f(j) for j in sel]) for k, f in extra.items()})
            return g

        coincide = [j for j in js if j.kind in ("revolute", "universal", "spherical")]
        self.groups["coincide"] = arrays(coincide)
        if self.planar:
            pris = [j for j in js if j.kind == "prismatic"]
            self.groups["planar_prismatic"] = arrays(pris, a=lambda j: _v3(j.axis),
                                                     n=lambda j: np.array([-j.axis[1], j.axis[0], 0.0]))
        else:
            axial = [j for j in js if j.kind in ("revolute", "prismatic", "cylindrical")]
            basis = {j.name: _basis(_v3(j.axis)) for j in axial}
            self.groups["parallel"] = arrays(axial, a=lambda j: _v3(j.axis), u=lambda j: basis[j.name][0],
                                             w=lambda j: basis[j.name][1])
            lock = [j for j in axial if j.kind == "prismatic"]
            self.groups["lock"] = arrays(lock, u=lambda j: basis[j.name][0], w=lambda j: basis[j.name][1])
            line = [j for j in axial if j.kind in ("prismatic", "cylindrical")]
            self.groups["line"] = arrays(line, u=lambda j: basis[j.name][0], w=lambda j: basis[j.name][1])
            uni = [j for j in js if j.kind == "universal"]
            self.groups["universal"] = arrays(uni, l1=lambda j: ix[j.fixed_in[0]], l2=lambda j: ix[j.fixed_in[1]],
                                              a1=lambda j: _v3(j.axes[0]), a2=lambda j: _v3(j.axes[1]))
        self.basis = {j.name: _basis(_v3(j.axis)) for j in js if j.axis is not None and not self.planar}

    # each block: (residuals, tail rows of the frame index, tail grads (m, 6), head index, head grads)
    def blocks(self, R, P):
        out = []
        g = self.groups.get("coincide")
        if g is not None:
            rt = np.einsum("jab,jb->ja", R[g["t"]], g["c"])
            rh = np.einsum("jab,jb->ja", R[g["h"]], g["c"])
            d = rh + P[g["h"]] - rt - P[g["t"]]
            for k in ((0, 1) if self.planar else (0, 1, 2)):
                e = np.tile(_I3[k], (len(d), 1))
                out.append((d[:, k], g["t"], np.hstack([_skew_rows(rt, k), -e]), g["h"],
                            np.hstack([-_skew_rows(rh, k), e]), g["names"]))
        if self.planar:
            g = self.groups.get("planar_prismatic")
            if g is not None:
                _perpendicular(out, g, np.einsum("jab,jb->ja", R[g["t"]], g["a"]),
                               np.einsum("jab,jb->ja", R[g["h"]], g["n"]))
                self._line(out, g, R, P, [np.einsum("jab,jb->ja", R[g["t"]], g["n"])])
            return out
        g = self.groups.get("parallel")
        if g is not None:
            da = np.einsum("jab,jb->ja", R[g["t"]], g["a"])
            for key in ("u", "w"):
                _perpendicular(out, g, da, np.einsum("jab,jb->ja", R[g["h"]], g[key]))
        g = self.groups.get("lock")
        if g is not None:
            _perpendicular(out, g, np.einsum("jab,jb->ja", R[g["t"]], g["u"]),
                           np.einsum("jab,jb->ja", R[g["h"]], g["w"]))
        g = self.groups.get("line")
        if g is not None:
            self._line(out, g, R, P, [np.einsum("jab,jb->ja", R[g["t"]], g[k]) for k in ("u", "w")])
        g = self.groups.get("universal")
        if g is not None:
            d1 = np.einsum("jab,jb->ja", R[g["l1"]], g["a1"])
            d2 = np.einsum("jab,jb->ja", R[g["l2"]], g["a2"])
            zero = np.zeros_like(d1)
            out.append((np.einsum("ja,ja->j", d1, d2), g["l1"], np.hstack([_cross(d1, d2), zero]), g["l2"],
                        np.hstack([_cross(d2, d1), zero]), g["names"]))
        return out

    @staticmethod
    def _line(out, g, R, P, normals):
        rt = np.einsum("jab,jb->ja", R[g["t"]], g["c"])
        rh = np.einsum("jab,jb->ja", R[g["h"]], g["c"])
        delta = rh + P[g["h"]] - rt - P[g["t"]]
        for n in normals:
            out.append((np.einsum("ja,ja->j", delta, n), g["t"], np.hstack([_cross(n, delta) - _cross(rt, n), -n]),
                        g["h"], np.hstack([_cross(rh, n), n]), g["names"]))

    def input_blocks(self, R, P, inputs):
        """Blocks of the motion inputs: a joint's coordinate, a load port's point."""
        joints = {j.name: j for j in self.linkage.joints}
        ports = {p.name: p for p in self.linkage.ports}
        out = []
        for name, target in inputs.items():
            port = ports.get(name)
            if port is not None and port.kind == "load":
                k = self.index[port.link]
                r = R[k] @ _v3(port.point)
                x = r + P[k]
                for i in range(len(port.point)):
                    e = _I3[i]
                    out.append((np.array([x[i] - target[i]]), np.array([self.ground]), np.zeros((1, 6)), np.array([k]),
                                np.r_[np.cross(r, e), e][None, :], [name]))
                continue
            j = joints.get(name) or joints[port.joint]
            t, h = self.index[j.tail], self.index[j.head]
            if j.kind == "revolute":
                if self.planar:
                    rel = R[t].T @ R[h]
                    angle, d = math.atan2(rel[1, 0], rel[0, 0]), _Z
                else:
                    u, w = self.basis[j.name]
                    hu = R[h] @ u
                    angle, d = math.atan2((R[t] @ w) @ hu, (R[t] @ u) @ hu), R[t] @ _v3(j.axis)
                res = (angle - target[0] + math.pi) % (2 * math.pi) - math.pi
                out.append((np.array([res]), np.array([t]), np.r_[-d, 0, 0, 0][None, :], np.array([h]),
                            np.r_[d, 0, 0, 0][None, :], [name]))
            else:
                c = _v3(j.point)
                rt, rh = R[t] @ c, R[h] @ c
                delta = rh + P[h] - rt - P[t]
                d = R[t] @ _v3(j.axis)
                out.append((np.array([delta @ d - target[0]]), np.array([t]),
                            np.r_[np.cross(d, delta) - np.cross(rt, d), -d][None, :], np.array([h]),
                            np.r_[np.cross(rh, d), d][None, :], [name]))
        return out

    def assemble(self, blocks):
        """``(residuals, Jacobian, joint names)``; the scatter indices are kept per structure."""
        key = tuple((len(b[0]), tuple(b[1][:1]), tuple(b[3][:1])) for b in blocks)
        plans = self.__dict__.setdefault("_plans", {})
        plan = plans.get(key)
        if plan is None:
            six = np.arange(6)
            rows, tcols, hcols, names, i = [], [], [], [], 0
            for res, t, _, h, _, nm in blocks:
                rows.append(np.repeat(np.arange(i, i + len(res)), 6))
                tcols.append((6 * t[:, None] + six).ravel())
                hcols.append((6 * h[:, None] + six).ravel())
                names += nm
                i += len(res)
            plan = plans[key] = (i, np.concatenate(rows), np.concatenate(tcols), np.concatenate(hcols), names)
        m, rows, tcols, hcols, names = plan
        r = np.concatenate([b[0] for b in blocks])
        jac = np.zeros((m, 6 * len(self.links)))
        jac[rows, tcols] = np.concatenate([b[2] for b in blocks]).ravel()
        jac[rows, hcols] += np.concatenate([b[4] for b in blocks]).ravel()
        return r, jac[:, self.cols], names


def _system(linkage) -> _System:
    cached = linkage.__dict__.get("_pose_system")
    if cached is None:
        cached = _System(linkage)
        linkage.__dict__["_pose_system"] = cached  # the linkage is frozen data: its equations never change
    return cached


def mobility(linkage) -> int:
    """Degrees of freedom of *linkage*: pose coordinates of its moving links minus the rank of
    its joints' constraint equations at the reference pose."""
    sys_ = _system(linkage)
    n = len(sys_.links)
    _, jac, _ = sys_.assemble(sys_.blocks(np.tile(_I3, (n, 1, 1)), np.zeros((n, 3))))
    if jac.size == 0:
        return sys_.n
    s = np.linalg.svd(jac, compute_uv=False)
    return sys_.n - int((s > 1e-9 * max(1.0, s[0])).sum())


def _newton(sys_, R, P, inputs, tol, max_iter):
    R, P = R.copy(), P.copy()
    keep = [i for i in range(len(sys_.links)) if i != sys_.ground]
    width = 3 if sys_.planar else 6
    err, names, r = float("inf"), [], np.zeros(0)
    for _ in range(max_iter):
        r, jac, names = sys_.assemble(sys_.blocks(R, P) + sys_.input_blocks(R, P, inputs))
        err = float(np.abs(r).max()) if r.size else 0.0
        if err < tol or not np.isfinite(err) or err > 1e6:
            break
        if jac.shape[0] == jac.shape[1]:
            try:
                delta = np.linalg.solve(jac, -r)
            except np.linalg.LinAlgError:
                delta = np.linalg.lstsq(jac, -r, rcond=None)[0]
        else:
            delta = np.linalg.lstsq(jac, -r, rcond=None)[0]
        small = err < 1e-4 and float(np.abs(delta).max()) < 0.1 * math.sqrt(tol)
        delta = delta.reshape(len(keep), width)
        if sys_.planar:
            phi = np.zeros((len(keep), 3))
            phi[:, 2] = delta[:, 0]
            dp = np.c_[delta[:, 1:], np.zeros(len(keep))]
        else:
            phi, dp = delta[:, :3], delta[:, 3:]
        R[keep] = _rotations(phi) @ R[keep]
        P[keep] = P[keep] + dp
        if small:  # Newton converges quadratically: the residual now is far below tol
            err = 0.0
            break
    return R, P, err, r, names


def _log(turn):
    """Rotation vectors of small rotations (the skew part of each matrix)."""
    return 0.5 * np.stack([turn[:, 2, 1] - turn[:, 1, 2], turn[:, 0, 2] - turn[:, 2, 0], turn[:, 1, 0] - turn[:, 0, 1]],
                          axis=1)


def extrapolate(last: Pose, before: Pose, ratio: float = 1.0, earlier: Pose | None = None) -> Pose:
    """A guess for the next pose of a trajectory: *last* moved on as it moved from *before*
    (*ratio*: the next step over the last one), to second order when the pose *earlier* than
    *before* is given (equal steps). Newton's method then needs one step, or two."""
    phi = _log(last.R @ np.transpose(before.R, (0, 2, 1)))
    dp = last.P - before.P
    if earlier is not None and ratio == 1.0:
        phi = 2 * phi - _log(before.R @ np.transpose(earlier.R, (0, 2, 1)))
        dp = 2 * dp - (before.P - earlier.P)
        inputs = {k: [3 * a - 3 * b + c for a, b, c in zip(v, before.inputs.get(k, v), earlier.inputs.get(k, v))]
                  for k, v in last.inputs.items()}
    else:
        phi, dp = ratio * phi, ratio * dp
        inputs = {k: [a + ratio * (a - b) for a, b in zip(v, before.inputs.get(k, v))] for k, v in last.inputs.items()}
    return Pose(last.linkage, _rotations(phi) @ last.R, last.P + dp, last.index, inputs)


def solve_pose(linkage, inputs: dict, guess: Pose | None = None, *, tol: float = 1e-11, max_iter: int = 30) -> Pose:
    """The pose of *linkage* with the motion *inputs* (``{joint or port: [coordinates]}``: a
    joint's angle in rad or displacement from the reference pose, or a load port's point),
    solved from *guess* (default: the reference pose)."""
    joints = {j.name for j in linkage.joints}
    ports = {p.name for p in linkage.ports}
    clean = {}
    for name, value in inputs.items():
        if name not in joints and name not in ports:
            raise InputError(f"motion input {name!r} is neither a joint nor a port of {linkage.name!r}")
        clean[name] = [float(x) for x in (value if isinstance(value, (list, tuple, np.ndarray)) else [value])]
    sys_ = _system(linkage)
    n = len(sys_.links)
    if guess is None:
        R0, P0, start = np.tile(_I3, (n, 1, 1)), np.zeros((n, 3)), _reference_inputs(linkage, clean)
    else:
        R0, P0, start = guess.R, guess.P, guess.inputs
    if not hasattr(sys_, "scale"):
        sys_.scale = max(1.0, max(float(np.abs(_v3(j.point)).max()) for j in linkage.joints))
    tol = tol * sys_.scale
    R, P, err, r, names = _newton(sys_, R0, P0, clean, tol, max_iter)
    if err >= tol and set(start) == set(clean):
        R, P, err, r, names = _creep(sys_, R0, P0, start, clean, tol, max_iter)
    if err >= tol:
        worst = names[int(np.argmax(np.abs(r)))] if len(r) else "?"
        said = ", ".join(f"{k} = {_fmt(v)}" for k, v in clean.items())
        raise GeometryError(f"{linkage.name}: the joints cannot all close at {said}: joint {worst} stays "
                            f"{float(np.abs(r).max()):.3g} apart. Check its links' lengths and the range of the inputs")
    return Pose(linkage, R, P, sys_.index, clean)


def _creep(sys_, R, P, start, target, tol, max_iter):
    """Homotopy in the inputs: from the guess's inputs to the target in halving steps."""
    done, step = 0.0, 0.5
    err, r, names = float("inf"), np.zeros(0), []
    while done < 1.0 and step > 1e-4:
        s = min(1.0, done + step)
        mid = {k: [a + s * (b - a) for a, b in zip(start[k], target[k])] for k in target}
        R2, P2, err, r, names = _newton(sys_, R, P, mid, tol, max_iter)
        if err < tol:
            R, P, done, step = R2, P2, s, min(0.5, step * 2)
        else:
            step /= 2
    return R, P, (err if done < 1.0 else 0.0), r, names


def _reference_inputs(linkage, clean) -> dict:
    """The values the inputs take in the reference pose (zero for joints, the drawn point for ports)."""
    ports = {p.name: p for p in linkage.ports}
    out = {}
    for name, value in clean.items():
        port = ports.get(name)
        out[name] = list(port.point) if port is not None and port.kind == "load" else [0.0] * len(value)
    return out


def _fmt(v) -> str:
    return "[" + ", ".join(f"{x:.6g}" for x in v) + "]" if len(v) > 1 else f"{v[0]:.6g}"
