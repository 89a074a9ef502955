"""``kinefuse sil report``: every IMU filter through the model, host and QEMU loops on the
scenario set; Markdown + PNG report (errors vs ground truth, bit-exact table, cost table)."""
from __future__ import annotations

import argparse
import contextlib
import json
import math
from pathlib import Path

from kinefuse.host.errors import KinefuseError
from kinefuse.host import argtypes
from kinefuse.host.outputs import add_force_arg, check_output_dir, output_folder

# what a report writes into --out (report.write_markdown, report.write_png, the full JSON)
REPORT_FILES = ("sil_report.md", "sil_report.png", "sil_report.json")


def register(subparsers) -> None:
    p = subparsers.add_parser("sil", help="software/processor-in-the-loop harness")
    sub = p.add_subparsers(dest="sil_command", metavar="ACTION")
    r = sub.add_parser("report", help="run the scenario set through every loop; write Markdown + PNG")
    r.add_argument("--out", default="sil_report", help="output directory (default ./sil_report)")
    r.add_argument("--ci", action="store_true",
                   help="the CI subset: short (12 s) simulated scenarios, no BROAD trial")
    r.add_argument("--filters", default=None, help="comma-separated filters (default: every IMU filter)")
    r.add_argument("--scenarios", default=None, help="comma-separated simulator scenarios")
    r.add_argument("--seconds", type=float, default=None, help="keep only the first SECONDS of each scenario")
    r.add_argument("--broad-seconds", type=float, default=None,
                   help="keep only the first SECONDS of the BROAD trial (default: --seconds; 0: the whole trial)")
    r.add_argument("--broad", default=None,
                   help="BROAD trial file added to the set (default: first shared/bundled trial; 'none')")
    r.add_argument("--seed", type=argtypes.seed, default=1, help="simulator seed (default 1)")
    r.add_argument("--no-qemu", action="store_true", help="skip the Cortex-M loops")
    r.add_argument("--with-ref", action="store_true", help="also score the float64 reference (slow)")
    r.add_argument("--firmware", action="store_true",
                   help="also run the unit application: SIL (host build f32/q, pty) and PIL (QEMU M4F "
                        "f32/q, M0 q) against the unit model, every output bit (q: the raw Q quaternion)")
    r.add_argument("--pil-samples", type=int, default=None, metavar="N",
                   help="--firmware: PIL runs the first N samples of each case (default 300; 0: whole cases; "
                        "QEMU's UART streams a few hundred samples/s)")
    r.add_argument("--sil-samples", type=int, default=None, metavar="N",
                   help="--firmware: SIL runs the first N samples of each case (default 0: whole cases)")
    r.add_argument("--jobs", type=int, default=None,
                   help="--firmware: firmware loops run at a time (one unit each; default 1)")
    r.add_argument("--cost", default=None, metavar="JSON",
                   help="include a cost table from `kinefuse bench cost --json` output")
    r.add_argument("--json", action="store_true", help="one JSON object on stdout")
    add_force_arg(r, "an earlier report in --out")
    r.set_defaults(func=run_report)
    p.set_defaults(func=lambda args: (p.print_help(), 2)[1])


def run_report(args: argparse.Namespace) -> int:
    from kinefuse.hil_tests.harness import loops, report, scenarios
    from kinefuse.hil_tests.sim.segments import SpecError

    from kinefuse.host.bench.common import given as not_blank, name_list
    # given but empty (an unset shell variable) meant every filter / the whole scenario set /
    # the default BROAD trial
    name_list("--filters", args.filters, (), "madgwick,flagship")
    name_list("--scenarios", args.scenarios, (), "rest,constant_rotation")
    not_blank("--broad", args.broad, "a BROAD trial file or 'none'")
    not_blank("--cost", args.cost, "a `kinefuse bench cost --json` file")
    not_blank("--out", args.out, "an output folder")     # ("" wrote into the current folder)
    filters = [f.strip() for f in args.filters.split(",")] if args.filters is not None else loops.imu_filters()
    bad = [f for f in filters if f not in loops.imu_filters()]
    if bad:
        raise KinefuseError(f"unknown IMU filter {bad[0]!r} (available: {', '.join(loops.imu_filters())})")
    # a name given twice ran twice: every row repeated and the bit-exact count inflated
    for opt, given in (("--filters", filters), ("--scenarios", args.scenarios.split(",") if args.scenarios else [])):
        given = [g.strip() for g in given]
        twice = [g for k, g in enumerate(given) if g in given[:k]]
        if twice:
            raise KinefuseError(f"{opt} names {twice[0]} twice")
    if args.seconds is not None and not (math.isfinite(args.seconds) and args.seconds > 0):
        raise KinefuseError("--seconds must be positive and finite")
    if args.broad_seconds is not None and not (math.isfinite(args.broad_seconds) and args.broad_seconds >= 0):
        raise KinefuseError("--broad-seconds must be positive and finite, or 0 for the whole trial")
    # the options of the firmware loops were ignored without --firmware
    fw_only = [o for o, v in (("--pil-samples", args.pil_samples), ("--sil-samples", args.sil_samples),
                              ("--jobs", args.jobs)) if v is not None]
    if fw_only and not args.firmware:
        raise KinefuseError(f"{fw_only[0]} sets the firmware loops: add --firmware (or leave it out)")
    if (args.pil_samples is not None and args.pil_samples < 0) or (args.sil_samples or 0) < 0 \
            or (args.jobs is not None and args.jobs < 1):
        raise KinefuseError("--pil-samples and --sil-samples must be >= 0, --jobs >= 1")
    if args.no_qemu and args.pil_samples is not None:
        # the PIL loops run under QEMU: --no-qemu leaves them out and N went unused
        raise KinefuseError("--pil-samples sets the PIL loops (QEMU), which --no-qemu leaves out; "
                            "--sil-samples sets the SIL ones")
    broad = "none" if args.ci and args.broad is None else args.broad
    if broad == "none" and args.broad_seconds is not None:      # (was ignored)
        raise KinefuseError("--broad-seconds: this report has no BROAD trial "
                            + ("(--ci leaves it out; add --broad FILE)" if args.broad is None else "(--broad none)"))
    qemu = not args.no_qemu
    if qemu:
        from kinefuse.hil_tests.qemu import qemu_unavailable
        reason = qemu_unavailable()
        if reason:
            raise KinefuseError(f"{reason} (or pass --no-qemu)")
    if broad not in (None, "none"):     # before the scenarios are simulated, not after
        _check_broad_file(broad)
    cost = report.load_cost(args.cost) if args.cost is not None else []
    names = ([s.strip() for s in args.scenarios.split(",")] if args.scenarios is not None
             else list(scenarios.CI_SCENARIOS if args.ci else scenarios.FULL_SCENARIOS))
    seconds = args.seconds if args.seconds is not None else (scenarios.CI_SECONDS if args.ci else None)
    out = check_output_dir(args.out, args.force, REPORT_FILES)
    from kinefuse.host.bench.common import progress
    with output_folder(out) as out:
        with progress(not args.json) as bar:
            task = bar.add_task("simulating scenarios", total=None)
            try:
                # the CI subset's pieces include each scenario's event (scenarios.ci_case)
                cases = [scenarios.ci_case(n, seconds=seconds, seed=args.seed)
                         if args.ci and seconds is not None
                         else scenarios.sim_case(n, seed=args.seed, seconds=seconds) for n in names]
            except SpecError as exc:
                raise KinefuseError(str(exc)) from None
            if broad != "none":
                path = broad or scenarios.default_broad_trial()
                case = scenarios.broad_case(path)
                keep = seconds if args.broad_seconds is None else args.broad_seconds
                cases.append(case.head(int(keep * case.rate_hz)) if keep else case)
            empty = [c for c in cases if c.n == 0]
            if empty:       # shorter than one sample: every loop would fail on an empty input
                opt = "--broad-seconds" if empty[0].source == "broad" and args.broad_seconds is not None else "--seconds"
                raise KinefuseError(f"{opt} keeps no sample of {empty[0].name} ({empty[0].rate_hz:g} Hz): "
                                    f"give at least {math.ceil(1e4 / empty[0].rate_hz) / 1e4:g} s")
            if args.firmware:
                from kinefuse.hil_tests.harness.firmware import firmware_missing
                if firmware_missing():
                    raise KinefuseError(firmware_missing())
            rep = report.build_report(cases, filters, with_ref=args.with_ref, qemu=qemu,
                                      firmware=args.firmware, pil_samples=args.pil_samples,
                                      sil_samples=args.sil_samples or 0, jobs=args.jobs or 1,
                                      progress=lambda s: bar.update(task, description=s))
        rep.cost = cost
        # inside output_folder: a folder this run created goes again if the writes fail
        md, png = _write_report(rep, out)
    if args.json:
        print(json.dumps({"markdown": str(md), "png": str(png) if png else None,
                          "all_bitexact": rep.all_bitexact, "seconds": rep.seconds,
                          "bitexact": rep.bitexact}, default=float))
    else:
        n_bad = sum(1 for r in rep.bitexact if r["mismatch"] or r["error"])
        print(f"wrote {md}" + (f" and {png}" if png else ""))
        print(f"bit-exact: {len(rep.bitexact) - n_bad} of {len(rep.bitexact)} loop comparisons identical"
              f" ({report.run_time_text(rep.seconds)})")
        for r in rep.bitexact:
            if r["error"]:
                print(f"ERROR {r['filter']} {r['system']} {r['loop']} on {r['case']}: {r['error']}")
            elif r["mismatch"]:
                from kinefuse.hil_tests.harness.compare import Mismatch
                print("MISMATCH " + f"{r['filter']} on {r['case']}: " + Mismatch(**r["mismatch"]).message())
    return 0 if rep.all_bitexact else 1


def _write_report(rep, out: Path):
    """The report's files, staged (host/outputs.py): written under temporary names and renamed
    when all are complete, so a failed write (full disk, interrupt) leaves the folder as it was,
    never a new Markdown next to an earlier run's PNG or JSON."""
    from kinefuse.hil_tests.harness import report
    from kinefuse.host.outputs import staged
    final = {n: out / n for n in REPORT_FILES}
    try:
        with staged() as st:
            # write_png writes nothing (None) when no f32/q error was scored: ask for its
            # temporary name only when there is a figure, so there is always a file to rename
            png = None
            if any(k[2] in ("f32", "q") for k in rep.errors):
                png = report.write_png(rep, out, path=st.path(final[REPORT_FILES[1]]))
            report.write_markdown(rep, out, REPORT_FILES[1] if png else None,
                                  path=st.path(final[REPORT_FILES[0]]))
            st.path(final[REPORT_FILES[2]]).write_text(json.dumps(rep.as_dict(), default=float))
    except OSError as exc:
        raise KinefuseError(f"cannot write the report in {out}: {exc.strerror or exc}") from None
    if png is None:
        with contextlib.suppress(FileNotFoundError, IsADirectoryError):
            final[REPORT_FILES[1]].unlink()     # an earlier run's figure, of other numbers (--force)
    return final[REPORT_FILES[0]], (final[REPORT_FILES[1]] if png else None)


def _check_broad_file(path: str) -> None:
    p = Path(path)
    if not p.exists():
        raise KinefuseError(f"BROAD trial {path} not found")
    if p.is_dir():
        raise KinefuseError(f"--broad {path} is a folder: give one trial file (.mat or .npz)")
