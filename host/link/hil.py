"""Sensor input for a unit in the loop: HIL_SENSOR frames from SI arrays, and back.

Convention (kinefuse.xml): HIL_SENSOR carries one sensor sample in the unit's SENSOR frame (the
"NED body frame" wording of common.xml does not apply), ``time_usec`` is the sample time on the
unit's clock (us since boot), acc is specific force in m/s^2, gyro rad/s, mag in gauss
(1 gauss = 100 uT), temperature degC; ``fields_updated`` says which values are new.  A unit in
HIL mode answers each HIL_SENSOR with the KF_RAW_SAMPLE it would have measured (flag SIMULATED).
"""
from __future__ import annotations

import numpy as np

from kinefuse.host.link.batchenc import encode_batch
from kinefuse.host.link.dialect import HOST_COMPONENT_ID, HOST_SYSTEM_ID, RAW_SCALE

UT_PER_GAUSS = 100.0
UPDATED_ACC_GYRO = 0x3F     # HIL_SENSOR_UPDATED_{X,Y,Z}{ACC,GYRO}
UPDATED_MAG = 0x1C0         # HIL_SENSOR_UPDATED_{X,Y,Z}MAG
UPDATED_TEMPERATURE = 0x1000


def hil_sensor_frames(time_us, acc_mps2, gyro_radps, mag_uT=None, temperature_degC=None, mag_updated=None,
                      sysid: int = HOST_SYSTEM_ID, compid: int = HOST_COMPONENT_ID, seq0: int = 0,
                      sensor_id: int = 0) -> bytes:
    """HIL_SENSOR frames for N samples: time (N,), acc/gyro/mag (N, 3) in SI (mag in uT)."""
    t = np.asarray(time_us, dtype=np.uint64)
    n = t.size
    acc = np.asarray(acc_mps2, np.float32).reshape(n, 3)
    gyro = np.asarray(gyro_radps, np.float32).reshape(n, 3)
    flags = np.full(n, UPDATED_ACC_GYRO, np.uint32)
    v = {"time_usec": t, "xacc": acc[:, 0], "yacc": acc[:, 1], "zacc": acc[:, 2],
         "xgyro": gyro[:, 0], "ygyro": gyro[:, 1], "zgyro": gyro[:, 2], "id": np.full(n, sensor_id, np.uint8)}
    if mag_uT is not None:
        mag = np.asarray(mag_uT, np.float64).reshape(n, 3) / UT_PER_GAUSS
        v.update(xmag=mag[:, 0].astype(np.float32), ymag=mag[:, 1].astype(np.float32), zmag=mag[:, 2].astype(np.float32))
        upd = np.ones(n, bool) if mag_updated is None else np.asarray(mag_updated, bool)
        flags |= np.where(upd, UPDATED_MAG, 0).astype(np.uint32)
    if temperature_degC is not None:
        v["temperature"] = np.broadcast_to(np.asarray(temperature_degC, np.float32), (n,))
        flags |= UPDATED_TEMPERATURE
    v["fields_updated"] = flags
    return encode_batch("HIL_SENSOR", v, sysid=sysid, compid=compid, seq0=seq0, n=n)


#: the largest KF_RAW_SAMPLE.gyro_shift a unit sends (kinefuse.xml): gyro range 2^3 * 32.767 rad/s
GYRO_SHIFT_MAX = 3


def raw_gyro_counts(gyro_radps):
    """Gyro rad/s (..., 3) -> (KF_RAW_SAMPLE gyro_x/y/z, gyro_shift, clipped) as the unit forms
    them: per sample the smallest shift 0..3 for which all three ``round((x / 1e-3) * 2^-shift)``
    (float64 division, exact power-of-two scaling, round half to even) are within +-32767;
    beyond 2^3 * 32.767 rad/s shift 3, saturated to int16 and ``clipped``."""
    r0 = np.asarray(gyro_radps, np.float64) / RAW_SCALE["gyro"]
    shift = np.full(r0.shape[:-1], GYRO_SHIFT_MAX, np.uint8)
    for k in range(GYRO_SHIFT_MAX - 1, -1, -1):
        fits = np.all(np.abs(np.round(np.ldexp(r0, -k))) <= 32767, axis=-1)
        shift = np.where(fits, np.uint8(k), shift).astype(np.uint8)
    r = np.round(np.ldexp(r0, -shift[..., None].astype(np.int64)))
    return (np.clip(r, -32768, 32767).astype(np.int16), shift,
            np.any(np.abs(r) > 32767, axis=-1))


def gyro_radps(arr) -> np.ndarray:
    """(N, 3) rad/s of decoded KF_RAW_SAMPLE rows (a structured array or mapping with gyro_x/y/z
    and, from firmware that sends it, gyro_shift): gyro_raw * 2^gyro_shift * 1e-3.  Rows
    without the extension field (older firmware, older recordings) have shift 0."""
    g = np.column_stack([np.asarray(arr[f"gyro_{x}"]) for x in "xyz"]).astype(np.float64)
    names = getattr(getattr(arr, "dtype", None), "names", None)
    has = ("gyro_shift" in names) if names is not None else ("gyro_shift" in arr)
    if has:
        g = np.ldexp(g, np.asarray(arr["gyro_shift"]).astype(np.int64).reshape(-1, 1))
    return g * RAW_SCALE["gyro"]


def raw_counts(acc_mps2, gyro_radps, mag_uT, temperature_degC=0.0):
    """SI values -> the int16 fields of KF_RAW_SAMPLE (round to nearest, saturate) + clip flags,
    the gyro in 1-count (mrad/s) units: the counts the unit's calibration map (int16 input)
    takes in HIL mode 0.  The gyro fields the unit sends: :func:`raw_gyro_counts`;
    :func:`raw_sample_counts` gives all fields as sent."""
    def q(x, scale):
        r = np.round(np.asarray(x, np.float64) / scale)
        return np.clip(r, -32768, 32767).astype(np.int16), np.any(np.abs(r) > 32767, axis=-1)
    a, ca = q(acc_mps2, RAW_SCALE["acc"])
    g, cg = q(gyro_radps, RAW_SCALE["gyro"])
    m, cm = q(mag_uT, RAW_SCALE["mag"])
    t, _ = q(np.asarray(temperature_degC)[..., None], RAW_SCALE["temperature"])
    flags = ca * 1 | cg * 2 | cm * 4
    return a, g, m, t[..., 0], flags.astype(np.uint8)


def raw_sample_counts(acc_mps2, gyro_radps, mag_uT, temperature_degC=0.0):
    """SI values -> the fields of KF_RAW_SAMPLE as the unit sends them for HIL input:
    (acc, gyro, mag, temperature, flags, gyro_shift); the gyro with :func:`raw_gyro_counts`
    (GYRO_CLIPPED only beyond 2^3 * 32.767 rad/s), the rest as :func:`raw_counts`."""
    a, _, m, t, flags = raw_counts(acc_mps2, gyro_radps, mag_uT, temperature_degC)
    g, shift, cg = raw_gyro_counts(gyro_radps)
    flags = (flags & ~np.uint8(2)) | (cg * 2).astype(np.uint8)
    return a, g, m, t, flags.astype(np.uint8), shift
