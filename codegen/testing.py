"""Test helpers shared by the generator tests and the harness (random IMU samples)."""
from __future__ import annotations

import numpy as np


def random_imu(n: int, seed: int = 0, bad_fraction: float = 0.0) -> dict[str, np.ndarray]:
    """Plausible random IMU samples, optionally with non-finite / out-of-range ones."""
    rng = np.random.default_rng(seed)
    t = np.arange(n) * 0.01
    gyr = np.column_stack([np.sin(0.7 * t), np.cos(0.3 * t), 0.5 * np.sin(0.2 * t)]) * 2.0
    gyr += rng.normal(0, 0.01, (n, 3))
    acc = np.tile([0.0, 0.0, 9.81], (n, 1)) + rng.normal(0, 0.3, (n, 3))
    mag = np.tile([0.0, 20.0, -40.0], (n, 1)) + rng.normal(0, 0.5, (n, 3))
    mag_valid = rng.random(n) < 0.5
    dt = np.full(n, 0.01) + rng.normal(0, 0.0005, n)
    if bad_fraction:
        pick = rng.random(n) < bad_fraction
        bad = np.array([np.nan, np.inf, -np.inf, 1e9, -1e30, 0.0])
        for arr in (gyr, acc, mag):
            m = pick & (rng.random(n) < 0.5)
            arr[m, rng.integers(0, 3, m.sum())] = rng.choice(bad, m.sum())
        m = pick & (rng.random(n) < 0.3)
        dt[m] = rng.choice(np.array([np.nan, -0.01, 0.0, 5.0, np.inf]), m.sum())
    return {"gyr": gyr, "acc": acc, "mag": mag, "mag_valid": mag_valid, "dt": dt}


def build_adhoc(est, workdir, systems=("f32", "q")):
    """Generate, compile (cffi) and load an estimator that is not in the registry.

    Returns {system: (CRunner, ModelRunner)} sharing the generated model's metadata."""
    import types
    from pathlib import Path

    from kinefuse.codegen.build import build
    from kinefuse.codegen.estimator import generated_stem
    from kinefuse.codegen.generate import render_estimator
    from kinefuse.codegen.runner import CRunner, ModelRunner

    d = Path(workdir)
    (d / "models").mkdir(parents=True, exist_ok=True)
    files = render_estimator(est, "adhoc", systems)
    for rel, text in files.items():
        (d / rel).write_text(text)
    out = {}
    for system in systems:
        P = generated_stem(est.name, system)
        spec_h = d / f"kf_{est.inputs.name}_{system}.h"
        mod = types.ModuleType(f"adhoc_{P}")
        exec(compile(files[f"models/{P}.py"], f"<model {P}>", "exec"), mod.__dict__)
        ffi_lib = build(f"adhoc_{P}", [spec_h, d / f"{P}.h"], [d / f"{P}.c"], include_dirs=[d])
        out[system] = (CRunner(est.name, system, mod, ffi_lib, est.inputs.name),
                       ModelRunner(est.name, system, mod))
    return out
