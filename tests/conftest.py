"""Shared test configuration.

Hypothesis: no per-example deadline (CI machines are shared and symbolic examples vary in
cost; a deadline would make tests flaky, not stricter), and a derandomised run in CI so that a
failure is reproducible from the log.
"""

import os

from hypothesis import HealthCheck, settings

settings.register_profile(
    "rigidmech",
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
    derandomize=bool(os.environ.get("CI")),
)
settings.load_profile("rigidmech")
