"""`kinefuse run`: one filter over one recording, estimates to CSV."""
from __future__ import annotations

import math
import sys

import numpy as np

from kinefuse.host import runner
from kinefuse.host import argtypes
from kinefuse.host.errors import KinefuseError
from kinefuse.host.outputs import add_force_arg, check_new_file


def register(sub):
    p = sub.add_parser("run", help="run a filter over a recording and write the estimates as CSV")
    p.add_argument("--filter", default=None,
                   help=f"filter name (default: {runner.default_filter()}; see `kinefuse filters`)")
    p.add_argument("--impl", default="f32", choices=runner.IMPLS,
                   help="ref: Python reference (float64); f32: generated float32 C; "
                        "q: generated fixed-point C (default f32)")
    p.add_argument("--input", required=True,
                   help="recording: BROAD .mat or bundled .npz trial (IMU filters); joint-angle "
                        "series for the angle smoothers: seed-004 Arduino CSV, or a CSV with t (s) "
                        "and angle_deg columns")
    p.add_argument("--out", required=True,
                   help="output CSV: t,w,x,y,z (+ status columns); angle smoothers: "
                        "t,angle_deg,rate_deg_s[,omega_rad_s] (+ rejected)")
    p.add_argument("--param", action="append", metavar="NAME=VALUE", help="parameter override")
    p.add_argument("--preset", help="named parameter set (see `kinefuse filters`)")
    p.add_argument("--status", action="store_true", help="append the filter's status outputs")
    p.add_argument("--frame", default=None, choices=runner.FRAMES,
                   help="earth frame of the written quaternions (default enu, as BROAD; IMU "
                        "filters only)")
    p.add_argument("--fs", type=argtypes.real(0.0, math.inf, lo_open=True, hi_open=True), default=None, metavar="HZ",
                   help="sampling rate of a seed-004 Arduino CSV (it has no time column; default 35)")
    add_force_arg(p, "the output CSV")
    p.set_defaults(func=run)


def run(args) -> int:
    from kinefuse.host.broad import load_trial
    check_new_file(args.out, args.force, inputs=[args.input])
    name = args.filter or runner.default_filter()
    if name not in runner.filter_names():
        raise KinefuseError(f"unknown filter {name!r} (available: {', '.join(runner.filter_names())})")
    prm = runner.parse_params(args.param)
    from kinefuse.host import angle_series
    if angle_series.is_angle_filter(name):
        if args.frame is not None:
            raise KinefuseError(f"--frame applies to the quaternions of the IMU filters; {name!r} "
                                f"writes a joint angle, which has no earth frame")
        return _run_angle(name, args, prm)
    if name not in runner.imu_filter_names():
        from kinefuse.codegen import estimators
        raise KinefuseError(f"filter {name!r} takes {estimators.get(name).inputs.name} inputs, "
                            f"which run does not read; run takes IMU filters "
                            f"({', '.join(runner.imu_filter_names())}) and the joint-angle "
                            f"smoothers ({', '.join(angle_series.angle_filter_names())})")
    args.frame = args.frame or "enu"
    kind = angle_series.sniff(args.input)
    if kind is not None:
        raise KinefuseError(f"filter {name!r} takes IMU samples, but {args.input} is a joint-angle "
                            f"series ({kind}); smooth it with "
                            f"{', '.join(angle_series.angle_filter_names())}")
    if args.fs is not None:
        raise KinefuseError("--fs applies to the seed-004 Arduino CSV only (angle smoothers)")
    _point_recordings_to_replay(args)
    trial = load_trial(args.input)
    res = runner.run_filter(name, args.impl, trial, prm, args.preset)
    n = len(res.q)
    runner.write_estimates_csv(args.out, runner.output_times(trial), res, f"kinefuse run --filter {name} --impl {args.impl}; t in s; "
                               f"quaternion w,x,y,z sensor->earth, {runner.FRAME_TEXT[args.frame]}; "
                               f"input {args.input}", status=args.status, frame=args.frame)
    msg = f"wrote {n} rows to {args.out} ({name}, {args.impl})"
    rejected = runner.rejected_count(res)
    if rejected:        # as replay says it: a sample or reading the filter could not use
        msg += (f"; {rejected} sample(s) or sensor reading(s) rejected by the filter (non-finite "
                f"or out of range: state kept)")
    print(msg, file=sys.stderr)
    return 0


def _point_recordings_to_replay(args) -> None:
    """`run` reads BROAD trials; a unit recording or a sensor vendor's CSV is `replay`'s input."""
    from pathlib import Path
    from kinefuse.host import readers
    from kinefuse.host.readers import broad as broad_reader
    path = Path(args.input)
    if not path.is_file() or path.suffix.lower() in (".mat", ".npz"):
        return                      # load_trial names the problem
    try:
        fmt = readers.detect_format(str(path))
    except readers.ReaderError:
        return
    what = {"kfr": "a kinefuse unit recording (.kfr)", "xsens-dot": "an Xsens DOT export",
            "matrix": "a MATRIX export", "metabase": "a MetaBase export",
            "kinefuse-csv": "a kinefuse CSV recording"}
    if fmt != broad_reader.FORMAT:
        raise KinefuseError(f"{path} is {what.get(fmt, 'a ' + fmt + ' recording')}; run takes a "
                            f"BROAD trial: use {replay_command(args)}")


def replay_command(args) -> str:
    """The `kinefuse replay` line that computes what this `run` asked for: every option that
    changes the estimates or the CSV carried over, shell-quoted (a path with spaces, a
    parameter value) so it can be pasted as it is."""
    import shlex
    words = ["kinefuse", "replay", str(args.input), "--out", str(args.out)]
    if args.filter:
        words += ["--filter", args.filter]
    if args.impl != "f32":
        words += ["--impl", args.impl]
    if args.preset:
        words += ["--preset", args.preset]
    for p in args.param or ():
        words += ["--param", p]
    if args.status:
        words.append("--status")
    if args.frame and args.frame != "enu":
        words += ["--frame", args.frame]
    if getattr(args, "force", False):
        words.append("--force")
    return " ".join(shlex.quote(w) for w in words)


def _run_angle(name: str, args, prm) -> int:
    """A seed-004 joint-angle smoother over a joint-angle series (host/angle_series.py)."""
    from pathlib import Path
    from kinefuse.host import angle_series
    path = str(args.input)
    if Path(path).suffix.lower() in angle_series.IMU_SUFFIXES:
        raise KinefuseError(f"filter {name!r} smooths a joint-angle series (seed-004 Arduino CSV, "
                            f"or a CSV with t [s] and angle_deg columns), but {path} is an IMU "
                            f"recording; use an IMU filter (e.g. {runner.default_filter()})")
    if Path(path).is_file() and angle_series.sniff(path) is None:
        from kinefuse.host.readers import ReaderError, detect_format
        try:
            fmt = detect_format(path)
        except ReaderError:
            fmt = None
        if fmt is not None:
            raise KinefuseError(f"filter {name!r} smooths a joint-angle series, but {path} is an "
                                f"IMU recording ({fmt}); use an IMU filter (e.g. "
                                f"{runner.default_filter()})")
    series = angle_series.load(path, fs=args.fs)
    out = angle_series.run(name, args.impl, series, prm, args.preset)
    n_rows = len(series.t)
    if n_rows and int(np.asarray(out["rejected"]).reshape(n_rows, -1)[-1, 0]) == n_rows:
        # every sample kept the initial state: the CSV would hold 0° throughout
        hint = (f"; at --fs {args.fs:g} Hz a step is {1.0 / args.fs:g} s" if args.fs is not None
                else "")
        raise KinefuseError(f"{path}: the filter rejected every one of the {n_rows} samples "
                            f"(angle beyond ±3.2 rad = ±183° or time step not in (0, 0.2] s{hint}); "
                            f"nothing was filtered")
    # the columns the file has (a filter without a rate output has no rate_deg_s column)
    cols = ("t s, angle_deg deg" + (", rate_deg_s deg/s" if "rate" in out else "")
            + (", omega_rad_s rad/s (oscillator frequency)" if "omega" in out else "")
            + (", rejected (cumulative count)" if args.status else ""))
    n = _write_angle_csv(args.out, series.t, out,
                         f"kinefuse run --filter {name} --impl {args.impl}; {cols}; filtered "
                         f"joint angle; time base {series.time_base}; input {path} "
                         f"({series.fmt})", status=args.status)
    rejected = int(out["rejected"][-1, 0]) if n else 0
    if rejected:
        print(f"kinefuse: {rejected} sample(s) rejected by the filter (angle beyond ±3.2 rad = ±183° or "
              f"time step not in (0, 0.2] s): state kept", file=sys.stderr)
    missing = int(np.count_nonzero(~np.isfinite(series.angle)))
    if missing:
        print(f"kinefuse: {missing} sample(s) without an angle (predicted only)", file=sys.stderr)
    print(f"wrote {n} rows to {args.out} ({name}, {args.impl})", file=sys.stderr)
    return 0


def _write_angle_csv(path, t, out: dict, comment: str, status: bool = False) -> int:
    """The smoothed series: header ``t,angle_deg,rate_deg_s[,omega_rad_s][,rejected]`` (degrees
    from the filter's radians, ``angle_series.COLUMNS``), written by :func:`runner.write_csv`:
    t with 15 significant digits (a time stamp since the epoch keeps its fraction) and no
    half-written file on a failed write."""
    from kinefuse.host import angle_series
    n = len(t)
    cols, header = [np.asarray(t, float)], ["t"]
    for key, (col, scale) in angle_series.COLUMNS.items():
        if key in out:
            cols.append(np.asarray(out[key], float).reshape(n) * scale)
            header.append(col)
    if status:
        for key, v in out.items():
            if key not in angle_series.COLUMNS:
                cols.append(np.asarray(v, float).reshape(n))
                header.append(key)
    runner.write_csv(path, comment, header, cols)
    return n
