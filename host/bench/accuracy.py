"""``kinefuse bench accuracy``: BROAD orientation accuracy of kinefuse filters and competitors.

Scores are the published BROAD metric (see :mod:`kinefuse.host.metrics`): RMSE in degrees of the
total, heading and inclination error over the movement phases, mean over trials.
"""
from __future__ import annotations

import concurrent.futures as cf
import contextlib
import dataclasses
import functools
import json
import math
import multiprocessing
import os
import sys
import time
from pathlib import Path

from kinefuse.host import broad, competitors, metrics
from kinefuse.host.errors import KinefuseError
from kinefuse.host.console import print_table

IMPLS = ("ref", "f32", "q")


# ------------------------------------------------------------------------------------------------
# What to run

@dataclasses.dataclass(frozen=True)
class Spec:
    """One estimator to score: a kinefuse filter (with an implementation) or a competitor."""

    kind: str                                 # "kinefuse" or "competitor"
    name: str
    impl: str = "ref"
    params: tuple[tuple[str, float | str], ...] = ()   # str: a choice label (mode=6d)

    @property
    def label(self) -> str:
        return f"{self.name} ({self.impl})" if self.kind == "kinefuse" else self.name

    def params_dict(self) -> dict[str, float] | None:
        return dict(self.params) or None


def heading_free(spec: Spec) -> bool:
    """True when ``spec`` ignores the magnetometer (a 6D competitor, or a kinefuse filter run
    with ``mode=6d``): its heading is not referenced to north, so only its inclination means
    anything against BROAD's north-aligned reference."""
    if spec.kind == "competitor":
        return not competitors.get(spec.name).nine_d
    check = getattr(load_runner(), "check_params", None)
    if check is None:
        return False
    return check(spec.name, dict(spec.params)).get("mode", 1.0) < 0.5


def load_runner():
    """The lead's ``kinefuse.host.runner`` module, or raise KinefuseError saying why not."""
    try:
        from kinefuse.host import runner
    except ImportError as exc:
        raise KinefuseError(f"kinefuse filters are not available ({exc}); "
                            f"competitors still work, e.g. --filter vqf") from None
    return runner


def runner_filter_names() -> list[str]:
    """Registered kinefuse filters that take IMU samples (what a BROAD trial provides)."""
    try:
        runner = load_runner()
    except KinefuseError:
        return []
    names = getattr(runner, "imu_filter_names", runner.filter_names)
    return list(names())


def parse_params(items: list[str] | None) -> tuple[tuple[str, float | str], ...]:
    """``["k=v", ...]`` -> ((k, v), ...); one-line error for a malformed item, a name given twice
    or a non-finite value (:func:`kinefuse.host.paramargs.parse_assignments`).

    A value that is not a number stays text: a kinefuse filter resolves its choices' labels
    (``mode=6d``) and checks every value in :func:`resolve`; a competitor takes numbers only.
    """
    from kinefuse.host.paramargs import parse_assignments
    return tuple(parse_assignments(items, "--param", form="KEY=NUMBER").items())


def _check_kinefuse_params(name: str, params: tuple) -> None:
    """One-line error now (not in a worker later) for a value filter ``name`` refuses."""
    check = getattr(load_runner(), "check_params", None)
    if check is not None:
        check(name, dict(params))
    else:                       # a runner without declarations: numbers only
        _numbers_only(params)


def _numbers_only(params: tuple) -> None:
    for k, v in params:
        if isinstance(v, str):
            raise KinefuseError(f"--param {k}: {v!r} is not a number")


def resolve(name: str, impl: str, params: tuple = (), *, impl_given: bool = False) -> list[Spec]:
    """Specs for a ``--filter``/``--compare`` name ("all" = every registered kinefuse filter).
    ``impl_given``: the user chose ``impl`` for this very filter, so a competitor (which runs its
    own implementation) refuses any but ``ref`` instead of ignoring it."""
    name = name.strip()
    if impl not in IMPLS:
        raise KinefuseError(f"unknown implementation {impl!r} (choose from {', '.join(IMPLS)})")
    if name == "all":
        load_runner()
        names = runner_filter_names()
        if not names:
            raise KinefuseError("no kinefuse filters are registered yet")
        for n in names:
            _check_kinefuse_params(n, params)
        return [Spec("kinefuse", n, impl, params) for n in names]
    if competitors.is_competitor(name):
        if impl_given and impl != "ref":
            raise KinefuseError(f"--impl {impl}: {name} is a competitor and runs its own "
                                f"implementation; --impl chooses between kinefuse's (ref, f32, q)")
        comp = competitors.require(name)
        unknown = sorted({k for k, _ in params} - set(comp.params))
        if unknown:
            raise KinefuseError(f"{name}: unknown parameter {', '.join(unknown)} "
                                f"(known: {', '.join(comp.params) or 'none'})")
        _numbers_only(params)
        return [Spec("competitor", name, "ref", params)]
    kinefuse_names = runner_filter_names()
    if name in kinefuse_names:
        _check_kinefuse_params(name, params)
        return [Spec("kinefuse", name, impl, params)]
    known = kinefuse_names + competitors.competitor_names()
    raise KinefuseError(f"unknown filter {name!r} (known: {', '.join(known)}, all)")


def default_filter_name() -> str:
    runner = load_runner()
    return runner.default_filter()


# ------------------------------------------------------------------------------------------------
# Running (in worker processes when there is more than one task)

@functools.lru_cache(maxsize=16)
def _cached_trial(path: str):
    return broad.load_trial(path)


def estimate(spec: Spec, trial):
    """Run ``spec`` on ``trial``; returns an object with ``.q`` (N,4) and ``.status`` (dict)."""
    if spec.kind == "competitor":
        return competitors.run_competitor(spec.name, trial, spec.params_dict())
    runner = load_runner()
    res = runner.run_filter(spec.name, spec.impl, trial, spec.params_dict())
    return res


_IN_WORKER = False


def _worker_init() -> None:
    global _IN_WORKER
    _IN_WORKER = True


@contextlib.contextmanager
def _silenced_fds():
    """In worker processes: drop what filters print (e.g. C compiler output on first build)
    so that it does not tear through the progress bar; errors still arrive as exceptions."""
    if not _IN_WORKER:
        yield
        return
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, 1)
        os.dup2(devnull, 2)
        yield
    finally:
        sys.stdout.flush()
        sys.stderr.flush()
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in saved + [devnull]:
            os.close(fd)


def _task(path: str, spec: Spec) -> tuple[str, str | None, dict[str, float], bool]:
    """Score one estimator on one trial: (trial name, group, score, produced NaN)."""
    import numpy as np

    trial = _cached_trial(path)
    try:
        with _silenced_fds():
            res = estimate(spec, trial)
    except KinefuseError as exc:
        raise KinefuseError(f"{spec.label} on {trial.name}: {exc}") from None
    except Exception as exc:  # a bug in a filter: keep which filter and trial it was
        raise RuntimeError(f"{spec.label} on {trial.name}: {type(exc).__name__}: {exc}") from exc
    q = np.asarray(res.q, dtype=np.float64)
    if q.shape != (trial.n, 4):
        raise KinefuseError(f"{spec.label} returned quaternions of shape {q.shape} "
                            f"for {trial.name} with {trial.n} samples")
    nan = bool(np.isnan(q).any())
    return trial.name, trial.group(), metrics.score_trial(q, trial), nan


@dataclasses.dataclass
class Results:
    """scores[spec label][trial name] = {"total", "heading", "inclination"} (degrees)."""

    specs: list[Spec]
    trial_names: list[str]
    groups: dict[str, str | None]
    scores: dict[str, dict[str, dict[str, float]]]
    failures: dict[str, str]                 # spec label -> first error message (tolerant mode)
    skipped: list[str]                       # spec labels not run within the time budget
    seconds: float

    def mean(self, label: str) -> dict[str, float]:
        return metrics.mean_score(self.scores[label][t] for t in self.trial_names)

    def group_means(self, label: str) -> dict[str, dict[str, float]]:
        return metrics.group_scores(self.scores[label], self.groups)


def default_jobs(n_tasks: int) -> int:
    return max(1, min(os.cpu_count() or 1, n_tasks))


def evaluate(paths: list[Path], specs: list[Spec], jobs: int | None = None,
             tolerate_failures: bool = False, quiet: bool = False,
             budget_s: float | None = None) -> Results:
    """Score every spec on every trial file, in parallel processes when ``jobs`` > 1.

    Tasks run spec by spec, in the order given.  With ``tolerate_failures`` a spec that fails is
    dropped and reported in ``failures`` (the demo uses this to skip implementations that are
    not available); otherwise the first failure is raised.  With ``budget_s``, specs whose
    trials have not all started within that many seconds are dropped and listed in ``skipped``.
    """
    paths = [Path(p) for p in paths]
    tasks = [(str(p), s) for s in specs for p in paths]
    jobs = default_jobs(len(tasks)) if jobs is None else max(1, jobs)
    scores: dict[str, dict[str, dict[str, float]]] = {s.label: {} for s in specs}
    groups: dict[str, str | None] = {}
    order: dict[str, int] = {}
    failures: dict[str, str] = {}
    skipped: set[str] = set()
    nan_warned: set[tuple[str, str]] = set()
    t0 = time.perf_counter()

    def over_budget() -> bool:
        # the first estimator always runs, so that there is something to show
        return (budget_s is not None and time.perf_counter() - t0 > budget_s
                and any(len(v) == len(paths) for v in scores.values()))

    def record(spec: Spec, path: str, outcome) -> None:
        name, group, score, nan = outcome
        order.setdefault(name, paths.index(Path(path)))
        groups[name] = group
        scores[spec.label][name] = score
        if nan and (spec.label, name) not in nan_warned:
            nan_warned.add((spec.label, name))
            _warn(f"{spec.label} produced NaN quaternions on {name}; its score there is NaN")

    def failed(spec: Spec, exc: BaseException) -> None:
        if not tolerate_failures:
            raise exc
        failures.setdefault(spec.label, str(exc).splitlines()[0] if str(exc) else type(exc).__name__)

    pool = None
    if jobs > 1 and len(tasks) > 1:
        # Workers are forked (where available) before the progress bar starts its thread; fork
        # also spares re-importing __main__ and keeps the parent's filter registry.
        method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
        pool = cf.ProcessPoolExecutor(max_workers=min(jobs, len(tasks)),
                                      mp_context=multiprocessing.get_context(method),
                                      initializer=_worker_init)
    try:
        futures = {pool.submit(_task, path, spec): (path, spec) for path, spec in tasks} if pool else {}
        with _progress(quiet) as progress:
            bar = progress.add_task("scoring", total=len(tasks)) if progress else None
            if pool is None:
                for path, spec in tasks:
                    if spec.label not in failures and spec.label not in skipped:
                        if over_budget() and not scores[spec.label]:
                            skipped.add(spec.label)
                        else:
                            _describe(progress, bar, spec, path)
                            try:
                                record(spec, path, _task(path, spec))
                            except Exception as exc:  # noqa: BLE001 - failed() decides
                                failed(spec, exc)
                    _advance(progress, bar)
            else:
                for fut in cf.as_completed(futures):
                    path, spec = futures[fut]
                    if fut.cancelled():
                        skipped.add(spec.label)
                    else:
                        _describe(progress, bar, spec, path)
                        try:
                            record(spec, path, fut.result())
                        except Exception as exc:  # noqa: BLE001 - failed() decides
                            failed(spec, exc)
                    if over_budget():  # let started specs finish, drop the others
                        started = {sp.label for f, (_, sp) in futures.items()
                                   if f.running() or (f.done() and not f.cancelled())}
                        for other, (_, other_spec) in futures.items():
                            if other_spec.label not in started and other.cancel():
                                skipped.add(other_spec.label)
                    _advance(progress, bar)
    finally:
        if pool is not None:
            pool.shutdown(wait=True, cancel_futures=True)
    dropped = set(failures) | skipped
    for label in dropped:
        scores.pop(label, None)
    trial_names = sorted(order, key=order.get)
    return Results([s for s in specs if s.label not in dropped], trial_names, groups, scores,
                   failures, [s.label for s in specs if s.label in skipped and s.label not in failures],
                   time.perf_counter() - t0)


def _warn(msg: str) -> None:
    print(f"kinefuse: warning: {msg}", file=sys.stderr)


class _NoProgress:
    def __enter__(self):
        return None

    def __exit__(self, *exc):
        return False


def _progress(quiet: bool):
    if quiet:
        return _NoProgress()
    from rich.console import Console
    from rich.progress import (BarColumn, MofNCompleteColumn, Progress, SpinnerColumn,
                               TextColumn, TimeElapsedColumn)

    return Progress(SpinnerColumn(), TextColumn("{task.description}"), BarColumn(),
                    MofNCompleteColumn(), TimeElapsedColumn(),
                    console=Console(stderr=True), transient=True,
                    disable=not sys.stderr.isatty())


def _describe(progress, bar, spec: Spec, path: str) -> None:
    if progress is not None:
        progress.update(bar, description=f"{spec.label} · {Path(path).stem[:28]}")


def _advance(progress, bar) -> None:
    if progress is not None:
        progress.advance(bar)


# ------------------------------------------------------------------------------------------------
# Output

def _num(x: float) -> float | None:
    return None if x is None or not math.isfinite(x) else float(x)


def _block(results: Results, label: str) -> dict:
    # (the group means, which the tables and the README's per-group figures give, were missing)
    return {"trials": {t: {k: _num(results.scores[label][t][k]) for k in metrics.KINDS}
                       for t in results.trial_names},
            "groups": {g: {k: _num(v) for k, v in sc.items()}
                       for g, sc in results.group_means(label).items()},
            "mean": {k: _num(v) for k, v in results.mean(label).items()}}


def _spec_block(results: Results, spec: Spec) -> dict:
    """:func:`_block` plus what was run: parameters, a competitor's settings, 6D."""
    out = _block(results, spec.label)
    check = getattr(load_runner(), "check_params", None) if spec.kind == "kinefuse" else None
    if check is not None:       # every parameter the filter ran with, defaults included
        out["params"] = check(spec.name, dict(spec.params))
    elif spec.params:
        out["params"] = dict(spec.params)
    if spec.kind == "competitor":
        comp = competitors.get(spec.name)
        out["settings"] = comp.description
        out["params"] = {**comp.params, **dict(spec.params)}
    if heading_free(spec):
        out["heading_referenced"] = False   # 6D: only the inclination is meaningful
    return out


def to_json(results: Results, filter_arg: str, impl: str, main: list[Spec],
            compare: list[Spec]) -> dict:
    """The ``--json`` object (NaN scores become null)."""
    if filter_arg == "all":
        out = {"filter": "all", "impl": impl,
               "filters": {s.name: _spec_block(results, s) for s in main}}
    else:
        out = {"filter": main[0].name, "impl": impl, **_spec_block(results, main[0])}
    if compare:
        out["compare"] = {s.name: _spec_block(results, s) for s in compare}
    out["units"] = ("deg: RMSE of the total, heading and inclination error over each trial's "
                    "movement phases; mean = over trials")
    return out


def _cell(score: dict[str, float]) -> str:
    def f(x):
        return "n/a" if not math.isfinite(x) else f"{x:.2f}"
    return f"{f(score['total'])} / {f(score['heading'])} / {f(score['inclination'])}"


def print_tables(results: Results, console=None) -> None:
    """One table per BROAD group (trials and group mean) and a summary of group means."""
    from rich.console import Console
    from rich.table import Table

    labels = [s.label for s in results.specs]
    console = console if console is not None else Console()   # print_table widens per table
    by_group: dict[str | None, list[str]] = {}
    for t in results.trial_names:
        by_group.setdefault(results.groups.get(t), []).append(t)
    ordered = [g for g in broad.GROUP_TITLES if g in by_group] + ([None] if None in by_group else [])
    caption = "RMSE in degrees over the movement phases: total / heading / inclination"
    for g in ordered:
        title = broad.GROUP_TITLES.get(g, "other trials") if g else "other trials"
        table = Table(title=f"[bold]{title}[/bold]", title_justify="left")
        table.add_column("trial", no_wrap=True)
        for lab in labels:
            table.add_column(lab, justify="right", no_wrap=True)
        for t in by_group[g]:
            table.add_row(t, *[_cell(results.scores[lab][t]) for lab in labels])
        if len(by_group[g]) > 1:
            table.add_row("[bold]group mean[/bold]",
                          *[f"[bold]{_cell(metrics.mean_score(results.scores[lab][t] for t in by_group[g]))}[/bold]"
                            for lab in labels])
        print_table(table, console)
    summary = Table(title="[bold]summary (mean of trials)[/bold]", title_justify="left",
                    caption=caption, caption_justify="left")
    summary.add_column("group", no_wrap=True)
    for lab in labels:
        summary.add_column(lab, justify="right", no_wrap=True)
    for g in ordered:
        if g is None:
            continue
        ts = by_group[g]
        summary.add_row(f"{broad.GROUP_TITLES[g]} ({len(ts)})",
                        *[_cell(metrics.mean_score(results.scores[lab][t] for t in ts)) for lab in labels])
    summary.add_row(f"[bold]all trials ({len(results.trial_names)})[/bold]",
                    *[f"[bold]{_cell(results.mean(lab))}[/bold]" for lab in labels])
    print_table(summary, console)
    # (kinefuse filters run with mode=6d were scored for heading without a word)
    not_north = [s.label for s in results.specs if heading_free(s)]
    if not_north:
        console.print(f"note: {', '.join(not_north)} estimate heading without a magnetometer; "
                      f"only their inclination is meaningful.")
    comps = [s for s in results.specs if s.kind == "competitor"]
    for s in comps:     # the settings the competitors ran with, next to their scores
        set_ = ", ".join(f"{k}={v:g}" for k, v in {**competitors.get(s.name).params,
                                                   **dict(s.params)}.items())
        console.print(f"{s.name}: {competitors.get(s.name).description} ({set_}); same "
                      f"samples and rate as ours")


# ------------------------------------------------------------------------------------------------
# Command

def resolve_data(data: str | None) -> tuple[list[Path], str]:
    if data:
        files = broad.find_trials(data)
        return files, f"{len(files)} trial file(s) from {data}"
    files, where = broad.default_data()
    if not files:
        raise KinefuseError("no trials found: neither the shared BROAD folder nor the bundled "
                            "excerpt is present; pass --data")
    return files, f"{len(files)} {where} (default; choose with --data)"


def register_bench(sub) -> None:
    p = sub.add_parser(
        "accuracy", help="orientation accuracy on BROAD (RMSE total/heading/inclination, °)",
        description="Score orientation filters on BROAD trials with the published BROAD metric: "
                    "RMSE in degrees of the total, heading and inclination error over the "
                    "movement phases, per trial, per group and as the mean over trials.")
    p.add_argument("--data", metavar="DIR|FILE",
                   help="BROAD folder or trial file (.mat, or an excerpt .npz); default: "
                        "$KINEFUSE_BROAD or the shared BROAD folder if present, else the "
                        "bundled excerpt")
    p.add_argument("--filter", metavar="NAME",
                   help="kinefuse filter, a competitor (vqf, imufusion, ahrs-madgwick, ...) or "
                        "'all' (every kinefuse filter); default: the default kinefuse filter")
    p.add_argument("--impl", default="ref", choices=IMPLS,
                   help="implementation of kinefuse filters: Python reference, float32 C, "
                        "fixed-point C (default: ref)")
    p.add_argument("--param", action="append", metavar="KEY=VALUE",
                   help="filter parameter override, repeatable")
    p.add_argument("--compare", metavar="A,B",
                   help=f"also score these, side by side ({', '.join(competitors.competitor_names())})")
    p.add_argument("--jobs", type=int, metavar="N",
                   help="worker processes (default: number of CPUs)")
    p.add_argument("--json", action="store_true", help="print one JSON object on stdout")
    p.set_defaults(func=run)


def run(args) -> int:
    if args.jobs is not None and args.jobs < 1:
        raise KinefuseError("--jobs must be at least 1")
    from kinefuse.host.bench.common import given
    # given but empty (an unset shell variable) silently meant the default filter or data
    given("--filter", args.filter, "a filter name, a competitor or 'all'")
    given("--data", args.data, "a BROAD folder or trial file")
    params = parse_params(args.param)
    filter_arg = args.filter.strip() if args.filter is not None else default_filter_name()
    main = resolve(filter_arg, args.impl, params, impl_given=True)
    compare: list[Spec] = []
    compare_names = [n.strip() for n in (args.compare or "").split(",") if n.strip()]
    if args.compare is not None and not compare_names:
        raise KinefuseError(f"--compare {args.compare!r}: names no filter (comma-separated names, e.g. "
                            f"vqf,imufusion)")
    for name in compare_names:
        for spec in resolve(name, args.impl):
            if spec.label not in {s.label for s in main + compare}:
                compare.append(spec)
    files, where = resolve_data(args.data)
    print(f"data: {where}", file=sys.stderr)
    results = evaluate(files, main + compare, jobs=args.jobs)
    print(f"scored {len(results.trial_names)} trial(s) x {len(main + compare)} estimator(s) "
          f"in {results.seconds:.1f} s", file=sys.stderr)
    # (said only for the default data: --data naming the excerpt got the cut trials' scores
    # without a word; a trial .npz is always an excerpt)
    if any(Path(f).suffix.lower() == ".npz" for f in files):
        print("note: excerpt scores are not comparable with published full-trial BROAD figures",
              file=sys.stderr)
    if args.json:
        print(json.dumps(to_json(results, filter_arg, args.impl, main, compare), allow_nan=False))
    else:
        print_tables(results)
    return 0
