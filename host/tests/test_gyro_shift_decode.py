"""KF_RAW_SAMPLE.gyro_shift on the host: a .kfr recording of the fake unit answering HIL_SENSOR
at 2,500 deg/s replays (kfr reader, export) without clipping; recordings without the field
decode as shift 0."""
from __future__ import annotations

import math
import time

import numpy as np

from kinefuse.host.link.batchenc import encode_batch
from kinefuse.host.link.dialect import UNIT_COMPONENT_ID
from kinefuse.host.link.recording import RecordingWriter, make_header
from kinefuse.host.readers import kfr

MSG_RAW = 52500
GYRO_CLIPPED = 2


def _fake_unit_hil_recording(path, gyr, n=400):
    """Feed a fake unit ``n`` HIL_SENSOR samples at 200 Hz with gyro ``gyr`` (n, 3) rad/s and
    record its answers, as read by the host, into ``path``."""
    from kinefuse.host.link.decoder import StreamDecoder
    from kinefuse.host.link.fakeunit import FakeConnection
    from kinefuse.host.link.hil import hil_sensor_frames
    t_us = 1_000_000 + np.arange(n, dtype=np.int64) * 5000
    acc = np.tile([0.0, 0.0, 9.81], (n, 1))
    mag = np.tile([20.0, 0.0, -40.0], (n, 1))
    conn = FakeConnection("stream=0")
    head = make_header([{"id": 0, "connection": conn.url}])
    t0 = time.monotonic_ns()
    head["start_monotonic_ns"] = t0
    dec = StreamDecoder(native=False)
    got = 0
    try:
        with RecordingWriter(path, head) as w:
            data = hil_sensor_frames(t_us, acc, gyr, mag)
            conn.write(data)
            deadline = time.monotonic() + 20
            while got < n and time.monotonic() < deadline:
                b = conn.read(0.2)
                if not b:
                    continue
                # the host times: samples 5 ms apart as the unit's clock says, whenever they came
                got += sum(f.msgid == MSG_RAW for f in dec.feed(b))
                w.rx(0, [(t0 + int(got * 5e6), b)])
    finally:
        conn.close()
    assert got == n
    return t_us


def test_a_fake_unit_recording_at_2500_dps_replays_without_clipping(tmp_path):
    n = 400
    s = np.arange(n) / 200.0
    gyr = np.column_stack([math.radians(2500.0) * np.sin(2 * np.pi * 1.0 * s), 0.2 + 0 * s,
                           math.radians(-2100.0) * np.cos(2 * np.pi * 0.5 * s)])
    p = tmp_path / "fast.kfr"
    _fake_unit_hil_recording(p, gyr, n)
    r = kfr.read(str(p))
    assert len(r) == n
    g32 = gyr.astype(np.float32).astype(np.float64)        # HIL_SENSOR carries float32
    err = np.abs(r.gyr - g32)
    assert np.max(np.abs(r.gyr[:, 0])) > math.radians(2400.0)   # not clipped at 32.767 rad/s
    assert np.all(err <= 2e-3 / 2 + 1e-12), err.max()            # half an LSB at shift 1
    # and the fake unit did not flag the samples clipped (as the firmware: only beyond 2^3 x 32.767 rad/s)
    from kinefuse.host.link.frames import decode_file
    arr = decode_file(p).streams[0].arrays[MSG_RAW]
    assert len(arr) == n and not np.any(arr["flags"].astype(int) & GYRO_CLIPPED)
    assert set(np.unique(arr["gyro_shift"]).tolist()) == {0, 1}
    # kinefuse export gives the same rad/s
    from kinefuse.host.link.export import export_csv
    from kinefuse.host.link.frames import decode_file
    from kinefuse.host.readers import kinefuse_csv
    files = export_csv(decode_file(p), tmp_path, ["KF_RAW_SAMPLE"])
    csv = kinefuse_csv.read(files[0]["file"])
    assert np.allclose(csv.gyr, r.gyr, rtol=1e-5, atol=1e-9)    # the CSV holds 6 significant digits
    assert np.max(np.abs(csv.gyr[:, 0])) > math.radians(2400.0)


def test_frames_without_the_field_decode_as_shift_0_and_with_it_scale(tmp_path):
    """Old 46-byte frames (no extension) read as 1 mrad/s; a frame with gyro_shift k as 2^k."""
    n = 50
    v = {"time_boot_us": (1_000_000 + 5000 * np.arange(n)).astype(np.uint64),
         "sample_counter": np.arange(n, dtype=np.uint32), "acc_z": np.full(n, 1000),
         "gyro_x": np.full(n, 30000), "gyro_y": np.full(n, -7), "gyro_z": np.zeros(n, int),
         "unit_id": np.full(n, 1, np.uint8), "flags": np.full(n, 16, np.uint8)}
    old = encode_batch("KF_RAW_SAMPLE", v, sysid=1, compid=UNIT_COMPONENT_ID, n=n)
    assert len(old) == 46 * n
    v2 = dict(v, gyro_shift=np.full(n, 3, np.uint8))
    new = encode_batch("KF_RAW_SAMPLE", v2, sysid=2, compid=UNIT_COMPONENT_ID, n=n)
    p = tmp_path / "both.kfr"
    head = make_header([{"id": 0, "connection": "synthetic"}])
    head["start_monotonic_ns"] = 10**12
    with RecordingWriter(p, head) as w:
        fr = len(old) // n, len(new) // n
        w.rx(0, [(10**12 + int(k * 5e6), old[k * fr[0]:(k + 1) * fr[0]] + new[k * fr[1]:(k + 1) * fr[1]])
                 for k in range(n)])
    r1, r2 = kfr.read(str(p), unit=1), kfr.read(str(p), unit=2)
    assert np.allclose(r1.gyr[:, 0], 30.0) and np.allclose(r1.gyr[:, 1], -0.007)
    assert np.allclose(r2.gyr[:, 0], 240.0) and np.allclose(r2.gyr[:, 1], -0.056)
