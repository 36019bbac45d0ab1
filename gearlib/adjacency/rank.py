"""Penaud and Alazard's count of the degrees of freedom: ``N - rank(M)`` (their eq. (4)).

Every row of the adjacency matrix ``M`` sums to zero, so the count includes the rotation of
the whole mechanism as one body; each constraint row (a held link, two links joined) that is
independent of the gear rows removes one freedom, so with one link held the count equals
:func:`gearlib.dof`. Derived in chapter 4.

>>> import gearlib as gl
>>> count = gl.adjacency_rank(gl.catalog.car_differential())
>>> count.rows, count.rank, count.dof
(5, 4, 3)
>>> gl.adjacency_rank(gl.catalog.car_differential(), zero_speed=[1]).dof
2
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..mechanism.data import Mechanism, requires_mechanism
from .matrix import adjacency_matrix, constraint_rows

__all__ = ["AdjacencyRank", "adjacency_rank"]


@dataclass(frozen=True)
class AdjacencyRank:
    """``links`` (N), ``rows`` of ``[M; C]``, their ``rank`` and ``dof = N - rank``."""

    links: int
    rows: int
    rank: int
    constraints: int = 0

    @property
    def dof(self) -> int:
        """``N - rank``: Penaud's eq. (4), the free rotation included unless a link is held."""
        return self.links - self.rank

    @property
    def redundant_rows(self) -> int:
        """Rows that repeat what the others impose (a second identical planet, say)."""
        return self.rows - self.rank

    def __int__(self) -> int:
        return self.dof

    __index__ = __int__


@requires_mechanism
def adjacency_rank(mech: Mechanism, *, zero_speed=(), equal=(), exact: bool = False,
                   rtol: float = 1e-10) -> AdjacencyRank:
    """The rank of Penaud's matrix ``M`` (with constraint rows ``C`` for ``zero_speed`` and
    ``equal`` links, as in :func:`gearlib.speed_ratio_matrix`) and ``N - rank``.

    The rank is that of the singular values above ``rtol`` times the largest (the tolerance
    :func:`gearlib.null_space` uses, so ``dof`` is the number of columns it returns), or the
    exact rank of the sympy matrix with ``exact=True`` (symbolic ratios need it).
    """
    C = constraint_rows(mech, zero_speed=zero_speed, equal=equal)
    n = len(mech.links)
    if exact:
        import sympy

        M = adjacency_matrix(mech, exact=True)
        A = M.col_join(sympy.Matrix(C.astype(int).tolist())) if C.size else M
        return AdjacencyRank(n, A.rows, int(A.rank(simplify=True)), C.shape[0])
    M = adjacency_matrix(mech)
    A = np.vstack([M, C]) if C.size else M
    if A.shape[0] == 0:
        return AdjacencyRank(n, 0, 0, 0)
    s = np.linalg.svd(A, compute_uv=False)
    rank = int((s > rtol * max(1.0, s[0])).sum())
    return AdjacencyRank(n, A.shape[0], rank, C.shape[0])
