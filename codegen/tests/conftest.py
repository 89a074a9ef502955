"""Shared fixtures of the generator tests."""
from __future__ import annotations

import numpy as np
import pytest


@pytest.fixture(scope="session")
def excerpt_inputs():
    """IMU inputs from the bundled BROAD excerpt (the default suite needs nothing else)."""
    from kinefuse.host import broad, runner
    files = broad.bundled_trials()
    assert files, "the bundled BROAD excerpt is missing"
    trial = broad.load_trial(files[0])
    return trial, runner.imu_inputs(trial)
