"""Errors raised by gearlib.

Every problem gearlib can diagnose raises a subclass of :class:`GearlibError`, with a
message that names the offending element (a link, a pair, a file, an input) and says
how to fix it. They also subclass :class:`ValueError`, so code that already catches
``ValueError`` keeps working.

What gearlib reports without refusing (data that can be analysed but could not be built as
given, such as a planetary set whose planets do not fit) is a Python warning of a subclass
of :class:`GearlibWarning`; ``warnings.simplefilter("error", gl.GearlibWarning)`` turns them
into errors.

>>> import gearlib as gl
>>> try:
...     gl.Mechanism.from_dict({"links": [1, 2], "gear_pairs": [{"gears": [1, 3], "teeth": [20, 40]}]})
... except gl.UnknownLinkError as err:
...     print(err)
gear pair (1, 3) refers to unknown link 3; declared links are 1, 2. Add 3 to `links` or fix the id.
"""

from __future__ import annotations

__all__ = [
    "GearlibError",
    "MechanismError",
    "DataFormatError",
    "UnknownLinkError",
    "DuplicateEdgeError",
    "SelfMeshError",
    "ToothNumberError",
    "CarrierError",
    "AxisError",
    "DisconnectedError",
    "OverconstrainedError",
    "ConstraintError",
    "InputError",
    "FileFormatError",
    "GeometryError",
    "GearlibWarning",
    "AssemblyWarning",
    "DataWarning",
]


class GearlibError(ValueError):
    """Base class of every error gearlib raises on purpose.

    The message is kept on one line: a control character that came from the user's data
    (a link id ``"\\n"``, a tab in a name) is shown escaped, so it cannot break a log or
    a notebook's error line.
    """

    def __init__(self, *args):
        if len(args) == 1 and isinstance(args[0], str):
            args = (_one_line(args[0]),)
        super().__init__(*args)


def _one_line(text: str) -> str:
    if text.isprintable():
        return text
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in text)


class MechanismError(GearlibError):
    """The description of a mechanism is malformed."""


class DataFormatError(MechanismError):
    """A field has the wrong type or shape (for example ``teeth: 20`` instead of ``[20, 40]``)."""


class UnknownLinkError(MechanismError):
    """A pair, an input or an option refers to a link the mechanism does not declare."""


class DuplicateEdgeError(MechanismError):
    """The same turning pair or gear pair (or link id) is given twice."""


class SelfMeshError(MechanismError):
    """A gear pair meshes a gear with itself, or a turning pair joins a link to itself."""


class ToothNumberError(MechanismError):
    """A tooth number is not a positive integer of sensible size."""


class CarrierError(MechanismError):
    """A gear pair has no possible carrier (transfer vertex), or more than one, or a wrong one."""


class AxisError(MechanismError):
    """Axis labels of turning pairs contradict each other."""


class DisconnectedError(MechanismError):
    """The graph of the mechanism falls apart into separate pieces."""


class OverconstrainedError(MechanismError):
    """Gear pairs close a loop whose ratios do not multiply to one: the loop locks its gears."""


class ConstraintError(GearlibError):
    """Inputs, held links or joined links contradict each other or the gear pairs."""


class InputError(ConstraintError):
    """The inputs do not fit the mechanism: wrong number, grounded link, or not independent."""


class FileFormatError(MechanismError):
    """A mechanism file cannot be read: missing, empty, not YAML/JSON, or not a mapping."""


class GeometryError(MechanismError):
    """Pitch radii or axis directions cannot be realised: centre distances that do not close a
    loop, radii that disagree with the tooth numbers, or a bevel gear that cannot lie on one cone."""


class GearlibWarning(UserWarning):
    """Base class of the warnings gearlib issues: the data can be analysed, but something in it
    deserves a look."""


class AssemblyWarning(GearlibWarning):
    """A planetary set fails an assembly condition: its planets are not concentric with the sun
    and ring (profile shift can offset a small difference), cannot be spaced equally, or
    collide with their neighbours (:func:`gearlib.assembly_conditions`)."""


class DataWarning(GearlibWarning):
    """Data that can be analysed but contradicts itself in a way that is probably a typing
    mistake: an ``internal`` gear pair whose Penaud angles make the ratio of an external mesh
    (or the reverse), a spur pair whose angles make a complex ratio. The data decide (the
    angles give the ratio); the warning says which field to check."""
