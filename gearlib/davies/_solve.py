"""Linear algebra for Davies networks: exact (sympy domains) or floating point (numpy).

Exact matrices are solved with :class:`sympy.polys.matrices.DomainMatrix`, which picks the
smallest domain (rationals, an algebraic field, or rational functions of symbols such as the
radii and the friction coefficients) and is far faster than solving ``sympy.Matrix`` objects.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import sympy
from sympy.polys.matrices import DomainMatrix

__all__ = ["nullspace", "solve", "rank", "ExactSolution"]


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


class ExactSolution(Sequence):
    """The exact solution of a linear system, ``x_k = numerator_k / denominator`` in the
    domain the solver picked (integers, or polynomials in the friction coefficients). It
    reads like a tuple of sympy expressions (not cancelled: callers cancel what they use),
    each converted when first read: a formula needs two of them, and converting every
    polynomial back to a sympy expression was most of the time of a symbolic solve."""

    def __init__(self, domain, numerators: tuple, denominator):
        self.domain, self.numerators, self.denominator = domain, numerators, denominator
        self._exprs: dict = {}

    def __len__(self) -> int:
        return len(self.numerators)

    def __getitem__(self, k):
        if isinstance(k, slice):
            return tuple(self[i] for i in range(*k.indices(len(self))))
        if k < 0:
            k += len(self)
        if k not in self._exprs:
            to = self.domain.to_sympy
            self._exprs[k] = to(self.numerators[k]) / to(self.denominator)
        return self._exprs[k]

    def __eq__(self, other):
        return isinstance(other, Sequence) and tuple(self) == tuple(other)

    def __hash__(self):
        return hash(tuple(self))

    def __repr__(self) -> str:
        return repr(tuple(self))


def _few_symbols(A: sympy.Matrix, b: sympy.Matrix, most: int = 12):
    """Solve ``A x = b`` when only a few entries of *A* hold a symbol, each as ``c * symbol``
    with a symbol of its own (a friction row ``T_f - zeta U = 0`` of a lossy action
    analysis), by the Woodbury identity; None when that does not apply (then the caller
    eliminates the whole system).

    Write ``A = A0 + U Z V^T``: ``A0`` is *A* with those entries zero, ``Z`` holds the entries
    and ``U``, ``V`` pick their rows and columns. With ``[x0, W] = A0^-1 [b, U]`` (rational
    numbers only) the solution is ``x = x0 - W y`` where ``(I + Z V^T W) y = Z V^T x0`` is a
    system of one unknown per symbolic entry. The big elimination then runs over the
    rationals, and only the small one over polynomials in the symbols.
    """
    rows, cols = A.shape
    if rows != cols or b.free_symbols:
        return None
    entries = []
    for (r, c), value in A.todok().items():
        if value.free_symbols:
            coef, sym = value.as_coeff_Mul()
            if not (sym.is_Symbol and coef.is_Rational):
                return None
            entries.append((r, c, coef, sym))
    k = len(entries)
    if not entries or k > most or len({sym for *_, sym in entries}) < k:
        # each symbol in one entry only (a friction coefficient meets one row): then every
        # solution is multilinear in the symbols, as the formula's fast factoring expects
        return None
    A0 = A.copy()
    for r, c, _, _ in entries:
        A0[r, c] = 0
    units = sympy.zeros(rows, k)
    for e, (r, _, _, _) in enumerate(entries):
        units[r, e] = 1
    dm = DomainMatrix.from_Matrix(A0.row_join(b).row_join(units)).convert_to(sympy.QQ)
    rref, den, pivots = dm.rref_den()
    if tuple(pivots) != tuple(range(cols)):
        return None  # A0 is singular: the general elimination decides
    Q = sympy.QQ
    Y = [[Q.quo(rref[i, j].element, den) for j in range(cols, cols + 1 + k)] for i in range(rows)]
    symbols = sorted({sym for *_, sym in entries}, key=sympy.default_sort_key)
    dom = Q[tuple(symbols)]
    R = dom.ring
    z = [R(coef) * R.gens[symbols.index(sym)] for _, _, coef, sym in entries]
    cs = [c for _, c, _, _ in entries]
    # (I + Z V^T W) y = Z V^T x0
    M = [[(R.one if e == f else R.zero) + z[e] * Y[cs[e]][1 + f] for f in range(k)] + [z[e] * Y[cs[e]][0]]
         for e in range(k)]
    small, den2, piv2 = DomainMatrix(M, (k, k + 1), dom).rref_den()
    if tuple(piv2) != tuple(range(k)):
        return None
    ys = [small[e, k].element for e in range(k)]
    nums = tuple(Y[i][0] * den2 - sum((Y[i][1 + e] * ys[e] for e in range(k)), R.zero) for i in range(rows))
    return ExactSolution(dom, nums, den2)


def solve(matrix, rhs, exact: bool, what: str = "system"):
    """The unique solution of ``matrix x = rhs``; raises ValueError naming *what* when the
    solution is not unique or does not exist."""
    n = matrix.shape[1]
    if exact:
        A, b = sympy.Matrix(matrix), sympy.Matrix(rhs)
        low_rank = _few_symbols(A, b)
        if low_rank is not None:
            return low_rank
        dm = DomainMatrix.from_Matrix(A.row_join(b))
        rref, den, pivots = dm.rref_den()  # fraction-free: fast over polynomial rings
        if n in pivots:
            raise ValueError(f"the {what} has no solution")
        if len(pivots) < n:
            raise ValueError(f"the {what} leaves {n - len(pivots)} unknown(s) undetermined")
        nums = [None] * n
        for i, j in enumerate(pivots):
            nums[j] = rref[i, n].element
        return ExactSolution(rref.domain, tuple(nums), den)
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
