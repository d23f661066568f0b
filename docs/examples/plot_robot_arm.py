r"""
A robot arm from URDF under joint torques: holding torques from RNEA, motion from ABA
=====================================================================================

A two-joint arm read from a URDF robot description (:func:`rigiddyn.load_urdf`): a base fixed to the world, an
upper arm on a shoulder joint and a forearm on an elbow joint, both about horizontal y axes. In a scene each link
is a body (:meth:`rigiddyn.Scene.add_tree`) under :class:`rigiddyn.UniformGravity`; a joint's motor is a pair of
couples, +τ a on the link it drives and −τ a on its parent, a the joint's axis (fixed in both links' frames for a
revolute joint, so each couple is a :class:`rigiddyn.ScheduledLoads` load fixed in its body's frame).

**What it checks:** the holding torques that inverse dynamics gives (:func:`rigiddyn.rnea` at rest, Featherstone
Table 5.1) keep the arm at rest under gravity; with the shoulder's torque then raised for a second, the scene's run
equals a hand-written RK4 loop around :func:`rigiddyn.aba` with the same joint torques, to the round-off bound of
the same map evaluated in another order. (The constant torques hold only the start pose: knocked out of it, the
arm swings under gravity and its light forearm whirls round.)
"""

# %%
# The arm, its scene and its motors
# ---------------------------------
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd

URDF = """<robot name="arm">
  <link name="base"><inertial><mass value="5.0"/><origin xyz="0 0 0.25"/>
    <inertia ixx="0.1" iyy="0.1" izz="0.05" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="upper"><inertial><mass value="1.0"/><origin xyz="0.25 0 0"/>
    <inertia ixx="0.001" iyy="0.02" izz="0.02" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="fore"><inertial><mass value="0.5"/><origin xyz="0.2 0 0"/>
    <inertia ixx="0.0005" iyy="0.007" izz="0.007" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="50" velocity="5"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="fore"/>
    <origin xyz="0.5 0 0"/><axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="50" velocity="5"/></joint>
</robot>"""
G_W = np.array([0.0, 0.0, -9.81])
arm = rd.load_urdf(URDF)  # no gravity of its own: the scene's element loads it
print(arm.link_names, "q:", arm.nq)

q0 = np.array([0.3, -0.6])  # shoulder and elbow angles [rad] (Ry: positive turns the arm's x axis down)
holding = rd.rnea(rd.load_urdf(URDF, gravity=G_W), q0, np.zeros(2), np.zeros(2))  # [N m]
print(f"holding torques: shoulder {holding[0]:.6f} N m, elbow {holding[1]:.6f} N m")


def arm_scene(torque_schedule):
    """The arm under gravity with its motors: torque_schedule(joint) -> [(tau [N m], t_start, t_end), ...]."""
    scene = rd.Scene(elements=[rd.UniformGravity(g_W=G_W)])
    links = scene.add_tree(arm)
    for joint, link in enumerate((1, 2)):  # the shoulder drives link 1, the elbow link 2 (link 0: the fixed base)
        axis = arm.joints[link].axis
        axis_in_parent = arm.placements[link].rotation @ axis
        parent = arm.parents[link]
        for body, couple in ((links[link], axis), (links[parent], -axis_in_parent)):
            scene.add(rd.ScheduledLoads(body=body, loads=[
                rd.AppliedLoad(torque=tau * couple, frame="body", t_start=t0, t_end=t1)
                for tau, t0, t1 in torque_schedule(joint)]))
    return scene


# %%
# Held at rest
# ------------
start = arm.joint_states(np.concatenate([q0]))
held = rd.simulate(arm_scene(lambda j: [(holding[j], 0.0, np.inf)]), start, 1e-3, duration=2.0, method="rk4")
drift = np.max(np.abs(held.joint_q - q0))
print(f"held for 2 s: largest joint drift {drift:.2e} rad")
# at rest the accelerations are zero to round-off (~1e-15 rad/s^2 from terms of size g/l ~ 20), which two seconds
# integrate to ~1e-15 rad: within 1e-12 rad
assert drift < 1e-12

# %%
# A torque pulse: the scene against a hand loop around ABA
# --------------------------------------------------------
pulse = 0.5  # [N m] added to the shoulder's holding torque for 1 s


def schedule(joint):
    steps = [(holding[joint], 0.0, np.inf)]
    return steps + ([(pulse, 0.5, 1.5)] if joint == 0 else [])


dt, duration = 1e-3, 2.0
run = rd.simulate(arm_scene(schedule), start, dt, duration=duration, method="rk4", record_every=10)

heavy = rd.load_urdf(URDF, gravity=G_W)


q, v = q0.copy(), np.zeros(2)
for k in range(round(duration / dt)):  # RK4 on (q, v); the pulse's switch times fall on step boundaries, so each
    tau = holding + (np.array([pulse, 0.0]) if 500 <= k < 1500 else 0.0)  # step takes its torque whole, as the run

    def a(q, v):
        return rd.aba(heavy, q, v, tau)

    k1q, k1v = v, a(q, v)
    k2q, k2v = v + dt / 2 * k1v, a(q + dt / 2 * k1q, v + dt / 2 * k1v)
    k3q, k3v = v + dt / 2 * k2v, a(q + dt / 2 * k2q, v + dt / 2 * k2v)
    k4q, k4v = v + dt * k3v, a(q + dt * k3q, v + dt * k3v)
    q, v = q + dt / 6 * (k1q + 2 * k2q + 2 * k3q + k4q), v + dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
print(f"after {duration} s: scene q = {run.joint_q[-1]}, hand loop q = {q}")
# the same RK4 map: the two differ by the order of their sums (gravity as link forces or as a base acceleration),
# a few eps of terms ~ g/l = 20 rad/s^2 per evaluation; 8000 evaluations on a motion whose tangent map stays O(10)
# over 2 s carry that to ~1e-10: within 1e-9
assert np.max(np.abs(run.joint_q[-1] - q)) < 1e-9 and np.max(np.abs(run.joint_v[-1] - v)) < 1e-9
assert run.balance.verdict["energy"] == "closed"  # the motors' couples do work: the balance holds it

fig, ax = plt.subplots(figsize=(7, 3))
ax.plot(run.t, run.joint_q[:, 0], label="shoulder")
ax.plot(run.t, run.joint_q[:, 1], label="elbow")
ax.axvspan(0.5, 1.5, color="0.9", label="shoulder pulse")
ax.set_xlabel("t [s]")
ax.set_ylabel("joint angle [rad]")
ax.legend()
fig.tight_layout()
plt.show()
