"""``kinefuse bench seed001``: the ChakaMo hinge-board protocol (seed 001, §7.2) in simulation.

Seed 001 compares four filters on two MetaMotionR units (BMI160 + BMM150; accelerometer and
gyroscope at 100 Hz, magnetometer at 20 Hz) taped to a hinged board:

* static test: the board held at 0/30/45/60/90° about the hinge (sensor x, "roll") for 60 s;
  analysed from 25 s to 45 s of each hold (seed §7.5);
* dynamic tests: 30 s rest at 0°, ten 0→90→0° cycles at 45 °/s ("slow") and at 90 °/s ("fast"),
  30 s rest; compared through the mean angles of the 20 s before and after the motion.

Here the motion, the sensors and the site are simulated (:mod:`kinefuse.hil_tests.sim`):
scenario ``hinge_protocol`` (hinge about the earth's x = East), the sensor on the moving board,
MetaMotionR noise of Table 7.2 per unit (DA, C8), the Montevideo field (22.6 µT, dip −36°),
no calibration error.  The ground truth replaces the seed's "theoretical" quaternion (TEO).

Reported, as in the seed's tables (degrees, per axis X/Y/Z = roll/pitch/yaw, ZYX Euler angles of
the error quaternion q_i ⊗ q_j*, eq. 7.3):
  Table 7.3   standard deviation of each filter's angles in the static windows (mean of holds);
  Tables 7.4-7.8  RMSE filter vs truth and filter vs filter in each static window;
  Tables 7.9/7.10 |mean after − mean before| of each filter's angles around the dynamic motion;
  plus the RMSE vs truth during the dynamic motion (not available to the seed).
Filters: Madgwick, VAC, VAK, GUO with the seed's parameters (preset ``seed001``) and the
flagship filter (defaults) when registered; ``--params default`` runs every filter with its
defaults instead.
"""
from __future__ import annotations

import json
import time

import numpy as np

from kinefuse.host.bench.common import progress
from kinefuse.host.errors import KinefuseError
from kinefuse.host.console import print_table
from kinefuse.host import argtypes

SEED_FILTERS = ("madgwick", "vac", "vak", "guo")
LABELS = {"madgwick": "MAD", "vac": "VAC", "vak": "VAK", "guo": "GUO", "flagship": "FLAG",
          "truth": "TEO"}
STATIC_DEG = (0.0, 30.0, 45.0, 60.0, 90.0)
WINDOW_S = (25.0, 45.0)        # analysed part of each 60 s hold (seed §7.5)
REST_WINDOW_S = 20.0           # before/after the dynamic motion (seed Tables 7.9/7.10)
TARGET_STATIC_DEG = 0.5        # issue 7: static hinge-axis RMSE for GUO, VAK, flagship
# seed 001 Table 7.2 (static test at 0°): per-axis standard deviations of each unit
UNITS = {
    "DA": {"acc": {"noise_mg": [1.40, 1.40, 1.60]}, "gyr": {"noise_dps": [0.07, 0.05, 0.04]},
           "mag": {"noise_uT": [0.56, 0.48, 0.42]}},
    "C8": {"acc": {"noise_mg": [1.30, 1.30, 1.50]}, "gyr": {"noise_dps": [0.07, 0.05, 0.05]},
           "mag": {"noise_uT": [0.56, 0.49, 0.42]}},
}
MONTEVIDEO = {"field_uT": 22.6, "dip_deg": -36.0, "declination_deg": 0.0}
# the seed's own results (hardware), for orientation only: TEO-filter roll RMSE range, Tables 7.4-7.8
SEED_STATIC_ROLL_RMSE_DEG = (0.45, 6.11)


def register_bench(sub):
    p = sub.add_parser("seed001", help="seed 001 hinge-board protocol (static + dynamic) in "
                                       "simulation: per-axis std, RMSE vs truth and filter vs filter")
    p.add_argument("--impl", default="f32", choices=("ref", "f32", "q"),
                   help="implementation of the filters (default: generated float32 C)")
    p.add_argument("--params", default=None, choices=("seed001", "default"),
                   help="seed001 (the default): the seed's parameter sets (presets); default: our "
                        "defaults")
    p.add_argument("--filters", default=None,
                   help="comma-separated filter names (default: madgwick,vac,vak,guo[,flagship])")
    p.add_argument("--seed", type=argtypes.seed, default=None,
                   help="simulation seed (default 1; unit C8 uses seed + 1)")
    p.add_argument("--hold-s", type=float, default=None,
                   help="static hold duration, s (default and seed: 60; the window is 25-45 s of each hold)")
    p.add_argument("--broad", nargs="?", const="", default=None, metavar="DIR|FILE",
                   help="instead: BROAD accuracy of MAD/VAC/VAK/GUO (our defaults) against the "
                        "ahrs package's Madgwick, AQUA and FKF, same trials, same metric "
                        "(default data: the shared BROAD folder; slow: ahrs is pure Python)")
    p.add_argument("--json", action="store_true", help="one JSON object on stdout")
    p.set_defaults(func=run)


# ------------------------------------------------------------------------------------------------
# geometry

def quat_mul(a, b):
    aw, ax, ay, az = np.moveaxis(np.asarray(a, float), -1, 0)
    bw, bx, by, bz = np.moveaxis(np.asarray(b, float), -1, 0)
    return np.stack([aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw],
                    axis=-1)


def conj(q):
    return np.asarray(q, float) * np.array([1.0, -1.0, -1.0, -1.0])


def euler_zyx_deg(q) -> np.ndarray:
    """(N, 3) roll X, pitch Y, yaw Z in degrees of (N, 4) quaternions (ZYX intrinsic)."""
    q = np.asarray(q, float)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q.T
    roll = np.arctan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y))
    pitch = np.arcsin(np.clip(2.0 * (w * y - z * x), -1.0, 1.0))
    yaw = np.arctan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
    return np.degrees(np.stack([roll, pitch, yaw], axis=1))


def axis_errors_deg(q_i, q_j) -> np.ndarray:
    """Per-axis error (seed eq. 7.3): ZYX Euler angles of q_i ⊗ q_j*, degrees (N, 3)."""
    return euler_zyx_deg(quat_mul(q_i, conj(q_j)))


def rms(a, axis=0):
    return np.sqrt(np.mean(np.asarray(a) ** 2, axis=axis))


# ------------------------------------------------------------------------------------------------
# simulation and windows

def scenario(hold_s: float):
    from kinefuse.hil_tests.sim import library
    from kinefuse.hil_tests.sim.hinge import seed001_steps
    sc = library.scenario("hinge_protocol")
    motion = dict(sc.motion)
    motion["joint"] = seed001_steps(static_s=hold_s)
    return sc.replace(motion=motion, earth=MONTEVIDEO)


def simulate(unit: str, seed: int, hold_s: float):
    """The moving-board unit's recording (noise of seed unit ``unit``)."""
    from kinefuse.hil_tests import sim
    sc = scenario(hold_s)
    sensor = {"preset": "metamotionr"}
    sensor.update(UNITS[unit])
    return sim.simulate(sc, seed=seed, unit="distal", sensor=sensor)


def _runs(mask):
    """(start, stop) index pairs of the True runs of a boolean array."""
    d = np.diff(np.concatenate([[0], mask.astype(np.int8), [0]]))
    return list(zip(np.nonzero(d == 1)[0], np.nonzero(d == -1)[0]))


def static_windows(rec, hold_s: float):
    """{angle: index array} of the analysed part of each static hold (first occurrence)."""
    theta = np.degrees(rec.truth["joint_angle"])
    t = rec.t
    out = {}
    for a in STATIC_DEG:
        runs = [r for r in _runs(np.abs(theta - a) < 1e-6) if t[r[1] - 1] - t[r[0]] >= 0.9 * hold_s]
        if not runs:
            raise KinefuseError(f"seed001: no {a:g}° hold found in the simulated protocol")
        s, e = runs[0]
        t0 = t[s]
        lo, hi = t0 + min(WINDOW_S[0], 0.4 * hold_s), t0 + min(WINDOW_S[1], 0.75 * hold_s)
        out[a] = np.nonzero((t >= lo) & (t < hi))[0]
    return out


def dynamic_segments(rec):
    """[(before, during, after) index arrays] of the dynamic tests: groups of at least ten
    moves (|dθ/dt| > 1 °/s) separated by less than 2 s (the static test's single transitions,
    60 s apart, do not qualify)."""
    theta = np.degrees(rec.truth["joint_angle"])
    t = rec.t
    rate = np.gradient(theta, t)
    runs = _runs(np.abs(rate) > 1.0)
    groups, cur = [], None
    for s, e in runs:
        if cur is not None and t[s] - t[cur[1] - 1] < 2.0:
            cur = (cur[0], e, cur[2] + 1)
        else:
            if cur is not None:
                groups.append(cur)
            cur = (s, e, 1)
    if cur is not None:
        groups.append(cur)
    out = []
    for s, e, moves in groups:
        if moves < 10:
            continue
        ts, te = t[s], t[e - 1]
        before = np.nonzero((t >= ts - REST_WINDOW_S) & (t < ts))[0]
        after = np.nonzero((t > te) & (t <= te + REST_WINDOW_S))[0]
        out.append((before, np.arange(s, e), after))
    return out


# ------------------------------------------------------------------------------------------------
# filters

def filter_list(arg: str | None) -> list[str]:
    from kinefuse.codegen import estimators
    names = list(SEED_FILTERS) + (["flagship"] if "flagship" in estimators.ESTIMATORS else [])
    if arg is not None:
        names = [n.strip() for n in arg.split(",") if n.strip()]
        if not names:
            raise KinefuseError(f"--filters {arg!r}: names no filter (comma-separated names, e.g. "
                                f"{','.join(SEED_FILTERS)})")
    from kinefuse.host.bench.common import no_repeats
    no_repeats("--filters", names)      # (the filter ran twice, its column shown once)
    for n in names:
        if n not in estimators.ESTIMATORS:
            raise KinefuseError(f"unknown filter {n!r} (available: {', '.join(estimators.ESTIMATORS)})")
        if estimators.ESTIMATORS[n].inputs.name != "imu":
            raise KinefuseError(f"filter {n!r} does not take IMU samples")
    return names


def filter_params(name: str, which: str) -> tuple[dict, str]:
    from kinefuse.codegen import estimators
    est = estimators.get(name)
    if which == "seed001" and "seed001" in est.presets:
        return est.resolve_params(None, "seed001"), "seed001"
    return est.resolve_params(None), "default"


def run_filter(name: str, impl: str, rec, params: dict) -> np.ndarray:
    from kinefuse.codegen import runner
    inputs = {"gyr": rec.gyr, "acc": rec.acc, "mag": rec.mag, "mag_valid": rec.mag_valid,
              "dt": rec.dt}
    q = np.asarray(runner.run(name, impl, inputs, params)["q"], float)
    if not np.all(np.isfinite(q)):
        raise KinefuseError(f"seed001: filter {name} ({impl}) produced non-finite output")
    return q


# ------------------------------------------------------------------------------------------------
# the tables

def unit_tables(rec, qs: dict[str, np.ndarray], hold_s: float) -> dict:
    names = list(qs)
    truth = rec.q_true
    wins = static_windows(rec, hold_s)
    std = {n: np.mean([np.std(euler_zyx_deg(qs[n][idx]), axis=0) for idx in wins.values()],
                      axis=0).tolist() for n in names}
    static = {}
    for a, idx in wins.items():
        rows = {}
        for n in names:
            rows[f"TEO-{LABELS.get(n, n)}"] = rms(axis_errors_deg(qs[n][idx], truth[idx])).tolist()
        for i, n in enumerate(names):
            for m in names[i + 1:]:
                rows[f"{LABELS.get(n, n)}-{LABELS.get(m, m)}"] = \
                    rms(axis_errors_deg(qs[n][idx], qs[m][idx])).tolist()
        static[f"{a:g}"] = rows
    dyn = []
    for before, during, after in dynamic_segments(rec):
        rate = float(np.nanmax(np.abs(np.gradient(np.degrees(rec.truth["joint_angle"][during]),
                                                   rec.t[during]))))
        item = {"rate_dps": round(rate, 1), "mean_diff": {}, "rmse_vs_truth": {}}
        for n in names:
            e = euler_zyx_deg(qs[n])
            item["mean_diff"][LABELS.get(n, n)] = np.abs(e[after].mean(axis=0)
                                                         - e[before].mean(axis=0)).tolist()
            item["rmse_vs_truth"][LABELS.get(n, n)] = \
                rms(axis_errors_deg(qs[n][during], truth[during])).tolist()
        dyn.append(item)
    return {"std": {LABELS.get(n, n): v for n, v in std.items()}, "static_rmse": static,
            "dynamic": dyn}


SIM_DEFAULTS = {"params": "seed001", "seed": 1, "hold_s": 60.0}


def run(args) -> int:
    if args.broad is not None:
        return run_broad(args)
    for k, v in SIM_DEFAULTS.items():
        if getattr(args, k) is None:
            setattr(args, k, v)
    names = filter_list(args.filters)
    if not (args.hold_s >= 10.0 and np.isfinite(args.hold_s)):     # (inf reached the simulator)
        raise KinefuseError(f"--hold-s {args.hold_s:g}: must be a finite number of seconds, at least 10")
    params = {n: filter_params(n, args.params) for n in names}
    out = {"bench": "seed001", "impl": args.impl, "seed": args.seed, "hold_s": args.hold_s,
           "site": MONTEVIDEO, "sensor": "metamotionr (seed 001 Table 7.2 noise per unit)",
           "filters": {LABELS.get(n, n): {"name": n, "params": params[n][1]} for n in names},
           "units": {}}
    t0 = time.perf_counter()
    with progress() as bar:      # on stderr: --json keeps it
        task = bar.add_task("seed001: simulate and filter", total=len(UNITS) * (len(names) + 1))
        for k, unit in enumerate(UNITS):
            rec = simulate(unit, args.seed + k, args.hold_s)
            bar.advance(task)
            qs = {}
            for n in names:
                qs[n] = run_filter(n, args.impl, rec, params[n][0])
                bar.advance(task)
            out["units"][unit] = unit_tables(rec, qs, args.hold_s)
    # the figure of the issue: static hinge-axis (X) RMSE vs truth, worst hold and unit
    summary = {}
    for n in names:
        lab = LABELS.get(n, n)
        worst = max(out["units"][u]["static_rmse"][a][f"TEO-{lab}"][0]
                    for u in out["units"] for a in out["units"][u]["static_rmse"])
        summary[lab] = {"static_hinge_rmse_max_deg": worst,
                        "meets_0.5deg": bool(worst <= TARGET_STATIC_DEG)}
    out["summary"] = summary
    out["seconds"] = round(time.perf_counter() - t0, 2)
    if args.json:
        print(json.dumps(out))
        return 0
    _print(out)
    return 0


# ------------------------------------------------------------------------------------------------
# BROAD: the seed's filters against the ahrs package's implementations of the same methods

#: kinefuse filter -> the ahrs implementation of the same method (None: ahrs has none)
AHRS_PEERS = {"madgwick": "ahrs-madgwick", "vac": "ahrs-aqua", "vak": None, "guo": "ahrs-fkf"}


def run_ahrs_fkf(trial) -> np.ndarray:
    """ahrs.filters.FKF (Guo's fast KF) with its defaults, as sensor → ENU quaternions.

    Its output maps sensor to North-West-Up, rotated here by +90° about up into ENU.  The frame
    is checked on synthetic data with a known orientation (a resting sensor in random attitudes:
    the converted output is within 0.5° of the truth, the unconverted one 90° off;
    ``host/tests/test_seed001.py``), not chosen by the BROAD score (which agrees: 8.4° over
    the 12 trials, against 179° read as North-East-Down and 89° unrotated).  Its quaternions
    are not normalised (its measurement quaternion has norm 1/4); the metric normalises them."""
    from ahrs.filters import FKF
    from kinefuse.host.competitors import Q_NWU_TO_ENU, mag_readings
    from kinefuse.host.metrics import quat_mul as qm
    if getattr(trial, "steps", None) is not None:   # (as the other competitors: one rate only)
        raise KinefuseError(f"ahrs-fkf runs at one constant sample rate; {trial.name} has sample "
                            f"times of its own (jitter, drops or gaps), which it cannot take")
    # a simulator trial's samples without a new magnetometer reading get the last one (FKF has
    # no step without it; it took whatever the file held there, blank rows included)
    Q = FKF(gyr=trial.gyr, acc=trial.acc, mag=mag_readings(trial, hold=True),
            frequency=trial.rate_hz).Q
    return qm(Q_NWU_TO_ENU, np.asarray(Q, float))


def _score_peer(peer: str, trial) -> dict:
    from kinefuse.host import competitors, metrics
    if peer == "ahrs-fkf":
        q = run_ahrs_fkf(trial)
    else:
        q = competitors.run_competitor(peer, trial, status=False).q
    return metrics.score_trial(q, trial)


def _score_ours(name: str, impl: str, trial) -> dict:
    from kinefuse.host import metrics, runner
    return metrics.score_trial(runner.run_filter(name, impl, trial).q, trial)


def run_broad(args) -> int:
    from kinefuse.host import broad, metrics
    from kinefuse.host.bench.common import trial_files
    import importlib.util
    # the simulation's options do not apply: refused, not ignored
    given = [f"--{k.replace('_', '-')}" for k in SIM_DEFAULTS if getattr(args, k) is not None]
    if given:
        raise KinefuseError(f"{', '.join(given)}: simulation option(s), not used by --broad (which runs "
                            f"the filters with our defaults on BROAD trials)")
    names = filter_list(args.filters)
    if args.filters is not None and any(n not in AHRS_PEERS for n in names):
        raise KinefuseError(f"--filters {args.filters}: --broad compares {', '.join(AHRS_PEERS)} only")
    names = [n for n in names if n in AHRS_PEERS]
    if importlib.util.find_spec("ahrs") is None:
        raise KinefuseError("seed001 --broad needs the ahrs package (pip install ahrs)")
    files, where = trial_files(args.broad or None)
    jobs = [(n, "ours") for n in names] + [(AHRS_PEERS[n], "ahrs") for n in names if AHRS_PEERS[n]]
    scores: dict[str, dict[str, dict]] = {}
    t0 = time.perf_counter()
    with progress() as bar:      # on stderr: --json keeps it
        task = bar.add_task("seed001 --broad", total=len(files) * len(jobs))
        for f in files:
            trial = broad.load_trial(f)
            for label, kind in jobs:
                sc = _score_ours(label, args.impl, trial) if kind == "ours" else \
                    _score_peer(label, trial)
                scores.setdefault(label, {})[trial.name] = sc
                bar.advance(task)
    means = {k: metrics.mean_score(v.values()) for k, v in scores.items()}
    out = {"bench": "seed001-broad", "data": where, "trials": len(files), "impl": args.impl,
           "params": "defaults", "mean": means, "per_trial": scores,
           "pairs": {n: AHRS_PEERS[n] for n in names},
           "seconds": round(time.perf_counter() - t0, 1)}
    if args.json:
        # a NaN score (no movement phase in a trial, or a NaN estimate) printed NaN: not JSON
        print(json.dumps(_nan_to_null(out), allow_nan=False))
        return 0
    print(f"BROAD, {len(files)} trials from {where}: mean RMSE (deg) total / heading / inclination;"
          f" kinefuse filters with their defaults ({args.impl})")
    for n in names:
        m = means[n]
        line = f"  {n:<9} {m['total']:6.2f} {m['heading']:6.2f} {m['inclination']:6.2f}"
        peer = AHRS_PEERS[n]
        if peer:
            p = means[peer]
            line += (f"   {peer:<14} {p['total']:6.2f} {p['heading']:6.2f} {p['inclination']:6.2f}")
        else:
            line += "   (no ahrs implementation of this method)"
        print(line)
    print(f"({out['seconds']} s)")
    return 0


def _fmt(v):
    return f"{v:6.2f}"


def _nan_to_null(v):
    """``v`` with every non-finite float replaced by None (null in JSON)."""
    if isinstance(v, dict):
        return {k: _nan_to_null(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_nan_to_null(x) for x in v]
    if isinstance(v, float) and not np.isfinite(v):
        return None
    return v


def _print(out: dict):
    from rich.console import Console
    from rich.table import Table
    con = Console()
    units = list(out["units"])
    cols = [f"{ax}_{u}" for ax in "XYZ" for u in units]
    con.print(f"[bold]seed 001 hinge protocol, simulated[/] ({out['impl']}; parameters: "
              + ", ".join(f"{k} {v['params']}" for k, v in out["filters"].items())
              + f"; seed {out['seed']}; Montevideo field)")
    con.print("Angles: ZYX Euler of q_i ⊗ q_j* in degrees; X = roll = the hinge axis.")

    def table(title, rows):
        tb = Table(title=title, title_justify="left")
        tb.add_column("")
        for c in cols:
            tb.add_column(f"{c} (°)", justify="right")
        for name, per_unit in rows.items():
            tb.add_row(name, *[_fmt(per_unit[u][i]) for i in range(3) for u in units])
        print_table(tb, con)

    labs = list(out["units"][units[0]]["std"])
    table("Table 7.3 — mean standard deviation, static holds",
          {lab: {u: out["units"][u]["std"][lab] for u in units} for lab in labs})
    for a in out["units"][units[0]]["static_rmse"]:
        rows = {r: {u: out["units"][u]["static_rmse"][a][r] for u in units}
                for r in out["units"][units[0]]["static_rmse"][a]}
        table(f"RMSE, static test at {a}° (seed Tables 7.4-7.8)", rows)
    for k, item in enumerate(out["units"][units[0]]["dynamic"]):
        rate = item["rate_dps"]
        table(f"Dynamic test at {rate:g} °/s — |mean after − mean before| (Tables 7.9/7.10)",
              {lab: {u: out["units"][u]["dynamic"][k]["mean_diff"][lab] for u in units}
               for lab in labs})
        table(f"Dynamic test at {rate:g} °/s — RMSE vs truth during the motion",
              {lab: {u: out["units"][u]["dynamic"][k]["rmse_vs_truth"][lab] for u in units}
               for lab in labs})
    con.print(f"Static hinge-axis RMSE vs truth, worst hold and unit (target <= "
              f"{TARGET_STATIC_DEG}° for GUO, VAK, flagship; the seed measured "
              f"{SEED_STATIC_ROLL_RMSE_DEG[0]}-{SEED_STATIC_ROLL_RMSE_DEG[1]}° on hardware):")
    for lab, s in out["summary"].items():
        con.print(f"  {lab:<5} {s['static_hinge_rmse_max_deg']:6.3f}°")
    con.print(f"({out['seconds']} s)")

