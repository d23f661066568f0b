"""The rotation array functions that run blocks of items in vector registers (quat_to_matrix, quat_to_mrp,
quat_inverse, mrp_to_quat): on the portable path (RIGIDDYN_PORTABLE=1, 2 items per register) and on the AVX2 one
(4 per register) every item of a stack gets the bits it gets alone (the one-item path), including the items the
blocks leave to it (a half turn for quat_to_mrp, |p| > 1 for mrp_to_quat) and the last items of a stack; the two
paths give the same bits; a bad item is named by its index on both."""

from __future__ import annotations

import platform

import pytest

from test_vector_instructions import run_on_path

# Each function on stacks of 1 to 13 items (blocks of 2 and 4 and every remainder), both quaternion layouts: the
# stacked result and the results of its items one by one, as hex bytes; and the message of a stack with a NaN in
# item 6. As JSON.
RUN = """
import json, numpy as np, rigiddyn as rd
rng = np.random.default_rng(11)
q = rng.normal(size=(13, 4))
q /= np.linalg.norm(q, axis=1, keepdims=True)
q[5, 3] = 0.0   # a half turn: quat_to_mrp's tie rule, one item at a time
q[5] /= np.linalg.norm(q[5])
q[8] *= 1.0 + 5e-7  # within the unit-norm tolerance: normalised
mrp = 0.3 * rng.normal(size=(13, 3))
mrp[[2, 9]] *= 20.0  # |p| > 1 (the other shadow set): one item at a time
functions = {"quat_to_matrix": rd.quat_to_matrix, "quat_to_mrp": rd.quat_to_mrp, "quat_inverse": rd.quat_inverse}
results = {}
for scalar_first in (False, True):
    q_in = np.roll(q, 1, axis=1) if scalar_first else q
    cases = [(name, lambda x, f=f: f(x, scalar_first=scalar_first), q_in) for name, f in functions.items()]
    cases.append(("mrp_to_quat", lambda x: rd.mrp_to_quat(x, scalar_first=scalar_first), mrp))
    for name, f, x in cases:
        for n in range(1, len(x) + 1):
            key = f"{name}/{scalar_first}/{n}"
            results[key] = [f(x[:n]).tobytes().hex(), np.array([f(x[i]) for i in range(n)]).tobytes().hex()]
bad = q.copy()
bad[6, 1] = np.nan
messages = {}
for name, f in functions.items():
    try:
        f(bad)
    except ValueError as e:
        messages[name] = str(e)
bad = mrp.copy()
bad[6, 2] = np.inf
try:
    rd.mrp_to_quat(bad)
except ValueError as e:
    messages["mrp_to_quat"] = str(e)
print(json.dumps({"path": rd.vector_instructions(), "results": results, "messages": messages}))
"""


def _run(portable: str | None) -> dict:
    return run_on_path(RUN, portable)


@pytest.fixture(scope="module")
def runs() -> dict:
    return {"portable": _run("1"), "default": _run(None)}


@pytest.mark.parametrize("path", ["portable", "default"])
def test_each_item_of_a_stack_gets_the_bits_of_that_item_alone(runs, path) -> None:
    # bound 0: a block evaluates the one-item formula's operations in the same order, lane by lane (so3_lanes.hpp)
    for key, (stacked, one_by_one) in runs[path]["results"].items():
        assert stacked == one_by_one, key


@pytest.mark.parametrize("path", ["portable", "default"])
def test_a_bad_item_is_named_by_its_index(runs, path) -> None:
    messages = runs[path]["messages"]
    assert set(messages) == {"quat_to_matrix", "quat_to_mrp", "quat_inverse", "mrp_to_quat"}
    for name, message in messages.items():
        expected_name = "mrp" if name == "mrp_to_quat" else "q"
        assert message.startswith(f"{expected_name}: expected ") and "finite" in message, message
        assert message.endswith("(item 6)"), message


def test_portable_and_avx2_paths_give_the_same_bits(runs) -> None:
    assert runs["portable"]["path"] == "portable"
    if runs["default"]["path"] == "portable":
        pytest.skip("this machine runs the portable path only")
    if platform.machine() != "x86_64":
        pytest.skip("the AVX2 kernels are built on x86-64 only")
    # bound 0: both paths evaluate the same IEEE operations in the same order, the AVX2 one compiled without fused
    # multiply-add (so3_lanes.hpp)
    assert runs["default"]["results"] == runs["portable"]["results"]
