"""Clinical knee (seed 001 step-up) and elbow (seed 002) reports.

Knee protocol (seed 001 §8.4): magnetometer calibration (figure-eight, 60 s, per sensor),
standing still 30 s, lying supine 30 s, then ≥ 10 step-up cycles; one recording per sensor
and task.  Pipeline, in order — each step is reported in the summary:

1. optional unit calibration files (accel/gyro/mag affine maps) are applied to every sample;
2. magnetometer hard/soft iron from the figure-eight recordings (ellipsoid fit), or from the
   unit file; without either the magnetometer is *not* used (raw hard iron of tens of µT would
   corrupt the heading) and the filter runs in 6-D; nor is it when the calibrated task readings
   do not have the calibration's field norm (±25 %: another sensor's figure-eight), with a warning;
3. sensor-to-segment offsets q_SB from the standing and lying recordings (two-posture method,
   mean accelerometer over the longest static window of each), or functionally from a
   flexion–extension recording and the standing one (X = each sensor's gyroscope principal
   axis, sign towards the sensor's +x, i.e. the sensor mounted roughly along the segment;
   Y = the standing vertical orthogonalised; :func:`.alignment.functional_flexion_axis`
   without orientations, so no common heading is needed; both segments must rotate mainly
   about their medio-lateral axes, as in squats or the step-up task itself); without either
   the sensor axes are taken as the segment axes (seed 001 §8.2 "manual" mounting) —
   flagged in the report;
4. sensor orientations q_GS: the device's own quaternions if present (``orientation="auto"``
   or ``"device"``), else the orientation filter (a parameter; see :mod:`.orientation`) run on
   bias-corrected gyroscope data (bias from static windows);
5. the shank stream is interpolated onto the thigh time base (both recordings are assumed to
   start together, as in a MetaBase session); overlapping span only;
6. heading: with device quaternions or a 6-D filter the two sensors do not share a heading
   reference, so the shank heading is aligned to the thigh's in the standing posture (device
   quaternions) or in the first still period of the task; with a calibrated magnetometer both
   already share magnetic north and nothing is changed;
7. q_joint = q_GB_thigh* ⊗ q_GB_shank and knee angles (convention named in every output);
8. cycles (:mod:`.cycles`), 0–100 % normalisation, mean ± SD, range of motion, outputs:
   ``knee_angles.png``, ``knee_timeseries.csv``, ``knee_cycles.csv``, ``knee_mean_sd.csv``,
   ``knee_summary.md``.
"""
from __future__ import annotations

import contextlib
import os
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from kinefuse.host.calib import gyro as gyro_cal
from kinefuse.host.calib import mag as mag_cal
from kinefuse.host.calib import static as S
from kinefuse.host.calib import unitfile
from kinefuse.host.errors import KinefuseError
from kinefuse.host.kinematics import alignment, cycles, joint
from kinefuse.host.kinematics import orientation as O
from kinefuse.host.kinematics import quat as Q
from kinefuse.host.outputs import staged
from kinefuse.host.readers.recording import Recording


@dataclass
class JointResult:
    t: np.ndarray                  # s, from the start of the overlap
    angles: np.ndarray             # N×3 deg
    columns: tuple
    convention: str                # one-line description for headers
    q_joint: np.ndarray
    info: dict = field(default_factory=dict)
    warnings: list = field(default_factory=list)


def _note(progress, msg):
    if progress is not None:
        progress(msg)


def _apply_unit(rec: Recording, doc: dict | None) -> Recording:
    if doc is None:
        return rec
    if rec.metadata.get("calibrated_on_unit"):
        # a unit recording whose samples the unit calibrated (KF_RAW_SAMPLE flag): the file's
        # maps were applied a second time, and the angles came from doubly corrected readings
        raise KinefuseError(f"{rec.source}: the unit applied its stored calibration to these readings "
                            f"already (every sample flagged calibrated); the unit calibration file "
                            f"(--unit-cal) would apply one a second time: leave it out")
    r = Recording(**{**rec.__dict__})
    if rec.acc is not None:
        r.acc = unitfile.apply(doc, "accel", rec.acc)
    if rec.gyr is not None:
        r.gyr = unitfile.apply(doc, "gyro", rec.gyr)
    if rec.mag is not None:
        r.mag = unitfile.apply(doc, "mag", rec.mag)
    if rec.mag_native is not None:
        r.mag_native = unitfile.apply(doc, "mag", rec.mag_native)
    return r


def _on_one_clock(a: Recording, b: Recording, info: dict) -> tuple[Recording, Recording, tuple]:
    """Recordings on one clock (units of one .kfr file: equal ``metadata["clock_id"]``) are cut
    to the span both cover and share a time origin; others are aligned by their starts.
    Returns (a, b, (origin of a, origin of b))."""
    cid = a.metadata.get("clock_id")
    if cid is None or cid != b.metadata.get("clock_id"):
        info["time_alignment"] = "by start (each recording's first sample at t = 0)"
        return a, b, (a.t[0], b.t[0])
    lo, hi = max(a.t[0], b.t[0]), min(a.t[-1], b.t[-1])
    if hi <= lo:
        raise KinefuseError(f"{a.source} and {b.source}: the two recordings do not overlap in time")

    def cut(r):
        return r.slice(int(np.searchsorted(r.t, lo)), int(np.searchsorted(r.t, hi, side="right")))
    info["time_alignment"] = "common clock (one recording of both units): overlap used"
    return cut(a), cut(b), (lo, lo)


def _static_info(cfg: S.StaticConfig) -> dict:
    """The static-detection thresholds, units in the names (the report stated none of them, so
    a report made with --acc-std-max 0.5 read like one with the defaults)."""
    return {"window_s": cfg.window_s, "gyr_std_max_rad_s": cfg.gyr_std_max,
            "gyr_abs_max_rad_s": cfg.gyr_abs_max, "acc_std_max_m_s2": cfg.acc_std_max,
            "min_duration_s": cfg.min_duration_s, "trim_s": cfg.trim_s}


def _posture_mean(rec: Recording, name: str, cfg: S.StaticConfig) -> tuple[np.ndarray, dict]:
    rec.require("acc")
    wins = S.detect_static(rec.t, rec.acc, rec.gyr, cfg, source=rec.source)
    S.require_windows(wins, 1, f"{name} posture ({rec.source})", cfg)
    w = max(wins, key=lambda w: w.n)
    return rec.acc[w.start:w.stop].mean(axis=0), {"window_s": [w.t0, w.t1], "samples": w.n}


def _gyro_bias(recs: list[Recording], cfg: S.StaticConfig) -> tuple[np.ndarray, str]:
    for r in recs:
        if r is None or r.gyr is None or r.acc is None:
            continue
        wins = S.detect_static(r.t, r.acc, r.gyr, cfg, source=r.source)
        if sum(w.n for w in wins) * (1.0 / r.fs) >= 1.0:
            c = gyro_cal.bias_from_static(r.t, r.gyr, r.acc, cfg, wins)
            return c.b, f"{c.n_samples} static samples of {os.path.basename(r.source)}"
    return np.zeros(3), "none (no static period ≥ 1 s found; gyroscope used as is)"


#: a magnetometer calibration applied to a task recording must give the field it was fitted to:
#: a median |m| off by more than this fraction is another sensor's calibration (offsets of tens
#: of µT: 85 µT for a 22.6 µT field in the simulated protocol) or another place, not the few per
#: cent indoor disturbances change it by
MAG_TASK_NORM_TOL = 0.25


def _mag_mismatch(m_cal, field_norm) -> str | None:
    """Why the calibrated task magnetometer ``m_cal`` (µT) does not match the calibration's field
    norm, or None (also when the norm is unknown)."""
    if field_norm is None or not np.isfinite(field_norm) or not field_norm > 0:
        return None
    n = np.linalg.norm(np.asarray(m_cal, float), axis=1)
    n = n[np.isfinite(n)]
    if not len(n):
        return None
    med = float(np.median(n))
    if abs(med / field_norm - 1.0) <= MAG_TASK_NORM_TOL:
        return None
    return (f"calibrated, its readings have a median |m| of {med:.1f} µT, {med / field_norm:.2f} × the "
            f"{field_norm:.1f} µT field")


def _interp_quat(t_src, q_src, t_dst) -> np.ndarray:
    """Normalised linear interpolation of a sign-continuous quaternion stream."""
    q = Q.unwrap_sign(q_src)
    out = np.column_stack([np.interp(t_dst, t_src, q[:, j]) for j in range(4)])
    return Q.normalize(out)


def _first_still(rec: Recording, cfg: S.StaticConfig, other: Recording | None = None) -> tuple[slice, bool]:
    """Samples (on ``rec``'s time base) of the first period where ``rec`` — and ``other``, if
    given, mapped by elapsed time — is still for ≥ ``cfg.min_duration_s``; else the first 0.5 s.
    Returns (samples, whether a still period was found): the fallback is whatever the subject
    did then, and callers say so."""
    n_default = max(2, int(0.5 * rec.fs)) if np.isfinite(rec.fs) else 10
    if rec.acc is None:
        return slice(0, min(n_default, len(rec.t))), False
    ok = S.still_mask(rec.t, rec.acc, rec.gyr, cfg, source=rec.source)
    if other is not None and other.acc is not None:
        ok_o = S.still_mask(other.t, other.acc, other.gyr, cfg, source=other.source)
        te = rec.t - rec.t[0]
        j = np.clip(np.searchsorted(other.t - other.t[0], te), 0, len(other.t) - 1)
        ok = ok & ok_o[j]
    dt = float(np.median(np.diff(rec.t)))
    edges = np.flatnonzero(np.diff(np.concatenate([[0], ok.astype(np.int8), [0]])))
    for a, b in zip(edges[::2], edges[1::2]):
        if (b - a) * dt >= cfg.min_duration_s:
            trim = int(round(cfg.trim_s / dt))
            return slice(int(a + trim), int(b - trim)), True
    return slice(0, min(n_default, len(rec.t))), False


def sensor_orientation(rec: Recording, *, filter=None, orientation: str = "auto",
                       mag: np.ndarray | None = None, gyro_bias=None) -> tuple[np.ndarray, str]:
    """q_GS for one recording: device quaternions or the filter; returns (q, description)."""
    if orientation not in ("auto", "device", "filter"):
        raise KinefuseError(f"orientation must be auto, device or filter, not {orientation!r}")
    if orientation in ("auto", "device") and rec.quat is not None:
        return Q.normalize(rec.quat), "device quaternions"
    if orientation == "device":
        raise KinefuseError(f"{rec.source}: no device quaternions in this {rec.fmt} recording")
    rec.require("acc", "gyr")
    spec = filter if filter is not None else O.default_filter_name()
    f = O.resolve_filter(spec)
    g = rec.gyr - (np.zeros(3) if gyro_bias is None else gyro_bias)
    user = not isinstance(spec, str) or ":" in spec      # the user's own function (module:function)
    try:
        q = np.asarray(f(rec.t, rec.acc, g, mag), dtype=float)
    except Exception as exc:
        if not user or isinstance(exc, KinefuseError):
            raise
        # the user's function failed: one line naming it, not an internal error of kinefuse
        raise KinefuseError(f"orientation filter {spec!r} failed: {type(exc).__name__}: {exc} (it is "
                            f"called as f(t, acc, gyr, mag) and returns N×4 quaternions)") from None
    if q.shape != (len(rec.t), 4) or not np.all(np.isfinite(q)):
        raise KinefuseError(f"orientation filter {spec!r} returned {q.shape} values or non-finite "
                            f"numbers; expected {len(rec.t)}×4 quaternions")
    name = spec if isinstance(spec, str) else getattr(spec, "__name__", "custom")
    return Q.normalize(q), f"filter '{name}' ({'9-D' if mag is not None else '6-D'})"


def _unused_filter(seg: str, filter, desc: str, rec: Recording) -> list[str]:
    """A filter asked for, but orientation 'auto' took the recording's own quaternions: the
    report would read as the filter's while it is the device's."""
    if filter is None or desc != "device quaternions":
        return []
    name = filter if isinstance(filter, str) else getattr(filter, "__name__", "custom")
    return [f"{seg}: filter '{name}' not used: {os.path.basename(rec.source)} has device "
            f"quaternions, and orientation 'auto' uses them (orientation 'filter' runs the filter)"]


def knee_from_recordings(thigh: Recording, shank: Recording, *, standing=None, lying=None,
                         functional=None, mag_recordings=None, mag_calibrations=None, unit_calibrations=None,
                         filter=None, orientation: str = "auto", side: str = "right",
                         convention: str = "grood-suntay", field_norm: float | None = None,
                         mag_gate: float | None = None,
                         static_config: S.StaticConfig = S.StaticConfig(),
                         progress: Callable | None = None) -> JointResult:
    """Knee angles from thigh/shank recordings (see the module docstring for the pipeline).

    ``standing``/``lying``/``functional``/``mag_recordings``: (thigh, shank) Recording pairs
    or None (``functional``: flexion–extension recordings, used with ``standing`` instead of
    ``lying``);
    ``mag_calibrations``: (thigh, shank) MagCalibration pairs (alternative to recordings);
    ``unit_calibrations``: (thigh, shank) unit-file dicts or None.
    """
    info: dict = {"side": side, "convention": convention, "static_detection": _static_info(static_config)}
    warnings: list[str] = []
    units = unit_calibrations or (None, None)
    segs = ("thigh", "shank")
    task = [_apply_unit(thigh, units[0]), _apply_unit(shank, units[1])]
    task[0], task[1], origin = _on_one_clock(task[0], task[1], info)
    stand = [None, None] if standing is None else [_apply_unit(r, u) for r, u in zip(standing, units)]
    lie = [None, None] if lying is None else [_apply_unit(r, u) for r, u in zip(lying, units)]

    # --- 2. magnetometer
    _note(progress, "magnetometer calibration")
    mags = [None, None]
    mag_mismatch: list[str] = []
    for k in range(2):
        cal = None
        if mag_calibrations is not None and mag_calibrations[k] is not None:
            cal = mag_calibrations[k]
        elif mag_recordings is not None and mag_recordings[k] is not None:
            mr = _apply_unit(mag_recordings[k], units[k])
            samples = mr.mag_samples()
            if samples is None:
                raise KinefuseError(f"{mr.source}: no magnetometer data for the calibration")
            cal = mag_cal.calibrate(samples, field_norm=field_norm)
            warnings += [f"{segs[k]} magnetometer: {w}" for w in cal.warnings]
        unit_has_mag = units[k] is not None and "mag" in units[k]["sensors"]
        if task[k].mag is None and cal is not None:
            # the calibration (and any gate) would go unused without a word
            warnings.append(f"{segs[k]} magnetometer calibration given, but the task recording "
                            f"({os.path.basename(task[k].source)}) has no magnetometer data: not used "
                            f"(6-D orientation)")
        if task[k].mag is not None and (cal is not None or unit_has_mag):
            m = cal.apply(task[k].mag) if cal is not None else task[k].mag
            why = _mag_mismatch(m, cal.field_norm if cal is not None
                                else units[k]["sensors"]["mag"].get("field_norm"))
            if why is not None:
                # another sensor's figure-eight (or unit file): its offsets turn this sensor's
                # readings into a field that is not the Earth's, and the 9-D headings were garbage
                src = "figure-eight fit" if cal is not None else "unit calibration file"
                mag_mismatch.append(f"{segs[k]} magnetometer calibration does not fit the task recording "
                                    f"({os.path.basename(task[k].source)}): {why} of the {src} (the other "
                                    f"sensor's calibration, or another magnetic environment?); magnetometer "
                                    f"not used (6-D orientation; headings aligned at the start of the task)")
                info[f"{segs[k]}_mag"] = f"not used: {why}"
                continue
            if mag_gate is not None:
                m, keep = mag_cal.gate_norm(m, mag_gate)
                info[f"{segs[k]}_mag_gated_fraction"] = float(1 - keep.mean())
            mags[k] = m
            if cal is not None:
                info[f"{segs[k]}_mag"] = {"offset_uT": cal.b.tolist(), "field_norm_uT": cal.field_norm,
                                          "spread_reduction": cal.spread_reduction}
            else:
                info[f"{segs[k]}_mag"] = "from unit calibration file"
    use_mag = all(m is not None for m in mags)
    warnings += mag_mismatch
    if not use_mag and not mag_mismatch and any(r.mag is not None for r in task):
        warnings.append("magnetometer present but not calibrated for both sensors: not used "
                        "(6-D orientation; headings aligned at the start of the task)")
    if not use_mag:
        mags = [None, None]

    # --- 3. sensor-to-segment offsets
    _note(progress, "sensor-to-segment calibration")
    q_SB = [Q.identity(), Q.identity()]
    if functional is not None:
        if stand[0] is None:
            raise KinefuseError("functional calibration needs the standing recordings too "
                                "(--calib-standing: the vertical Y axis)")
        if lie[0] is not None:
            raise KinefuseError("give either the lying (two-posture) or the functional calibration, not both")
        func = [_apply_unit(r, u) for r, u in zip(functional, units)]
        for k in range(2):
            func[k].require("gyr")
            a_st, i_st = _posture_mean(stand[k], f"{segs[k]} standing", static_config)
            bias, _ = _gyro_bias([func[k], stand[k]], static_config)
            try:
                axis, planarity = alignment.principal_axis(func[k].gyr - bias, sign_ref=[1.0, 0.0, 0.0])
                if planarity > 0.5:
                    raise KinefuseError(
                        f"the recorded motion is not a clean flexion–extension (second/first singular "
                        f"value {planarity:.2f} > 0.5); repeat the functional trial")
                q_SB[k] = alignment.functional_standing(axis, a_st)
            except KinefuseError as exc:
                raise KinefuseError(f"{func[k].source}: {segs[k]} functional calibration: {exc}") from None
            info[f"{segs[k]}_mounting_deg"] = float(np.degrees(Q.angle_between(q_SB[k], Q.identity())))
            info[f"{segs[k]}_functional"] = {"flexion_axis_sensor": axis.tolist(), "planarity": planarity,
                                             "standing": i_st}
        info["alignment"] = ("functional: flexion axis from each gyroscope's principal axis, "
                             "vertical from the standing posture")
    elif stand[0] is not None and lie[0] is not None:
        for k in range(2):
            a_st, i_st = _posture_mean(stand[k], f"{segs[k]} standing", static_config)
            a_ly, i_ly = _posture_mean(lie[k], f"{segs[k]} lying", static_config)
            q_SB[k] = alignment.two_posture(a_st, a_ly)
            info[f"{segs[k]}_mounting_deg"] = float(np.degrees(Q.angle_between(q_SB[k], Q.identity())))
            info[f"{segs[k]}_postures"] = {"standing": i_st, "lying": i_ly}
        info["alignment"] = "two-posture (seed 001 §8.3)"
    else:
        info["alignment"] = "none: sensor axes taken as segment axes (X medio-lateral to the left, Y up, Z anterior)"
        warnings.append("no standing/lying calibration: knee angles assume the sensors were "
                        "mounted exactly along the segment axes")

    # --- 4. orientations
    q_GS = []
    how = []
    for k in range(2):
        _note(progress, f"{segs[k]} orientation")
        bias, bias_src = (np.zeros(3), "n/a")
        if not (orientation in ("auto", "device") and task[k].quat is not None):
            bias, bias_src = _gyro_bias([task[k], stand[k], lie[k]], static_config)
        q, desc = sensor_orientation(task[k], filter=filter, orientation=orientation,
                                     mag=mags[k], gyro_bias=bias)
        q_GS.append(q)
        how.append(desc)
        info[f"{segs[k]}_orientation"] = desc
        warnings += _unused_filter(segs[k], filter, desc, task[k])
        if desc == "device quaternions" and mags[k] is not None:
            warnings.append(f"{segs[k]} magnetometer calibration not used: the orientation is the device's "
                            f"own quaternions (orientation 'filter' runs the filter with it)")
        info[f"{segs[k]}_gyro_bias_rad_s"] = {"value": np.asarray(bias).tolist(), "source": bias_src}

    # --- 5. common time base
    t_th = task[0].t - origin[0]
    t_sh = task[1].t - origin[1]
    t_end = min(t_th[-1], t_sh[-1])
    sel = t_th <= t_end
    t = t_th[sel]
    qT = q_GS[0][sel]
    qS = _interp_quat(t_sh, q_GS[1], t)
    if abs(t_th[-1] - t_sh[-1]) > 1.0:
        warnings.append(f"thigh and shank recordings differ in length by {abs(t_th[-1] - t_sh[-1]):.1f} s; "
                        f"the overlap ({t_end:.1f} s) is used")

    # --- 6. segments and heading
    qB_T = alignment.segment_orientation(qT, q_SB[0])
    qB_S = alignment.segment_orientation(qS, q_SB[1])
    device = all(d == "device quaternions" for d in how)
    if device or not use_mag:
        ref = None
        if device and stand[0] is not None and stand[0].quat is not None and stand[1].quat is not None:
            (st0, ok0), (st1, ok1) = _first_still(stand[0], static_config), _first_still(stand[1], static_config)
            st = [st0, st1]
            for seg, ok, r in (("thigh", ok0, stand[0]), ("shank", ok1, stand[1])):
                if not ok:
                    warnings.append(f"no still period ≥ {static_config.min_duration_s:g} s in the {seg} standing "
                                    f"recording ({os.path.basename(r.source)}): headings aligned on its first "
                                    f"0.5 s, whatever the subject did then")
            D = O.yaw_alignment(alignment.segment_orientation(stand[0].quat[st[0]], q_SB[0]),
                                alignment.segment_orientation(stand[1].quat[st[1]], q_SB[1]))
            ref = "standing posture"
        else:
            st, found = _first_still(task[0], static_config, task[1])
            i0, i1 = st.start, min(st.stop, len(t))
            D = O.yaw_alignment(qB_T[i0:i1], qB_S[i0:i1])
            if found:
                ref = f"first still period of the task ({t[i0]:.1f}–{t[i1 - 1]:.1f} s)"
            else:
                ref = f"first {t[i1 - 1] - t[i0]:.1f} s of the task (no still period found)"
                warnings.append(f"no period ≥ {static_config.min_duration_s:g} s where thigh and shank are both "
                                f"still: the shank heading is aligned to the thigh's over the first "
                                f"{t[i1 - 1] - t[i0]:.1f} s of the task, whatever the leg did then (ab/adduction "
                                f"and rotation may be offset); record a still period first")
        qB_S = Q.mul(D, qB_S)
        info["heading_alignment"] = {"reference": ref,
                                     "shank_yaw_change_deg": float(np.degrees(Q.to_euler(D, "ZYX")[0]))}
    else:
        info["heading_alignment"] = "none (both sensors referenced to magnetic north)"

    # --- 7. angles
    _note(progress, "knee angles")
    qj = joint.joint_quaternion(qB_T, qB_S)
    ang = joint.knee_angles(qj, convention=convention, side=side)
    return JointResult(t, ang, joint.KNEE_COLUMNS, joint.knee_convention_text(convention, side),
                       qj, info, warnings + thigh.warnings + shank.warnings)


ELBOW_COLUMNS = ("flexion_deg", "abduction_deg", "internal_rotation_deg")
ELBOW_INITS = joint.ELBOW_INITS


def elbow_from_recordings(arm: Recording, forearm: Recording, *, filter=None,
                          orientation: str = "auto", sequence: str = "XYZ",
                          init: str = "zero-at-start", unit_calibrations=None,
                          static_config: S.StaticConfig = S.StaticConfig(),
                          progress: Callable | None = None) -> JointResult:
    """Elbow angles for the seed-002 set-up (arm = proximal, forearm = distal).

    ``init``: ``zero-at-start`` — the arm sensor axes are the segment axes and the forearm frame
    coincides with the arm frame in the first still period (angles 0 there); ``seed002`` — eqs.
    2.1–2.4 with GB q_0 = identity: both segment frames coincide with the earth frame in the
    first still period; ``none`` — raw sensor quaternions (what the seed's MATLAB code does).
    """
    if init not in ELBOW_INITS:
        raise KinefuseError(f"init must be one of {', '.join(ELBOW_INITS)}, not {init!r}")
    units = unit_calibrations or (None, None)
    recs = [_apply_unit(arm, units[0]), _apply_unit(forearm, units[1])]
    info: dict = {"sequence": sequence, "init": init, "static_detection": _static_info(static_config)}
    recs[0], recs[1], origin = _on_one_clock(recs[0], recs[1], info)
    warnings: list[str] = []
    qs = []
    for k, name in enumerate(("arm", "forearm")):
        _note(progress, f"{name} orientation")
        bias, src = (np.zeros(3), "n/a")
        if not (orientation in ("auto", "device") and recs[k].quat is not None):
            bias, src = _gyro_bias([recs[k]], static_config)
        q, desc = sensor_orientation(recs[k], filter=filter, orientation=orientation, gyro_bias=bias)
        qs.append(q)
        warnings += _unused_filter(name, filter, desc, recs[k])
        info[f"{name}_orientation"] = desc
        info[f"{name}_gyro_bias_rad_s"] = {"value": np.asarray(bias).tolist(), "source": src}
    t_a = recs[0].t - origin[0]
    t_f = recs[1].t - origin[1]
    t_end = min(t_a[-1], t_f[-1])
    sel = t_a <= t_end
    t = t_a[sel]
    qA = qs[0][sel]
    qF = _interp_quat(t_f, qs[1], t)
    st, found = _first_still(recs[0], static_config, recs[1])   # both segments still
    i0, i1 = st.start, min(st.stop, len(t))
    if not found and init != "none":
        # the reference is the posture of that moment, still or not: every angle is relative to it
        warnings.append(f"no period ≥ {static_config.min_duration_s:g} s where arm and forearm are both still: "
                        f"the reference posture (--init {init}) is the first {t[i1 - 1] - t[i0]:.1f} s of the "
                        f"recording, whatever the elbow did then, and every angle is relative to it; record "
                        f"a still period (or use --init none)")
    if init == "zero-at-start":
        q_SB_A = Q.identity()
        q_SB_F = Q.normalize(Q.mul(Q.conj(qF[i0:i1]), qA[i0:i1]).mean(axis=0))
    elif init == "seed002":
        q_SB_A = alignment.static_pose_offset(qA[i0])
        q_SB_F = alignment.static_pose_offset(qF[i0])
    else:
        q_SB_A = q_SB_F = Q.identity()
    info["reference_window_s"] = [float(t[i0]), float(t[i1 - 1])]
    qj = joint.joint_quaternion(qA, qF, q_SB_A, q_SB_F)
    ang = joint.elbow_angles(qj, sequence=sequence)
    return JointResult(t, ang, ELBOW_COLUMNS, joint.elbow_convention_text(sequence), qj, info,
                       warnings + arm.warnings + forearm.warnings)


# ----------------------------------------------------------------------------- outputs
def detect_cycles(res: JointResult, kind: str, *, drop_edge: int = 0,
                  max_rmse_deg: float = 10.0) -> cycles.CycleSet:
    flex = res.angles[:, 0]
    if kind == "knee":
        bounds = cycles.step_up_bounds(res.t, flex)
    else:
        s = flex - np.median(flex[: max(2, len(flex) // 20)])
        sig = -s if abs(s.min()) > abs(s.max()) else s  # flexion may be negative about X
        bounds = cycles.between_minima_bounds(res.t, sig)
    return cycles.normalise(res.t, res.angles, bounds, drop_edge=drop_edge, max_rmse_deg=max_rmse_deg)


def _plot(path: str, res: JointResult, cs: cycles.CycleSet, title: str) -> None:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    pct = np.linspace(0, 100, cycles.N_POINTS)
    fig = Figure(figsize=(8.0, 9.0), dpi=110)
    FigureCanvasAgg(fig)
    axes = fig.subplots(3, 1, sharex=True)
    labels = [c.replace("_deg", "").replace("_", " ") for c in res.columns]
    for j, ax in enumerate(axes):
        for c in cs.curves:
            ax.plot(pct, c[:, j], color="0.75", lw=0.7)
        m, sd = cs.mean[:, j], cs.sd[:, j]
        ax.fill_between(pct, m - sd, m + sd, color="tab:blue", alpha=0.25, lw=0, label="mean ± SD")
        ax.plot(pct, m, color="tab:blue", lw=2.0, label="mean")
        ax.set_ylabel(f"{labels[j]} (°)")
        ax.grid(True, alpha=0.3)
    axes[0].legend(loc="best", fontsize=8)
    axes[-1].set_xlabel("cycle (%)")
    import textwrap
    conv = "\n".join(textwrap.wrap(res.convention, 110))
    fig.suptitle(f"{title} — {len(cs.curves)} cycles\n{conv}", fontsize=8)
    fig.savefig(path, format="png")


def _csv(path: str, header_comment: str, cols: list[str], data: np.ndarray, fmt="%.4f") -> None:
    with open(path, "w", encoding="utf-8") as f:
        f.write(f"# {header_comment}\n")
        f.write(",".join(cols) + "\n")
        np.savetxt(f, data, delimiter=",", fmt=fmt)


REPORT_FILES = ("angles.png", "timeseries.csv", "cycles.csv", "mean_sd.csv", "summary.md")
#: knee flexion (ISB: + flexion) below this on the mean cycle is not a hyperextension a knee
#: makes (genu recurvatum rarely exceeds 10-15°): the thigh and shank, or their calibration
#: recordings, were most likely swapped
KNEE_HYPEREXTENSION_WARN_DEG = -15.0


def report_files(kind: str) -> list[str]:
    """The files :func:`write_report` writes for ``kind`` ('knee' or 'elbow')."""
    return [f"{kind}_{name}" for name in REPORT_FILES]


def _none_if_nan(v: float):
    return None if not np.isfinite(v) else float(v)


def _plausibility(kind: str, cs: cycles.CycleSet, rom: dict) -> list[str]:
    """Warnings for results that are computed correctly from doubtful inputs."""
    w = []
    if len(cs.curves) < 2:
        w.append(f"only {len(cs.curves)} cycle kept: standard deviations over cycles are not defined "
                 f"(n/a in the summary, nan in {kind}_mean_sd.csv)")
    if kind == "knee":
        lo = float(rom["min_mean"][0])
        if lo < KNEE_HYPEREXTENSION_WARN_DEG:
            w.append(f"knee flexion reaches {lo:.0f}° (mean cycle minimum; ISB: flexion positive), a "
                     f"hyperextension beyond {-KNEE_HYPEREXTENSION_WARN_DEG:.0f}°: are the thigh and shank "
                     f"recordings (or their calibration recordings) swapped?")
    return w


def write_report(out_dir: str, kind: str, res: JointResult, cs: cycles.CycleSet, *,
                 title: str, inputs: dict, max_cycle_rmse_deg: float = 10.0) -> dict:
    """Write PNG, CSVs and Markdown for ``kind`` ('knee' or 'elbow'); returns the summary.
    ``max_cycle_rmse_deg``: the rejection threshold ``cs`` was made with (stated in the summary).

    All files are written under temporary names first and renamed when every one is complete:
    a failure leaves the folder as it was (no report half of this run, half of an earlier one)."""
    made = not os.path.isdir(out_dir)
    try:
        os.makedirs(out_dir, exist_ok=True)
    except OSError as exc:
        raise KinefuseError(f"cannot create output directory {out_dir}: {exc.strerror}") from None
    final = {name: os.path.join(out_dir, f"{kind}_{name}") for name in REPORT_FILES}
    for path in final.values():
        if os.path.isdir(path):
            raise KinefuseError(f"cannot write {path}: a folder of that name is in the way")
    try:
        with staged() as stage:
            tmp = {name: str(stage.path(final[name])) for name in REPORT_FILES}
            summary = _write_files(tmp.__getitem__, kind, res, cs, title=title, inputs=inputs,
                                   max_cycle_rmse_deg=max_cycle_rmse_deg)
    except BaseException as exc:
        if made:
            with contextlib.suppress(OSError):
                os.rmdir(out_dir)            # the (now empty) folder this call created
        if isinstance(exc, OSError):
            raise KinefuseError(f"cannot write the {kind} report in {out_dir}: "
                                f"{exc.strerror or exc}") from None
        raise
    return summary


def _write_files(p, kind: str, res: JointResult, cs: cycles.CycleSet, *, title: str, inputs: dict,
                 max_cycle_rmse_deg: float) -> dict:
    cols = list(res.columns)
    # time series with the cycle number (−1 outside kept cycles); cycles are numbered among all
    # detected ones, as the summary names the rejected ones.  Cycle numbers are counts and
    # written as integers ("3", not "3.0000"); the percent grid (0, 1, …, 100 % of the cycle)
    # with the fewest digits that state it exactly
    n_ang = len(cols)
    cyc_idx = np.full(len(res.t), -1, dtype=np.int64)
    for k in cs.kept:
        i0, i1 = cs.bounds[k]
        cyc_idx[i0:i1] = cs.number(k)
    _csv(p("timeseries.csv"), res.convention, ["t_s"] + cols + ["cycle"],
         np.column_stack([res.t, res.angles, cyc_idx]), fmt=["%.4f"] * (1 + n_ang) + ["%d"])
    pct = np.linspace(0, 100, cycles.N_POINTS)
    rows = [np.column_stack([np.full(len(pct), cs.number(k)), pct, c]) for k, c in zip(cs.kept, cs.curves)]
    _csv(p("cycles.csv"), res.convention, ["cycle", "percent"] + cols, np.vstack(rows),
         fmt=["%d", "%.6g"] + ["%.4f"] * n_ang)
    msd = np.column_stack([pct] + [x for j in range(n_ang) for x in (cs.mean[:, j], cs.sd[:, j])])
    _csv(p("mean_sd.csv"), res.convention,
         ["percent"] + [f"{c.replace('_deg', '')}_{s}_deg" for c in cols for s in ("mean", "sd")], msd,
         fmt=["%.6g"] + ["%.4f"] * (2 * n_ang))
    _plot(p("angles.png"), res, cs, title)
    rom = cs.rom()
    summary = {
        "kind": kind, "title": title, "convention": res.convention, "inputs": inputs,
        "n_cycles_detected": cs.n_detected, "n_edge_cycles_dropped": 2 * cs.edge_dropped,
        "n_cycles_kept": len(cs.curves),
        "max_cycle_rmse_deg": float(max_cycle_rmse_deg),
        "rejected_cycles": [{"cycle": cs.number(k), "rmse_deg": e} for k, e in cs.rejected],
        # a standard deviation over one cycle is not defined: null (n/a), not 0
        "cycle_duration_s": {"mean": float(cs.durations_s.mean()),
                             "sd": float(cs.durations_s.std(ddof=1)) if len(cs.durations_s) > 1 else None},
        "range_of_motion_deg": {c: {"mean": float(rom["rom_mean"][j]), "sd": _none_if_nan(rom["rom_sd"][j]),
                                    "max_mean": float(rom["max_mean"][j]),
                                    "min_mean": float(rom["min_mean"][j])} for j, c in enumerate(cols)},
        "processing": res.info, "warnings": list(res.warnings) + _plausibility(kind, cs, rom),
        "files": report_files(kind),
    }
    _markdown(p("summary.md"), summary)
    return summary


def _sd(v, fmt: str) -> str:
    """A standard deviation for text: ``n/a`` when not defined (one cycle)."""
    return "n/a" if v is None else format(v, fmt)


def _fmt(v) -> str:
    """Compact human-readable rendering of summary values (floats to 3 decimals)."""
    if isinstance(v, float):
        return f"{v:.3f}"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_fmt(x) for x in v) + "]"
    if isinstance(v, dict):
        return "; ".join(f"{k.replace('_', ' ')} {_fmt(x)}" for k, x in v.items())
    return str(v)


def _markdown(path: str, s: dict) -> None:
    L = [f"# {s['title']}", "", f"**Convention:** {s['convention']}", "", "## Inputs", ""]
    L += [f"- {k}: `{v}`" for k, v in s["inputs"].items() if v]
    L += ["", "## Cycles", "",
          f"- detected: {s['n_cycles_detected']}, kept: {s['n_cycles_kept']}"
          f" (cycles deviating > {s['max_cycle_rmse_deg']:g}° RMS from the mean flexion curve are rejected)"
          + (f"; edge cycles dropped: {s['n_edge_cycles_dropped'] // 2} at each end (--drop-edge-cycles)"
             if s["n_edge_cycles_dropped"] else ""),
          f"- duration: {s['cycle_duration_s']['mean']:.2f} ± {_sd(s['cycle_duration_s']['sd'], '.2f')} s"]
    for r in s["rejected_cycles"]:
        L.append(f"- rejected cycle {r['cycle']}: {r['rmse_deg']:.1f}° RMS from the mean")
    L += ["", "## Range of motion (per cycle, mean ± SD over cycles)", "",
          "| angle | ROM (°) | max (°) | min (°) |", "|---|---|---|---|"]
    for c, v in s["range_of_motion_deg"].items():
        L.append(f"| {c.replace('_deg', '').replace('_', ' ')} | {v['mean']:.1f} ± {_sd(v['sd'], '.1f')} | "
                 f"{v['max_mean']:.1f} | {v['min_mean']:.1f} |")
    L += ["", "## Processing", ""]
    for k, v in s["processing"].items():
        L.append(f"- {k.replace('_', ' ')}: {_fmt(v)}")
    if s["warnings"]:
        L += ["", "## Warnings", ""] + [f"- {w}" for w in s["warnings"]]
    L += ["", "## Files", ""] + [f"- {f}" for f in s["files"]]
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(L) + "\n")
