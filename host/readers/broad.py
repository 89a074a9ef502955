"""BROAD benchmark trial (.mat, MATLAB v5): imu_acc m/s², imu_gyr rad/s, imu_mag µT; or a trial
of the excerpt bundled with kinefuse (.npz, read by :func:`kinefuse.host.broad.load_trial`).

Laidig, Caruso, Cereatti, Seel, Data 6(7):72, 2021 (CC BY 4.0).  ``opt_quat`` (optical
reference, sensor → East-North-Up, NaN where markers were lost) and ``movement`` go to
``channels`` (``opt_quat_wxyz``, ``movement``) — they are a reference, not a device estimate.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from kinefuse.host.readers.recording import ReaderError, Recording, check_acc_units

FORMAT = "broad-mat"


def read(path: str, **_) -> Recording:
    if str(path).lower().endswith(".npz"):
        return _read_excerpt(path)
    try:
        import scipy.io
        d = scipy.io.loadmat(path)
    except FileNotFoundError:
        raise ReaderError(path, "file not found") from None
    except IsADirectoryError:
        raise ReaderError(path, "is a directory; give one recording file") from None
    except Exception as exc:  # scipy raises several types for non-MAT files
        raise ReaderError(path, f"not a MATLAB v5 file ({type(exc).__name__})") from None
    for k in ("imu_acc", "imu_gyr", "sampling_rate"):
        if k not in d:
            raise ReaderError(path, f"missing variable {k!r} (not a BROAD trial?)")
    fs = float(np.asarray(d["sampling_rate"]).ravel()[0])
    if not (np.isfinite(fs) and fs > 0):
        raise ReaderError(path, f"sampling_rate {fs} is not a positive number")
    acc = np.asarray(d["imu_acc"], dtype=float)
    gyr = np.asarray(d["imu_gyr"], dtype=float)
    n = len(acc)
    for name, a in (("imu_acc", acc), ("imu_gyr", gyr)):
        if a.shape != (n, 3):
            raise ReaderError(path, f"{name} has shape {a.shape}, expected N×3")
        if not np.all(np.isfinite(a)):
            raise ReaderError(path, f"{name} has non-finite values")
    check_acc_units(path, acc, "m/s^2")
    rec = Recording(t=np.arange(n) / fs, acc=acc, gyr=gyr, fs=fs, source=path, fmt=FORMAT,
                    metadata={"frame": "ENU reference (opt_quat)", "licence": "CC BY 4.0, BROAD"})
    if "imu_mag" in d:
        mag = np.asarray(d["imu_mag"], dtype=float)
        if mag.shape != (n, 3):
            raise ReaderError(path, f"imu_mag has shape {mag.shape}, expected N×3")
        if not np.all(np.isfinite(mag)):   # was passed on: NaN headings downstream
            raise ReaderError(path, "imu_mag has non-finite values")
        rec.mag = mag
    if "opt_quat" in d:   # NaN rows are lost markers (allowed); a wrong shape is no reference
        q = np.asarray(d["opt_quat"], dtype=float)
        if q.shape != (n, 4):
            raise ReaderError(path, f"opt_quat has shape {q.shape}, expected N×4 (N = {n} IMU samples)")
        rec.channels["opt_quat_wxyz"] = q
    if "movement" in d:
        mv = np.asarray(d["movement"], dtype=float).ravel()
        if mv.size != n:
            raise ReaderError(path, f"movement has {mv.size} values, expected one per IMU sample ({n})")
        rec.channels["movement"] = mv
    return rec


def _read_excerpt(path: str) -> Recording:
    from kinefuse.host.broad import load_trial
    from kinefuse.host.errors import KinefuseError
    try:
        tr = load_trial(path)
    except KinefuseError as exc:  # "<path as load_trial prints it>: <problem>"
        raise ReaderError(path, str(exc).removeprefix(f"{Path(path)}: ")) from None
    check_acc_units(path, tr.acc, "m/s^2")
    rec = Recording(t=tr.t, acc=tr.acc, gyr=tr.gyr, mag=tr.mag, fs=tr.rate_hz, source=path, fmt=FORMAT,
                    metadata={"frame": "ENU reference (opt_quat)", "licence": "CC BY 4.0, BROAD",
                              "trial": tr.name})
    rec.channels["opt_quat_wxyz"] = tr.quat_ref
    rec.channels["movement"] = tr.movement.astype(float)
    return rec
