"""Hypothesis draws the same examples on every run: each test's random generator is seeded from the test itself
(`derandomize`), so that the suite on a fresh clone runs exactly what it ran before the change under test, and a
failure there is the change's, not a new draw's. Set RIGIDDYN_HYPOTHESIS_EXPLORE=1 to draw new examples instead (a
search for failing cases: a failure prints the `@reproduce_failure` line that replays it, to be kept as an
`@example`).

The profiles the test files register inherit this one's setting (a profile registered without a parent takes the
profile loaded at the time), and this file is imported before them.
"""

import os

from hypothesis import settings

settings.register_profile("rigiddyn_repeatable", derandomize=True)
settings.register_profile("rigiddyn_explore", derandomize=False)
EXPLORE = os.environ.get("RIGIDDYN_HYPOTHESIS_EXPLORE") == "1"
settings.load_profile("rigiddyn_explore" if EXPLORE else "rigiddyn_repeatable")
