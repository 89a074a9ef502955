"""Helpers of the property-based checks (``hil_tests/tests/test_props_*.py``).

Outputs are taken from the host C (``host-f32`` / ``host-q``), which the bit-exactness tests
tie to the Python models and to the Cortex-M builds: a property that holds here holds on
the unit.  Orientation outputs are the size-4 real outputs whose name starts with ``q``
(w, x, y, z, sensor → earth, ENU).
"""
from __future__ import annotations

import functools

import numpy as np

from kinefuse.codegen import estimators
from kinefuse.hil_tests.harness import loops, motion


def quaternion_outputs(name: str) -> list[str]:
    cls = estimators.ESTIMATORS[name]
    return [v.name for v in cls.outputs if v.size == 4 and v.type == "real" and v.name.startswith("q")]


def run(name: str, system: str, inputs: dict, params: dict | None = None) -> dict[str, np.ndarray]:
    """Host C outputs decoded to float64 (``system`` 'f32' or 'q'; 'ref' for the reference)."""
    if system == "ref":
        return loops.run_loop("ref", name, inputs, params)
    lp = f"host-{system}"
    return loops.decode(name, lp, loops.run_loop(lp, name, inputs, params))


def rest(q, seconds: float, rate_hz: float = 100.0, field=None, mag_valid=True):
    n = int(round(seconds * rate_hz))
    return motion.synth(q, np.zeros((n, 3)), 1.0 / rate_hz, field=field, mag_valid=mag_valid)


def concat(*parts):
    ins = {k: np.concatenate([p[0][k] for p in parts]) for k in parts[0][0]}
    return ins, np.concatenate([p[1] for p in parts])


@functools.lru_cache(maxsize=None)
def uses_magnetometer(name: str, system: str = "f32") -> bool:
    """True when the filter's heading follows magnetic north: at rest, turning the field by 90°
    about the vertical turns the estimated heading by more than 45° within 60 s."""
    q0 = np.array([1.0, 0.0, 0.0, 0.0])
    a, _ = rest(q0, 60.0, field=motion.field_enu(0.0))
    b, _ = rest(q0, 60.0, field=motion.field_enu(90.0))
    qa = run(name, system, a)["q"][-1]
    qb = run(name, system, b)["q"][-1]
    _, heading, _ = motion.errors_deg(qa, qb)
    return bool(heading > 45.0)


def smooth_rates(rng: np.random.Generator, n: int, rate_hz: float, amplitude: float) -> np.ndarray:
    """Band-limited body rates (rad/s): three sinusoids per axis, random frequencies 0.1–1.5 Hz,
    tapered to zero at both ends."""
    t = np.arange(n) / rate_hz
    w = np.zeros((n, 3))
    for ax in range(3):
        for _ in range(3):
            f = rng.uniform(0.1, 1.5)
            w[:, ax] += rng.uniform(-1, 1) * amplitude / 3 * np.sin(2 * np.pi * f * t + rng.uniform(0, 6.3))
    taper = np.minimum(1.0, np.minimum(t, t[-1] - t) / 1.0) if n > 1 else np.ones(n)
    return w * taper[:, None]
