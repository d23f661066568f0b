"""The states a sweep compares: a one-body run's, and an independent reference's with its own error."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np


@dataclass
class States:
    """States of one body at n times: t (n,) [s], p_W (n, 3) [m], q_WB (n, 4) (x, y, z, w), v_W (n, 3) [m/s],
    w_B (n, 3) [rad/s]."""

    t: np.ndarray
    p_W: np.ndarray
    q_WB: np.ndarray
    v_W: np.ndarray
    w_B: np.ndarray


def states_of(result: Any) -> States:
    """The recorded states of the one body of a SceneResult (``result.body(0)``)."""
    body = result.body(0)
    return States(np.asarray(body.t), np.asarray(body.p_W), np.asarray(body.q_WB),
                  np.asarray(body.v_W), np.asarray(body.w_B))


def rows_at(states: States, times: np.ndarray) -> States:
    """The rows of `states` (at a superset of `times`, both ascending) at `times`."""
    rows = np.searchsorted(states.t, times)
    return States(states.t[rows], states.p_W[rows], states.q_WB[rows], states.v_W[rows], states.w_B[rows])


@dataclass
class Independent:
    """The second reference for one step grid: its states (States, or SceneStates of a scene), an estimate of
    its own error per measure and its name (for reference_check)."""

    states: Any
    error: dict[str, float]
    name: str
