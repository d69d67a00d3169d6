"""The double pendulum and its report, derived once for the tests of tests/report."""

import pytest

from rigidmech import models, report


@pytest.fixture(scope="session")
def double_pendulum():
    return models.double_pendulum()


@pytest.fixture(scope="session")
def double_pendulum_report(double_pendulum):
    return report.derivation(double_pendulum)
