"""Sensor calibration: every result is the per-sample affine map cal = M · (raw − b)
(:func:`kinefuse.host.calib.affine.apply_affine`).

accel (seed-002 LS, Procrustes, full model), gyro (static-window bias, known-rate scale),
mag (ellipsoid hard/soft iron, coverage, seed-001 gating), static (still-window detection used
by every calibration), unitfile (per-unit JSON), ellipsoid (shared fitting).
"""
