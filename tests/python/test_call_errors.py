"""A call that no signature of a compiled function accepts says why (call_errors.hpp): an unknown keyword is named
with the closest valid one, a missing, repeated or surplus argument is named, and a value of the wrong type names
its parameter, the type expected and the value given; never pybind11's "incompatible function arguments" list of
overloads. The overload that says it shows in no signature or docstring.
"""

from __future__ import annotations

import inspect
import re

import numpy as np
import pytest

import rigiddyn as rd

I_BOX = np.diag([1.0, 2.0, 2.5])


def _body():
    return rd.RigidBody(1.0, I_BOX)


def _state():
    return rd.RigidBodyState(w_B=[0.1, 0.2, 0.3])


@pytest.mark.parametrize("call, message", [
    # a function
    (lambda: rd.simulate(_body(), _state(), dt=0.01, step=10),
     "simulate(): unexpected keyword argument 'step' (did you mean 'steps'?)"),
    (lambda: rd.step(_body(), _state(), dt=0.01, metod="rk4"),
     "step(): unexpected keyword argument 'metod' (did you mean 'method'?)"),
    # a method of a class, a static method, a constructor
    (lambda: rd.Scene().add_body(rd.Particle(1.0), nam="dot"),
     "Scene.add_body(): unexpected keyword argument 'nam' (did you mean 'name'?)"),
    (lambda: rd.SceneFrame.rotating([0.0, 0.0, 1.0], rat=0.5),
     "SceneFrame.rotating(): unexpected keyword argument 'rat' (did you mean 'rate'?)"),
    (lambda: rd.RigidBody(mas=1.0), "RigidBody(): unexpected keyword argument 'mas' (did you mean 'mass'?)"),
    # nothing close: no guess
    (lambda: rd.simulate(_body(), _state(), dt=0.01, steps=2, zzz=1), "simulate(): unexpected keyword argument 'zzz'"),
])
def test_an_unknown_keyword_is_named_with_the_closest_valid_one(call, message):
    with pytest.raises(TypeError) as refused:
        call()
    assert str(refused.value) == message


@pytest.mark.parametrize("call, message", [
    (lambda: rd.simulate(_body()), "simulate(): missing required argument 'initial'"),
    (lambda: rd.RigidBody(), "RigidBody(): missing required argument 'mass'"),
    (lambda: rd.quat_multiply(), "quat_multiply(): missing required arguments 'q1' and 'q2'"),
    (lambda: rd.simulate(_body(), _state(), 0.01, 2, model=_body()),
     "simulate(): got multiple values for argument 'model'"),
    (lambda: rd.quat_multiply([0, 0, 0, 1.0], [0, 0, 0, 1.0], False, 4, 5),
     "quat_multiply(): takes 3 positional arguments but 5 were given"),
    (lambda: rd.Motion([0, 0, 1.0], [0, 0, 0.0]).dot(rd.Force(), 1),
     "Motion.dot(): takes 1 positional argument but 2 were given"),
])
def test_a_missing_repeated_or_surplus_argument_is_named(call, message):
    with pytest.raises(TypeError) as refused:
        call()
    assert str(refused.value) == message


@pytest.mark.parametrize("value, got", [("x", "str 'x'"), (1.5, "float 1.5"), (None, "None")])
def test_a_value_pybind11_cannot_convert_names_its_parameter(value, got):
    # InertiaCheck(value) is pybind11's int constructor of the enum: the value is converted by pybind11, not by the
    # binding, and both of pybind11's passes (without and with conversions) refuse it
    with pytest.raises(TypeError) as refused:
        rd.InertiaCheck(value)
    assert str(refused.value) == f"value: expected an int, got {got}"


def test_a_value_of_the_wrong_type_names_its_parameter():
    # the bindings convert their arguments themselves (numpy_io.hpp): the same form of message
    with pytest.raises(TypeError, match=r"^dt: expected a real number, got str '1'$"):
        rd.simulate(_body(), _state(), dt="1", steps=10)


def test_the_calls_that_fit_still_work():
    assert rd.InertiaCheck(1) == rd.InertiaCheck.allow_unrealizable
    assert rd.InertiaCheck(np.int64(0)) == rd.InertiaCheck.physical  # converted by pybind11 in its second pass
    run = rd.simulate(_body(), _state(), 0.01, steps=2)
    np.testing.assert_array_equal(run.t, [0.0, 0.01, 0.02])


def test_operators_keep_python_s_own_error():
    # an operator returns NotImplemented to Python, which raises its TypeError: no overload is added to it
    with pytest.raises(TypeError, match="unsupported operand"):
        rd.SpatialInertia(1.0, [0, 0, 0.0], I_BOX) + "x"  # type: ignore[operator]


def test_no_signature_or_docstring_shows_the_added_overload():
    assert str(inspect.signature(rd.simulate)).startswith("(model, initial, dt=None, steps=None,")
    assert str(inspect.signature(rd.InertiaCheck)) == "(value)"
    assert str(inspect.signature(rd.Scene.add_body)) == "(self, body, name=None, mass_flow=None)"
    for f in (rd.simulate, rd.Scene.add_body, rd.SceneFrame.rotating, rd.InertiaCheck.__init__):
        assert "Overloaded function" not in (f.__doc__ or ""), f
        assert "(first)" not in (f.__doc__ or "") and "**kwargs" not in (f.__doc__ or ""), f


def test_no_message_lists_pybind11_s_overloads():
    calls = [lambda: rd.simulate(), lambda: rd.Scene().add(), lambda: rd.InertiaCheck(object()),
             lambda: rd.quat_to_matrix(q=[0, 0, 0, 1.0], w=1)]
    for call in calls:
        with pytest.raises(TypeError) as refused:
            call()
        assert not re.search("incompatible (function|constructor) arguments|Invoked with", str(refused.value))
