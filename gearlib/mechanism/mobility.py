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


def redundant_gear_pairs(mech: Mechanism) -> tuple:
    """Gear pairs whose Willis equation follows from the pairs before them (for the actual,
    numeric ratios): a duplicate planet, for example. Empty for symbolic ratios."""
    if mech.is_symbolic:
        return ()
    ech, _ = _rank_and_basis(mech, [])
    return tuple(gp for gp in ech.dependent if gp is not None)


def dof(mech: Mechanism, ground=None, *, held=(), joined=()) -> Mobility:
    """Degrees of freedom of *mech* with one link (``ground``) held, and held/joined links."""
    m, jr, jg = len(mech.links), len(mech.turning_pairs), len(mech.gear_pairs)
    ix = mech.index
    ground = mech.resolve(ground if ground is not None else (mech.ground if mech.ground is not None else mech.link_ids[0]))
    extra = [{ix[ground]: Fraction(1)}]
    extra += [{ix[mech.resolve(h)]: Fraction(1)} for h in held]
    extra += [{ix[mech.resolve(u)]: Fraction(1), ix[mech.resolve(v)]: Fraction(-1)} for u, v in joined]
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


def choose_inputs(mech: Mechanism, ground=None, *, candidates=None) -> list:
    """Links that can be driven together as independent inputs, as many as the mechanism has
    degrees of freedom: the first ones of *candidates* (default: every link in order) that
    each remove one freedom when held.

    >>> import gearlib as gl
    >>> gl.choose_inputs(gl.catalog.car_differential(), ground=1)
    [2, 3]
    """
    ground = mech.resolve(ground if ground is not None else (mech.ground if mech.ground is not None else mech.link_ids[0]))
    n = dof(mech, ground).rank
    chosen: list = []
    for link in candidates if candidates is not None else mech.link_ids:
        if len(chosen) == n:
            break
        link = mech.resolve(link)
        if link == ground or link in chosen:
            continue
        if dof(mech, ground, held=chosen + [link]).rank == n - len(chosen) - 1:
            chosen.append(link)
    return chosen
