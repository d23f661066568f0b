"""Helpers shared by several test files (imported as `from _helpers import ...`; pytest puts this
directory on sys.path)."""

import numpy as np
import rigiddyn as rd
from scipy.spatial.transform import Rotation


def hat(v):
    """The cross-product matrix [v]x (3, 3) of a 3-vector: hat(v) @ u == np.cross(v, u)."""
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def planar_and_rigid_runs(method, loads):
    """The same in-plane motion simulated twice, 200 steps of 0.005 s with gravity (0, -9.81, 0)
    m/s^2: as a PlanarBody (m = 2 kg, I_zz = 0.7 kg m^2) and as a RigidBody (diag(0.5, 0.6, 0.7))
    kept in the xy plane. Returns (planar, spatial) results."""
    planar = rd.simulate(rd.PlanarBody(2.0, 0.7), rd.PlanarBodyState([0.1, 0.2], 0.4, [1.0, -0.5], 2.0),
                         0.005, 200, method=method, loads=loads, gravity=[0, -9.81, 0])
    spatial = rd.simulate(rd.RigidBody(2.0, np.diag([0.5, 0.6, 0.7])),
                          rd.RigidBodyState(p_W=[0.1, 0.2, 0], q_WB=Rotation.from_rotvec([0, 0, 0.4]).as_quat(),
                                            v_W=[1.0, -0.5, 0], w_B=[0, 0, 2.0]),
                          0.005, 200, method=method, loads=loads, gravity=[0, -9.81, 0])
    return planar, spatial


def same_estimate(a, b):
    """Whether two GlobalErrors (or objects with their fields) are the same to the bit (NaN where the other has
    NaN): order, verdicts, reliable flags and every array."""
    quantities = ("attitude", "angular_velocity", "position", "velocity", "energy", "angular_momentum")
    names = (*quantities, "observed_order", "reliable")
    return (a.order == b.order and a.verdict == b.verdict
            and all(np.array_equal(getattr(a, n), getattr(b, n), equal_nan=n != "reliable") for n in names)
            and all(np.array_equal(a.reliable_for(q), b.reliable_for(q)) for q in quantities))
