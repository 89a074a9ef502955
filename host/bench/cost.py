"""``kinefuse bench cost``: per-update cost of every IMU filter and of the seed-004 joint-angle
smoothers on Cortex-M4F and M0, with x-io Fusion and VQF measured in the same run with the same
flags and the same motion (the smoothers get as many samples of the seed-004 servo protocol).

Per filter, number format and target: executed instructions per update (exact, QEMU counting
plugin, averaged over K updates after 400 warm-up updates of the same synthetic motion the
competitors get: 100 Hz, magnetometer present), estimated cycles and µs at 64 MHz (an estimate
from the executed instruction mix with a Cortex-M4 cycle table: FP add/mul 1, load/store 2,
VDIV/VSQRT 14, VFMA 3, taken branch 3 — not a measurement), and the flash/RAM the filter adds
to a program (``arm-none-eabi-size`` with and without it, ``-Os``, ``--gc-sections``); the part
of that which is the filter's own object file is given separately from newlib/libgcc.

``--json``: exactly one JSON object ``{"rows": [...], ...}``; each row has ``impl``
(kinefuse|fusion|vqf), ``filter``, ``format`` (f32|q), ``target`` (m4f|m0),
``instructions_per_update``, ``flash_bytes``, ``ram_bytes`` and more.

``--profile``: for our rows, the same single-step trace also attributes the instructions of an
update to functions (what GCC kept out of line: libgcc's soft-float and 64-bit routines, libm,
runtime helpers; with their calls per update) and to lines of the Python reference (each
generated statement carries its ``file.py:N`` comment; inlined helpers count at their caller).
"""
from __future__ import annotations

import argparse
import json

from kinefuse.host.errors import KinefuseError
from kinefuse.host.console import print_table as print_fitted
from kinefuse.host import argtypes

COMPETITOR_CASES = ("fusion-ahrs-9d", "fusion-ahrs-6d", "vqf-9d-f32", "vqf-6d-f32")
TARGETS = {"f32": ("m4f", "m0"), "q": ("m4f", "m0")}
GOALS = {  # (filter, format, target, sensors): instructions per update the issue sets as a target
    # (the flagship's are for 9D; the Madgwick target names no sensor set, so both rows carry it)
    ("flagship", "f32", "m4f", "9d"): 400, ("flagship", "q", "m0", "9d"): 2500,
    ("madgwick", "f32", "m4f", "9d"): 200, ("madgwick", "f32", "m4f", "6d"): 200,
}
SENSOR_SETS = ("9d", "6d")


def register_bench(bench_subparsers) -> None:
    p = bench_subparsers.add_parser(
        "cost", help="instructions per update (exact, QEMU), cycle estimate, flash/RAM on "
                     "Cortex-M4F and M0 for every filter, with Fusion and VQF")
    p.add_argument("--filters", default=None,
                   help="comma-separated filters (default: every IMU filter and joint-angle smoother)")
    p.add_argument("--formats", default="f32,q", help="comma-separated number formats (default f32,q)")
    p.add_argument("--targets", default="m4f,m0", help="comma-separated targets (default m4f,m0)")
    p.add_argument("--sensors", default="9d",
                   help="comma-separated sensor sets of our IMU filters' rows: 9d (a magnetometer "
                        "reading every sample) and/or 6d (none: the gyroscope and accelerometer "
                        "path, as Fusion's and VQF's 6D rows); default 9d")
    p.add_argument("--k", type=int, default=1000,
                   help="counted updates of our filters (default 1000, at most 1000; Fusion and "
                        "VQF always count 1000, each row gives its k)")
    p.add_argument("--no-competitors", action="store_true", help="skip Fusion and VQF")
    p.add_argument("--no-mix", action="store_true", help="skip the instruction-mix cycle estimate")
    p.add_argument("--profile", action="store_true",
                   help="also show where each of our updates spends its instructions: by function "
                        "(libgcc, libm, runtime helpers) and by line of the Python reference")
    p.add_argument("--top", type=int, default=None, help="--profile: entries shown (default 12)")
    p.add_argument("--jobs", type=argtypes.integer(1, 256), default=2, help="parallel measurements (default 2)")
    p.add_argument("--json", action="store_true", help="one JSON object on stdout")
    p.set_defaults(func=run)


def _own_split(cost, stems: set[str]) -> dict:
    origin = cost.size_origin.get("-Os", {})
    own_flash = sum(v.flash for k, v in origin.items() if k in stems)
    own_ram = sum(v.ram for k, v in origin.items() if k in stems or k == "kf_cost_driver")
    return {"own_flash_bytes": own_flash, "own_ram_bytes": own_ram,
            "size_by_origin": {k: v.as_dict() for k, v in origin.items()}}


def measure_ours(name: str, system: str, target: str, k: int, mix: bool,
                 profile: bool = False, top: int = 12, sensors: str = "9d") -> dict:
    from kinefuse.hil_tests.harness import cost as hc
    from kinefuse.hil_tests.qemu import cost as qc

    row = hc.measure_filter(name, system, target, k=k, mix=False, sensors=sensors)
    # size split: rebuild through measure_call_cost's origin data
    table_c, table_dir, _ct, _n = hc._table_sources(name, system, sensors)
    prelude, setup, call, finish, baseline = hc._snippets(name, system, sensors)
    from kinefuse.codegen.generate import GENERATED_DIR
    from kinefuse.codegen.estimator import generated_stem
    stem = generated_stem(name, system)
    total, origin = qc.size_delta_by_origin([GENERATED_DIR / f"{stem}.c", table_c], setup, call,
                                            target, opt="-Os", prelude=prelude, finish=finish,
                                            baseline_code=baseline,
                                            include_dirs=[GENERATED_DIR, table_dir])
    row["own_flash_bytes"] = sum(v.flash for kk, v in origin.items() if kk == stem)
    row["own_ram_bytes"] = sum(v.ram for kk, v in origin.items() if kk in (stem, "kf_cost_driver"))
    row["size_by_origin"] = {kk: v.as_dict() for kk, v in origin.items()}
    if mix or profile:   # one single-step trace serves both (builds carry -g line information)
        prog = qc.cost_program([GENERATED_DIR / f"{stem}.c", table_c], setup, call, target,
                               prelude=prelude, finish=finish, baseline_code=baseline,
                               include_dirs=[GENERATED_DIR, table_dir])
        per = hc.per_update_trace(prog.elf, target, hc.K_MIX)
        if profile:
            row["profile"] = hc.profile(prog.elf, per, hc.K_MIX, top)
        if mix:
            row.update(hc.cycle_estimate(prog, target, hc.K_MIX, per=per))
    goal = GOALS.get((name, system, target, sensors))
    if goal is not None:
        row["goal_instructions"] = goal
        row["goal_met"] = row["instructions_per_update"] <= goal
    return row


def measure_competitor(case: str, target: str, mix: bool) -> dict:
    from kinefuse.hil_tests.harness import cost as hc
    from kinefuse.hil_tests.qemu.competitors import CASES, K, WARMUP, fetch_sdist, measure_case

    r = measure_case(case, target)
    c = CASES[case]
    row = {"impl": competitor_impl(case), "filter": case, "sensors": competitor_sensors(case),
           "format": "f32", "target": target, "description": c.description, "k": K, "warmup": WARMUP}
    if r.cost is None:
        row.update({"error": r.error, "instructions_per_update": None, "flash_bytes": None,
                    "ram_bytes": None})
        return row
    row.update({"instructions_per_update": r.cost.per_call,
                "flash_bytes": r.cost.size["-Os"].flash, "ram_bytes": r.cost.size["-Os"].ram,
                "size": {o: s.as_dict() for o, s in r.cost.size.items()}})
    stems = {p.stem for p in c.sources(fetch_sdist(c.package))}
    row.update(_own_split(r.cost, stems))
    if mix:
        row.update(hc.cycle_estimate(r.cost.build, target))
    return row


def competitor_impl(case: str) -> str:
    """The ``impl`` of a competitor case's rows: fusion or vqf (the --json schema's names)."""
    return "fusion" if case.startswith("fusion") else "vqf"


def competitor_sensors(case: str) -> str:
    """9d or 6d: the sensor set of a competitor case (named in the case: fusion-ahrs-6d, ...)."""
    return "6d" if "-6d" in case else "9d"


def _job(kind: str, a: str, b: str, c: str, k: int, mix: bool, profile: bool = False,
         top: int = 12, sensors: str | None = "9d") -> dict:
    try:
        if kind == "ours":
            return measure_ours(a, b, c, k, mix, profile, top, sensors or "9d")
        return measure_competitor(a, c, mix)
    except KinefuseError as exc:
        # (a failed competitor row said impl "competitor", outside the schema's kinefuse|fusion|vqf)
        return {"impl": "kinefuse" if kind == "ours" else competitor_impl(a), "filter": a,
                "format": b, "target": c, "sensors": sensors,
                "error": str(exc), "instructions_per_update": None, "flash_bytes": None,
                "ram_bytes": None}


def run(args: argparse.Namespace) -> int:
    from concurrent.futures import ProcessPoolExecutor

    from kinefuse.hil_tests.harness import loops
    from kinefuse.hil_tests.qemu import qemu_unavailable

    from kinefuse.host.angle_series import angle_filter_names
    from kinefuse.host.bench.common import name_list
    costable = loops.imu_filters() + angle_filter_names()
    # (an empty --filters meant every filter: the longest run of all instead of an error)
    # (an empty name, "madgwick,", was an unknown filter '')
    filters = name_list("--filters", args.filters, costable, "madgwick,flagship")
    unknown = [f for f in filters if f not in costable]
    if unknown:
        raise KinefuseError(f"unknown IMU filter or joint-angle smoother {unknown[0]!r} "
                            f"(available: {', '.join(costable)})")
    formats = [f.strip() for f in args.formats.split(",") if f.strip()]
    targets = [t.strip() for t in args.targets.split(",") if t.strip()]
    if (not formats or not targets or any(f not in ("f32", "q") for f in formats)
            or any(t not in ("m4f", "m0") for t in targets)):
        raise KinefuseError("--formats takes f32,q and --targets m4f,m0")   # (an empty list measured nothing)
    sensors = [x.strip() for x in args.sensors.split(",") if x.strip()]
    if not sensors or any(x not in SENSOR_SETS for x in sensors):
        raise KinefuseError("--sensors takes 9d,6d")
    for opt, given in (("--filters", filters), ("--formats", formats), ("--targets", targets),
                       ("--sensors", sensors)):
        twice = [g for k, g in enumerate(given) if g in given[:k]]
        if twice:       # (each row was measured and listed twice)
            raise KinefuseError(f"{opt} names {twice[0]} twice")
    if not 1 <= args.k <= 1000:
        raise KinefuseError("--k must be between 1 and 1000")
    if args.top is not None and not args.profile:      # (was ignored)
        raise KinefuseError("--top sets the --profile listing: add --profile (or leave it out)")
    top = 12 if args.top is None else args.top
    if top < 1:
        raise KinefuseError("--top must be at least 1")
    reason = qemu_unavailable()        # after the options: their errors need no QEMU
    if reason:
        raise KinefuseError(reason)
    jobs, notes = plan_jobs(filters, formats, targets, not args.no_competitors, args.k, sensors)
    from kinefuse.host.bench.common import eprint, progress
    for note in notes:        # (rows left out without a word looked like a complete table)
        eprint(f"note: {note}")
    if not jobs:
        raise KinefuseError("nothing to measure with these --filters, --formats and --targets")
    rows = []
    # the bar is on stderr, so --json keeps it (a full run takes many minutes)
    with progress() as bar, ProcessPoolExecutor(max(1, args.jobs)) as pool:
        task = bar.add_task("cost on M4F/M0", total=len(jobs))
        futs = [pool.submit(_job, kind, a, b, c, args.k, not args.no_mix, args.profile, top, sx)
                for kind, a, b, c, sx in jobs]
        for fut in futs:
            rows.append(fut.result())
            bar.advance(task)
    result = {"rows": rows, "clock_hz": 64_000_000,
              "cycle_model": "estimate: Cortex-M4 table (FP add/mul 1, load/store 2, VDIV/VSQRT 14, "
                             "VFMA 3, taken branch 3) over the executed instruction mix; not measured",
              "motion": "competitors.motion(): 100 Hz synthetic rotation with magnetometer, 400 "
                        "warm-up updates, then K counted; rows with sensors 6d: the same samples "
                        "without a magnetometer reading (mag_valid 0)",
              # (the nested size records' flash/ram carried no unit)
              "units": "instructions_per_update: executed instructions per update (mean of k); "
                       "flash_bytes, ram_bytes, own_*_bytes and every flash/ram in size and "
                       "size_by_origin: bytes; est_us_at_64mhz: microseconds"}
    if args.json:
        print(json.dumps(result))
    else:
        print_table(rows)
        if args.profile:
            print_profiles(rows)
    return 0 if all(not r.get("error") for r in rows) else 1


def plan_jobs(filters: list[str], formats: list[str], targets: list[str], competitors: bool,
              k: int = 1000, sensors: tuple[str, ...] | list[str] = ("9d",),
              ) -> tuple[list[tuple[str, str, str, str, str | None]], list[str]]:
    """The measurements to make (kind, filter, format, target, sensors), and a note for each
    kind of row the options leave out."""
    from kinefuse.hil_tests.harness import loops
    jobs, notes = [], []
    imu = set(loops.imu_filters())
    for f in filters:
        have = loops.systems(f)
        missing = [s for s in formats if s not in have]
        if missing:
            notes.append(f"{f} is not generated in {', '.join(missing)}: no such row")
        sets = list(sensors) if f in imu else [None]
        if f not in imu and "9d" not in sensors:
            notes.append(f"{f} takes a joint-angle series (no sensor set): its rows are measured "
                         f"as without --sensors")
        jobs += [("ours", f, s, t, x) for x in sets for s in formats if s in have
                 for t in targets if t in TARGETS[s]]
    if competitors and "f32" in formats:
        jobs += [("competitor", c, "f32", t, competitor_sensors(c))
                 for c in COMPETITOR_CASES for t in targets]
        if k != 1000:
            notes.append(f"--k {k} counts our updates; Fusion and VQF rows count 1000 (see each "
                         f"row's k)")
    elif competitors:
        notes.append("Fusion and VQF are measured in float32 only: no competitor rows without "
                     "f32 in --formats (--no-competitors to leave them out)")
    return jobs, notes


def print_table(rows: list[dict]) -> None:
    from rich.table import Table

    t = Table(title="Cost per update (instructions exact under QEMU; cycles/µs estimated at 64 MHz; "
                    "bytes added, -Os)")
    for col in ("impl", "filter", "sensors", "format", "target", "instr/update", "est. cycles", "est. µs",
                "flash", "own flash", "RAM", "own RAM", "goal"):
        t.add_column(col, justify="right")
    for r in rows:
        if r.get("error"):
            t.add_row(r["impl"], r["filter"], r.get("sensors") or "", r["format"], r["target"],
                      f"error: {r['error']}", *[""] * 7)
            continue
        goal = ""
        if "goal_instructions" in r:
            goal = f"≤{r['goal_instructions']} {'met' if r['goal_met'] else 'MISSED'}"
        cyc = r.get("est_cycles_per_update")
        t.add_row(r["impl"], r["filter"], r.get("sensors") or "", r["format"], r["target"],
                  f"{r['instructions_per_update']:,.1f}",
                  f"{cyc:,.0f}" if cyc is not None else "-",
                  f"{r['est_us_at_64mhz']:.1f}" if cyc is not None else "-",
                  str(r["flash_bytes"]), str(r.get("own_flash_bytes", "")), str(r["ram_bytes"]),
                  str(r.get("own_ram_bytes", "")), goal)
    print_fitted(t)


def print_profiles(rows: list[dict]) -> None:
    from rich.console import Console
    from rich.table import Table

    con = Console()
    for r in rows:
        prof = r.get("profile")
        if not prof:
            continue
        head = (f"{r['filter']} {r.get('sensors') or ''} {r['format']} {r['target']}: "
                f"{prof['traced_instructions_per_update']:,.0f} "
                f"instructions per update ({prof['traced_updates']} updates traced)")
        t = Table(title=head + ", by function")
        for col in ("function", "instr/update", "calls/update"):
            t.add_column(col, justify="left" if col == "function" else "right")
        for f in prof["functions"]:
            calls = f["calls_per_update"]
            t.add_row(f["name"], f"{f['instructions_per_update']:,.1f}",
                      "" if calls is None else f"{calls:g}")
        print_fitted(t, con)
        t = Table(title=head + ", by line of the reference (inlined code counts at its caller)")
        for col in ("reference line", "instr/update"):
            t.add_column(col, justify="left" if col == "reference line" else "right")
        for g in prof["reference_lines"]:
            t.add_row(g["where"], f"{g['instructions_per_update']:,.1f}")
        print_fitted(t, con)
