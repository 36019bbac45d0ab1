"""Checks for the exercises of chapter 5, Davies' efficiency (``exercises/05_davies_efficiency.ipynb``)."""

from __future__ import annotations

from .. import catalog
from ..mechanism.data import Mechanism
from ._core import Hint, close, register

_ZETA_PAIR = "A spur pair r1 = 1, r2 = 2, gear 1 driving, eta_12 = 0.97: the Coulomb coefficient zeta of the mesh."


def _near(value, rtol=1e-4):
    def test(answer, expected):
        try:
            return close(answer, value, rtol=rtol)
        except Exception:
            return False

    return test


def _pair_zeta(eta, driver_first=True):
    r1, r2 = 1, 2
    return r1 * r2 * (1 - eta) / (r1 + eta * r2) if driver_first else r1 * r2 * (1 - eta) / (r2 + eta * r1)


@register(
    "davies_pair_zeta",
    chapter="05",
    question=_ZETA_PAIR,
    hints=[
        Hint(_near(_pair_zeta(0.97, driver_first=False)),
             "That is the coefficient for gear 2 driving gear 1. Here gear 1 drives: the power reaching gear 2 is "
             "eta_12 times the power gear 1 sends into the mesh."),
        Hint(_near(0.03), "That is 1 - eta_12: zeta is a length (a lever arm), and it depends on both radii."),
    ],
    generic_hint="Write the mesh action as U (contact force) plus a friction torque zeta*U, take the powers at "
    "gear 1 and gear 2 relative to the frame, and solve eta_12 = P_21/P_12 for zeta.",
)
def davies_pair_zeta():
    from ..davies import efficiency

    res = efficiency(catalog.load("laus_simple_pair"), 0, 1, 2, eta=0.97)
    return abs(res.meshes[0].zeta)


def _epicyclic(z2=60, z4=35):
    mech = catalog.load("laus_epicyclic")
    if (z2, z4) != (60, 35):
        mech = mech.with_gear_pair((2, 3), teeth=(z2, z4), radii=(z2, z4))
    return mech


@register(
    "davies_epicyclic_efficiency",
    chapter="05",
    question="Laus's epicyclic train (z = 80, 60, 30, 35), carrier 5 input, annulus 2 output, both meshes 0.98.",
    hints=[
        Hint(_near(0.88912), "That is eq. (78), the formula for annulus 2 as the input: the input/output choice "
             "decides which formula applies, and here the carrier drives."),
        Hint(_near(1.12474), "An efficiency above 1 is impossible: that formula assumes r1 > r2. Choose the formula "
             "with the pitch radii (40 and 60 mm), not the tooth numbers (80 and 60)."),
        Hint(_near(0.9604), "That is the efficiency of the train with the carrier held (0.98 squared). With the carrier "
             "turning, the meshes handle 2.8 times the input power."),
    ],
    generic_hint="Find which gear drives in each mesh from the virtual power flow relative to the carrier, then use "
    "the matching formula of Table 5 with eta_13 = eta_42 = 0.98.",
    standard_hints=True,
)
def davies_epicyclic_efficiency():
    from ..davies import efficiency

    return efficiency(_epicyclic(), 1, 5, 2, eta=0.98).value


@register(
    "davies_recirculation",
    chapter="05",
    question="Epicyclic train with annulus 2 of 64 teeth and planet gear 4 of 39 teeth (module 2 mm), other data as "
    "in the chapter: lossless virtual power through mesh 1-3 per unit input power.",
    hints=[
        Hint(_near(1.0), "That is the real power flow (seen from the frame). Measure the flow from the carrier 5."),
        Hint(_near(2.8), "That is the value for the chapter's train (60 and 35 teeth); the radii changed."),
    ],
    generic_hint="Relative to the carrier the flow through mesh 1-3 is T_A t_A r1 r4 / (r1 r4 - r2 r3), with the "
    "pitch radii in mm.",
)
def davies_recirculation():
    from ..davies import efficiency

    res = efficiency(_epicyclic(64, 39), 1, 5, 2, eta=1.0)
    return res.mesh(1, 3).virtual_power


@register(
    "davies_humpage_efficiency",
    chapter="05",
    question="Humpage's bevel reducer (Nelson and Cipra's teeth), input 1, output 4, frame 5, every mesh 0.99.",
    hints=[
        Hint(_near(0.597708), "That is what the thesis's printed planet axis gives. Its carrier turns at 1155/2352 of "
             "the input instead of 5/24: use the axis consistent with the pitch cones (or the Willis equations)."),
        Hint(_near(0.970299), "That is 0.99 cubed: it ignores the power recirculating through the planet meshes."),
    ],
    generic_hint="Use formula (H1) of the chapter with eta_12 = eta_25 = eta_43 = 0.99 and the radii 20, 56, 24, 35, 76.",
)
def davies_humpage_efficiency():
    from ..davies import efficiency

    return efficiency(catalog.humpage(), 5, 1, 4, eta=0.99).value


@register(
    "davies_humpage_driver",
    chapter="05",
    question="Humpage's reducer driven from the output shaft 4 (frame 5): which link drives in the mesh between the "
    "planet 2 and the fixed gear 5?",
    hints=[
        Hint(lambda a, e: close(a, 2), "With shaft 1 as the input the planet drives gear 5; reversing the ports "
             "reverses every carrier-relative flow."),
    ],
    generic_hint="Take the lossless virtual power flow of the mesh relative to the carrier 6: its sign says which gear "
    "gives power to the other. Answer with a link id.",
    standard_hints=False,
)
def davies_humpage_driver():
    from ..davies import efficiency

    res = efficiency(catalog.humpage(), 5, 4, 1, eta=0.98)
    return res.mesh(5, 2).driver


@register(
    "davies_pair_bearings",
    chapter="05",
    question="Simple pair with eta_12 = 0.97 and Coulomb bearings of efficiency 0.99 at the input and at the output.",
    hints=[
        Hint(_near(0.97), "That leaves out the two bearings: each takes its own share of the power."),
        Hint(_near(0.99 * 0.97), "One bearing is missing: both port bearings lose power."),
    ],
    generic_hint="With the port bearings' efficiencies defined as in Laus eqs. (45) and (47), the overall efficiency "
    "is a product.",
)
def davies_pair_bearings():
    from ..davies import efficiency

    mech: Mechanism = catalog.load("laus_simple_pair")
    # bearing coefficients giving 0.99 at each port (Laus eqs. 46 and 48, gear 1 driving)
    zc = abs(efficiency(mech, 0, 1, 2, eta=0.97).meshes[0].zeta)
    r1, r2 = 1, 2
    za = (1 - 0.99) * (r1 + zc) / 0.99
    zb = (1 - 0.99) * (r2 - zc)
    return efficiency(mech, 0, 1, 2, eta=0.97, bearings={"A": za, "B": zb}).value
