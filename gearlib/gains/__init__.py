"""Unit-by-unit gains: chapter 3 (planetary trains, automatic transmissions, geared robots).

Liu, Chen and Chang (2004, Sec. 3-4) find the relation between a mechanism's inputs and its
output unit by unit: a local gain inside each kinematic unit (Rules 1-5), and the propagation
of motion through the common linkages. Chen (1998) did the same for geared robot wrists with
transmission and input units and a structure matrix. This package holds

* ``unit_tree`` and ``local`` - speeds inside a unit and its local gains;
* ``rules`` - Rules 1-5, derived in sympy and matched to a unit;
* ``propagation`` and ``relation`` - the propagation plan from inputs to output
  (:func:`~gearlib.plan`) and the global relation it gives (:func:`~gearlib.propagate`, :func:`~gearlib.unit_ratio`);
* ``transmission`` - every gear of an automatic transmission, the shift table;
* ``schedule`` - the shift table of a transmission's own schedule: ratios, steps, slips,
  efficiencies, power flow, and every combination of its shift elements classified;
* ``robots`` - Chen's transmission lines, units and structure matrix;
* ``scaling`` - how solve time grows with the length of a train;
* ``lever`` and ``lever_plot`` - lever diagrams of planetary trains (Benford and Leising), a
  gear's speeds drawn on them;
* ``drawing`` and ``widget`` - the propagation drawn, and the transmission explorer.

Everything in ``EXPORTS`` is public; ``TOP`` is also ``gl.<name>``.
"""

from .._common.exports import lazy

EXPORTS = {
    "unit_tree": ("unit_speeds",),
    "local": ("local_gain", "LocalGain", "GainSymbol"),
    "rules": ("RuleDerivation", "RuleMatch", "derive_rule", "match_rule", "RULES"),
    "propagation": ("Step", "Plan", "plan", "parse_relative"),
    "relation": ("Propagation", "propagate", "unit_ratio", "METHODS"),
    "transmission": ("OperatingMode", "ModeResult", "ShiftTable", "operating_modes", "shift_table",
                     "plot_mode_sweep", "LIU_CHEN_MODES"),
    "schedule": ("GearResult", "MeshPower", "Combination", "ScheduleTable", "schedule_table", "classify", "KINDS"),
    "robots": ("GearedRobot", "TransmissionLine", "RobotUnit", "geared_robot", "canonical_spanning_tree",
               "UNIT_TYPES", "unit_gains"),
    # gearlib.gains.scaling is the module; its function is gearlib.gains.scaling.scaling
    "scaling": ("ScalingCurve", "dense_nullspace_ratio", "plot_scaling"),
    "drawing": ("draw_propagation", "plot_shift_table", "plot_gear_efficiency", "plot_gear_power"),
    "lever": ("LeverSet", "LeverNode", "Lever", "LeverDiagram", "lever_diagram"),
    "lever_plot": ("lever_geometry", "draw_levers"),
    "widget": ("TransmissionExplorer", "transmission_explorer"),
}

TOP = (
    "relation", "rules", "transmission", "robots", "propagation", "scaling",
    "plan", "propagate", "Propagation", "unit_ratio", "local_gain", "derive_rule", "match_rule",
    "shift_table", "geared_robot", "GearedRobot", "lever_diagram", "draw_levers",
)

__getattr__, __dir__, __all__ = lazy(__name__, EXPORTS)
