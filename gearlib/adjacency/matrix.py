"""Penaud and Alazard's complex-weighted adjacency matrix and its null space.

The table ``T`` of links and joints has ``T(i, j) = "p"`` for a turning pair and
``T(i, j) = N_i e^{i theta_i}`` for a gear pair; each gear pair ``(i, j)`` with carrier
``k`` adds a row to ``M`` with ``M[l, i] = T(i, j)``, ``M[l, j] = T(j, i)`` and
``M[l, k] = -T(i, j) - T(j, i)``: the Willis equation with a complex ratio
``e_{i,j} = -T(i,j)/T(j,i)``. Every speed vector lies in ``Ker M``.

Two traps (chapter 4 and the book's :ref:`notes on the sources <sources-pa>`): ``Ker M``
always contains ``[1, ..., 1]`` (the whole mechanism turning as one body), so with one link
grounded the degrees of freedom are ``N - rank(M) - 1``; and a null-space basis is not
unique, so compare normalised speed ratios (or subspaces, :func:`same_subspace`), never raw basis columns. Derived in chapter 4.

>>> import gearlib as gl
>>> diff = gl.catalog.car_differential()
>>> M = gl.adjacency_matrix(diff)
>>> M.shape, int(np.linalg.matrix_rank(M))
((5, 7), 4)
>>> W = gl.speed_ratio_matrix(diff, zero_speed=[1], normalize_to=[3, 4])
>>> np.round(W[[1, 6]].real, 6).tolist()
[[-2.5, -2.5], [0.5, 0.5]]
>>> print(gl.direction(W[4, 0]))
0.860233∠54.4623°
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import sympy

from .._common.matview import MatrixView, format_entry, polar_text
from ..errors import ConstraintError, DataFormatError, InputError
from ..mechanism.data import Mechanism
from ..mechanism.data import requires_mechanism

__all__ = [
    "link_table",
    "adjacency_matrix",
    "null_space",
    "reduced_basis",
    "same_subspace",
    "constraint_rows",
    "speed_ratio_matrix",
    "Direction",
    "direction",
    "show_link_table",
    "show_matrix",
    "MatrixView",
    "format_entry",
]


@requires_mechanism
def link_table(mech: Mechanism) -> dict:
    """Penaud's table ``T``: ``{(i, j): "p" or T(i, j)}`` for every turning and gear pair.

    >>> T = gl.link_table(gl.catalog.load("penaud_example_1"))
    >>> T[(1, 3)], T[(3, 1)], T[(4, 3)]
    (15*exp(I*pi/4), 10*exp(-I*pi/12), 'p')
    """
    T = {}
    for tp in mech.turning_pairs:
        a, b = tp.links
        T[(a, b)] = T[(b, a)] = "p"
    for gp in mech.gear_pairs:
        a, b = gp.gears
        ta, tb = gp.weights
        T[(a, b)], T[(b, a)] = ta, tb
    return T


@requires_mechanism
def adjacency_matrix(mech: Mechanism, *, exact: bool = False):
    """The adjacency matrix ``M`` (one row per gear pair, one column per link).

    A complex numpy array, or a sympy Matrix with ``exact=True``. Rows follow
    ``mech.gear_pairs``, columns ``mech.link_ids``.
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
    return np.array([[0j if v == 0 else complex(sympy.N(v, 20)) for v in row] for row in rows], dtype=complex)


def _matrix(A, what: str) -> np.ndarray:
    """*A* as a 2-D numeric array (a 1-D array is one row), finite; else a DataFormatError."""
    try:
        A = np.asarray(A)
    except (ValueError, TypeError):
        raise DataFormatError(f"{what}: expected a matrix of numbers (rows of equal length)") from None
    if A.dtype == object or A.dtype.kind not in "biufc":
        try:
            A = A.astype(complex if A.dtype == object else float)
            if A.dtype == complex and not np.iscomplex(A).any():
                A = A.real
        except (ValueError, TypeError):
            raise DataFormatError(f"{what}: expected a matrix of numbers, got entries of type {A.dtype}") from None
    if A.ndim > 2:
        raise DataFormatError(f"{what}: expected a matrix (2 dimensions), got an array of shape {A.shape}")
    A = np.atleast_2d(A)
    if A.dtype.kind in "fc" and not np.isfinite(A).all():
        i, j = np.argwhere(~np.isfinite(A))[0]
        raise DataFormatError(f"{what}: entry ({i}, {j}) is {A[i, j]}; every entry must be a finite number")
    return A


def _tolerance(value, what: str) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating)) or not 0 <= value < 1:
        raise DataFormatError(f"{what}: a relative tolerance is a number in [0, 1), such as 1e-10; got {value!r}")


def null_space(A: np.ndarray, rtol: float = 1e-10, *, basis: str = "orthonormal") -> np.ndarray:
    """A basis of ``Ker A`` (as columns).

    ``basis="orthonormal"`` (the default) is the basis from the singular value decomposition,
    what MATLAB's ``null`` returns; it is unique only up to a unitary change of basis.
    ``basis="reduced"`` is the stable basis of :func:`reduced_basis`: it depends on ``A`` alone.

    >>> K = gl.null_space(np.array([[1.0, -1.0, 0.0]]), basis="reduced")
    >>> K.round(12).tolist()
    [[1.0, 0.0], [1.0, 0.0], [0.0, 1.0]]
    """
    if basis not in ("orthonormal", "reduced"):
        raise DataFormatError(f"basis must be 'orthonormal' or 'reduced', got {basis!r}")
    A = _matrix(A, "A")
    _tolerance(rtol, "rtol")
    n = A.shape[1]
    if A.shape[0] == 0:
        K = np.eye(n, dtype=A.dtype if np.iscomplexobj(A) else float)
    else:
        _, s, vh = np.linalg.svd(A)
        tol = rtol * max(1.0, s[0] if s.size else 0.0)
        rank = int((s > tol).sum())
        K = vh[rank:].conj().T
        if not np.iscomplexobj(A):
            K = K.real
    if basis == "reduced":
        K, _ = reduced_basis(K)
    return K


def reduced_basis(K: np.ndarray, rtol: float = 1e-9) -> tuple[np.ndarray, list[int]]:
    """The basis of the column space of *K* that is the identity on its first independent rows.

    Rows (links) are taken in order; a row joins the *pivots* when it is independent of the
    rows already chosen. Then ``B = K (K[pivots, :])^{-1}``: column ``k`` is the speed vector
    with link ``pivots[k]`` at 1 and the other pivot links still. Any basis of the same
    subspace gives the same ``B``, so this is the basis to print or compare.

    >>> K = np.array([[1.0, 1.0], [2.0, 0.0], [0.0, 3.0]]) @ np.array([[0.6, 0.8], [-0.8, 0.6]])
    >>> B, pivots = gl.reduced_basis(K)
    >>> pivots, B.round(12).tolist()
    ([0, 1], [[1.0, 0.0], [0.0, 1.0], [3.0, -1.5]])
    """
    K = _matrix(K, "K")
    _tolerance(rtol, "rtol")
    d = K.shape[1]
    pivots: list[int] = []
    if d == 0:
        return K.copy(), pivots
    scale = max(1.0, float(np.abs(K).max()))
    for i in range(K.shape[0]):
        trial = K[pivots + [i], :]
        s = np.linalg.svd(trial, compute_uv=False)
        if s[-1] > rtol * scale:
            pivots.append(i)
            if len(pivots) == d:
                break
    if len(pivots) < d:
        raise ConstraintError(f"the basis has {d} columns but only {len(pivots)} independent rows")
    return _clean(K @ np.linalg.inv(K[pivots, :])), pivots


def _clean(B: np.ndarray) -> np.ndarray:
    """Round-off below 1e-13 of the largest entry becomes 0, in the real and imaginary parts
    separately; a complex result with no imaginary part stays complex (the dtype of ``M``)."""
    B = np.array(B)
    scale = 1e-13 * max(1.0, float(np.abs(B).max(initial=0.0)))
    if np.iscomplexobj(B):
        B.real[np.abs(B.real) < scale] = 0.0
        B.imag[np.abs(B.imag) < scale] = 0.0
    else:
        B[np.abs(B) < scale] = 0.0
    return B


def same_subspace(K1: np.ndarray, K2: np.ndarray, tol: float = 1e-9) -> bool:
    """True when the columns of *K1* and *K2* span the same subspace (compared by projectors).

    >>> K = np.array([[1.0], [2.0]])
    >>> gl.same_subspace(K, -3 * K), gl.same_subspace(K, np.array([[2.0], [1.0]]))
    (True, False)
    """
    K1, K2 = _matrix(K1, "K1"), _matrix(K2, "K2")
    _tolerance(tol, "tol")
    if K1.shape[0] != K2.shape[0]:
        return False

    def projector(K):
        if K.size == 0:
            return np.zeros((K.shape[0], K.shape[0]))
        U, s, _ = np.linalg.svd(K, full_matrices=False)
        Q = U[:, : int((s > 1e-10 * max(1.0, s[0])).sum())]
        return Q @ Q.conj().T

    return bool(np.abs(projector(K1) - projector(K2)).max(initial=0.0) <= tol)


@requires_mechanism
def constraint_rows(mech: Mechanism, *, zero_speed=(), equal=()) -> np.ndarray:
    """Penaud's constraint rows ``C`` (``C Omega = 0``): a 1 in the column of each link of
    ``zero_speed`` (a held link), and ``+1, -1`` for each pair of links in ``equal``.

    >>> gl.constraint_rows(gl.catalog.load("penaud_example_1"), zero_speed=[1], equal=[(2, 4)]).tolist()
    [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, -1.0]]
    """
    ix = mech.index
    n = len(mech.links)
    if isinstance(zero_speed, (str, int)):
        zero_speed = [zero_speed]
    rows = []
    for z in zero_speed:
        row = np.zeros(n)
        row[ix[mech.resolve(z, "zero_speed link")]] = 1
        rows.append(row)
    for pair in equal:
        if isinstance(pair, (str, bytes)) or not isinstance(pair, Sequence) or len(pair) != 2:
            raise DataFormatError(f"equal: each item must be a pair of links (u, v), got {pair!r}")
        u, v = (mech.resolve(x, "equal-speed link") for x in pair)
        if u == v:
            raise ConstraintError(f"equal: the pair ({u}, {v}) names one link twice; give two different links")
        row = np.zeros(n)
        row[ix[u]], row[ix[v]] = 1, -1
        rows.append(row)
    return np.array(rows).reshape(len(rows), n)


@requires_mechanism
def speed_ratio_matrix(mech: Mechanism, *, zero_speed=(), normalize_to=(), equal=(),
                       basis: str = "orthonormal") -> np.ndarray:
    """Penaud's speed-ratio matrix ``Omega_0`` (links x degrees of freedom): ``Ker [M; C]``.

    Parameters
    ----------
    zero_speed : links whose speed is set to zero (rows ``C`` with a 1 in that column).
    normalize_to : links ``r`` (one per degree of freedom): ``Omega_0 = K (K[r, :])^{-1}``,
        so that column ``k`` is the speed vector when link ``r_k`` turns at 1 and the others
        in ``normalize_to`` are still. Then every speed vector is ``Omega_0 @ Lambda`` with
        ``Lambda`` the speeds of the links ``r`` (Penaud's eq. (5)).
    equal : pairs of links constrained to equal speeds.
    basis : ``"orthonormal"`` or ``"reduced"``, the basis returned when ``normalize_to`` is
        empty (see :func:`null_space`).

    Raises
    ------
    InputError
        ``normalize_to`` does not name one independent link per degree of freedom.

    Examples
    --------
    >>> ex1 = gl.catalog.load("penaud_example_1")
    >>> W = gl.speed_ratio_matrix(ex1, zero_speed=[1], normalize_to=[2])
    >>> [str(gl.direction(w)) for w in W[:3, 0]]  # links 1, 2 and 3
    ['0', '1', '1.36216∠36.5868°']
    """
    M = adjacency_matrix(mech)
    C = constraint_rows(mech, zero_speed=zero_speed, equal=equal)
    A = np.vstack([M, C]) if C.size else M
    K = null_space(A, basis="orthonormal" if normalize_to else basis)
    if isinstance(normalize_to, (str, int)):
        normalize_to = [normalize_to]
    if not normalize_to:
        return K
    r = [mech.index[mech.resolve(x, "normalize_to link")] for x in normalize_to]
    d = K.shape[1]
    if len(r) != d:
        held = f" with links {list(zero_speed)} held" if zero_speed else ""
        raise InputError(
            f"{mech.name!r} has {d} degree{'s' if d != 1 else ''} of freedom in Ker[M; C]{held}, so "
            f"normalize_to needs {d} link(s), one per degree of freedom; got {len(r)} ({list(normalize_to)})"
        )
    R = K[r, :]
    s = np.linalg.svd(R, compute_uv=False)
    if s[-1] <= 1e-10 * max(1.0, s[0]):
        raise InputError(
            f"normalize_to links {list(normalize_to)} are not independent (their speeds are tied by the gear "
            "pairs and constraints); normalise to other links"
        )
    return _clean(K @ np.linalg.inv(R))


# ---------------------------------------------------------------------------- directions
@dataclass(frozen=True)
class Direction:
    """A complex speed read as a vector in the plane of the axes: ``magnitude`` and
    ``angle`` (radians, counter-clockwise from the real axis)."""

    magnitude: float
    angle: float

    @property
    def degrees(self) -> float:
        return math.degrees(self.angle)

    def __str__(self) -> str:
        """``r∠phi°``, the book's polar form (the angle in degrees)."""
        if self.magnitude == 0:
            return "0"
        return polar_text(cmath.rect(self.magnitude, self.angle), 6)


def direction(z, tol: float = 1e-12) -> Direction:
    """Magnitude and direction of a complex speed (Penaud's ``|omega| e^{i phi}``).

    The angle is measured in the plane that holds the axes of the links compared; it is
    meaningful only between links whose axes share that plane (chapter 4, caveat 4).

    >>> d = gl.direction(-2j)
    >>> d.magnitude, round(d.degrees, 9)
    (2.0, -90.0)
    """
    try:
        z = complex(z)
    except (TypeError, ValueError, OverflowError):
        raise DataFormatError(f"direction: expected a (complex) number, got {z!r}"[:200]) from None
    if not cmath.isfinite(z):
        raise DataFormatError(f"direction: expected a finite number, got {z}")
    r = abs(z)
    if r <= tol:
        return Direction(0.0, 0.0)
    phi = cmath.phase(z)
    if abs(z.imag) <= tol * r:
        phi = 0.0 if z.real > 0 else math.pi
    return Direction(r, phi)


# ---------------------------------------------------------------------------- display
@requires_mechanism
def show_link_table(mech: Mechanism) -> MatrixView:
    """Penaud's table ``T`` as a readable N x N table: ``(p)`` for a turning pair, the
    complex weight ``N e^{i theta}`` for a gear pair, empty otherwise."""
    T = link_table(mech)
    ids = mech.link_ids
    entries = [[("(p)" if T[(i, j)] == "p" else format_entry(T[(i, j)])) if (i, j) in T else "" for j in ids]
               for i in ids]
    return MatrixView(f"table T of {mech.name}", [str(i) for i in ids], [str(j) for j in ids], entries)


def show_matrix(A, *, rows=None, cols=None, title: str = "", style: str = "exact", digits: int = 4) -> MatrixView:
    """A matrix shown with labelled rows and columns (text, HTML and LaTeX in a notebook).

    *A* is a :class:`~gearlib.Mechanism` (its matrix ``M``, rows labelled ``(i, j)/k``) or an
    array. ``style="exact"`` keeps ``N e^{i theta}`` terms where they are known;
    ``style="polar"`` writes every entry as ``r∠phi°`` (the angle in degrees).

    >>> print(gl.show_matrix(np.array([[1, -2j]]), rows=["r"], cols=["a", "b"], style="polar"))
       a         b
    r  1  2∠-90°
    """
    if isinstance(A, Mechanism):
        mech = A
        exact = adjacency_matrix(mech, exact=True) if style == "exact" else adjacency_matrix(mech)
        rows = rows or [f"{gp.label}/{gp.carrier}" for gp in mech.gear_pairs]
        cols = cols or [str(i) for i in mech.link_ids]
        title = title or f"adjacency matrix M of {mech.name}"
        A = exact
    if isinstance(A, sympy.MatrixBase):
        data = [[A[i, j] for j in range(A.shape[1])] for i in range(A.shape[0])]
    else:
        arr = np.atleast_2d(np.asarray(A))
        data = arr.tolist()
    n_rows, n_cols = len(data), (len(data[0]) if data else 0)
    rows = [str(r) for r in (rows or range(1, n_rows + 1))]
    cols = [str(c) for c in (cols or range(1, n_cols + 1))]
    if len(rows) != n_rows or len(cols) != n_cols:
        raise DataFormatError(f"show_matrix: {len(rows)} row and {len(cols)} column labels for a "
                              f"{n_rows} x {n_cols} matrix")
    entries = [[format_entry(v, style=style, digits=digits) for v in row] for row in data]
    return MatrixView(title, rows, cols, entries)
