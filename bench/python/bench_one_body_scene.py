"""simulate of one body (its one-body scene) against the one-body model it replaced, in the same process.

One free rigid body (I = diag(1, 2, 3), w_B = (0.1, 1, 0.1), uniform gravity) stepped by rk4 for n steps:
  - rigiddyn: rd.simulate(body, ...), the body's one-body scene on the scene model's one-body layout, whose
    records hold the scene's columns (per record 16 + 20 per body + 2 per element = 38 doubles here: the state,
    the pivot reaction, H about the centre of mass, the mass, the energies, momenta and impulses, the gravity
    element's work and power);
  - one-body model: rd.simulate_batch(body, [state], threads=1), the same run on RigidBodyModel (a batch sample's
    19 doubles per record), the path simulate took before it ran scenes.
Both are wall times of the whole call, best of 5, recording every step and every 1000th step: the ratio at 1000
is the stepping, at 1 the stepping and the recording.

    python bench/python/bench_one_body_scene.py           # n = 1e6
    python bench/python/bench_one_body_scene.py --small   # n = 1e5 (what ctest runs)
"""

import rigiddyn as rd
from _bench_common import best_time, parse_small, report_ratio


def main():
    args = parse_small(__doc__, "1e5 steps instead of 1e6")
    steps = 100_000 if args.small else 1_000_000
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    state = rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])
    for record_every in (1, 1000):
        options = dict(record_every=record_every, gravity=True, error=False)
        scene = best_time(lambda: rd.simulate(body, state, 1e-3, steps, "rk4", **options), repeats=5)
        model = best_time(lambda: rd.simulate_batch(body, [state], 1e-3, steps, "rk4", threads=1, **options),
                          repeats=5)
        report_ratio(f"simulate_one_body_rk4_record_every_{record_every}", steps, scene, model, "one_body_model")


if __name__ == "__main__":
    main()
