"""``kinefuse plot``: an orientation estimate against the BROAD optical reference, as a PNG."""
from __future__ import annotations

import sys
from pathlib import Path

from kinefuse.host import broad
from kinefuse.host.bench import accuracy
from kinefuse.host.errors import KinefuseError
from kinefuse.host.outputs import add_force_arg, check_new_file


def register(sub) -> None:
    p = sub.add_parser(
        "plot", help="plot a filter's orientation against the BROAD reference (PNG)",
        description="Run a filter on one trial and plot estimate vs optical reference as Euler "
                    "angles (ZYX yaw-pitch-roll of sensor->ENU), the total/heading/inclination "
                    "error over time, the movement phases and the filter's status flags.")
    p.add_argument("--input", required=True, metavar="TRIAL",
                   help="trial file (.mat/.npz), or a trial name or number such as 32 looked "
                        "up in the default data (shared BROAD folder or bundled excerpt)")
    p.add_argument("--filter", metavar="NAME",
                   help="kinefuse filter or competitor (vqf, imufusion, ...); default: the "
                        "default kinefuse filter")
    p.add_argument("--impl", default="ref", choices=accuracy.IMPLS,
                   help="implementation of a kinefuse filter (default: ref)")
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


def run(args) -> int:
    params = accuracy.parse_params(args.param)
    name = (args.filter or "").strip() or accuracy.default_filter_name()
    if name == "all":
        raise KinefuseError("plot takes one filter, not 'all'")
    spec = accuracy.resolve(name, args.impl, params, impl_given=True)[0]
    trial_file = resolve_trial(args.input)
    trial = broad.load_trial(trial_file)
    window = None
    if args.start is not None or args.end is not None:
        start = 0.0 if args.start is None else args.start
        end = trial.duration_s if args.end is None else args.end
        if start >= trial.duration_s:
            raise KinefuseError(f"--start {start}: the trial is only {trial.duration_s:.1f} s long")
        if not 0.0 <= start < end:
            raise KinefuseError(f"--start/--end: need 0 <= start < end, got {start} and {end}")
        window = (start, end)
    safe = spec.label.replace(" (", "_").replace(")", "").replace(" ", "_")
    out = Path(args.out) if args.out else Path(f"{trial.name}_{safe}.png")
    if out.suffix.lower() != ".png":
        raise KinefuseError(f"--out {out}: the plot is written as PNG, name it *.png")
    check_new_file(out, args.force, inputs=[trial_file])
    from rich.console import Console

    err = Console(stderr=True)
    with err.status(f"running {spec.label} on {trial.name} ({trial.n} samples)"):
        res = accuracy.estimate(spec, trial)
    import numpy as np

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
    print(f"{spec.label} on {trial.name}: RMSE total {s['total']:.2f}°, heading "
          f"{s['heading']:.2f}°, inclination {s['inclination']:.2f}° (movement phases)",
          file=sys.stderr)
    print(str(out))
    return 0
