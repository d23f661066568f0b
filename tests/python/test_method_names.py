"""A mistyped method name is refused naming the argument, listing every method and suggesting the closest
one ("did you mean 'rk4'?"), wherever a method is named: simulate, step, simulate_batch, a scene's
describe and compile, and the command line; a name close to none gets no suggestion."""

import re

import pytest

import rigiddyn as rd
from rigiddyn.__main__ import main

BODY = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
STATE = rd.RigidBodyState(w_B=[0.1, 1.0, 0.2])


def _scene():
    scene = rd.Scene()
    scene.add_body(BODY, name="b")
    return scene


CALLS = {
    "simulate": lambda m: rd.simulate(BODY, STATE, 0.01, 10, m),
    "step": lambda m: rd.step(BODY, STATE, 0.01, m),
    "simulate_batch": lambda m: rd.simulate_batch(BODY, [STATE, STATE], 0.01, 10, m),
    "scene simulate": lambda m: rd.simulate(_scene(), [STATE], 0.01, 10, m),
    "describe": lambda m: _scene().describe(m),
    "compile": lambda m: _scene().compile(m),
}


@pytest.mark.parametrize("call", CALLS)
@pytest.mark.parametrize("typed, meant", [("rk44", "rk4"), ("RK4", "rk4"), ("spliting_dlm", "splitting_dlm"),
                                          ("exactt", "exact")])
def test_a_typo_names_the_closest_method(call, typed, meant):
    with pytest.raises(ValueError, match=rf"^method: expected one of explicit_euler, .*exact \(did you mean "
                                         rf"'{meant}'\?\), got '{typed}'$"):
        CALLS[call](typed)


@pytest.mark.parametrize("call", CALLS)
def test_a_name_close_to_none_gets_no_suggestion(call):
    with pytest.raises(ValueError) as caught:
        CALLS[call]("verlet")
    assert "did you mean" not in str(caught.value)
    assert re.match(r"^method: expected one of .*, got 'verlet'$", str(caught.value))


@pytest.mark.parametrize("command", [["simulate", "t_handle", "--dt", "0.01", "--steps", "10"],
                                     ["simulate", "pendulum", "--steps", "10"]])
def test_the_command_line_suggests_too(command, tmp_path, capsys):
    code = main([*command, "--method", "rk44", "--out", str(tmp_path / "out")])
    assert code == 2
    err = capsys.readouterr().err
    assert "--method: expected one of" in err and "(did you mean 'rk4'?), got 'rk44'" in err
