"""Answers that are one value: :class:`Value` (a number of a given kind) and :class:`Symbolic`
(an expression in given symbols), with the typical mistakes of each kind of quantity.

A number passes when it is exactly the reference, or within half a unit of its last digit
and given to at least ``figures`` significant figures; a right number with fewer figures is
told so ("right to 2 figures; give at least 3"). A wrong one is compared with the typical
mistakes of the exercise (:class:`Mistake`: the value a mistake gives, and what to say),
then with those of its kind of quantity:

=============  ==========================================================================
quantity       standard diagnoses
=============  ==========================================================================
``ratio``      sign; reciprocal (output over input); minus the reciprocal; measured
               relative to the carrier instead of the frame
``speed``      sign; rpm or Hz given for rad/s (or written with a unit: converted)
``frequency``  negative; rad/s (2 pi) or per minute given for Hz; the number of planets
``efficiency`` input and output exchanged (1/eta); the loss (1 - eta); a percentage without
               ``%``; one mesh's efficiency, or the product of the meshes' (``meshes=``);
               above 1; negative
``count``      not a whole number; negative
``length``     sign; a unit that does not fit
``number``     sign; reciprocal
=============  ==========================================================================
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from dataclasses import dataclass

import sympy

from ._compare import agreement, equivalent, numeric
from ._spec import Spec, Verdict
from ._read import Reading, Unreadable, read

__all__ = ["Value", "Symbolic", "Mistake", "Hint", "QUANTITIES"]


@dataclass(frozen=True)
class Mistake:
    """A typical mistake: ``value(expected, params)`` is what it gives (or a list of
    values, any of which it may give); ``message`` says what went wrong (never the answer)."""

    value: Callable
    message: str


@dataclass(frozen=True)
class Hint:
    """A condition on a wrong answer: ``test(answer, expected, params) -> bool`` (sympy values)."""

    test: Callable
    message: str


_TWO_PI = 2 * sympy.pi
# units of an angular rate, as multiples of 1 rad/s
_RATE = {"rad/s": sympy.Integer(1), "Hz": _TWO_PI, "rpm": _TWO_PI / 60, "deg/s": sympy.pi / 180}

SIGN = ("The size is right but the sign is not: count the external meshes from input to output (each reverses "
        "the direction relative to its carrier; an internal one keeps it); for bevel gears the sign follows the "
        "axis directions the exercise chose.")
RECIPROCAL = ("You have the reciprocal: in this book a speed ratio is output over input (input over output is the "
              "reduction).")
MINUS_RECIPROCAL = "You have minus the reciprocal: check which speed goes on top, and the sign."
FRAME = ("That looks like a speed measured relative to the carrier (or to the input) rather than to the frame: "
         "both speeds of the ratio are relative to the held link.")


def _standard(quantity: str, value: Value) -> list:
    if quantity == "ratio":
        return [Mistake(lambda e, p: -e, SIGN), Mistake(lambda e, p: 1 / e, RECIPROCAL),
                Mistake(lambda e, p: -1 / e, MINUS_RECIPROCAL), Mistake(lambda e, p: 1 - e, FRAME)]
    if quantity == "speed":
        return [Mistake(lambda e, p: -e, SIGN),
                Mistake(lambda e, p: e * 60 / _TWO_PI, "That number is the speed in revolutions per minute; the "
                        "question asks for rad/s (or write the unit after the number, as in '... rpm')."),
                Mistake(lambda e, p: e / _TWO_PI, "That number is the speed in revolutions per second; the "
                        "question asks for rad/s (one revolution is 2 pi rad).")]
    if quantity == "frequency":
        out = [Mistake(lambda e, p: e * _TWO_PI, "That number is in rad/s: the question asks for Hz, events per "
                       "second (divide by 2 pi, or write the unit after the number)."),
               Mistake(lambda e, p: e * 60, "That is the number of events per minute; the question asks for Hz."),
               Mistake(lambda e, p: e / _TWO_PI, "You divided by 2 pi once too often: a speed in Hz is already in "
                       "revolutions per second."),
               Hint(lambda a, e, p: numeric(a).real < 0, "A frequency counts events per second: give its size, which "
                    "is never negative.")]
        if value.planets is not None:
            out += [Mistake(lambda e, p: e * value.planets(p), "That is off by the number of planets: count how many "
                            "planets one defect meets per turn, and whether the question asks about one planet."),
                    Mistake(lambda e, p: e / value.planets(p), "That is off by the number of planets: a defect on a "
                            "gear that every planet meshes meets each of them in turn.")]
        return out
    if quantity == "efficiency":
        out = [Mistake(lambda e, p: 1 / e, "You have exchanged input and output (1/eta): an efficiency is the output "
                       "power over the input power, never above 1."),
               Mistake(lambda e, p: 1 - e, "That is the loss (1 - eta), the share of the power that is lost, not the "
                       "efficiency."),
               Mistake(lambda e, p: 100 * e, "That looks like a percentage: add a percent sign, or divide by 100.")]
        if value.meshes is not None:
            out += [Mistake(lambda e, p: sympy.Mul(*value.meshes(p)), "That is the product of the mesh efficiencies: "
                            "it holds when the carrier is held, but here the meshes carry a different power from the "
                            "input (seen from the carrier)."),
                    Mistake(lambda e, p: list(value.meshes(p)), "That is the efficiency of one mesh: the train's "
                            "efficiency combines every lossy mesh it has.")]
        out += [Hint(lambda a, e, p: numeric(a).real > 1, "An efficiency above 1 would make power: check which "
                     "formula applies (which gear drives in each mesh) and the radii you used."),
                Hint(lambda a, e, p: numeric(a).real < 0, "A negative efficiency means the train locks itself or runs "
                     "the other way: check the signs of the speeds and which gear drives.")]
        return out
    if quantity == "count":
        return [Hint(lambda a, e, p: numeric(a).real < 0, "A count cannot be negative.")]
    if quantity in ("length", "number"):
        out = [Mistake(lambda e, p: -e, "The size is right; the sign is not.")]
        return out + ([Mistake(lambda e, p: 1 / e, "You have the reciprocal.")] if quantity == "number" else [])
    raise ValueError(f"unknown quantity {quantity!r}; use one of {', '.join(QUANTITIES)}")


QUANTITIES = {"ratio": None, "speed": "rad/s", "frequency": "Hz", "efficiency": None, "count": None,
              "length": None, "number": None}
_GENERIC = {
    "ratio": "Go back to the Willis equation of each gear pair (speeds relative to its carrier) and eliminate "
             "step by step.",
    "speed": "Write the Willis equation of each gear pair with the known speeds put in, and solve for this one.",
    "frequency": "Find the speeds first; then count how many events happen per turn of the right relative speed.",
    "efficiency": "Find which gear drives in each mesh, then combine the mesh efficiencies with the power each "
                  "mesh carries.",
    "count": "Not this number: count again, one element at a time.",
    "length": "Not yet: write the powers at both gears and solve for the coefficient.",
    "number": "Not yet: go back over the method of the chapter step by step.",
}


def _with_unit(reading: Reading, unit: str | None, quantity: str) -> Reading:
    """The reading in the question's unit (converting rpm, rad/s, Hz), or Unreadable."""
    if reading.percent and quantity != "efficiency":
        raise Unreadable("a percent sign fits an efficiency; give this number without it")
    if reading.unit is None or reading.unit == unit:
        return reading
    if unit is None:
        raise Unreadable(f"a {quantity} has no unit: give the number alone")
    if reading.unit in _RATE and unit in _RATE:
        f = _RATE[reading.unit] / _RATE[unit]
        spread = complex(reading.spread)
        if reading.exact and reading.value.is_Integer:
            spread = 0.5  # "2827 rad/s": a whole number with a unit is rounded to units
        return dataclasses.replace(reading, value=reading.value * f, spread=spread * float(f), unit=unit)
    raise Unreadable(f"that unit does not fit: give the answer in {unit}")


def _matches(reading: Reading, value, figures: int) -> bool:
    try:
        ag = agreement(reading, sympy.sympify(value))
    except (ValueError, TypeError, ZeroDivisionError):
        return False
    return ag.equal or ag.within or ag.right >= max(3, figures)


class Value(Spec):
    """A number of one kind of ``quantity`` (see the module's table).

    ``figures``: significant figures a decimal answer must give; ``exact=True`` asks for the
    exact value (a decimal right to its digits is told to give the fraction);
    ``mistakes``/``hints``: the exercise's own diagnoses, tried before the standard ones
    (``standard=False`` leaves those out); ``unit``: the unit of the answer (``"Hz"``,
    ``"rad/s"``; other units of the same kind are converted); ``meshes(params)``: the mesh
    efficiencies of an efficiency question; ``planets(params)``: the number of planets of a
    frequency question; ``generic``: the last hint, when nothing more specific applies.
    """

    def __init__(self, quantity: str = "number", *, figures: int = 3, exact: bool = False, mistakes=(), hints=(),
                 standard: bool = True, unit: str | None = "", meshes: Callable | None = None,
                 planets: Callable | None = None, generic: str | None = None):
        if quantity not in QUANTITIES:
            raise ValueError(f"unknown quantity {quantity!r}; use one of {', '.join(QUANTITIES)}")
        self.quantity, self.figures, self.exact = quantity, figures, exact
        self.unit = QUANTITIES[quantity] if unit == "" else unit
        self.meshes, self.planets = meshes, planets
        self.mistakes = [*mistakes, *hints, *(_standard(quantity, self) if standard else [])]
        self.generic = generic or _GENERIC[quantity]
        what = {"count": "a whole number", "efficiency": "a number between 0 and 1 (or with %)"}.get(
            quantity, "a number: an int, a Fraction, a decimal, a complex number, or text such as 'p/q'")
        self.form = what + (f", in {self.unit}" if self.unit else "")

    def prepare(self, reference):
        # a float reference (computed numerically) is kept as it is: no guessing of a fraction
        return sympy.Float(reference, 17) if isinstance(reference, float) else sympy.sympify(reference)

    def example(self, reference, params):
        return reference

    def check_form(self, answer) -> None:
        _with_unit(read(answer), self.unit, self.quantity)

    def judge(self, answer, reference, params) -> Verdict:
        raw = read(answer)
        reading = _with_unit(raw, self.unit, self.quantity)
        if self.quantity == "count" and not (reading.exact and reading.value.is_Integer):
            return Verdict(False, "A count is a whole number")
        try:
            ag = agreement(reading, reference)
        except ValueError:
            return Verdict(False, "That number is far too large for this question")
        if ag.equal:
            return Verdict(True, "Well done", 1.0)
        if ag.within:
            if self.exact:
                return Verdict(False, f"Right to {_n(ag.given)}; the exercise asks for the exact value, as a fraction "
                               "(Fraction(p, q) or text 'p/q')", details={"figures": ag.given})
            if ag.given >= self.figures:
                return Verdict(True, "Well done (right to the digits you gave)", 1.0, {"figures": ag.given})
            return Verdict(False, f"Right to {_n(ag.given)}; give at least {self.figures} significant figures",
                           details={"figures": ag.given})
        if not reading.exact and not self.exact and ag.right >= self.figures:
            return Verdict(True, f"Well done: right to {_n(ag.right)} (the digits after that are off: was an "
                           "intermediate result rounded?)", 1.0, {"figures": ag.right})
        if raw.unit is not None and raw.unit != self.unit and _matches(dataclasses.replace(raw, unit=None), reference,
                                                                       self.figures):
            return Verdict(False, f"The number is right but the unit is not: that number is the answer in "
                           f"{self.unit}, and {raw.unit} is another unit (write {self.unit}, or no unit)")
        for m in self.mistakes:
            try:
                if isinstance(m, Mistake):
                    wrongs = m.value(reference, params)
                    wrongs = wrongs if isinstance(wrongs, (list, tuple)) else [wrongs]
                    for wrong in map(sympy.sympify, wrongs):
                        if agreement(Reading(wrong), reference).right >= 6:
                            continue  # this mistake gives the right answer here: it is no mistake
                        if _matches(reading, wrong, self.figures):
                            return Verdict(False, m.message)
                elif m.test(reading.value, reference, params):
                    return Verdict(False, m.message)
            except (ValueError, TypeError, ZeroDivisionError, ArithmeticError):
                continue
        if not reading.exact and ag.right >= 3:
            return Verdict(False, f"Right to {_n(ag.right)}, but the next digit is off: keep more digits through the "
                           "intermediate steps", details={"figures": ag.right})
        return Verdict(False, self.generic)


def _n(figures) -> str:
    return "every digit" if figures == math.inf else f"{figures} significant figure{'s' if figures != 1 else ''}"


def _plain(expr):
    """The expression with every symbol replaced by a plain one of the same name (a reader's
    ``Symbol("e_1_2", positive=True)`` is the book's ``e_1_2``)."""
    return expr.xreplace({s: sympy.Symbol(s.name) for s in expr.free_symbols})


class Symbolic(Spec):
    """An expression in the symbols ``symbols`` (names), checked up to algebra: equal at
    random rational points (exactly for rational functions, to 30 digits otherwise).

    ``values(params)`` gives the symbols' values for the exercise's numbers, so that a number
    given instead of the formula, or a formula right only for these numbers, is recognised;
    ``mistakes`` are :class:`Mistake` objects whose ``value`` is an expression.
    """

    def __init__(self, symbols, *, values: Callable | None = None, mistakes=(), generic: str | None = None,
                 standard: bool = True):
        self.symbols = tuple(symbols)
        self.values, self.generic = values, generic or ("Not this expression: write the Willis equation of each "
                                                        "gear pair and eliminate the unknown speeds one at a time.")
        std = [Mistake(lambda e, p: -e, "The expression has the wrong sign: check each relative speed "
                       "(omega_b - omega_c, not omega_c - omega_b)."),
               Mistake(lambda e, p: 1 / e, "You have the reciprocal: output over input."),
               Mistake(lambda e, p: -1 / e, "You have minus the reciprocal: check which speed goes on top, and the "
                       "sign.")]
        self.mistakes = [*mistakes, *(std if standard else [])]
        self.form = "an expression in " + ", ".join(self.symbols) + " (sympy or text)"

    def prepare(self, reference):
        return _plain(sympy.sympify(reference))

    def check_form(self, answer) -> None:
        read(answer, names=True)

    def judge(self, answer, reference, params) -> Verdict:
        reading = read(answer, names=True)
        value = _plain(reading.value)
        used = {s.name for s in value.free_symbols}
        extra = sorted(used - set(self.symbols))
        if extra:
            return Verdict(False, f"Your answer uses {', '.join(extra)}, which this question does not use; write it "
                           f"in {', '.join(self.symbols)}")
        subs = {sympy.Symbol(k): sympy.sympify(v) for k, v in (self.values(params) if self.values else {}).items()}
        if not used and reference.free_symbols:
            if subs and agreement(reading, reference.xreplace(subs)).within:
                return Verdict(False, "That is the value for the numbers of the exercise; the question asks for the "
                               "formula, in the symbols")
            return Verdict(False, "Give the answer as a formula in the symbols of the question, not as a number")
        if equivalent(value, reference):
            return Verdict(True, "Well done", 1.0)
        for m in self.mistakes:
            try:
                wrong = _plain(sympy.sympify(m.value(reference, params)))
                if not equivalent(wrong, reference) and equivalent(value, wrong):
                    return Verdict(False, m.message)
            except (ValueError, TypeError, ZeroDivisionError, ArithmeticError):
                continue
        if subs:
            try:
                at = value.xreplace(subs)
                if at.is_number and agreement(Reading(at), reference.xreplace(subs)).equal:
                    return Verdict(False, "Right for the numbers of the exercise, but not as a formula: a step used "
                                   "their values; keep every ratio a symbol")
            except (ValueError, TypeError, ZeroDivisionError):
                pass
        return Verdict(False, self.generic)
