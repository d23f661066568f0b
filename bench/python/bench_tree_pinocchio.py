"""RNEA, CRBA and ABA on robots read from URDF, rigiddyn against Pinocchio (the `peers` extra), both called
from Python.

The robots are example-robot-data's UR5 (6 joints), Panda (9) and Talos on a floating base (38 velocity
coordinates) where that package is installed, else two robots written here as URDF: a 7-joint arm and a
floating-base tree of four 6-joint limbs (30 velocity coordinates). Each library loads the same URDF
(rigiddyn.load_urdf; Pinocchio's buildModelFromXML) with gravity, and is called at one random state:

- rigiddyn: rd.rnea(tree, q, v, a), rd.crba(tree, q), rd.aba(tree, q, v, tau) (each call sizes its own
  workspace and returns a new array);
- Pinocchio: pin.rnea(model, data, q, v, a), pin.crba(model, data, q) (the upper triangle),
  pin.aba(model, data, q, v, tau) (the data allocated once, outside the loop).

Each time is the best of several rounds of a loop of calls, in ns per call. The bare call of each binding (a
property getter: tree.nv, pybind11; model.nv, Boost.Python) is timed the same way; an algorithm's time
less its library's bare call is the cost of the algorithm and of converting its arrays (a call with
arrays costs more than a getter, so this overstates the algorithm's own cost, by the same order for both).

    python bench/python/bench_tree_pinocchio.py           # 20 000 calls a round, 7 rounds
    python bench/python/bench_tree_pinocchio.py --small   # 1 000 calls a round, 3 rounds (what ctest runs)

Prints, per robot and algorithm, the "ratio ..." line (bench/python/_bench_common.py) and the times less
the bare calls. Without yourdfpy (the `urdf` extra) the script says so and stops; without Pinocchio it
prints rigiddyn's times only.
"""

import importlib.util
from pathlib import Path

import numpy as np

import rigiddyn as rd
from _bench_common import parse_small, per_call, report_ratio

GRAVITY = [0.0, 0.0, -9.81]
ROBOTS = {"ur5": ("ur_description/urdf/ur5_robot.urdf", False),
          "panda": ("panda_description/urdf/panda.urdf", False),
          "talos": ("talos_data/robots/talos_reduced.urdf", True)}


def example_robot_data():
    """example-robot-data's robots folder (its PyPI wheel installs it under cmeel.prefix), or None."""
    cmeel = importlib.util.find_spec("cmeel")  # found, not imported
    if cmeel is None or cmeel.origin is None:
        return None
    robots = Path(cmeel.origin).resolve().parents[1] / "cmeel.prefix" / "share" / "example-robot-data" / "robots"
    return robots if robots.is_dir() else None


def limb_urdf(limbs, joints_per_limb, name):
    """A URDF of `limbs` chains of `joints_per_limb` revolute joints (axes z, y, x in turn, 0.2 m apart) on a
    base link; each link a 1 kg rod of 0.2 m along its x axis."""
    inertial = ('<inertial><mass value="1.0"/><origin xyz="0.1 0 0"/><inertia ixx="0.001" iyy="0.0034" '
                'izz="0.0034" ixy="0" ixz="0" iyz="0"/></inertial>')
    lines = [f'<robot name="{name}">', f'<link name="base">{inertial}</link>']
    for limb in range(limbs):
        parent = "base"
        for j in range(joints_per_limb):
            link = f"l{limb}_{j}"
            lines.append(f'<link name="{link}">{inertial}</link>')
            lines.append(f'<joint name="{link}_joint" type="revolute"><parent link="{parent}"/><child link="{link}"/>'
                         f'<origin xyz="{0.2 if j else 0.0} 0 0" rpy="0 0 {np.pi / 2 * limb if j == 0 else 0.0!r}"/>'
                         f'<axis xyz="{["0 0 1", "0 1 0", "1 0 0"][j % 3]}"/>'
                         '<limit lower="-3" upper="3" effort="10" velocity="5"/></joint>')
            parent = link
    return "\n".join(lines + ["</robot>"])


def robots():
    """name -> (URDF text, floating_base): example-robot-data's, else the two written here."""
    folder = example_robot_data()
    if folder is not None and all((folder / path).is_file() for path, _ in ROBOTS.values()):
        return {name: ((folder / path).read_text(), floating) for name, (path, floating) in ROBOTS.items()}
    print("example-robot-data is not installed (pip install example-robot-data): robots written here instead")
    return {"arm7": (limb_urdf(1, 7, "arm7"), False), "limbs4x6": (limb_urdf(4, 6, "limbs4x6"), True)}


def random_state(rng, tree):
    """q (the free joint's quaternion, if any, normalised), v, a and tau at random."""
    q = rng.uniform(-1.0, 1.0, tree.nq)
    if tree.nq != tree.nv:  # a floating base: q[3:7] its quaternion
        q[3:7] /= np.linalg.norm(q[3:7])
    return q, rng.normal(size=tree.nv), rng.normal(size=tree.nv), rng.normal(size=tree.nv)


def pinocchio_calls(pin, text, floating_base, tree, q, v, a, tau):
    """Pinocchio's rnea, crba and aba on the same state (q, v mapped by joint name), and its bare call."""
    model = pin.buildModelFromXML(text, pin.JointModelFreeFlyer()) if floating_base else pin.buildModelFromXML(text)
    model.gravity.linear = np.array(GRAVITY)
    data = model.createData()
    assert model.nv == tree.nv, (model.nv, tree.nv)
    # the timing does not depend on which state: Pinocchio's own neutral q moved by the same v, a and tau
    q_pin = pin.integrate(model, pin.neutral(model), 0.1 * v)
    return {"rnea": lambda: pin.rnea(model, data, q_pin, v, a), "crba": lambda: pin.crba(model, data, q_pin),
            "aba": lambda: pin.aba(model, data, q_pin, v, tau)}, lambda: model.nv


def main():
    args = parse_small(__doc__, "1 000 calls a round, 3 rounds, instead of 20 000 and 7")
    calls, rounds = (1_000, 3) if args.small else (20_000, 7)
    if importlib.util.find_spec("yourdfpy") is None:
        print("yourdfpy is not importable (pip install '.[urdf]'): no robot can be read, nothing timed")
        return
    try:
        import pinocchio as pin
    except ImportError:
        pin = None
        print("pinocchio is not importable (pip install '.[peers]'): rigiddyn's times only")
    rng = np.random.default_rng(0)
    for name, (text, floating_base) in robots().items():
        tree = rd.load_urdf(text, floating_base=floating_base, gravity=GRAVITY)
        q, v, a, tau = random_state(rng, tree)
        ours = {"rnea": lambda: rd.rnea(tree, q, v, a), "crba": lambda: rd.crba(tree, q),
                "aba": lambda: rd.aba(tree, q, v, tau)}
        bare_rd = per_call(lambda: tree.nv, calls, rounds)
        print(f"{name}: nv = {tree.nv}, {tree.num_links} links; bare call tree.nv {bare_rd * 1e9:.0f} ns", end="")
        if pin is None:
            print()
            for algorithm, fn in ours.items():
                t = per_call(fn, calls, rounds)
                print(f"  {algorithm}: rigiddyn {t * 1e9:.0f} ns/call, {(t - bare_rd) * 1e9:.0f} ns less the bare call")
            continue
        theirs, bare = pinocchio_calls(pin, text, floating_base, tree, q, v, a, tau)
        bare_pin = per_call(bare, calls, rounds)
        print(f", model.nv {bare_pin * 1e9:.0f} ns")
        for algorithm, fn in ours.items():
            t_rd, t_pin = per_call(fn, calls, rounds), per_call(theirs[algorithm], calls, rounds)
            report_ratio(f"{algorithm}_{name}", 1, t_rd, t_pin, "pinocchio")
            net_rd, net_pin = t_rd - bare_rd, t_pin - bare_pin
            print(f"  {algorithm} less the bare call: rigiddyn {net_rd * 1e9:.0f} ns, pinocchio {net_pin * 1e9:.0f} ns, "
                  f"rigiddyn/pinocchio = {net_rd / net_pin:.3f}")


if __name__ == "__main__":
    main()
