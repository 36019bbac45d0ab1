"""No exercise's answer is in view before it is solved: not in its chapter (the text and the
executed outputs the book build keeps), not in a catalogue description, not on the exercise
page. Numbers and expressions are compared by value: a fraction, a decimal that rounds the
answer to its digits (three or more significant figures), a whole number of three digits or
more; an expression or a matrix's entries are parsed out of the page and compared up to
algebra.

The chapter-level test needs the executed notebooks of a book build (``make book``; set
``BOOK_HTML`` to use another build); the helpers are tested here on their own.
"""

from __future__ import annotations

import json
import math
import os
import pathlib
import re
from fractions import Fraction

import pytest
import sympy
import yaml

import gearlib as gl
from gearlib.check import _core
from notebook_tools import ROOT

HTML = pathlib.Path(os.environ.get("BOOK_HTML", ROOT / "book" / "_build" / "html")).resolve()
EXECUTED = HTML.parent / "jupyter_execute"
NUMBER = re.compile(r"(?<![\w.])[-\u2212]?(?:\d+\.\d+|\.\d+|\d+)(?:\s*/\s*\d+)?(?![\w.])")
WORD = re.compile(r"\b(?!(?:pi|exp|sqrt|sin|cos|tan|log|Matrix)\b)[A-Za-z]{2,}\b(?![_(])")


def _notebook_text(path: pathlib.Path) -> str:
    """Markdown, code and every text output of a notebook."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    parts = []
    for cell in nb["cells"]:
        parts.append("".join(cell["source"]))
        for out in cell.get("outputs", []):
            if "text" in out:
                parts.append("".join(out["text"]))
            for kind, data in out.get("data", {}).items():
                # text, HTML, LaTeX and markdown outputs, and glue's records of them
                if re.search(r"text/(plain|html|latex|markdown)$", kind):
                    parts.append("".join(data) if isinstance(data, list) else str(data))
    return "\n".join(parts)


def _html_text(path: pathlib.Path) -> str:
    """The text of a built page (glued values are only there: the notebook keeps their code)."""
    import html

    page = path.read_text(encoding="utf-8")
    page = re.sub(r"<(script|style)\b.*?</\1>", " ", page, flags=re.S)
    return html.unescape(re.sub(r"<[^>]+>", " ", page))


def _catalogue_descriptions() -> str:
    texts = []
    for p in sorted((ROOT / "gearlib" / "catalog" / "data").glob("*.yaml")):
        data = yaml.safe_load(p.read_text(encoding="utf-8"))
        texts.append(str(data.get("description", "")))
    return "\n".join(texts)


def _numbers(text: str):
    """Every number written in *text*: (value as Fraction, significant figures or None if exact)."""
    for m in NUMBER.finditer(text.replace("\u2212", "-")):
        s = m.group(0).replace(" ", "")
        try:
            if "/" in s:
                p, q = s.split("/")
                if int(q) == 0:
                    continue
                yield Fraction(int(p), int(q)), None, s
            elif "." in s:
                digits = len(s.lstrip("-").replace(".", "").lstrip("0"))
                yield Fraction(s), digits, s
            else:
                yield Fraction(int(s)), None, s
        except (ValueError, ZeroDivisionError):
            continue


def _values(reference) -> list:
    """The numbers and expressions an answer consists of (a dict's parts, a matrix's entries)."""
    if isinstance(reference, dict):
        if "mech" in reference:
            return []  # a model: many right answers
        return [v for x in reference.values() for v in _values(x)]
    if isinstance(reference, sympy.MatrixBase):
        return [sympy.Matrix(reference)]
    if isinstance(reference, (frozenset, set, tuple, list, str)) or reference is None:
        return []  # links and choices: too small to find by value
    return [sympy.sympify(reference)]


def number_leaks(text: str, value) -> list[str]:
    """Numbers in *text* that show the number *value*."""
    try:
        z = complex(sympy.N(value, 30))
    except (TypeError, ValueError):
        return []
    if abs(z.imag) > 1e-12 * max(1.0, abs(z)) or not math.isfinite(z.real):
        return []  # complex answers are found as expressions
    x = z.real
    exact = value if isinstance(value, sympy.Rational) else None  # (nsimplify turned 8460/13 into powers)
    found = []
    for v, digits, s in _numbers(text):
        if digits is None:
            if exact is not None and v == Fraction(int(exact.p), int(exact.q)) and (v.denominator != 1 or abs(v) >= 100):
                found.append(s)
        elif digits >= 3 and x != 0 and float(v) != 0:
            if float(f"{abs(x):.{digits}g}") == abs(float(v)):
                found.append(s)
    return found


def _candidates(text: str, limit: int = 20000):
    """Pieces of *text* that may be expressions, read by the checks' own safe reader."""
    from gearlib.check._read import Unreadable, read_text

    seen = 0
    for line in text.splitlines():
        line = WORD.sub("|", line)  # prose between expressions separates them
        for piece in re.split(r"[,;=\[\]{}$|:]|\\\\|&", line):
            piece = piece.strip()
            if not piece or not re.search(r"[A-Za-z]_\d", piece) or len(piece) > 300:
                continue
            seen += 1
            if seen > limit:
                return
            try:
                yield read_text(piece, names=True, units=False).value
            except (Unreadable, TypeError, ValueError, ZeroDivisionError, RecursionError):
                continue


def expression_leaks(text: str, expr) -> list[str]:
    """Expressions in *text* equal to *expr* (up to algebra), or for a matrix, all of its
    entries that hold symbols found in the text."""
    from gearlib.check._compare import equivalent

    if isinstance(expr, sympy.MatrixBase):
        entries = [e for e in expr if sympy.sympify(e).free_symbols]
        cands = list(_candidates(text))
        hit = [e for e in entries if any(c.free_symbols == e.free_symbols and equivalent(c, e) for c in cands)]
        return [str(expr)] if entries and len(hit) == len(entries) else []
    if not expr.free_symbols:
        return []
    names = {s.name for s in expr.free_symbols}
    linear = any(n.startswith("omega_") for n in names)  # a constraint sum a_i omega_i = 0: any multiple shows it
    out = []
    for c in _candidates(text):
        if {s.name for s in c.free_symbols} == names and (equivalent(c, expr) or linear and _multiple(c, expr)):
            out.append(str(c))
    return out


def _multiple(a, b, points: int = 4) -> bool:
    """True when *a* is a constant non-zero multiple of *b* (their ratio is one number at
    random rational points)."""
    import random

    symbols = sorted(a.free_symbols | b.free_symbols, key=str)
    rng = random.Random(11)
    ratios = []
    for _ in range(3 * points):
        point = {x: sympy.Rational(rng.randint(2, 97), rng.randint(2, 31)) for x in symbols}
        try:
            va, vb = a.xreplace(point), b.xreplace(point)
        except (TypeError, ValueError, ZeroDivisionError):
            continue
        if vb == 0 or not (va.is_number and vb.is_number):
            continue
        ratios.append(sympy.nsimplify(va / vb))
        if len(ratios) >= points:
            break
    return len(ratios) >= points and ratios[0] != 0 and all(r == ratios[0] for r in ratios)


def leaks(text: str, reference) -> list[str]:
    out = []
    for v in _values(reference):
        if isinstance(v, sympy.MatrixBase) or v.free_symbols:
            out += expression_leaks(text, v)
        else:
            out += number_leaks(text, v)
            if not v.is_real:
                out += [f"complex {v}"] if any(
                    c.is_number and abs(complex(c) - complex(v)) < 1e-6 for c in _complex_numbers(text)) else []
    return out


def _complex_numbers(text: str):
    for m in re.finditer(r"\(?-?\d+\.?\d*\s*[+-]\s*\d+\.?\d*[ij]\)?", text):
        try:
            yield sympy.sympify(m.group(0).replace("i", "*I").replace("j", "*I"))
        except (sympy.SympifyError, SyntaxError, TypeError):
            continue


# ----------------------------------------------------------------------------- the helpers alone
def test_numbers_are_found_by_value_and_to_their_digits():
    text = "the carrier turns at 2/7, that is 0.2857 of it; 0.29 is too short to count; 1/12 and 0.0833"
    assert number_leaks(text, sympy.Rational(2, 7)) == ["2/7", "0.2857"]
    assert number_leaks(text, sympy.Rational(1, 12)) == ["1/12", "0.0833"]
    assert number_leaks("a ratio of 4/14", sympy.Rational(2, 7)) == ["4/14"]
    assert number_leaks("0.2858 and 2/9", sympy.Rational(2, 7)) == []
    assert number_leaks("mesh at 450 Hz, then 45 teeth", sympy.Integer(450)) == ["450"]
    assert number_leaks("teeth 2, 3", sympy.Integer(2)) == []  # small whole numbers are everywhere


def test_expressions_are_found_up_to_algebra():
    e12, e23 = sympy.symbols("e_1_2 e_2_3")
    text = "the ratio is -e_1_2*e_2_3/(1 - e_1_2*e_2_3) here"
    assert expression_leaks(text, e12 * e23 / (e12 * e23 - 1))
    assert not expression_leaks(text, 1 / (1 - e12 * e23))
    m = sympy.Matrix([[1, 1 / e12], [0, 1 / (e12 * e23)]])
    assert expression_leaks("A = Matrix([[1, 1/e_1_2], [0, 1/(e_2_3*e_1_2)]])", m)
    assert not expression_leaks("A = Matrix([[1, 1/e_1_2], [0, 1/e_2_3]])", m)


def test_a_constraint_is_found_up_to_a_factor():
    w3, w4, e12 = sympy.symbols("omega_3 omega_4 e_1_2")
    assert expression_leaks("the constraint -2*e_1_2*omega_3 + 2*omega_4 = 0", e12 * w3 - w4)
    assert not expression_leaks("the constraint e_1_2*omega_3 + omega_4 = 0", e12 * w3 - w4)
    assert not expression_leaks("a ratio 2*e_1_2 here", e12)  # other answers: equal up to algebra only


def _chapter_file(chapter: str, folder: pathlib.Path) -> pathlib.Path | None:
    hits = sorted(folder.glob(f"{chapter}_*.ipynb"))
    return hits[0] if hits else None


def _chapters():
    return sorted({c.chapter for c in map(gl.check.get, gl.check.names())})


@pytest.mark.parametrize("chapter", _chapters())
def test_no_answer_on_its_exercise_page_or_in_the_catalogue(chapter):
    page = _notebook_text(_chapter_file(chapter, ROOT / "exercises"))
    catalogue = _catalogue_descriptions()
    found = []
    for name in gl.check.names():
        check = gl.check.get(name)
        if check.chapter != chapter:
            continue
        _, reference = _core._reference(check)
        for where, text in (("exercise page", page), ("catalogue", catalogue)):
            hit = leaks(text, reference)
            if hit:
                found.append(f"{check.exercise} {name}: {where} shows {hit[:3]}")
    assert not found, "\n".join(found)


@pytest.mark.book
@pytest.mark.parametrize("chapter", _chapters())
def test_no_answer_in_its_executed_chapter_or_exercise_page(chapter):
    chapter_nb = _chapter_file(chapter, EXECUTED / "chapters")
    assert chapter_nb is not None, f"no executed chapter {chapter} in {EXECUTED}: build the book first"
    texts = {"chapter": _notebook_text(chapter_nb)}
    page = HTML / "chapters" / chapter_nb.with_suffix(".html").name
    if page.is_file():
        texts["chapter's page"] = _html_text(page)
    executed_page = _chapter_file(chapter, EXECUTED / "exercises")
    if executed_page is not None:
        texts["executed exercise page"] = _notebook_text(executed_page)
    found = []
    for name in gl.check.names():
        check = gl.check.get(name)
        if check.chapter != chapter:
            continue
        _, reference = _core._reference(check)
        for where, text in texts.items():
            hit = leaks(text, reference)
            if hit:
                found.append(f"{check.exercise} {name}: the {where} shows {hit[:3]}")
    assert not found, "\n".join(found)


@pytest.mark.book
def test_the_search_finds_what_earlier_exercises_leaked():
    """The answers the first exercises had in view (the reviews' list) are found in the
    executed chapters: a fraction, a decimal and an expression."""
    e = sympy.Symbol
    third = (e("e_1_7") * e("e_7_8") - 1) * (e("e_2_3") * e("e_3_5") - 1) / (
        e("e_1_6") * e("e_2_3") * e("e_3_5") * e("e_6_2") - e("e_2_3") * e("e_3_5") + 1)
    cases = [("01", sympy.Rational(17, 1176)), ("00", sympy.Rational(2, 7)), ("03", third),
             ("05", sympy.Float("0.7768966795436122"))]
    for chapter, old in cases:
        nb = _chapter_file(chapter, EXECUTED / "chapters")
        text = _notebook_text(nb) + _html_text(HTML / "chapters" / nb.with_suffix(".html").name)
        assert leaks(text, old), f"the search misses the answer {old} of an earlier exercise in chapter {chapter}"
