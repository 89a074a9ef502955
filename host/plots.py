"""Plots of an orientation estimate against the BROAD optical reference.

Euler angles are the ZYX (yaw-pitch-roll) sequence of the sensor -> ENU rotation,
R = Rz(yaw)·Ry(pitch)·Rx(roll): yaw about Up, 0° when the sensor x axis points East, positive
counter-clockwise seen from above; pitch about the once-rotated y axis (±90°), positive when the
sensor x axis points below the horizontal (x·Up = −sin pitch: the opposite sign of the aviation
nose-up pitch in NED); roll about the sensor x axis, positive when the sensor y axis points above
the horizontal (y·Up = cos pitch · sin roll).  Matplotlib is used through its object API with the Agg canvas, so plotting never
needs a display and never changes pyplot state.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from kinefuse.host import metrics

EULER_NAMES = ("yaw", "pitch", "roll")
#: the signs of pitch and roll, as the figure states them
SIGNS = "pitch > 0: sensor x below the horizontal; roll > 0: sensor y above it"


def euler_zyx_deg(q: np.ndarray) -> np.ndarray:
    """(N,3) yaw, pitch, roll in degrees of (N,4) w,x,y,z quaternions (NaN rows stay NaN)."""
    q = metrics.quat_normalise(np.asarray(q, dtype=np.float64))
    w, x, y, z = q.T
    yaw = np.arctan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
    pitch = np.arcsin(np.clip(2.0 * (w * y - x * z), -1.0, 1.0))
    roll = np.arctan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y))
    return np.degrees(np.stack([yaw, pitch, roll], axis=1))


def _break_wraps(t: np.ndarray, angle: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Insert NaN where an angle wraps by more than 180° so the line does not cross the plot."""
    jumps = np.flatnonzero(np.abs(np.diff(angle)) > 180.0) + 1
    return np.insert(t, jumps, np.nan), np.insert(angle, jumps, np.nan)


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """(start, stop) index pairs of the True runs of a boolean series."""
    m = np.concatenate([[False], np.asarray(mask, dtype=bool), [False]])
    edges = np.flatnonzero(np.diff(m.astype(np.int8)))
    return list(zip(edges[::2], edges[1::2]))


def plot_estimate(trial, q_est: np.ndarray, label: str, out: str | Path,
                  status: dict[str, np.ndarray] | None = None,
                  window: tuple[float, float] | None = None) -> Path:
    """Write a PNG: Euler angles (estimate vs reference), errors, movement and status flags.

    ``window`` (start s, end s) limits the time axis; the estimate must cover the whole trial.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    out = Path(out)
    t = trial.t
    sel = np.ones(trial.n, dtype=bool)
    if window is not None:
        sel = (t >= window[0]) & (t <= window[1])
    errs = metrics.error_series(q_est, trial.quat_ref)
    rmse = metrics.score_trial(q_est, trial)
    eul_est = euler_zyx_deg(q_est)
    eul_ref = euler_zyx_deg(trial.quat_ref)
    flags = {"movement (scored)": trial.movement}
    for key, val in (status or {}).items():
        arr = np.asarray(val)
        # boolean series, or integer 0/1 series as generated C returns them; others are not flags
        if arr.shape == (trial.n,) and (arr.dtype == bool or (
                np.issubdtype(arr.dtype, np.integer) and np.isin(arr, (0, 1)).all())):
            flags[key.replace("_", " ")] = arr.astype(bool)

    fig = Figure(figsize=(13, 11), dpi=110, layout="constrained")
    FigureCanvasAgg(fig)
    heights = [2, 2, 2, 2.4, 0.35 * len(flags) + 0.5]
    axes = fig.subplots(5, 1, sharex=True, gridspec_kw={"height_ratios": heights})
    fig.suptitle(f"{trial.name}: {label} vs optical reference\n"
                 f"Euler angles ZYX (yaw-pitch-roll) of sensor→ENU; yaw 0° = sensor x toward East, "
                 f"counter-clockwise about Up\n{SIGNS}", fontsize=11)
    ts = t[sel]
    moving = _runs(trial.movement[sel])

    def shade(ax):
        for a, b in moving:
            ax.axvspan(ts[a], ts[b - 1], color="tab:blue", alpha=0.06, lw=0)

    for i, (ax, name) in enumerate(zip(axes[:3], EULER_NAMES)):
        shade(ax)
        if name == "yaw":
            ax.plot(*_break_wraps(ts, eul_ref[sel, i]), color="black", lw=1.0, label="reference")
            ax.plot(*_break_wraps(ts, eul_est[sel, i]), color="tab:red", lw=0.8, alpha=0.85,
                    label=label)
            ax.set_ylim(-185, 185)
            ax.set_yticks([-180, -90, 0, 90, 180])
        else:
            ax.plot(ts, eul_ref[sel, i], color="black", lw=1.0, label="reference")
            ax.plot(ts, eul_est[sel, i], color="tab:red", lw=0.8, alpha=0.85, label=label)
        ax.set_ylabel(f"{name} (°)")
        ax.grid(alpha=0.3)
    axes[0].legend(loc="upper left", fontsize=8, ncols=2)

    ax = axes[3]
    shade(ax)
    colors = {"total": "black", "heading": "tab:orange", "inclination": "tab:green"}
    for kind in metrics.KINDS:
        ax.plot(ts, getattr(errs, kind)[sel], color=colors[kind], lw=0.8,
                label=f"{kind} (RMSE {rmse[kind]:.2f}°)")
    ax.set_ylabel("error (°)")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=8, ncols=3,
              title="error vs reference; RMSE over the whole trial's movement phases",
              title_fontsize=8)

    ax = axes[4]
    names = list(flags)
    for row, name in enumerate(names):
        for a, b in _runs(flags[name][sel]):
            ax.broken_barh([(ts[a], ts[b - 1] - ts[a] + trial.dt)], (row - 0.35, 0.7),
                           color="tab:blue" if row == 0 else "tab:purple")
    ax.set_yticks(range(len(names)), names, fontsize=8)
    ax.set_ylim(len(names) - 0.5, -0.5)
    ax.set_xlabel("time (s)")
    ax.grid(axis="x", alpha=0.3)
    if len(names) == 1:
        ax.set_title("status flags: none reported by this filter", fontsize=8, loc="right")
    ax.set_xlim(ts[0], ts[-1])
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out)
    return out
