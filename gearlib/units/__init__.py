"""Kinematic units and kinematic fractionation: chapter 2.

Liu, Chen and Chang (2004) split a geared mechanism into kinematic units (KUs), each a
carrier with the gears it holds, joined by common linkages (2-link chains and coaxial
triangles); Chatterjee and Tsai's fundamental geared entities are the comparison. This
package holds

* ``unit`` - one unit, its thin edges, the common linkages (data);
* ``catalogue`` - the catalogue of units with up to five links (K3-1 ... K5-7, S and D
  variants), rebuilt from first principles, and the classification of a unit against it;
* ``fractionation`` - the four steps for any mechanism: :func:`~gearlib.kinematic_units`;
* ``fge`` - fundamental geared entities;
* ``drawing`` and ``widget`` - units drawn in colour, the four steps side by side, the
  catalogue, and the unit explorer.

How motion then propagates from unit to unit, and the gains, are chapter 3:
``gearlib.gains``. Everything in ``EXPORTS`` is public; ``TOP`` is also ``gl.<name>``.
"""

from .._common.exports import lazy

EXPORTS = {
    "unit": ("ThinEdge", "KinematicUnit", "CommonLinkage"),
    "fractionation": ("Fractionation", "kinematic_units", "separated_displacement_graph"),
    "catalogue": ("CatalogueEntry", "ku_catalogue", "classify", "structure_graph"),
    "fge": ("FundamentalGearedEntity", "fundamental_geared_entities"),
    "drawing": ("draw_unit", "draw_units", "unit_colors", "draw_units_gallery", "draw_displacement_graph",
                "draw_fractionation", "draw_ku_catalogue"),
    "widget": ("UnitExplorer", "unit_explorer"),
    # the modules' names before the package existed
    "ku_types": "catalogue",
    "unit_plot": "drawing",
    "unit_widgets": "widget",
}

TOP = (
    "kinematic_units", "Fractionation", "KinematicUnit", "CommonLinkage", "fundamental_geared_entities",
    "ku_catalogue", "draw_units", "draw_fractionation", "draw_ku_catalogue", "unit_explorer",
    "unit_plot", "unit_widgets", "fge", "ku_types",
)

__getattr__, __dir__, __all__ = lazy(__name__, EXPORTS)
