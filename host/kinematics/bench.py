"""``kinefuse bench joint-angles`` — measured figures of the alignment and joint-angle code.

* seed 002 §5.4 misalignment study (λ = 60°, 70°): parabola coefficients vs the published ones,
  and the Y/Z-axis cases;
* seed 001 eqs. 6.1–6.3 as published vs :func:`..joint.joint_quaternion`: angle of the knee
  rotation at the calibration posture (should be 0);
* simulated knee step-up (:func:`..simulate.knee_protocol`: 10 cycles, 10° random sensor
  misalignment on both segments, 1° posture imperfection, gyroscope bias, hard/soft iron,
  noise), ``--runs`` seeds: knee-angle RMSE against the truth after the two-posture
  calibration, and without calibration, through the same report pipeline the CLI uses
  (its default orientation filter, flagship — ``runner.default_filter()`` — in 9-D with the
  figure-eight magnetometer calibration), and with the functional calibration instead of the
  lying posture (:func:`..simulate.squats` trial + standing);
* the independent simulator's walking scenario (``kinefuse.hil_tests.sim`` "gait"), when
  present: knee flexion from its true orientations (convention check) and through the stand-in
  filter.
"""
from __future__ import annotations

import json

import numpy as np

from kinefuse.host.kinematics import alignment, joint, misalignment
from kinefuse.host.kinematics import quat as Q
from kinefuse.host.console import print_table
from kinefuse.host import argtypes
# report and simulate (scipy) are imported on use: `kinefuse --help` must stay fast

PUBLISHED = {60: {"a": 0.01389, "c": 0.05043, "r2": 0.9995}, 70: {"a": 0.02013, "c": 0.1497, "r2": 0.9979}}


def register_bench(sub) -> None:
    p = sub.add_parser("joint-angles", help="joint-angle figures (seed 002 misalignment study, knee step-up RMSE)")
    p.add_argument("--runs", type=argtypes.integer(1, 10_000), default=5, help="simulated step-up sessions")
    p.add_argument("--misalign", type=argtypes.real(0.0, 90.0), default=10.0, help="sensor misalignment (deg)")
    p.add_argument("--posture", type=argtypes.real(0.0, 45.0), default=1.0, help="calibration posture imperfection (deg)")
    p.add_argument("--json", action="store_true", help="print exactly one JSON object")
    p.set_defaults(func=run)


def misalignment_study() -> dict:
    out = {}
    for lam in (60, 70):
        r = misalignment.seed002_study(lam)
        out[str(lam)] = {k: r[k] for k in ("a", "b", "c", "r2", "rmse")} | {"published": PUBLISHED[lam]}
    d = misalignment.SEED002_DELTAS_DEG
    out["Y_axis_max_abs(err-|delta|)"] = float(np.abs(misalignment.flexion_error(60, d, axis="Y") - np.abs(d)).max())
    out["Z_axis_max_err"] = float(misalignment.flexion_error(60, d, axis="Z").max())
    return out


def seed001_errata(seed: int = 0) -> dict:
    """Knee rotation (deg) at the calibration posture with the published eqs. 6.1–6.3."""
    from kinefuse.host.kinematics import simulate
    rng = np.random.default_rng(seed)
    post = simulate.posture_orientations(0.0, rng)
    res = {}
    q_SB = {s: simulate.random_mounting(10.0, rng) for s in ("thigh", "shank")}
    R = {s: Q.to_matrix(q_SB[s]) for s in q_SB}
    q_GS = {s: Q.mul(post[f"standing_{s}"], Q.conj(q_SB[s])) for s in q_SB}
    for conv in ("standard", "madgwick"):
        q = joint.seed001_knee_quaternion(q_GS["thigh"], q_GS["shank"], R["thigh"], R["shank"], convention=conv)
        res[f"published_{conv}_deg"] = float(np.degrees(Q.angle_between(q, Q.identity())))
    q = joint.joint_quaternion(q_GS["thigh"], q_GS["shank"], q_SB["thigh"], q_SB["shank"])
    res["kinefuse_deg"] = float(np.degrees(Q.angle_between(q, Q.identity())))
    res["relative_mounting_deg"] = float(np.degrees(Q.angle_between(q_SB["thigh"], q_SB["shank"])))
    return res


def knee_rmse(runs: int, misalign: float, posture: float) -> dict:
    from kinefuse.host.kinematics import report, simulate
    cal, raw, mount, func = [], [], [], []
    for s in range(runs):
        P = simulate.knee_protocol(seed=s, misalign_deg=misalign, posture_deg=posture)
        pairs = lambda d: (d["thigh"], d["shank"])  # noqa: E731
        r = report.knee_from_recordings(*pairs(P.task), standing=pairs(P.standing), lying=pairs(P.lying),
                                        mag_recordings=pairs(P.mag))
        truth = P.truth.angles_deg[: len(r.t)]
        cal.append(np.sqrt(((r.angles - truth) ** 2).mean(axis=0)))
        sq = simulate.squats(P.q_SB, rng=np.random.default_rng(100 + s))
        rf = report.knee_from_recordings(*pairs(P.task), standing=pairs(P.standing), functional=pairs(sq),
                                         mag_recordings=pairs(P.mag))
        func.append(np.sqrt(((rf.angles - P.truth.angles_deg[: len(rf.t)]) ** 2).mean(axis=0)))
        r0 = report.knee_from_recordings(*pairs(P.task), mag_recordings=pairs(P.mag))
        raw.append(np.sqrt(((r0.angles - truth) ** 2).mean(axis=0)))
        for seg in ("thigh", "shank"):
            a_st = P.standing[seg].acc.mean(axis=0)
            a_ly = P.lying[seg].acc.mean(axis=0)
            mount.append(alignment.mounting_error_deg(alignment.two_posture(a_st, a_ly), P.q_SB[seg]))
    cal, raw, func = np.array(cal), np.array(raw), np.array(func)
    names = ("flexion", "adduction", "internal_rotation")
    return {"runs": runs, "misalignment_deg": misalign, "posture_imperfection_deg": posture,
            "rmse_two_posture_deg": {n: {"mean": float(cal[:, j].mean()), "max": float(cal[:, j].max())}
                                     for j, n in enumerate(names)},
            "rmse_uncalibrated_deg": {n: {"mean": float(raw[:, j].mean()), "max": float(raw[:, j].max())}
                                      for j, n in enumerate(names)},
            "rmse_functional_deg": {n: {"mean": float(func[:, j].mean()), "max": float(func[:, j].max())}
                                    for j, n in enumerate(names)},
            "mounting_error_deg": {"mean": float(np.mean(mount)), "max": float(np.max(mount))}}


def independent_gait() -> dict:
    """Knee flexion on the independent simulator's walking scenario (kinefuse.hil_tests.sim
    "gait", sensors along its segment axes: x forward, y left, z up), with its true sensor
    orientations (checks the conventions) and with the stand-in complementary filter (6-D,
    headings aligned at the start)."""
    try:
        from kinefuse.hil_tests import sim
    except ImportError:
        return {"available": False}
    from kinefuse.host.kinematics import orientation as O
    recs = sim.run("gait", seed=1)
    th, sh = recs["thigh"], recs["shank"]
    truth = np.degrees(th.truth["knee_flexion"])
    q_SB = Q.from_matrix(np.column_stack([[0, 1.0, 0], [0, 0, 1.0], [1.0, 0, 0]]))  # our X,Y,Z in its axes
    out = {"available": True}
    for name, (qt, qs) in {"true_orientations": (th.q_true, sh.q_true),
                           "complementary_filter": (O.complementary_filter(th.t, th.acc, th.gyr),
                                                    O.complementary_filter(sh.t, sh.acc, sh.gyr))}.items():
        bt, bs = alignment.segment_orientation(qt, q_SB), alignment.segment_orientation(qs, q_SB)
        bs = Q.mul(O.yaw_alignment(bt[:100], bs[:100]), bs)
        ang = joint.knee_angles(joint.joint_quaternion(bt, bs))
        out[name] = {"flexion_rmse_deg": float(np.sqrt(np.mean((ang[:, 0] - truth) ** 2))),
                     "max_abs_adduction_deg": float(np.abs(ang[:, 1]).max()),
                     "max_abs_rotation_deg": float(np.abs(ang[:, 2]).max())}
    out["flexion_range_deg"] = float(np.ptp(truth))
    return out


def run(args) -> int:
    from rich.console import Console
    with Console(stderr=True).status("joint-angle benchmark: misalignment study, simulated step-ups, gait"):
        res = {"misalignment_study": misalignment_study(), "seed001_calibration_posture": seed001_errata(),
               "knee_step_up": knee_rmse(args.runs, args.misalign, args.posture),
               "independent_gait": independent_gait()}
    if args.json:
        print(json.dumps(res))
        return 0
    from rich.console import Console
    from rich.table import Table
    c = Console()
    t = Table(title="seed 002 misalignment study: |flexion error| = a·δ² + b·δ + c (δ about arm X)")
    for col in ("λ", "a", "a (seed)", "c", "c (seed)", "R²", "R² (seed)"):
        t.add_column(col)
    for lam in ("60", "70"):
        r = res["misalignment_study"][lam]
        p = r["published"]
        t.add_row(lam + "°", f"{r['a']:.5f}", f"{p['a']:.5f}", f"{r['c']:.5f}", f"{p['c']:.5f}",
                  f"{r['r2']:.4f}", f"{p['r2']:.4f}")
    print_table(t, c)
    ms = res["misalignment_study"]
    c.print(f"about Y: max | |error| − |δ| | = {ms['Y_axis_max_abs(err-|delta|)']:.2e}°; "
            f"about Z: max |error| = {ms['Z_axis_max_err']:.2e}°")
    e = res["seed001_calibration_posture"]
    c.print(f"seed 001 eqs. 6.1–6.3 at the calibration posture (relative mounting "
            f"{e['relative_mounting_deg']:.1f}°): standard conversion {e['published_standard_deg']:.2f}°, "
            f"Madgwick conversion {e['published_madgwick_deg']:.2e}°, kinefuse {e['kinefuse_deg']:.2e}°")
    k = res["knee_step_up"]
    t = Table(title=f"simulated knee step-up, {k['runs']} runs, {k['misalignment_deg']:g}° sensor misalignment, "
                    f"{k['posture_imperfection_deg']:g}° posture error: RMSE vs truth (deg)")
    for col in ("angle", "two-posture mean", "max", "functional mean", "max", "uncalibrated mean", "max"):
        t.add_column(col)
    for n in ("flexion", "adduction", "internal_rotation"):
        a, f, b = k["rmse_two_posture_deg"][n], k["rmse_functional_deg"][n], k["rmse_uncalibrated_deg"][n]
        t.add_row(n, f"{a['mean']:.2f}", f"{a['max']:.2f}", f"{f['mean']:.2f}", f"{f['max']:.2f}",
                  f"{b['mean']:.2f}", f"{b['max']:.2f}")
    print_table(t, c)
    c.print(f"two-posture mounting estimate error: mean {k['mounting_error_deg']['mean']:.2f}°, "
            f"max {k['mounting_error_deg']['max']:.2f}°")
    gi = res["independent_gait"]
    if gi.get("available"):
        c.print(f"independent simulator, walking (knee range {gi['flexion_range_deg']:.0f}°): flexion RMSE "
                f"{gi['true_orientations']['flexion_rmse_deg']:.2e}° from true orientations, "
                f"{gi['complementary_filter']['flexion_rmse_deg']:.2f}° with the stand-in complementary filter")
    return 0
