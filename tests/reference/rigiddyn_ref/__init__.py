"""rigiddyn_ref: the independent numpy reference implementation of rigiddyn.

Written equation by equation from the texts of docs/references.md and textbook formulas
(Featherstone, "Rigid Body Dynamics Algorithms"; Shoemake; Diebel, "Representing Attitude"), in
plain numpy. It never imports rigiddyn; it never imports scipy either, except exact_dynamics (the
closed forms of the pendulum, the Lagrange top and the constant-thrust burn), which takes its elliptic
functions from scipy.special (ellipj, ellipk, Carlson's elliprf/elliprj) rather than from the core's own.
It is the oracle the core is compared with, and the baseline of the Python benchmarks. The modules
pivoted, moving_frame, variable_mass, exact_dynamics, tree and balance are imported by name (not re-exported here).

Conventions follow docs/conventions.md: SI units; quaternions (x, y, z, w) unless
``scalar_first=True``; Hamilton product; active rotations; spatial vectors angular part first.
Every function accepts one item or a stack with a leading axis n (numpy broadcasting over ``...``).
"""

from . import dynamics, inertia, integrators, kinematics, scene, scene_exact, so3, spatial

__all__ = ["dynamics", "inertia", "integrators", "kinematics", "scene", "scene_exact", "so3", "spatial"]
