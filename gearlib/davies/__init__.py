"""Davies' method: motions, actions, power flow and efficiency of gear trains (chapter 5).

Laus (2011) extends Davies' network method, Kirchhoff's laws for the motions and the
actions of a machine, with friction, active couplings and power flow. This package applies
it to any one-degree-of-freedom gear train with parallel or intersecting axes given as a
:class:`gearlib.Mechanism`:

* :func:`layout` - axes and pitch points from the radii and the topology;
* :func:`network` - the coupling graph, unit screws and network matrices ``M_N``, ``A_N``;
* :func:`motions`, :func:`actions` - the two Kirchhoff laws, with friction as constitutive rows;
* :func:`coupling_powers`, :func:`mesh_flows`, :func:`power_flow` - power and power flow;
* :func:`efficiency` - the overall efficiency, numeric or as a formula;
* :func:`turning_conditions`, :func:`efficiency_formulas`, :func:`derivative_check`;
* :func:`torque_balance_efficiency` - an independent, conventional check;
* drawings, a widget, friction models and a generator of random consistent trains.

>>> import gearlib as gl
>>> res = gl.davies.efficiency(gl.catalog.humpage(), ground=5, input=1, output=4, eta=0.98)
>>> round(res.value, 6), res.ratio
(0.632647, 0.014455782312925...)
"""

from .conventional import TorqueBalance, torque_balance_efficiency
from .drawing import draw_coupling_graph, plot_coupling_powers, plot_efficiency_sweep, plot_layout, plot_power_flow
from .examples import humpage_radii, laus_humpage_geometry
from .friction import (
    bearing_multiplier,
    buckingham_efficiency,
    contact_path,
    equivalent_zeta,
    involute_efficiency,
    pivot_friction_torque,
)
from .formulas import FormulaCase, TurningCondition, derivative_check, efficiency_formulas, turning_conditions
from .generate import KINDS, TrainCase, random_train
from .geometry import MODES, Axis, Layout, MeshGeometry, layout, radius_symbols
from .graph import CouplingGraph, replicate
from .identify import LossFit, efficiencies_from_losses
from .motion import Motions, check_willis, motions
from .network import LOSS_ROLES, Coupling, Network, Variable, network
from .overall import GLOVER, Efficiency, MeshResult, efficiency, eta_symbol
from .power import (
    MeshFlow,
    column_powers,
    coupling_powers,
    mesh_flows,
    mesh_power_ratio,
    power_flow,
    real_flows,
    tellegen,
)
from .statics import VISCOUS_LAWS, Actions, actions, viscous_torque
from .widget import EfficiencyExplorer, efficiency_explorer, with_teeth

__all__ = [
    # geometry and network
    "layout", "Layout", "Axis", "MeshGeometry", "MODES", "radius_symbols",
    "network", "Network", "Coupling", "Variable", "LOSS_ROLES", "CouplingGraph", "replicate",
    # the two Kirchhoff laws
    "motions", "Motions", "check_willis", "actions", "Actions", "viscous_torque", "VISCOUS_LAWS",
    # power and efficiency
    "coupling_powers", "column_powers", "tellegen", "power_flow", "mesh_flows", "MeshFlow", "real_flows",
    "mesh_power_ratio", "efficiency", "Efficiency", "MeshResult", "GLOVER", "eta_symbol",
    "turning_conditions", "TurningCondition", "efficiency_formulas", "FormulaCase", "derivative_check",
    "torque_balance_efficiency", "TorqueBalance", "efficiencies_from_losses", "LossFit",
    # friction models
    "involute_efficiency", "buckingham_efficiency", "contact_path", "equivalent_zeta", "bearing_multiplier",
    "pivot_friction_torque",
    # Laus's models, random trains, drawings, widget
    "laus_humpage_geometry", "humpage_radii", "random_train", "TrainCase", "KINDS",
    "draw_coupling_graph", "plot_layout", "plot_coupling_powers", "plot_power_flow", "plot_efficiency_sweep",
    "efficiency_explorer", "EfficiencyExplorer", "with_teeth",
]
