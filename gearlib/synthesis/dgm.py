"""Topological synthesis of non-fractionated differential geared mechanisms (DGMs).

Chen, Yao and Lee (2003) call a mechanism with ``n`` *terminals* (an input and outputs,
all turning about the ground) an n-terminal DGM when it has three characteristics:

* C1: one kinematic constraint ``sum a_i w_i = 0`` among the terminal speeds;
* C2: it has ``n - 1`` degrees of freedom;
* C3: every terminal is adjacent to (coaxial with) the ground.

For a non-fractionated chain these become N1 (the chain has ``n - 1`` dof and one of its
links is the ground), N2 (the ground is adjacent to at least ``n`` links) and N3 (every
non-terminal lies in at least two fundamental circuits). The constraint comes from the
fundamental circuit equations (matrix ``A`` of CYL eq. (6), :func:`gearlib.willis_matrix`
with the ground column deleted) by eliminating the non-terminal speeds; a non-terminal is
*redundant* when none of the gear ratios of its circuits (as a gear or as the carrier)
appears in the constraint. :func:`~gearlib.synthesis.identify` runs the whole procedure of Section 4.

The elimination is exact Gauss elimination over the field of rational functions of the
gear ratios (a sympy polynomial domain), about a hundred times faster than ``sympy.solve``.

>>> m = gl.catalog.load("cyl_gkc_5_7_2")
>>> c = gl.synthesis.terminal_constraint(m, (5, 6, 7), ground=4)
>>> c.equation
-e_2_1*e_6_2*omega_6 + e_5_1*omega_5 + e_7_3*omega_7*(e_2_1*e_6_2 - 1)
>>> c.admissible, c.redundant
(True, ())
"""

from __future__ import annotations

import functools
import itertools
import math
import numbers
from dataclasses import dataclass, field
from functools import cached_property

import sympy

from .._common import linalg as _linalg
from .._common.parse import parse_expr
from .atlas import canonical_graph, chain_problems, geared_chains, isomorphic
from ..mechanism.equations import omega
from ..errors import DataFormatError, InputError
from ..mechanism.data import Mechanism
from ..mechanism._accept import takes_mechanism

__all__ = [
    "adjacency", "circuit_matrix", "terminal_constraint", "TerminalConstraint", "identify",
    "Identification", "synthesize", "proportional",
]


def _ratio_symbols(gp) -> frozenset:
    return frozenset(gp.e.free_symbols) if gp.e.free_symbols else frozenset({gp.symbol})


@takes_mechanism
def adjacency(mech: Mechanism) -> dict:
    """``{link: links coaxial with it}``: the links a turning pair could join to each link
    once coaxial links are re-arranged (CYL's "adjacent according to the coaxial conditions").

    >>> gl.synthesis.adjacency(gl.catalog.load("cyl_gkc_5_7_2"))[4]
    (1, 3, 5, 6, 7)
    """
    ids = mech.link_ids
    return {u: tuple(v for v in ids if v != u and mech.coaxial(u, v)) for u in ids}


def circuit_matrix(mech: Mechanism, *, ground) -> tuple[sympy.Matrix, tuple]:
    """CYL's matrix ``A`` (eq. 6): one fundamental circuit equation per gear pair, row
    ``w_b - e w_a + (e - 1) w_c = 0`` with symbolic ratios, the ground column deleted.
    Returns the matrix and the link of each column.

    >>> A, cols = gl.synthesis.circuit_matrix(gl.catalog.load("cyl_standard_differential"), ground=0)
    >>> cols, A.row(2)
    ((1, 2, 3, 4, 5), Matrix([[1, 0, 0, 0, -e_5_1]]))
    """
    ground = mech.resolve(ground, "ground")
    from ..mechanism.equations import willis_matrix

    cols = tuple(x for x in mech.link_ids if x != ground)
    return willis_matrix(mech, symbolic=True, ground=ground), cols


def _subtract(row: dict, factor, pivot: dict, fld) -> None:
    """``row -= factor * pivot`` on sparse rows, dropping entries that become zero."""
    for k, v in pivot.items():
        new = row.get(k, fld.zero) - factor * v
        if fld.is_zero(new):
            row.pop(k, None)
        else:
            row[k] = new


def _size(x) -> tuple:
    try:
        return (0 if x.numer.is_ground and x.denom.is_ground else 1, len(x.numer) + len(x.denom))
    except AttributeError:
        return (0, 0)


@functools.lru_cache(maxsize=32)
def _domain_rows(mech: Mechanism):
    """The circuit equations over an exact field, all columns: ``(field, [{column: entry}])``."""
    from ..mechanism.equations import willis_matrix

    A = willis_matrix(mech, symbolic=True)
    fld, elems = _linalg.domain_for(list(A) or [sympy.Integer(0)])
    width = A.cols
    return fld, [{j: elems[i * width + j] for j in range(width) if not fld.is_zero(elems[i * width + j])}
                 for i in range(A.rows)]


def _eliminate(mech: Mechanism, ground, terminals) -> tuple[list, object]:
    """RREF rows (lists over the terminals, domain elements) of the terminal constraints."""
    fld, full = _domain_rows(mech)
    g = mech.index[ground]
    rows = [{j: v for j, v in r.items() if j != g} for r in full]  # the ground's speed is 0
    cols = tuple(x for x in mech.link_ids if x != ground)
    where = {x: mech.index[x] for x in cols}
    # eliminate the non-terminal speeds, each time the one in the fewest rows (least fill-in,
    # so the smallest fractions: Markowitz's rule); min keeps the first of equals, in link order
    left = [where[x] for x in cols if x not in terminals]
    while left:
        j = min(left, key=lambda c: sum(c in r for r in rows))
        left.remove(j)
        having = [r for r in rows if j in r]
        if not having:
            continue
        pivot = min(having, key=lambda r: _size(r[j]))
        rows = [r for r in rows if r is not pivot]
        for r in rows:
            if j in r:
                _subtract(r, r[j] / pivot[j], pivot, fld)
    out = []  # reduced row echelon form over the terminal columns
    for j in (where[t] for t in terminals):
        having = [r for r in rows if j in r]
        if not having:
            continue
        pivot = min(having, key=lambda r: _size(r[j]))
        rows = [r for r in rows if r is not pivot]
        inv = fld.inv(pivot[j])
        pivot = {k: v * inv for k, v in pivot.items()}
        for r in rows + out:
            if j in r:
                _subtract(r, r[j], pivot, fld)
        out.append(pivot)
    return [[r.get(where[t], fld.zero) for t in terminals] for r in out], fld


def _primitive(values: list, elems=None, dom=None) -> tuple:
    """Coefficients cleared of denominators and common factors, first non-zero one positive.

    With the row's domain elements *elems* of a fraction field over the integers (the usual
    case: symbolic ratios), the work is done in the polynomial ring (:func:`_primitive_ring`),
    which gives the same expressions many times faster; sympy expressions otherwise."""
    if elems is not None:
        fast = _primitive_ring(elems, dom)
        if fast is not None:
            return fast
    values = [sympy.cancel(v) for v in values]
    den = sympy.lcm_list([sympy.fraction(v)[1] for v in values])
    nums = [sympy.cancel(v * den) for v in values]
    common = sympy.gcd_list([n for n in nums if n != 0]) if any(n != 0 for n in nums) else 1
    nums = [sympy.expand(sympy.cancel(n / common)) for n in nums]
    lead = next(n for n in nums if n != 0)
    if sympy.Poly(lead, *sorted(lead.free_symbols, key=str) or [sympy.Symbol("x")]).LC() < 0:
        nums = [-n for n in nums]
    return tuple(sympy.factor(n) for n in nums)


def _primitive_ring(elems: list, dom) -> tuple | None:
    """:func:`_primitive` over ``ZZ[e_a_b]``: lcm of the denominators, gcd of the numerators,
    the sign of sympy's leading coefficient (lex order of the symbol names), each coefficient
    factored as :func:`sympy.factor` prints it. None when *dom* is not ``ZZ(...)``."""
    from sympy.polys.polyutils import _sort_gens

    from .._common.multilinear import factor_list

    if not (getattr(dom, "is_FractionField", False) and dom.domain.is_ZZ):
        return None
    ring = dom.field.ring
    den = ring.one
    for e in elems:
        den = den.lcm(e.denom)
    nums = [e.numer * den.exquo(e.denom) for e in elems]
    common = ring.zero
    for n in nums:
        common = common.gcd(n) if n else common
    if not common:
        return None
    nums = [n.exquo(common) for n in nums]
    def negative(p, order):  # the leading coefficient (lex, generators in this order) is < 0
        return p[max(p.itermonoms(), key=lambda m: tuple(m[i] for i in order))] < 0

    # the first coefficient is made positive with the symbols sorted by name (as _primitive
    # does); each factor gets the sign sympy.factor gives it, in sympy's generator order
    by_name = sorted(range(ring.ngens), key=lambda i: str(ring.symbols[i]))
    sympy_order = [ring.symbols.index(x) for x in _sort_gens(list(ring.symbols))]
    if negative(next(n for n in nums if n), by_name):
        nums = [-n for n in nums]
    out = []
    for n in nums:
        if not n:
            out.append(sympy.Integer(0))
            continue
        const, factors = factor_list(n)
        const = int(const)
        expr = sympy.Integer(1)
        for f, k in factors:
            if negative(f, sympy_order):
                f, const = -f, const * (-1) ** k
            expr *= f.as_expr() ** k
        out.append(const * expr)
    return tuple(out)


@dataclass(frozen=True)
class TerminalConstraint:
    """The kinematic constraint(s) among chosen terminals with a chosen ground, and CYL's
    screening: N3 failures, redundant links, admissibility."""

    mechanism: Mechanism = field(repr=False)
    ground: object
    terminals: tuple
    rows: tuple = field(repr=False)  # RREF rows over the terminals (sympy expressions)
    _domain_rows: tuple = field(default=None, repr=False, compare=False)  # the same, (domain, elements)

    @property
    def count(self) -> int:
        """Number of independent constraints among the terminals (C1 needs exactly one)."""
        return len(self.rows)

    @property
    def non_terminals(self) -> tuple:
        return tuple(x for x in self.mechanism.link_ids if x != self.ground and x not in self.terminals)

    @cached_property
    def coefficients(self) -> tuple | None:
        """``(a_1, ..., a_n)`` of ``sum a_i w_i = 0`` (polynomials in the ratios), or None
        unless there is exactly one constraint."""
        if self.count != 1:
            return None
        dom, elems = self._domain_rows if self._domain_rows is not None else (None, None)
        return _primitive(list(self.rows[0]), elems and elems[0], dom)

    @property
    def equation(self) -> sympy.Expr | None:
        """``sum a_i omega_i`` (equal to zero), or None unless there is exactly one constraint."""
        if self.coefficients is None:
            return None
        return sum(a * omega(t) for a, t in zip(self.coefficients, self.terminals))

    @cached_property
    def ratios(self) -> frozenset:
        """The gear-ratio symbols that appear in the constraint rows."""
        return frozenset().union(*(sympy.sympify(v).free_symbols for row in self.rows for v in row))

    def circuits_of(self, link) -> tuple:
        """The gear pairs whose fundamental circuit *link* belongs to (as a gear or the carrier)."""
        return tuple(gp for gp in self.mechanism.gear_pairs if link in gp.gears or link == gp.carrier)

    @property
    def n3_failures(self) -> tuple:
        """Non-terminals in fewer than two fundamental circuits (N3)."""
        return tuple(x for x in self.non_terminals if len(self.circuits_of(x)) < 2)

    @cached_property
    def redundant(self) -> tuple:
        """Non-terminals none of whose circuits' gear ratios appear in the constraint."""
        return tuple(x for x in self.non_terminals
                     if not any(_ratio_symbols(gp) & self.ratios for gp in self.circuits_of(x)))

    @property
    def missing_terminals(self) -> tuple:
        """Terminals whose coefficient is zero (they do not take part in the constraint)."""
        if self.count != 1:
            return ()
        return tuple(t for t, a in zip(self.terminals, self.rows[0]) if a == 0)

    @property
    def reasons(self) -> tuple:
        """Why this assignment is not an admissible DGM (empty when it is)."""
        out = []
        if self.count != 1:
            out.append(f"{self.count} constraints among the terminals, not one (C1)")
        if self.redundant:
            out.append("redundant links " + ", ".join(map(str, self.redundant)))
        if self.missing_terminals:
            out.append("terminals " + ", ".join(map(str, self.missing_terminals)) + " not in the constraint")
        return tuple(out)

    @property
    def admissible(self) -> bool:
        return not self.reasons

    def numeric(self, values=None) -> tuple | None:
        """The coefficients with the mechanism's own gear ratios put in for the symbols
        ``e_a_b`` (exact numbers for tooth numbers), or with *values* ``{symbol or (a, b): value}``
        where given; None unless there is exactly one constraint. Rational coefficients are
        scaled to the smallest whole numbers (the equation equals zero, so only their ratios
        count).

        >>> d = gl.catalog.load("cyl_standard_differential")
        >>> gl.synthesis.terminal_constraint(d, (1, 2, 3), ground=0).numeric()
        (2, 5, 5)
        """
        if self.coefficients is None:
            return None
        subs = {gp.symbol: gp.e for gp in self.mechanism.gear_pairs}
        for key, value in (values or {}).items():
            if isinstance(key, (tuple, list)):
                gp, sign = self.mechanism.gear_pair(*key)
                key, value = gp.symbol, parse_expr(value, f"values[{key}]") ** sign
            subs[sympy.Symbol(str(key))] = parse_expr(value, f"values[{key}]")
        nums = [sympy.simplify(sympy.sympify(a).xreplace(subs)) for a in self.coefficients]
        if all(x.is_Rational for x in nums) and any(nums):  # the smallest whole numbers, same ratios
            den = functools.reduce(sympy.ilcm, [x.q for x in nums], 1)
            whole = [int(x * den) for x in nums]
            g = functools.reduce(math.gcd, whole)
            nums = [sympy.Integer(w // g) for w in whole]
        return tuple(nums)

    def numeric_equation(self, values=None):
        """``sum a_i omega_i`` with the numbers of :meth:`numeric` (equal to zero)."""
        nums = self.numeric(values)
        if nums is None:
            return None
        return sum(a * omega(t) for a, t in zip(nums, self.terminals))

    def __str__(self) -> str:
        terms = ", ".join(map(str, self.terminals))
        head = f"ground {self.ground}, terminals {terms}: "
        if self.equation is not None:
            head += f"{self.equation} = 0"
        else:
            head += f"{self.count} constraints"
        return head + ("" if self.admissible else " (" + "; ".join(self.reasons) + ")")


@takes_mechanism
def terminal_constraint(mech: Mechanism, terminals, *, ground) -> TerminalConstraint:
    """Eliminate the non-terminal speeds from the fundamental circuit equations.

    Parameters
    ----------
    mech : Mechanism; numeric ratios are replaced by their symbols ``e_a_b`` (the
        redundancy test needs symbols).
    terminals : link ids (input and outputs), in the order of the coefficients.
    ground : the held link.

    >>> d = gl.catalog.load("cyl_standard_differential")
    >>> print(gl.synthesis.terminal_constraint(d, (1, 2, 3), ground=0))
    ground 0, terminals 1, 2, 3: -e_4_2*e_5_1*omega_3 + e_4_3*e_5_1*omega_2 + omega_1*(e_4_2 - e_4_3) = 0
    """
    if not isinstance(mech, Mechanism):
        raise DataFormatError(f"expected a gl.Mechanism, got {type(mech).__name__}")
    ground = mech.resolve(ground, "ground")
    if isinstance(terminals, (str, numbers.Integral)):
        terminals = (terminals,)
    terms = tuple(mech.resolve(t, "terminal") for t in terminals)
    if not terms:
        raise InputError("give at least one terminal")
    if len(set(terms)) != len(terms):
        raise InputError(f"terminals {', '.join(map(str, terms))} name a link twice")
    if ground in terms:
        raise InputError(f"link {ground} is the ground (speed 0); it cannot also be a terminal")
    rows, fld = _eliminate(mech, ground, terms)
    exprs = tuple(tuple(fld.to_sympy(v) for v in row) for row in rows)
    return TerminalConstraint(mech, ground, terms, exprs, (fld.domain, tuple(tuple(r) for r in rows)))


def proportional(first, second) -> bool:
    """True when two coefficient vectors (or ``sum a_i omega_i`` expressions over the same
    terminals) are equal up to a common non-zero factor: every 2x2 minor vanishes."""
    a, b = (list(x) for x in (first, second))
    if len(a) != len(b) or not any(sympy.sympify(x) != 0 for x in a) or not any(sympy.sympify(x) != 0 for x in b):
        return False
    return all(sympy.expand(sympy.cancel(a[i] * b[j] - a[j] * b[i])) == 0
               for i, j in itertools.combinations(range(len(a)), 2))


@dataclass(frozen=True)
class Identification:
    """The identification procedure of CYL Section 4 applied to one chain."""

    chain: Mechanism = field(repr=False)
    n_terminals: int
    adjacency: dict = field(repr=False)
    grounds: tuple
    candidates: tuple = field(repr=False)  # TerminalConstraint for every (ground, terminals)
    duplicates: dict = field(repr=False)  # (ground, terminals) -> the earlier isomorphic one

    @property
    def admissible(self) -> tuple:
        """Admissible assignments, isomorphic repeats left out (Step 6): :attr:`repeats` lists
        those left out, :attr:`all_admissible` every admissible assignment."""
        return tuple(c for c in self.candidates if c.admissible and (c.ground, c.terminals) not in self.duplicates)

    @property
    def all_admissible(self) -> tuple:
        """Every admissible assignment, the isomorphic repeats included, in the order tried."""
        return tuple(c for c in self.candidates if c.admissible)

    @property
    def repeats(self) -> tuple:
        """``(candidate, (ground, terminals) of its earlier twin)`` for each admissible assignment
        left out of :attr:`admissible` as isomorphic to an earlier one."""
        return tuple((c, self.duplicates[(c.ground, c.terminals)]) for c in self.candidates
                     if (c.ground, c.terminals) in self.duplicates)

    def __repr__(self) -> str:
        dropped = len(self.duplicates)
        note = (f"; {dropped} isomorphic repeat{'s' * (dropped != 1)} left out (see .repeats, .all_admissible)"
                if dropped else "")
        return (f"Identification({self.chain.name!r}, n_terminals={self.n_terminals}, grounds={self.grounds}: "
                f"{len(self.admissible)} admissible{note})")

    __str__ = __repr__

    def result(self, cand: TerminalConstraint) -> str:
        """``"admissible"``, ``"isomorphic to ground g, terminals ..."`` or ``"—"``."""
        key = (cand.ground, cand.terminals)
        if key in self.duplicates:
            g, t = self.duplicates[key]
            return f"isomorphic to ground {g}, terminals {', '.join(map(str, t))}"
        return "admissible" if cand.admissible else "—"

    def table(self) -> list[dict]:
        """One row per candidate, as CYL's Table 1: ground, terminals, constraints, N3
        failures, redundant links and the result."""
        return [{"ground": c.ground, "terminals": c.terminals, "constraints": c.count, "N3": c.n3_failures,
                 "redundant": c.redundant, "result": self.result(c)} for c in self.candidates]


@takes_mechanism
def identify(chain: Mechanism, n_terminals: int | None = None, *, grounds=None) -> Identification:
    """Every admissible (ground, terminals) assignment of a non-fractionated chain.

    Steps (CYL Section 4): the ground is a link adjacent to at least ``n`` links (N2); the
    terminals are ``n`` of its adjacent links; the constraint among them is derived and
    checked (one constraint, every terminal in it, no redundant link); assignments isomorphic
    to an earlier one (same chain, ground and terminals up to renumbering) are left out.

    Parameters
    ----------
    chain : a geared kinematic chain (see :func:`gearlib.synthesis.atlas.chain_problems`).
    n_terminals : int, optional; default: the chain's dof + 1 (N1). Any other value is an error.
    grounds : links to try as the ground (default: every link that satisfies N2).

    >>> ident = gl.synthesis.identify(gl.catalog.load("cyl_gkc_5_7_2"))
    >>> ident.grounds, [(c.ground, c.terminals) for c in ident.admissible]
    ((1, 3, 4, 6), [(4, (5, 6, 7))])
    """
    if not isinstance(chain, Mechanism):
        raise DataFormatError(f"expected a gl.Mechanism, got {type(chain).__name__}")
    problems = chain_problems(chain)
    if problems:
        raise InputError(f"{chain.name!r} is not a geared kinematic chain: {problems[0]}")
    dof = len(chain.turning_pairs) - len(chain.gear_pairs)
    if n_terminals is None:
        n_terminals = dof + 1
    if isinstance(n_terminals, bool) or not isinstance(n_terminals, numbers.Integral) or n_terminals < 2:
        raise InputError(f"n_terminals must be an integer of at least 2, got {n_terminals!r}")
    if n_terminals != dof + 1:
        raise InputError(f"a DGM with {n_terminals} terminals needs a chain of {n_terminals - 1} dof (N1); "
                         f"{chain.name!r} has {dof}: use {dof + 1} terminals or another chain")
    adj = adjacency(chain)
    if grounds is None:
        grounds = tuple(x for x in chain.link_ids if len(adj[x]) >= n_terminals)
    else:
        grounds = chain.resolve_links(grounds, "ground")
    cands, dups, kept = [], {}, []
    for g in grounds:
        for terms in itertools.combinations(adj[g], n_terminals):
            c = terminal_constraint(chain, terms, ground=g)
            cands.append(c)
            if c.admissible:
                graph = canonical_graph(chain, ground=g, terminals=terms)
                twin = next((k for k, other in kept if isomorphic(graph, other)), None)
                if twin is None:
                    kept.append(((g, terms), graph))
                else:
                    dups[(g, terms)] = twin
    return Identification(chain, int(n_terminals), adj, grounds, tuple(cands), dups)


def synthesize(n_links: int, n_terminals: int = 3) -> tuple:
    """Every admissible non-fractionated ``n_terminals``-terminal DGM with *n_links* links,
    from the chains :func:`gearlib.synthesis.atlas.geared_chains` enumerates: a tuple of
    ``(chain, TerminalConstraint)``.

    >>> [(chain.name, c.ground, c.terminals) for chain, c in gl.synthesis.synthesize(6)]
    []
    """
    if isinstance(n_terminals, bool) or not isinstance(n_terminals, numbers.Integral) or n_terminals < 2:
        raise InputError(f"n_terminals must be an integer of at least 2, got {n_terminals!r}")
    out = []
    for chain in geared_chains(n_links, n_terminals - 1):
        out += [(chain, c) for c in identify(chain, n_terminals).admissible]
    return tuple(out)
