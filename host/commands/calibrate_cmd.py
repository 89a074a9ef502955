"""``kinefuse calibrate accel|gyro|mag`` — sensor calibration from poses or recordings.

Examples::

    kinefuse calibrate accel --poses poses.csv --targets targets.csv --method ls --json
    kinefuse calibrate accel --input six_poses.csv --out unit7.json --serial DOT-7
    kinefuse calibrate gyro --input still.csv --json
    kinefuse calibrate mag --input figure8.csv --field-norm 22.6 --json
    kinefuse calibrate apply --calib unit7.json --port /dev/ttyUSB0   # write it to the unit
    kinefuse calibrate apply --calib unit7-shank.json --port /dev/ttyUSB0 --sensor 1   # two-sensor unit

POSES.csv: one row per pose, the mean raw accelerometer x,y,z (or x,y for the seed-002 2-D
protocol); TARGETS.csv: the expected gravity vector of each pose (same shape).  Both accept an
optional header line and ``#`` comments.  ``--json`` prints exactly one JSON object; for accel
it is ``{"R": [[…]…], "bias": […] or null, "det": …, "residual_rms": …}``.
"""
from __future__ import annotations

import json
import math
import sys

import numpy as np

from kinefuse.host import argtypes
from kinefuse.host.calib import static     # light (numpy); fitting modules load on use
from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.cli_util import check_unit_option

G_STANDARD = 9.80665  # m/s²


def register(subparsers) -> None:
    p = subparsers.add_parser("calibrate", help="calibrate a unit's accelerometer, gyroscope or magnetometer",
                              description=__doc__.split("\n\n")[0].replace("``", ""))
    sub = p.add_subparsers(dest="sensor", metavar="SENSOR", parser_class=type(p))
    p.set_defaults(func=lambda args: (p.print_help(), 2)[1])

    def common(sp, recording_required: bool):
        sp.add_argument("--input", metavar="RECORDING", required=recording_required,
                        help="recording (Xsens DOT/MATRIX/MetaBase/kinefuse CSV, .kfr, BROAD .mat or "
                             "bundled .npz trial)")
        sp.add_argument("--format", dest="fmt", help="recording format (default: detected)")
        sp.add_argument("--fs", type=argtypes.real(0.0, math.inf, lo_open=True),
                        help="sampling rate (Hz) for formats without time stamps")
        sp.add_argument("--unit", metavar="ID",
                        help="unit in a .kfr recording holding several: its unit (MAVLink system) "
                             "id, or s<stream>:<id>")
        sp.add_argument("--json", action="store_true", help="print exactly one JSON object")
        sp.add_argument("--out", metavar="CALIB.json", help="write/update the unit calibration file")
        sp.add_argument("--serial", help="unit serial number (needed when --out creates a new file)")
        sp.add_argument("--range", dest="ranges", action="append", default=[], metavar="NAME=VALUE",
                        help="configured sensor range stored in the unit file, e.g. acc_g=8, gyr_dps=2000")
        g = sp.add_argument_group("static detection")
        d = static.StaticConfig()
        g.add_argument("--static-window", type=float, default=d.window_s, help="moving window (s)")
        g.add_argument("--gyr-std-max", type=float, default=d.gyr_std_max, help="rad/s")
        g.add_argument("--gyr-abs-max", type=float, default=d.gyr_abs_max, help="rad/s")
        g.add_argument("--acc-std-max", type=float, default=d.acc_std_max, help="m/s²")
        g.add_argument("--min-duration", type=float, default=d.min_duration_s, help="s")

    a = sub.add_parser("accel", help="accelerometer: seed-002 LS, Procrustes or full model")
    common(a, False)
    a.add_argument("--poses", metavar="POSES.csv", help="mean raw acceleration per pose (rows)")
    a.add_argument("--targets", metavar="TARGETS.csv", help="expected gravity vector per pose")
    a.add_argument("--method", choices=["ls", "procrustes", "full"],
                   help="default: ls with targets, full (|acc| = g) without")
    a.add_argument("--g", type=argtypes.real(0.0, math.inf, lo_open=True), default=None,
                   help=f"gravity (m/s²) for |acc| = g, the fit without --targets (default "
                        f"{G_STANDARD})")
    a.set_defaults(func=run_accel)

    gy = sub.add_parser("gyro", help="gyroscope bias from static windows (+ scale from known rates)")
    common(gy, True)
    gy.add_argument("--rate-windows", metavar="RATES.csv",
                    help="rows t_start,t_end,wx,wy,wz: spans with a known constant rate (rad/s)")
    gy.set_defaults(func=run_gyro)

    m = sub.add_parser("mag", help="magnetometer hard/soft iron (ellipsoid fit)")
    common(m, True)
    m.add_argument("--model", choices=["auto", "full", "hard"], default="auto",
                   help="full: hard + soft iron; hard: offset only; auto (default): full when "
                        "the readings visit at least 60%% of the direction sphere, else hard")
    m.add_argument("--field-norm", type=argtypes.real(0.0, math.inf, lo_open=True, hi_open=True),
                   help="local field magnitude (µT) to scale to")
    m.add_argument("--gate", type=float, metavar="UT",
                   help="seed-001 gating: report the samples whose calibrated |m| leaves ±UT of the "
                        "mean (seed: 0.5); the report command applies it with --mag-gate")
    m.set_defaults(func=run_mag)

    ap = sub.add_parser("apply", help="write a unit calibration file to the unit (parameters, read back)",
                        description="Write the calibration file's accelerometer, gyroscope and magnetometer "
                                    "maps to the unit as its KF_ACC/GYR/MAG_M<ij>, _B<i> parameters (--sensor 1: "
                                    "KF_ACC2/GYR2/MAG2_*, the second IMU of a two-sensor unit), then read "
                                    "every value back.  Refused when the file's serial number is not the "
                                    "unit's KF_SERIAL_NO.  Sensors absent from the file keep their values.  A "
                                    "two-sensor unit has two calibration files, one per IMU, both with the "
                                    "unit's serial number.")
    ap.add_argument("--calib", required=True, metavar="CALIB.json", help="unit calibration file")
    ap.add_argument("--port", metavar="CONN", help="serial port or connection string of the unit")
    ap.add_argument("--baud", default=921600, metavar="BAUD", help="serial baud rate (default 921600)")
    ap.add_argument("--unit", type=int, metavar="SYSID", help="system id of the unit (default: first heartbeat)")
    ap.add_argument("--sensor", type=int, choices=(0, 1), default=0,
                    help="the unit's sensor the file calibrates: 0 (default; KF_ACC_* ...) or 1, the second "
                         "IMU of a two-sensor unit (KF_ACC2_* ...)")
    ap.add_argument("--timeout", type=argtypes.real(0.0, 3600.0, lo_open=True), default=3.0, metavar="S",
                    help="wait this long for the unit (default 3)")
    ap.add_argument("--dry-run", action="store_true", help="print the parameters without connecting")
    ap.add_argument("--json", action="store_true", help="print exactly one JSON object")
    from kinefuse.host.link.signing import add_key_args
    add_key_args(ap, "the calibration writes")
    ap.set_defaults(func=run_apply)


# ----------------------------------------------------------------------------- helpers
def _static_cfg(args) -> static.StaticConfig:
    return static.StaticConfig.from_args(args)


def _numeric_csv(path: str, ncols: tuple, what: str) -> np.ndarray:
    from kinefuse.host.readers.table import read as read_table
    tab = read_table(path, has_header=False)
    rows, lines = tab.rows, list(tab.lines)
    rows = [(r, l) for r, l in zip(rows, lines) if not r[0].lstrip().startswith("#")]
    out = []
    for k, (r, ln) in enumerate(rows):
        cells = [c for c in r if c.strip() != ""]
        try:
            vals = [float(c) for c in cells]
        except ValueError:
            if k == 0:
                continue  # header line
            raise KinefuseError(f"{path}: line {ln}: {what} values must be numbers") from None
        if len(vals) not in ncols:
            raise KinefuseError(f"{path}: line {ln}: expected {' or '.join(map(str, ncols))} "
                                f"columns, got {len(vals)}")
        out.append(vals)
    if not out:
        raise KinefuseError(f"{path}: no {what} rows")
    if len({len(r) for r in out}) != 1:
        raise KinefuseError(f"{path}: rows have different numbers of columns")
    return np.array(out)


def _ranges(args) -> dict:
    """``--range NAME=VALUE`` -> {name: value}: a known name (unitfile.SENSOR_RANGES), a
    positive finite number, each name once; one-line errors otherwise."""
    from kinefuse.host.calib.unitfile import SENSOR_RANGES
    from kinefuse.host.paramargs import parse_assignments
    out = parse_assignments(args.ranges, "--range", numbers_only=True)
    for k, v in out.items():
        if k not in SENSOR_RANGES:
            raise KinefuseError(f"--range {k}: unknown sensor range (valid: {', '.join(SENSOR_RANGES)})")
        if not v > 0:
            raise KinefuseError(f"--range {k}={v:g}: a sensor range must be positive")
    return out


def _check_ranges(args) -> None:
    """--range before any work: valid names and values, and only with --out (where it is stored);
    --serial likewise only with --out (it was accepted and ignored without).  An empty --out was
    taken as no --out (nothing written, without a word); a blank --serial was written to the file
    as the unit's serial, and spaces around one made it another unit's."""
    if args.out is not None and not args.out.strip():
        raise KinefuseError("--out is empty: give the unit calibration file to write")
    if args.serial is not None:
        if not args.serial.strip():
            raise KinefuseError(f"--serial {args.serial!r} is blank: give the unit's serial number")
        args.serial = args.serial.strip()
    if _ranges(args) and not args.out:
        raise KinefuseError("--range is stored in the unit calibration file: give --out")
    if args.serial is not None and not args.out:
        raise KinefuseError("--serial names the unit in the calibration file: give --out")
    if args.out:
        _check_out_file(args)


def _check_out_file(args) -> None:
    """--out before the recording is read and fitted (these were said only after the work): a
    folder, a missing folder, another unit's file, a new file without --serial."""
    from pathlib import Path
    from kinefuse.host.calib import unitfile
    out = Path(args.out)
    if out.is_dir():
        raise KinefuseError(f"--out {out} is a folder (Is a directory): give the unit calibration file")
    if str(out.parent) and not out.parent.is_dir():
        raise KinefuseError(f"cannot write {out}: folder {out.parent} does not exist")
    unitfile.load_or_new(args.out, args.serial, None)


def _read(args):
    from kinefuse.host.readers import detect_format, kfr, read_recording
    from kinefuse.host.commands.report_cmd import check_fs_option
    opts = {}
    if args.fs is not None:
        check_fs_option(args.fs, args.input, args.fmt or detect_format(args.input))
        opts["fs"] = args.fs
    check_unit_option(args.unit)
    if args.unit is not None:
        fmt = args.fmt or detect_format(args.input)
        if fmt != kfr.FORMAT:
            raise KinefuseError(f"--unit {args.unit}: {args.input} is not a .kfr unit recording "
                                f"({fmt}); --unit selects a unit in a .kfr file")
        opts["unit"] = args.unit
    rec = read_recording(args.input, args.fmt, **opts)
    for w in rec.warnings:
        print(f"kinefuse: warning: {w}", file=sys.stderr)
    return rec


def _emit(args, obj: dict, text: list[str]) -> None:
    if args.json:
        print(json.dumps(obj))
    else:
        print("\n".join(text))


def _save(args, sensor: str, M, b, **extra) -> None:
    if not args.out:
        return
    from kinefuse.host.calib import unitfile
    doc = unitfile.load_or_new(args.out, args.serial, _ranges(args))
    old = doc["sensors"].get(sensor)
    unitfile.set_sensor(doc, sensor, M, b, **extra)
    unitfile.save(doc, args.out)
    if not args.json:
        kept = (f" (the previous one, of {old.get('date', 'unknown date')}, kept under history.{sensor})"
                if old is not None else "")
        print(f"wrote {sensor} calibration to {args.out}{kept}")


# ----------------------------------------------------------------------------- accel
def _check_accel_units(args, raw, targets) -> None:
    """Poses and targets (or --g) in the same unit: a pose table in g fitted against m/s² gave
    a scale of 9.8 without a word (and a unit file the unit refuses)."""
    if not (np.all(np.isfinite(raw)) and (targets is None or np.all(np.isfinite(targets)))):
        return          # accel.fit names non-finite values
    ref = float(np.median(np.linalg.norm(targets, axis=1))) if targets is not None else args.g
    got = float(np.median(np.linalg.norm(raw, axis=1)))
    if ref > 0 and got > 0 and not 0.5 <= got / ref <= 2.0:
        what = f"the targets' ({ref:.4g})" if targets is not None else f"--g {ref:g}"
        src = args.poses or args.input
        raise KinefuseError(f"{src}: the poses' median |acc| is {got:.4g}, {got / ref:.3g} × {what}: "
                            f"not the same unit (g and m/s²?); give both in m/s²")


def _check_poses_options(args) -> None:
    """--poses holds the pose means already: the options that read a recording and find its
    static windows were accepted and ignored."""
    d = static.StaticConfig()
    unused = [o for o, given in (("--format", args.fmt is not None), ("--fs", args.fs is not None),
                                 ("--unit", args.unit is not None),
                                 ("--static-window", args.static_window != d.window_s),
                                 ("--gyr-std-max", args.gyr_std_max != d.gyr_std_max),
                                 ("--gyr-abs-max", args.gyr_abs_max != d.gyr_abs_max),
                                 ("--acc-std-max", args.acc_std_max != d.acc_std_max),
                                 ("--min-duration", args.min_duration != d.min_duration_s)) if given]
    if unused:
        raise KinefuseError(f"{', '.join(unused)}: option(s) of --input RECORDING (reading it, finding "
                            f"its static poses); --poses {args.poses} holds the pose means already")


def run_accel(args) -> int:
    from kinefuse.host.calib import accel
    _check_ranges(args)
    targets = None
    n_samples = None
    if args.poses and args.input:
        raise KinefuseError("give either --poses or --input, not both")
    if args.g is not None and args.targets:
        # the targets' gravity vectors are what the fit matches: --g was ignored without a word
        raise KinefuseError(f"--g {args.g:g} sets |acc| = g of the fit without --targets; with "
                            f"--targets the fit matches their gravity vectors: give one or the other")
    args.g = G_STANDARD if args.g is None else args.g
    if args.poses:
        _check_poses_options(args)
        raw = _numeric_csv(args.poses, (2, 3), "pose")
        if args.targets is None and args.method in (None, "ls", "procrustes"):
            raise KinefuseError("--poses needs --targets for the ls and procrustes methods "
                                "(or use --method full to fit |acc| = g)")
    elif args.input:
        rec = _read(args)
        rec.require("acc")
        cfg = _static_cfg(args)
        wins = static.detect_static(rec.t, rec.acc, rec.gyr, cfg, source=args.input)
        static.require_windows(wins, 3, "accelerometer poses", cfg)
        raw = static.window_means(rec.acc, wins)
        n_samples = int(sum(w.n for w in wins))
    else:
        raise KinefuseError("give --poses POSES.csv (with --targets) or --input RECORDING")
    if args.targets:
        targets = _numeric_csv(args.targets, (2, 3), "target")
        if targets.shape != raw.shape:
            src = "static windows detected" if args.input else "poses"
            raise KinefuseError(f"{args.targets}: {targets.shape[0]} targets of {targets.shape[1]} columns for "
                                f"{raw.shape[0]} {src} of {raw.shape[1]} columns")
    method = args.method or ("ls" if targets is not None else "full")
    _check_accel_units(args, raw, targets)
    cal = accel.fit(raw, targets, method=method, g=args.g)
    if not cal.det > 0:
        # a unit file refuses such a map, so --json refuses it too (consistently, before output)
        raise KinefuseError(f"accelerometer fit ({method}) has det = {cal.det:.4f} ≤ 0: a reflection, not a "
                            f"calibration (are the targets in a left-handed frame, or one axis' sign "
                            f"flipped?); refused")
    # the poses may be in g throughout (--g 1, or targets in g): the fit is then in g, and a unit
    # file, whose accelerometer entry is m/s², stored a bias in g labelled m/s²
    ref = float(np.median(np.linalg.norm(targets, axis=1))) if targets is not None else args.g
    si = 9.7 <= ref <= 9.9
    if args.out and not si:
        what = f"the targets' |g| is {ref:.4g}" if targets is not None else f"--g {ref:g}"
        raise KinefuseError(f"{what}: the poses are not in m/s², but the unit calibration file stores the "
                            f"accelerometer in m/s²; give poses and targets in m/s² to write --out")
    unit = "m/s²" if si else "(the poses' unit)"
    for w in cal.warnings:
        print(f"kinefuse: warning: {w}", file=sys.stderr)
    if args.out:
        M = np.eye(3)
        d = cal.M.shape[0]
        M[:d, :d] = cal.M
        b = np.zeros(3)
        if cal.b is not None:
            b[:d] = cal.b
        _save(args, "accel", M, b, method=method, model=cal.model, residual_rms=cal.residual_rms,
              n_poses=cal.n_poses, n_samples=n_samples, det=cal.det,
              protocol="2-D (z axis not calibrated)" if d == 2 else "3-D")
    text = [f"accelerometer calibration ({method}, {cal.model}, {cal.n_poses} poses)",
            "R =" if cal.b is None else "M =",
            *("  " + "  ".join(f"{v:9.5f}" for v in row) for row in cal.M),
            f"bias = {'none' if cal.b is None else ', '.join(f'{v:.5f}' for v in cal.b) + ' ' + unit}",
            f"det = {cal.det:.5f}", f"residual_rms = {cal.residual_rms:.5f} {unit}"]
    _emit(args, cal.to_json(), text)
    return 0


# ----------------------------------------------------------------------------- gyro
def run_gyro(args) -> int:
    from kinefuse.host.calib import gyro
    _check_ranges(args)
    rec = _read(args)
    rec.require("gyr", "acc")
    cfg = _static_cfg(args)
    if args.rate_windows:
        rw = _numeric_csv(args.rate_windows, (5,), "rate window")
        cal = gyro.scale_from_recording(rec.t, rec.gyr, rec.acc, rw, cfg, source=args.input)
    else:
        cal = gyro.bias_from_static(rec.t, rec.gyr, rec.acc, cfg, source=args.input)
    _save(args, "gyro", cal.M, cal.b, method=cal.method, n_windows=cal.n_windows,
          n_samples=cal.n_samples, window_spread=cal.window_spread, residual_rms=cal.residual_rms)
    text = [f"gyroscope calibration ({cal.method}): {cal.n_windows} window{'' if cal.n_windows == 1 else 's'}, {cal.n_samples} samples",
            f"bias = {', '.join(f'{v:.6f}' for v in cal.b)} rad/s "
            f"({', '.join(f'{np.degrees(v):.3f}' for v in cal.b)} °/s)",
            (f"spread of window means = {cal.window_spread:.6f} rad/s" if np.isfinite(cal.window_spread)
             else "spread of window means = n/a (one static window: a drifting bias cannot be seen)")
            if cal.method == "static-bias" else f"residual_rms = {cal.residual_rms:.6f} rad/s"]
    _emit(args, cal.to_json(), text)
    return 0


# ----------------------------------------------------------------------------- mag
def run_mag(args) -> int:
    from kinefuse.host.calib import mag
    _check_ranges(args)
    rec = _read(args)
    samples = rec.mag_samples()
    if samples is None:
        raise KinefuseError(f"{args.input}: {rec.fmt} recording has no magnetometer data")
    cal = mag.calibrate(samples, model=args.model, field_norm=args.field_norm)
    for w in cal.warnings:
        print(f"kinefuse: warning: {w}", file=sys.stderr)
    obj = cal.to_json()
    gate_txt = []
    if args.gate is not None:
        _, keep = mag.gate_norm(cal.apply(samples), args.gate)
        obj["gate_uT"] = args.gate
        obj["gated_fraction"] = float(1.0 - keep.mean())
        gate_txt = [f"gating ±{args.gate:g} µT: {100 * obj['gated_fraction']:.1f}% of samples would be held"]
    _save(args, "mag", cal.W, cal.b, method=f"ellipsoid-{cal.model}", field_norm=cal.field_norm,
          n_samples=cal.n_samples, residual_rms=cal.residual_rms,
          norm_std_before=cal.norm_std_before, norm_std_after=cal.norm_std_after,
          spread_reduction=cal.spread_reduction, coverage=cal.coverage)
    chosen = f"{cal.model}, chosen by --model auto" if args.model == "auto" else cal.model
    text = [f"magnetometer calibration ({chosen}, {cal.n_samples} samples)",
            f"offset b = {', '.join(f'{v:.3f}' for v in cal.b)} µT",
            "W =", *("  " + "  ".join(f"{v:9.5f}" for v in row) for row in cal.W),
            f"|m| spread: {cal.norm_std_before:.3f} µT ({100 * cal.rel_spread_before:.2f} %) before, "
            f"{cal.norm_std_after:.3f} µT ({100 * cal.rel_spread_after:.2f} %) after "
            f"(×{cal.spread_reduction:.1f})",
            f"coverage: {100 * cal.coverage['cells_visited']:.0f}% of directions, "
            f"smallest spread {cal.coverage['min_eigenvalue']:.3f} (sphere 0.333)"] + gate_txt
    _emit(args, obj, text)
    return 0


# ----------------------------------------------------------------------------- apply
def run_apply(args) -> int:
    from kinefuse.host.calib import unitfile, unitparams
    doc = unitfile.load(args.calib)
    values = unitparams.plan(doc, args.calib, args.sensor)
    if args.dry_run:
        _emit(args, {"serial": doc["serial"], "sensor": args.sensor, "sensors": sorted(doc["sensors"]),
                     "params": values},
              [f"{k} = {v!r}" for k, v in values.items()])
        return 0
    if not args.port:
        raise KinefuseError("calibrate apply needs --port CONN (or --dry-run)")
    from kinefuse.host.link.connection import open_connection, parse_baud
    from kinefuse.host.link.session import Session
    from kinefuse.host.link.signing import key_from_args
    key = key_from_args(args)
    conn = open_connection(args.port, parse_baud(args.baud))
    with Session(conn, key=key) as s:
        sysid = args.unit
        if sysid is None:
            from kinefuse.host.link.cli_util import first_unit
            sysid = first_unit(s, args.port, args.timeout)
        res = unitparams.apply_to_unit(s, sysid, doc, args.calib, sensor=args.sensor,
                                       warn=lambda m: print(f"kinefuse: warning: {m}", file=sys.stderr))
    _emit(args, res, [f"unit {sysid}: wrote {len(res['written'])} calibration parameters of sensor {args.sensor} "
                      f"({', '.join(res['sensors'])}; {len(res['changed'])} changed) from {args.calib}, "
                      f"read back and verified"])
    return 0
