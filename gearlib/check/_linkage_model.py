"""Answers that are a linkage (chapter 7): :class:`LinkageModel`, checked by what the linkage
does over one turn of its crank, whatever link ids and drawn pose the reader chose."""

from __future__ import annotations

from collections.abc import Mapping

from ._model import MAX_TEXT, _bounded_data
from ._read import Unreadable
from ._spec import Spec, Verdict

__all__ = ["LinkageModel"]


class LinkageModel(Spec):
    """A linkage modelled by the reader (the dict of ``gl.linkages.Linkage.from_dict``, a
    ``Linkage``, or YAML text) with a revolute joint ``A`` driven by a port and a prismatic
    joint ``D`` with a port: compared with the reference by the efficiency over one turn of
    ``A`` under a constant unit torque, and by the stroke of ``D``."""

    form = "a dict as in gl.linkages.Linkage.from_dict (or YAML text), with joints named 'A' and 'D'"

    def _linkage(self, answer):
        from ..errors import GearlibError
        from ..linkages.data import Linkage
        from ..linkages.io import loads

        if answer is None:
            raise Unreadable("no answer yet: replace `None` with your linkage (a dict as in gl.linkages.Linkage"
                             ".from_dict)")
        try:
            if isinstance(answer, Linkage):
                linkage = answer
            elif isinstance(answer, str):
                if len(answer) > MAX_TEXT:
                    raise Unreadable("the text is far longer than this linkage needs")
                linkage = loads(answer, where="your data")
            elif isinstance(answer, Mapping):
                linkage = Linkage.from_dict(dict(_bounded_data(dict(answer))))
            else:
                raise Unreadable("give a linkage: the dict of gl.linkages.Linkage.from_dict, or YAML text")
        except GearlibError as err:
            raise Unreadable(f"your data: {err}") from None
        except (TypeError, ValueError, AttributeError, KeyError, RecursionError, OverflowError):
            raise Unreadable("your data cannot be read as a linkage: see gl.linkages.Linkage.from_dict") from None
        if len(linkage.links) > 12 or len(linkage.joints) > 12:
            raise Unreadable("your linkage has far more links or joints than this one needs")
        names = {j.name: j for j in linkage.joints}
        if "A" not in names or names["A"].kind != "revolute" or "D" not in names or names["D"].kind != "prismatic":
            raise Unreadable("name the crank's revolute joint 'A' and the slide's prismatic joint 'D'")
        ports = {p.joint: p for p in linkage.ports if p.joint is not None}
        if "A" not in ports or "D" not in ports:
            raise Unreadable("put a port on joint A (the crank torque) and one on joint D (the slider's force)")
        if ports["A"].role != "input" or ports["D"].role != "output":
            raise Unreadable("the crank drives: its port is the input, the slider's the output")
        if linkage.dof != 1:
            raise Unreadable(f"your linkage has {linkage.dof} degrees of freedom; a slider-crank has one")
        return linkage, ports["A"].name

    def _behaviour(self, linkage, port):
        from ..linkages.rating import cycle

        res = cycle(linkage, "A", {port: 1})
        u = res.series(next(m.name for m in res.network.motion_cols if m.coupling == "D"))
        stroke = float(res.weights @ abs(u)) / 2   # the slider's travel over a turn is twice its stroke
        return res.efficiency, stroke

    def check_form(self, answer) -> None:
        self._linkage(answer)

    def prepare(self, reference):
        from ..linkages.data import Linkage

        linkage = Linkage.from_dict(reference)
        eff, stroke = self._behaviour(linkage, "A")
        return {"data": reference, "eff": eff, "stroke": stroke, "e": reference["joints"][2]["point"][1]}

    def example(self, reference, params):
        return reference["data"]

    def judge(self, answer, reference, params) -> Verdict:
        from ..errors import GearlibError

        linkage, port = self._linkage(answer)
        try:
            eff, stroke = self._behaviour(linkage, port)
        except GearlibError as err:
            return Verdict(False, f"Your linkage cannot turn its crank through a full turn: {err}")
        if abs(stroke - reference["stroke"]) > 1e-6 * reference["stroke"]:
            centred = 2.0  # a centred slider-crank's stroke is 2 a1
            if abs(stroke - centred) < 1e-6:
                return Verdict(False, "Your slider travels as far as a centred slider-crank's: the slide line must "
                               "pass at the height e above the crank's centre")
            return Verdict(False, "Your slider's stroke is not the one described: check the crank's and the "
                           "coupler's lengths and the height of the slide line")
        if abs(eff - 1) < 1e-12:
            return Verdict(False, "Your linkage loses nothing: give the slide its Coulomb friction")
        if abs(eff - reference["eff"]) > 1e-6:
            return Verdict(False, "Your linkage moves as described but loses another amount: check the friction "
                           "coefficient and which joint has it")
        return Verdict(True, "Well done: your model turns and loses like the linkage described", 1.0)
