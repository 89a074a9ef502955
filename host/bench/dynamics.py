"""``kinefuse bench dynamics``: the reduced dynamic EKF of seeds 000/003.

* ``pendulum``: seed 000 Annex A — 24 combinations of integrator (FE, HE = Heun, TF/TN =
  trapezoidal with fixed-point / Newton-Raphson iterations), state propagation Φ (PE first
  order, SE second order, EX exact) and noise covariance Σ_k (CT Taylor, VL Van Loan), plus the
  simplified sensitivity of Table A.3: RMS of z, ż, T_e and the real-time factor, for the
  float64 reference (Python) and the generated float32 C (host);
* ``robustness``: observer masses 60/15 kg against a 50/25 kg truth; both markers of bar 1 lost
  for 300 ms at the peak speed; the dynamic filter against the kinematic FCDI; observability;
* ``leg``: the wearable leg (hip/knee torques from two IMUs): RMSE, lag, float32 C against the
  reference, Cortex-M4F instructions per step (QEMU, when available).

The first run generates and compiles every variant (cached under ~/.cache/kinefuse/dyn; about
10-30 s each, two at a time with --jobs 2); the Python reference runs take most of the rest.
``--json`` prints exactly one JSON object on stdout; progress goes to stderr.
"""
from __future__ import annotations

import json
import math
import sys

from kinefuse.host.errors import KinefuseError
from kinefuse.host.console import print_table
from kinefuse.host import argtypes

PARTS = ("pendulum", "robustness", "leg")


def register_bench(sub):
    p = sub.add_parser("dynamics", help="dynamic EKF: seed 000 Annex-A variants, robustness "
                       "(masses, occlusion) against FCDI, wearable leg torques")
    p.add_argument("--parts", default=",".join(PARTS),
                   help=f"comma-separated subset of {','.join(PARTS)} (default: all)")
    p.add_argument("--variants", choices=("all", "quick"), default="all",
                   help="pendulum variants: all 25 rows, or 4 (FDMC, simplified, Heun, Van Loan)")
    p.add_argument("--no-ref", action="store_true",
                   help="skip the (slow) Python reference runs of the pendulum variants")
    p.add_argument("--no-qemu", action="store_true", help="skip the Cortex-M4F count")
    p.add_argument("--no-fixed", action="store_true",
                   help="skip the leg's fixed-point emulation (about a minute)")
    p.add_argument("--jobs", type=int, default=None,
                   help="parallel processes of the pendulum variants (default 2; robustness and "
                        "leg run in one process)")
    p.add_argument("--seed", type=argtypes.seed, default=0, help="noise seed of the synthetic trials")
    p.add_argument("--json", action="store_true", help="one JSON object on stdout")
    p.set_defaults(func=run)


def _clean(o):
    """JSON-safe: NaN/inf -> None, numpy scalars -> Python."""
    if isinstance(o, dict):
        return {str(k): _clean(v) for k, v in o.items()}
    if isinstance(o, (list, tuple)):
        return [_clean(v) for v in o]
    if hasattr(o, "item") and not isinstance(o, (str, bytes)):
        o = o.item()
    if isinstance(o, float) and not math.isfinite(o):
        return None
    return o


def run(args) -> int:
    parts = [p.strip() for p in args.parts.split(",") if p.strip()]
    bad = [p for p in parts if p not in PARTS]
    if bad or not parts:
        raise KinefuseError(f"unknown part {', '.join(bad) or '(none)'}; choose from "
                            f"{', '.join(PARTS)}")
    if args.jobs is not None and args.jobs < 1:
        raise KinefuseError("--jobs must be at least 1")
    jobs = 2 if args.jobs is None else args.jobs
    # options of a part that is not run: refused, not ignored
    unused = [o for o, part, given in (("--variants", "pendulum", args.variants != "all"),
                                       ("--no-ref", "pendulum", args.no_ref),
                                       ("--no-qemu", "leg", args.no_qemu),
                                       ("--no-fixed", "leg", args.no_fixed))
              if given and part not in parts]
    if unused:
        raise KinefuseError(f"{', '.join(unused)}: option(s) of a part not run (--parts "
                            f"{','.join(parts)}); --variants and --no-ref apply to pendulum, "
                            f"--no-qemu and --no-fixed to leg")
    if args.jobs is not None and "pendulum" not in parts:
        # a harmless speed option: said, not refused (robustness and leg are sequential)
        print(f"kinefuse: note: --jobs applies to the pendulum part only; --parts "
              f"{','.join(parts)} runs in one process", file=sys.stderr)
    from kinefuse.host.bench.common import progress
    from kinefuse.host.dynamics import bench as B
    result: dict = {}
    with progress(True) as bar:
        if "pendulum" in parts:
            # plant noise chosen on another truth seed, then the table on the scored seed
            result["pendulum_tuning"] = B.tuning(bar, args.seed)
            result["pendulum"] = B.pendulum_table(args.variants, jobs, not args.no_ref, bar,
                                                  args.seed, result["pendulum_tuning"]["q_used"])
        if "robustness" in parts:
            result["robustness"] = B.robustness(bar, args.seed)
        if "leg" in parts:
            result["leg"] = B.leg_study(bar, qemu=not args.no_qemu, seed=args.seed,
                                        fixed=not args.no_fixed)
    result = _clean(result)
    if args.json:
        print(json.dumps(result))
        return 0
    _print(result)
    return 0


#: what the pendulum table's numbers are (RMS over the samples after the first, as Annex A)
PENDULUM_UNITS = ("RMS z over its components x0, y0 (m), θ1, θ2 (rad); RMS ż over ẋ0, ẏ0 (m/s), "
                  "θ̇1, θ̇2 (rad/s); RMS F_e over the four efforts (N·m, N, N, N·m); RMS τ1 in "
                  "N·m; RT: real-time factor (trial duration / computing time); ops: operations "
                  "per filter step")


def _f(v, fmt="{:.4f}"):
    return "-" if v is None else fmt.format(v)


def _print(r: dict) -> None:
    from rich.console import Console
    from rich.table import Table
    con = Console()
    if "pendulum" in r:
        t = Table(title="Double pendulum, seed 000 Annex A (Table A.1 trial, 3 s at 100 Hz): "
                        "reference (float64 Python) | generated float32 C",
                  caption=PENDULUM_UNITS, caption_justify="left")
        for c in ("int.", "Φ", "Σ", "sens.", "RMS z", "RMS ż", "RMS F_e", "RMS τ1", "RT ref",
                  "RMS F_e f32", "RT f32 C", "ops"):
            t.add_column(c, justify="right")
        for row in r["pendulum"]:
            t.add_row(row["integrator"].upper(), row["phi"].upper(), row["sigma"].upper(),
                      row["sensitivity"][:4], _f(row["rms_z"]), _f(row["rms_zdot"]),
                      _f(row["rms_fe"], "{:.3f}"), _f(row["rms_tau1"], "{:.2f}"),
                      _f(row["rt_factor_ref"], "{:.2f}"), _f(row["f32"]["rms_fe"], "{:.3f}"),
                      _f(row["rt_factor_f32_c"], "{:,.0f}"), str(row["ops"]))
        print_table(t, con)
        tu = r.get("pendulum_tuning")
        if tu:
            con.print(f"Plant PSD of the efforts (FDMC, f32 C), tuned on seed {tu['tuning_seed']}: "
                      + ", ".join(f"q={s['q']:g}: RMS F_e {s['rms_fe']:.2f}"
                                  for s in tu["sweep"])
                      + f"  -> used q = {tu['q_used']:g} (N^2/s, (N*m)^2/s)"
                      + (" (at the edge of the search)" if tu["at_edge"] else ""))
            con.print(f"  same sweep on the scored seed {tu['scored_seed']} (not used): "
                      + ", ".join(f"q={s['q']:g}: {s['rms_fe']:.2f}"
                                  for s in tu["scored_seed_sweep"]))
    if "robustness" in r:
        rb = r["robustness"]
        tn = rb["tuning"]
        con.print(f"Robustness tuning on seed {tn['tuning_seed']}: FDMC q = {tn['fd_q']:g}"
                  + (" (at the edge of the search)" if tn["fd_q_at_edge"] else "")
                  + f", FCDI sigma_a = {tn['fcdi_sigma_a']:g}"
                  + (" (at the edge of the search)" if tn["fcdi_sigma_a_at_edge"] else ""))
        t = Table(title=f"Robustness, seed 000 §3.3.4 — {rb['trial']}")
        t.add_column("study")
        t.add_column("dynamic EKF (FDMC)", justify="right")
        t.add_column("FDMC + residual low/high (occlusion: FDMC, other q)", justify="right")
        t.add_column("FCDI", justify="right")
        for label in ("true_masses", "observer_60_15"):
            m = rb["mass_misdistribution"][label]
            t.add_row(f"τ1 RMSE (N·m), {label.replace('_', ' ')}", _f(m["fd_tau1_rmse"], "{:.2f}"),
                      f"{_f(m['fd_residual_low_tau1_rmse'], '{:.2f}')} / "
                      f"{_f(m['fd_residual_high_tau1_rmse'], '{:.2f}')}",
                      _f(m["fcdi_tau1_rmse"], "{:.2f}"))
        oc = rb["occlusion"]
        rows = (("theta1_max_abs_error_rad", "occlusion: max |θ1 error| (rad)", "{:.4f}"),
                ("theta1dot_max_abs_error_rad_s", "occlusion: max |θ̇1 error| (rad/s)",
                 "{:.2f}"),
                ("tau1_rmse_during_nm", "occlusion: τ1 RMSE during (N·m)", "{:.2f}"),
                ("tau1_rmse_500ms_after_nm", "occlusion: τ1 RMSE 0.5 s after", "{:.2f}"),
                ("tau1_rmse_trial_nm", "occlusion: τ1 RMSE whole trial", "{:.2f}"),
                ("tau1_rmse_trial_without_occlusion_nm", "no occlusion: τ1 RMSE whole trial",
                 "{:.2f}"),
                ("tau1_reconvergence_s", "occlusion: τ1 reconvergence (s)", "{:.2f}"),
                ("theta1_reconvergence_s", "occlusion: θ1 reconvergence (s)", "{:.2f}"))
        for key, label, fmt in rows:
            t.add_row(label, _f(oc["fd"][key], fmt),
                      f"(q={oc['q_of_fd_q_annex_a']:g}: {_f(oc['fd_q_annex_a'][key], fmt)})",
                      _f(oc["fcdi"][key], fmt))
        print_table(t, con)
        ob = rb["observability"]
        con.print("Observability rank: " + ", ".join(
            f"{k}: {v['rank']}/{v['n']}" for k, v in ob.items() if isinstance(v, dict)))
    if "leg" in r:
        lg = r["leg"]
        t = Table(title=f"Wearable leg — {lg['trial']}")
        t.add_column("case")
        for c in ("hip RMSE N·m", "knee RMSE N·m", "hip lag ms", "knee lag ms"):
            t.add_column(c, justify="right")
        for label, m in (("RK4 float32 C", lg["f32"]), ("RK4 reference", lg["ref"]),
                         ("forward Euler (f32 C)", lg["forward_euler"]),
                         ("gyroscopes only (f32 C)", lg["gyroscopes_only"]),
                         ("with ankle force sensor", lg["foot_sensor"]),
                         ("faster gait 1.4 Hz (f32 C)", lg["faster_gait_1p4hz"]["f32"]),
                         ("faster gait 1.4 Hz (reference)", lg["faster_gait_1p4hz"]["ref"])):
            t.add_row(label, _f(m["hip_rmse_nm"], "{:.3f}"), _f(m["knee_rmse_nm"], "{:.3f}"),
                      _f(m["hip_lag_ms"], "{:.1f}"), _f(m["knee_lag_ms"], "{:.1f}"))
        print_table(t, con)
        con.print("Observability rank: " + ", ".join(
            f"{k}: {v['rank']}/{v['n']}" for k, v in lg["observability"].items()))
        con.print(f"float32 C vs reference: max {lg['f32_vs_ref_max_nm']:.2e} N·m; "
                  f"Cortex-M4F instructions per step: "
                  f"{_f(lg['m4f_instructions_per_step'], '{:,.0f}')}")
        fx = lg.get("fixed_point")
        if fx:
            con.print(f"Fixed point: generator: {fx['generator']}")
            for o in fx["oracle_fixed_point"]:
                fg = o["same_formats_on_a_faster_gait_1p4hz"]
                con.print(f"  oracle Q formats (observed range x{o['margin']:g}, fractional bits "
                          f"{o['fractional_bits_range'][0]}..{o['fractional_bits_range'][1]}): "
                          f"max torque deviation {_f(o['max_torque_error_nm'], '{:.2e}')} N·m; "
                          f"same formats on a faster gait: "
                          f"{_f(fg['max_torque_error_nm'], '{:.2e}')} N·m, {fg['resets']} resets")
