"""The variational midpoint method on trees: how many steps its fixed point leaves unconverged, by step size.

  PYTHONPATH=build/<dir>/python python3 bench/python/bench_variational_convergence.py [--small]

`implicit_midpoint` on a scene with a tree solves each step's discrete Euler–Lagrange equations by a fixed point,
its iterates mixed by Anderson's method (scene/scene_model.hpp); a step whose iterates miss the tolerance (1e-14
relative) within 20 is counted in `result.unconverged_steps`. The trees: 40 random trees of 5 links (a free base
on every other tree, then ball and revolute joints at random, rod-like links of 0.5–3 kg with transverse moments of
0.05–0.5 kg m² and axial ones 0.02–1.5 times those, so that thin links turn fast), each under UniformGravity,
linear Drag and a spring from its last link to a world anchor, started from random joint rates, run for 2 s at each
step size. Prints per step size the unconverged
steps of all runs, their total, and the runs that diverged (--small: 8 trees, two step sizes: what ctest runs).
"""

from __future__ import annotations

import sys
import warnings

import numpy as np

import rigiddyn as rd


def random_tree(rng, n, floating):
    """A tree of n links: a free base (floating) or a hinge, then ball or revolute joints on random parents."""
    tree = rd.Tree()
    for i in range(n):
        mass = rng.uniform(0.5, 3.0)
        transverse = rng.uniform(0.05, 0.5)  # a rod-like link: I = diag(I_a, I_t, I_t), I_a ≤ 2 I_t (realizable)
        axial = transverse * rng.uniform(0.02, 1.5)
        inertia = rd.SpatialInertia(mass, rng.uniform(-0.3, 0.3, 3), np.diag([axial, transverse, transverse]))
        if i == 0:
            joint = rd.FreeJoint() if floating else rd.RevoluteJoint(rng.normal(size=3))
            tree.add_link("link0", -1, joint, inertia)
            continue
        joint = rd.SphericalJoint() if rng.random() < 0.5 else rd.RevoluteJoint(rng.normal(size=3))
        tree.add_link(f"link{i}", int(rng.integers(0, i)), joint, inertia,
                      rd.Transform(translation=rng.uniform(-0.8, 0.8, 3)))
    return tree


def scene_of(tree):
    scene = rd.Scene(elements=[rd.UniformGravity(), rd.Drag(linear=0.3, angular_linear=0.2)])
    scene.add_tree(tree, "tree")
    scene.add(rd.SpringDamper(body_a=tree.num_links - 1, point_a_B=[0.1, 0.2, -0.1], point_b=[0.5, -0.3, 2.0],
                              stiffness=40.0, rest_length=0.5, damping=1.5))
    return scene


def main(small: bool) -> None:
    trees, steps = (8, (0.02, 0.1)) if small else (40, (0.005, 0.02, 0.05, 0.1, 0.2))
    warnings.simplefilter("ignore")  # the coarse steps are inaccurate, unconverged or diverge on purpose: counted here
    for h in steps:
        unconverged = total = diverged = 0
        for seed in range(trees):
            rng = np.random.default_rng(seed)
            tree = random_tree(rng, 5, seed % 2 == 0)
            v = rng.normal(size=tree.nv)
            result = rd.simulate(scene_of(tree), tree.joint_states(tree.neutral_configuration(), v), h, duration=2.0,
                                 method="implicit_midpoint", error=False, accuracy_level=None)
            unconverged += result.unconverged_steps
            total += len(result.t) - 1
            diverged += bool(result.diverged)
        print(f"h = {h:g} s: {unconverged} of {total} steps unconverged, {diverged} of {trees} runs diverged")


if __name__ == "__main__":
    main("--small" in sys.argv[1:])
