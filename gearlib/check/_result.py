"""What a check returns: :class:`CheckResult`, for the reader and for a grader."""

from __future__ import annotations

import html
from dataclasses import dataclass, field
from types import MappingProxyType

__all__ = ["CheckResult"]


@dataclass(frozen=True)
class CheckResult:
    """The verdict of a check.

    ``passed`` and ``message`` are for the reader (the message is a hint when the answer is
    not right, and never holds the answer). A grader reads ``score`` out of ``points``
    (the exercise's difficulty in stars: one, two or three points; parts of an answer that
    are right count their share), ``exercise`` (``"1.3"``), ``variant`` (the seed the numbers
    were drawn from, ``None`` for the book's numbers) and ``details`` (which parts passed, a
    prediction recorded before the answer). Truthy when passed, so that an autograder test
    reads ``assert gl.check.<name>(answer), "..."``.
    """

    passed: bool
    message: str
    name: str = ""
    exercise: str = ""
    variant: str | None = None
    points: int = 1
    score: float = 0.0
    details: MappingProxyType = field(default_factory=lambda: MappingProxyType({}))

    def __bool__(self) -> bool:
        return self.passed

    @property
    def mark(self) -> str:
        if self.details.get("recorded") and self.passed:
            return "✎ Recorded."
        return "✔ Correct." if self.passed else "✘ Not yet."

    def __str__(self) -> str:
        return f"{self.mark} {self.message}".strip()

    def __repr__(self) -> str:
        return str(self)

    def _repr_html_(self) -> str:
        color = "#1a7f37" if self.passed else "#9a6700"
        return f"<p style='color:{color}'><b>{self.mark}</b> {html.escape(self.message)}</p>"

    def to_dict(self) -> dict:
        """Plain data for a grader or a JSON log (no answer in it)."""
        return {"name": self.name, "exercise": self.exercise, "variant": self.variant, "passed": self.passed,
                "score": self.score, "points": self.points, "message": self.message, "details": dict(self.details)}
