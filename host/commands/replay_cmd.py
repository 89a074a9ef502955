"""``kinefuse replay``: feed a recording through a filter and write the estimates as CSV.

    kinefuse replay walk.kfr --unit 2 --out est.csv
    kinefuse replay walk.kfr --out est.csv --filter madgwick --impl q --param beta=0.05
    kinefuse replay dot_export.csv --out est.csv --status
    kinefuse replay host/data/broad_excerpt/24_disturbed_tapping_A.npz --out est.csv
    kinefuse replay walk.kfr --out est.csv --compare-unit      # vs the unit's KF_ORIENTATION

REC is a unit recording (``.kfr``, one unit chosen with ``--unit``), any file
:func:`kinefuse.host.readers.read_recording` reads (Xsens DOT, MATRIX, MetaBase, seed-004,
kinefuse CSV) or a BROAD trial (``.mat`` / bundled ``.npz``, exactly as ``kinefuse run``).
Each sample's time step comes from the recording's time stamps (gaps stay gaps: a step longer
than the filters' 1 s limit makes the filter reject that sample, and the count is reported);
the magnetometer is used on the samples that carry a new reading.
"""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from kinefuse.host import runner
from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.cli_util import check_unit_option
from kinefuse.host.outputs import add_force_arg, check_new_file

BROAD_SUFFIXES = (".mat", ".npz")
MSG_ORI = 52501
ORI_INITIALISED = 1
EARTH_ENU, EARTH_NED = 1, 2


def register(subparsers) -> None:
    p = subparsers.add_parser("replay", help="feed a recording (.kfr, reader formats, BROAD) through a filter, "
                                             "estimates to CSV",
                              description=__doc__.split("\n\n")[0].split(": ", 1)[-1])
    p.add_argument("rec", metavar="REC", help="recording: .kfr unit recording, Xsens DOT / MATRIX / MetaBase / "
                                              "kinefuse CSV, or BROAD .mat / bundled .npz trial")
    p.add_argument("--out", required=True, metavar="CSV", help="output CSV: t,w,x,y,z (+ status columns)")
    p.add_argument("--filter", default=None,
                   help=f"filter name (default: {runner.default_filter()}; see `kinefuse filters`)")
    p.add_argument("--impl", default="f32", choices=runner.IMPLS,
                   help="ref: Python reference (float64); f32: generated float32 C; "
                        "q: generated fixed-point C (default f32)")
    p.add_argument("--param", action="append", metavar="NAME=VALUE", help="parameter override")
    p.add_argument("--preset", help="named parameter set (see `kinefuse filters`)")
    p.add_argument("--unit", metavar="ID", help="unit of a multi-unit .kfr: unit (system) id, s<stream> or "
                                                "s<stream>:<id>")
    p.add_argument("--status", action="store_true", help="append the filter's status outputs")
    p.add_argument("--frame", default="enu", choices=runner.FRAMES,
                   help="earth frame of the written quaternions (default enu)")
    p.add_argument("--compare-unit", action="store_true",
                   help="(.kfr) angle between the unit's own KF_ORIENTATION and the replayed orientation")
    add_force_arg(p, "the output CSV")
    p.set_defaults(func=run)


def run(args) -> int:
    name = args.filter or runner.default_filter()
    if name not in runner.filter_names():
        raise KinefuseError(f"unknown filter {name!r} (available: {', '.join(runner.filter_names())})")
    _check_imu_filter(name)
    prm = runner.parse_params(args.param)
    check_unit_option(args.unit)
    path = str(args.rec)
    check_new_file(args.out, args.force, inputs=[path])
    broad = Path(path).suffix.lower() in BROAD_SUFFIXES
    from kinefuse.host.readers.kfr import decode_once
    with decode_once():     # a .kfr decoded once: its samples and --compare-unit's KF_ORIENTATION
        rec = None
        if broad:
            if args.unit is not None:
                raise KinefuseError("--unit applies to .kfr unit recordings, not to BROAD trials")
            if args.compare_unit:
                raise KinefuseError("--compare-unit needs a .kfr unit recording with KF_ORIENTATION messages")
            from kinefuse.host.broad import load_trial
            trial = load_trial(path)
            inputs = trial                      # the same input as `kinefuse run`
            t = runner.output_times(trial)
            time_base = ("s from the first sample (constant rate)" if trial.steps is None
                         else "s, the file's sample times")
        else:
            from kinefuse.host import angle_series
            if angle_series.sniff(path) == "angle-csv":
                # was "unknown recording format": the smoothers read it, through `run`
                smoothers = angle_series.angle_filter_names()
                raise KinefuseError(f"{path} is a joint-angle series (t, angle_deg), not IMU samples: "
                                    f"smooth it with a joint-angle smoother ({', '.join(smoothers)}), "
                                    f"e.g. {_run_command(args, path, smoothers[0])}")
            from rich.console import Console
            from kinefuse.host.link.cli_util import progress
            with progress(Console(stderr=True), f"reading {path}"):    # moves with a .kfr's decoding
                rec = read_imu_recording(path, args.unit)
            for w in rec.warnings:
                print(f"kinefuse: warning: {w}", file=sys.stderr)
            inputs = runner.recording_inputs(rec)
            t = inputs.t
            time_base = time_base_text(rec)
        unit_q = unit_orientation(path, rec) if args.compare_unit else None

    res = _run_filter(name, args.impl, inputs, prm, args.preset)
    dt = np.atleast_1d(getattr(inputs, "dt", None))
    gaps = int(np.count_nonzero(dt > runner.DT_MAX)) if dt.ndim == 1 and dt.size > 1 else 0
    comment = (f"kinefuse replay --filter {name} --impl {args.impl}; t in s ({time_base}); quaternion w,x,y,z "
               f"sensor->earth, {runner.FRAME_TEXT[args.frame]}; input {path}"
               + (f" unit {rec.metadata['unit']}" if rec is not None and rec.fmt == "kfr" else ""))
    n = runner.write_estimates_csv(args.out, t, res, comment, status=args.status,
                                   frame=args.frame)
    rejected = runner.rejected_count(res)
    msg = f"wrote {n} rows to {args.out} ({name}, {args.impl})"
    if rejected is not None:
        msg += f"; {rejected} sample(s) rejected by the filter"
        if gaps:
            msg += f" ({gaps} after a gap longer than {runner.DT_MAX:g} s)"
    print(msg, file=sys.stderr)
    if unit_q is not None:
        print(_compare(unit_q, res.q, rec))
    return 0


def _check_imu_filter(name: str) -> None:
    """Before the recording is read (a long .kfr decode): replay feeds IMU samples, so the
    other filters are refused here, the joint-angle smoothers with the `run` that takes them."""
    if name in runner.imu_filter_names():
        return
    from kinefuse.codegen import estimators
    from kinefuse.host import angle_series
    msg = (f"filter {name!r} takes {estimators.get(name).inputs.name} inputs, not IMU samples: "
           f"replay runs the IMU filters ({', '.join(runner.imu_filter_names())})")
    if angle_series.is_angle_filter(name):
        msg += (f"; smooth a joint-angle series with kinefuse run --filter {name} --input SERIES.csv "
                f"--out CSV")
    raise KinefuseError(msg)


def _run_command(args, path: str, name: str) -> str:
    """The `kinefuse run` line for a joint-angle series, the user's options carried over."""
    import shlex
    words = ["kinefuse", "run", "--filter", name, "--input", path, "--out", str(args.out)]
    if args.impl != "f32":
        words += ["--impl", args.impl]
    if args.status:
        words.append("--status")
    if getattr(args, "force", False):
        words.append("--force")
    return " ".join(shlex.quote(w) for w in words)


def _run_filter(name, impl, inputs, prm, preset):
    n = len(inputs.gyr)
    if n > 200_000 and sys.stderr.isatty():
        from rich.console import Console
        with Console(stderr=True).status(f"replaying {n:,} samples through {name} ({impl})"):
            return runner.run_filter(name, impl, inputs, prm, preset)
    return runner.run_filter(name, impl, inputs, prm, preset)


def read_imu_recording(path: str, unit):
    """A recording that replay (and plot) can feed to an IMU filter: read with its format's reader
    (``unit``: a .kfr's unit), one-line errors for a missing accelerometer or gyroscope."""
    from kinefuse.host.readers import ReaderError, detect_format, read_recording
    fmt = detect_format(path)
    if unit is not None and fmt != "kfr":
        raise KinefuseError(f"--unit applies to .kfr unit recordings; {path} is a {fmt} file")
    try:
        rec = read_recording(path, fmt, **({"unit": unit} if fmt == "kfr" else {}))
    except ReaderError as exc:
        if fmt == "kfr" and "units in this recording" in exc.problem:
            raise KinefuseError(f"{path}: {exc.problem.split(';')[0]}; choose one with --unit ID") from None
        raise
    if rec.acc is None or rec.gyr is None:
        missing = " and ".join(n for n in ("accelerometer", "gyroscope")
                               if getattr(rec, {"accelerometer": "acc", "gyroscope": "gyr"}[n]) is None)
        raise KinefuseError(f"{path}: the {rec.fmt} recording has no {missing} data (a filter needs both)")
    return rec


def time_base_text(rec) -> str:
    if rec.fmt == "kfr":
        if rec.metadata.get("time_base") == "host":
            start = rec.metadata.get("start_utc")
            return "host clock, s since the recording started" + (f" at {start}" if start else "")
        return "the unit's own clock, s since boot"
    return f"the {rec.fmt} file's own clock"


# ------------------------------------------------------------------------------ --compare-unit
def unit_orientation(path: str, rec):
    """The unit's KF_ORIENTATION quaternions (ENU) matched to the replayed samples by device time:
    (sample indices, quaternions, note)."""
    if rec is None or rec.fmt != "kfr":
        raise KinefuseError("--compare-unit needs a .kfr unit recording with KF_ORIENTATION messages")
    from kinefuse.host.readers import kfr
    df = kfr.decoded(path)      # the reader's decode: once for samples and orientation in kfr.decode_once()
    ds = df.streams.get(rec.metadata["stream"])
    arr = None if ds is None else ds.arrays.get(MSG_ORI)
    if arr is not None:
        arr = arr[arr["_sysid"] == rec.metadata["sysid"]]
    if arr is None or not arr.size:
        raise KinefuseError(f"{path}: unit {rec.metadata['unit']} sent no KF_ORIENTATION messages "
                            f"(nothing to compare with --compare-unit)")
    arr = arr[(arr["status"] & ORI_INITIALISED) != 0]
    q = np.column_stack([arr[f"q_{c}"] for c in "wxyz"]).astype(np.float64)
    frames = np.unique(arr["earth_frame"])
    note = ""
    if frames.size > 1:
        raise KinefuseError(f"{path}: the unit's KF_ORIENTATION changes earth frame during the recording")
    if frames.size and int(frames[0]) == EARTH_NED:
        q = runner.swap_enu_ned(q)
        note = " (unit's NED quaternions turned to ENU)"
    elif frames.size and int(frames[0]) != EARTH_ENU:
        note = " (unit's earth frame unknown: taken as ENU)"
    # KF_ORIENTATION.time_boot_us = the newest KF_RAW_SAMPLE used: match on the device time
    dev = np.round(np.asarray(rec.channels["device_time_s"]) * 1e6).astype(np.int64)
    order = np.argsort(dev, kind="stable")
    sd = dev[order]
    ot = arr["time_boot_us"].astype(np.int64)
    lo = np.searchsorted(sd, ot, side="left")
    hi = np.searchsorted(sd, ot, side="right")
    ok = (hi - lo) == 1                  # exactly one sample at that device time (reboots may repeat times)
    idx = order[np.minimum(lo[ok], len(sd) - 1)]
    if not idx.size:
        raise KinefuseError(f"{path}: none of unit {rec.metadata['unit']}'s KF_ORIENTATION messages matches a "
                            f"received KF_RAW_SAMPLE (by device time): nothing to compare")
    return idx, q[ok], note, int(arr.size)


def _compare(unit, q_replay: np.ndarray, rec) -> str:
    from kinefuse.host.kinematics.quat import angle_between
    idx, q_unit, note, total = unit
    ang_all = np.degrees(angle_between(q_unit, q_replay[idx]))
    finite = np.isfinite(ang_all)
    ang = ang_all[finite]
    if not ang.size:
        return f"unit {rec.metadata['unit']}: no finite orientation pair to compare"
    line = (f"unit {rec.metadata['unit']} on-board orientation vs replay{note}: {ang.size} of {total} "
            f"KF_ORIENTATION messages matched; angle RMS {np.sqrt(np.mean(ang ** 2)):.2f} deg, "
            f"max {ang.max():.2f} deg, median {np.median(ang):.2f} deg")
    gap = _first_lost(rec)
    if gap is not None:
        # the unit's filter used the samples the recording lost; the replay never saw them, so
        # after the first loss the two need not agree: the figure before it is the comparison
        before = ang_all[finite & (idx < gap)]
        t_gap = float(np.asarray(rec.t)[gap])
        line += (f"; samples were lost just before t = {t_gap:.3f} s (the unit's filter used them, "
                 f"the replay cannot): up to there, {before.size} message(s)")
        if before.size:
            line += (f", angle RMS {np.sqrt(np.mean(before ** 2)):.2f} deg, "
                     f"max {before.max():.2f} deg")
    return line


def _first_lost(rec) -> int | None:
    """Index of the first replayed sample that follows a lost one (a sample-counter gap)."""
    from kinefuse.host.link.stats import counter_analysis
    c = rec.channels.get("sample_counter")
    if c is None or len(c) < 2:
        return None
    c = np.asarray(c, np.int64)
    stride = counter_analysis(c)["stride"] or 1
    d = np.diff(c)
    after = np.flatnonzero(d > stride)
    return int(after[0]) + 1 if after.size else None
