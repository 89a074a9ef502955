"""Plots of an orientation estimate: against the BROAD optical reference (:func:`plot_estimate`),
or of a unit or vendor recording without one (:func:`plot_recording`).

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


def status_flags(status: dict[str, np.ndarray] | None, n: int) -> dict[str, np.ndarray]:
    """The filter's boolean status outputs (or integer 0/1 series, as generated C returns them)
    of length n, named for a plot; counters and vectors are not flags."""
    flags = {}
    for key, val in (status or {}).items():
        arr = np.asarray(val)
        if arr.shape != (n,):
            continue
        if key == "rejected" and np.issubdtype(arr.dtype, np.integer):
            # a running count: mark the samples where it grows (a count of 1 read as a flag
            # painted every sample after the first rejection)
            flags["rejected"] = np.diff(arr, prepend=0) > 0
        elif arr.dtype == bool or (np.issubdtype(arr.dtype, np.integer) and np.isin(arr, (0, 1)).all()):
            flags[key.replace("_", " ")] = arr.astype(bool)
    return flags


def lost_before(dt: np.ndarray) -> np.ndarray:
    """True on the samples whose time step is over 1.5 x the median: samples were lost (or the
    sensor paused) just before them."""
    dt = np.asarray(dt, dtype=np.float64)
    return dt > 1.5 * float(np.median(dt)) if dt.size else np.zeros(0, dtype=bool)


def _flag_panel(ax, ts, flags: dict[str, np.ndarray], sel, step: float, first_color: str) -> None:
    names = list(flags)
    for row, name in enumerate(names):
        for a, b in _runs(flags[name][sel]):
            ax.broken_barh([(ts[a], ts[b - 1] - ts[a] + step)], (row - 0.35, 0.7),
                           color=first_color if row == 0 else "tab:purple")
    ax.set_yticks(range(len(names)), names, fontsize=8)
    ax.set_ylim(len(names) - 0.5, -0.5)
    ax.set_xlabel("time (s)")
    ax.grid(axis="x", alpha=0.3)


def _save(fig, out: Path) -> None:
    """Save under a temporary name, renamed when complete: a failed write (a full disk, an
    interrupt) leaves no cut PNG, and with --force the earlier plot as it was."""
    import io

    from kinefuse.host.outputs import staged
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    out.parent.mkdir(parents=True, exist_ok=True)
    with staged() as st:
        st.path(out).write_bytes(buf.getvalue())


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
    flags = {"movement (scored)": trial.movement, **status_flags(status, trial.n)}

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
                label=f"{kind} (RMSE {rmse[kind]:.2f}°)" if np.isfinite(rmse[kind])
                else f"{kind} (no movement phase scored)")
    ax.set_ylabel("error (°)")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=8, ncols=3,
              title="error vs reference; RMSE over the whole trial's movement phases",
              title_fontsize=8)

    ax = axes[4]
    _flag_panel(ax, ts, flags, sel, trial.dt, "tab:blue")
    if len(flags) == 1:
        ax.set_title("status flags: none reported by this filter", fontsize=8, loc="right")
    ax.set_xlim(ts[0], ts[-1])
    _save(fig, out)
    return out


def plot_recording(t: np.ndarray, q_est: np.ndarray, label: str, title: str, out: str | Path,
                   gyr: np.ndarray, acc: np.ndarray, mag: np.ndarray | None, mag_valid: np.ndarray,
                   dt: np.ndarray, status: dict[str, np.ndarray] | None = None,
                   unit_q: tuple[np.ndarray, np.ndarray] | None = None,
                   window: tuple[float, float] | None = None, time_text: str = "s") -> Path:
    """Write a PNG of a recording without a reference: the estimate's Euler angles (and the
    unit's own KF_ORIENTATION, ``unit_q`` = (sample indices, quaternions), where recorded), the
    sensor magnitudes (|gyroscope| deg/s; |accelerometer| m/s^2 with g; |magnetometer| uT on
    the samples with a reading), and the flags: samples lost (a time step over 1.5 x the median)
    and the filter's status."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    out = Path(out)
    t = np.asarray(t, dtype=np.float64)
    n = len(t)
    sel = np.ones(n, dtype=bool) if window is None else (t >= window[0]) & (t <= window[1])
    ts = t[sel]
    eul = euler_zyx_deg(q_est)
    step = float(np.median(dt)) if len(dt) else 0.0
    flags = {"samples lost": lost_before(dt), **status_flags(status, n)}

    fig = Figure(figsize=(13, 11), dpi=110, layout="constrained")
    FigureCanvasAgg(fig)
    axes = fig.subplots(6, 1, sharex=True,
                        gridspec_kw={"height_ratios": [2, 2, 2, 1.4, 1.4, 0.35 * len(flags) + 0.5]})
    fig.suptitle(f"{title}: {label}\n"
                 f"Euler angles ZYX (yaw-pitch-roll) of sensor→ENU; yaw 0° = sensor x toward East, "
                 f"counter-clockwise about Up\n{SIGNS}", fontsize=11)
    eul_u = idx_u = None
    if unit_q is not None:
        idx_u, q_u = unit_q
        keep = sel[idx_u]
        idx_u, eul_u = idx_u[keep], euler_zyx_deg(q_u[keep])
    for i, (ax, name) in enumerate(zip(axes[:3], EULER_NAMES)):
        draw = _break_wraps if name == "yaw" else (lambda a, b: (a, b))
        if eul_u is not None and idx_u.size:
            ax.plot(*draw(t[idx_u], eul_u[:, i]), color="black", lw=1.0, label="unit's KF_ORIENTATION")
        ax.plot(*draw(ts, eul[sel, i]), color="tab:red", lw=0.8, alpha=0.85, label=label)
        if name == "yaw":
            ax.set_ylim(-185, 185)
            ax.set_yticks([-180, -90, 0, 90, 180])
        ax.set_ylabel(f"{name} (°)")
        ax.grid(alpha=0.3)
    axes[0].legend(loc="upper left", fontsize=8, ncols=2)

    ax = axes[3]
    ax.plot(ts, np.degrees(np.linalg.norm(np.asarray(gyr)[sel], axis=1)), color="tab:blue", lw=0.7)
    ax.set_ylabel("|gyroscope|\n(°/s)")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax = axes[4]
    a_norm = np.linalg.norm(np.asarray(acc)[sel], axis=1)
    ax.plot(ts, a_norm, color="tab:green", lw=0.7, label="|accelerometer| (m/s²)")
    ax.axhline(9.81, color="tab:green", lw=0.6, ls=":", label="g")
    ax.set_ylabel("|acc.| (m/s²)")
    # from 0: at this scale a still unit reads a flat g, and motion or tapping stands out
    ax.set_ylim(0, max(12.0, 1.1 * float(np.nanmax(a_norm, initial=0.0))))
    ax.grid(alpha=0.3)
    if mag is not None and np.any(mag_valid[sel]):
        m_sel = sel & np.asarray(mag_valid, dtype=bool)
        m_norm = np.linalg.norm(np.asarray(mag)[m_sel], axis=1)
        ax2 = ax.twinx()
        ax2.plot(t[m_sel], m_norm, color="tab:brown", lw=0.7, label="|magnetometer| (µT)")
        ax2.set_ylabel("|mag.| (µT)")
        ax2.set_ylim(0, 1.6 * float(np.nanmax(m_norm, initial=1.0)))
        h1, l1 = ax.get_legend_handles_labels()
        h2, l2 = ax2.get_legend_handles_labels()
        ax.legend(h1 + h2, l1 + l2, loc="lower left", fontsize=8, ncols=3)
    else:
        ax.legend(loc="lower left", fontsize=8, ncols=2, title="no magnetometer readings",
                  title_fontsize=8)

    _flag_panel(axes[5], ts, flags, sel, step, "tab:red")
    axes[5].set_xlabel(f"time ({time_text})")
    axes[5].set_xlim(ts[0], ts[-1])
    _save(fig, out)
    return out
