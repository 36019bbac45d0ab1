"""Answers that are a choice or a collection: :class:`Choice` (one option of a list, such as a
kind of linkage, or a reason), :class:`LinkId` (one link), :class:`LinkSet` (a set of
links), :class:`Groups` (a list of sets of links, such as kinematic units) and
:class:`Parts` (an answer in several parts, such as a choice and its reason, or the step
of a derivation that is wrong and the corrected value; each part is checked by its own
spec, and a grader gets the share of parts that are right).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Mapping

from ._spec import Spec, Verdict
from ._read import Unreadable

__all__ = ["Choice", "LinkId", "LinkSet", "Groups", "Parts", "normalise"]

MAX_ITEMS = 200


def _cap(text: str) -> str:
    """A capital for a first word in lower case; a symbol (``e_(2,7)``) keeps its case."""
    return text[:1].upper() + text[1:] if re.match(r"[a-z]+[ ,:']", text) else text


def normalise(text: str) -> str:
    """Lower case, letters and digits only: ``"Two-link chain"`` and ``"two link chain"`` agree."""
    text = str(text).casefold()
    for dash in ("\u2212", "\u2013", "\u2014"):
        text = text.replace(dash, "-")
    return re.sub(r"[^0-9a-z\u00c0-\u024f]", "", text)


class Choice(Spec):
    """One of ``options``: a list of texts, or ``{key: text}`` (then the key, such as ``"B"``,
    or the text is accepted). ``synonyms``: ``{option: [other ways to write it]}``;
    ``wrong``: ``{option: message}`` for a wrong option; ``generic``: the message for any other
    wrong option; ``normaliser``: how texts are compared (by default lower case, letters and
    digits only).
    The reference function returns the right option (its key)."""

    def __init__(self, options, *, synonyms: Mapping | None = None, wrong: Mapping | None = None,
                 generic: str = "Not this one: read the question again and weigh each option.",
                 normaliser: Callable = normalise):
        self.options = dict(options) if isinstance(options, Mapping) else {str(o): str(o) for o in options}
        self.norm = normaliser
        self._lookup = {}
        for key, text in self.options.items():
            for form in (key, text, *((synonyms or {}).get(key, ()))):
                self._lookup.setdefault(self.norm(form), key)
        self.wrong = dict(wrong or {})
        self.generic = generic
        self.form = "one of " + ", ".join(repr(k) for k in self.options)

    def option(self, answer) -> str:
        """The option an answer names, or :class:`Unreadable`."""
        if answer is None:
            raise Unreadable(f"no answer yet: replace `None` with {self.form}")
        if isinstance(answer, bool):
            raise Unreadable(f"give {self.form}, not True or False")
        if isinstance(answer, int):
            if answer.bit_length() > 64:
                raise Unreadable(f"that number is far too large: give {self.form}")
            answer = str(answer)
        if not isinstance(answer, str):
            raise Unreadable(f"give {self.form}, as text")
        if len(answer) > 400:
            raise Unreadable("the answer is too long; give the option, not an essay")
        key = self._lookup.get(self.norm(re.sub(r"^\(?\s*([A-Za-z0-9])\s*\)\s*$", r"\1", answer.strip())))
        if key is None:
            raise Unreadable(f"that is not one of the options: give {self.form}")
        return key

    def check_form(self, answer) -> None:
        self.option(answer)

    def prepare(self, reference):
        key = self._lookup.get(self.norm(str(reference)))
        if key is None:
            raise ValueError(f"the reference {reference!r} is not one of the options")
        return key

    def judge(self, answer, reference, params) -> Verdict:
        key = self.option(answer)
        if key == reference:
            return Verdict(True, "Well done", 1.0)
        return Verdict(False, self.wrong.get(key, self.generic))


def _link(x):
    if isinstance(x, bool):
        raise Unreadable("a link id is a number or a name, not True or False")
    if isinstance(x, int):
        return x
    if isinstance(x, float) and x.is_integer():
        return int(x)
    if hasattr(x, "is_Integer") and getattr(x, "is_Integer", False):
        return int(x)
    if isinstance(x, str):
        t = re.sub(r"^\s*link\s*", "", x.strip(), flags=re.IGNORECASE)
        if re.fullmatch(r"[+-]?\d{1,9}", t):
            return int(t)
        if re.fullmatch(r"[A-Za-z][A-Za-z0-9_'.-]{0,31}", t):
            return t
    raise Unreadable("a link id is a whole number (or the link's name in the data)")


class LinkId(Spec):
    """One link of a mechanism. ``links(params)``: the mechanism's link ids (an id that is not
    one gets its own message); ``wrong``: ``{link: message}``, or a function of the params
    returning one."""

    form = "a link id"

    def __init__(self, *, links: Callable | None = None, wrong=None,
                 generic: str = "Not that link: go back to the turning pairs and their axis labels."):
        self.links, self.wrong, self.generic = links, wrong or {}, generic

    def check_form(self, answer) -> None:
        if answer is None:
            raise Unreadable("no answer yet: replace `None` with a link id")
        if isinstance(answer, (list, tuple, set, dict)):
            raise Unreadable("this asks for one link")
        _link(answer)

    def judge(self, answer, reference, params) -> Verdict:
        self.check_form(answer)
        got = _link(answer)
        if got == reference:
            return Verdict(True, "Well done", 1.0)
        if self.links is not None and got not in set(self.links(params)):
            return Verdict(False, f"There is no link {got} in this mechanism")
        wrong = self.wrong(params) if callable(self.wrong) else self.wrong
        return Verdict(False, wrong.get(got, self.generic))


def _collection(answer, what: str) -> list:
    if answer is None:
        raise Unreadable(f"no answer yet: replace `None` with {what}")
    if isinstance(answer, str):
        parts = [p for p in re.split(r"[\s,;{}\[\]()]+", answer) if p]
        if len(parts) > MAX_ITEMS:
            raise Unreadable("too many items")
        return parts
    if isinstance(answer, (int,)) and not isinstance(answer, bool):
        return [answer]
    if isinstance(answer, (Mapping, bytes)) or not isinstance(answer, Iterable):
        raise Unreadable(f"give {what}")
    out = []
    for x in answer:
        out.append(x)
        if len(out) > MAX_ITEMS:
            raise Unreadable("too many items")
    return out


class LinkSet(Spec):
    """A set of links (a list, set or text such as ``"1, 3"``), order free. ``what`` names them
    in messages ("possible grounds"); ``too_few``/``too_many``: what to say when some are
    missing or some should not be there."""

    def __init__(self, *, what: str = "links", too_few: str = "", too_many: str = "", hints=()):
        self.what, self.too_few, self.too_many, self.hints = what, too_few, too_many, tuple(hints)
        self.form = "a list of link ids such as [1, 2]"

    def prepare(self, reference):
        return frozenset(reference)

    def example(self, reference, params):
        return sorted(reference, key=str)

    def check_form(self, answer) -> None:
        {_link(x) for x in _collection(answer, self.form)}

    def judge(self, answer, reference, params) -> Verdict:
        got = {_link(x) for x in _collection(answer, self.form)}
        if got == reference:
            return Verdict(True, "Well done", 1.0)
        for h in self.hints:
            if h.test(got, reference, params):
                return Verdict(False, h.message)
        missing, extra = reference - got, got - reference
        if missing and not extra:
            return Verdict(False, f"Some {self.what} are missing. {self.too_few}")
        if extra and not missing:
            return Verdict(False, f"Some of these are not {self.what}. {self.too_many}")
        return Verdict(False, f"Some {self.what} are missing, and some of these should not be there. {self.too_few}")


class Groups(Spec):
    """A list of groups of links (each a set), such as the kinematic units of a mechanism;
    order free. ``hints``: :class:`~gearlib.check.Hint` objects tested on the answer read as
    a list of frozensets."""

    def __init__(self, *, what: str = "groups", hints=(), generic: str = "Not these groups."):
        self.what, self.hints, self.generic = what, tuple(hints), generic
        self.form = "a list of sets of link ids, such as [{1, 2}, {3, 4}]"

    def prepare(self, reference):
        return sorted((frozenset(g) for g in reference), key=lambda g: sorted(map(str, g)))

    def example(self, reference, params):
        return [set(g) for g in reference]

    def check_form(self, answer) -> None:
        self._groups(answer)

    def _groups(self, answer) -> list:
        if isinstance(answer, str):
            raise Unreadable(f"give {self.form}, not text")
        groups = []
        for g in _collection(answer, self.form):
            if isinstance(g, (str, int)):
                raise Unreadable(f"give {self.form}: each group a set of links")
            groups.append(frozenset(_link(x) for x in _collection(g, "a set of links")))
        return groups

    def judge(self, answer, reference, params) -> Verdict:
        groups = self._groups(answer)
        if sorted(groups, key=lambda g: sorted(map(str, g))) == reference:
            return Verdict(True, "Well done", 1.0)
        if len(groups) != len(reference):
            return Verdict(False, f"That is a different number of {self.what}")
        for h in self.hints:
            if h.test(groups, reference, params):
                return Verdict(False, h.message)
        return Verdict(False, self.generic)


class Parts(Spec):
    """An answer in parts: ``{key: (label, spec)}``. The reader gives a dict with those keys,
    or a tuple in that order; the reference function returns ``{key: reference}``. Each part
    is judged by its spec; the score is the share of parts that are right."""

    def __init__(self, parts: Mapping):
        self.parts = dict(parts)
        self.form = ("a dict {" + ", ".join(f"{k!r}: ..." for k in self.parts) + "} or a tuple ("
                     + ", ".join(label for label, _ in self.parts.values()) + ")")

    def prepare(self, reference):
        return {k: spec.prepare(reference[k]) for k, (_, spec) in self.parts.items()}

    def example(self, reference, params):
        return {k: spec.example(reference[k], params) for k, (_, spec) in self.parts.items()}

    def _split(self, answer) -> dict:
        keys = list(self.parts)
        if answer is None:
            raise Unreadable(f"no answer yet: give {self.form}")
        if isinstance(answer, Mapping):
            lookup = {normalise(k): k for k in keys}
            out = {}
            for k, v in list(answer.items())[:MAX_ITEMS]:
                if not isinstance(k, str) or normalise(k) not in lookup:
                    raise Unreadable(f"unknown part {k!r}: give {self.form}")
                out[lookup[normalise(k)]] = v
            return out
        if isinstance(answer, (tuple, list)) and len(answer) == len(keys):
            return dict(zip(keys, answer))
        raise Unreadable(f"give {self.form}")

    def check_form(self, answer) -> None:
        self._split(answer)

    def judge(self, answer, reference, params) -> Verdict:
        given = self._split(answer)
        right, notes, details = 0, [], {}
        for k, (label, spec) in self.parts.items():
            if k not in given or given[k] is None:
                notes.append(f"{_cap(label)}: not given yet.")
                details[k] = False
                continue
            try:
                v = spec.judge(given[k], reference[k], params)
            except Unreadable as err:
                v = Verdict(False, str(err))
            details[k] = v.passed
            right += v.passed
            if not v.passed:
                notes.append(f"{_cap(label)}: {_cap(v.message.rstrip('.'))}.")
        if right == len(self.parts):
            return Verdict(True, "Well done: every part is right", 1.0, details)
        ok = [label for k, (label, _) in self.parts.items() if details.get(k)]
        both = ", ".join(ok[:-1]) + " and " + ok[-1] if len(ok) > 1 else "".join(ok)
        head = _cap(both) + (" is" if len(ok) == 1 else " are") + " right. " if ok else ""
        return Verdict(False, head + " ".join(notes), right / len(self.parts), details)
