"""Davies' method beyond gear trains: the efficiency of linkages and parallel robots (chapter 7).

Laus (2011, chapter 4) applies Davies' network method to any machine: the couplings of a
linkage carry screws of order 3 (planar) or 6 (spatial), friction is an action in parallel
with each coupling tied to the forces it carries by a Coulomb law, a load enters through a
virtual coupling, and the absolute values of the friction laws are settled by continuation
from the frictionless solution (his Algorithm 2). This package does it for any linkage given
as data (revolute, prismatic, universal, spherical and cylindrical joints, planar or
spatial):

* :class:`Linkage` - links, joints with their geometry and friction, ports, tasks; read with
  :func:`load` (a YAML/JSON file or a catalogue entry: :func:`names`), written with :func:`save`;
* :func:`solve_pose` - every link's position from the motion inputs (Newton), :func:`mobility`;
* :func:`network` - the coupling network: couplings (a split prismatic pair becomes a square
  and a round annulus), named motion and action variables, circuit and cutset matrices (chapter
  5's :class:`~gearlib.davies.CouplingGraph`), unit screws at a pose, ``M_N`` and ``A_N``;
* :func:`instant` - motions and actions at one instant, Algorithm 2 for the signs;
* :func:`run` - a task followed in time: energies, efficiency, losses by coupling, reversals;
  :func:`cycle` - one turn of a driven joint, split where the motions reverse;
  :func:`jump` - the change of an actuator force across a reversal;
* :func:`slider_crank_efficiency`, :func:`slider_modes` - the thesis' closed forms (120),
  (123) and the friction modes of a slider (section 4.1);
* :func:`three_upu`, :func:`slider_crank` - the catalogue's linkages with other dimensions or
  friction (and the thesis' comparison model without split pairs);
* drawings: :func:`draw_linkage`, :func:`draw_linkage_graph`, :func:`plot_task_powers`.

Everything in ``EXPORTS`` is public; ``TOP`` is also ``gl.<name>``.

>>> import gearlib as gl
>>> res = gl.linkages.run(gl.linkages.load("laus_3upu"), "lift")
>>> round(res.energy_out, 6)
4000.0
"""

from .._common.exports import lazy

EXPORTS = {
    "elements": ("Joint", "Port", "Friction", "KINDS", "ROLES"),
    "tasks": ("Task", "RULES", "expression", "weights"),
    "data": ("Linkage",),
    "io": ("load", "loads", "save", "names", "path", "read_data"),
    "screws": ("rotation", "translation", "force", "couple", "power", "perpendicular", "MOTION_COORDS", "ACTION_COORDS",
                "PLANAR"),
    "pose": ("Pose", "solve_pose", "mobility", "extrapolate"),
    "couplings": ("Coupling", "Column", "FrictionTerm", "LinkageNetwork", "network"),
    "solve": ("Instant", "instant", "solve_motions", "solve_actions", "primaries"),
    "rating": ("TaskResult", "Reversal", "run", "jump", "cycle"),
    "catalogue": ("slider_crank", "three_upu", "slider_block", "slider_crank_efficiency", "slider_modes",
                  "SliderModes"),
    "drawing": ("draw_linkage", "draw_linkage_graph", "plot_task_powers"),
}

TOP = ("Linkage",)

__getattr__, __dir__, __all__ = lazy(__name__, EXPORTS)
