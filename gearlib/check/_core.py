"""The machinery behind exercise checks: the registry, variants, predictions, the result.

A check is registered with :func:`register`, which takes the function that computes the
reference answer from the problem's numbers and keeps it here, out of the check's reach: a
:class:`Check` object has no attribute, method, repr or message that carries the answer.
What the answer must look like, and how a wrong one is diagnosed, is the check's *spec*
(:class:`~gearlib.check.Value`, :class:`~gearlib.check.Symbolic`,
:class:`~gearlib.check.Choice`, :class:`~gearlib.check.Model`,
:class:`~gearlib.check.Design`, ...).

Variants: ``data`` holds the book's numbers and ``params(rng)`` draws other ones from a
:class:`random.Random` seeded by the check's name and the variant (a student id or an
int), through SHA-256, so that a variant has the same numbers in every process.
"""

from __future__ import annotations

import hashlib
import random
import re
from collections import OrderedDict
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from types import MappingProxyType

from ._read import Unreadable
from ._result import CheckResult
from ._spec import Spec, Verdict

__all__ = ["Check", "register", "register_custom", "KINDS", "Prediction", "REGISTRY"]

REGISTRY: dict[str, Check] = {}
_SECRETS: dict[str, _Secret] = {}
_PREDICTIONS: dict[tuple, str] = {}
_ATTEMPTED: set = set()

KINDS = {
    "compute": "compute by hand, then confirm with gearlib",
    "model": "model a mechanism from a sketch or a description into data",
    "derive": "derive a symbolic result",
    "design": "design or inverse problem with many right answers",
    "concept": "conceptual question with a reason",
    "mistake": "find the mistake in a derivation, a data file or a printed value",
    "predict": "predict, then compute",
    "explore": "explore with the library (a loop, a count over an atlas)",
}
_EXERCISE = re.compile(r"^\d{1,2}\.\d{1,2}$")


@dataclass(frozen=True)
class Prediction:
    """A guess the reader commits to before computing: one of ``choice``'s options.

    ``truth(reference, params)`` names the right option; ``explain`` (text, or a function of
    the params) is shown once the computed answer has passed.
    """

    choice: object
    truth: Callable
    explain: object = ""


@dataclass
class _Secret:
    compute: Callable
    spec: Spec
    data: dict
    params: Callable | None
    prediction: Prediction | None
    memo: OrderedDict = field(default_factory=OrderedDict)


def variant_key(variant) -> str | None:
    """The variant as text (``None`` for the book's numbers); ints and their text agree."""
    if variant is None:
        return None
    if isinstance(variant, bool) or not isinstance(variant, (int, str)):
        raise Unreadable("a variant is a student id (text) or a whole number")
    key = str(variant).strip()
    if not key or len(key) > 100:
        raise Unreadable("a variant is a non-empty student id of at most 100 characters")
    return key


def _rng(name: str, key: str) -> random.Random:
    digest = hashlib.sha256(f"gearlib.check\0{name}\0{key}".encode()).digest()
    return random.Random(int.from_bytes(digest[:8], "big"))


def _given(name: str, key: str | None) -> dict:
    secret = _SECRETS[name]
    if key is None or secret.params is None:
        return dict(secret.data)
    return dict(secret.params(_rng(name, key)))


def _state(name: str, key: str | None):
    """``(params, prepared reference)`` of a variant, computed once."""
    secret = _SECRETS[name]
    if key in secret.memo:
        secret.memo.move_to_end(key)
        return secret.memo[key]
    params = _given(name, key)
    reference = secret.spec.prepare(secret.compute(**params))
    secret.memo[key] = (params, reference)
    while len(secret.memo) > 128:
        secret.memo.popitem(last=False)
    return params, reference


def _sentence(message: str) -> str:
    """*message* with a full stop; a first word in lower case (an Unreadable message such as
    "no answer yet: ...") gets a capital, a symbol (``e_(1,2) is ...``) keeps its case."""
    message = message.strip()
    if message and message[-1] not in ".!?":
        message += "."
    if re.match(r"[a-z]+[ ,:]", message):
        message = message[0].upper() + message[1:]
    return message


def _show(value) -> str:
    if isinstance(value, Fraction):
        return f"{value.numerator}/{value.denominator}" if value.denominator != 1 else str(value.numerator)
    if isinstance(value, (list, tuple)):
        return ", ".join(_show(v) for v in value)
    return str(value)


class Check:
    """One exercise check: call it with an answer, ``check(answer, variant=None)``, to get a
    :class:`~gearlib.check.CheckResult`.

    Public: ``name``, ``exercise`` (``"1.3"``), ``title``, ``stars`` (difficulty, 1 to 3,
    also the points a grader gives), ``minutes`` (estimated time), ``kind`` (see
    ``gl.check.KINDS``), ``chapter`` (``"01"``), ``question`` (the statement, with
    ``{name}`` for the numbers of a variant), ``form`` (what kind of answer it takes);
    :meth:`given` and :meth:`statement` for a variant's numbers, :meth:`predict` for a guess
    recorded before the answer.
    """

    __slots__ = ("name", "exercise", "title", "stars", "minutes", "kind", "chapter", "question", "form")
    _PUBLIC = (*__slots__, "points", "given", "statement", "predict", "predicts", "variants", "info")

    def __init__(self, name, exercise, title, stars, minutes, kind, question, form):
        for key, value in zip(Check.__slots__, (name, exercise, title, stars, minutes, kind,
                                               f"{int(exercise.split('.')[0]):02d}", question, form)):
            object.__setattr__(self, key, value)

    def __setattr__(self, key, value):
        raise AttributeError("exercise checks are read-only")

    def __dir__(self):
        return sorted(self._PUBLIC)

    def __repr__(self) -> str:
        return (f"<check {self.exercise} {self.title!r} ({'★' * self.stars}, about {self.minutes} min): "
                f"gl.check.{self.name}(answer)>")

    @property
    def points(self) -> int:
        """The points a grader gives for a right answer: the difficulty in stars."""
        return self.stars

    @property
    def predicts(self) -> bool:
        """Whether the exercise asks for a prediction (:meth:`predict`) before the answer."""
        return _SECRETS[self.name].prediction is not None

    @property
    def variants(self) -> bool:
        """Whether other numbers can be drawn (``variant=`` a student id)."""
        return _SECRETS[self.name].params is not None

    def given(self, variant=None) -> dict:
        """The numbers of the problem statement for *variant* (the book's when ``None``)."""
        return _given(self.name, variant_key(variant))

    def statement(self, variant=None) -> str:
        """The question with the numbers of *variant* filled in."""
        given = self.given(variant)
        return re.sub(r"\{(\w+)\}", lambda m: _show(given[m.group(1)]) if m.group(1) in given else m.group(0),
                      self.question)

    def info(self) -> dict:
        """Plain data about the exercise (for a course kit's table of exercises)."""
        return {"name": self.name, "exercise": self.exercise, "title": self.title, "stars": self.stars,
                "minutes": self.minutes, "kind": self.kind, "chapter": self.chapter, "points": self.points,
                "form": self.form, "variants": self.variants, "predicts": self.predicts}

    def _result(self, passed, message, key, score=0.0, details=None) -> CheckResult:
        message = _sentence(message)
        return CheckResult(bool(passed), message, self.name, self.exercise, key,
                           self.points, round(score * self.points, 6), MappingProxyType(dict(details or {})))

    def predict(self, guess, variant=None) -> CheckResult:
        """Record a prediction before computing (exercises of kind ``predict``)."""
        try:
            key = variant_key(variant)
        except Unreadable as err:
            return self._result(False, str(err), None)
        secret = _SECRETS[self.name]
        if secret.prediction is None:
            return self._result(False, "This exercise asks for no prediction: give your answer to the check itself",
                                key)
        if (self.name, key) in _ATTEMPTED:
            kept = _PREDICTIONS.get((self.name, key))
            return self._result(False, f"Your answer has been checked already; the prediction you recorded before "
                                f"it stands ({kept!r})", key, details={"prediction": kept, "recorded": True})
        try:
            option = secret.prediction.choice.option(guess)
        except Unreadable as err:
            return self._result(False, str(err), key)
        _PREDICTIONS[(self.name, key)] = option
        return self._result(True, f"Prediction recorded: {option!r}. Now compute the answer and check it", key,
                            details={"prediction": option, "recorded": True})

    def __call__(self, answer, variant=None) -> CheckResult:
        try:
            key = variant_key(variant)
        except Unreadable as err:
            return self._result(False, str(err), None)
        secret = _SECRETS[self.name]
        details = {}
        if secret.prediction is not None:
            if (self.name, key) not in _PREDICTIONS:
                return self._result(False, f"First record your prediction: gl.check.{self.name}.predict(...) "
                                    "with one of the options of the exercise", key)
            details["prediction"] = _PREDICTIONS[(self.name, key)]
        _ATTEMPTED.add((self.name, key))
        try:
            secret.spec.check_form(answer)
        except Unreadable as err:
            return self._result(False, str(err), key, details=details)
        except Exception:  # the judge below says what is wrong in its own words
            pass
        try:
            params, reference = _state(self.name, key)
        except Exception as err:  # a bug in the check itself, not the reader's fault
            return self._result(False, f"This check could not compute its reference ({type(err).__name__}); "
                                "please report it", key)
        try:
            verdict = secret.spec.judge(answer, reference, params)
        except Unreadable as err:
            verdict = Verdict(False, str(err))
        except RecursionError:
            verdict = Verdict(False, "That answer is nested too deeply to read")
        except Exception as err:  # a check never crashes on a reader's answer
            verdict = Verdict(False, f"This answer could not be checked ({type(err).__name__}); give it in the form "
                              f"the exercise asks for: {secret.spec.form}")
        message = verdict.message
        details.update(verdict.details)
        if verdict.passed and secret.prediction is not None:
            truth = secret.prediction.truth(reference, params)
            right = details["prediction"] == truth
            details["prediction_right"] = right
            explain = secret.prediction.explain
            explain = explain(params) if callable(explain) else explain
            message = _sentence(message) + (" Your prediction was right." if right else
                        f" Your prediction ({details['prediction']!r}) was not.") + (f" {explain}" if explain else "")
        return self._result(verdict.passed, message, key, verdict.score if not verdict.passed else 1.0, details)


def register(name: str, *, exercise: str, title: str, stars: int = 1, minutes: int = 10, kind: str = "compute",
             question: str = "", answer: Spec | None = None, data: Mapping | None = None,
             params: Callable | None = None, predict: Prediction | None = None):
    """Decorator: register the function that computes the reference answer as check *name*.

    The function takes the problem's numbers as keyword arguments: ``data`` (the book's
    numbers, the default variant) or what ``params(rng)`` draws for a variant. ``answer``
    says what the answer looks like and how to diagnose a wrong one (default: a number,
    :class:`~gearlib.check.Value`). The decorated name becomes the :class:`Check`; the
    function is kept out of its reach. See the API page for a worked example.
    """
    from ._value import Value

    if not _EXERCISE.match(str(exercise)):
        raise ValueError(f"check {name!r}: exercise must be 'chapter.k' such as '1.3', got {exercise!r}")
    if stars not in (1, 2, 3):
        raise ValueError(f"check {name!r}: stars must be 1, 2 or 3, got {stars!r}")
    if kind not in KINDS:
        raise ValueError(f"check {name!r}: kind must be one of {', '.join(KINDS)}, got {kind!r}")
    if not (isinstance(minutes, int) and 0 < minutes <= 240):
        raise ValueError(f"check {name!r}: minutes must be a whole number of minutes, got {minutes!r}")
    spec = answer if answer is not None else Value()

    def deco(fn):
        if name in REGISTRY:
            raise ValueError(f"check {name!r} is registered twice")
        taken = [c.name for c in REGISTRY.values() if c.exercise == exercise]
        if taken:
            raise ValueError(f"exercise {exercise} is already check {taken[0]!r}")
        check = Check(name, exercise, title, stars, minutes, kind, question or (fn.__doc__ or "").strip(),
                      spec.form)
        _SECRETS[name] = _Secret(fn, spec, dict(data or {}), params, predict)
        REGISTRY[name] = check
        return check

    return deco


class _Custom(Spec):
    form = "the answer the exercise asks for"

    def __init__(self, accept):
        self.accept = accept

    def judge(self, answer, reference, params):
        ok, message = self.accept(answer, **params)
        return Verdict(bool(ok), message, float(bool(ok)))

    def example(self, reference, params):  # pragma: no cover - a custom check knows no example
        raise NotImplementedError


def register_custom(name: str, accept: Callable, *, exercise: str, title: str, stars: int = 1, minutes: int = 10,
                    kind: str = "compute", question: str = "", data=None, params=None) -> Check:
    """A check that judges the answer itself: ``accept(answer, **numbers) -> (ok, message)``.
    Prefer a spec (:class:`~gearlib.check.Choice`, :class:`~gearlib.check.Design`, ...): their
    messages are tested against leaks for every check."""
    return register(name, exercise=exercise, title=title, stars=stars, minutes=minutes, kind=kind,
                    question=question, answer=_Custom(accept), data=data, params=params)(lambda **_: None)


# for the tests of the machinery only: never shown to a reader
def _reference(check: Check, variant=None):
    return _state(check.name, variant_key(variant))


def _example(check: Check, variant=None):
    params, reference = _state(check.name, variant_key(variant))
    return _SECRETS[check.name].spec.example(reference, params)


def _forget_predictions() -> None:
    _PREDICTIONS.clear()
    _ATTEMPTED.clear()
