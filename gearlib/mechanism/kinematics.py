"""Every link's angular velocity, and speed ratios, from the Willis equations.

Unknowns are the speeds ``omega_u`` of all links, with the ground at zero. Equations are
the Willis equations of the gear pairs (:mod:`gearlib.mechanism.equations`), plus one row per
constraint: the ground, held links (brakes), joined links (clutches), and inputs. Four
methods solve the same system and must agree:

``"exact"``
    sparse elimination in exact arithmetic: :class:`fractions.Fraction` for tooth
    numbers, algebraic numbers for Penaud's complex weights;
``"symbolic"``
    every numeric gear ratio replaced by its symbol ``e_a_b``: the result is a rational
    function of the ratios (and of symbolic inputs);
``"nullspace"``
    Penaud and Alazard's method: the null space of the complex-weighted adjacency matrix
    with the constraint rows, normalised to the inputs (:mod:`gearlib.adjacency`);
``"numeric"``
    one dense LU solve in floating point, the fast path for large mechanisms.

For planar trains ``omega_u`` is the angular velocity of ``u``. For spatial (bevel)
trains it is Tsai's scalar along each link's own axis: differences are physical
angular velocities only between coaxial links (``Mechanism.coaxial``), and Penaud's
complex values carry the direction in the plane of the axes. Derived in chapter 1.

>>> import gearlib as gl
>>> m = gl.catalog.simple_planetary(sun=24, ring=60)
>>> gl.ratio(m, output=4, input=1, ground=3)    # carrier over sun, ring held
Fraction(2, 7)
>>> sol = gl.speeds(m, ground=3, inputs={1: 70})
>>> sol[4], sol[2]
(Fraction(20, 1), Fraction(-140, 3))
"""

from __future__ import annotations

import sys
import html

import cmath
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np
import sympy

from .._common import linalg as _linalg
from .._common.matview import polar_text
from .._common.parse import parse_expr, to_fraction
from .equations import omega
from ..errors import ConstraintError, DataFormatError, InputError
from .data import Mechanism
from ._accept import takes_mechanism

__all__ = ["Solution", "speeds", "ratio", "METHODS", "Constraints", "format_value"]

METHODS = ("exact", "symbolic", "nullspace", "numeric")


# ---------------------------------------------------------------------------- constraints
@dataclass(frozen=True)
class Constraints:
    """Ground, held links, joined links and inputs, resolved to column indices.

    ``inputs`` holds ``(u, v, value)``: the speed of link ``u`` relative to link ``v``.
    """

    mechanism: Mechanism
    ground: object
    held: tuple = ()
    joined: tuple = ()
    inputs: tuple = ()

    @classmethod
    def build(cls, mech, ground, inputs, held=(), joined=(), *, symbolic_inputs=False) -> Constraints:
        if ground is None:
            ground = mech.ground
        if ground is None:
            raise InputError(f"choose a ground link for {mech.name!r} (ground=...); links are {list(mech.link_ids)}")
        ground = mech.resolve(ground, "ground")
        held = mech.resolve_links(held, "held link")
        for h in held:
            if h == ground:
                raise ConstraintError(f"link {h} is the ground and also held; the ground is already fixed")
        joined_out = []
        for u, v in mech.resolve_pairs(joined, "joined link"):
            if u == v:
                raise ConstraintError(f"joined pair ({u}, {v}) joins a link to itself")
            joined_out.append((u, v))
        items = cls._input_items(mech, inputs)
        out = []
        seen = set()
        for key, value in items:
            u, v = cls._input_key(mech, key, ground)
            if u != v and u not in held and (u, v) not in seen and (v, u) not in seen \
                    and type(value) in (int, float) and _finite(value):
                seen.add((u, v))  # the common case, valid: skip the checks below
                out.append((u, v, value))
                continue
            where = f"input {u}" if v == ground else f"input {u}/{v}"
            if u == ground and v == ground:
                raise InputError(f"{where}: link {u} is the ground; its speed is 0. Give inputs to other links")
            if u == v:
                raise InputError(f"{where}: a link cannot be driven relative to itself")
            if v == ground and u in held:
                raise ConstraintError(f"{where}: link {u} is held (speed 0) and also driven; drop one of them")
            if (u, v) in seen or (v, u) in seen:
                raise InputError(f"{where} is given twice")
            seen.add((u, v))
            if value is None:
                if not symbolic_inputs:
                    raise InputError(f"{where}: give its speed, e.g. inputs={{{u!r}: 1}}")
                value = omega(u) if v == ground else omega(u, v)
            elif type(value) in (int, float, Fraction) and _finite(value):
                pass  # a plain number: kept as it is (read exactly by the exact solvers)
            else:
                value = parse_expr(value, where)
                if value.free_symbols and not symbolic_inputs:
                    raise InputError(
                        f"{where}: speed {value} is not a number; give a number, or use method='symbolic' for "
                        "symbolic speeds"
                    )
            out.append((u, v, value))
        return cls(mech, ground, held, tuple(joined_out), tuple(out))

    @staticmethod
    def _input_items(mech, inputs):
        if type(inputs) is dict:
            return list(inputs.items())
        if inputs is None:
            inputs = mech.inputs
        if isinstance(inputs, Mapping):
            return list(inputs.items())
        if isinstance(inputs, (str, bytes, int)):
            return [(inputs, None)]
        if isinstance(inputs, Sequence):
            return [(k, None) for k in inputs]
        raise DataFormatError(f"inputs must be a mapping link -> speed (or a list of links), got {inputs!r}")

    @staticmethod
    def _input_key(mech, key, ground):
        if type(key) is int and key in mech.index:  # the common case, fast
            return key, ground
        if isinstance(key, str) and "/" in key:
            u, v = key.split("/", 1)
        elif isinstance(key, tuple) and len(key) == 2:
            u, v = key
        else:
            u, v = key, ground
        return mech.resolve(u, "input link"), mech.resolve(v, "input reference link")

    def rows(self):
        """Constraint rows ``(dict, rhs, tag)``: ground, held, joined, then inputs."""
        ix = self.mechanism.index
        yield {ix[self.ground]: 1}, 0, ("ground", self.ground)
        for h in self.held:
            yield {ix[h]: 1}, 0, ("held", h)
        for u, v in self.joined:
            yield {ix[u]: 1, ix[v]: -1}, 0, ("joined", (u, v))
        for u, v, value in self.inputs:
            row = {ix[u]: 1}
            if v != self.ground:
                row[ix[v]] = -1
            yield row, value, ("input", (u, v))

    def describe_input(self, u, v) -> str:
        return f"{u}" if v == self.ground else f"{u}/{v}"


def _finite(x) -> bool:
    """A number that fits a float: not NaN, not infinite, not an integer beyond 1.8e308."""
    return -_FLOAT_MAX <= x <= _FLOAT_MAX


_FLOAT_MAX = sys.float_info.max


def _as_fraction(v):
    """The exact rational value of an input speed, or None."""
    if isinstance(v, Fraction):
        return v
    if type(v) is int:
        return Fraction(v)
    if type(v) is float:
        return Fraction(repr(v))
    return to_fraction(v)


def _as_expr(v) -> sympy.Expr:
    """An input speed as an exact sympy expression (floats by their decimal form)."""
    if isinstance(v, sympy.Basic):
        return v
    return parse_expr(v, "input")


def _gear_rows(mech: Mechanism, ratio_of):
    ix = mech.index
    for gp in mech.gear_pairs:
        a, b = gp.gears
        e = ratio_of(gp)
        row = {ix[b]: 1}
        row[ix[a]] = row.get(ix[a], 0) - e
        row[ix[gp.carrier]] = row.get(ix[gp.carrier], 0) + (e - 1)
        yield row, 0, ("gear", gp)


# ---------------------------------------------------------------------------- solution
@dataclass(frozen=True)
class Solution:
    """Every link's speed (relative to the ground) for one set of inputs.

    Index it with a link id: ``sol[3]``. Values are :class:`fractions.Fraction` or sympy
    expressions (methods ``"exact"``, ``"symbolic"``) or Python numbers (``"nullspace"``,
    ``"numeric"``).
    """

    mechanism: Mechanism
    constraints: Constraints
    values: tuple
    method: str
    dof: int
    notes: tuple = field(default=(), compare=False)

    def __getitem__(self, link):
        return self.values[self.mechanism.index[self.mechanism.resolve(link)]]

    def __iter__(self):
        return iter(self.mechanism.link_ids)

    def items(self):
        return zip(self.mechanism.link_ids, self.values)

    def relative(self, u, v):
        """Speed of link *u* relative to link *v*, ``omega_u - omega_v``."""
        return _sub(self[u], self[v])

    def ratio(self, output, input, relative_to=None):
        """``omega(output/ref) / omega(input/ref)``, *ref* the ground unless given."""
        ref = self.constraints.ground if relative_to is None else relative_to
        num, den = self.relative(output, ref), self.relative(input, ref)
        if _is_zero(den):
            raise ConstraintError(f"link {input} does not move relative to {ref} in this solution; no ratio")
        return _div(num, den)

    def as_complex(self) -> np.ndarray:
        """All speeds as a complex numpy array (in ``mechanism.link_ids`` order)."""
        return np.array([_to_complex(v) for v in self.values], dtype=complex)

    def to_json(self) -> dict:
        """``{"dof": int, "speeds": {"3": [re, im], ...}}``, the command line's ``--json`` form."""
        z = self.as_complex()
        return {"dof": self.dof, "speeds": {str(k): [float(v.real), float(v.imag)] for k, v in zip(self, z)}}

    def table(self, digits: int = 6) -> list[tuple]:
        """Rows ``(link, name, value as text)``."""
        out = []
        for lk, v in zip(self.mechanism.links, self.values):
            out.append((lk.id, lk.name or "", format_value(v, digits)))
        return out

    def tilted_note(self) -> str:
        """A sentence on the links whose axes are tilted to the ground's (bevel planets,
        :func:`~gearlib.mechanism.tilted_links`): their value is no angular velocity; empty when
        there are none."""
        from .graph import tilted_links

        tilted = tilted_links(self.mechanism, self.constraints.ground)
        if not tilted:
            return ""
        pairs = ", ".join(f"ω{x} − ω{ref}" for x, ref in tilted.items())
        links = ", ".join(str(x) for x in tilted)
        return (f"Link{'s' if len(tilted) > 1 else ''} {links} turn{'' if len(tilted) > 1 else 's'} about an axis "
                f"tilted to the ground's: {'their' if len(tilted) > 1 else 'its'} ω is a value of the Willis "
                f"equations, not an angular velocity; the spin relative to the link it turns on ({pairs}) is one.")

    def __str__(self) -> str:
        rows = self.table()
        w = max(len(str(r[0])) for r in rows)
        n = max(len(r[1]) for r in rows)
        head = f"speeds of {self.mechanism.name!r} (ground {self.constraints.ground}, method {self.method})"
        note = self.tilted_note()
        return "\n".join([head] + [f"  {str(i):>{w}}  {name:<{n}}  {val}" for i, name, val in rows]
                         + ([note] if note else []))

    def _repr_pretty_(self, p, cycle):
        """IPython's text/plain (the PDF book, a terminal): the table of :meth:`__str__`, not the
        dataclass fields."""
        p.text(str(self))

    def _repr_html_(self) -> str:
        rows = "".join(
            f"<tr><td>{i}</td><td>{name}</td><td style='text-align:right'>{val}</td></tr>" for i, name, val in self.table()
        )
        return (
            f"<table><caption>Speeds relative to link {self.constraints.ground} ({self.method})</caption>"
            f"<tr><th>link</th><th>name</th><th>&omega;</th></tr>{rows}</table>"
            + (f"<p><small>{html.escape(note)}</small></p>" if (note := self.tilted_note()) else "")
        )

    def plot(self, ax=None, **kwargs):
        """Bar chart of the speeds, see :func:`gearlib.plot_speeds`."""
        from .plot import plot_speeds

        return plot_speeds(self, ax=ax, **kwargs)


def format_value(v, digits: int = 6) -> str:
    """A speed or ratio as short text: fractions exactly, floats rounded, complex in polar form
    ``r∠phi°`` (the angle in degrees)."""
    if isinstance(v, Fraction):
        return str(v)
    if isinstance(v, sympy.Basic):
        if v.free_symbols:
            return str(v)
        if v.is_Rational:
            return str(v)
        v = complex(v.evalf(30))
    z = complex(v)
    if abs(z.imag) <= 1e-12 * max(1.0, abs(z)):
        return f"{z.real:.{digits}g}"
    return polar_text(z, digits)


def _to_complex(v) -> complex:
    if isinstance(v, sympy.Basic):
        if v.free_symbols:
            raise ConstraintError(f"value {v} is symbolic; substitute numbers first")
        return complex(v.evalf(30))
    return complex(v)


def _is_zero(v) -> bool:
    if isinstance(v, sympy.Basic):
        return sympy.simplify(v) == 0
    if isinstance(v, Fraction):
        return v == 0
    return abs(v) < 1e-300


def _sub(a, b):
    if isinstance(a, sympy.Basic) or isinstance(b, sympy.Basic):
        return sympy.cancel(sympy.sympify(a) - sympy.sympify(b))
    return a - b


def _div(a, b):
    if isinstance(a, sympy.Basic) or isinstance(b, sympy.Basic):
        return sympy.factor(sympy.cancel(sympy.sympify(a) / sympy.sympify(b)))
    return a / b


# ---------------------------------------------------------------------------- solvers
def _count_message(mech, cons: Constraints, dof: int) -> str:
    extra = ""
    if cons.held or cons.joined:
        extra = " with the held and joined links given"
    return (
        f"{mech.name!r} has {dof} degree{'s' if dof != 1 else ''} of freedom with link {cons.ground} "
        f"grounded{extra}, so it needs {dof} input{'s' if dof != 1 else ''}; got {len(cons.inputs)}"
        + (f" ({', '.join(cons.describe_input(u, v) for u, v, _ in cons.inputs)})" if cons.inputs else "")
    )


def _tag_text(tag) -> str:
    kind, what = tag
    if kind == "gear":
        return f"gear pair {what.label}"
    if kind == "input":
        u, v = what
        return f"input {u}" if v is None else f"input {u}/{v}"
    return f"{kind} {what}"


def _solve_echelon(mech, cons: Constraints, field, gear_rows, m) -> tuple[list, int]:
    gear_rows = list(gear_rows)
    cons_rows = list(cons.rows())
    weight: dict = {}
    for row, _, _ in gear_rows + cons_rows:
        for c in row:
            weight[c] = weight.get(c, 0) + 1
    ech = _linalg.Echelon(field, weight)
    for row, rhs, tag in gear_rows:
        ech.add(row, rhs, tag)
    inputs = []
    for row, rhs, tag in cons_rows:
        if tag[0] == "input":
            inputs.append((row, rhs, tag))
        else:
            ech.add(row, rhs, tag)
            if ech.inconsistent:
                raise ConstraintError(f"{_tag_text(tag)} contradicts the other constraints")
    dof = m - ech.rank
    if len(inputs) != dof:
        raise InputError(_count_message(mech, cons, dof))
    for row, rhs, tag in inputs:
        if not ech.add(row, rhs, tag):
            u, v = tag[1]
            text = cons.describe_input(u, v)
            raise InputError(
                f"input {text} is not independent of the other inputs and constraints: its speed is already "
                f"fixed by them. Choose another input link (the mechanism has {dof} degrees of freedom "
                f"with link {cons.ground} grounded)"
            )
    return ech.solve(m), dof


def _exact(mech, cons: Constraints) -> tuple[list, int]:
    m = len(mech.links)
    fracs = {id(gp): to_fraction(gp.e) for gp in mech.gear_pairs}
    values = [_as_fraction(v) for _, _, v in cons.inputs]
    if all(f is not None for f in fracs.values()) and all(v is not None for v in values):
        cons_f = Constraints(cons.mechanism, cons.ground, cons.held, cons.joined,
                             tuple((u, v, f) for (u, v, _), f in zip(cons.inputs, values)))
        x, dof = _solve_echelon(mech, cons_f, _linalg.FRACTIONS, _gear_rows(mech, lambda gp: fracs[id(gp)]), m)
        return x, dof
    return _domain_solve(mech, cons, lambda gp: gp.e, m)


def _domain_solve(mech, cons, ratio_of, m):
    ratios = [ratio_of(gp) for gp in mech.gear_pairs]
    values = [_as_expr(v) for _, _, v in cons.inputs]
    field, elems = _linalg.domain_for(ratios + values)
    conv = dict(zip(range(len(ratios)), elems[: len(ratios)]))
    pos = {id(gp): i for i, gp in enumerate(mech.gear_pairs)}
    cons_d = Constraints(cons.mechanism, cons.ground, cons.held, cons.joined,
                         tuple((u, v, val) for (u, v, _), val in zip(cons.inputs, elems[len(ratios):])))
    x, dof = _solve_echelon(mech, cons_d, field, _gear_rows(mech, lambda gp: conv[pos[id(gp)]]), m)
    if field.name.startswith("EX"):  # arbitrary expressions: bring each speed to one fraction
        return [sympy.cancel(field.to_sympy(v)) for v in x], dof
    # rational-function and algebraic fields keep their elements as reduced fractions already;
    # sympy.cancel here would cost about 20 ms a link and change nothing
    return [field.to_sympy(v) for v in x], dof


def _symbolic(mech, cons):
    """Ratios as symbols. Gear pairs whose equation is implied by the others for the actual
    ratios (a duplicate planet) are left out: with free symbols they would wrongly lock."""
    from .mobility import redundant_gear_pairs

    m = len(mech.links)
    redundant = {id(gp) for gp in redundant_gear_pairs(mech)}
    if redundant:
        kept = tuple(gp for gp in mech.gear_pairs if id(gp) not in redundant)
        mech = _without_pairs(mech, kept)
        cons = Constraints(mech, cons.ground, cons.held, cons.joined, cons.inputs)
    return _domain_solve(mech, cons, lambda gp: gp.symbol if not gp.e.free_symbols else gp.e, m)


def _without_pairs(mech, kept):
    """The same mechanism with only the gear pairs *kept* (no re-validation needed: removing
    a redundant pair keeps every carrier and the connectivity)."""
    import copy

    new = copy.copy(mech)
    object.__setattr__(new, "gear_pairs", kept)
    new.__dict__.pop("index", None)
    return new


def _coo(mech, cons):
    """The system ``A x = b`` as COO triplets (gear rows, constraint rows, input rows last).

    Returns ``(rows, cols, data, shape, b, dtype)``; complex when a gear ratio or an input is.
    """
    m = len(mech.links)
    ratios, vals, is_complex = _numbers(mech, cons)
    dtype = complex if is_complex else float
    ix = mech.index
    n = len(ratios)
    ia = np.fromiter((ix[gp.gears[0]] for gp in mech.gear_pairs), np.int64, n)
    ib = np.fromiter((ix[gp.gears[1]] for gp in mech.gear_pairs), np.int64, n)
    ic = np.fromiter((ix[gp.carrier] for gp in mech.gear_pairs), np.int64, n)
    e = np.array(ratios if is_complex else [r.real for r in ratios], dtype=dtype)
    r = np.arange(n)
    rows, cols, data = [r, r, r], [ib, ia, ic], [np.ones(n, dtype=dtype), -e, e - 1]
    b = np.zeros(n, dtype=dtype)
    extra_r, extra_c, extra_d, extra_b = [], [], [], []
    vi = iter(vals)
    for i, (row, _rhs, tag) in enumerate(cons.rows()):
        for c, v in row.items():
            extra_r.append(n + i)
            extra_c.append(c)
            extra_d.append(v)
        val = next(vi) if tag[0] == "input" else 0
        extra_b.append(val if is_complex else val.real)
    rows.append(np.array(extra_r, dtype=np.int64))
    cols.append(np.array(extra_c, dtype=np.int64))
    data.append(np.array(extra_d, dtype=dtype))
    b = np.concatenate([b, np.array(extra_b, dtype=dtype)])
    shape = (n + len(extra_b), m)
    return np.concatenate(rows), np.concatenate(cols), np.concatenate(data), shape, b, dtype


def _numbers(mech, cons):
    """The gear ratios and the input speeds as (complex) numbers, and whether any of them has
    an imaginary part (then the system is complex)."""
    ratios = [gp.e_value for gp in mech.gear_pairs]
    vals = [_to_complex(v) for _, _, v in cons.inputs]
    return ratios, vals, any(r.imag != 0 for r in ratios) or any(v.imag != 0 for v in vals)


def _numeric_matrix(mech, cons):
    """The dense ``A x = b`` of the Willis and constraint rows (the LAPACK baseline's input)."""
    rows, cols, data, shape, b, dtype = _coo(mech, cons)
    A = np.zeros(shape, dtype=dtype)
    np.add.at(A, (rows, cols), data)
    return A, b


_PLAN_CACHE_SIZE = 32


def _numeric(mech, cons):
    """Floating-point speeds through the speed-ratio matrix ``Omega_0`` of these constraints.

    ``Omega_0`` (links x inputs) is computed once per mechanism and set of constraint links by
    one sparse (or, for small mechanisms, dense) LU factorisation, and cached on the
    mechanism; each call is then one matrix-vector product with the input speeds. When the
    system is not square (redundant gear pairs) or singular, the null-space method decides
    the degrees of freedom and explains what is wrong with the inputs.
    """
    key = _plan_key(cons)
    cache = mech.__dict__.setdefault("_speed_plans", {})
    entry = cache.get(key)
    if entry is None:
        plan = _numeric_plan(mech, cons)
        # one real input on a small mechanism: keep the column as a Python list too (with its
        # largest entry), so a call is a list times a number (numpy's per-call overhead
        # dominates at this size)
        small = plan[:, 0].tolist() if plan.dtype == float and plan.shape[1] == 1 and plan.shape[0] <= 64 else None
        if len(cache) >= _PLAN_CACHE_SIZE:
            cache.pop(next(iter(cache)))
        entry = cache[key] = (plan, small, None if small is None else max(map(abs, small), default=0.0))
    plan, small, largest = entry
    values = [v if type(v) in (int, float) else _to_complex(v) for _, _, v in cons.inputs]
    if small is not None and type(values[0]) is not complex:
        return _scaled(small, largest, values[0]), 1
    if plan.dtype != complex and any(type(v) is complex and v.imag for v in values):
        values = np.array(values, dtype=complex)
    with np.errstate(over="ignore", invalid="ignore"):
        result = plan @ np.asarray(values)
    if not np.isfinite(result).all():
        raise InputError(_OVERFLOW)
    return _clean(result), len(cons.inputs)


def _dense_small(mech, cons):
    """The square dense matrix of :func:`_coo`'s system for a small mechanism, filled entry
    by entry (a handful of numpy calls instead of a dozen: most of a first call's time at
    this size), or None when the system is not square."""
    m = len(mech.links)
    cons_rows = list(cons.rows())
    n = len(mech.gear_pairs)
    if n + len(cons_rows) != m:
        return None
    ratios, _, is_complex = _numbers(mech, cons)
    A = [[0.0] * m for _ in range(m)]  # Python lists: an entry costs far less than in an array
    ix = mech.index
    for row, gp, e in zip(A, mech.gear_pairs, ratios):
        e = e if is_complex else e.real
        a, b = gp.gears
        row[ix[b]] += 1
        row[ix[a]] -= e
        row[ix[gp.carrier]] += e - 1
    for row, (entries, _, _) in zip(A[n:], cons_rows):
        for c, v in entries.items():
            row[c] += v
    return np.array(A, dtype=complex if is_complex else float)


def _numeric_plan(mech, cons) -> np.ndarray:
    m, k = len(mech.links), len(cons.inputs)
    omega0 = _square_plan(mech, cons, m, k) if k else None
    # not square, or singular: the null space finds the degrees of freedom, checks the inputs
    return omega0 if omega0 is not None else _nullspace_plan(mech, cons)


def _square_plan(mech, cons, m, k):
    """``Omega_0`` from the square system by one LU factorisation (dense up to 64 links,
    sparse above), or None when the system is not square or is singular."""
    if m <= 64:
        A = _dense_small(mech, cons)
        if A is None:
            return None
        dtype = A.dtype
    else:
        rows, cols, data, shape, _, dtype = _coo(mech, cons)
        if shape[0] != m:
            return None
    rhs = np.zeros((m, k), dtype=dtype)
    rhs[m - k + np.arange(k), np.arange(k)] = 1  # input rows come last
    try:
        if m <= 64:
            omega0 = np.linalg.solve(A, rhs)
        else:
            import scipy.sparse
            import scipy.sparse.linalg

            A = scipy.sparse.csc_matrix((data, (rows, cols)), shape=shape)
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                omega0 = scipy.sparse.linalg.splu(A).solve(rhs)
    except (np.linalg.LinAlgError, RuntimeError, Warning):
        return None
    # accepted when finite with a residual at round-off (on Python floats: cheap at any size here)
    flat = omega0.ravel().tolist()
    residual = max(map(abs, (A @ omega0 - rhs).ravel().tolist()))
    if all(map(cmath.isfinite, flat)) and residual <= 1e-9 * max(1.0, max(map(abs, flat))):
        return omega0
    return None


def _nullspace_plan(mech, cons) -> np.ndarray:
    """Penaud's speed-ratio matrix ``Omega_0 = K (R K)^-1`` for these inputs, where ``K`` spans
    the null space of ``M`` with the constraint rows and ``R`` picks the input speeds; raises
    InputError when the inputs are too few, too many, or not independent."""
    K, dof = _constrained_null_space(mech, cons)
    if len(cons.inputs) != dof:
        raise InputError(_count_message(mech, cons, dof))
    if dof == 0:
        return np.zeros((len(mech.links), 0))
    ix = mech.index
    R = np.array([K[ix[u]] - K[ix[v]] for u, v, _ in cons.inputs])
    s = np.linalg.svd(R, compute_uv=False)
    if s[-1] <= 1e-10 * max(1.0, s[0]):
        names = ", ".join(cons.describe_input(u, v) for u, v, _ in cons.inputs)
        raise InputError(
            f"inputs {names} are not independent: together they fix fewer than {dof} freedoms. "
            "Choose other input links"
        )
    omega0 = K @ np.linalg.inv(R)
    if np.abs(omega0.imag).max(initial=0.0) <= 1e-12 * max(1.0, np.abs(omega0).max(initial=0.0)):
        omega0 = omega0.real
    return omega0


def _constrained_null_space(mech, cons):
    """Null space of Penaud's M with the ground, held and joined rows; and its dimension."""
    from ..adjacency.matrix import adjacency_matrix, null_space

    M = adjacency_matrix(mech)
    rows = [r for r in cons.rows() if r[2][0] != "input"]
    C = np.zeros((len(rows), len(mech.links)))
    for i, (row, _, _) in enumerate(rows):
        for c, v in row.items():
            C[i, c] = v
    K = null_space(np.vstack([M, C]) if M.size else C)
    return K, K.shape[1]


def _nullspace(mech, cons):
    """Penaud and Alazard's method: the null space of the complex-weighted adjacency matrix
    with the constraint rows, normalised to the inputs."""
    omega0 = _nullspace_plan(mech, cons)
    values = np.array([_to_complex(v) for _, _, v in cons.inputs], dtype=complex)
    return _clean(omega0 @ values), len(cons.inputs)


def _remember_numeric(mech, ground, inputs, cons):
    """After a validated numeric solve with ``{link: number}`` inputs, remember what it took,
    so that the next call with the same ground and input links (a widget moving a slider)
    skips the validation: :func:`_repeat_numeric`."""
    if len(inputs) != 1 or len(cons.inputs) != 1:
        return
    _, small, largest = mech.__dict__.get("_speed_plans", {}).get(_plan_key(cons), (None, None, None))
    if small is None:
        return
    fast = mech.__dict__.setdefault("_speed_repeat", {})
    if len(fast) >= _PLAN_CACHE_SIZE:
        fast.pop(next(iter(fast)))
    u, w, _ = cons.inputs[0]
    fast[_repeat_key(ground, inputs)] = (cons.ground, u, w, small, largest)


def _plan_key(cons) -> tuple:
    """What a numeric plan depends on: the ground, brakes, clutches and the input links."""
    return cons.ground, cons.held, cons.joined, tuple([(u, v) for u, v, _ in cons.inputs])


def _repeat_key(ground, inputs):
    # the types too: 1.0 and True equal 1 as dict keys, but are not valid link ids
    k = next(iter(inputs))
    return type(ground), ground, type(k), k


def _repeat_numeric(mech, ground, inputs):
    """The solution of :func:`speeds` for one real input on a small mechanism already solved
    with the same ground and input link (see :func:`_remember_numeric`), or None."""
    fast = mech.__dict__.get("_speed_repeat")
    if not fast or len(inputs) != 1:
        return None
    entry = fast.get(_repeat_key(ground, inputs))
    if entry is None:
        return None
    v = next(iter(inputs.values()))
    if type(v) not in (int, float) or not _finite(v):
        return None  # NaN, infinities, other types: the full path gives the error message
    g, u, w, column, largest = entry
    return Solution(mech, Constraints(mech, g, (), (), ((u, w, v),)), tuple(_scaled(column, largest, v)), "numeric", 1)


def _scaled(column: list, largest: float, v) -> list:
    """``column * v`` cleaned as :func:`_clean` does (``largest``: the largest ``|column|``),
    in one pass over Python floats."""
    if abs(v) * largest > _FLOAT_MAX:
        raise InputError(_OVERFLOW)
    lim = 1e-12 * max(1.0, abs(v) * largest)
    return [0.0 if -lim < (y := x * v) < lim else y for x in column]


_OVERFLOW = ("the speeds exceed a float's range (about 1.8e308) for these inputs; scale the inputs down "
             "(every speed is proportional to them)")


def _clean(x) -> list:
    """Floating-point speeds as Python numbers: round-off below 1e-12 of the largest speed
    becomes 0, and complex values with no imaginary part become floats."""
    x = np.asarray(x)
    scale = 1e-12 * max(1.0, float(np.abs(x).max(initial=0.0)))
    if not np.iscomplexobj(x):
        return np.where(np.abs(x) < scale, 0.0, x).tolist()
    re = np.where(np.abs(x.real) < scale, 0.0, x.real)
    im = np.where(np.abs(x.imag) < scale, 0.0, x.imag)
    if not im.any():
        return re.tolist()
    return [complex(a, b) if b else a for a, b in zip(re.tolist(), im.tolist())]


_SOLVERS = {"exact": _exact, "symbolic": _symbolic, "nullspace": _nullspace, "numeric": _numeric}


@takes_mechanism
def speeds(mech: Mechanism, ground=None, inputs=None, *, method: str = "exact", held=(), joined=()) -> Solution:
    """Every link's speed relative to the ground, for given input speeds.

    Parameters
    ----------
    mech : Mechanism
    ground : link id, optional
        The link held fixed (speed 0). Defaults to ``mech.ground``.
    inputs : mapping, optional
        ``{link: speed}``; a key ``"u/v"`` or ``(u, v)`` drives *u* relative to *v*. Give
        as many inputs as the mechanism has degrees of freedom. With ``method="symbolic"``
        a list of links gives symbolic speeds ``omega_u``.
    method : {"exact", "symbolic", "nullspace", "numeric"}
        See the module documentation. All four give the same speeds.
    held : links fixed to the ground as well (brakes).
    joined : pairs of links made to turn together (clutches).

    Returns
    -------
    Solution

    Raises
    ------
    InputError
        Wrong number of inputs (the message says how many are needed), an input on the
        ground, or inputs that are not independent.
    ConstraintError
        Held or joined links that contradict each other.

    Examples
    --------
    >>> import gearlib as gl
    >>> diff = gl.catalog.car_differential()
    >>> sol = gl.speeds(diff, ground=1, inputs={3: 26, 4: 30})
    >>> sol[7], sol[2]
    (Fraction(28, 1), Fraction(-140, 1))
    >>> gl.speeds(diff, ground=1, inputs={3: 26})
    Traceback (most recent call last):
    ...
    gearlib.errors.InputError: 'car differential' has 2 degrees of freedom with link 1 grounded, so it needs 2 inputs; got 1 (3)
    """
    # a plain {link: number} numeric solve: a repeat of an earlier one may skip validation
    repeatable = method == "numeric" and type(inputs) is dict and not held and not joined
    if repeatable:
        sol = _repeat_numeric(mech, ground, inputs)
        if sol is not None:
            return sol
    if method not in _SOLVERS:
        raise DataFormatError(f"method must be one of {', '.join(METHODS)}, got {method!r}")
    cons = Constraints.build(mech, ground, inputs, held, joined, symbolic_inputs=(method == "symbolic"))
    with np.errstate(over="ignore", invalid="ignore"):  # an overflow is reported below, once
        values, dof = _SOLVERS[method](mech, cons)
    if repeatable:
        _remember_numeric(mech, ground, inputs, cons)
    if method == "exact" and values and isinstance(values[0], sympy.Basic):
        values = [v if to_fraction(v) is None else to_fraction(v) for v in values]
    if method != "symbolic" and any(not -_FLOAT_MAX <= v <= _FLOAT_MAX if isinstance(v, (Fraction, float, int))
                                    else isinstance(v, complex) and not cmath.isfinite(v) for v in values):
        raise InputError(_OVERFLOW)
    return Solution(mech, cons, tuple(values), method, dof)


@takes_mechanism
def ratio(mech: Mechanism, output, input, *, ground=None, relative_to=None, method: str = "exact",
          held=(), joined=()):
    """The speed ratio ``omega(output/ref) / omega(input/ref)`` of a one-dof mechanism.

    *ref* is ``relative_to``, or the ground. *output* and *input* may also be pairs
    ``(u, v)`` (or text ``"u/v"``) for relative speeds, as in Liu and Chen's
    ``theta_{8,1} / theta_{4,1}``. With ``method="symbolic"`` the result is an expression in
    the gear-ratio symbols ``e_a_b``.

    >>> import gearlib as gl
    >>> fig1 = gl.catalog.load("liu_chen_fig1")
    >>> gl.ratio(fig1, output=3, input=4, ground=5, method="symbolic")
    -e_4_1/(e_2_1*e_5_2 - 1)
    """
    if ground is None:
        ground = mech.ground
    ref = ground if relative_to is None else relative_to

    def split(x, what):
        if isinstance(x, str) and "/" in x:
            u, v = x.split("/", 1)
        elif isinstance(x, (tuple, list)) and len(x) == 2:
            u, v = x
        else:
            return (mech.resolve(x, what), ref)
        return (mech.resolve(u, what), mech.resolve(v, f"{what} reference"))

    inp = split(input, "input")
    out = split(output, "output")
    sol = speeds(mech, ground, {inp: 1}, method=method, held=held, joined=joined)
    value = sol.relative(*out)
    if method == "symbolic":
        return sympy.factor(value)
    return value
