"""Degrees of freedom: a count and the rank of the Willis equations.

* the mobility count ``F = 3(m - 1) - 2 J_R - J_G`` (Chen, Yao and Lee eq. (1)), in which
  every link has three freedoms and a turning pair removes two, a gear pair one (planar and
  spherical trains);
* the gear-pair/turning-pair rule ``F = J_R - J_G`` (Buchsbaum and Freudenstein): the same
  count when the turning pairs form a tree, ``J_R = m - 1``, and then it holds for bevel
  trains too (each turning pair gives one rotation, each gear pair ties two). In general
  ``3(m - 1) - 2 J_R - J_G = (J_R - J_G) - 3 (J_R - m + 1)``: each loop of turning pairs
  lowers the first by two and raises the second by one;
* the rank: ``F = m - 1 - rank(W)`` with ``W`` the matrix of the Willis equations, which is
  what the mechanism actually does.

When they disagree :func:`dof` says why: loops of coaxial bearings, gear pairs whose
Willis equation repeats the others (a duplicate planet), or gear loops that lock. Derived
in chapter 1.

>>> import gearlib as gl
>>> mob = gl.dof(gl.catalog.car_differential())
>>> mob.planar, mob.count, mob.rank
(-3, 3, 2)
>>> print(mob.explanation[0])
Turning pairs (7, 3), (7, 4) close loops of coaxial bearings (one axis label): they count in J_R but remove no freedom; each such loop lowers the planar count by two and raises the pair rule by one.
>>> print(mob.explanation[-1])
Without them both counts give 2, the rank.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction

from .._common import linalg as _linalg
from .._common.parse import to_fraction
from .data import Mechanism
from ._accept import takes_mechanism

__all__ = ["Mobility", "dof", "redundant_gear_pairs", "choose_inputs"]


@dataclass(frozen=True)
class Mobility:
    """Degrees of freedom of a mechanism with one link held, by three rules, and why they differ.

    ``int(mobility)`` is the true value, ``rank``.
    """

    links: int
    turning_pairs: int
    gear_pairs: int
    planar: int
    count: int
    rank: int
    redundant_turning_pairs: tuple = ()
    redundant_gear_pairs: tuple = ()
    locked_gear_pairs: tuple = ()
    explanation: tuple = field(default=(), compare=False)

    def __int__(self) -> int:
        return self.rank

    __index__ = __int__

    @property
    def agree(self) -> bool:
        """True when both counting rules give the rank."""
        return self.planar == self.count == self.rank

    def __str__(self) -> str:
        m, jr, jg = self.links, self.turning_pairs, self.gear_pairs
        lines = [
            f"m = {m} links, J_R = {jr} turning pairs, J_G = {jg} gear pairs",
            f"planar count   3(m-1) - 2 J_R - J_G = {self.planar}",
            f"pair rule      J_R - J_G            = {self.count}",
            f"rank           m - 1 - rank(W)      = {self.rank}",
        ]
        lines += [f"  * {text}" for text in self.explanation]
        return "\n".join(lines)


def _rank_and_basis(mech: Mechanism, extra_rows):
    """Echelon of the Willis rows (exact) followed by *extra_rows*."""
    fr = [to_fraction(gp.e) for gp in mech.gear_pairs]
    if all(f is not None for f in fr):
        field_, ratios = _linalg.FRACTIONS, fr
    else:
        exprs = [gp.e if gp.e.free_symbols else gp.e for gp in mech.gear_pairs]
        field_, ratios = _linalg.domain_for(exprs)
    ech = _linalg.Echelon(field_)
    ix = mech.index
    for gp, e in zip(mech.gear_pairs, ratios):
        a, b = gp.gears
        row = {ix[b]: field_.convert(1)}
        row[ix[a]] = row.get(ix[a], field_.zero) - e
        row[ix[gp.carrier]] = row.get(ix[gp.carrier], field_.zero) + e - field_.convert(1)
        ech.add(row, 0, gp)
    rank_w = ech.rank
    for row in extra_rows:
        ech.add(row, 0, None)
    return ech, rank_w


def _null_basis(ech: _linalg.Echelon, n: int) -> list[list]:
    zero = ech.field.zero
    basis = []
    for f in ech.free_columns(n):
        x = {c: zero for c in range(n)}
        x[f] = ech.field.convert(1)
        for col in reversed(ech.order):
            row, _ = ech.pivots[col]
            value = zero
            for c, v in row.items():
                if c != col:
                    value = value - v * x[c]
            x[col] = value
        basis.append([x[i] for i in range(n)])
    return basis


# ------------------------------------------------------------- a fast certificate, modulo a prime
_P = (1 << 61) - 1  # a Mersenne prime


def _mod(x: Fraction):
    d = x.denominator % _P
    return None if d == 0 else x.numerator % _P * pow(d, -1, _P) % _P


def _modular_certificate(mech: Mechanism, extra_rows):
    """``(rank of W, rank of [W; extra])`` when they can be certified cheaply, else None.

    The exact elimination of a long train carries fractions with as many digits as the train
    has gears (a 100,000-pair serial train: numbers of 30,000 digits). Modulo a prime *p* the
    numbers stay small. A row independent of the others modulo *p* is independent over the
    rationals (a rational dependency, cleared of denominators, would hold modulo *p* too), so
    when every row is independent modulo *p* the ranks are exact; so is "no gear pair is locked"
    when, modulo *p*, every gear turns relative to its carrier in some null vector. Any other
    outcome (a dependent row, an apparently locked pair, a ratio that is not rational or whose
    denominator *p* divides) returns None and the exact elimination decides."""
    ratios = []
    for gp in mech.gear_pairs:
        if gp.ratio is None and gp.angles is None and gp.kind != "bevel":  # from the teeth, without sympy
            na, nb = gp.teeth
            f = Fraction(-na if gp.kind == "external" else na, nb)
        else:
            f = to_fraction(gp.e)
        e = None if f is None else _mod(f)
        if e is None:
            return None
        ratios.append(e)
    ix = mech.index
    pivots: dict = {}  # column -> row (dict, pivot coefficient 1)
    order: list = []

    def add(row) -> bool:
        row = {c: v % _P for c, v in row.items() if v % _P}
        stack = [c for c in row if c in pivots]
        while stack:
            c = stack.pop()
            coef = row.pop(c, 0)
            if not coef:
                continue
            for col, val in pivots[c].items():
                if col == c:
                    continue
                new = (row.get(col, 0) - coef * val) % _P
                if new:
                    if col not in row and col in pivots:
                        stack.append(col)
                    row[col] = new
                else:
                    row.pop(col, None)
        if not row:
            return False
        col = max(row)
        inv = pow(row[col], -1, _P)
        pivots[col] = {c: v * inv % _P for c, v in row.items()}
        order.append(col)
        return True

    for gp, e in zip(mech.gear_pairs, ratios):
        a, b = gp.gears
        row = {ix[b]: 1}
        row[ix[a]] = row.get(ix[a], 0) - e
        row[ix[gp.carrier]] = row.get(ix[gp.carrier], 0) + e - 1
        if not add(row):
            return None
    rank_w = len(order)
    for row in extra_rows:
        if not add({c: _mod(Fraction(v)) for c, v in row.items()}):
            return None
    n = len(mech.links)
    turning = [False] * len(mech.gear_pairs)
    for f in (c for c in range(n) if c not in pivots):
        x = [0] * n
        x[f] = 1
        for col in reversed(order):
            value = 0
            for c, v in pivots[col].items():
                if c != col:
                    value -= v * x[c]
            x[col] = value % _P
        for i, gp in enumerate(mech.gear_pairs):
            if x[ix[gp.gears[0]]] != x[ix[gp.carrier]]:
                turning[i] = True
    if not all(turning):
        return None
    return rank_w, len(order)


@takes_mechanism
def redundant_gear_pairs(mech: Mechanism) -> tuple:
    """Gear pairs whose Willis equation follows from the pairs before them (for the actual,
    numeric ratios): a duplicate planet, for example. Empty for symbolic ratios."""
    if mech.is_symbolic:
        return ()
    ech, _ = _rank_and_basis(mech, [])
    return tuple(gp for gp in ech.dependent if gp is not None)


@takes_mechanism
def dof(mech: Mechanism, ground=None, *, held=(), joined=()) -> Mobility:
    """Degrees of freedom of *mech* with one link (``ground``) held, and held/joined links."""
    m, jr, jg = len(mech.links), len(mech.turning_pairs), len(mech.gear_pairs)
    ix = mech.index
    ground = mech.resolve(ground if ground is not None else (mech.ground if mech.ground is not None else mech.link_ids[0]),
                          "ground")
    extra = [{ix[ground]: Fraction(1)}]
    held = mech.resolve_links(held, "held link")
    joined = mech.resolve_pairs(joined, "joined link")
    extra += [{ix[h]: Fraction(1)} for h in held]
    extra += [{ix[u]: Fraction(1), ix[v]: Fraction(-1)} for u, v in joined]
    fast = _modular_certificate(mech, extra) if len(mech.gear_pairs) > 200 else None
    if fast is not None:  # every row independent, no pair locked: certified without big numbers
        rank_dof, redundant_gp, locked = m - fast[1], (), ()
    else:
        ech, rank_w = _rank_and_basis(mech, extra)
        rank_dof = m - ech.rank
        redundant_gp = tuple(gp for gp in ech.dependent if gp is not None)
        basis = _null_basis(ech, m)
        is_zero = ech.field.is_zero
        locked = tuple(
            gp
            for gp in mech.gear_pairs
            if all(is_zero(x[ix[gp.gears[0]]] - x[ix[gp.carrier]]) for x in basis)
        )
    planar = 3 * (m - 1) - 2 * jr - jg
    count = jr - jg
    shift = len(held) + len(joined)
    planar -= shift
    count -= shift
    red_tp = mech.redundant_turning_pairs
    notes = []
    if red_tp:
        names = ", ".join(str(tp.links) for tp in red_tp)
        notes.append(
            f"Turning pairs {names} close loops of coaxial bearings (one axis label): they count in J_R but remove "
            "no freedom; each such loop lowers the planar count by two and raises the pair rule by one."
        )
    if redundant_gp:
        names = ", ".join(gp.label for gp in redundant_gp)
        notes.append(
            f"Gear pair{'s' if len(redundant_gp) > 1 else ''} {names} add{'s' if len(redundant_gp) == 1 else ''} no "
            "new equation: the Willis equation follows from the other pairs (for example a second planet "
            "identical to the first), so the counts are too low by one per such pair."
        )
    if locked:
        names = ", ".join(gp.label for gp in locked)
        notes.append(
            f"Gear pair{'s' if len(locked) > 1 else ''} {names} cannot turn relative to {'their' if len(locked) > 1 else 'its'} "
            "carrier: the gear pairs over-constrain (lock) part of the mechanism."
        )
    if not notes and not (planar == count == rank_dof):
        notes.append("The counting rules assume the turning pairs form a tree; here they do not.")
    if red_tp or redundant_gp:
        corrected = (jr - len(red_tp)) - (jg - len(redundant_gp)) - shift
        planar_corrected = 3 * (m - 1) - 2 * (jr - len(red_tp)) - (jg - len(redundant_gp)) - shift
        both = "both counts give" if planar_corrected == corrected else f"the planar count gives {planar_corrected} and the pair rule"
        notes.append(f"Without them {both} {corrected}" + (", the rank." if corrected == rank_dof else f"; the rank is {rank_dof}."))
    return Mobility(m, jr, jg, planar, count, rank_dof, red_tp, redundant_gp, locked, tuple(notes))


@takes_mechanism
def choose_inputs(mech: Mechanism, ground=None, *, candidates=None) -> list:
    """Links that can be driven together as independent inputs, as many as the mechanism has
    degrees of freedom: the first ones of *candidates* (default: every link in order) that
    each remove one freedom when held.

    >>> import gearlib as gl
    >>> gl.choose_inputs(gl.catalog.car_differential(), ground=1)
    [2, 3]
    """
    ground = mech.resolve(ground if ground is not None else (mech.ground if mech.ground is not None else mech.link_ids[0]),
                          "ground")
    n = dof(mech, ground).rank
    chosen: list = []
    for link in mech.resolve_links(candidates, "candidate") if candidates is not None else mech.link_ids:
        if len(chosen) == n:
            break
        if link == ground or link in chosen:
            continue
        if dof(mech, ground, held=chosen + [link]).rank == n - len(chosen) - 1:
            chosen.append(link)
    return chosen
