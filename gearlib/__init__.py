"""gearlib: the library behind the open textbook on geared mechanisms.

Use it as ``import gearlib as gl``. Mechanisms are validated, immutable data
(:class:`Mechanism`, loadable with :func:`load` or from :mod:`gearlib.catalog`); analyses
are functions of a mechanism (:func:`speeds`, :func:`ratio`, :func:`dof`, ...); drawings are
in :mod:`gearlib.plot` and take ``ax=``; exercise checks live in :mod:`gearlib.check`.

Importing gearlib changes no global state (matplotlib settings, numpy print options,
random generators).

>>> import gearlib as gl
>>> m = gl.catalog.simple_planetary(sun=24, ring=60)
>>> gl.ratio(m, output=4, input=1, ground=3)
Fraction(2, 7)
"""

from . import catalog, check, plot, widgets
from .display import number
from .generate import random_mechanism, serial_train
from .adjacency import adjacency_matrix, link_table, null_space, speed_ratio_matrix
from .equations import WillisEquation, omega, ratio_symbols, willis_equations, willis_matrix
from .errors import (
    AxisError,
    CarrierError,
    ConstraintError,
    DataFormatError,
    DisconnectedError,
    DuplicateEdgeError,
    FileFormatError,
    GearlibError,
    GeometryError,
    InputError,
    MechanismError,
    OverconstrainedError,
    SelfMeshError,
    ToothNumberError,
    UnknownLinkError,
)
from .graph import FundamentalCircuit, displacement_graph, fundamental_circuits, to_networkx
from .io import load, loads, save
from .kinematics import Constraints, Solution, ratio, speeds
from .mechanism import Bearing, GearPair, Link, Mechanism, TurningPair
from .mobility import Mobility, choose_inputs, dof
from .plot import draw_graph, plot_speeds

# --- chapter 2: kinematic units (gearlib/units.py) -------------------------------
from . import propagation, unit_plot, unit_widgets, units
from .fge import fundamental_geared_entities
from .ku_types import ku_catalogue
from .propagation import plan
from .unit_plot import draw_fractionation, draw_ku_catalogue, draw_units
from .unit_widgets import unit_explorer
from .units import CommonLinkage, Fractionation, KinematicUnit, kinematic_units
# --- chapter 3: unit-by-unit gains (gearlib/gains.py, gearlib/robots.py) ----------
from . import gains, relation, robots, rules, transmission
from .gains import local_gain
from .relation import Propagation, propagate, unit_ratio
from .robots import GearedRobot, geared_robot
from .rules import derive_rule, match_rule
from .transmission import shift_table
# --- chapter 4: complex adjacency, frequencies (gearlib/adjacency.py, gearlib/frequencies.py)
from .adjacency import (
    constraint_rows,
    direction,
    reduced_basis,
    same_subspace,
    show_link_table,
    show_matrix,
)
from .cornering import cornering_explorer, plot_cornering, wheel_speeds
from .frequencies import (
    BearingFrequencies,
    FrequencyRow,
    FrequencyTable,
    bearing_frequencies,
    frequency_table,
    load_bearings,
    plot_spectrum,
    with_bearings,
)
# --- chapter 5: Davies' efficiency (gearlib/davies/) ------------------------------
from . import davies
from .davies import efficiency, torque_balance_efficiency
# --- chapter 6: differential synthesis (gearlib/atlas.py, gearlib/synthesis.py) ---
from . import atlas, synthesis
from .synthesis import identify, terminal_constraint
from .dgm_view import dgm_explorer, plot_dgm, plot_identification

__version__ = "0.1.0"

__all__ = [
    # data
    "Mechanism", "Link", "TurningPair", "GearPair", "Bearing", "load", "loads", "save", "catalog", "check",
    # graph and equations (chapter 1)
    "to_networkx", "fundamental_circuits", "FundamentalCircuit", "displacement_graph",
    "willis_equations", "willis_matrix", "WillisEquation", "omega", "ratio_symbols",
    "dof", "Mobility", "choose_inputs", "speeds", "ratio", "Solution", "Constraints",
    # Penaud and Alazard's matrix (chapters 1 and 4)
    "link_table", "adjacency_matrix", "null_space", "speed_ratio_matrix",
    # drawing
    "plot", "widgets", "draw_graph", "plot_speeds", "number",
    # random and large mechanisms (tests, benchmarks)
    "random_mechanism", "serial_train",
    # chapter 2: kinematic units
    "units", "kinematic_units", "Fractionation", "KinematicUnit", "CommonLinkage", "fundamental_geared_entities",
    "ku_catalogue", "plan", "propagation", "unit_plot", "draw_units", "draw_fractionation", "draw_ku_catalogue",
    "unit_widgets", "unit_explorer",
    # chapter 3: unit-by-unit gains
    "gains", "relation", "rules", "transmission", "robots", "propagate", "Propagation", "unit_ratio", "local_gain",
    "derive_rule", "match_rule", "shift_table", "geared_robot", "GearedRobot",
    # chapter 4: complex adjacency, frequencies
    "reduced_basis", "same_subspace", "constraint_rows", "direction", "show_link_table", "show_matrix",
    "frequency_table", "FrequencyTable", "FrequencyRow", "bearing_frequencies", "BearingFrequencies",
    "plot_spectrum", "load_bearings", "with_bearings", "wheel_speeds", "cornering_explorer", "plot_cornering",
    # chapter 5: Davies' efficiency
    "davies", "efficiency", "torque_balance_efficiency",
    # chapter 6: differential synthesis
    "atlas", "synthesis", "terminal_constraint", "identify", "plot_dgm", "plot_identification", "dgm_explorer",
    # errors
    "GearlibError", "MechanismError", "DataFormatError", "UnknownLinkError", "DuplicateEdgeError",
    "SelfMeshError", "ToothNumberError", "CarrierError", "AxisError", "DisconnectedError",
    "OverconstrainedError", "ConstraintError", "InputError", "FileFormatError", "GeometryError",
]
