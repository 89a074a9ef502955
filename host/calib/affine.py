"""The one calibration map applied to every sensor sample: ``cal = M · (raw − b)``.

This is the Python reference for the on-unit application of calibration parameters (to be
generated as float32 and fixed-point C): a plain per-sample affine map with a 3×3 matrix and a
3-vector, no branches, no state.  Keep it that way.
"""
from __future__ import annotations

import numpy as np


def apply_affine(raw, M, b):
    """Calibrate samples: ``M @ (raw - b)`` for each row of ``raw`` (…×3).

    ``M`` (3×3) and ``b`` (3) come from a calibration; units are those of the fit (the
    accelerometer in m/s², the gyroscope in rad/s, the magnetometer in µT).
    """
    raw = np.asarray(raw)
    return (raw - np.asarray(b)) @ np.asarray(M).T
