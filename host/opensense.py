"""OpenSim OpenSense orientation tables (``.sto``, ``DataType=Quaternion``).

OpenSense's IMU Placer and IMU Inverse Kinematics read one table: a ``time`` column (s) and one
column per IMU, named after the model's IMU frame (``pelvis_imu``, ``femur_r_imu``, ...), each
cell the quaternion ``w,x,y,z`` of the sensor's orientation in the IMUs' common world frame,
on one time grid at ``DataRate`` Hz.  The quaternions written here are sensor -> East-North-Up,
the frame of every kinefuse filter: z up, as the Xsens frame OpenSense's default
``sensor_to_opensim_rotations`` (-pi/2, 0, 0) turns into OpenSim's y-up ground.

Units recorded in one ``.kfr`` share the host clock their sample times are mapped to, so their
orientations are put on one grid by spherical linear interpolation between the samples around
each grid time (over the span all units cover).
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError

OPENSIM_VERSION = "4.5"    # the header's OpenSimVersion (the table format is version 3)


@dataclass
class ImuSeries:
    name: str              # the model's IMU frame, e.g. femur_r_imu
    t: np.ndarray          # (N,) s, increasing
    q: np.ndarray          # (N,4) w,x,y,z sensor -> ENU


def slerp_at(t: np.ndarray, q: np.ndarray, grid: np.ndarray) -> np.ndarray:
    """(M,4) unit quaternions at the grid times (within [t[0], t[-1]]), each the spherical
    linear interpolation of the two samples around it (the shorter arc); w >= 0."""
    q = np.asarray(q, dtype=np.float64)
    q = q / np.linalg.norm(q, axis=1, keepdims=True)
    k = np.clip(np.searchsorted(t, grid, side="right") - 1, 0, len(t) - 2)
    t0, t1 = t[k], t[k + 1]
    u = np.clip((grid - t0) / (t1 - t0), 0.0, 1.0)[:, None]
    a, b = q[k], q[k + 1]
    d = np.sum(a * b, axis=1, keepdims=True)
    b = np.where(d < 0, -b, b)
    d = np.abs(d)
    ang = np.arccos(np.clip(d, -1.0, 1.0))
    s = np.sin(ang)
    near = s < 1e-9
    wa = np.where(near, 1.0 - u, np.sin((1.0 - u) * ang) / np.where(near, 1.0, s))
    wb = np.where(near, u, np.sin(u * ang) / np.where(near, 1.0, s))
    out = wa * a + wb * b
    out /= np.linalg.norm(out, axis=1, keepdims=True)
    return np.where(out[:, :1] < 0, -out, out)


def common_grid(series: list[ImuSeries], rate_hz: float) -> np.ndarray:
    """The times k / rate (whole k) from the latest first sample to the earliest last sample of
    all IMUs."""
    start = max(float(s.t[0]) for s in series)
    end = min(float(s.t[-1]) for s in series)
    k0, k1 = int(np.ceil(start * rate_hz - 1e-9)), int(np.floor(end * rate_hz + 1e-9))
    if k1 < k0 + 1:
        # one IMU: "overlap" named a second recording that is not there
        what = (f"{series[0].name}'s samples span {end - start:.3f} s" if len(series) == 1 else
                "the IMUs' recordings do not overlap in time" if end < start else
                f"the IMUs' recordings overlap in time by {end - start:.3f} s")
        raise KinefuseError(f"{what}: less than two rows at {rate_hz:g} Hz, nothing to write")
    return np.arange(k0, k1 + 1) / rate_hz


def gap_in_grid(s: ImuSeries, grid: np.ndarray) -> tuple[float, float]:
    """(longest step s, time it starts) among the samples the rows at ``grid`` are interpolated
    between: from the last sample at or before the first row to the first at or after the last
    (a margin of one row missed a gap just before or after the common span)."""
    i0 = max(int(np.searchsorted(s.t, grid[0], side="right")) - 1, 0)
    i1 = min(int(np.searchsorted(s.t, grid[-1], side="left")), len(s.t) - 1)
    used = s.t[i0:i1 + 1]
    if len(used) < 2:
        return 0.0, float(used[0]) if len(used) else float(grid[0])
    k = int(np.argmax(np.diff(used)))
    return float(used[k + 1] - used[k]), float(used[k])


def write_sto(path: str | Path, grid: np.ndarray, series: list[ImuSeries], rate_hz: float) -> int:
    """Write the OpenSense table; returns the number of rows."""
    from kinefuse.host.outputs import staged

    cols = [slerp_at(s.t, s.q, grid) for s in series]
    # under a temporary name, renamed when complete: a failed or interrupted write leaves no
    # cut table (and with --force the earlier one as it was)
    with staged() as st, open(st.path(path), "w", newline="\n") as f:
        f.write(f"DataRate={rate_hz:.6f}\nDataType=Quaternion\nversion=3\n"
                f"OpenSimVersion={OPENSIM_VERSION}\nendheader\n")
        f.write("time\t" + "\t".join(s.name for s in series) + "\n")
        for i, t in enumerate(grid):
            f.write(f"{t:.6f}\t" + "\t".join(",".join(f"{v:.8f}" for v in c[i]) for c in cols) + "\n")
    return len(grid)


def read_sto(path: str | Path) -> tuple[dict[str, str], np.ndarray, dict[str, np.ndarray]]:
    """(header, time, {column: (N,4) quaternions}) of a quaternion table (for checks)."""
    lines = Path(path).read_text().splitlines()
    end = lines.index("endheader")
    header = dict(ln.split("=", 1) for ln in lines[:end])
    names = lines[end + 1].split("\t")
    rows = [ln.split("\t") for ln in lines[end + 2:]]
    t = np.array([float(r[0]) for r in rows])
    cols = {n: np.array([[float(v) for v in r[j].split(",")] for r in rows])
            for j, n in enumerate(names) if j > 0}
    return header, t, cols
