"""``kinefuse demo``: kinefuse filters vs competitors on the bundled BROAD excerpt, in a minute.

Needs no network and no shared data folder: the excerpt ships with kinefuse.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

from kinefuse.host import broad, competitors, metrics
from kinefuse.host.bench import accuracy
from kinefuse.host.errors import KinefuseError
from kinefuse.host.console import print_table

DEMO_COMPETITORS = ("vqf", "imufusion")
PLOT_TRIAL = "32_disturbed_attached_magnet_1cm"   # shows magnetic disturbance handling


def register(sub) -> None:
    p = sub.add_parser(
        "demo", help="first run: filters vs VQF/Fusion on the bundled BROAD excerpt",
        description="Run the kinefuse filters (every available implementation) and, if "
                    "installed, VQF and x-io Fusion on the BROAD excerpt bundled with kinefuse; "
                    "print their accuracy against the optical reference and write a plot.")
    p.add_argument("--out", default="kinefuse-demo", metavar="DIR",
                   help="folder for the plot and the JSON results, rewritten on every run; "
                        "the plot an earlier run wrote of another estimator is removed, no "
                        "other file is touched (default: ./kinefuse-demo)")
    p.add_argument("--budget", type=float, default=40.0, metavar="S",
                   help="start no new estimator after this many seconds; started ones finish "
                        "(default: 40; inf: no budget)")
    p.add_argument("--jobs", type=int, metavar="N", help="worker processes (default: CPUs)")
    p.set_defaults(func=run)


def _specs(err) -> tuple[list[accuracy.Spec], list[accuracy.Spec]]:
    """Kinefuse specs: (float32 C, then fixed point and Python references), default first."""
    try:
        runner = accuracy.load_runner()
        names = accuracy.runner_filter_names()
        default = runner.default_filter()
    except KinefuseError as exc:
        err.print(f"[yellow]note:[/yellow] {exc}")
        return [], []
    if default in names:
        names.remove(default)
        names.insert(0, default)
    fast = [accuracy.Spec("kinefuse", n, "f32") for n in names]
    slow = ([accuracy.Spec("kinefuse", n, "q") for n in names]
            + [accuracy.Spec("kinefuse", n, "ref") for n in names])
    return fast, slow


def _short(trial_name: str) -> str:
    """'32_disturbed_attached_magnet_1cm' -> '32 attached magnet 1cm' (column headers)."""
    num, _, rest = trial_name.partition("_")
    for prefix in ("undisturbed_", "disturbed_"):
        rest = rest.removeprefix(prefix)
    return f"{num} {rest.replace('_', ' ')}"


def run(args) -> int:
    from rich.console import Console
    from rich.table import Table

    out_dir = Path(args.out)
    if not args.budget > 0:          # NaN too: it compares false, and every estimator ran
        raise KinefuseError(f"--budget must be a positive number of seconds (inf: no budget), "
                            f"got {args.budget:g}")
    if args.jobs is not None and args.jobs < 1:
        raise KinefuseError("--jobs must be at least 1")
    err = Console(stderr=True)
    files = broad.bundled_trials()
    if not files:
        raise KinefuseError(f"the bundled BROAD excerpt is missing from {broad.EXCERPT_DIR}; "
                            f"reinstall kinefuse")
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise KinefuseError(f"{out_dir}: cannot create the output folder ({exc.strerror})") from None

    fast, slow = _specs(err)
    comps = [c for c in DEMO_COMPETITORS if competitors.available(c)]
    missing = [c for c in DEMO_COMPETITORS if c not in comps]
    # float32 C first (fast), competitors, then fixed point (compiled on first use) and the
    # Python references (slow) as time allows
    specs = fast[:1] + [accuracy.Spec("competitor", c) for c in comps] + fast[1:] + slow
    if not specs:
        raise KinefuseError("nothing to run: no kinefuse filters and neither vqf nor imufusion "
                            "is installed (pip install 'kinefuse[bench]')")
    err.print(f"kinefuse demo: {len(files)} trials of the bundled BROAD excerpt "
              f"(Laidig et al. 2021, CC BY 4.0), {len(specs)} estimators")
    if missing:
        err.print(f"[yellow]note:[/yellow] {', '.join(missing)} not installed, not compared "
                  f"(pip install 'kinefuse[bench]')")
    res = accuracy.evaluate(files, specs, jobs=args.jobs, tolerate_failures=True,
                            budget_s=args.budget)
    for label, why in res.failures.items():
        err.print(f"[yellow]not available:[/yellow] {label}: {why}")
    if res.skipped:
        err.print(f"[yellow]skipped (time budget {args.budget:g} s):[/yellow] "
                  f"{', '.join(res.skipped)}; run them with kinefuse bench accuracy")
    if not res.specs:
        raise KinefuseError("every estimator failed; see the messages above")

    console = Console()
    table = Table(title="[bold]Orientation error against the optical reference[/bold] "
                        "(bundled BROAD excerpt)", title_justify="left",
                  caption="RMSE in degrees over the movement phases: per trial the total error, "
                          "then the mean over trials of total (T), heading (H) and inclination (I) "
                          "error.  Excerpt scores are not comparable with full-trial BROAD figures.",
                  caption_justify="left")
    table.add_column("estimator", no_wrap=True)
    for t in res.trial_names:
        table.add_column(t.partition("_")[0], justify="right")
    for kind in "THI":
        table.add_column(f"mean {kind}", justify="right")
    for spec in res.specs:
        row = [f"[bold]{spec.label}[/bold]" if spec.kind == "kinefuse" else spec.label]
        row += [_fmt(res.scores[spec.label][t]["total"]) for t in res.trial_names]
        mean = res.mean(spec.label)
        row += [_fmt(mean[k]) for k in metrics.KINDS]
        table.add_row(*row)
    print_table(table, console)
    console.print("trials: " + "; ".join(_short(t) for t in res.trial_names))
    for spec in res.specs:      # (the competitors' scores came without the settings they ran with)
        if spec.kind == "competitor":
            console.print(f"{spec.name}: {competitors.get(spec.name).description}")

    payload = {"data": "bundled BROAD excerpt", "trials": res.trial_names,
               "estimators": {s.label: accuracy._spec_block(res, s) for s in res.specs},
               "not_available": res.failures, "skipped": res.skipped,
               "units": "deg: RMSE of the total, heading and inclination error over each "
                        "trial's movement phases; mean = over trials"}
    json_path = out_dir / "accuracy.json"
    plot_spec = next((s for s in res.specs if s.kind == "kinefuse"), res.specs[0])
    earlier = _earlier_plot(json_path)     # read before the JSON that names it is rewritten
    plot_trial, plot_path = _plot_target(plot_spec, out_dir)
    payload["plot"] = plot_path.name        # what the next run may remove
    try:
        json_path.write_text(json.dumps(payload, indent=2, allow_nan=False) + "\n")
        if earlier is not None and earlier != plot_path.name:
            # an earlier run plotted another estimator (one failed or was not installed then):
            # its PNG would pass for this run's plot.  Only the file its JSON names is removed.
            stale = out_dir / earlier
            if stale.is_symlink() or stale.is_file():
                stale.unlink()
        _plot(plot_spec, plot_trial, plot_path, err)
    except OSError as exc:
        raise KinefuseError(f"{out_dir}: cannot write results ({exc.strerror or exc})") from None

    console.print(f"\nwrote [bold]{plot_path}[/bold]  ({plot_spec.label} on {plot_trial.name})")
    console.print(f"wrote [bold]{json_path}[/bold]")
    console.print("next: [bold]kinefuse bench accuracy --data DIR --compare vqf,imufusion[/bold] "
                  "on the full BROAD trials; [bold]kinefuse plot --input TRIAL --filter NAME[/bold]")
    return 0


def _earlier_plot(json_path: Path) -> str | None:
    """The PNG an earlier demo wrote into this folder: the plain ``*.png`` name its
    ``accuracy.json`` records under ``"plot"`` (None when there is no such JSON, it is not a
    demo's, or it predates the record).  Nothing else in the folder is the demo's to remove."""
    try:
        earlier = json.loads(json_path.read_text())
    except (OSError, ValueError):
        return None
    if not isinstance(earlier, dict) or earlier.get("data") != "bundled BROAD excerpt":
        return None
    name = earlier.get("plot")
    if not isinstance(name, str) or Path(name).name != name or not name.lower().endswith(".png"):
        return None
    return name


def _plot_target(spec: accuracy.Spec, out_dir: Path):
    """(the trial the demo plots, the PNG it writes for ``spec``)."""
    trial_file = next((f for f in broad.bundled_trials() if f.stem == PLOT_TRIAL),
                      broad.bundled_trials()[0])
    trial = broad.load_trial(trial_file)
    safe = spec.label.replace(" (", "_").replace(")", "").replace(" ", "_")
    return trial, out_dir / f"{trial.name}_{safe}.png"


def _plot(spec: accuracy.Spec, trial, path: Path, err) -> None:
    from kinefuse.host.plots import plot_estimate

    with err.status(f"plotting {spec.label} on {trial.name}"):
        res = accuracy.estimate(spec, trial)
        plot_estimate(trial, res.q, spec.label, path, status=getattr(res, "status", None))


def _fmt(x: float) -> str:
    return "n/a" if not math.isfinite(x) else f"{x:.2f}"
