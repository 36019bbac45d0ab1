"""Local gains of kinematic units (chapter 3).

Inside a kinematic unit with carrier *k*, the fundamental-circuit (Willis) equations
``theta_{b,k} = e_{a,b} theta_{a,k}`` chain along the gear tree: relative to the carrier every
gear *g* turns at ``c_g`` times the first gear, ``c_g`` the product of the ratios on the path
(Liu, Chen and Chang eq. (1); ``c_k = 0`` for the carrier). Any two coaxial links *z, w* of the
unit then turn relative to each other at ``c_z - c_w``, and the **local gain** from a local
input ``theta_{x,y}`` to a local output ``theta_{z,w}`` is

    G(z, w; x, y) = theta_{z,w} / theta_{x,y} = (c_z - c_w) / (c_x - c_y).

Rules 1-5 of the paper are the special cases of this formula (see :mod:`gearlib.gains.rules`, which
derives each in sympy from the circuit equations); :mod:`gearlib.gains.relation` combines local gains
along the propagation paths. Derived in chapter 3.

>>> import gearlib as gl
>>> ku2 = gl.kinematic_units(gl.catalog.load("liu_chen_fig1")).unit(2)
>>> gl.local_gain(ku2, output=(3, 5), input=(1, 5), method="symbolic")   # eq. (19)
-1/(e_2_1*e_5_2 - 1)
>>> gl.local_gain(ku2, output=(3, 5), input=(1, 5))
Fraction(1, 3)
"""

from __future__ import annotations
from dataclasses import dataclass, field
import sympy
from ..errors import ConstraintError, InputError
from ..units.unit import KinematicUnit
from .unit_tree import _pair, _tree

__all__ = ['local_gain', 'LocalGain', 'GainSymbol']


class GainSymbol(sympy.Symbol):
    """A sympy symbol for one local gain, printed ``G2(3,5;1,5)`` and in LaTeX as the paper's
    :math:`{}^{3,5}[\\mathrm{K4{-}1S}]_{1,5}`."""

    def __new__(cls, name, tex=None):
        obj = super().__new__(cls, name)
        if tex is not None:
            obj._tex = tex
        return obj

    def _latex(self, printer):
        return getattr(self, "_tex", self.name)


def local_gain(unit: KinematicUnit, output, input, *, method: str = "exact"):
    """The local gain ``theta_out / theta_in`` of a kinematic unit.

    *output* and *input* are pairs ``(z, w)`` (``theta_{z,w}``, z relative to w), text
    ``"z/w"``, or a single gear (relative to the carrier). Both must join coaxial links of the
    unit (a thin edge, g-c or g-g). Works for units of any size.

    >>> import gearlib as gl
    >>> ku2 = gl.kinematic_units(gl.catalog.load("liu_chen_transmission")).unit(2)
    >>> gl.local_gain(ku2, output=(8, 1), input=(2, 1), method="symbolic")  # Rule 5, corrected eq. (24)
    (e_1_7*e_7_8 - 1)/(e_1_6*e_6_2 - 1)
    """
    if method not in ("exact", "symbolic"):
        raise InputError(f"method must be 'exact' or 'symbolic', got {method!r}")
    if not isinstance(unit, KinematicUnit):
        raise InputError(f"local_gain needs a kinematic unit, such as gl.kinematic_units(mech).unit(1); got "
                         f"{type(unit).__name__}")
    z, w = _pair(unit, output, "output")
    x, y = _pair(unit, input, "input")
    c = _tree(unit).speed
    den = c(x, method) - c(y, method)
    if den == 0:
        raise ConstraintError(f"in {unit.name} links {x} and {y} always turn together; theta_{x},{y} cannot drive it")
    value = (c(z, method) - c(w, method)) / den
    if method == "symbolic":
        return sympy.factor(sympy.cancel(value))
    return value


@dataclass(frozen=True)
class LocalGain:
    """One local gain used in a propagation: unit, local output and input pairs, the rule it
    matches (1-5, or None), and its symbol."""

    unit: KinematicUnit
    output: tuple
    input: tuple
    symbol: GainSymbol = field(compare=False)

    @property
    def rule(self):
        from .rules import match_rule

        m = match_rule(self.unit, self.output, self.input)
        return m.rule if m else None

    @property
    def expression(self):
        """The gain in the gear-ratio symbols."""
        return local_gain(self.unit, self.output, self.input, method="symbolic")

    @property
    def value(self):
        return local_gain(self.unit, self.output, self.input)

    @property
    def latex(self) -> str:
        return self.symbol._latex(None)

    def __repr__(self) -> str:
        return str(self.symbol)

    def __str__(self) -> str:
        return f"{self.symbol} = theta_{self.output[0]},{self.output[1]} / theta_{self.input[0]},{self.input[1]} in " \
               f"{self.unit.name} ({self.unit.label})"


def _gain_symbol(unit, z, w, x, y) -> GainSymbol:
    name = f"G{unit.index}({z},{w};{x},{y})"
    kind = unit.label.replace("-", "{-}").replace(" ", r"\ ")
    tex = rf"{{}}^{{{z},{w}}}[\mathrm{{{kind}}}]_{{{x},{y}}}"
    return GainSymbol(name, tex)
