"""Run kinefuse filters on recordings (BROAD trials, simulator recordings, decoded captures).

This is the host's single entry point to the estimators: it maps a recording's sensor arrays
onto a filter's input record and returns the orientation (and status) per input sample.
"""
from __future__ import annotations

import dataclasses
import os
import types
from pathlib import Path

import numpy as np

from kinefuse.codegen import estimators, runner as cg_runner
from kinefuse.codegen.estimators.common import DT_MAX
from kinefuse.host.errors import KinefuseError

IMPLS = ("ref", "f32", "q")


@dataclasses.dataclass
class FilterResult:
    q: np.ndarray                                   # (N, 4) w,x,y,z sensor -> earth (ENU)
    status: dict[str, np.ndarray] = dataclasses.field(default_factory=dict)
    outputs: dict[str, np.ndarray] = dataclasses.field(default_factory=dict)
    units: dict[str, str] = dataclasses.field(default_factory=dict)   # output name -> unit


def filter_names() -> list[str]:
    return list(estimators.ESTIMATORS)


def imu_filter_names() -> list[str]:
    """Filters that take IMU samples (the others take, e.g., an angle series)."""
    return [n for n, cls in estimators.ESTIMATORS.items() if cls.inputs.name == "imu"]


def default_filter() -> str:
    return "flagship" if "flagship" in estimators.ESTIMATORS else "madgwick"


def parse_params(items: list[str] | None) -> dict[str, float | str]:
    """['beta=0.1', 'mode=9d'] -> {'beta': 0.1, 'mode': '9d'}; one-line errors for a malformed
    item, a name given twice or a non-finite value.  A value that is not a number stays text: the
    filter's declaration resolves a choice's label (``mode=6d``) and refuses anything else
    (:func:`check_params`)."""
    from kinefuse.host.paramargs import parse_assignments
    return parse_assignments(items, "--param", form="name=value")


def check_params(name: str, params: dict | None = None, preset: str | None = None) -> dict[str, float]:
    """Filter ``name``'s full parameter set (defaults, then ``preset``, then ``params``; an
    override wins over the preset), every value checked against its declaration (range, choices,
    labels); KinefuseError (one line) otherwise."""
    est = estimators.get(name)
    try:
        return est.resolve_params(params, preset)
    except ValueError as exc:
        raise KinefuseError(str(exc)) from None


def output_times(trial) -> np.ndarray:
    """The t column (s) of a trial's estimates: its own sample times when it has them (a
    simulator .mat with timing effects), else index x sample period (BROAD)."""
    if getattr(trial, "steps", None) is not None:
        return np.asarray(trial.t, dtype=np.float64)
    return np.arange(trial.n) * float(trial.dt)


def imu_inputs(trial, mag_every: int = 1) -> dict[str, np.ndarray]:
    """A recording's arrays as the 'imu' input record (dt per sample in seconds)."""
    n = len(trial.gyr)
    dt = getattr(trial, "steps", None)      # a trial with sample times of its own
    if dt is None:
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
    if "q" not in [v.name for v in est.outputs]:
        # (an internal KeyError after the whole run)
        raise KinefuseError(f"filter {name!r} has no 'q' output (its outputs: "
                            f"{', '.join(v.name for v in est.outputs)}); an IMU filter for run, "
                            f"replay and bench must output the orientation quaternion q")
    prm = check_params(name, params, preset)
    out = cg_runner.run(name, impl, imu_inputs(trial), prm)
    q = np.asarray(out["q"], dtype=np.float64)
    status = {k: np.asarray(v).reshape(len(q), -1).squeeze(axis=1)
              for k, v in out.items() if k != "q" and np.asarray(v).reshape(len(q), -1).shape[1] == 1}
    # a flag has no unit: say what its values are (rest (0/1) in the CSV's comment line)
    units = {v.name: v.unit or ("(0/1)" if getattr(v, "type", "") == "bool" else "")
             for v in est.outputs}
    return FilterResult(q=q, status=status, outputs=out, units=units)


def recording_inputs(rec) -> types.SimpleNamespace:
    """A reader :class:`~kinefuse.host.readers.Recording` as filter input (for :func:`run_filter`).

    ``dt`` per sample from the recording's time stamps (the first sample gets the median step;
    a unit recording's steps come from the unit's own sample clock, ``device_time_s``): gaps
    stay gaps, so a step beyond the filters' limit (``DT_MAX`` = 1 s) makes the filter
    reject that sample.  ``mag_valid`` is True on the samples carrying a new magnetometer
    reading (``rec.mag_t``; every sample when the file has one magnetometer value per sample),
    False throughout without a magnetometer (``mag`` is then zero).
    """
    rec.require("acc", "gyr")
    t = np.asarray(rec.t, dtype=np.float64)
    n = len(t)
    d = np.diff(t)
    dev = rec.channels.get("device_time_s")
    if dev is not None and len(dev) == n:
        # a unit recording: the steps of the unit's own sample clock, which its filter used.
        # t maps that clock to the host's by a fitted line, which frames that waited in a
        # buffer before the host read them can bend; across a reboot (the device clock
        # restarts) the host-time step stays
        dd = np.diff(np.asarray(dev, dtype=np.float64))
        d = np.where(dd > 0, dd, d)
    first = float(np.median(d)) if d.size else 0.0
    dt = np.concatenate([[first], d]) if n else np.zeros(0)
    if rec.mag is None:
        mag, mag_valid = np.zeros((n, 3)), np.zeros(n, dtype=bool)
    else:
        mag = np.asarray(rec.mag, dtype=np.float64)
        mag_valid = np.ones(n, dtype=bool) if rec.mag_t is None else np.isin(t, rec.mag_t)
    return types.SimpleNamespace(gyr=np.asarray(rec.gyr, np.float64), acc=np.asarray(rec.acc, np.float64),
                                 mag=mag, mag_valid=mag_valid, dt=dt, t=t)


def rejected_count(res: FilterResult) -> int | None:
    """Samples the filter rejected over the run (its cumulative ``rejected`` output)."""
    r = res.outputs.get("rejected")
    if r is None or not len(res.q):
        return None
    return int(np.asarray(r).reshape(len(res.q), -1)[-1, 0])


#: the ENU <-> NED swap (x <-> y, z -> -z): a half turn about (1, 1, 0)/sqrt(2), its own inverse
Q_SWAP_ENU_NED = np.array([0.0, np.sqrt(0.5), np.sqrt(0.5), 0.0])
FRAMES = ("enu", "ned")
FRAME_TEXT = {"enu": "earth frame ENU (x East, y North, z Up)",
              "ned": "earth frame NED (x North, y East, z Down)"}


#: status outputs that are sensor->earth quaternions or earth-frame covariances (xx, xy, xz, yy,
#: yz, zz): written in the requested earth frame like q
EARTH_QUATERNIONS = ("q6", "q9")
EARTH_COVARIANCES = ("cov_att",)
#: status outputs that are 3-vectors along the sensor axes (gyroscope bias and its variance,
#: the ESKF's linear acceleration): the same in either earth frame
SENSOR_VECTORS = ("bias", "var_bias", "lin_acc")


def _cov6_enu_to_ned(c: np.ndarray) -> np.ndarray:
    """(xx, xy, xz, yy, yz, zz) of an ENU covariance as the NED one, S P Sᵀ with S the swap
    x <-> y, z -> -z."""
    xx, xy, xz, yy, yz, zz = (c[:, i] for i in range(6))
    return np.column_stack([yy, xy, 0.0 - yz, xx, 0.0 - xz, zz])   # 0.0 - v: no -0 in the CSV


def swap_enu_ned(q: np.ndarray) -> np.ndarray:
    """Sensor->ENU quaternions as sensor->NED, or NED as ENU (the swap is its own inverse)."""
    from kinefuse.host.kinematics.quat import mul
    return mul(Q_SWAP_ENU_NED, np.asarray(q, float))


def to_earth_frame(q: np.ndarray, frame: str) -> np.ndarray:
    """Sensor->ENU quaternions (w, x, y, z) expressed sensor->``frame`` ('enu' or 'ned')."""
    if frame == "enu":
        return q
    if frame != "ned":
        raise KinefuseError(f"unknown earth frame {frame!r} (choose enu or ned)")
    out = swap_enu_ned(q)
    return np.where(out[:, :1] < 0, -out, out)          # canonical w >= 0


def write_estimates_csv(path, t, res: FilterResult, comment: str, status: bool = False,
                        frame: str = "enu") -> int:
    """Estimates as CSV: ``# comment`` line, header ``t,w,x,y,z`` (+ the filter's status outputs
    when ``status``), one row per input sample; returns the number of rows.  The quaternions
    are written sensor->``frame`` (the filters work in ENU; 'ned' rotates them)."""
    n = len(res.q)
    q = to_earth_frame(np.asarray(res.q, float), frame)
    cols = [np.asarray(t, dtype=np.float64), q[:, 0], q[:, 1], q[:, 2], q[:, 3]]
    header = ["t", "w", "x", "y", "z"]
    if status:
        described = []
        for k, v in res.outputs.items():
            if k == "q":
                continue
            v = np.asarray(v).reshape(n, -1).astype(float)
            if k in EARTH_QUATERNIONS and v.shape[1] == 4:
                v = to_earth_frame(v, frame)            # q6, q9: sensor->frame like q
            elif k in EARTH_COVARIANCES and v.shape[1] == 6 and frame == "ned":
                v = _cov6_enu_to_ned(v)
            for i in range(v.shape[1]):
                cols.append(v[:, i])
                header.append(k if v.shape[1] == 1 else f"{k}_{i}")
            unit = res.units.get(k, "")
            described.append(f"{k} {unit}".strip() if unit else k)
        if described:
            f = frame.upper()
            notes = ([f"{', '.join(k for k in EARTH_QUATERNIONS if k in res.outputs)} sensor->{f}"]
                     if any(k in res.outputs for k in EARTH_QUATERNIONS) else [])
            notes += [f"{k} in the {f} frame" for k in EARTH_COVARIANCES if k in res.outputs]
            # what the numbered columns hold (k_0, k_1, ...)
            width = {k: np.asarray(v).reshape(n, -1).shape[1] for k, v in res.outputs.items() if k != "q"}
            quats = [k for k in EARTH_QUATERNIONS if width.get(k) == 4]
            covs = [k for k in EARTH_COVARIANCES if width.get(k) == 6]
            vecs = [k for k in SENSOR_VECTORS if width.get(k) == 3]
            if quats:
                notes.append(f"{', '.join(k + '_0..3' for k in quats)} = w, x, y, z")
            if covs:
                notes.append(f"{', '.join(k + '_0..5' for k in covs)} = xx, xy, xz, yy, yz, zz")
            if vecs:
                notes.append(f"{', '.join(k + '_0..2' for k in vecs)} = x, y, z of the sensor frame")
            comment = (f"{comment}; status columns: {', '.join(described)}"
                       + (f" ({'; '.join(notes)})" if notes else ""))
    write_csv(path, comment, header, cols)
    return n


#: the t column keeps 15 significant digits: a time stamp in s since the epoch (1.7e9 s) or a
#: unit's clock after weeks of uptime stays resolved to the µs (9 digits, as for the estimates,
#: wrote 1733250000.03 s as 1.73325e+09 and every row of a second got the same t)
T_FMT = "%.15g"
VALUE_FMT = "%.9g"


def write_csv(path, comment: str, header: list[str], cols: list[np.ndarray]) -> None:
    """``# comment`` line, ``header`` line, one row per sample: the first column (t, s) with
    :data:`T_FMT`, the others with :data:`VALUE_FMT`.  A regular file is written under a
    temporary name and renamed into place, so a failed write (full disk, interrupt) leaves no
    half-written CSV and an earlier file as it was; KinefuseError (one line) on failure."""
    given = Path(path)
    data = np.column_stack(cols) if cols else np.zeros((0, 0))
    fmts = [T_FMT] + [VALUE_FMT] * (data.shape[1] - 1)

    def write(target):
        with open(target, "w") as f:
            f.write(f"# {comment}\n")
            f.write(",".join(header) + "\n")
            np.savetxt(f, data, delimiter=",", fmt=fmts)

    try:
        if given.exists() and not given.is_file():     # /dev/stdout, a FIFO: write it directly
            write(given)
            return
        dest = Path(os.path.realpath(given))           # through a symlink: replace its target
        tmp = dest.with_name(f".{dest.name}.{os.getpid()}.tmp")
        try:
            open(tmp, "x").close()
        except PermissionError:
            if not dest.exists():
                raise
            write(dest)             # a writable file in a folder that is not: in place
            return
        try:
            write(tmp)
            if dest.exists():
                import shutil
                shutil.copymode(dest, tmp)          # --force keeps the file's permissions
            os.replace(tmp, dest)
        except BaseException:
            tmp.unlink(missing_ok=True)
            raise
    except OSError as exc:
        raise KinefuseError(f"cannot write {path}: {exc.strerror or exc}") from None
