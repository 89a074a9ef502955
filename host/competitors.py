"""Other people's orientation filters, run on a :class:`~kinefuse.host.broad.Trial` for comparison.

Every runner returns quaternions (w, x, y, z) rotating sensor coordinates into the earth frame
East-North-Up, one row per input sample - the convention of the BROAD reference - whatever the
library's own convention is.  The conversions below were established by reproducing the BROAD
scores in ``notes/broad.md`` (see ``host/data/broad_excerpt/README.md`` and the tests):

* ``vqf`` (VQF, BasicVQF, offline VQF): already sensor -> ENU, no conversion.
* ``imufusion`` (x-io Fusion 1.3.x): sensor -> North-West-Up; its ``convention`` setting is silently
  ignored by the Python binding, so we rotate NWU -> ENU ourselves (+90° about Up).
* ``ahrs`` Madgwick: sensor -> NWU (magnetic reference (bx, 0, bz)); rotated like Fusion.
* ``ahrs`` Mahony: sensor -> ENU (magnetic reference (0, by, bz)); no conversion.
* ``ahrs`` EKF: run in its NED mode with the accelerometer negated, rotated NED -> ENU.
* ``ahrs`` AQUA: earth -> sensor (inverse) of NWU; conjugated, then rotated like Fusion.

Inputs are converted to each library's units (Fusion: °/s and g; others rad/s and m/s²;
magnetometer µT, which all of them normalise).
"""
from __future__ import annotations

import dataclasses
import importlib
import math
import time
from typing import Callable

import numpy as np

from kinefuse.host.errors import KinefuseError
from kinefuse.host.metrics import quat_conj, quat_mul

STANDARD_GRAVITY = 9.80665  # m/s², only to express acceleration in g for Fusion (it normalises)
#: Rotation of +90° about the vertical axis: q_enu = Q_NWU_TO_ENU ⊗ q_nwu.
Q_NWU_TO_ENU = np.array([math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)])
#: Rotation NED -> ENU (180° about the horizontal axis half-way between north and east).
Q_NED_TO_ENU = np.array([0.0, math.sqrt(0.5), math.sqrt(0.5), 0.0])


@dataclasses.dataclass
class CompetitorResult:
    """Same shape as the lead's FilterResult: quaternions and optional boolean status series."""

    q: np.ndarray                                   # (N,4) w,x,y,z sensor -> ENU
    status: dict[str, np.ndarray] = dataclasses.field(default_factory=dict)


@dataclasses.dataclass(frozen=True)
class Competitor:
    name: str
    module: str                    # Python module that must be importable (PyPI package)
    pip: str                       # what to install
    description: str               # one line: what it is and which settings
    run: Callable                  # (trial, params, status) -> CompetitorResult
    params: dict[str, float]       # tunable settings and the defaults used (for --param)
    nine_d: bool = True            # False: heading is not referenced to north (score inclination only)


def mag_readings(trial, hold: bool = False) -> np.ndarray:
    """The magnetometer as the competitors get it: zero on the samples that carry no new reading
    (a simulator trial's ``mag_valid``), where VQF, Fusion and ahrs all skip their magnetometer
    step - as our filters do.  (They got the held last reading again, or the zeros of a sensor
    without a magnetometer, as a new reading on every sample.)  ``hold``: for ahrs' EKF, which
    refuses a zero field and has no step without it, the last reading (the first before it)."""
    mag = np.asarray(trial.mag, dtype=np.float64)
    valid = getattr(trial, "mag_valid", None)
    if valid is None:
        return mag
    valid = np.asarray(valid, dtype=bool)
    if not hold:
        return np.where(valid[:, None], mag, 0.0)
    if not valid.any():
        raise KinefuseError(f"{trial.name} has no magnetometer reading, which ahrs' EKF needs")
    last = np.maximum.accumulate(np.where(valid, np.arange(len(valid)), -1))
    return mag[np.where(last < 0, int(np.argmax(valid)), last)]


def _check_params(comp_name: str, allowed: dict, params: dict | None) -> dict:
    params = dict(params or {})
    unknown = sorted(set(params) - set(allowed))
    if unknown:
        known = ", ".join(sorted(allowed)) or "none"
        raise KinefuseError(f"{comp_name}: unknown parameter {', '.join(unknown)} (known: {known})")
    return {**allowed, **params}


# ---------------------------------------------------------------------------------------------
# VQF (Laidig & Seel, Information Fusion 2023), C++ through Cython; output sensor -> ENU.

_VQF_PARAMS = {  # VQF's own defaults (VQFParams), kept here so that --param can list them
    "tauAcc": 3.0, "tauMag": 9.0, "motionBiasEstEnabled": 1.0, "restBiasEstEnabled": 1.0,
    "magDistRejectionEnabled": 1.0, "restThGyr": 2.0, "restThAcc": 0.5, "restMinT": 1.5,
}
_VQF_BOOL = {"motionBiasEstEnabled", "restBiasEstEnabled", "magDistRejectionEnabled"}


def _vqf_kwargs(p: dict) -> dict:
    for k in _VQF_BOOL:
        if p[k] not in (0, 1):
            raise KinefuseError(f"vqf: parameter {k}={p[k]!r} is a switch: 0 or 1")
    return {k: (bool(v) if k in _VQF_BOOL else float(v)) for k, v in p.items()}


def _run_vqf(trial, params, status, *, variant="9d"):
    import vqf

    p = _vqf_kwargs(_check_params("vqf", _VQF_PARAMS, params))
    gyr, acc, mag = (np.ascontiguousarray(a, dtype=np.float64)
                     for a in (trial.gyr, trial.acc, mag_readings(trial)))
    out = vqf.VQF(trial.dt, **p).updateBatch(gyr, acc, mag)
    q = out["quat6D"] if variant == "6d" else out["quat9D"]
    st = {"rest": np.asarray(out["restDetected"], dtype=bool)}
    if variant == "9d":
        st["mag_disturbed"] = np.asarray(out["magDistDetected"], dtype=bool)
    return CompetitorResult(np.asarray(q, dtype=np.float64), st if status else {})


_BASICVQF_PARAMS = {"tauAcc": 3.0, "tauMag": 9.0}


def _run_basicvqf(trial, params, status):
    import vqf

    p = _check_params("vqf-basic", _BASICVQF_PARAMS, params)
    gyr, acc, mag = (np.ascontiguousarray(a, dtype=np.float64)
                     for a in (trial.gyr, trial.acc, mag_readings(trial)))
    out = vqf.BasicVQF(trial.dt, **{k: float(v) for k, v in p.items()}).updateBatch(gyr, acc, mag)
    return CompetitorResult(np.asarray(out["quat9D"], dtype=np.float64))


def _run_offline_vqf(trial, params, status):
    import vqf

    p = _vqf_kwargs(_check_params("vqf-offline", _VQF_PARAMS, params))
    gyr, acc, mag = (np.ascontiguousarray(a, dtype=np.float64)
                     for a in (trial.gyr, trial.acc, mag_readings(trial)))
    out = vqf.offlineVQF(gyr, acc, mag, trial.dt, p)
    st = {"rest": np.asarray(out["restDetected"], dtype=bool),
          "mag_disturbed": np.asarray(out["magDistDetected"], dtype=bool)} if status else {}
    return CompetitorResult(np.asarray(out["quat9D"], dtype=np.float64), st)


# ---------------------------------------------------------------------------------------------
# x-io Fusion (imufusion 1.3.x): C, one Python call per sample; output sensor -> NWU.

#: Settings of Fusion's README / advanced example: gain 0.5, ±2000 °/s gyroscope range,
#: 10° acceleration and magnetic rejection, rejection timeout 5 s.
FUSION_README = {"gain": 0.5, "gyroscope_range": 2000.0, "acceleration_rejection": 10.0,
                 "magnetic_rejection": 10.0, "rejection_timeout": 5.0}
#: Best single gain found on BROAD (notes/broad.md): 0.1 with rejection disabled.
FUSION_BEST = {"gain": 0.1, "gyroscope_range": 2000.0, "acceleration_rejection": 0.0,
               "magnetic_rejection": 0.0, "rejection_timeout": 0.0}


def _run_fusion(trial, params, status, *, name="imufusion", defaults=FUSION_README, bias=False):
    import imufusion

    p = _check_params(name, defaults, params)
    ahrs = imufusion.Ahrs()
    # convention is passed for documentation only: 1.3.x ignores it and always works in NWU
    ahrs.set_settings(imufusion.AhrsSettings(
        sample_rate=float(trial.rate_hz), convention=imufusion.CONVENTION_NWU,
        gain=float(p["gain"]), gyroscope_range=float(p["gyroscope_range"]),
        acceleration_rejection=float(p["acceleration_rejection"]),
        magnetic_rejection=float(p["magnetic_rejection"]),
        rejection_timeout=float(p["rejection_timeout"])))
    offset = None
    if bias:
        offset = imufusion.Bias()
        offset.set_settings(imufusion.BiasSettings(sample_rate=float(trial.rate_hz)))
    gyr = np.ascontiguousarray(np.degrees(trial.gyr))          # °/s
    acc = np.ascontiguousarray(trial.acc / STANDARD_GRAVITY)   # g
    mag = np.ascontiguousarray(mag_readings(trial))            # µT (Fusion: arbitrary units)
    n = trial.n
    q = np.empty((n, 4))
    acc_rej = np.zeros(n, dtype=bool) if status else None
    mag_rej = np.zeros(n, dtype=bool) if status else None
    for i in range(n):
        g = offset.update(gyr[i]) if offset is not None else gyr[i]
        ahrs.update(g, acc[i], mag[i])
        q[i] = ahrs.get_quaternion()
        if status:
            s = ahrs.get_internal_states()
            acc_rej[i] = s.accelerometer_ignored
            mag_rej[i] = s.magnetometer_ignored
    st = {"acc_rejected": acc_rej, "mag_rejected": mag_rej} if status else {}
    return CompetitorResult(quat_mul(Q_NWU_TO_ENU, q), st)


# ---------------------------------------------------------------------------------------------
# ahrs (pure Python, Garcia): batch constructors compute .Q for the whole trial.

def _run_ahrs_madgwick(trial, params, status):
    from ahrs.filters import Madgwick

    p = _check_params("ahrs-madgwick", {"gain": 0.041}, params)
    # Madgwick's MARG update references gravity (0,0,1) and the field (bx,0,bz): earth = NWU
    Q = Madgwick(gyr=trial.gyr, acc=trial.acc, mag=mag_readings(trial), frequency=trial.rate_hz,
                 gain=float(p["gain"])).Q
    return CompetitorResult(quat_mul(Q_NWU_TO_ENU, Q))


def _run_ahrs_mahony(trial, params, status):
    from ahrs.filters import Mahony

    p = _check_params("ahrs-mahony", {"k_P": 1.0, "k_I": 0.3}, params)
    # Mahony's MARG update references the field as (0, by, bz): earth = ENU already
    Q = Mahony(gyr=trial.gyr, acc=trial.acc, mag=mag_readings(trial), frequency=trial.rate_hz,
               k_P=float(p["k_P"]), k_I=float(p["k_I"])).Q
    return CompetitorResult(np.asarray(Q, dtype=np.float64))


EKF_WMM_DATE = (2026, 12, 3)   # the date of the README's ahrs EKF scores


def ekf_magnetic_reference():
    """ahrs' default EKF reference (WMM at Munich, NED, nT) on EKF_WMM_DATE."""
    import datetime

    from ahrs.common.constants import MUNICH_HEIGHT, MUNICH_LATITUDE, MUNICH_LONGITUDE
    from ahrs.utils.wmm import WMM
    wmm = WMM(date=datetime.date(*EKF_WMM_DATE), latitude=MUNICH_LATITUDE,
              longitude=MUNICH_LONGITUDE, height=MUNICH_HEIGHT)
    return np.array([wmm.X, wmm.Y, wmm.Z])


def _run_ahrs_ekf(trial, params, status):
    from ahrs.filters import EKF

    p = _check_params("ahrs-ekf", {"var_gyr": 0.3 ** 2, "var_acc": 0.5 ** 2, "var_mag": 0.8 ** 2},
                      params)
    # ahrs' EKF predicts the accelerometer as R^T·(0,0,1) in its NED mode: gravity (down), not
    # the specific force an accelerometer measures (+g upward at rest, as in BROAD).  Feeding
    # -acc makes the measurement model and its ecompass initialisation consistent; the output
    # is sensor -> NED.  (In ENU mode -acc fixes the model but starts the filter upside down.)
    # Its magnetic reference is ahrs' default, WMM at Munich (with declination), but on a fixed
    # date: the default is today's, so the score changed from run to run.
    Q = EKF(gyr=trial.gyr, acc=-trial.acc, mag=mag_readings(trial, hold=True),
            frequency=trial.rate_hz, frame="NED", var_gyr=float(p["var_gyr"]),
            var_acc=float(p["var_acc"]), var_mag=float(p["var_mag"]),
            magnetic_ref=ekf_magnetic_reference()).Q
    return CompetitorResult(quat_mul(Q_NED_TO_ENU, np.asarray(Q, dtype=np.float64)))


def _run_ahrs_aqua(trial, params, status):
    from ahrs.filters import AQUA

    p = _check_params("ahrs-aqua", {"alpha": 0.01, "beta": 0.01, "adaptive": 0.0}, params)
    Q = AQUA(gyr=trial.gyr, acc=trial.acc, mag=mag_readings(trial), frequency=trial.rate_hz,
             alpha=float(p["alpha"]), beta=float(p["beta"]), adaptive=bool(p["adaptive"])).Q
    # AQUA's quaternion is the inverse rotation (earth -> sensor) of an NWU earth frame
    return CompetitorResult(quat_mul(Q_NWU_TO_ENU, quat_conj(np.asarray(Q, dtype=np.float64))))


def _registry() -> dict[str, Competitor]:
    def fusion(name, defaults, bias):
        return lambda trial, params, status: _run_fusion(trial, params, status, name=name,
                                                         defaults=defaults, bias=bias)

    comps = [
        Competitor("vqf", "vqf", "vqf", "VQF 9D (Laidig & Seel 2023), default parameters",
                   lambda t, p, s: _run_vqf(t, p, s, variant="9d"), _VQF_PARAMS),
        Competitor("vqf-6d", "vqf", "vqf",
                   "VQF 6D (no magnetometer), default parameters; heading not north-referenced",
                   lambda t, p, s: _run_vqf(t, p, s, variant="6d"), _VQF_PARAMS, nine_d=False),
        Competitor("vqf-basic", "vqf", "vqf", "BasicVQF 9D (no bias estimation, no rejection)",
                   _run_basicvqf, _BASICVQF_PARAMS),
        Competitor("vqf-offline", "vqf", "vqf", "offline VQF 9D (non-causal, uses future samples)",
                   _run_offline_vqf, _VQF_PARAMS),
        Competitor("imufusion", "imufusion", "imufusion",
                   "x-io Fusion, README settings (gain 0.5, rejection 10°/10°, timeout 5 s)",
                   fusion("imufusion", FUSION_README, False), FUSION_README),
        Competitor("imufusion-best", "imufusion", "imufusion",
                   "x-io Fusion, best gain on BROAD (gain 0.1, no rejection)",
                   fusion("imufusion-best", FUSION_BEST, False), FUSION_BEST),
        Competitor("imufusion-bias", "imufusion", "imufusion",
                   "x-io Fusion, README settings plus its gyroscope bias (offset) correction",
                   fusion("imufusion-bias", FUSION_README, True), FUSION_README),
        Competitor("ahrs-madgwick", "ahrs", "ahrs", "Madgwick MARG (ahrs package), gain 0.041",
                   _run_ahrs_madgwick, {"gain": 0.041}),
        Competitor("ahrs-ekf", "ahrs", "ahrs",
                   "EKF (ahrs package), accelerometer sign fixed, default noises and magnetic reference",
                   _run_ahrs_ekf, {"var_gyr": 0.09, "var_acc": 0.25, "var_mag": 0.64}),
        Competitor("ahrs-aqua", "ahrs", "ahrs", "AQUA (Valenti et al. 2015, ahrs package)",
                   _run_ahrs_aqua, {"alpha": 0.01, "beta": 0.01, "adaptive": 0.0}),
        Competitor("ahrs-mahony", "ahrs", "ahrs", "Mahony MARG (ahrs package), k_P 1.0, k_I 0.3",
                   _run_ahrs_mahony, {"k_P": 1.0, "k_I": 0.3}),
    ]
    return {c.name: c for c in comps}


COMPETITORS: dict[str, Competitor] = _registry()


def competitor_names() -> list[str]:
    return list(COMPETITORS)


def is_competitor(name: str) -> bool:
    return name in COMPETITORS


def get(name: str) -> Competitor:
    try:
        return COMPETITORS[name]
    except KeyError:
        raise KinefuseError(f"unknown competitor {name!r} (known: {', '.join(COMPETITORS)})") from None


def available(name: str) -> bool:
    """True if the package the competitor needs is installed."""
    try:
        importlib.import_module(get(name).module)
        return True
    except ImportError:
        return False


def require(name: str) -> Competitor:
    comp = get(name)
    if not available(name):
        raise KinefuseError(f"{name} needs the Python package {comp.pip!r} "
                            f"(pip install {comp.pip}, or pip install 'kinefuse[bench]')")
    return comp


def run_competitor(name: str, trial, params: dict[str, float] | None = None,
                   status: bool = True) -> CompetitorResult:
    """Run competitor ``name`` on ``trial``; quaternions w,x,y,z sensor -> ENU, one per sample."""
    comp = require(name)
    if getattr(trial, "steps", None) is not None:
        # (ran at the nominal rate while our filters integrated the trial's own time steps)
        raise KinefuseError(f"{name} runs at one constant sample rate; {trial.name} has sample "
                            f"times of its own (jitter, drops or gaps), which it cannot take")
    res = comp.run(trial, params, status)
    q = np.asarray(res.q, dtype=np.float64)
    if q.shape != (trial.n, 4):
        raise KinefuseError(f"{name} returned {q.shape} quaternions for {trial.n} samples")
    res.q = q
    return res


def samples_per_s(name: str, trial, max_samples: int | None = None, repeat: int = 3) -> float:
    """Throughput of competitor ``name`` in samples per second on ``trial`` (best of ``repeat``).

    Measured through each library's Python interface as a user would call it: VQF processes the
    whole batch in C++, Fusion is called once per sample from Python, ``ahrs`` is pure Python.
    Status outputs are not collected.  ``max_samples`` limits the work for slow filters.
    """
    require(name)
    if max_samples is not None and max_samples < trial.n:
        trial = trial.window(0, max_samples)
    best = math.inf
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter()
        COMPETITORS[name].run(trial, None, False)
        best = min(best, time.perf_counter() - t0)
    return trial.n / best
