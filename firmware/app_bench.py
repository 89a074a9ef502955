"""``kinefuse bench firmware``: end-to-end figures of the unit application.

* stream: the host build streams its synthetic sensor at ``--rate`` for ``--seconds`` over a
  pty into ``kinefuse record``; the .kfr is decoded and compared with what was sent (lost,
  duplicated, wrong, mistimed samples; the unit's own drop counters);
* hil: HIL_SENSOR round trips through the host build (BROAD excerpt), samples per second, and
  how many answers are bit-identical to the generated models;
* cost: instructions per sample of the application pipeline (counts -> calibration -> filter
  -> messages queued) on emulated Cortex-M4F (float32) and Cortex-M0 (fixed point), exact
  counts from QEMU (``(count(K) - count(0)) / K``), with streaming on and off;
* sizes: flash/RAM of the application per target, all filters and a two-filter build.
"""
from __future__ import annotations

import math
import time

import numpy as np

from kinefuse.host.errors import KinefuseError

SECTIONS = ("stream", "hil", "cost", "sizes")


def register_bench(bench_subparsers) -> None:
    p = bench_subparsers.add_parser("firmware", help="unit application: streaming loss, HIL, cost, size",
                                    description=__doc__.split("\n\n")[0].split(": ", 1)[-1])
    p.add_argument("--seconds", type=float, default=None, help="streaming duration (default 60)")
    p.add_argument("--rate", type=int, default=None, help="sensor / KF_RAW_SAMPLE rate in Hz (default 1000)")
    p.add_argument("--only", action="append", choices=SECTIONS, help="run only these sections (repeatable)")
    p.add_argument("--hil-samples", type=int, default=None, help="HIL samples per filter (default 3000)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run)


def run(args) -> int:
    from kinefuse.host.link.cli_util import console, print_json
    todo = args.only or list(SECTIONS)
    # a section's options were ignored when --only left it out
    for opt, value, section in (("--seconds", args.seconds, "stream"), ("--rate", args.rate, "stream"),
                                ("--hil-samples", args.hil_samples, "hil")):
        if value is not None and section not in todo:
            raise KinefuseError(f"{opt} sets the {section} section, which --only leaves out")
    args.seconds = 60.0 if args.seconds is None else args.seconds
    args.rate = 1000 if args.rate is None else args.rate
    args.hil_samples = 3000 if args.hil_samples is None else args.hil_samples
    if not (math.isfinite(args.seconds) and args.seconds > 0) or not 1 <= args.rate <= 2000:
        raise KinefuseError("--seconds must be positive and finite and --rate within 1..2000 Hz")
    if args.hil_samples < 1:
        raise KinefuseError(f"--hil-samples {args.hil_samples}: must be at least 1")
    con = console(args.json)
    out: dict = {}
    if "stream" in todo:
        from kinefuse.firmware.hostunit import stream_check
        with con.status(f"streaming {args.seconds:g} s at {args.rate} Hz through a pty into kinefuse record..."):
            out["stream"] = stream_check(args.seconds, args.rate)
        s = out["stream"]
        con.print(f"stream: {s['samples_received']:,} of {s['samples_expected']:,} samples recorded; lost "
                  f"{s['lost']}, duplicated {s['duplicates']}, wrong {s['wrong']}, mistimed {s['timing_errors']}, "
                  f"unit drops {s.get('unit_frames_dropped')}/{s.get('unit_samples_dropped')}, "
                  f"CRC errors {s['crc_errors']}; {s['rx_bytes'] / max(s['seconds'], 1e-9) / 1e3:.1f} kB/s; "
                  f"{'OK' if s['ok'] else 'FAILED'}")
    if "hil" in todo:
        with con.status("HIL round trips through the host build..."):
            out["hil"] = hil_bench(args.hil_samples)
        for r in out["hil"]:
            con.print(f"hil {r['system']:3} {r['filter']:9}: {r['samples']} samples, {r['samples_per_s']:,.0f}/s "
                      f"round trip, bit-identical to the model: {r['bit_identical']}/{r['samples']}")
    if "cost" in todo:
        with con.status("counting instructions per sample under QEMU..."):
            out["cost"] = cost_bench()
        for r in out["cost"]:
            con.print(f"cost {r['target']:3} {r['filter']:9} streaming {'on ' if r['streaming'] else 'off'}: "
                      f"{r['instructions_per_sample']:,.0f} instructions per sample")
    if "sizes" in todo:
        from kinefuse.firmware.build import size_report
        with con.status("cross-building for the size report..."):
            rows = size_report()
            from kinefuse.firmware import build as fb
            for target in ("m4f", "m0"):
                r = fb.build_target(target, opt="-Os", filters=["madgwick", "flagship"])
                rows.append({"target": target, "opt": "-Os", "filters": "madgwick,flagship", **r.size.as_dict()})
        out["sizes"] = rows
        for r in rows:
            con.print(f"size {r['target']:3} {r['opt']} {r.get('filters', 'all filters'):17}: flash {r['flash']:,} B, "
                      f"RAM {r['ram']:,} B (static)")
    if args.json:
        print_json(out)
    ok = out.get("stream", {}).get("ok", True) and all(r["bit_identical"] == r["samples"] for r in out.get("hil", []))
    return 0 if ok else 1


def hil_bench(n: int) -> list[dict]:
    from kinefuse.firmware.hostunit import HostUnit, hil_run, unit_model
    from kinefuse.host import broad, runner
    from kinefuse.host.link.params import ParamClient
    trial = broad.load_trial(broad.bundled_trials()[0])
    inp = runner.imu_inputs(trial)
    n = min(n, len(inp["acc"]) - 7800)
    sl = slice(7800, 7800 + n)
    t = np.arange(n, dtype=np.int64) * 3500 + 1000
    upd = np.ones(n, bool)
    rows = []
    for system in ("f32", "q"):
        with HostUnit(system, sensor=False, filters=["madgwick", "flagship"]) as unit:
            s = unit.session()
            pc = ParamClient(s, 1)
            pc.set("KF_RATE_HZ", 286)
            for name, fid in (("madgwick", 3), ("flagship", 5)):
                pc.set("KF_FILTER", fid)
                hil_run(s, t[:200], inp["acc"][sl][:200], inp["gyr"][sl][:200], inp["mag"][sl][:200],
                        upd[:200], window=200, timeout=30)           # warm-up (decoder, caches)
                pc.set("KF_FILTER", 0)
                pc.set("KF_FILTER", fid)                              # a fresh filter for the timed run
                t0 = time.perf_counter()
                got = hil_run(s, t, inp["acc"][sl], inp["gyr"][sl], inp["mag"][sl], upd, window=200, timeout=30)
                dt = time.perf_counter() - t0
                ref = unit_model(name, system, t, inp["acc"][sl], inp["gyr"][sl], inp["mag"][sl], upd, rate_hz=286)
                same = int(np.all(got["q"].view(np.uint32) == ref["q"].view(np.uint32), axis=1).sum())
                rows.append({"system": system, "filter": name, "samples": n, "seconds": round(dt, 3),
                             "samples_per_s": n / dt, "bit_identical": same})
    return rows


COST_PRELUDE = r'''
#include <string.h>
#include "kf_app.h"
#include "kf_hal_test.h"
static kf_app g_app;
static kf_sample g_s;
'''


def cost_bench(k: int = 200) -> list[dict]:
    from kinefuse.firmware import build as fb
    from kinefuse.firmware.targets import toolchain_missing
    from kinefuse.hil_tests.qemu.cost import measure_call_cost
    from kinefuse.hil_tests.qemu.runner import qemu_missing
    reason = toolchain_missing() or qemu_missing()
    if reason:
        return [{"skipped": reason}]
    csrc = fb.FIRMWARE_DIR / "tests" / "csrc"
    rows = []
    for target in ("m4f", "m0"):
        system = fb.TARGET_SYSTEM[target]
        for name, fid in (("madgwick", 3), ("flagship", 5)):
            for streaming in (1, 0):
                setup = (f"kft_reset(4096); kf_app_init(&g_app); g_app.values[KF_P_FILTER].u = {fid}u; "
                         "kf_config_select_filter(&g_app); g_app.streaming = %du; "
                         "memset(&g_s, 0, sizeof g_s); g_s.acc[2] = 1000; g_s.gyr[0] = 120; g_s.gyr[2] = -300; "
                         "g_s.mag[0] = 150; g_s.mag[1] = 120; g_s.mag[2] = -450;" % streaming)
                call = ("g_s.time_us += 1000u; g_s.mag_valid = (uint8_t)((kf_i % 10u) == 0u); "
                        "g_s.gyr[1] = (int16_t)(kf_i & 63u); kf_app_sample(&g_app, &g_s); "
                        "g_app.tx.tail = g_app.tx.head;")
                srcs = fb.app_sources(system, board_main=False, filters=["madgwick", "flagship"]) + [csrc / "kf_hal_test.c"]
                defs = fb._defines(system, fb.BOARD_TX_BYTES, False, ["madgwick", "flagship"])
                res = measure_call_cost(srcs, setup, call, target, k=k, prelude=COST_PRELUDE + '#include "kf_app_internal.h"\n',
                                        include_dirs=[fb.APP_DIR, fb.GENERATED_DIR, fb.MAVLINK_DIR, csrc],
                                        defines=defs, extra_cflags=["-isystem", str(fb.MAVLINK_DIR)])
                rows.append({"target": target, "system": system, "filter": name, "streaming": bool(streaming),
                             "instructions_per_sample": res.per_call, "k": k})
    return rows
