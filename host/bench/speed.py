"""`kinefuse bench speed`: samples per second of the generated C batch path, of the Python models
and of the reference, and of x-io Fusion's C and VQF's C++ on the same trial in the same run.

Fusion's Python binding has no batch call, so its C (from the imufusion sdist, benchmark-only,
never committed) is compiled here with our flags into the same kind of batch loop as ours.  VQF
is timed through its own C++ batch call (vqf.VQF.updateBatch).  Each timing is the best of several
repetitions; only ratios measured in one run are meaningful on a shared machine.
"""
from __future__ import annotations

import json
import time

import numpy as np

from kinefuse.host import runner
from kinefuse.host.bench.common import eprint, trial_files
from kinefuse.host.errors import KinefuseError

_FUSION_WRAPPER = r"""
#include "Fusion.h"
void kf_fusion_run(const float *gyr_dps, const float *acc_g, const float *mag_ut, float *q,
                   int n, float rate_hz)
{
    FusionAhrs ahrs;
    const FusionAhrsSettings settings = {
        .sampleRate = rate_hz, .convention = FusionConventionNwu, .gain = 0.5f,
        .gyroscopeRange = 2000.0f, .accelerationRejection = 10.0f,
        .magneticRejection = 10.0f, .rejectionTimeout = 5 * (int)rate_hz,
    };
    int i;
    FusionAhrsInitialise(&ahrs);
    FusionAhrsSetSettings(&ahrs, &settings);
    for (i = 0; i < n; i++) {
        const FusionVector g = {.array = {gyr_dps[3 * i], gyr_dps[3 * i + 1], gyr_dps[3 * i + 2]}};
        const FusionVector a = {.array = {acc_g[3 * i], acc_g[3 * i + 1], acc_g[3 * i + 2]}};
        const FusionVector m = {.array = {mag_ut[3 * i], mag_ut[3 * i + 1], mag_ut[3 * i + 2]}};
        FusionQuaternion o;
        FusionAhrsUpdate(&ahrs, g, a, m);
        o = FusionAhrsGetQuaternion(&ahrs);
        q[4 * i] = o.element.w;
        q[4 * i + 1] = o.element.x;
        q[4 * i + 2] = o.element.y;
        q[4 * i + 3] = o.element.z;
    }
}
"""


def register_bench(sub):
    p = sub.add_parser("speed", help="samples/s of the generated C, models, reference, Fusion, VQF")
    p.add_argument("--filter", default=None, help="filter name (default: the default filter)")
    p.add_argument("--data", help="trial file or folder (first trial used)")
    p.add_argument("--repeat", type=int, default=5, help="repetitions of the fast paths (best taken)")
    p.add_argument("--model-samples", type=int, default=5000,
                   help="samples used for the (slow) Python model and reference timings")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=run)


def _best(fn, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def fusion_runner():
    """The x-io Fusion C (imufusion sdist) in a batch loop, built with our host flags."""
    from pathlib import Path
    from kinefuse.codegen.build import build
    from kinefuse.hil_tests.qemu.competitors import _fusion_sources, fetch_sdist
    root = fetch_sdist("imufusion")
    srcs = _fusion_sources(root)
    fusion_dir = srcs[0].parent
    wrapper = Path(root) / "kf_fusion_batch.c"
    wrapper.write_text(_FUSION_WRAPPER)
    cdef = ("void kf_fusion_run(const float *gyr_dps, const float *acc_g, const float *mag_ut, "
            "float *q, int n, float rate_hz);")
    # C99 + designated initialisers; Fusion needs <math.h> (libm), linked by default on Linux
    ffi, lib = build("fusion_batch", [], srcs + [wrapper], extra_cdef=cdef, extra_source=cdef,
                     include_dirs=[fusion_dir])
    return ffi, lib


def run(args) -> int:
    from kinefuse.codegen import runner as cg
    from kinefuse.codegen import estimators
    from kinefuse.host.broad import load_trial
    name = args.filter or runner.default_filter()
    if name not in runner.filter_names():
        raise KinefuseError(f"unknown filter {name!r} (available: {', '.join(runner.filter_names())})")
    files, where = trial_files(args.data)
    trial = load_trial(files[0])
    n = trial.n
    est = estimators.get(name)
    prm = est.resolve_params(runner.parse_params(None))
    inputs = runner.imu_inputs(trial)
    eprint(f"bench speed: {name} on {files[0].name} ({n} samples)")
    sps: dict[str, float | None] = {}
    for system in ("f32", "q"):
        r = cg.runner(name, system)
        call, _ = r.prepare(r.encode(inputs, prm))   # records packed once, as Fusion's arrays
        call()
        sps[f"{system}_c"] = n / _best(call, args.repeat)
    m = min(args.model_samples, n)
    small = {k: v[:m] for k, v in inputs.items()}
    for system in ("f32", "q"):
        r = cg.runner(name, f"{system}-model")
        enc = r.encode(small, prm)
        sps[f"{system}_model"] = m / _best(lambda: r.run_encoded(enc), 1)
    sps["ref"] = m / _best(lambda: cg.run(name, "ref", small, prm), 1)
    # competitors, same trial, same run
    try:
        ffi, lib = fusion_runner()
        g = np.ascontiguousarray(np.degrees(trial.gyr), dtype=np.float32)
        a = np.ascontiguousarray(trial.acc / 9.80665, dtype=np.float32)
        mg = np.ascontiguousarray(trial.mag, dtype=np.float32)
        q = np.zeros((n, 4), np.float32)
        fp = lambda arr, w=False: ffi.cast("float *", ffi.from_buffer(arr, require_writable=w))  # noqa: E731
        call = lambda: lib.kf_fusion_run(fp(g), fp(a), fp(mg), fp(q, True), n,  # noqa: E731
                                         float(trial.rate_hz))
        call()
        sps["imufusion"] = n / _best(call, args.repeat)
    except Exception as exc:  # competitor sources unavailable (offline) -> report, do not fail
        eprint(f"  x-io Fusion not measured: {exc}")
        sps["imufusion"] = None
    try:
        import vqf
        g = np.ascontiguousarray(trial.gyr, dtype=np.float64)
        a = np.ascontiguousarray(trial.acc, dtype=np.float64)
        mg = np.ascontiguousarray(trial.mag, dtype=np.float64)
        call = lambda: vqf.VQF(float(trial.dt)).updateBatch(g, a, mg)  # noqa: E731
        call()
        sps["vqf"] = n / _best(call, args.repeat)
    except ImportError:
        eprint("  VQF not measured: `pip install vqf` (benchmark extra)")
        sps["vqf"] = None
    result = {"filter": name, "samples_per_s": sps}
    if args.json:
        print(json.dumps(result))
        return 0
    print(f"{name}: samples per second on {files[0].name} ({n} samples; models and reference on "
          f"{m})")
    labels = {"f32_c": "generated float32 C (batch)", "q_c": "generated fixed-point C (batch)",
              "f32_model": "float32 Python model", "q_model": "fixed-point Python model",
              "ref": "Python reference (float64)", "imufusion": "x-io Fusion C (same flags, batch)",
              "vqf": "VQF C++ (updateBatch)"}
    for k, v in sps.items():
        print(f"  {labels[k]:<36} {('%12.0f' % v) if v else '           -'}")
    if sps.get("imufusion"):
        print(f"  ratio float32 C / Fusion: {sps['f32_c'] / sps['imufusion']:.2f}")
    if sps.get("vqf"):
        print(f"  ratio float32 C / VQF:    {sps['f32_c'] / sps['vqf']:.2f}")
    return 0
