"""Mechanisms as data, their graph and their kinematics: chapters 0 and 1.

A geared mechanism is a graph in the vocabulary of Freudenstein (1971), Tsai (2001) and
Penaud and Alazard: links are vertices, gear pairs heavy edges with a carrier (the transfer
vertex), turning pairs thin edges labelled with their axis. This package holds

* the data: ``elements`` (links, turning pairs, gear pairs, bearings), ``data``
  (:class:`~gearlib.Mechanism`, validated and frozen), ``shifting`` (a transmission's brakes,
  clutches and schedule), ``assembly`` (can the planets of each planetary set be built in?),
  ``io`` (YAML and JSON files) and
  ``generate`` (random valid mechanisms, long serial trains);
* the graph and the Willis (fundamental-circuit) equations: ``graph``, ``equations``;
* the solvers and the degrees of freedom: ``kinematics`` (:func:`~gearlib.speeds`,
  :func:`~gearlib.ratio`: exact, symbolic, numeric and, through chapter 4's matrix, null
  space) and ``mobility`` (:func:`~gearlib.dof`);
* drawings and widgets: ``sketch`` (the kinematic sketch, the stick diagram an engineer
  draws, computed from the data: :func:`~gearlib.draw_sketch`), ``plot`` (the graph in the
  papers' convention, speed bars) and
  ``widgets`` (the speed explorer, and the :class:`~gearlib.mechanism.Canvas` every
  widget of the book draws on); ``display`` (numbers for prose).

Everything listed in ``EXPORTS`` is public; the names in ``TOP`` are also ``gl.<name>``.
"""

from .._common.exports import lazy

EXPORTS = {
    "elements": ("Link", "Bearing", "TurningPair", "GearPair", "GEAR_KINDS"),
    "data": ("Mechanism",),
    "shifting": ("ShiftElement", "GearState", "SHIFT_KINDS"),
    "assembly": ("PlanetarySet", "AssemblyCondition", "planetary_sets", "assembly_conditions", "check_assembly",
                 "with_concentric_teeth"),
    "io": ("load", "save", "loads"),
    "generate": ("random_mechanism", "serial_train"),
    "graph": ("to_networkx", "FundamentalCircuit", "fundamental_circuits", "displacement_graph", "tilted_links"),
    "teeth": ("Gear", "gears", "set_teeth", "followers"),
    "equations": ("omega", "WillisEquation", "willis_equations", "willis_matrix", "ratio_symbols"),
    "kinematics": ("Solution", "speeds", "ratio", "METHODS", "Constraints", "format_value"),
    "mobility": ("Mobility", "dof", "redundant_gear_pairs", "choose_inputs"),
    "display": ("Number", "number", "Formula", "formula"),
    "plot": ("style", "graph_layout", "draw_graph", "plot_speeds", "plot_ratio_sweep"),
    "sketch": ("Sketch", "Block", "Line", "AxisLine", "Symbol", "Label", "sketch_layout", "draw_sketch",
               "figure_size"),
    "widgets": ("Canvas", "Explorer", "SpeedExplorer", "speed_explorer", "plot_speed_sweep", "render_png",
                "encode_png", "with_snapshot"),
}

TOP = (
    "Mechanism", "Link", "TurningPair", "GearPair", "Bearing", "load", "loads", "save",
    "to_networkx", "fundamental_circuits", "FundamentalCircuit", "displacement_graph",
    "willis_equations", "willis_matrix", "WillisEquation", "omega", "ratio_symbols",
    "dof", "Mobility", "choose_inputs", "speeds", "ratio", "Solution", "Constraints",
    "draw_graph", "plot_speeds", "number", "random_mechanism", "serial_train", "assembly_conditions",
    "with_concentric_teeth", "formula",
    "draw_sketch", "sketch_layout", "Sketch",
    "plot", "sketch", "widgets", "display", "equations", "generate", "graph", "io", "kinematics", "mobility",
)

__getattr__, __dir__, __all__ = lazy(__name__, EXPORTS)
