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
        .magneticRejection = 10.0f, .rejectionTimeout = 5.0f,   /* s in Fusion 1.3 (5*rate was 1425 s at 285 Hz) */
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
    p.add_argument("--repeat", type=int, default=15,
                   help="rounds of the C/C++ batch paths, timed in turns (best of each taken)")
    p.add_argument("--model-samples", type=int, default=5000,
                   help="samples used for the (slow) Python model and reference timings")
    p.add_argument("--instructions", action="store_true",
                   help="also count instructions per sample of the f32 C and Fusion's C under "
                        "valgrind (deterministic, unlike times on a shared machine)")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=run)


def _best(fn, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def _best_interleaved(calls: dict, repeat: int) -> dict[str, float]:
    """Best time of each call, the calls taking turns for `repeat` rounds: a change of the
    machine's load during the run then falls on all of them alike instead of on whichever was
    being timed (timing each path's repetitions in a block moved the Fusion ratio by +-30 %)."""
    best = {k: float("inf") for k in calls}
    for _ in range(repeat):
        for k, fn in calls.items():
            t = time.perf_counter()
            fn()
            best[k] = min(best[k], time.perf_counter() - t)
    return best


def fusion_inputs(trial):
    """Fusion's units: gyroscope deg/s, accelerometer g, magnetometer as recorded (float32)."""
    return (np.ascontiguousarray(np.degrees(trial.gyr), dtype=np.float32),
            np.ascontiguousarray(trial.acc / 9.80665, dtype=np.float32),
            np.ascontiguousarray(trial.mag, dtype=np.float32))


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


_COUNT_MAIN = r"""
#include <stdio.h>
#include <stdlib.h>
#include "%(header)s"
void kf_fusion_run(const float *gyr_dps, const float *acc_g, const float *mag_ut, float *q,
                   int n, float rate_hz);
static void *slurp(const char *path, long *len)
{
    FILE *f = fopen(path, "rb");
    void *buf;
    if (f == NULL) { perror(path); exit(2); }
    fseek(f, 0, SEEK_END); *len = ftell(f); fseek(f, 0, SEEK_SET);
    buf = malloc((size_t)*len);
    if (fread(buf, 1, (size_t)*len, f) != (size_t)*len) { perror(path); exit(2); }
    fclose(f);
    return buf;
}
int main(int argc, char **argv)
{
    long len_in, len_f;
    const %(P)s_input *in = slurp(argv[1], &len_in);
    const int n = (int)(len_in / (long)sizeof(*in));
    %(P)s_output *out = malloc(sizeof(*out) * (size_t)n);
    %(P)s_params p;
    %(P)s_state s;
    %(P)s_default_params(&p);
    %(P)s_init(&s, &p);
    %(P)s_run(&s, in, out, (uint32_t)n);
#ifdef KF_WITH_FUSION
    {
        const float *fus = slurp(argv[2], &len_f);
        float *q = malloc(sizeof(float) * 4u * (size_t)n);
        kf_fusion_run(fus, fus + 3 * n, fus + 6 * n, q, n, (float)atof(argv[3]));
        printf("%%d %%g %%g\n", n, (double)out[n - 1].%(OUT)s, (double)q[4 * n - 4]);
    }
#else
    (void)len_f;
    printf("%%d %%g\n", n, (double)out[n - 1].%(OUT)s);
#endif
    return 0;
}
"""


_VQF_COUNT_MAIN = r"""
#include <cstdio>
#include <cstdlib>
#include <vector>
#include "vqf.hpp"
/* VQF::update over the trial, as VQF::updateBatch does (double precision, the library default) */
extern "C" void kf_vqf_run(const double *gyr, const double *acc, const double *mag, double *q,
                           int n, double ts)
{
    VQF vqf(ts);
    for (int i = 0; i < n; i++) {
        vqf.update(gyr + 3 * i, acc + 3 * i, mag + 3 * i);
        vqf.getQuat9D(q + 4 * i);
    }
}
int main(int argc, char **argv)
{
    FILE *f = std::fopen(argv[1], "rb");
    if (f == NULL) { std::perror(argv[1]); return 2; }
    std::fseek(f, 0, SEEK_END); long len = std::ftell(f); std::fseek(f, 0, SEEK_SET);
    std::vector<double> buf((size_t)len / sizeof(double));
    if (std::fread(buf.data(), 1, (size_t)len, f) != (size_t)len) { std::perror(argv[1]); return 2; }
    std::fclose(f);
    const int n = (int)(buf.size() / 9);
    std::vector<double> q(4 * (size_t)n);
    kf_vqf_run(buf.data(), buf.data() + 3 * n, buf.data() + 6 * n, q.data(), n, std::atof(argv[2]));
    std::printf("%d %g\n", n, q[4 * (size_t)n - 4]);
    return 0;
}
"""


def vqf_instructions_per_sample(trial) -> float:
    """Instructions per sample of VQF's C++ (its PyPI sdist, benchmark-only) updating over the
    trial, built with our host flags (C++ instead of C99), counted by valgrind like ours."""
    import re
    import subprocess
    import tempfile
    from pathlib import Path
    from kinefuse.codegen.build import HOST_CFLAGS
    from kinefuse.hil_tests.qemu.competitors import fetch_sdist
    src = Path(fetch_sdist("vqf")) / "vqf" / "cpp"
    flags = [f for f in HOST_CFLAGS if not f.startswith("-W") and not f.startswith("-std=")]
    with tempfile.TemporaryDirectory(prefix="kf-count-vqf-") as tmp:
        t = Path(tmp)
        (t / "main.cpp").write_text(_VQF_COUNT_MAIN)
        np.concatenate([np.ascontiguousarray(a, dtype=np.float64).ravel()
                        for a in (trial.gyr, trial.acc, trial.mag)]).tofile(t / "in.bin")
        cmd = ["g++", *flags, "-std=c++11", "-fno-exceptions", "-fno-rtti", "-I", str(src),
               "-o", str(t / "count"), str(t / "main.cpp"), str(src / "vqf.cpp"), "-lm"]
        proc = subprocess.run(cmd, capture_output=True, text=True)
        if proc.returncode != 0:
            raise KinefuseError(f"could not build VQF's instruction counter: {proc.stderr[-400:]}")
        out = t / "callgrind.out"
        proc = subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
                               "--collect-atstart=no", "--toggle-collect=kf_vqf_run",
                               str(t / "count"), str(t / "in.bin"), str(trial.dt)],
                              capture_output=True, text=True)
        if proc.returncode != 0:
            raise KinefuseError(f"valgrind failed: {proc.stderr.strip().splitlines()[-1:]}")
        ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", str(out)],
                             capture_output=True, text=True).stdout
    m = re.search(r"^\s*([\d,]+)\s.*\bkf_vqf_run\b", ann, re.M)
    if m is None:
        raise KinefuseError("callgrind reported no count for kf_vqf_run")
    return int(m.group(1).replace(",", "")) / trial.n


def instructions_per_sample(name: str, inputs: dict, prm: dict, trial) -> dict[str, float]:
    """Instructions per sample of our f32 batch path and of Fusion's, same flags, same trial,
    counted by valgrind (callgrind, only inside the two batch functions).  ``trial`` None (the
    angle smoothers): ours only."""
    import re
    import shutil
    import subprocess
    import tempfile
    from pathlib import Path
    from kinefuse.codegen import runner as cg
    from kinefuse.codegen.build import HOST_CFLAGS
    from kinefuse.codegen.generate import GENERATED_DIR
    from kinefuse.hil_tests.qemu.competitors import _fusion_sources, fetch_sdist
    if shutil.which("valgrind") is None:
        raise KinefuseError("--instructions needs valgrind (apt-get install valgrind)")
    from kinefuse.codegen.estimator import generated_stem
    P = generated_stem(name, "f32")
    header = (GENERATED_DIR / f"{P}.h").read_text()
    in_type = re.search(r"const (kf_\w+_input_f32) \*in", header).group(1)
    fusion_too = trial is not None
    first_out = "q[0]" if fusion_too else "angle"
    r = cg.runner(name, "f32")
    enc = r.encode(inputs, prm)
    rec = np.zeros(enc.n, dtype=r._dtype(in_type, "input"))
    for fname, size, _typ in r.fields["input"]:
        rec[fname] = enc.inputs[fname].reshape(enc.n) if size == 1 else enc.inputs[fname]
    fusion = _fusion_sources(fetch_sdist("imufusion")) if fusion_too else []
    with tempfile.TemporaryDirectory(prefix="kf-count-") as tmp:
        t = Path(tmp)
        (t / "main.c").write_text(_COUNT_MAIN.replace("%(header)s", f"{P}.h")
                                  .replace("%(P)s_input", in_type).replace("%(P)s", P)
                                  .replace("%(OUT)s", first_out).replace("%%", "%"))
        rec.tofile(t / "in.bin")
        flags = [f for f in HOST_CFLAGS if not f.startswith("-W")]
        extra = []
        if fusion_too:
            (t / "fusion_batch.c").write_text(_FUSION_WRAPPER)
            np.concatenate([v.ravel() for v in fusion_inputs(trial)]).tofile(t / "fusion.bin")
            extra = ["-DKF_WITH_FUSION", "-I", str(fusion[0].parent), str(t / "fusion_batch.c"),
                     *map(str, fusion)]
        else:
            (t / "fusion.bin").write_bytes(b"")
        cmd = (["gcc", *flags, "-I", str(GENERATED_DIR), "-o", str(t / "count"), str(t / "main.c"),
                str(GENERATED_DIR / f"{P}.c"), *extra, "-lm"])
        proc = subprocess.run(cmd, capture_output=True, text=True)
        if proc.returncode != 0:
            raise KinefuseError(f"could not build the instruction counter: {proc.stderr[-400:]}")
        out = t / "callgrind.out"
        proc = subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
                               "--collect-atstart=no", f"--toggle-collect={P}_run",
                               "--toggle-collect=kf_fusion_run", str(t / "count"),
                               str(t / "in.bin"), str(t / "fusion.bin"),
                               str(trial.rate_hz if fusion_too else 0)],
                              capture_output=True, text=True)
        if proc.returncode != 0:
            raise KinefuseError(f"valgrind failed: {proc.stderr.strip().splitlines()[-1:]}")
        ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", str(out)],
                             capture_output=True, text=True).stdout
    counts = {}
    for key, fn in (("f32_c", f"{P}_run"),) + ((("imufusion", "kf_fusion_run"),) if fusion_too else ()):
        m = re.search(r"^\s*([\d,]+)\s.*\b" + re.escape(fn) + r"\b", ann, re.M)
        if m is None:
            raise KinefuseError(f"callgrind reported no count for {fn}")
        counts[key] = int(m.group(1).replace(",", "")) / enc.n
    return counts


def run(args) -> int:
    from kinefuse.codegen import runner as cg
    from kinefuse.codegen import estimators
    from kinefuse.host.broad import load_trial
    from kinefuse.host.bench.common import given
    given("--filter", args.filter, "a filter name")        # (meant the default filter)
    given("--data", args.data, "a trial file or folder")    # (searched the current folder)
    name = args.filter.strip() if args.filter is not None else runner.default_filter()
    if name not in runner.filter_names():
        raise KinefuseError(f"unknown filter {name!r} (available: {', '.join(runner.filter_names())})")
    if args.repeat < 1:
        raise KinefuseError(f"--repeat {args.repeat}: must be at least 1")
    if args.model_samples < 1:
        raise KinefuseError(f"--model-samples {args.model_samples}: must be at least 1")
    import shutil
    if args.instructions and shutil.which("valgrind") is None:    # (was found out after the timings)
        raise KinefuseError("--instructions needs valgrind (apt-get install valgrind)")
    from kinefuse.host import angle_series
    angle = angle_series.is_angle_filter(name)
    if not angle and name not in runner.imu_filter_names():
        raise KinefuseError(f"bench speed times IMU filters and the joint-angle smoothers; "
                            f"{name!r} takes {estimators.ESTIMATORS[name].inputs.name} inputs")
    est = estimators.get(name)
    prm = est.resolve_params(runner.parse_params(None))
    if angle:
        # no IMU competitor applies; data: one long take of the seed-004 servo protocol
        trial = None
        if args.data is None:
            from kinefuse.host.bench.seed004 import long_series
            inputs = long_series()
            what = "a 1,500 s seed-004 servo take (20° sine at 5 rad/s, 35 Hz, 1.8° noise)"
        else:
            inputs = angle_series.inputs(angle_series.load(args.data))
            what = str(args.data)
        n = len(inputs["dt"])
    else:
        files, where = trial_files(args.data)
        trial = load_trial(files[0])
        n = trial.n
        inputs = runner.imu_inputs(trial)
        what = files[0].name
    eprint(f"bench speed: {name} on {what} ({n} samples)")
    sps: dict[str, float | None] = {}
    batch = {}                            # the C/C++ batch paths, timed in turns below
    for system in ("f32", "q"):
        r = cg.runner(name, system)
        call, _ = r.prepare(r.encode(inputs, prm))   # records packed once, as Fusion's arrays
        call()
        batch[f"{system}_c"] = call
    if not angle:                        # competitors, same trial, same run
        batch.update(_competitors(sps, trial, n))
    for k, t in _best_interleaved(batch, args.repeat).items():
        sps[k] = n / t
    m = min(args.model_samples, n)
    small = {k: v[:m] for k, v in inputs.items()}
    for system in ("f32", "q"):
        r = cg.runner(name, f"{system}-model")
        enc = r.encode(small, prm)
        sps[f"{system}_model"] = m / _best(lambda: r.run_encoded(enc), 1)
    sps["ref"] = m / _best(lambda: cg.run(name, "ref", small, prm), 1)
    order = ("f32_c", "q_c", "f32_model", "q_model", "ref", "imufusion", "vqf")
    sps = {k: sps[k] for k in order if k in sps}
    # (the JSON did not say which data, how many samples, nor that a competitor is missing)
    result = {"filter": name, "data": what, "samples": n, "model_samples": m,
              "repeat": args.repeat, "samples_per_s": sps}
    missing = [k for k, v in sps.items() if v is None]
    if missing:
        result["not_measured"] = missing
    if args.instructions:
        eprint("  counting instructions under valgrind (a few seconds)...")
        result["instructions_per_sample"] = instructions_per_sample(name, inputs, prm, trial)
        if trial is not None:
            try:
                result["instructions_per_sample"]["vqf"] = vqf_instructions_per_sample(trial)
            except KinefuseError as exc:   # no C++ compiler or sdist offline: report, do not fail
                eprint(f"  VQF instructions not counted: {exc}")
    if args.json:
        print(json.dumps(result))
        return 0
    print(f"{name}: samples per second on {what} ({n} samples; models and reference on "
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
    ips = result.get("instructions_per_sample")
    if ips and "imufusion" in ips:
        print(f"  instructions per sample (valgrind, x86-64, same flags): float32 C "
              f"{ips['f32_c']:.1f}, x-io Fusion {ips['imufusion']:.1f} "
              f"(Fusion / ours = {ips['imufusion'] / ips['f32_c']:.2f})")
    elif ips:
        print(f"  instructions per sample (valgrind, x86-64, same flags): float32 C "
              f"{ips['f32_c']:.1f}")
    if ips and ips.get("vqf"):
        print(f"  VQF C++ {ips['vqf']:.1f} instructions per sample (VQF / ours = "
              f"{ips['vqf'] / ips['f32_c']:.2f})")
    return 0


def _competitors(sps: dict, trial, n: int) -> dict:
    """x-io Fusion's C and VQF's C++ on the same trial: their batch calls, to be timed with ours
    (an unavailable one is reported and set to None in sps)."""
    calls = {}
    try:
        ffi, lib = fusion_runner()
        g, a, mg = fusion_inputs(trial)
        q = np.zeros((n, 4), np.float32)
        fp = lambda arr, w=False: ffi.cast("float *", ffi.from_buffer(arr, require_writable=w))  # noqa: E731
        call = lambda: lib.kf_fusion_run(fp(g), fp(a), fp(mg), fp(q, True), n,  # noqa: E731
                                         float(trial.rate_hz))
        call()
        calls["imufusion"] = call
    except Exception as exc:  # competitor sources unavailable (offline) -> report, do not fail
        eprint(f"  x-io Fusion not measured: {exc}")
        sps["imufusion"] = None
    try:
        import vqf
        vg = np.ascontiguousarray(trial.gyr, dtype=np.float64)
        va = np.ascontiguousarray(trial.acc, dtype=np.float64)
        vm = np.ascontiguousarray(trial.mag, dtype=np.float64)
        call = lambda: vqf.VQF(float(trial.dt)).updateBatch(vg, va, vm)  # noqa: E731
        call()
        calls["vqf"] = call
    except ImportError:
        eprint("  VQF not measured: `pip install vqf` (benchmark extra)")
        sps["vqf"] = None
    return calls
