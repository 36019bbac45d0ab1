"""Davies' method: motions, actions, power flow and efficiency of gear trains (chapter 5).

Laus (2011) extends Davies' network method, Kirchhoff's laws for the motions and the
actions of a machine, with friction, active couplings and power flow. This package applies
it to any one-degree-of-freedom gear train with parallel or intersecting axes given as a
:class:`gearlib.Mechanism`:

* :func:`layout` - axes and pitch points from the radii and the topology;
* :func:`network` (``coupling_network``) - the coupling graph, unit screws and network
  matrices ``M_N``, ``A_N``;
* :func:`motions`, :func:`actions` - the two Kirchhoff laws, with friction as constitutive rows;
* :func:`coupling_powers`, :func:`mesh_flows`, :func:`power_flow` - power and power flow;
* :func:`efficiency` - the overall efficiency, numeric or as a formula;
* :func:`operating_point` - trains with two or more degrees of freedom (differentials,
  power-split devices) rated at given port speeds and torques;
* :func:`turning_conditions`, :func:`efficiency_formulas`, :func:`derivative_check`;
* :func:`torque_balance_efficiency` - an independent, conventional check;
* drawings, a widget, friction models and a generator of random consistent trains.

Everything in ``EXPORTS`` is public; ``TOP`` is also ``gl.<name>``.

>>> import gearlib as gl
>>> res = gl.davies.efficiency(gl.catalog.humpage(), ground=5, input=1, output=4, eta=0.98)
>>> round(res.value, 6), res.ratio
(0.632647, 0.014455782312925...)
"""

from .._common.exports import lazy

EXPORTS = {
    "geometry": ("Axis", "MeshGeometry", "Layout", "layout", "radius_symbols", "MODES"),
    "coupling_network": ("Coupling", "Variable", "Network", "network", "LOSS_ROLES"),
    "graph": ("CouplingGraph", "replicate"),
    "motion": ("Motions", "motions", "check_willis"),
    "statics": ("Actions", "actions", "VISCOUS_LAWS", "viscous_torque"),
    "power": ("coupling_powers", "column_powers", "tellegen", "power_flow", "MeshFlow", "mesh_flows",
             "real_flows", "mesh_power_ratio"),
    "overall": ("efficiency", "Efficiency", "MeshResult", "GLOVER", "eta_symbol"),
    "operating": ("operating_point", "OperatingPoint", "PortResult", "MeshLoss"),
    "formulas": ("TurningCondition", "turning_conditions", "FormulaCase", "efficiency_formulas",
                "derivative_check", "by_gears"),
    "conventional": ("torque_balance_efficiency", "TorqueBalance"),
    "identify": ("LossFit", "efficiencies_from_losses"),
    "friction": ("involute_efficiency", "buckingham_efficiency", "contact_path", "equivalent_zeta",
                "bearing_multiplier", "pivot_friction_torque"),
    "examples": ("laus_humpage_geometry", "humpage_radii"),
    "generate": ("TrainCase", "random_train", "KINDS"),
    "drawing": ("draw_coupling_graph", "plot_layout", "plot_coupling_powers", "plot_power_flow"),
    "widget": ("EfficiencyExplorer", "efficiency_explorer", "with_teeth", "plot_efficiency_sweep"),
}

TOP = ("efficiency", "torque_balance_efficiency")

__getattr__, __dir__, __all__ = lazy(__name__, EXPORTS)
