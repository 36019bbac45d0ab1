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

import importlib

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

__version__ = "0.1.0"

# Public names and the module each lives in. Modules load on first use (PEP 562), so
# ``import gearlib`` stays quick and a reader who never draws never imports matplotlib.
# A name whose module equals the name is a submodule (``gl.catalog``, ``gl.plot``).
_WHERE = {
    # catalog
    "catalog": "catalog",
    # check
    "check": "check",
    # plot
    "plot": "plot",
    "draw_graph": "plot",
    "plot_speeds": "plot",
    # widgets
    "widgets": "widgets",
    # display
    "number": "display",
    # generate
    "random_mechanism": "generate",
    "serial_train": "generate",
    # adjacency
    "adjacency_matrix": "adjacency",
    "link_table": "adjacency",
    "null_space": "adjacency",
    "speed_ratio_matrix": "adjacency",
    "constraint_rows": "adjacency",
    "direction": "adjacency",
    "reduced_basis": "adjacency",
    "same_subspace": "adjacency",
    "show_link_table": "adjacency",
    "show_matrix": "adjacency",
    # equations
    "WillisEquation": "equations",
    "omega": "equations",
    "ratio_symbols": "equations",
    "willis_equations": "equations",
    "willis_matrix": "equations",
    # graph
    "FundamentalCircuit": "graph",
    "displacement_graph": "graph",
    "fundamental_circuits": "graph",
    "to_networkx": "graph",
    # io
    "load": "io",
    "loads": "io",
    "save": "io",
    # kinematics
    "Constraints": "kinematics",
    "Solution": "kinematics",
    "ratio": "kinematics",
    "speeds": "kinematics",
    # mechanism
    "Bearing": "mechanism",
    "GearPair": "mechanism",
    "Link": "mechanism",
    "Mechanism": "mechanism",
    "TurningPair": "mechanism",
    # mobility
    "Mobility": "mobility",
    "choose_inputs": "mobility",
    "dof": "mobility",
    # propagation
    "propagation": "propagation",
    "plan": "propagation",
    # unit_plot
    "unit_plot": "unit_plot",
    "draw_fractionation": "unit_plot",
    "draw_ku_catalogue": "unit_plot",
    "draw_units": "unit_plot",
    # unit_widgets
    "unit_widgets": "unit_widgets",
    "unit_explorer": "unit_widgets",
    # units
    "units": "units",
    "CommonLinkage": "units",
    "Fractionation": "units",
    "KinematicUnit": "units",
    "kinematic_units": "units",
    # fge
    "fundamental_geared_entities": "fge",
    # ku_types
    "ku_catalogue": "ku_types",
    # gains
    "gains": "gains",
    "local_gain": "gains",
    # relation
    "relation": "relation",
    "Propagation": "relation",
    "propagate": "relation",
    "unit_ratio": "relation",
    # robots
    "robots": "robots",
    "GearedRobot": "robots",
    "geared_robot": "robots",
    # rules
    "rules": "rules",
    "derive_rule": "rules",
    "match_rule": "rules",
    # transmission
    "transmission": "transmission",
    "shift_table": "transmission",
    # cornering
    "cornering_explorer": "cornering",
    "plot_cornering": "cornering",
    "wheel_speeds": "cornering",
    # frequencies
    "BearingFrequencies": "frequencies",
    "FrequencyRow": "frequencies",
    "FrequencyTable": "frequencies",
    "bearing_frequencies": "frequencies",
    "frequency_table": "frequencies",
    "load_bearings": "frequencies",
    "plot_spectrum": "frequencies",
    "with_bearings": "frequencies",
    # davies
    "davies": "davies",
    "efficiency": "davies",
    "torque_balance_efficiency": "davies",
    # atlas
    "atlas": "atlas",
    # synthesis
    "synthesis": "synthesis",
    "identify": "synthesis",
    "terminal_constraint": "synthesis",
    # dgm_view
    "dgm_explorer": "dgm_view",
    "plot_dgm": "dgm_view",
    "plot_identification": "dgm_view",
    # every other public module, reachable as gl.<module>
    "adjacency": "adjacency",
    "bearings": "bearings",
    "cornering": "cornering",
    "dgm_view": "dgm_view",
    "display": "display",
    "equations": "equations",
    "fge": "fge",
    "frequencies": "frequencies",
    "generate": "generate",
    "graph": "graph",
    "io": "io",
    "kinematics": "kinematics",
    "ku_types": "ku_types",
    "mechanism": "mechanism",
    "mobility": "mobility",
    "scaling": "scaling",
}


def __getattr__(name: str):
    try:
        where = _WHERE[name]
    except KeyError:
        raise AttributeError(f"module 'gearlib' has no attribute {name!r}") from None
    module = importlib.import_module(f".{where}", __name__)
    value = module if where == name else getattr(module, name)
    globals()[name] = value  # next time, no lookup
    return value


def __dir__():
    return sorted(set(globals()) | set(_WHERE))


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
