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


def raw_counts(acc_mps2, gyro_radps, mag_uT, temperature_degC=0.0):
    """SI values -> the int16 fields of KF_RAW_SAMPLE (round to nearest, saturate) + clip flags."""
    def q(x, scale):
        r = np.round(np.asarray(x, np.float64) / scale)
        return np.clip(r, -32768, 32767).astype(np.int16), np.any(np.abs(r) > 32767, axis=-1)
    a, ca = q(acc_mps2, RAW_SCALE["acc"])
    g, cg = q(gyro_radps, RAW_SCALE["gyro"])
    m, cm = q(mag_uT, RAW_SCALE["mag"])
    t, _ = q(np.asarray(temperature_degC)[..., None], RAW_SCALE["temperature"])
    flags = ca * 1 | cg * 2 | cm * 4
    return a, g, m, t[..., 0], flags.astype(np.uint8)
