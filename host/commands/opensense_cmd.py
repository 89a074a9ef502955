"""``kinefuse opensense``: replay a recording's units through a filter and write their orientations
as an OpenSim OpenSense table (``.sto``) for IMU Placer / IMU Inverse Kinematics.

    kinefuse opensense walk.kfr --imu 1=pelvis_imu --imu 2=femur_r_imu --imu 3=tibia_r_imu \\
        --out walk_orientations.sto [--rate 100] [--filter flagship --impl f32]
"""
from __future__ import annotations

import re
import sys
from pathlib import Path

import numpy as np

from kinefuse.host import runner
from kinefuse.host.errors import KinefuseError
from kinefuse.host.outputs import add_force_arg, check_new_file

NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def register(sub) -> None:
    p = sub.add_parser("opensense", help="write units' orientations as an OpenSim OpenSense table (.sto)",
                       description=__doc__.split("\n\n")[0].split(": ", 1)[-1])
    p.add_argument("rec", metavar="REC", help="recording: a .kfr (its units share the host clock) or "
                                              "a one-sensor reader format (Xsens DOT, MetaBase, ...)")
    p.add_argument("--imu", action="append", required=True, metavar="UNIT=NAME",
                   help="a unit of the recording (as replay --unit: 2, s1, s1:2) and the model's IMU "
                        "frame it is on (e.g. femur_r_imu); repeatable; NAME alone: the only unit")
    p.add_argument("--out", required=True, metavar="STO", help="the table to write (.sto)")
    p.add_argument("--rate", type=float, metavar="HZ",
                   help="rate of the table (default: the slowest unit's sample rate, whole Hz)")
    p.add_argument("--max-gap", type=float, default=0.1, metavar="S",
                   help="longest run of lost samples interpolated over (default 0.1 s); a longer "
                        "one is an error")
    p.add_argument("--filter", default=None,
                   help=f"orientation filter (default: {runner.default_filter()})")
    p.add_argument("--impl", default="f32", choices=runner.IMPLS, help="implementation (default f32)")
    p.add_argument("--param", action="append", metavar="NAME=VALUE", help="parameter override")
    p.add_argument("--preset", help="named parameter set (see `kinefuse filters`)")
    add_force_arg(p, "the table")
    p.set_defaults(func=run)


def _imus(items: list[str]) -> list[tuple[str | None, str]]:
    out: list[tuple[str | None, str]] = []
    for item in items:
        unit, sep, name = item.rpartition("=")
        unit, name = (unit.strip() or None) if sep else None, name.strip()
        if sep and unit is None:
            raise KinefuseError(f"--imu {item!r}: expected UNIT=NAME (or NAME for a one-unit recording)")
        if not NAME.fullmatch(name):
            raise KinefuseError(f"--imu {item!r}: {name!r} is not an IMU frame name (letters, digits, _; "
                                f"OpenSense names them <body>_imu)")
        if name.lower() == "time":      # the table's first column is named time
            raise KinefuseError(f"--imu {item!r}: 'time' names the table's time column, not an IMU frame")
        if any(n == name for _, n in out):
            raise KinefuseError(f"--imu: the name {name} is given twice")
        if any(u == unit for u, _ in out):
            raise KinefuseError(f"--imu: unit {unit if unit else '(the only one)'} is given twice")
        out.append((unit, name))
    if len(out) > 1 and any(u is None for u, _ in out):
        raise KinefuseError("--imu: with several IMUs give each one's unit: UNIT=NAME")
    return out


def run(args) -> int:
    from kinefuse.host.commands.replay_cmd import read_imu_recording
    from kinefuse.host.opensense import ImuSeries, common_grid, gap_in_grid, write_sto

    name = args.filter or runner.default_filter()
    if name not in runner.imu_filter_names():
        raise KinefuseError(f"{name!r} is not an IMU orientation filter (available: "
                            f"{', '.join(runner.imu_filter_names())})")
    prm = runner.parse_params(args.param)
    runner.check_params(name, prm, args.preset)
    imus = _imus(args.imu)
    if args.rate is not None and not 0 < args.rate <= 10_000:
        raise KinefuseError(f"--rate must be in (0, 10000] Hz, not {args.rate:g}")
    if not args.max_gap > 0:
        raise KinefuseError("--max-gap must be positive")
    path = str(args.rec)
    if Path(path).suffix.lower() in (".mat", ".npz"):
        raise KinefuseError(f"{path}: a BROAD/simulator trial has no units to place on a model; give a "
                            f"unit recording (.kfr or a reader format)")
    out = Path(args.out)
    if out.suffix.lower() != ".sto":
        raise KinefuseError(f"--out {out}: OpenSense reads .sto tables, name it *.sto")
    check_new_file(out, args.force, inputs=[path])

    recs, units, warned = [], {}, set()
    from kinefuse.host.readers.kfr import decode_once
    with decode_once():    # every unit read before any filter runs: a missing one fails first
        for unit, imu_name in imus:
            if unit is not None and Path(path).suffix.lower() != ".kfr":
                raise KinefuseError(f"--imu {unit}={imu_name}: units are chosen in .kfr recordings; "
                                    f"{path} holds one sensor (give --imu {imu_name})")
            rec = read_imu_recording(path, unit)
            if rec.fmt == "kfr":
                # 1 and s0:1 name the same unit: one sensor cannot be on two bodies
                key = (rec.metadata["stream"], rec.metadata["sysid"])
                if key in units:
                    raise KinefuseError(f"--imu {unit}={imu_name}: unit {rec.metadata['unit']} is "
                                        f"already given as {units[key]}")
                units[key] = imu_name
            recs.append((imu_name, rec))
    series, rates = [], []
    for imu_name, rec in recs:
        for w in rec.warnings:
            if w not in warned:     # the file's own warnings (truncated, damaged) once, not per unit
                warned.add(w)
                print(f"kinefuse: warning: {w}", file=sys.stderr)
        inputs = runner.recording_inputs(rec)
        t = np.asarray(inputs.t, dtype=np.float64)
        if len(t) < 2:
            raise KinefuseError(f"{path}: {imu_name}: {len(t)} sample(s), nothing to interpolate")
        res = runner.run_filter(name, args.impl, inputs, prm, args.preset)
        keep = np.concatenate([[True], np.diff(t) > 0])     # duplicates and steps back: dropped
        series.append(ImuSeries(imu_name, t[keep], np.asarray(res.q, dtype=np.float64)[keep]))
        rates.append(1.0 / float(np.median(np.diff(t[keep]))))
        who = f"unit {rec.metadata['unit']}" if rec.fmt == "kfr" else rec.fmt
        print(f"{imu_name}: {who}, {len(t):,} samples at {rates[-1]:.1f} Hz, "
              f"{runner.rejected_count(res) or 0} rejected by {name}", file=sys.stderr)
    rate = args.rate if args.rate is not None else float(max(1, round(min(rates))))
    grid = common_grid(series, rate)
    for s in series:
        gap, t_gap = gap_in_grid(s, grid)
        if gap > args.max_gap:
            raise KinefuseError(f"{s.name}: {gap:.3f} s without samples after t = {t_gap:.3f} s (longer than "
                                f"--max-gap {args.max_gap:g} s): interpolating would invent the motion")
    try:
        n = write_sto(out, grid, series, rate)
    except OSError as exc:
        raise KinefuseError(f"cannot write {out}: {exc.strerror or exc}") from None
    print(f"wrote {out}: {n} rows at {rate:g} Hz, t = {grid[0]:.3f} .. {grid[-1]:.3f} s, "
          f"{', '.join(s.name for s in series)} (sensor -> ENU, {name} {args.impl}; OpenSense "
          f"sensor_to_opensim_rotations -1.5707963 0 0)", file=sys.stderr)
    return 0
