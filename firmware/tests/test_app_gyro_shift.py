"""KF_RAW_SAMPLE.gyro_shift (kinefuse.xml extension field): gyro fields in units of
2^gyro_shift mrad/s, so that HIL rates above the int16 range of 1 mrad/s counts (+-32.767 rad/s
= +-1,877 deg/s; MEMS gyroscopes measure +-2000 deg/s) are sent instead of clipped.  The unit
(in-process test HAL and the host build on a pty), the host decode, the fake unit and the
models of firmware/hostunit.py are compared."""
from __future__ import annotations

import math
import shutil
import struct

import numpy as np
import pytest

from kinefuse.host.link.hil import gyro_radps, raw_gyro_counts, raw_sample_counts

MSG_RAW = 52500
GYRO_CLIPPED, MAG_UPDATED, TEMPERATURE_VALID, SIMULATED = 2, 8, 32, 64
INPUT_CLIPPED = 128       # KF_ORIENTATION_STATUS_INPUT_CLIPPED


def _hil_fields(t, gyro, **over):
    f = dict(time_usec=t, xacc=0.1, yacc=0.2, zacc=9.8, xgyro=gyro[0], ygyro=gyro[1], zgyro=gyro[2],
             xmag=0.2, ymag=0.0, zmag=-0.4, abs_pressure=0.0, diff_pressure=0.0, pressure_alt=0.0,
             temperature=21.5, fields_updated=0x11FF, id=0)
    f.update(over)
    return f


def _raw_frames(data: bytes) -> list[bytes]:
    """Payloads of the KF_RAW_SAMPLE frames in a MAVLink 2 byte stream (parsed here, not by the
    host decoder under test): magic 0xFD, len, incompat, compat, seq, sysid, compid, msgid[3]."""
    out, i = [], 0
    while True:
        i = data.find(b"\xfd", i)
        if i < 0 or i + 10 > len(data):
            return out
        n, incompat = data[i + 1], data[i + 2]
        msgid = int.from_bytes(data[i + 7:i + 10], "little")
        end = i + 10 + n + 2 + (13 if incompat & 1 else 0)
        if msgid == MSG_RAW and end <= len(data):
            out.append(data[i + 10:i + 10 + n])
            i = end
        else:
            i += 1


def _answer(unit, t, gyro):
    """(decoded KF_RAW_SAMPLE, its payload bytes, KF_ORIENTATION) for one HIL_SENSOR."""
    unit.send("HIL_SENSOR", **_hil_fields(t, gyro))
    buf = unit.ffi.new("uint8_t[]", 65536)
    data = b""
    while True:
        n = unit.lib.kft_take(buf, 65536)
        if n == 0:
            break
        data += bytes(unit.ffi.buffer(buf, n))
    frames = unit.dec.feed(data)
    raw = [f.msg for f in frames if f.msgid == MSG_RAW]
    ori = [f.msg for f in frames if f.msgid == 52501]
    payloads = _raw_frames(data)
    assert len(raw) == 1 and len(payloads) == 1
    return raw[0], payloads[0], (ori[0] if ori else None)


def _f32(x):
    return [float(np.float32(v)) for v in x]


def test_2500_dps_is_sent_with_shift_1_and_decodes_within_half_an_lsb(unit):
    g = _f32([math.radians(2500.0), -0.5, math.radians(-1900.0)])
    m, _, _ = _answer(unit, 1_000_000, g)
    assert m.gyro_shift == 1
    assert m.flags & GYRO_CLIPPED == 0
    got = gyro_radps({"gyro_x": [m.gyro_x], "gyro_y": [m.gyro_y], "gyro_z": [m.gyro_z],
                      "gyro_shift": [m.gyro_shift]})[0]
    lsb = 2.0 ** m.gyro_shift * 1e-3
    assert np.all(np.abs(got - np.array(g)) <= lsb / 2), (got, g)


def test_100_dps_keeps_shift_0_and_the_bytes_of_the_46_byte_frame(unit):
    g = _f32([math.radians(100.0), -0.02, 0.03])
    t = 2_000_000
    m, payload, _ = _answer(unit, t, g)
    assert m.gyro_shift == 0
    # the KF_RAW_SAMPLE of before the extension: wire order of kinefuse.xml (sorted by size),
    # counts = round half to even of the float64 quotient, trailing zeros truncated (MAVLink 2)
    cnt = lambda x, s: int(round(float(np.float32(x)) / s))   # noqa: E731
    old = struct.pack("<QIhhhhhhhhhhBB", t, m.sample_counter, cnt(0.1, 9.80665e-3), cnt(0.2, 9.80665e-3),
                      cnt(9.8, 9.80665e-3), cnt(g[0], 1e-3), cnt(g[1], 1e-3), cnt(g[2], 1e-3),
                      cnt(float(np.float32(0.2)) * 100.0, 0.1), 0, cnt(float(np.float32(-0.4)) * 100.0, 0.1),
                      2150, m.unit_id, SIMULATED | TEMPERATURE_VALID | MAG_UPDATED)
    assert len(old) == 34                      # + 12 bytes of header and CRC: 46-byte frames
    assert payload == old.rstrip(b"\x00")


RATES_DPS = [0.0, 100.0, 1876.0, 1877.4, 1878.0, -1878.0, 2000.0, 2500.0, -2500.0, 3754.0, 3755.0,
             5000.0, 7509.0, 7510.0, 10000.0, 15019.0, 15020.0, -15020.0, 20000.0, -30000.0]


def _cases():
    """(3,) rad/s float32 gyro samples around every shift boundary, on each axis and mixed."""
    out = []
    for d in RATES_DPS:
        r = math.radians(d)
        out.append([r, 0.01, -0.02])
        out.append([0.3, r, -r / 3])
        out.append([-0.1, r / 2.5, r])
    # the exact boundaries in counts: 32767.5 mrad/s rounds to even (32768: does not fit)
    for s in range(4):
        for c in (32767.0, 32767.4, 32767.5, 32768.0, -32767.5, -32768.0):
            out.append([c * 2.0 ** s * 1e-3, 0.0, 0.0])
    return [_f32(c) for c in out]


@pytest.mark.parametrize("system", ["f32", "q"])
def test_unit_counts_match_the_model_and_the_fake_unit_bit_for_bit(inproc_builder, unit_type, system):
    from kinefuse.host.link.decoder import StreamDecoder
    from kinefuse.host.link.dialect import kinefuse as dialect
    from kinefuse.host.link.fakeunit import FakeUnit
    ffi, lib = inproc_builder(system)
    unit = unit_type(ffi, lib)
    cases = _cases()
    want_g, want_s, want_c = raw_gyro_counts(np.array(cases, np.float64))
    fake = FakeUnit(_NullConn(), streaming=False)   # not started: only its HIL answer is used
    dec = StreamDecoder(native=False)
    mav = dialect.MAVLink(None, srcSystem=255, srcComponent=190)
    seen = set()
    for i, g in enumerate(cases):
        m, _, _ = _answer(unit, 1_000_000 + 1000 * i, g)
        got = (m.gyro_x, m.gyro_y, m.gyro_z, m.gyro_shift, bool(m.flags & GYRO_CLIPPED))
        want = (*map(int, want_g[i]), int(want_s[i]), bool(want_c[i]))
        assert got == want, (i, g)
        seen.add(int(want_s[i]))
        hs = mav.hil_sensor_encode(**{k: v for k, v in _hil_fields(1_000_000 + 1000 * i, g).items()})
        fr = dec.feed(b"".join(fake._hil_sample(hs)))
        f = [x.msg for x in fr if x.msgid == MSG_RAW][0]
        assert (f.gyro_x, f.gyro_y, f.gyro_z, f.gyro_shift, bool(f.flags & GYRO_CLIPPED)) == want, (i, g)
    assert seen == {0, 1, 2, 3} and want_c.any() and not want_c[:3 * 5].any()
    # raw_sample_counts (the models' answer) has the gyro clip flag only beyond shift 3
    a, g, m, t, flags, shift = raw_sample_counts(np.zeros((len(cases), 3)), np.array(cases, np.float64),
                                                 np.zeros((len(cases), 3)))
    assert np.array_equal(shift, want_s) and np.array_equal((flags & GYRO_CLIPPED) != 0, want_c)


class _NullConn:
    url = "null"

    def write(self, data):
        pass

    def read(self, timeout):
        return b""

    def close(self):
        pass


def test_fast_rates_clip_the_calibrated_input_in_mode_0_only(unit):
    """HIL mode 0 feeds the calibration map's int16 counts (1 mrad/s): above 32.767 rad/s they
    saturate there, and KF_ORIENTATION says INPUT_CLIPPED although KF_RAW_SAMPLE does not."""
    g = _f32([math.radians(2500.0), 0.0, 0.0])
    m, _, ori = _answer(unit, 3_000_000, g)
    assert m.gyro_shift == 1 and not m.flags & GYRO_CLIPPED
    assert ori is not None and ori.status & INPUT_CLIPPED
    m, _, ori = _answer(unit, 3_001_000, _f32([math.radians(100.0), 0.0, 0.0]))
    assert m.gyro_shift == 0 and not ori.status & INPUT_CLIPPED


# ------------------------------------------------------------ the host build, bit for bit

@pytest.fixture(scope="module")
def fast_inputs():
    """BROAD motion (as test_app_host.py) with a shank-swing burst: up to 3,000 deg/s about x
    and 9,000 deg/s about z on a few samples, so every gyro_shift 0..3 occurs."""
    from kinefuse.host import broad, runner
    trial = broad.load_trial(broad.bundled_trials()[0])
    inp = runner.imu_inputs(trial)
    n, start = 300, 7850
    sl = slice(start, start + n)
    gyr = np.array(inp["gyr"][sl], np.float64)
    burst = np.sin(np.linspace(0, np.pi, 60))
    gyr[100:160, 0] += math.radians(3000.0) * burst
    gyr[120:150, 2] -= math.radians(9000.0) * np.linspace(0.05, 1.0, 30)   # through every shift
    t_us = 5_000_000 + np.arange(n, dtype=np.int64) * 3500
    return {"t": t_us, "acc": inp["acc"][sl], "gyr": gyr, "mag": inp["mag"][sl],
            "upd": (np.arange(n) % 4) == 0}


@pytest.mark.skipif(shutil.which("gcc") is None, reason="gcc not installed")
@pytest.mark.parametrize("system, mode", [("f32", 0), ("f32", 1), ("q", 0), ("q", 1)])
def test_host_unit_above_1877_dps_is_bit_identical_to_the_models(fast_inputs, system, mode):
    from kinefuse.firmware.hostunit import HostUnit, hil_run, unit_model
    from kinefuse.host.link.params import ParamClient
    d = fast_inputs
    with HostUnit(system, sensor=False) as u:
        s = u.session()
        try:
            pc = ParamClient(s, 1)
            for k, v in dict(KF_FILTER=5, KF_RATE_HZ=286, KF_HIL_MODE=mode).items():
                pc.set(k, v)
            got = hil_run(s, d["t"], d["acc"], d["gyr"], d["mag"], d["upd"])
        finally:
            s.close()
    ref = unit_model("flagship", system, d["t"], d["acc"], d["gyr"], d["mag"], d["upd"], rate_hz=286, mode=mode)
    assert set(np.unique(got["gyro_shift"]).tolist()) == {0, 1, 2, 3}
    assert np.array_equal(got["gyro_shift"], ref["gyro_shift"])
    assert np.array_equal(np.concatenate([got["acc"], got["gyr"], got["mag"]], 1), ref["counts"])
    assert not np.any(got["flags"] & GYRO_CLIPPED)
    assert np.array_equal(got["q"].view(np.uint32), ref["q"].view(np.uint32))
    # the host's decode of what was sent is within half an LSB of the float32 input
    dec = gyro_radps({"gyro_x": got["gyr"][:, 0], "gyro_y": got["gyr"][:, 1], "gyro_z": got["gyr"][:, 2],
                      "gyro_shift": got["gyro_shift"]})
    lsb = np.ldexp(1e-3, got["gyro_shift"].astype(int))[:, None]
    assert np.all(np.abs(dec - np.asarray(d["gyr"], np.float32).astype(np.float64)) <= lsb / 2)
