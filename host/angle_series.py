"""Joint-angle series for the seed-004 smoothers (``angle-kf``, ``angle-ekf``, ``angle-ukf``,
``angle-srukf``): reading, running, writing.

Accepted inputs (``kinefuse run --filter angle-… --input FILE``):

* ``seed004-arduino`` — the seed-004 Arduino serial CSV (RAW, UKF, EKF angles in degrees, no
  time column; read by :mod:`kinefuse.host.readers.seed004`): the **RAW** column (the angle the
  sensor's own fusion produced, before the board's filters) is smoothed; time is index / fs
  (fs = 35 Hz, the seed's protocols, unless given).
* ``angle-csv`` — a plain CSV with a header naming a time column ``t`` (or ``t_s``), seconds,
  and an ``angle_deg`` column, degrees; other columns are ignored, ``#`` lines are comments.  An
  empty or ``nan`` angle cell is a sample without a measurement (the filter predicts only).

The filters work in radians; the written CSV is in degrees: ``t`` s, ``angle_deg``,
``rate_deg_s``, and for the oscillator filters ``omega_rad_s`` (the frequency estimate).  Each
sample's time step comes from the time stamps (the first gets the median step); a step beyond
the smoothers' 0.2 s limit, or an angle beyond ±3.2 rad (183°), is rejected by the filter (state
kept, ``rejected`` counter incremented), as the IMU filters do.
"""
from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError

FORMATS = ("seed004-arduino", "angle-csv")
TIME_COLUMNS = ("t", "t_s")
ANGLE_COLUMN = "angle_deg"
IMU_SUFFIXES = (".mat", ".npz", ".kfr")


@dataclasses.dataclass
class AngleSeries:
    t: np.ndarray            # s
    angle: np.ndarray        # rad; NaN where the sample carries no measurement
    source: str = ""
    fmt: str = ""
    time_base: str = ""


def angle_filter_names() -> list[str]:
    from kinefuse.codegen import estimators
    return [n for n, cls in estimators.ESTIMATORS.items() if cls.inputs.name == "angle"]


def is_angle_filter(name: str) -> bool:
    return name in angle_filter_names()


def _cells(line: str) -> list[str]:
    return [c.strip().strip('"').strip().lower() for c in line.rstrip("\r\n").split(",")]


def _head(path: str, n: int = 25) -> list[str]:
    try:
        with open(path, encoding="utf-8-sig", errors="replace") as f:
            return [next(f, "") for _ in range(n)]
    except OSError as exc:
        raise KinefuseError(f"{path}: cannot open ({exc.strerror})") from None


def _csv_header(lines: list[str]) -> tuple[int, list[str]] | None:
    """(index, cells) of the first non-comment line if it names t and angle_deg."""
    for i, line in enumerate(lines):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        cells = _cells(line)
        if ANGLE_COLUMN in cells and any(c in cells for c in TIME_COLUMNS):
            return i, cells
        return None
    return None


def sniff(path: str | Path) -> str | None:
    """The angle-series format of ``path``, or None if it is not one (or does not exist)."""
    path = str(path)
    p = Path(path)
    if not p.is_file() or p.suffix.lower() in IMU_SUFFIXES:
        return None
    head = _head(path)
    if _csv_header(head) is not None:
        return "angle-csv"
    from kinefuse.host.readers import seed004
    return "seed004-arduino" if seed004.sniff_lines(head) else None


def _read_angle_csv(path: str) -> AngleSeries:
    try:
        with open(path, encoding="utf-8-sig", errors="replace") as f:
            lines = f.readlines()
    except OSError as exc:
        raise KinefuseError(f"{path}: cannot open ({exc.strerror})") from None
    found = _csv_header(lines)
    if found is None:
        raise KinefuseError(f"{path}: no header naming a t (s) and an {ANGLE_COLUMN} column")
    h, cells = found
    it = next(cells.index(c) for c in TIME_COLUMNS if c in cells)
    ia = cells.index(ANGLE_COLUMN)
    t, a = [], []
    for k in range(h + 1, len(lines)):
        line = lines[k]
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        row = [c.strip() for c in line.rstrip("\r\n").split(",")]
        if len(row) <= max(it, ia):
            raise KinefuseError(f"{path}: line {k + 1}: expected {len(cells)} columns, got {len(row)}")
        try:
            tv = float(row[it])
        except ValueError:
            raise KinefuseError(f"{path}: line {k + 1}: t: {row[it]!r} is not a number") from None
        cell = row[ia]
        if cell == "" or cell.lower() == "nan":
            av = math.nan
        else:
            try:
                av = float(cell)
            except ValueError:
                raise KinefuseError(f"{path}: line {k + 1}: {ANGLE_COLUMN}: {cell!r} is not a number") from None
            if not math.isfinite(av):
                raise KinefuseError(f"{path}: line {k + 1}: {ANGLE_COLUMN} = {cell} is not finite")
        if not math.isfinite(tv):
            raise KinefuseError(f"{path}: line {k + 1}: t = {row[it]} is not finite")
        if t and tv <= t[-1]:
            raise KinefuseError(f"{path}: line {k + 1}: t = {row[it]} s does not increase "
                                f"(previous {t[-1]:g} s)")
        t.append(tv)
        a.append(av)
    if not t:
        raise KinefuseError(f"{path}: no data rows")
    if all(math.isnan(v) for v in a):
        # every sample "predicted only": the filter's initial state (0°) was written as the angle
        raise KinefuseError(f"{path}: no angle in any of the {len(t)} rows ({ANGLE_COLUMN} empty or nan "
                            f"throughout); nothing to filter")
    return AngleSeries(np.asarray(t), np.radians(np.asarray(a)), path, "angle-csv",
                       "s, the file's t column")


def load(path: str | Path, fs: float | None = None) -> AngleSeries:
    """Read a joint-angle series (module docstring); one-line KinefuseError otherwise."""
    path = str(path)
    p = Path(path)
    if not p.exists():
        raise KinefuseError(f"{path}: no such file")
    if p.is_dir():
        raise KinefuseError(f"{path}: is a directory, expected a joint-angle series file")
    fmt = sniff(path)
    if fmt is None:
        raise KinefuseError(f"{path}: not a joint-angle series (expected the seed-004 Arduino CSV "
                            f"or a CSV with t [s] and {ANGLE_COLUMN} columns)")
    if fs is not None and fmt != "seed004-arduino":
        raise KinefuseError("--fs applies to the seed-004 Arduino CSV only (it has no time column)")
    if fmt == "angle-csv":
        return _read_angle_csv(path)
    from kinefuse.host.readers import read_recording
    rec = read_recording(path, fmt="seed004-arduino", fs=fs)
    return AngleSeries(np.asarray(rec.t, float), np.radians(rec.channels["angle_raw_deg"]), path,
                       fmt, f"s, index / {rec.fs:g} Hz (the file has no time column); RAW column")


def inputs(series: AngleSeries) -> dict[str, np.ndarray]:
    """The 'angle' input record: angle rad (0 where missing), angle_valid, dt s per sample."""
    t = np.asarray(series.t, float)
    d = np.diff(t)
    first = float(np.median(d)) if d.size else 0.02
    dt = np.concatenate([[first], d])
    a = np.asarray(series.angle, float)
    valid = np.isfinite(a)
    return {"angle": np.where(valid, a, 0.0), "angle_valid": valid, "dt": dt}


def run(name: str, impl: str, series_or_inputs, params: dict | None = None,
        preset: str | None = None) -> dict[str, np.ndarray]:
    """Outputs (float64, SI units) of smoother ``name`` in ``impl`` (ref, f32, q)."""
    from kinefuse.codegen import estimators, runner as cg
    from kinefuse.host.runner import IMPLS
    if not is_angle_filter(name):
        raise KinefuseError(f"filter {name!r} does not smooth a joint-angle series "
                            f"(those are: {', '.join(angle_filter_names())})")
    if impl not in IMPLS:
        raise KinefuseError(f"unknown implementation {impl!r} (choose from {', '.join(IMPLS)})")
    inp = series_or_inputs if isinstance(series_or_inputs, dict) else inputs(series_or_inputs)
    est = estimators.get(name)
    try:
        prm = est.resolve_params(params, preset)
    except ValueError as exc:
        raise KinefuseError(str(exc)) from None
    return cg.run(name, impl, inp, prm)


#: written columns: output name -> (column, scale from the filter's SI unit)
COLUMNS = {"angle": ("angle_deg", 180.0 / math.pi), "rate": ("rate_deg_s", 180.0 / math.pi),
           "omega": ("omega_rad_s", 1.0)}
