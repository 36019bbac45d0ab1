"""The coupling graph G_C: links as vertices, couplings as directed edges.

Davies' method treats a machine as a network (Laus 2011, ch. 2). Each *link* is a vertex;
each *coupling* (a turning pair, a gear mesh, or an active coupling through which a motor
or a load acts) is an edge with a direction: its motion is the motion of the *head* link
relative to the *tail* link, and its action is the action applied to the head.

A spanning tree splits the edges into *branches* and *chords*. Each chord closes one
fundamental circuit (a row of the circuit matrix ``B``); each branch cuts one fundamental
cutset (a row of the cutset matrix ``Q``). ``Q B^T = 0``. The motion graph and the action
graph replicate each edge once per freedom and once per action (:func:`replicate`).

>>> import gearlib as gl
>>> g = gl.davies.CouplingGraph(nodes=(0, 1, 2), edges=(("A", 0, 1), ("B", 0, 2), ("C", 1, 2)))
>>> g.chords
('C',)
>>> g.circuit_matrix().tolist()
[[1, -1, 1]]
>>> g.cutset_matrix().tolist()
[[1, 0, -1], [0, 1, 1]]
>>> g.spanning_tree_count()
3
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
import sympy

from .._common.topology import UnionFind
from ..errors import DisconnectedError, InputError

__all__ = ["CouplingGraph", "replicate"]


@dataclass(frozen=True)
class CouplingGraph:
    """A directed multigraph: *nodes* (link ids) and *edges* ``(name, tail, head)``.

    Parameters
    ----------
    chords : names of the edges to use as chords (the rest form the spanning tree).
        Default: the tree takes the edges in order, skipping each edge that would close a
        loop (Laus's choice in all three gear examples).
    """

    nodes: tuple
    edges: tuple
    chords_wanted: tuple | None = field(default=None, compare=False)

    def __post_init__(self):
        names = [e[0] for e in self.edges]
        if len(set(names)) != len(names):
            raise InputError(f"coupling names must be unique, got {names}")
        known = set(self.nodes)
        for name, a, b in self.edges:
            if a not in known or b not in known:
                raise InputError(f"coupling {name} joins unknown link {a if a not in known else b}")

    # ------------------------------------------------------------------ basic counts
    @property
    def names(self) -> tuple:
        return tuple(e[0] for e in self.edges)

    @property
    def n(self) -> int:
        return len(self.nodes)

    @property
    def e(self) -> int:
        return len(self.edges)

    @property
    def l(self) -> int:  # noqa: E743  (Laus's symbol for the number of circuits)
        return self.e - self.n + 1

    @property
    def k(self) -> int:
        return self.n - 1

    def index(self, name) -> int:
        try:
            return self.names.index(name)
        except ValueError:
            raise InputError(f"no coupling {name!r}; couplings are {', '.join(self.names)}") from None

    # ------------------------------------------------------------------ incidence and tree
    def incidence_matrix(self) -> np.ndarray:
        """``a_ij = +1`` if edge j starts at node i, ``-1`` if it ends there (n x e, integers)."""
        pos = {x: i for i, x in enumerate(self.nodes)}
        a = np.zeros((self.n, self.e), dtype=int)
        for j, (_, t, h) in enumerate(self.edges):
            a[pos[t], j] += 1
            a[pos[h], j] -= 1
        return a

    def reduced_incidence(self, reference) -> np.ndarray:
        """The incidence matrix without the row of the *reference* link (Laus's ``A_i``)."""
        keep = [i for i, x in enumerate(self.nodes) if x != reference]
        if len(keep) == self.n:
            raise InputError(f"link {reference} is not a vertex of the coupling graph")
        return self.incidence_matrix()[keep, :]

    def pseudo_inverse(self, reference) -> sympy.Matrix:
        """``A_i^+ = A_i^T (A_i A_i^T)^-1`` in exact rationals (Laus, eq. 7)."""
        a = sympy.Matrix(self.reduced_incidence(reference))
        return a.T * (a * a.T).inv()

    def spanning_tree_count(self) -> int:
        """Number of spanning trees, ``det(A_i A_i^T)`` (Kirchhoff's matrix-tree theorem)."""
        a = sympy.Matrix(self.reduced_incidence(self.nodes[0]))
        return int((a * a.T).det())

    @cached_property
    def _tree(self) -> tuple[tuple, tuple]:
        uf = UnionFind(self.nodes)
        wanted = set(self.chords_wanted or ())
        unknown = wanted - set(self.names)
        if unknown:
            raise InputError(f"chords {sorted(unknown)} are not couplings; couplings are {', '.join(self.names)}")
        branches, chords = [], []
        for name, t, h in self.edges:
            if name in wanted:
                continue
            (branches if uf.union(t, h) else chords).append(name)
        for name, t, h in self.edges:
            if name in wanted:
                if uf.union(t, h):
                    raise InputError(f"the chords {sorted(wanted)} leave no spanning tree: {name} is needed in the tree")
                chords.append(name)
        if len(branches) != self.n - 1:
            raise DisconnectedError("the coupling graph is not connected")
        order = {x: i for i, x in enumerate(self.names)}
        return tuple(sorted(branches, key=order.get)), tuple(sorted(chords, key=order.get))

    @property
    def branches(self) -> tuple:
        return self._tree[0]

    @property
    def chords(self) -> tuple:
        return self._tree[1]

    def tree_path(self, start, goal) -> list[tuple]:
        """Edges ``(name, sign)`` on the tree path from link *start* to link *goal*; the sign
        is +1 where the edge points along the path."""
        adj: dict = {x: [] for x in self.nodes}
        for name, t, h in self.edges:
            if name in self.branches:
                adj[t].append((h, name, 1))
                adj[h].append((t, name, -1))
        prev = {start: None}
        stack = [start]
        while stack:
            x = stack.pop()
            for y, name, sign in adj[x]:
                if y not in prev:
                    prev[y] = (x, name, sign)
                    stack.append(y)
        if goal not in prev:
            raise InputError(f"link {goal} is not connected to link {start}")
        path = []
        y = goal
        while prev[y] is not None:
            x, name, sign = prev[y]
            path.append((name, sign))
            y = x
        return path[::-1]

    def circuit_matrix(self) -> np.ndarray:
        """Fundamental circuit matrix ``B`` (l x e): one row per chord, traversed in the chord's
        direction; +1 for edges pointing along the traversal."""
        idx = {x: i for i, x in enumerate(self.names)}
        b = np.zeros((self.l, self.e), dtype=int)
        for row, chord in enumerate(self.chords):
            _, t, h = self.edges[idx[chord]]
            b[row, idx[chord]] = 1
            for name, sign in self.tree_path(h, t):  # back from head to tail through the tree
                b[row, idx[name]] += sign
        return b

    def cutset_matrix(self) -> np.ndarray:
        """Fundamental cutset matrix ``Q`` (k x e): one row per branch; +1 for edges crossing the
        cut in the branch's sense. Built as ``Q = [I | -B_t^T]`` so that ``Q B^T = 0``."""
        idx = {x: i for i, x in enumerate(self.names)}
        b = self.circuit_matrix()
        q = np.zeros((self.k, self.e), dtype=int)
        for row, branch in enumerate(self.branches):
            j = idx[branch]
            q[row, j] = 1
            for crow, chord in enumerate(self.chords):
                q[row, idx[chord]] = -b[crow, j]
        return q


def replicate(matrix, counts) -> np.ndarray:
    """Column replication: column j of *matrix* repeated ``counts[j]`` times (``B_M = B X_M``,
    ``Q_A = Q X_A``)."""
    matrix = np.asarray(matrix)
    cols = [matrix[:, j] for j, c in enumerate(counts) for _ in range(c)]
    if not cols:
        return np.zeros((matrix.shape[0], 0), dtype=matrix.dtype)
    return np.stack(cols, axis=1)
