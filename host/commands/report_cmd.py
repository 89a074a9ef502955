"""``kinefuse report knee|elbow`` — clinical joint-angle reports (PNG, CSV, Markdown).

Knee (seed 001 step-up protocol)::

    kinefuse report knee --thigh step-thigh.csv --shank step-shank.csv \\
        --calib-standing stand-thigh.csv stand-shank.csv \\
        --calib-lying lie-thigh.csv lie-shank.csv \\
        --mag-cal fig8-thigh.csv fig8-shank.csv --side right --out report/

Elbow (seed 002 set-up)::

    kinefuse report elbow --arm arm.csv --forearm forearm.csv --out report/

Units' recordings (``kinefuse record``, several units in one .kfr; times synchronised)::

    kinefuse report knee --thigh both.kfr --thigh-unit 1 --shank both.kfr --shank-unit 2 --out report/

Recordings may hold device quaternions (used by default) or raw IMU data (then the orientation
filter ``--filter`` is run: ``complementary`` or ``module:function``).
"""
from __future__ import annotations

import json
import math
import os
import sys

from kinefuse.host import argtypes
from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.cli_util import check_unit_option
from kinefuse.host.kinematics import joint   # light (numpy); the heavy modules load on use
from kinefuse.host.outputs import add_force_arg, check_output_dir


UNIT_HELP = ("unit of the {seg} sensor in .kfr recordings holding several units: its unit (MAVLink "
             "system) id, or s<stream>:<id>; also applies to the {seg} calibration recordings")


def register(subparsers) -> None:
    p = subparsers.add_parser("report", help="clinical joint-angle reports (knee step-up, elbow)",
                              description=__doc__.split("\n\n")[0].replace("``", ""))
    sub = p.add_subparsers(dest="joint", metavar="JOINT", parser_class=type(p))
    p.set_defaults(func=lambda args: (p.print_help(), 2)[1])

    def common(sp):
        sp.add_argument("--out", required=True, metavar="DIR", help="output directory")
        sp.add_argument("--format", dest="fmt", help="recording format (default: detected)")
        sp.add_argument("--fs", type=argtypes.real(0.0, math.inf, lo_open=True),
                        help="sampling rate (Hz) for formats without time stamps")
        sp.add_argument("--filter", default=None,
                        help="orientation filter for raw recordings: a kinefuse filter (default: the "
                             "default filter, flagship), name@q for fixed point, 'simple', or "
                             "module:function")
        sp.add_argument("--orientation", choices=["auto", "device", "filter"], default="auto",
                        help="auto: device quaternions when present, else the filter")
        sp.add_argument("--drop-edge-cycles", type=int, default=0, metavar="N",
                        help="ignore the first and last N cycles (filter convergence, seed 001 drops 1)")
        sp.add_argument("--max-cycle-rmse", type=float, default=10.0, metavar="DEG",
                        help="reject cycles deviating more than this from the mean flexion curve")
        sp.add_argument("--json", action="store_true", help="print the summary as one JSON object")
        add_force_arg(sp, "an earlier report of the same joint in DIR")
        from kinefuse.host.calib.static import StaticConfig
        g = sp.add_argument_group("static detection (postures, gyroscope bias, heading alignment)")
        d = StaticConfig()
        g.add_argument("--static-window", type=float, default=d.window_s, help="moving window (s)")
        g.add_argument("--gyr-std-max", type=float, default=d.gyr_std_max, help="rad/s")
        g.add_argument("--gyr-abs-max", type=float, default=d.gyr_abs_max, help="rad/s")
        g.add_argument("--acc-std-max", type=float, default=d.acc_std_max, help="m/s²")
        g.add_argument("--min-duration", type=float, default=d.min_duration_s, help="s")

    k = sub.add_parser("knee", help="knee step-up report (seed 001 protocol)")
    k.add_argument("--thigh", required=True, metavar="REC", help="step-up recording, thigh sensor")
    k.add_argument("--shank", required=True, metavar="REC", help="step-up recording, shank sensor")
    k.add_argument("--thigh-unit", metavar="ID", help=UNIT_HELP.format(seg="thigh"))
    k.add_argument("--shank-unit", metavar="ID", help=UNIT_HELP.format(seg="shank"))
    k.add_argument("--calib-standing", nargs=2, metavar=("THIGH", "SHANK"), help="standing still recordings")
    k.add_argument("--calib-lying", nargs=2, metavar=("THIGH", "SHANK"), help="lying supine recordings")
    k.add_argument("--calib-functional", nargs=2, metavar=("THIGH", "SHANK"),
                   help="functional calibration instead of lying: flexion-extension recordings (squats or "
                        "step-ups; each gyroscope's principal axis is the flexion axis), with --calib-standing")
    k.add_argument("--mag-cal", nargs=2, metavar=("THIGH", "SHANK"),
                   help="figure-eight recordings for the magnetometer calibration")
    k.add_argument("--unit-cal", nargs=2, metavar=("THIGH.json", "SHANK.json"),
                   help="unit calibration files (kinefuse calibrate --out)")
    k.add_argument("--field-norm", type=argtypes.real(0.0, math.inf, lo_open=True, hi_open=True),
                   help="local magnetic field (µT) for the mag calibration")
    k.add_argument("--mag-gate", type=float, metavar="UT",
                   help="seed-001 gating: hold samples whose |m| leaves ±UT of the mean (seed: 0.5)")
    k.add_argument("--side", choices=["right", "left"], default="right")
    k.add_argument("--convention", choices=list(joint.KNEE_CONVENTIONS), default="grood-suntay")
    common(k)
    k.set_defaults(func=run_knee)

    e = sub.add_parser("elbow", help="elbow flexion report (seed 002 set-up)")
    e.add_argument("--arm", required=True, metavar="REC")
    e.add_argument("--forearm", required=True, metavar="REC")
    e.add_argument("--arm-unit", metavar="ID", help=UNIT_HELP.format(seg="arm"))
    e.add_argument("--forearm-unit", metavar="ID", help=UNIT_HELP.format(seg="forearm"))
    e.add_argument("--unit-cal", nargs=2, metavar=("ARM.json", "FOREARM.json"),
                   help="unit calibration files (kinefuse calibrate --out)")
    e.add_argument("--sequence", choices=list(joint.ELBOW_SEQUENCES), default="XYZ",
                   help="XYZ: seed 002 eqs. 2.7-2.9; ZYX: the seed's MATLAB code")
    e.add_argument("--init", choices=list(joint.ELBOW_INITS), default="zero-at-start")
    common(e)
    e.set_defaults(func=run_elbow)


def _static_cfg(args):
    """The same thresholds and flags as ``kinefuse calibrate``."""
    from kinefuse.host.calib import static
    return static.StaticConfig.from_args(args)


def _reader(args):
    from kinefuse.host.readers import detect_format, kfr, read_recording
    opts = {"fs": args.fs} if args.fs is not None else {}

    def read(path, unit=None, option=None):
        """``unit`` goes to .kfr recordings only; ``option`` names it for the error when the
        main recording of a segment is not a .kfr."""
        if path is None:
            return None
        fmt = args.fmt or detect_format(path)
        check_fs_option(args.fs, path, fmt)
        extra = {}
        if unit is not None:
            if fmt == kfr.FORMAT:
                extra["unit"] = unit
            elif option is not None:
                raise KinefuseError(f"{option} {unit}: {path} is not a .kfr unit recording "
                                    f"({fmt}); {option} selects a unit in a .kfr file")
        return read_recording(path, fmt, **opts, **extra)
    return read


def check_fs_option(fs, path, fmt) -> None:
    """--fs sets the rate of formats without time stamps; the readers of the others ignored it
    without a word (a recording at 100 Hz stayed at 100 Hz with --fs 50).  Shared with
    ``kinefuse calibrate``."""
    from kinefuse.host.readers import matrix, seed004
    if fs is not None and fmt not in (matrix.FORMAT, seed004.FORMAT):
        raise KinefuseError(f"--fs {fs:g}: {path} ({fmt}) has its own time stamps; --fs sets the sampling "
                            f"rate of {matrix.FORMAT} and {seed004.FORMAT} files, which have none")


def _pair(read, paths, units=(None, None), option=None):
    if paths is None:
        return None
    recs = (read(paths[0], units[0]), read(paths[1], units[1]))
    if option is not None:
        _check_distinct_units(option, paths, recs)
    return recs


def _check_unit_options(args, options) -> None:
    """--thigh-unit "" (an unset shell variable) read as no unit option: the file's only unit
    was taken for that segment (and, with the other segment's also blank, for both)."""
    for opt in options:
        check_unit_option(getattr(args, opt.lstrip("-").replace("-", "_")), opt)


def _check_distinct_units(option, paths, recs) -> None:
    """After reading: two spellings of one unit of one .kfr (``1`` and ``s0:1``, or no option on
    a one-unit file and its id) passed :func:`_check_distinct`, and both segments got the same
    sensor's data ('flexion varies by only 0.0°')."""
    a, b = recs
    if a is None or b is None or a.fmt != "kfr" or b.fmt != "kfr":
        return
    try:
        same = os.path.samefile(paths[0], paths[1])
    except OSError:
        return
    ident = [(r.metadata.get("stream"), r.metadata.get("sysid")) for r in recs]
    if same and ident[0] == ident[1]:
        names = " and ".join(option) if isinstance(option, tuple) else option
        raise KinefuseError(f"{names}: {paths[0]} unit {a.metadata.get('unit')} given for both "
                            f"segments; each segment has its own sensor and recording")


class _Progress:
    """rich progress on stderr (transient); silent when stderr is not a terminal."""

    def __init__(self, total: int):
        self.total = total
        self._p = None

    def __enter__(self):
        if sys.stderr.isatty():
            from rich.console import Console
            from rich.progress import BarColumn, Progress, TextColumn
            self._p = Progress(TextColumn("{task.description}"), BarColumn(),
                               console=Console(stderr=True), transient=True)
            self._p.__enter__()
            self._task = self._p.add_task("reading", total=self.total)
        return self

    def __call__(self, msg: str):
        if self._p is not None:
            self._p.update(self._task, advance=1, description=msg)

    def __exit__(self, *exc):
        if self._p is not None:
            self._p.__exit__(*exc)


def _with_unit(path, unit) -> str:
    return path if unit is None else f"{path} (unit {unit})"


def _finish(args, kind, res, title, inputs) -> int:
    from kinefuse.host.kinematics import report
    cs = report.detect_cycles(res, kind, drop_edge=args.drop_edge_cycles,
                              max_rmse_deg=args.max_cycle_rmse)
    summary = report.write_report(args.out, kind, res, cs, title=title, inputs=inputs,
                                  max_cycle_rmse_deg=args.max_cycle_rmse)
    for w in summary["warnings"]:
        print(f"kinefuse: warning: {w}", file=sys.stderr)
    if args.json:
        print(json.dumps(summary))
    else:
        rom = summary["range_of_motion_deg"]
        print(f"{title}: {summary['n_cycles_kept']} of {summary['n_cycles_detected']} cycles")
        for c, v in rom.items():
            sd = "n/a" if v["sd"] is None else f"{v['sd']:4.1f}"
            print(f"  {c:<24} ROM {v['mean']:6.1f} ± {sd}°  (max {v['max_mean']:6.1f}, "
                  f"min {v['min_mean']:6.1f})")
        print(f"  {res.convention}")
        print(f"wrote {', '.join(summary['files'])} to {os.path.abspath(args.out)}")
    return 0


def _check_out(args, kind: str) -> None:
    """--out before any work: not empty (that was the current folder, named nowhere), not a file,
    no earlier report unless --force, and no folder in the way of a report file."""
    from kinefuse.host.kinematics import report
    if not args.out.strip():
        raise KinefuseError("--out is empty: give the folder for the report")
    out = check_output_dir(args.out, args.force, report.report_files(kind))
    up = out.absolute()
    while not up.exists() and up != up.parent:
        up = up.parent
    if not up.is_dir():
        raise KinefuseError(f"--out {out}: cannot create the folder, {up} is a file")


def _same_file(a, b) -> bool:
    """One file under two names (or the same name); a missing one is reported by its reader."""
    if a == b:
        return True
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False


def _check_distinct(pairs, units) -> None:
    """Each segment has its own sensor: one recording (one unit of it) given for both segments
    was reported as 'flexion varies by only 0.0°', or calibrated both sensors with one's data."""
    for option, paths in pairs:
        if paths is None:
            continue
        a, b = paths
        if _same_file(a, b) and units[0] == units[1]:
            names = " and ".join(option) if isinstance(option, tuple) else option
            which = "" if units[0] is None else f" (unit {units[0]})"
            raise KinefuseError(f"{names}: {a}{which} given for both segments; each segment has its own "
                                f"sensor and recording")


def _load_unit_cals(paths, segments):
    """The two --unit-cal files, one per segment's sensor, and the warnings about them.  One
    file given for both would correct the second sensor with the first one's biases and scale
    factors: refused, as one recording for both segments is.  Two files holding the same maps (a
    copy) are warned about: a two-sensor unit's two IMUs share the serial number, but not their
    calibration."""
    from kinefuse.host.calib import unitfile
    if paths is None:
        return None, []
    a, b = paths
    if _same_file(a, b):
        raise KinefuseError(f"--unit-cal: {a} given for both segments ({segments[0]} and "
                            f"{segments[1]}); each sensor has its own calibration file")
    units = (unitfile.load(a), unitfile.load(b))
    warnings = []
    if units[0]["sensors"] and units[0]["sensors"] == units[1]["sensors"]:
        warnings.append(f"--unit-cal: {a} and {b} hold the same calibration "
                        f"({', '.join(sorted(units[0]['sensors']))}); the {segments[0]} and "
                        f"{segments[1]} sensors are corrected alike: is one a copy of the other?")
    return units, warnings


def _check_cycle_args(args) -> None:
    """One-line errors for cycle options that would silently change which cycles are reported."""
    import math
    if args.drop_edge_cycles < 0:
        raise KinefuseError(f"--drop-edge-cycles {args.drop_edge_cycles}: must be 0 or more")
    if not (math.isfinite(args.max_cycle_rmse) and args.max_cycle_rmse > 0):
        raise KinefuseError(f"--max-cycle-rmse {args.max_cycle_rmse:g}: must be a positive number of "
                            f"degrees")
    if args.orientation == "device" and args.filter is not None:
        raise KinefuseError(f"--filter {args.filter}: not used with --orientation device (the device's "
                            f"quaternions); give one or the other")


def _check_mag_args(args, units) -> None:
    """--field-norm and --mag-gate act on a magnetometer calibration; without one they were
    accepted and silently ignored."""
    if args.field_norm is not None and args.mag_cal is None:
        raise KinefuseError("--field-norm scales the figure-eight magnetometer fit: give --mag-cal")
    unit_mag = units is not None and all("mag" in u["sensors"] for u in units)
    if args.mag_gate is not None and args.mag_cal is None and not unit_mag:
        raise KinefuseError("--mag-gate gates the calibrated magnetometer: give --mag-cal (or --unit-cal "
                            "files that both hold a mag calibration)")


def run_knee(args) -> int:
    from kinefuse.host.kinematics import report
    _check_cycle_args(args)
    _check_out(args, "knee")
    if args.calib_functional is not None:
        if args.calib_lying is not None:
            raise KinefuseError("give --calib-lying (two-posture) or --calib-functional, not both")
        if args.calib_standing is None:
            raise KinefuseError("--calib-functional needs --calib-standing (the vertical axis)")
    elif (args.calib_standing is None) != (args.calib_lying is None):
        raise KinefuseError("--calib-standing and --calib-lying go together (two-posture method)")
    _check_distinct([(("--thigh", "--shank"), (args.thigh, args.shank)),
                     ("--calib-standing", args.calib_standing), ("--calib-lying", args.calib_lying),
                     ("--calib-functional", args.calib_functional), ("--mag-cal", args.mag_cal)],
                    (args.thigh_unit, args.shank_unit))
    _check_unit_options(args, ("--thigh-unit", "--shank-unit"))
    read = _reader(args)
    units, unit_warnings = _load_unit_cals(args.unit_cal, ("thigh", "shank"))
    _check_mag_args(args, units)
    with _Progress(7) as prog:
        prog("reading recordings")
        seg_units = (args.thigh_unit, args.shank_unit)
        thigh = read(args.thigh, args.thigh_unit, "--thigh-unit")
        shank = read(args.shank, args.shank_unit, "--shank-unit")
        _check_distinct_units(("--thigh", "--shank"), (args.thigh, args.shank), (thigh, shank))
        res = report.knee_from_recordings(
            thigh, shank, standing=_pair(read, args.calib_standing, seg_units, "--calib-standing"),
            lying=_pair(read, args.calib_lying, seg_units, "--calib-lying"),
            functional=_pair(read, args.calib_functional, seg_units, "--calib-functional"),
            mag_recordings=_pair(read, args.mag_cal, seg_units, "--mag-cal"), unit_calibrations=units,
            filter=args.filter,
            orientation=args.orientation, side=args.side, convention=args.convention,
            field_norm=args.field_norm, mag_gate=args.mag_gate,
            static_config=_static_cfg(args), progress=prog)
    res.warnings.extend(unit_warnings)      # stderr and the summary, as a doubtful input's
    inputs = {"thigh": _with_unit(args.thigh, args.thigh_unit), "shank": _with_unit(args.shank, args.shank_unit),
              "standing": " ".join(args.calib_standing or []), "lying": " ".join(args.calib_lying or []),
              "functional": " ".join(args.calib_functional or []),
              "magnetometer calibration": " ".join(args.mag_cal or []),
              "unit calibration": " ".join(args.unit_cal or [])}
    return _finish(args, "knee", res, f"{args.side.capitalize()} knee, step-up", inputs)


def run_elbow(args) -> int:
    from kinefuse.host.kinematics import report
    _check_cycle_args(args)
    _check_out(args, "elbow")
    _check_distinct([(("--arm", "--forearm"), (args.arm, args.forearm))], (args.arm_unit, args.forearm_unit))
    _check_unit_options(args, ("--arm-unit", "--forearm-unit"))
    read = _reader(args)
    units, unit_warnings = _load_unit_cals(args.unit_cal, ("arm", "forearm"))
    with _Progress(3) as prog:
        prog("reading recordings")
        arm = read(args.arm, args.arm_unit, "--arm-unit")
        forearm = read(args.forearm, args.forearm_unit, "--forearm-unit")
        _check_distinct_units(("--arm", "--forearm"), (args.arm, args.forearm), (arm, forearm))
        res = report.elbow_from_recordings(arm, forearm, filter=args.filter,
                                           orientation=args.orientation, sequence=args.sequence,
                                           init=args.init, unit_calibrations=units,
                                           static_config=_static_cfg(args), progress=prog)
    res.warnings.extend(unit_warnings)      # stderr and the summary, as a doubtful input's
    inputs = {"arm": _with_unit(args.arm, args.arm_unit), "forearm": _with_unit(args.forearm, args.forearm_unit),
              "unit calibration": " ".join(args.unit_cal or [])}
    return _finish(args, "elbow", res, "Elbow flexion–extension", inputs)
