"""Sensor-to-segment alignment, joint orientation and angles, clinical reports.

quat (w,x,y,z conventions, named Euler sequences), alignment (two-posture, functional,
static pose), joint (q_prox* ⊗ q_dist, Grood & Suntay / seed-001 ZYX / seed-002 XYZ),
misalignment (seed 002 §5.4 study), cycles, orientation (pluggable filter), report (knee and
elbow), simulate (synthetic recordings with truth), bench (``kinefuse bench joint-angles``).
"""
