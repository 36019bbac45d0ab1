"""Penaud and Alazard's complex-weighted adjacency matrix and its null space.

The table ``T`` of links and joints has ``T(i, j) = "p"`` for a turning pair and
``T(i, j) = N_i e^{i theta_i}`` for a gear pair; each gear pair ``(i, j)`` with carrier
``k`` adds a row to ``M`` with ``M[l, i] = T(i, j)``, ``M[l, j] = T(j, i)`` and
``M[l, k] = -T(i, j) - T(j, i)``: the Willis equation with a complex ratio
``e_{i,j} = -T(i,j)/T(j,i)``. Every speed vector lies in ``Ker M``.

Two traps (``seed-notes`` section 6): ``Ker M`` always contains ``[1, ..., 1]`` (the whole
mechanism turning as one body), so with one link grounded the degrees of freedom are
``N - rank(M) - 1``; and a null-space basis is not unique, so compare normalised speed
ratios, never raw basis columns. Derived in chapter 4.

>>> import gearlib as gl
>>> diff = gl.catalog.car_differential()
>>> M = gl.adjacency_matrix(diff)
>>> M.shape, int(np.linalg.matrix_rank(M))
((5, 7), 4)
>>> W = gl.speed_ratio_matrix(diff, zero_speed=[1], normalize_to=[3, 4])
>>> np.round(W[[1, 6]].real, 6).tolist()
[[-2.5, -2.5], [0.5, 0.5]]
"""

from __future__ import annotations

import numpy as np
import sympy

from .errors import ConstraintError, InputError
from .mechanism import Mechanism

__all__ = ["link_table", "adjacency_matrix", "null_space", "speed_ratio_matrix"]


def link_table(mech: Mechanism) -> dict:
    """Penaud's table ``T``: ``{(i, j): "p" or T(i, j)}`` for every turning and gear pair."""
    T = {}
    for tp in mech.turning_pairs:
        a, b = tp.links
        T[(a, b)] = T[(b, a)] = "p"
    for gp in mech.gear_pairs:
        a, b = gp.gears
        ta, tb = gp.weights
        T[(a, b)], T[(b, a)] = ta, tb
    return T


def adjacency_matrix(mech: Mechanism, *, exact: bool = False):
    """The adjacency matrix ``M`` (one row per gear pair, one column per link).

    A complex numpy array, or a sympy Matrix with ``exact=True``.
    """
    n = len(mech.links)
    ix = mech.index
    rows = []
    for gp in mech.gear_pairs:
        if gp.e.free_symbols and not exact:
            raise ConstraintError(
                f"gear pair {gp.label} has a symbolic ratio {gp.e}; substitute numbers (or use exact=True)"
            )
        ta, tb = gp.weights
        row = [sympy.Integer(0)] * n
        a, b = gp.gears
        row[ix[a]] += ta
        row[ix[b]] += tb
        row[ix[gp.carrier]] += -ta - tb
        rows.append(row)
    if exact:
        return sympy.Matrix(rows) if rows else sympy.zeros(0, n)
    if not rows:
        return np.zeros((0, n), dtype=complex)
    return np.array([[complex(sympy.N(v, 20)) for v in row] for row in rows], dtype=complex)


def null_space(A: np.ndarray, rtol: float = 1e-10) -> np.ndarray:
    """An orthonormal basis of ``Ker A`` (columns), from the singular value decomposition."""
    A = np.atleast_2d(np.asarray(A))
    n = A.shape[1]
    if A.shape[0] == 0:
        return np.eye(n, dtype=A.dtype if np.iscomplexobj(A) else float)
    _, s, vh = np.linalg.svd(A)
    tol = rtol * max(1.0, s[0] if s.size else 0.0)
    rank = int((s > tol).sum())
    K = vh[rank:].conj().T
    if not np.iscomplexobj(A):
        K = K.real
    return K


def speed_ratio_matrix(mech: Mechanism, *, zero_speed=(), normalize_to=(), equal=()) -> np.ndarray:
    """Penaud's speed-ratio matrix ``Omega_0`` (links x degrees of freedom).

    Parameters
    ----------
    zero_speed : links whose speed is set to zero (rows ``C`` with a 1 in that column).
    normalize_to : links ``r`` (one per degree of freedom): ``Omega_0 = K (K[r, :])^{-1}``,
        so that column ``k`` is the speed vector when link ``r_k`` turns at 1 and the others
        in ``normalize_to`` are still.
    equal : pairs of links constrained to equal speeds.
    """
    ix = mech.index
    M = adjacency_matrix(mech)
    extra = []
    for z in zero_speed:
        row = np.zeros(len(mech.links))
        row[ix[mech.resolve(z)]] = 1
        extra.append(row)
    for u, v in equal:
        row = np.zeros(len(mech.links))
        row[ix[mech.resolve(u)]] = 1
        row[ix[mech.resolve(v)]] = -1
        extra.append(row)
    A = np.vstack([M] + [np.atleast_2d(r) for r in extra]) if extra else M
    K = null_space(A)
    if not normalize_to:
        return K
    r = [ix[mech.resolve(x)] for x in normalize_to]
    if len(r) != K.shape[1]:
        raise InputError(
            f"normalize_to needs {K.shape[1]} link(s), one per degree of freedom; got {len(r)}"
        )
    R = K[r, :]
    if np.linalg.matrix_rank(R) < len(r):
        raise InputError(f"links {list(normalize_to)} are not independent; normalise to other links")
    return K @ np.linalg.inv(R)
