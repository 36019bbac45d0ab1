"""The book's linkages with other numbers, and the thesis' closed forms.

* :func:`~gearlib.linkages.slider_crank` - the RRRP slider-crank (``laus_slider_crank``) with other lengths and
  friction; :func:`~gearlib.linkages.slider_crank_efficiency` - its efficiency over one turn at constant power,
  Laus's eqs. (120) (the crank drives) and (123) (the slider drives);
* :func:`~gearlib.linkages.three_upu` - the 3-UPU robot (``laus_3upu``) with other dimensions, friction laws, or
  without split prismatic pairs (the thesis' comparison model, section 4.3.4.4);
* :func:`~gearlib.linkages.slider_block` - a block on a guide loaded off its centre, and
  :func:`~gearlib.linkages.slider_modes`,
  the two friction modes of a slider (section 4.1) in closed form.

>>> import gearlib as gl
>>> round(gl.linkages.slider_crank_efficiency(1, 3, 0.1), 7), round(gl.linkages.slider_crank_efficiency(1, 3, 0.1, input="slider"), 7)
(0.9779364, 0.9784127)
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

from ..errors import InputError
from .data import Linkage
from .elements import Joint
from .io import load

__all__ = ["slider_crank", "three_upu", "slider_block", "slider_crank_efficiency", "slider_modes", "SliderModes"]


def slider_crank(a1: float = 1.0, a2: float = 3.0, mu: float = 0.1) -> Linkage:
    """The thesis' slider-crank with crank *a1*, coupler *a2* (> *a1*) and Coulomb coefficient
    *mu* at the slider."""
    if not (a1 > 0 and a2 > a1):
        raise InputError(f"a slider-crank turns round when 0 < a1 < a2; got a1 = {a1}, a2 = {a2}")
    return load("laus_slider_crank", parameters={"a1": a1, "a2": a2, "mu": mu})


def slider_crank_efficiency(a1: float, a2: float, mu: float, *, input: str = "crank") -> float:
    """Laus's closed forms: ``1 - (mu/pi) ln((a1 + a2)/(a2 - a1))`` (eq. 120, the crank drives)
    or ``pi / (pi + mu ln((a1 + a2)/(a2 - a1)))`` (eq. 123, the slider drives)."""
    if not (a1 > 0 and a2 > a1):
        raise InputError(f"the closed forms need 0 < a1 < a2; got a1 = {a1}, a2 = {a2}")
    g = math.log((a1 + a2) / (a2 - a1))
    if input == "crank":
        return 1 - mu / math.pi * g
    if input == "slider":
        return math.pi / (math.pi + mu * g)
    raise InputError(f"input is 'crank' or 'slider', got {input!r}")


def three_upu(*, split: bool = True, location: str = "base", law: str | None = None, multiplier: float | None = None,
              **parameters) -> Linkage:
    """The thesis' 3-UPU robot. *parameters* override the file's (``rb``, ``rt``, ``lB``, ``lC``,
    ``mu``, ``r``, ``h``); *law* (``"cosine"``, ``"constant"``) or *multiplier* set the factor on
    the forces across the universal joints' pins. ``split=False`` gives the comparison model of
    section 4.3.4.4: one prismatic coupling per limb at the ``location`` ``"base"``,
    ``"middle"`` or ``"platform"`` end, its friction from the forces it carries alone."""
    robot = load("laus_3upu", parameters=parameters or None)
    joints = []
    for j in robot.joints:
        if j.kind == "universal" and (law is not None or multiplier is not None):
            f = dataclasses.replace(j.friction, **({"law": law} if law is not None else {}),
                                    **({"multiplier": multiplier} if multiplier is not None else {}))
            j = dataclasses.replace(j, friction=f)
        if j.split is not None and not split:
            ends = {"base": j.point, "platform": robot.joint(_platform_joint(robot, j)).point}
            if location not in ("base", "middle", "platform"):
                raise InputError(f"location is 'base', 'middle' or 'platform', got {location!r}")
            point = ends.get(location) or tuple((a + b) / 2 for a, b in zip(ends["base"], ends["platform"]))
            j = Joint(j.name, "prismatic", j.links, point, axis=j.axis, normal=j.normal, friction=j.friction)
        joints.append(j)
    return robot.replace(joints=tuple(joints), name=robot.name + ("" if split else f", unsplit ({location})"))


def _platform_joint(robot, prismatic) -> str:
    rod = prismatic.head
    return next(j.name for j in robot.joints if j.kind == "universal" and rod in j.links)


def slider_block(length: float = 1.0, mu: float = 0.1, *, point=(0.0, 0.5), direction=(1.0, -1.0),
                 contacts: str = "ends") -> Linkage:
    """A block of *length* sliding along x on a frame, pushed by a force at port ``P`` (along
    the guide) against a load ``Q`` at *point* (relative to the block's centre) along
    *direction*. The guide is split into two contacts fixed in the block, at its ends
    (``"ends"``: the clearance model of Fig. 13b) or at a third of its length from the centre
    (``"thirds"``: the triangular pressures of Fig. 13a, in their second mode). Task ``push``:
    one unit of travel at unit speed under a unit load."""
    if not length > 0:
        raise InputError(f"the block's length must be positive, got {length}")
    half = {"ends": length / 2, "thirds": length / 3}.get(contacts)
    if half is None:
        raise InputError(f"contacts are 'ends' or 'thirds', got {contacts!r}")
    return Linkage.from_dict({
        "name": f"block on a guide ({contacts})", "space": "planar", "links": {0: "frame", 1: "block"}, "ground": 0,
        "joints": [{"name": "G", "kind": "prismatic", "links": [0, 1], "point": [0, 0], "axis": [1, 0],
                    "split": [[-half, 0], [half, 0]], "split_in": [1, 1], "split_names": ["G1", "G2"],
                    "friction": {"mu": mu}}],
        "ports": [{"name": "P", "joint": "G", "role": "input"},
                  {"name": "Q", "link": 1, "point": list(point), "force": list(direction), "role": "output"}],
        "tasks": {"push": {"time": [0, 1], "steps": 1, "motion": {"P": "t"}, "actions": {"Q": 1}}},
    })


@dataclass(frozen=True)
class SliderModes:
    """What :func:`~gearlib.linkages.slider_modes` finds: the ``mode`` (1: one normal reaction on the line of the
    load; 2: two reactions on opposite faces), the ``reactions`` and their ``places`` along the
    slider, and the ``friction`` force's size."""

    mode: int
    reactions: tuple
    places: tuple
    friction: float


def slider_modes(normal: float, moment: float, length: float, mu: float, *, model: str = "clearance") -> SliderModes:
    """The friction of a slider of *length* that carries a *normal* force whose moment about
    the slider's centre is *moment* (its line meets the guide at ``moment / normal``).

    ``model="clearance"`` puts the contacts of mode 2 at the slider's ends (Fig. 13b);
    ``"triangular"`` at a third of the length from the centre (triangular pressures, Fig. 13a),
    in which case mode 2 gives 3/2 of the clearance model's friction (Baranov's factor)."""
    if not length > 0 or mu < 0:
        raise InputError("need a positive length and mu >= 0")
    half = length / 2
    if abs(moment) <= abs(normal) * half:
        x = moment / normal if normal else 0.0
        return SliderModes(1, (normal,), (x,), mu * abs(normal))
    if model not in ("clearance", "triangular"):
        raise InputError(f"model is 'clearance' or 'triangular', got {model!r}")
    c = half if model == "clearance" else length / 3
    f1, f2 = normal / 2 - moment / (2 * c), normal / 2 + moment / (2 * c)
    return SliderModes(2, (f1, f2), (-c, c), mu * (abs(f1) + abs(f2)))
