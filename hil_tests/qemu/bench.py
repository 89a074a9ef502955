"""``kinefuse bench qemu``: measures the QEMU infrastructure itself and the competitors' cost.

Parts (all by default; ``--parts`` picks some):

* ``loop``: the instruction counter on the hand-countable ``kf_known_loop`` (expected
  3n + 3 per call) and the cost driver's loop overhead, per target;
* ``batch``: wall time to push ``--records`` (default 60 000) 16-byte records through the
  batch driver (quaternion normalisation), with a bit-exactness check against numpy;
* ``uart``: UART0 throughput over the TCP loopback (echo of ``--uart-bytes`` bytes);
* ``competitors``: x-io Fusion and VQF per-update instructions (-O2) and flash/RAM they add
  (-Os and -O2, split into the library's own code and newlib/libgcc), M4F and M0.

``--json`` prints exactly one JSON object on stdout.
"""
from __future__ import annotations

import argparse
import json
import time

import numpy as np

from kinefuse.host.errors import KinefuseError
from kinefuse.host.console import print_table

PARTS = ("loop", "batch", "uart", "competitors")


def register_bench(bench_subparsers) -> None:
    p = bench_subparsers.add_parser(
        "qemu", help="QEMU Cortex-M infrastructure: instruction counter check, batch and UART "
                     "throughput, Fusion/VQF cost on M4F and M0")
    p.add_argument("--parts", default=",".join(PARTS),
                   help=f"comma-separated subset of {','.join(PARTS)} (default: all)")
    p.add_argument("--targets", default="m4f,m0", help="comma-separated targets (default m4f,m0)")
    p.add_argument("--records", type=int, default=None, help="batch part: records (default 60000)")
    p.add_argument("--uart-bytes", type=int, default=None,
                   help="uart part: bytes echoed over UART0 (default 20000)")
    p.add_argument("--cases", default=None, help="competitors part: cases (default all: "
                   "fusion-ahrs-9d,fusion-ahrs-6d,vqf-9d,vqf-6d,vqf-9d-f32,vqf-6d-f32)")
    p.add_argument("--json", action="store_true", help="one JSON object on stdout")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from kinefuse.firmware.targets import TARGETS
    from kinefuse.hil_tests.qemu import qemu_unavailable
    from kinefuse.hil_tests.qemu.competitors import CASES
    from kinefuse.host.bench.common import name_list

    # the options first (one-line errors without QEMU too); an empty list measured nothing
    # and exited 0, a name given twice was measured and listed twice
    parts = name_list("--parts", args.parts, PARTS, ",".join(PARTS))
    targets = name_list("--targets", args.targets, TARGETS, "m4f,m0")
    cases = name_list("--cases", args.cases, CASES, ",".join(CASES))
    bad = [p for p in parts if p not in PARTS] + [t for t in targets if t not in TARGETS]
    if bad:
        raise KinefuseError(f"unknown part or target: {', '.join(bad)}")
    # options of a part not run: refused, not ignored
    unused = [o for o, part, v in (("--records", "batch", args.records),
                                   ("--uart-bytes", "uart", args.uart_bytes),
                                   ("--cases", "competitors", args.cases))
              if v is not None and part not in parts]
    if unused:
        raise KinefuseError(f"{', '.join(unused)}: option(s) of a part not run (--parts "
                            f"{','.join(parts)}); --records applies to batch, --uart-bytes to "
                            f"uart, --cases to competitors")
    records = 60_000 if args.records is None else args.records
    uart_bytes = 20_000 if args.uart_bytes is None else args.uart_bytes
    if records <= 0 or uart_bytes <= 0:
        raise KinefuseError("--records and --uart-bytes must be positive")
    unknown = [c for c in cases if c not in CASES]
    if unknown:
        raise KinefuseError(f"unknown competitor case {unknown[0]!r} (known: {', '.join(CASES)})")
    for opt, names in (("--parts", parts), ("--targets", targets), ("--cases", cases)):
        twice = [n for k, n in enumerate(names) if n in names[:k]]
        if twice:
            raise KinefuseError(f"{opt} names {twice[0]} twice")
    reason = qemu_unavailable()
    if reason:
        raise KinefuseError(reason)

    from rich.console import Console
    from rich.progress import Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

    err = Console(stderr=True)
    result: dict = {"targets": targets}
    steps = []
    for p in parts:
        if p == "competitors":
            steps += [("competitors", (c, t)) for c in cases for t in targets]
        else:
            steps += [(p, (t,)) for t in targets]
    with Progress(SpinnerColumn(), TextColumn("{task.description}"), TimeElapsedColumn(),
                  console=err, transient=True, disable=not err.is_terminal) as progress:
        task = progress.add_task("", total=len(steps))
        for part, what in steps:
            progress.update(task, description=f"{part}: {' '.join(what)}")
            if not err.is_terminal and not args.json:
                err.print(f"measuring {part} {' '.join(what)}")
            fn = {"loop": bench_loop, "batch": lambda t: bench_batch(t, records),
                  "uart": lambda t: bench_uart(t, uart_bytes),
                  "competitors": bench_competitor}[part]
            result.setdefault(part, []).append(fn(*what))
            progress.advance(task)

    if args.json:
        print(json.dumps(result, indent=1))
    else:
        _print_tables(result)
    return 0


# ---- parts ------------------------------------------------------------------------------

def bench_loop(target: str, n: int = 100, k: int = 1000) -> dict:
    from kinefuse.hil_tests.qemu.batch import csrc_path
    from kinefuse.hil_tests.qemu.cost import cost_program, count_calls, loop_overhead
    from kinefuse.hil_tests.qemu.insn import count_instructions

    prog = cost_program([csrc_path("selftest_known_loop.c")], "", f"(void)kf_known_loop({n}u);",
                        target, prelude="uint32_t kf_known_loop(uint32_t n);")
    addr, size = prog.symbol("kf_known_loop")
    counted = count_instructions(prog.elf, target, address_range=(addr, addr + size),
                                 args=[f"{k:010d}"]).in_range
    per_call = (count_calls(prog, k) - count_calls(prog, 0)) / k
    return {"target": target, "n": n, "k": k, "hand_count_per_call": 3 * n + 3,
            "plugin_count_per_call": counted / k, "exact": counted == k * (3 * n + 3),
            "whole_program_per_call": per_call, "loop_overhead": loop_overhead(target, k=k)}


def quat_normalise_model(q: np.ndarray) -> np.ndarray:
    """float32 model of csrc/selftest_quat_norm.c, operation by operation."""
    with np.errstate(all="ignore"):
        s = ((q[:, 0] * q[:, 0] + q[:, 1] * q[:, 1]) + q[:, 2] * q[:, 2]) + q[:, 3] * q[:, 3]
        return q * (np.float32(1.0) / np.sqrt(s))[:, None]


def bench_batch(target: str, records: int) -> dict:
    from kinefuse.hil_tests.qemu.batch import build_batch, csrc_path

    q = np.random.default_rng(3).normal(size=(records, 4)).astype("<f4")
    t0 = time.perf_counter()
    prog = build_batch([csrc_path("selftest_quat_norm.c")], "kf_selftest_quat_normalise",
                       in_size=16, out_size=16, target=target)
    build_s = time.perf_counter() - t0
    t0 = time.perf_counter()
    out, res = prog.run_detailed(q.tobytes(), timeout=600)
    wall = time.perf_counter() - t0
    got = np.frombuffer(out, "<f4").reshape(-1, 4)
    same = np.count_nonzero(got.view(np.uint32) == quat_normalise_model(q).view(np.uint32))
    return {"target": target, "records": records, "record_bytes_in": 16, "record_bytes_out": 16,
            "wall_s": wall, "qemu_s": res.wall_s, "records_per_s": records / wall,
            "build_s": build_s, "bit_exact_outputs": same, "outputs": got.size}


def bench_uart(target: str, nbytes: int) -> dict:
    from kinefuse.firmware.targets import build
    from kinefuse.hil_tests.qemu.batch import csrc_path
    from kinefuse.hil_tests.qemu.runner import run_elf

    prog = build([csrc_path("selftest_io.c")], target, name="selftest_io")
    payload = bytes((97 + i % 26) for i in range(nbytes)) + b"!"
    res = run_elf(prog.elf, target, args=["echo"], uart_input=payload,
                  timeout=max(60.0, nbytes / 500.0))
    ok = res.uart == b"ready\n" + payload.upper()
    return {"target": target, "bytes_each_way": len(payload), "wall_s": res.wall_s,
            "bytes_per_s_each_way": len(payload) / res.wall_s, "echo_correct": ok,
            "timed_out": res.timed_out}


def bench_competitor(case: str, target: str) -> dict:
    from kinefuse.hil_tests.qemu.competitors import CASES, fetch_sdist, measure_case

    r = measure_case(case, target)
    d = r.as_dict()
    d["description"] = CASES[case].description
    if r.cost is not None:
        root = fetch_sdist(CASES[case].package)
        own_stems = {p.stem for p in CASES[case].sources(root)}
        for opt, origin in r.cost.size_origin.items():
            own = sum(v.flash for k, v in origin.items() if k in own_stems)
            libs = sum(v.flash for k, v in origin.items() if k.endswith(".a"))
            d.setdefault("flash_split", {})[opt] = {"library_own_code": own,
                                                    "newlib_libgcc_libstdcxx": libs,
                                                    "other": r.cost.size[opt].flash - own - libs}
    return d


# ---- output ------------------------------------------------------------------------------

def _print_tables(result: dict) -> None:
    from rich.console import Console
    from rich.table import Table

    con = Console()
    if "loop" in result:
        t = Table(title="Instruction counter vs hand count (kf_known_loop(100), 3n+3 = 303)")
        for col in ("target", "hand", "plugin (range)", "exact", "whole program / call",
                    "driver loop overhead"):
            t.add_column(col, justify="right")
        for r in result["loop"]:
            t.add_row(r["target"], str(r["hand_count_per_call"]), f"{r['plugin_count_per_call']:.2f}",
                      "yes" if r["exact"] else "NO", f"{r['whole_program_per_call']:.3f}",
                      f"{r['loop_overhead']:.3f}")
        print_table(t, con)
    if "batch" in result:
        t = Table(title="Batch driver throughput (semihosting file I/O, 16 B in / 16 B out)")
        for col in ("target", "records", "wall s", "records/s", "bit-exact", "build s"):
            t.add_column(col, justify="right")
        for r in result["batch"]:
            t.add_row(r["target"], str(r["records"]), f"{r['wall_s']:.2f}",
                      f"{r['records_per_s']:,.0f}", f"{r['bit_exact_outputs']}/{r['outputs']}",
                      f"{r['build_s']:.2f}")
        print_table(t, con)
    if "uart" in result:
        t = Table(title="UART0 over TCP loopback (echo)")
        for col in ("target", "bytes each way", "wall s", "bytes/s each way", "correct"):
            t.add_column(col, justify="right")
        for r in result["uart"]:
            t.add_row(r["target"], str(r["bytes_each_way"]), f"{r['wall_s']:.2f}",
                      f"{r['bytes_per_s_each_way']:,.0f}", "yes" if r["echo_correct"] else "NO")
        print_table(t, con)
    if "competitors" in result:
        t = Table(title="Competitors per update (instructions at -O2; bytes added; RAM = static)")
        for col in ("case", "target", "instr/update", "flash -Os", "own code -Os",
                    "newlib/libgcc -Os", "RAM -Os", "flash -O2", "RAM -O2"):
            t.add_column(col, justify="right")
        for r in result["competitors"]:
            if r.get("error"):
                t.add_row(r["case"], r["target"], f"build failed: {r['error']}", *[""] * 6)
                continue
            s, split = r["size"], r["flash_split"]
            t.add_row(r["case"], r["target"], f"{r['instructions_per_call']:,.1f}",
                      str(s["-Os"]["flash"]), str(split["-Os"]["library_own_code"]),
                      str(split["-Os"]["newlib_libgcc_libstdcxx"]), str(s["-Os"]["ram"]),
                      str(s["-O2"]["flash"]), str(s["-O2"]["ram"]))
        print_table(t, con)
