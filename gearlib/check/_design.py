"""Answers with many right ones: :class:`Design` (choose numbers that meet conditions) and
:class:`Matrix` (a matrix, optionally up to the order of its rows and a factor per row).

A design is a dict of named fields (tooth numbers, a number of planets, efficiencies,
links); the check tests each :class:`Condition` in turn and says which one a wrong design
breaks. Any design that meets every condition passes.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import sympy

from ._choice import _link, normalise
from ._compare import equivalent, proportional
from ._spec import Spec, Verdict
from ._read import Unreadable, read

__all__ = ["Design", "Condition", "Matrix"]

FIELDS = {"teeth": (1, 10_000), "count": (1, 100), "number": None, "efficiency": None, "link": None}


@dataclass(frozen=True)
class Condition:
    """``test(design, params) -> bool``; ``message`` (text, or a function of the design and
    the params) says what the condition is and that the design breaks it."""

    name: str
    test: Callable
    message: object


class Design(Spec):
    """A design: ``fields`` ``{name: kind}`` (kinds: ``teeth``, ``count``, ``number``,
    ``efficiency``, ``link``), ``conditions`` in the order they are tested, and ``example``,
    a function of the params giving one valid design (for the tests; never shown)."""

    def __init__(self, fields: Mapping, conditions, *, example: Callable):
        self.fields = dict(fields)
        self.conditions = tuple(conditions)
        self._example = example
        self.form = "a dict {" + ", ".join(f"{k!r}: ..." for k in self.fields) + "}"

    def example(self, reference, params):
        return self._example(params)

    def _read(self, answer) -> dict:
        if answer is None:
            raise Unreadable(f"no answer yet: replace `None` with {self.form}")
        if not isinstance(answer, Mapping):
            raise Unreadable(f"give your design as {self.form}")
        lookup = {normalise(k): k for k in self.fields}
        out = {}
        for k, v in list(answer.items())[:50]:
            key = lookup.get(normalise(k)) if isinstance(k, str) else None
            if key is None:
                raise Unreadable(f"{k!r} is not part of this design; give {self.form}")
            out[key] = self._value(key, v)
        missing = [k for k in self.fields if k not in out]
        if missing:
            raise Unreadable("your design leaves out " + ", ".join(missing))
        return out

    def _value(self, key, v):
        kind = self.fields[key]
        if kind in ("teeth", "count"):
            r = read(v)
            if not (r.exact and r.value.is_Integer):
                raise Unreadable(f"{key} must be a whole number")
            n = int(r.value)
            lo, hi = FIELDS[kind]
            if not lo <= n <= hi:
                raise Unreadable(f"{key} = {n} is out of range ({lo} to {hi})")
            return n
        if kind == "link":
            return _link(v)
        r = read(v)
        if not r.value.is_real:
            raise Unreadable(f"{key} must be a real number")
        x = float(r.value)
        if kind == "efficiency" and not 0 < x <= 1:
            raise Unreadable(f"{key} is an efficiency: between 0 and 1")
        return x

    def check_form(self, answer) -> None:
        self._read(answer)

    def judge(self, answer, reference, params) -> Verdict:
        design = self._read(answer)
        broken = []
        for c in self.conditions:
            try:
                ok = bool(c.test(design, params))
            except (ZeroDivisionError, ValueError, TypeError, ArithmeticError):
                ok = False
            if not ok:
                broken.append(c)
        if not broken:
            return Verdict(True, "Well done: your design meets every condition (" +
                           ", ".join(c.name for c in self.conditions) + ")", 1.0)
        first = broken[0]
        message = first.message(design, params) if callable(first.message) else first.message
        message = message.rstrip(".") + "."
        more = f" {len(broken) - 1} more condition{'s' if len(broken) > 2 else ''} to meet after this one." \
            if len(broken) > 1 else ""
        return Verdict(False, f"{first.name[:1].upper() + first.name[1:]}: {message}{more}", 1 - len(broken) / len(self.conditions),
                       {"broken": [c.name for c in broken]})


def _entries(answer, depth=0):
    if depth > 2:
        raise Unreadable("a matrix is a list of rows, each a list of entries")
    if hasattr(answer, "tolist"):
        answer = answer.tolist()
    if isinstance(answer, sympy.MatrixBase):
        answer = answer.tolist()
    if isinstance(answer, (list, tuple)):
        if len(answer) > 50:
            raise Unreadable("that matrix is far larger than this one")
        return [_entries(x, depth + 1) for x in answer]
    if depth != 2:
        raise Unreadable("give the matrix as a list of rows, each a list of entries")
    return read(answer, names=True).value


class Matrix(Spec):
    """A matrix of numbers or expressions. ``rows_free``: any order of the rows;
    ``row_scale``: each row up to a non-zero factor (a Willis equation times a number is the
    same equation); ``symbols``: the names it may use; ``rows``/``columns``: what the rows
    and columns stand for, in messages; ``mistakes``: :class:`~gearlib.check.Mistake`
    objects whose ``value`` is a matrix a typical mistake gives."""

    def __init__(self, *, rows_free: bool = False, row_scale: bool = False, symbols=(), rows: str = "rows",
                 columns: str = "columns", mistakes=(), generic: str = "Not this matrix yet."):
        self.rows_free, self.row_scale, self.symbols = rows_free, row_scale, tuple(symbols)
        self.mistakes = tuple(mistakes)
        self.rows, self.columns, self.generic = rows, columns, generic
        self.form = f"a list of rows ({rows}), each a list of entries ({columns})"

    def prepare(self, reference):
        m = sympy.Matrix(reference)
        return sympy.ImmutableMatrix(m.xreplace({s: sympy.Symbol(s.name) for s in m.free_symbols}))

    def example(self, reference, params):
        return reference.tolist()

    def check_form(self, answer) -> None:
        if answer is None:
            raise Unreadable(f"no answer yet: replace `None` with {self.form}")
        _entries(answer)

    def judge(self, answer, reference, params) -> Verdict:
        self.check_form(answer)
        rows = _entries(answer)
        if not rows or not all(isinstance(r, list) for r in rows) or len({len(r) for r in rows}) != 1:
            raise Unreadable(f"give {self.form}, every row of the same length")
        plain = [[x.xreplace({s: sympy.Symbol(s.name) for s in x.free_symbols}) for x in r] for r in rows]
        extra = sorted({s.name for r in plain for x in r for s in x.free_symbols} - set(self.symbols))
        if extra:
            return Verdict(False, f"Your matrix uses {', '.join(extra)}, which this question does not use")
        n, m = reference.shape
        ref_rows = [list(reference.row(i)) for i in range(n)]
        if (len(plain), len(plain[0])) != (n, m):
            if (len(plain), len(plain[0])) == (m, n) and n != m:
                return Verdict(False, f"The shape is transposed: the rows are {self.rows}, the columns {self.columns}")
            return Verdict(False, f"The shape is not right: {n} rows ({self.rows}) and {m} columns ({self.columns})")

        def same(a, b):
            return (proportional(a, b) if self.row_scale else all(equivalent(x, y) for x, y in zip(a, b)))

        if not self.rows_free:
            bad = [i for i in range(n) if not same(plain[i], ref_rows[i])]
            if not bad:
                return Verdict(True, "Well done", 1.0)
            for mistake in self.mistakes:
                wrong = sympy.Matrix(mistake.value(reference, params))
                if wrong.shape == (n, m) and all(same(plain[i], list(wrong.row(i))) for i in range(n)):
                    return Verdict(False, mistake.message)
            if n == m and all(equivalent(plain[j][i], ref_rows[i][j]) for i in range(n) for j in range(m)):
                return Verdict(False, f"That is the transpose: each row belongs to one of the {self.rows}")
            return Verdict(False, f"Row {bad[0] + 1} is not right. {self.generic}", 1 - len(bad) / n)
        unused = list(range(n))
        for i, row in enumerate(plain):
            k = next((j for j in unused if same(row, ref_rows[j])), None)
            if k is None:
                what = "a multiple of any" if self.row_scale else "any"
                return Verdict(False, f"Row {i + 1} of your matrix is not {what} of the rows it should have. "
                               f"{self.generic}", (n - len(unused)) / n)
            unused.remove(k)
        return Verdict(True, "Well done", 1.0)
