"""Complex-weighted adjacency matrices, bevel gears and contact frequencies: chapter 4.

Penaud and Alazard write a geared mechanism as a complex-weighted adjacency matrix whose
null space gives every link's angular velocity, bevel gears included, and read gear-mesh,
tooth-defect and bearing frequencies off the speeds. This package holds

* ``matrix`` - the link table, the matrix :func:`~gearlib.adjacency_matrix`, its null space and
  normalisations, speed ratios, directions, readable matrices;
* ``rank`` - Penaud's count ``N - rank(M)`` (:func:`~gearlib.adjacency_rank`);
* ``frequencies`` and ``bearings`` - contact frequencies of every mesh and rolling
  bearing (:func:`~gearlib.frequency_table`), bearing data given apart from a mechanism;
* ``monitoring`` and ``planetary`` - condition monitoring: the fault frequencies of any
  gearbox in Hz, rpm and orders (:func:`~gearlib.fault_table`), planetary sets found from the
  graph (:func:`~gearlib.planetary_sets`), harmonics, sidebands and the spectrum map;
* ``cornering`` - the car differential on the road: wheel speeds, frequencies, a widget.

The kinematic solver ``gl.speeds(..., method="nullspace")`` of chapter 1 uses
``matrix``, which stands on the mechanism data alone. Everything in ``EXPORTS`` is
public; ``TOP`` is also ``gl.<name>``.
"""

from .._common.exports import lazy

EXPORTS = {
    "matrix": ("link_table", "adjacency_matrix", "null_space", "reduced_basis", "same_subspace", "constraint_rows",
               "speed_ratio_matrix", "Direction", "direction", "show_link_table", "show_matrix", "MatrixView",
               "format_entry"),
    "rank": ("AdjacencyRank", "adjacency_rank"),
    "frequencies": ("FrequencyRow", "FrequencyTable", "gear_frequencies", "frequency_table", "plot_spectrum",
                    "CONVENTIONS"),
    "bearings": ("BearingFrequencies", "bearing_frequencies", "read_bearings", "load_bearings", "with_bearings"),
    "monitoring": ("FaultLine", "FaultTable", "fault_table", "plot_fault_map", "FAMILIES"),
    "planetary": ("PlanetarySet", "planetary_sets", "tooth_factors"),
    "cornering": ("wheel_speeds", "CorneringExplorer", "cornering_explorer", "plot_cornering", "WHEEL_RADIUS",
                  "TRACK"),
}

TOP = (
    "link_table", "adjacency_matrix", "adjacency_rank", "AdjacencyRank", "null_space", "speed_ratio_matrix",
    "reduced_basis", "same_subspace", "constraint_rows", "direction", "show_link_table", "show_matrix",
    "frequency_table", "FrequencyTable", "FrequencyRow", "bearing_frequencies", "BearingFrequencies",
    "plot_spectrum", "load_bearings", "with_bearings", "wheel_speeds", "cornering_explorer", "plot_cornering",
    "fault_table", "FaultTable", "FaultLine", "plot_fault_map", "planetary_sets", "PlanetarySet",
    "bearings", "cornering", "frequencies", "monitoring",
)

__getattr__, __dir__, __all__ = lazy(__name__, EXPORTS)
