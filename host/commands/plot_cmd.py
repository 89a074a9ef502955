"""``kinefuse plot``: an orientation estimate as a PNG -- against the optical reference of a BROAD
trial (or simulator .mat), or, for a unit or vendor recording (.kfr, Xsens DOT, MATRIX,
MetaBase, kinefuse CSV), with the sensor magnitudes, lost samples, the filter's status and (a
.kfr) the unit's own on-board orientation."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from kinefuse.host import broad
from kinefuse.host.bench import accuracy
from kinefuse.host.errors import KinefuseError
from kinefuse.host.link.cli_util import check_unit_option
from kinefuse.host.outputs import add_force_arg, check_new_file


def register(sub) -> None:
    p = sub.add_parser(
        "plot", help="plot a filter's orientation (PNG): vs the BROAD reference, or of a recording",
        description="Run a filter on one trial and plot estimate vs optical reference as Euler "
                    "angles (ZYX yaw-pitch-roll of sensor->ENU), the total/heading/inclination "
                    "error over time, the movement phases and the filter's status flags.  A unit "
                    "or vendor recording (no reference) is plotted with its sensor magnitudes, "
                    "lost samples, the filter's status and, for a .kfr, the unit's own "
                    "KF_ORIENTATION.")
    p.add_argument("--input", required=True, metavar="TRIAL",
                   help="trial file (.mat/.npz), or a trial name or number such as 32 looked "
                        "up in the default data (shared BROAD folder or bundled excerpt); or a "
                        "recording (.kfr, Xsens DOT / MATRIX / MetaBase / kinefuse CSV)")
    p.add_argument("--unit", metavar="ID", help="unit of a multi-unit .kfr (as `kinefuse replay`)")
    p.add_argument("--filter", metavar="NAME",
                   help="kinefuse filter or competitor (vqf, imufusion, ...); default: the "
                        "default kinefuse filter")
    p.add_argument("--impl", default=None, choices=accuracy.IMPLS,
                   help="implementation of a kinefuse filter (default: ref for a BROAD trial, f32 "
                        "-- the generated C, 1000x faster -- for a recording)")
    p.add_argument("--param", action="append", metavar="KEY=VALUE",
                   help="filter parameter override, repeatable")
    p.add_argument("--out", metavar="PNG", help="output file (default: <trial>_<filter>_<impl>.png, a competitor's "
                        "<trial>_<name>.png)")
    p.add_argument("--start", type=float, metavar="S", help="plot from this time (s)")
    p.add_argument("--end", type=float, metavar="S", help="plot up to this time (s)")
    add_force_arg(p, "the PNG")
    p.set_defaults(func=run)


def resolve_trial(arg: str) -> Path:
    """A trial file path, or a unique trial name/prefix in the default or bundled data."""
    path = Path(arg)
    if path.exists():
        if path.is_dir():
            raise KinefuseError(f"{arg}: is a directory; --input takes one trial file")
        return path
    if any(sep in arg for sep in ("/", "\\")) or path.suffix.lower() in broad.TRIAL_SUFFIXES:
        raise KinefuseError(f"{arg}: no such file")
    default_files, _ = broad.default_data()
    for files in (default_files, broad.bundled_trials()):
        matches = [f for f in files if f.stem == arg] or [f for f in files if f.stem.startswith(arg)]
        if len(matches) == 1:
            return matches[0]
        if len(matches) > 1:
            names = ", ".join(f.stem for f in matches[:6])
            raise KinefuseError(f"{arg}: ambiguous trial name ({names})")
    raise KinefuseError(f"{arg}: no such file, and no trial of that name in the default data")


def _check_window_args(args) -> None:
    """--start/--end on their own (before any work): finite, and start < end."""
    for opt, v in (("--start", args.start), ("--end", args.end)):
        if v is not None and not abs(v) < float("inf"):
            raise KinefuseError(f"{opt} must be a finite time in s, not {v}")
    if args.start is not None and args.end is not None and not args.start < args.end:
        raise KinefuseError(f"--start/--end: need start < end, got {args.start:g} and {args.end:g}")


def _window(args, t, what: str):
    """--start/--end (s on the plot's time axis, the sample times ``t``) or None."""
    if args.start is None and args.end is None:
        return None
    t0, t1 = float(t[0]), float(t[-1])
    start = t0 if args.start is None else args.start
    end = t1 if args.end is None else args.end
    if start >= t1:
        raise KinefuseError(f"--start {start:g}: {what} ends at {t1:.1f} s")
    if end <= max(t0, 0.0) or not start < end:
        raise KinefuseError(f"--start/--end: {what} runs from {max(t0, 0.0):.1f} to {t1:.1f} s; "
                            f"got {start:g} to {end:g}")
    # a window between two samples (or in a gap) was an internal IndexError, one sample an
    # empty plot
    n = int(np.count_nonzero((t >= start) & (t <= end)))
    if n < 2:
        raise KinefuseError(f"--start/--end: {n} sample(s) of {what} between {start:g} and {end:g} s; "
                            f"give a window with at least two")
    return start, end


def _out_path(args, stem: str, spec, input_file: Path) -> Path:
    safe = spec.label.replace(" (", "_").replace(")", "").replace(" ", "_")
    out = Path(args.out) if args.out else Path(f"{stem}_{safe}.png")
    if out.suffix.lower() != ".png":
        raise KinefuseError(f"--out {out}: the plot is written as PNG, name it *.png")
    check_new_file(out, args.force, inputs=[input_file])
    return out


def _plot_recording(args, spec, path: Path) -> int:
    """A recording without reference: replay it through the filter, then plot."""
    from rich.console import Console

    from kinefuse.host import runner
    from kinefuse.host.commands.replay_cmd import read_imu_recording, time_base_text, unit_orientation
    from kinefuse.host.link.cli_util import progress
    from kinefuse.host.plots import plot_recording
    from kinefuse.host.readers.kfr import decode_once

    if spec.kind == "competitor":
        raise KinefuseError(f"{spec.name}: competitors are run on BROAD trials (constant rate, a "
                            f"magnetometer reading in every sample); plot a recording with a "
                            f"kinefuse filter")
    check_unit_option(args.unit)
    out = _out_path(args, path.stem, spec, path) if args.out else None   # before any work
    err = Console(stderr=True)
    unit_q = no_unit_q = None
    with decode_once():     # a .kfr is decoded once: its samples and the unit's KF_ORIENTATION
        with progress(err, f"reading {path}"):
            rec = read_imu_recording(str(path), args.unit)
        if rec.fmt == "kfr":
            try:
                idx, q_u, _note, _total = unit_orientation(str(path), rec)
                unit_q = (idx, q_u)
            except KinefuseError as exc:
                no_unit_q = exc
    inputs = runner.recording_inputs(rec)
    t = np.asarray(inputs.t, dtype=np.float64)
    if len(t) < 2:
        raise KinefuseError(f"{path}: {len(t)} sample(s): nothing to plot")
    window = _window(args, t, "the recording")
    who = f" unit {rec.metadata['unit']}" if rec.fmt == "kfr" else ""
    if out is None:
        several = rec.fmt == "kfr" and len(rec.metadata.get("units_in_file", [])) > 1
        tag = ""
        if several:     # two units with one id on two streams both got _u1: the stream too
            m = rec.metadata
            tag = f"_u{m['sysid']}" if m["unit"] == str(m["sysid"]) else f"_s{m['stream']}_u{m['sysid']}"
        out = _out_path(args, path.stem + tag, spec, path)
    for w in rec.warnings:
        print(f"kinefuse: warning: {w}", file=sys.stderr)
    if no_unit_q is not None:
        print(f"kinefuse: note: no on-board orientation plotted ({no_unit_q})", file=sys.stderr)
    with err.status(f"running {spec.label} on {path.name}{who} ({len(t):,} samples)"):
        res = runner.run_filter(spec.name, spec.impl, inputs, spec.params_dict())
    try:
        plot_recording(t, res.q, spec.label, f"{path.name}{who}", out, inputs.gyr, inputs.acc,
                       None if rec.mag is None else inputs.mag, inputs.mag_valid, inputs.dt,
                       status=res.status, unit_q=unit_q, window=window,
                       time_text=f"s, {time_base_text(rec)}")
    except OSError as exc:
        raise KinefuseError(f"{out}: cannot write the plot ({exc.strerror or exc})") from None
    rejected = runner.rejected_count(res)
    print(f"{spec.label} on {path.name}{who}: {len(t):,} samples"
          + ("" if rejected is None else f", {rejected} rejected by the filter"), file=sys.stderr)
    print(str(out))
    return 0


def run(args) -> int:
    params = accuracy.parse_params(args.param)
    name = (args.filter or "").strip() or accuracy.default_filter_name()
    if name == "all":
        raise KinefuseError("plot takes one filter, not 'all'")
    _check_window_args(args)
    trial_file = resolve_trial(args.input)
    recording = trial_file.suffix.lower() not in broad.TRIAL_SUFFIXES
    impl = args.impl or ("f32" if recording else "ref")
    spec = accuracy.resolve(name, impl, params, impl_given=args.impl is not None)[0]
    if recording:
        return _plot_recording(args, spec, trial_file)
    if args.unit is not None:
        raise KinefuseError("--unit applies to .kfr unit recordings, not to BROAD trials")
    trial = broad.load_trial(trial_file)
    window = _window(args, np.asarray(trial.t, dtype=np.float64), "the trial")
    out = _out_path(args, trial.name, spec, trial_file)
    from rich.console import Console

    err = Console(stderr=True)
    with err.status(f"running {spec.label} on {trial.name} ({trial.n} samples)"):
        res = accuracy.estimate(spec, trial)
    q = np.asarray(res.q, dtype=np.float64)
    if q.shape != (trial.n, 4):
        raise KinefuseError(f"{spec.label} returned quaternions of shape {q.shape} for {trial.n} samples")
    from kinefuse.host.plots import plot_estimate

    try:
        plot_estimate(trial, q, spec.label, out, status=getattr(res, "status", None), window=window)
    except OSError as exc:
        raise KinefuseError(f"{out}: cannot write the plot ({exc.strerror or exc})") from None
    from kinefuse.host.metrics import score_trial

    s = score_trial(q, trial)
    if not np.isfinite(s["total"]):     # printed "RMSE total nan°" for a trial at rest throughout
        print(f"{spec.label} on {trial.name}: no movement phase with a reference to score "
              f"(the plot shows the whole trial)", file=sys.stderr)
    else:
        print(f"{spec.label} on {trial.name}: RMSE total {s['total']:.2f}°, heading "
              f"{s['heading']:.2f}°, inclination {s['inclination']:.2f}° (movement phases)",
              file=sys.stderr)
    print(str(out))
    return 0
