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
    p.add_argument("--frame", default="enu", choices=runner.FRAMES,
                   help="earth frame of the written quaternions (default enu, as BROAD)")
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
        return _run_angle(name, args, prm)
    kind = angle_series.sniff(args.input)
    if kind is not None and name in runner.imu_filter_names():
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
    print(f"wrote {n} rows to {args.out} ({name}, {args.impl})", file=sys.stderr)
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
                            f"BROAD trial: use "
                            f"kinefuse replay {path} --out {args.out}"
                            + (f" --filter {args.filter}" if args.filter else ""))


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
    cols = ("t s, angle_deg deg, rate_deg_s deg/s" + (", omega_rad_s rad/s (oscillator "
            "frequency)" if "omega" in out else "") + (", rejected (cumulative count)"
                                                        if args.status else ""))
    n = angle_series.write_csv(args.out, series.t, out,
                               f"kinefuse run --filter {name} --impl {args.impl}; {cols}; filtered "
                               f"joint angle; time base {series.time_base}; input {path} "
                               f"({series.fmt})", status=args.status)
    rejected = int(out["rejected"][-1, 0]) if n else 0
    if rejected:
        print(f"kinefuse: {rejected} sample(s) rejected by the filter (angle beyond ±3.2 rad or "
              f"time step not in (0, 0.2] s): state kept", file=sys.stderr)
    missing = int(np.count_nonzero(~np.isfinite(series.angle)))
    if missing:
        print(f"kinefuse: {missing} sample(s) without an angle (predicted only)", file=sys.stderr)
    print(f"wrote {n} rows to {args.out} ({name}, {args.impl})", file=sys.stderr)
    return 0
