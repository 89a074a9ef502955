"""Run kinefuse filters on recordings (BROAD trials, simulator recordings, decoded captures).

This is the host's single entry point to the estimators: it maps a recording's sensor arrays
onto a filter's input record and returns the orientation (and status) per input sample.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from kinefuse.codegen import estimators, runner as cg_runner
from kinefuse.host.errors import KinefuseError

IMPLS = ("ref", "f32", "q")


@dataclasses.dataclass
class FilterResult:
    q: np.ndarray                                   # (N, 4) w,x,y,z sensor -> earth (ENU)
    status: dict[str, np.ndarray] = dataclasses.field(default_factory=dict)
    outputs: dict[str, np.ndarray] = dataclasses.field(default_factory=dict)


def filter_names() -> list[str]:
    return list(estimators.ESTIMATORS)


def imu_filter_names() -> list[str]:
    """Filters that take IMU samples (the others take, e.g., an angle series)."""
    return [n for n, cls in estimators.ESTIMATORS.items() if cls.inputs.name == "imu"]


def default_filter() -> str:
    return "flagship" if "flagship" in estimators.ESTIMATORS else "madgwick"


def parse_params(items: list[str] | None) -> dict[str, float]:
    """['beta=0.1', 'mode=9d'] -> {'beta': 0.1, 'mode': ...}; one-line errors."""
    out: dict[str, float] = {}
    for item in items or []:
        if "=" not in item:
            raise KinefuseError(f"--param expects name=value, got {item!r}")
        k, v = item.split("=", 1)
        k, v = k.strip(), v.strip()
        if v.lower() in ("6d", "9d"):
            out[k] = 0.0 if v.lower() == "6d" else 1.0
            continue
        try:
            out[k] = float(v)
        except ValueError:
            raise KinefuseError(f"--param {k}: {v!r} is not a number") from None
    return out


def imu_inputs(trial, mag_every: int = 1) -> dict[str, np.ndarray]:
    """A recording's arrays as the 'imu' input record (dt per sample in seconds)."""
    n = len(trial.gyr)
    dt = getattr(trial, "dt", None)
    if dt is None or np.ndim(dt) == 0:
        dt = np.full(n, float(dt) if dt is not None else 1.0 / float(trial.rate_hz))
    mag_valid = getattr(trial, "mag_valid", None)
    if mag_valid is None:
        mag_valid = np.ones(n, dtype=bool)
    mag_valid = np.asarray(mag_valid, dtype=bool).copy()
    if mag_every > 1:
        mag_valid[np.arange(n) % mag_every != 0] = False
    return {"gyr": np.asarray(trial.gyr, float), "acc": np.asarray(trial.acc, float),
            "mag": np.asarray(trial.mag, float), "mag_valid": mag_valid,
            "dt": np.asarray(dt, float)}


def run_filter(name: str, impl: str, trial, params: dict[str, float] | None = None,
               preset: str | None = None) -> FilterResult:
    """Run filter `name` ('ref', 'f32' = generated C, 'q' = fixed-point C) over a recording."""
    if name not in estimators.ESTIMATORS:
        raise KinefuseError(f"unknown filter {name!r} (available: {', '.join(filter_names())})")
    if impl not in IMPLS + ("f32-model", "q-model"):
        raise KinefuseError(f"unknown implementation {impl!r} (choose from {', '.join(IMPLS)})")
    est = estimators.get(name)
    if est.inputs.name != "imu":
        raise KinefuseError(f"filter {name!r} takes {est.inputs.name} inputs, not IMU samples")
    try:
        prm = est.resolve_params(params, preset)
    except ValueError as exc:
        raise KinefuseError(str(exc)) from None
    out = cg_runner.run(name, impl, imu_inputs(trial), prm)
    q = np.asarray(out["q"], dtype=np.float64)
    status = {k: np.asarray(v).reshape(len(q), -1).squeeze(axis=1)
              for k, v in out.items() if k != "q" and np.asarray(v).reshape(len(q), -1).shape[1] == 1}
    return FilterResult(q=q, status=status, outputs=out)
