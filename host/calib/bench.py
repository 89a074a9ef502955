"""``kinefuse bench calibration`` — measured figures of the calibration code.

* seed 002 Annex G worked example: R = Aᵀ·pinv(Bᵀ) vs the published matrix, det, and the
  published calibrated sample; the same poses with the Procrustes and full models;
* magnetometer: simulated tumbling recordings (60 s, 100 Hz, noise 0.2 µT) with random hard
  iron (σ 20 µT per axis) and soft iron (±5 % symmetric), ``--runs`` seeds: offset error and
  norm-spread reduction for the full (ellipsoid) and hard (sphere) models; plus the
  ``kinefuse.hil_tests.sim`` scenario ``mag_calibration`` (independent simulator) when present;
* accelerometer full model on the independent simulator's ``six_position`` scenario
  (bias, scale and misalignment errors), when present.
"""
from __future__ import annotations

import json

import numpy as np
from kinefuse.host.console import print_table
from kinefuse.host import argtypes

# the fitting modules (scipy) are imported on use: `kinefuse --help` must stay fast


def register_bench(sub) -> None:
    p = sub.add_parser("calibration", help="calibration figures (seed worked example, magnetometer, accelerometer)")
    p.add_argument("--runs", type=argtypes.integer(1, 10_000), default=10, help="simulated magnetometer recordings per model")
    p.add_argument("--json", action="store_true", help="print exactly one JSON object")
    p.set_defaults(func=run)


def worked_example() -> dict:
    from kinefuse.host.calib import accel
    ex = accel.SEED002_WORKED_EXAMPLE
    ls = accel.fit_ls(ex["raw_poses"], ex["targets"])
    pr = accel.fit_procrustes(ex["raw_poses"], ex["targets"])
    fu = accel.fit_full_targets(ex["raw_poses"], ex["targets"])
    return {
        "R": ls.M.tolist(),
        "max_abs_diff_vs_published_R": float(np.abs(ls.M - ex["published_R"]).max()),
        "det": ls.det, "published_det": ex["published_det"],
        "sample_calibrated": ls.apply(ex["sample_raw"]).tolist(),
        "published_sample_calibrated": ex["sample_calibrated"].tolist(),
        "max_abs_diff_sample": float(np.abs(ls.apply(ex["sample_raw"]) - ex["sample_calibrated"]).max()),
        "residual_rms": {"ls": ls.residual_rms, "procrustes": pr.residual_rms, "full": fu.residual_rms},
        "det_by_method": {"ls": ls.det, "procrustes": pr.det, "full": fu.det},
    }


def mag_simulated(runs: int) -> dict:
    from kinefuse.host.calib import mag
    from kinefuse.host.kinematics import simulate
    out = {}
    for model in ("full", "hard"):
        errs, red = [], []
        for s in range(runs):
            rng = np.random.default_rng(100 + s)
            hi = 20.0 * rng.standard_normal(3)
            A = 0.05 * rng.standard_normal((3, 3))
            si = np.eye(3) + 0.5 * (A + A.T)
            rec = simulate.tumble(60.0, 100.0, rng=rng, hard_iron=hi, soft_iron=si, mag_noise=0.2)
            cal = mag.calibrate(rec.mag, model=model, field_norm=22.6)
            errs.append(float(np.linalg.norm(cal.b - hi)))
            red.append(cal.spread_reduction)
        out[model] = {"offset_error_uT_max": max(errs), "offset_error_uT_mean": float(np.mean(errs)),
                      "spread_reduction_min": min(red), "spread_reduction_median": float(np.median(red))}
    return out


def independent_sim() -> dict:
    """Fits on the project's independent simulator (``kinefuse.hil_tests.sim``), if present."""
    try:
        from kinefuse.hil_tests import sim
    except ImportError:
        return {"available": False}
    from kinefuse.host.calib import accel, mag, static
    from kinefuse.host.kinematics import quat as Q
    out: dict = {"available": True}
    r = sim.simulate("mag_calibration", seed=1)
    sm = r.meta["sensor_model"]["mag"]
    A = np.asarray(sm["misalignment"]) @ np.diag(sm["scale"])
    b_true = A @ np.asarray(sm["hard_iron_uT"]) + np.asarray(sm["bias_uT"])
    W_true = np.linalg.inv(A @ np.asarray(sm["soft_iron"]))
    cal = mag.calibrate(r.mag[r.mag_valid], field_norm=float(r.meta["earth"]["field_uT"]))
    out["mag_calibration"] = {"offset_error_uT": float(np.linalg.norm(cal.b - b_true)),
                              "W_max_abs_error": float(np.abs(cal.W - W_true).max()),
                              "spread_reduction": cal.spread_reduction}
    r = sim.simulate("six_position", seed=1)
    sa = r.meta["sensor_model"]["acc"]
    g = float(r.meta["earth"]["g"])
    wins = static.detect_static(r.t, r.acc, r.gyr)
    raw = static.window_means(r.acc, wins)
    targets = np.array([np.mean(Q.rotate(Q.conj(r.q_true[w.start:w.stop]), [0.0, 0.0, g]), axis=0)
                        for w in wins])
    cal = accel.fit_full_targets(raw, targets)
    A = np.asarray(sa["misalignment"]) @ np.diag(sa["scale"])
    out["six_position"] = {
        "poses": len(raw),
        "bias_error_mg": float(np.abs(cal.b - np.asarray(sa["bias_mg"]) * 1e-3 * g).max() / (1e-3 * g)),
        "M_max_abs_error": float(np.abs(cal.M - np.linalg.inv(A)).max()),
        "residual_rms": cal.residual_rms}
    return out


def run(args) -> int:
    from rich.console import Console
    with Console(stderr=True).status("calibration benchmark: worked example, simulated magnetometers"):
        res = {"worked_example": worked_example(), "magnetometer_simulated": mag_simulated(args.runs),
               "independent_simulator": independent_sim()}
    if args.json:
        print(json.dumps(res))
        return 0
    from rich.console import Console
    from rich.table import Table
    c = Console()
    we = res["worked_example"]
    t = Table(title="seed 002 Annex G worked example (R = Aᵀ·pinv(Bᵀ))")
    for col in ("quantity", "kinefuse", "published"):
        t.add_column(col)
    t.add_row("max |R − R_pub|", f"{we['max_abs_diff_vs_published_R']:.2e}", "(4 decimals)")
    t.add_row("det R", f"{we['det']:.4f}", f"{we['published_det']:.4f}")
    t.add_row("calibrated sample", ", ".join(f"{v:.4f}" for v in we["sample_calibrated"]),
              ", ".join(f"{v:.4f}" for v in we["published_sample_calibrated"]))
    for m, v in we["residual_rms"].items():
        t.add_row(f"residual RMS ({m})", f"{v:.4f} m/s²", "")
    print_table(t, c)
    t = Table(title=f"magnetometer, simulated ({args.runs} runs, hard iron σ 20 µT, soft iron ±5 %)")
    for col in ("model", "offset error max (µT)", "mean (µT)", "spread reduction min", "median"):
        t.add_column(col)
    for m, v in res["magnetometer_simulated"].items():
        t.add_row(m, f"{v['offset_error_uT_max']:.3f}", f"{v['offset_error_uT_mean']:.3f}",
                  f"×{v['spread_reduction_min']:.1f}", f"×{v['spread_reduction_median']:.1f}")
    print_table(t, c)
    ind = res["independent_simulator"]
    if ind.get("available"):
        m, a = ind["mag_calibration"], ind["six_position"]
        c.print(f"independent simulator (kinefuse.hil_tests.sim): mag_calibration offset error "
                f"{m['offset_error_uT']:.3f} µT, max |W − W_true| {m['W_max_abs_error']:.4f}, spread "
                f"×{m['spread_reduction']:.1f}; six_position ({a['poses']} poses) bias error "
                f"{a['bias_error_mg']:.2f} mg, max |M − M_true| {a['M_max_abs_error']:.4f}")
    return 0
