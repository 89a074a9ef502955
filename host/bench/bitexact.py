"""`kinefuse bench bitexact`: generated C against its Python model, bit for bit, on every output
of every sample; and the deviation of both number systems from the float64 reference.

IMU filters run on BROAD trials (deviation: orientation angle between the number system's
quaternion and the reference's).  The seed-004 joint-angle smoothers run on the seed-004 servo
protocol as ``kinefuse bench seed004`` simulates it (20 series of 1,050 samples; or ``--data``
an angle series: seed-004 Arduino CSV or a t,angle_deg CSV); their deviation is that of the
filtered angle output."""
from __future__ import annotations

import json
from concurrent.futures import ProcessPoolExecutor

import numpy as np

from kinefuse.host import runner
from kinefuse.host.bench.common import eprint, progress, quat_angle_deg, trial_files
from kinefuse.host import argtypes


def register_bench(sub):
    p = sub.add_parser("bitexact", help="generated C vs Python models (bits) and vs the reference")
    p.add_argument("--data", help="BROAD folder or trial file (default: shared BROAD, else bundled)")
    p.add_argument("--filter", default=None, help="filter name (default: the default filter)")
    p.add_argument("--param", action="append", metavar="NAME=VALUE")
    p.add_argument("--jobs", type=argtypes.integer(1, 256), default=None,
                   help="parallel processes for BROAD trials (default 2; the joint-angle "
                        "smoothers' series run in one process)")
    p.add_argument("--no-ref", action="store_true",
                   help="bits only: skip the float64 reference (the slowest part; no deviation)")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=run)


def compare_trial(name: str, path: str, params: dict, with_ref: bool = True) -> dict:
    """Per-trial result for f32 and q: samples, differing samples, angle deviations, first diff."""
    from kinefuse.host.broad import load_trial
    return compare_inputs(name, runner.imu_inputs(load_trial(path)), params, with_ref)


def _angle_dev_deg(ref, got):
    return np.degrees(np.abs(np.asarray(got, float).reshape(-1) - np.asarray(ref, float).reshape(-1)))


def compare_inputs(name: str, inputs: dict, params: dict, with_ref: bool = True) -> dict:
    """:func:`compare_trial` on an input record (IMU: quaternion deviation; angle smoothers:
    deviation of the filtered angle)."""
    from kinefuse.codegen import runner as cg
    from kinefuse.codegen import estimators
    est = estimators.get(name)
    prm = est.resolve_params(params)
    key, deviation = ("q", quat_angle_deg) if est.inputs.name == "imu" else ("angle", _angle_dev_deg)
    ref = cg.run(name, "ref", inputs, prm)[key] if with_ref else None
    n = len(inputs["dt"])
    out = {}
    for system in ("f32", "q"):
        c = cg.run(name, system, inputs, prm, raw=True)
        m = cg.run(name, f"{system}-model", inputs, prm, raw=True)
        differ = np.zeros(n, dtype=bool)
        for k in c:
            differ |= np.any(cg.bits(c[k]).reshape(n, -1) != cg.bits(m[k]).reshape(n, -1), axis=1)
        r = cg.runner(name, f"{system}-model")
        q = r.decode_values("output", key, "real", c[key])
        dev = deviation(ref, q) if with_ref else np.full(1, np.nan)
        first = None
        if differ.any():
            i = int(np.argmax(differ))
            first = {"sample": i, "inputs": {k: np.asarray(v[i]).tolist() for k, v in inputs.items()},
                     "c": {k: np.asarray(v[i]).tolist() for k, v in c.items()},
                     "model": {k: np.asarray(v[i]).tolist() for k, v in m.items()}}
        out[system] = {"samples": int(n), "differing": int(differ.sum()),
                       "sq_dev": float(np.sum(dev ** 2)), "max_deg": float(np.max(dev)),
                       "first_difference": first}
    return out


def run(args) -> int:
    from kinefuse.host.bench.common import given
    given("--filter", args.filter, "a filter name")        # (meant the default filter)
    given("--data", args.data, "a BROAD folder, trial file or angle series")
    name = args.filter.strip() if args.filter is not None else runner.default_filter()
    if name not in runner.filter_names():
        from kinefuse.host.errors import KinefuseError
        raise KinefuseError(f"unknown filter {name!r} (available: {', '.join(runner.filter_names())})")
    params = runner.parse_params(args.param)
    runner.check_params(name, params)          # one-line error before any work starts
    from kinefuse.host import angle_series
    angle = angle_series.is_angle_filter(name)
    if not angle and name not in runner.imu_filter_names():
        from kinefuse.host.errors import KinefuseError
        raise KinefuseError(f"bench bitexact runs IMU filters and the joint-angle smoothers; "
                            f"{name!r} takes {_input_kind(name)}")
    results = {}
    if angle:
        series, where = _angle_data(args.data)
        eprint(f"bench bitexact: {name} on {len(series)} angle series from {where}")
        if args.jobs is not None:       # (was accepted and did nothing)
            eprint(f"note: --jobs {args.jobs} not used: the angle series run in one process")
        with progress(not args.json) as bar:
            task = bar.add_task(f"{name}: C vs model vs reference", total=len(series))
            for label, inp in series:
                results[label] = compare_inputs(name, inp, params, not args.no_ref)
                bar.advance(task)
    else:
        files, where = trial_files(args.data)
        eprint(f"bench bitexact: {name} on {len(files)} trial(s) from {where}")
        # the bar is on stderr: --json keeps it (all 12 trials take minutes)
        with progress() as bar, ProcessPoolExecutor(args.jobs or 2) as pool:
            task = bar.add_task(f"{name}: C vs model vs reference", total=len(files))
            futs = {pool.submit(compare_trial, name, str(f), params, not args.no_ref): f for f in files}
            for fut in futs:
                results[futs[fut].stem] = fut.result()
                bar.advance(task)
    # (the JSON of an IMU filter did not say which data nor how many trials it covers)
    summary = {"filter": name, "data": where, ("series" if angle else "trials"): len(results)}
    summary["deviation_of"] = ("filtered angle output, degrees" if angle else
                               "orientation angle from the float64 reference, degrees")
    for system in ("f32", "q"):
        n = sum(r[system]["samples"] for r in results.values())
        summary[system] = {
            "samples": n,
            "differing": sum(r[system]["differing"] for r in results.values()),
            "rms_deg": float(np.sqrt(sum(r[system]["sq_dev"] for r in results.values()) / max(n, 1))),
            "max_deg": max(r[system]["max_deg"] for r in results.values()),
        }
        if args.no_ref:
            summary[system]["rms_deg"] = summary[system]["max_deg"] = None
    if args.json:
        print(json.dumps(summary))
    else:
        print(f"{name}: generated C vs its Python model (bits of every output), and vs the float64 "
              f"reference ({'filtered angle' if angle else 'orientation angle'})")
        print(f"{'system':<8}{'samples':>10}{'differing':>11}{'RMS dev [deg]':>15}{'max dev [deg]':>15}")
        for system in ("f32", "q"):
            s = summary[system]
            dev = (f"{s['rms_deg']:>15.2e}{s['max_deg']:>15.2e}" if s["rms_deg"] is not None
                   else f"{'(no ref)':>15}{'(no ref)':>15}")
            print(f"{system:<8}{s['samples']:>10}{s['differing']:>11}{dev}")
    for tname, r in results.items():
        for system in ("f32", "q"):
            fd = r[system]["first_difference"]
            if fd:
                eprint(f"MISMATCH {system} in {tname} at sample {fd['sample']}: inputs {fd['inputs']}; "
                       f"C {fd['c']}; model {fd['model']}")
    return 1 if any(summary[s]["differing"] for s in ("f32", "q")) else 0


def _input_kind(name: str) -> str:
    from kinefuse.codegen import estimators
    return f"{estimators.ESTIMATORS[name].inputs.name} inputs"


def _angle_data(data: str | None) -> tuple[list[tuple[str, dict]], str]:
    """[(label, angle input record)], description: the seed-004 servo protocol, or a file."""
    from kinefuse.host import angle_series
    if data is None:
        from kinefuse.host.bench.seed004 import PROTOCOL_TEXT, protocol_series
        return [(f"servo{i:02d}", inp) for i, inp in enumerate(protocol_series())], PROTOCOL_TEXT
    s = angle_series.load(data)
    return [(str(data), angle_series.inputs(s))], f"{data} ({s.fmt})"
