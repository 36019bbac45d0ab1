"""The interface of a check's spec: what an answer must look like and how a wrong one is
diagnosed (:class:`Spec`), and what a spec says of an answer (:class:`Verdict`)."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

__all__ = ["Spec", "Verdict"]


@dataclass(frozen=True)
class Verdict:
    """What a spec says of an answer: ``score`` is the share of the answer that is right."""

    passed: bool
    message: str
    score: float = 0.0
    details: Mapping = field(default_factory=dict)


class Spec:
    """What an answer must look like and how a wrong one is diagnosed (subclass it)."""

    form = "your answer"

    def prepare(self, reference):
        """The reference as the spec compares it (called once per variant)."""
        return reference

    def check_form(self, answer) -> None:
        """Raise :class:`~gearlib.check.Unreadable` if *answer* is not of the form asked for
        (run before the reference is computed, so a malformed answer is answered at once)."""

    def judge(self, answer, reference, params) -> Verdict:  # pragma: no cover - interface
        raise NotImplementedError

    def example(self, reference, params):
        """An answer that passes (for the tests of the machinery; never shown)."""
        return reference
