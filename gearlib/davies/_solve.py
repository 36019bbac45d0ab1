"""Linear algebra for Davies networks: exact (sympy domains) or floating point (numpy).

Exact matrices are solved with :class:`sympy.polys.matrices.DomainMatrix`, which picks the
smallest domain (rationals, an algebraic field, or rational functions of symbols such as the
radii and the friction coefficients) and is far faster than solving ``sympy.Matrix`` objects.
"""

from __future__ import annotations

import numpy as np
import sympy
from sympy.polys.matrices import DomainMatrix

__all__ = ["nullspace", "solve", "rank"]


def _domain(matrix: sympy.Matrix):
    return DomainMatrix.from_Matrix(matrix).to_field()


def rank(matrix, exact: bool) -> int:
    if exact:
        if matrix.rows == 0 or matrix.cols == 0:
            return 0
        return _domain(matrix).rank()
    if matrix.size == 0:
        return 0
    return int(np.linalg.matrix_rank(matrix, tol=1e-9 * max(1.0, np.abs(matrix).max())))


def nullspace(matrix, exact: bool):
    """A basis of the null space as a list of column vectors (sympy) or a 2-D array (columns)."""
    if exact:
        if matrix.rows == 0:
            return [sympy.eye(matrix.cols)[:, j] for j in range(matrix.cols)]
        basis = _domain(matrix).nullspace().to_Matrix()
        return [basis[i, :].T for i in range(basis.rows)]
    if matrix.shape[0] == 0:
        return np.eye(matrix.shape[1])
    _, s, vt = np.linalg.svd(matrix)
    tol = 1e-9 * max(1.0, s.max() if s.size else 1.0)
    r = int((s > tol).sum())
    return vt[r:].T


def solve(matrix, rhs, exact: bool, what: str = "system"):
    """The unique solution of ``matrix x = rhs``; raises ValueError naming *what* when the
    solution is not unique or does not exist."""
    n = matrix.shape[1]
    if exact:
        aug = sympy.Matrix(matrix).row_join(sympy.Matrix(rhs))
        dm = DomainMatrix.from_Matrix(aug)
        rref, den, pivots = dm.rref_den()  # fraction-free: fast over polynomial rings
        if n in pivots:
            raise ValueError(f"the {what} has no solution")
        if len(pivots) < n:
            raise ValueError(f"the {what} leaves {n - len(pivots)} unknown(s) undetermined")
        dom = rref.domain
        den = dom.to_sympy(den)
        x = [None] * n
        for i, j in enumerate(pivots):
            x[j] = dom.to_sympy(rref[i, n].element) / den  # not cancelled: callers cancel what they use
        return x
    a = np.asarray(matrix, dtype=float)
    b = np.asarray(rhs, dtype=float).reshape(-1)
    # equilibrate the columns (lengths and forces differ by orders of magnitude), then solve
    scale = np.abs(a).max(axis=0)
    scale[scale == 0] = 1.0
    a_s = a / scale
    x, _, r, sv = np.linalg.lstsq(a_s, b, rcond=None)
    if r < n or (sv.size and sv[-1] < 1e-10 * sv[0]):
        raise ValueError(f"the {what} leaves {n - r} unknown(s) undetermined")
    for _ in range(2):  # iterative refinement: the residual to machine precision
        x = x + np.linalg.lstsq(a_s, b - a_s @ x, rcond=None)[0]
    if np.abs(a_s @ x - b).max() > 1e-8 * max(1.0, np.abs(b).max()):
        raise ValueError(f"the {what} has no solution")
    return x / scale
