"""Vectorised encoding (byte-identical to pymavlink) and HIL_SENSOR input to a unit in the loop."""
from __future__ import annotations

import time

import numpy as np
import pytest

from kinefuse.host.link.batchenc import encode_batch
from kinefuse.host.link.connection import create_pty_pair, open_tty_raw
from kinefuse.host.link.decoder import decode_bytes
from kinefuse.host.link.dialect import RAW_SCALE, module
from kinefuse.host.link.fakeunit import FakeUnit
from kinefuse.host.link.hil import hil_sensor_frames
from kinefuse.host.link.session import Session
from kinefuse.host.link.spec import kinefuse_dialect

D = kinefuse_dialect()
MOD = module()


@pytest.mark.parametrize("name", ["KF_RAW_SAMPLE", "HIL_SENSOR", "KF_ORIENTATION", "KF_EFFORTS", "PARAM_VALUE",
                                  "HEARTBEAT"])
def test_encode_batch_equals_pymavlink(name):
    spec = D[name]
    rng = np.random.default_rng(len(name))
    n = 64
    rec = np.zeros(n, spec.dtype)
    raw = rng.integers(0, 256, (n, spec.length), dtype=np.uint8)
    raw[::3, spec.length // 2:] = 0  # every third payload has a zero tail: truncated on the wire
    raw[5] = 0                       # all-zero payload: one byte kept
    rec = raw.view(spec.dtype).reshape(n).copy()
    for f, t in zip(spec.fields, spec.types):
        if t in ("float", "double"):  # keep floats finite (NaN payload bits are not the point here)
            rec[f] = np.where(np.isfinite(rec[f]), rec[f], 0)
        if t == "char":
            rec[f] = [bytes(c % 26 + 65 for c in v) for v in rec[f]]
    data = encode_batch(name, rec, sysid=3, compid=200, seq0=250)
    mav = MOD.MAVLink(None, srcSystem=3, srcComponent=200)
    ref = b""
    for k, r in enumerate(rec):
        mav.seq = (250 + k) % 256  # pack() itself does not advance the sequence number
        args = []
        for fn in spec.pymavlink_class.fieldnames:
            v = r[fn]
            args.append(v.tolist() if isinstance(v, np.ndarray) else v.item())
        ref += spec.pymavlink_class(*args).pack(mav)
    assert data == ref


def test_hil_sensor_frames_carry_si_values():
    n = 500
    t = np.arange(n, dtype=np.uint64) * 1000 + 123
    rng = np.random.default_rng(0)
    acc, gyro, mag = rng.normal(0, 5, (n, 3)), rng.normal(0, 2, (n, 3)), rng.normal(0, 40, (n, 3))
    frames, c = decode_bytes(hil_sensor_frames(t, acc, gyro, mag, temperature_degC=25.0,
                                               mag_updated=np.arange(n) % 10 == 0))
    assert c.frames_ok == n and c.bytes_skipped == 0
    for k in (0, 1, 250, 499):
        m = frames[k].msg
        assert m.time_usec == t[k]
        assert np.float32(m.xacc) == np.float32(acc[k, 0]) and np.float32(m.zgyro) == np.float32(gyro[k, 2])
        assert np.float32(m.ymag) == np.float32(mag[k, 1] / 100)  # gauss on the wire
        assert m.fields_updated == (0x3F | 0x1000 | (0x1C0 if k % 10 == 0 else 0))


def test_fake_unit_in_the_loop_answers_hil_sensor():
    pair = create_pty_pair()
    unit = FakeUnit(open_tty_raw(pair.device_path), unit_id=8, rate_hz=100).start()
    s = Session(pair.host)
    try:
        n = 200
        t = 10_000_000 + np.arange(n, dtype=np.uint64) * 1000
        acc = np.tile([0.1, -0.2, 9.80665], (n, 1)) + np.arange(n)[:, None] * 1e-3
        gyro = np.tile([0.0, 0.5, -40.0], (n, 1))  # z beyond 32.767 rad/s: gyro_shift 1
        gyro[180:, 2] = -300.0                     # beyond 2^3 * 32.767 rad/s: saturates
        mag = np.tile([20.0, 0.0, -45.0], (n, 1))
        s.send_bytes(hil_sensor_frames(t, acc, gyro, mag))
        got = []
        deadline = time.monotonic() + 10
        while len(got) < n and time.monotonic() < deadline:
            f = s.wait_for(lambda f: f.msgid == 52500 and f.msg.flags & 64, timeout=0.5)
            if f is not None:
                got.append(f.msg)
        assert len(got) == n
        assert [m.time_boot_us for m in got] == t.tolist()
        k = 150
        assert got[k].acc_z == round(acc[k, 2] / RAW_SCALE["acc"]) and got[k].gyro_shift == 1
        assert got[k].gyro_y == 250 and got[k].gyro_z == -20000 and not got[k].flags & 2  # 2 mrad/s
        assert got[0].gyro_shift == 1 and got[0].gyro_y == 250
        k = 190
        assert got[k].gyro_shift == 3 and got[k].gyro_z == -32768 and got[k].flags & 2  # clipped, and flagged
        assert got[k].mag_x == 200 and got[k].mag_z == -450
    finally:
        s.close()
        unit.stop()
