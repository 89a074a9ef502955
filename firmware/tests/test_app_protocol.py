"""The application's link behaviour on the in-process test HAL: malformed frames and unknown
messages counted and survived, parameter rejections, commands, time sync, the sensor path.
(The same protocol against the host tools over a pty: test_app_host.py.)"""
from __future__ import annotations

import struct

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from kinefuse.host.link.codec import Encoder, frame_from_payload
from kinefuse.host.link.params import decode_value
from kinefuse.host.link.spec import kinefuse_dialect

ENC = Encoder(255, 190)


def read_req(index: int) -> bytes:
    return ENC.encode("PARAM_REQUEST_READ", target_system=1, target_component=200, param_id="",
                      param_index=index)


def names(frames) -> list[str]:
    return [f.msg._msgname for f in frames]


def only(frames, name):
    return [f.msg for f in frames if f.msg._msgname == name]


# ------------------------------------------------------------------------- malformed input

def test_bad_crc_is_counted_and_the_next_frame_still_handled(unit):
    good = read_req(1)
    bad = bytearray(read_req(2))
    bad[12] ^= 0x10                                   # payload bit: CRC fails
    unit.feed(bytes(bad) + good)
    got = only(unit.take(), "PARAM_VALUE")
    assert [m.param_index for m in got] == [1]
    assert unit.counters()["crc_errors"] == 1


def test_unknown_incompat_flag_and_oversized_length_are_bad_frames(unit):
    f = bytearray(read_req(3))
    f[2] = 0x02                                       # an incompatibility flag we do not know
    g = bytearray(read_req(4))
    g[1] = 200                                        # longer than PARAM_REQUEST_READ can be
    unit.feed(bytes(f) + bytes(g) + read_req(5))
    assert [m.param_index for m in only(unit.take(), "PARAM_VALUE")] == [5]
    assert unit.counters()["bad_frames"] == 2


def test_unknown_and_unhandled_messages_are_counted(unit):
    # a message id outside the dialect (valid framing, CRC with some extra byte)
    spec = kinefuse_dialect()["HEARTBEAT"]
    payload = spec.struct.pack(*([0] * len(spec.fields)))
    frame = bytearray(frame_from_payload(spec, payload, 255, 190, 0))
    frame[7:10] = (40001).to_bytes(3, "little")
    # a dialect message the unit does not handle (valid CRC)
    att = ENC.encode("ATTITUDE", time_boot_ms=1, roll=0.1)
    unit.feed(bytes(frame) + att + read_req(0))
    c = unit.counters()
    assert c["unknown_ids"] >= 1 and c["unknown_messages"] == 1
    assert [m.param_index for m in only(unit.take(), "PARAM_VALUE")] == [0]


def test_stray_magic_bytes_do_not_hide_frames(unit):
    stream = b"\xfd" + read_req(6) + b"\xfd\x09\x00" + read_req(7) + b"\x00\xfd\xff" + read_req(8)
    unit.feed(stream)
    assert [m.param_index for m in only(unit.take(), "PARAM_VALUE")] == [6, 7, 8]


def test_byte_by_byte_delivery(unit):
    stream = read_req(9) + read_req(10)
    for i in range(len(stream)):
        unit.feed(stream[i:i + 1], polls=1)
    assert [m.param_index for m in only(unit.take(), "PARAM_VALUE")] == [9, 10]


@settings(max_examples=60, deadline=None, derandomize=True)
@given(chunks=st.lists(st.tuples(st.binary(max_size=300), st.integers(0, 60)), min_size=1, max_size=12))
def test_garbage_never_crashes_and_never_costs_a_valid_frame(inproc_lib, unit_type, chunks):
    """Random bytes and truncated frames between valid requests: the unit answers exactly the
    requests the host's reference decoder finds in the same byte stream (every valid one, once),
    and nothing crashes."""
    from kinefuse.host.link.decoder import StreamDecoder
    ffi, lib = inproc_lib
    u = unit_type(ffi, lib)
    stream = b""
    for i, (junk, cut) in enumerate(chunks):
        full = read_req(i % 20)
        stream += junk + full[:cut % len(full)] + b"\x00" * 280 + full
    found = [f.msg.param_index for f in StreamDecoder(native=False).feed(stream)
             if f.msg._msgname == "PARAM_REQUEST_READ"]
    assert len(found) >= len(chunks)          # at least the intact requests
    u.feed(stream, polls=2)
    got = [m.param_index for m in only(u.take(), "PARAM_VALUE")]
    assert got == found


@settings(max_examples=40, deadline=None, derandomize=True)
@given(data=st.binary(min_size=1, max_size=2000))
def test_arbitrary_bytes_are_survived(inproc_lib, unit_type, data):
    ffi, lib = inproc_lib
    u = unit_type(ffi, lib)
    u.feed(data, polls=2)
    u.feed(b"\x00" * 280 + read_req(3))               # still alive and answering
    assert 3 in [m.param_index for m in only(u.take(), "PARAM_VALUE")]


# ------------------------------------------------------------------------------ parameters

def test_parameter_list_has_every_parameter_once(unit):
    unit.send("PARAM_REQUEST_LIST", target_system=1, target_component=200)
    unit.poll(50)
    got = only(unit.take(), "PARAM_VALUE")
    n = unit.lib.kft_param_count()
    assert len(got) == n and sorted(m.param_index for m in got) == list(range(n))
    assert all(m.param_count == n for m in got)
    ids = [m.param_id for m in got]
    assert len(set(ids)) == n and all(i.startswith("KF_") and len(i) <= 16 for i in ids)


@pytest.mark.parametrize("name, value, ptype, error", [
    ("KF_ORI_RATE_HZ", 5000, 3, 2),        # out of range
    ("KF_UNIT_ID", 0, 1, 2),               # out of range (0 is broadcast)
    ("KF_MW_BETA", 6.0, 9, 2),             # madgwick beta in [0, 5]
    ("KF_MW_BETA", float("nan"), 9, 2),    # NaN
    ("KF_ACC_SCALE", 0.0, 9, 2),           # calibration scale must be > 0
    ("KF_FILTER", 99, 1, 2),               # no such filter
    ("KF_FILTER", 9, 1, 2),                # triad: wired, but not in this build
    ("KF_ORI_RATE_HZ", 50.0, 9, 2),        # wrong type
    ("KF_SIGNING", 1, 1, 5),               # read-only
    ("KF_NO_SUCH_PARAM", 1, 1, 1),         # unknown name
])
def test_rejected_parameter_sets(unit, name, value, ptype, error):
    before = unit.param(name) if name != "KF_NO_SUCH_PARAM" else None
    frames = unit.set_param(name, value, ptype) if name != "KF_NO_SUCH_PARAM" else None
    if frames is None:
        unit.send("PARAM_SET", target_system=1, target_component=200, param_id=name,
                  param_value=1.0, param_type=ptype)
        frames = unit.take()
    errs = only(frames, "PARAM_ERROR")
    assert len(errs) == 1 and errs[0].error == error and errs[0].param_id == name
    vals = only(frames, "PARAM_VALUE")
    if before is None:
        assert vals == []
    else:
        assert len(vals) == 1 and unit.param(name) == before      # the unchanged value is echoed
        assert decode_value(vals[0].param_value, vals[0].param_type) == before
    assert unit.counters()["param_rejects"] == 1


def test_parameter_set_applies_and_echoes(unit):
    frames = unit.set_param("KF_MW_BETA", 0.25)
    v = only(frames, "PARAM_VALUE")
    assert len(v) == 1 and v[0].param_value == np.float32(0.25)
    assert unit.param("KF_MW_BETA") == np.float32(0.25)
    frames = unit.set_param("KF_SERIAL_NO", 0xFFFFFFFF)         # bytewise uint32
    assert decode_value(only(frames, "PARAM_VALUE")[0].param_value, 5) == 0xFFFFFFFF


def test_unit_id_changes_the_system_id(unit):
    unit.set_param("KF_UNIT_ID", 9)
    unit.advance(2_000_000)
    unit.poll()
    hb = [f for f in unit.take() if f.msg._msgname == "HEARTBEAT"]
    assert hb and all(f.sysid == 9 for f in hb)


# ------------------------------------------------------------------------------- commands

def command(unit, cmd, *p, target=1):
    p = list(p) + [0.0] * (7 - len(p))
    unit.send("COMMAND_LONG", target_system=target, target_component=200, command=cmd,
              confirmation=0, **{f"param{i + 1}": float(v) for i, v in enumerate(p)})
    return unit.take()


def ack(frames, cmd):
    acks = [m for m in only(frames, "COMMAND_ACK") if m.command == cmd]
    assert len(acks) == 1, names(frames)
    return acks[0].result


def push_samples(unit, n, start_us=0, period_us=1000, k0=0):
    from kinefuse.firmware.hostunit import synthetic_samples
    s = synthetic_samples(n, 1000, k0)
    for i in range(n):
        smp = unit.ffi.new("kf_raw_sample *")
        smp.time_us = (start_us + i * period_us) & 0xFFFFFFFF
        for j in range(3):
            smp.acc[j], smp.gyr[j], smp.mag[j] = int(s["acc"][i, j]), int(s["gyr"][i, j]), int(s["mag"][i, j])
        smp.mag_valid = int(s["mag_valid"][i])
        assert unit.lib.kft_sensor_push(smp)
    unit.time_us = (start_us + (n - 1) * period_us) & 0xFFFFFFFF
    unit.lib.kft_set_time(unit.time_us)
    unit.poll(n // 64 + 4)
    return s


def test_sensor_samples_stream_with_counters_and_decimation(unit):
    unit.take()
    s = push_samples(unit, 200, start_us=5000)
    frames = unit.take()
    raw = only(frames, "KF_RAW_SAMPLE")
    ori = only(frames, "KF_ORIENTATION")
    assert [m.sample_counter for m in raw] == list(range(200))
    assert [m.time_boot_us for m in raw] == [5000 + 1000 * i for i in range(200)]
    assert [[m.acc_x, m.acc_y, m.acc_z] for m in raw] == s["acc"].tolist()
    assert [m.sample_counter for m in ori] == list(range(9, 200, 10))   # 100 Hz of 1 kHz
    assert all(m.filter_id == 5 and m.earth_frame == 1 for m in ori)
    assert len(only(frames, "HIGHRES_IMU")) == 2 and len(only(frames, "ATTITUDE_QUATERNION")) == 2


def test_sensor_path_is_the_calibration_then_the_filter_bit_for_bit(unit):
    """Non-default calibration and filter parameters: the unit's quaternions equal the
    generated models' (calib_apply -> flagship) in every bit."""
    from kinefuse.firmware.hostunit import counts_model
    calib = {"gyr_b0": 0.01, "gyr_b2": -0.02, "acc_m00": 1.01, "acc_m01": 0.02, "mag_b1": 3.5,
             "mag_scale": 0.098}
    for k, v in calib.items():
        unit.set_param({"gyr_b0": "KF_GYR_B0", "gyr_b2": "KF_GYR_B2", "acc_m00": "KF_ACC_M00",
                        "acc_m01": "KF_ACC_M01", "mag_b1": "KF_MAG_B1", "mag_scale": "KF_MAG_SCALE"}[k], v)
    unit.set_param("KF_FL_TAU_ACC", 2.5)
    unit.set_param("KF_ORI_RATE_HZ", 1000)
    unit.take()
    s = push_samples(unit, 180, start_us=1000)
    got = np.array([[m.q_w, m.q_x, m.q_y, m.q_z] for m in only(unit.take(), "KF_ORIENTATION")], np.float32)
    t = 1000 + 1000 * np.arange(180)
    ref = counts_model("flagship", "f32", t, s["acc"], s["gyr"], s["mag"], s["mag_valid"],
                       rate_hz=1000, params={"tau_acc": 2.5}, calib=calib)
    assert got.shape == (180, 4)
    assert np.array_equal(got.view(np.uint32), ref["q"].view(np.uint32))


def test_stream_stop_start_and_counter_reset(unit):
    assert ack(command(unit, 52500, 0), 52500) == 0
    push_samples(unit, 30)
    assert only(unit.take(), "KF_RAW_SAMPLE") == []
    assert ack(command(unit, 52500, 1, 1), 52500) == 0          # start, reset the counter
    push_samples(unit, 20, start_us=100_000, k0=30)
    assert [m.sample_counter for m in only(unit.take(), "KF_RAW_SAMPLE")] == list(range(20))


def test_set_message_interval_and_request_message(unit):
    assert ack(command(unit, 511, 52501, 20000), 511) == 0      # KF_ORIENTATION at 50 Hz
    assert unit.param("KF_ORI_RATE_HZ") == 50
    # an interval above 2 s rounded to 0 Hz and turned the stream off; now refused, rate kept
    assert ack(command(unit, 511, 52501, 3e6), 511) == 2
    assert ack(command(unit, 511, 52501, float("inf")), 511) == 2
    assert unit.param("KF_ORI_RATE_HZ") == 50
    assert ack(command(unit, 511, 52500, 250), 511) == 2        # KF_RAW_SAMPLE at 4 kHz: above KF_RATE_HZ's 2000
    assert ack(command(unit, 511, 52501, -1), 511) == 0         # off
    assert unit.param("KF_ORI_RATE_HZ") == 0
    assert ack(command(unit, 511, 33, 1000), 511) == 3          # unsupported message
    frames = command(unit, 512, 52504)
    assert ack(frames, 512) == 0 and len(only(frames, "KF_UNIT_STATUS")) == 1
    frames = command(unit, 512, 148)
    v = only(frames, "AUTOPILOT_VERSION")
    assert len(v) == 1 and v[0].capabilities & 0x10 and v[0].capabilities & 0x2000  # BYTEWISE, MAVLINK2
    assert ack(command(unit, 4242), 4242) == 3                  # unknown command: unsupported


def test_heading_tare_and_filter_reset(unit):
    assert ack(command(unit, 52501, 0.5), 52501) == 1            # no orientation yet
    unit.set_param("KF_ORI_RATE_HZ", 1000)
    push_samples(unit, 50)
    assert ack(command(unit, 52501, 0.5), 52501) == 0
    unit.take()
    push_samples(unit, 1, start_us=50_000, k0=50)
    m = only(unit.take(), "KF_ORIENTATION")[-1]
    assert m.status & 64                                          # HEADING_TARED
    q = np.array([m.q_w, m.q_x, m.q_y, m.q_z], float)
    hx, hy = 1 - 2 * (q[2] ** 2 + q[3] ** 2), 2 * (q[1] * q[2] + q[0] * q[3])
    assert abs(np.arctan2(hy, hx) - 0.5) < 2e-3                   # x axis heading = 0.5 rad
    assert ack(command(unit, 52502), 52502) == 0
    push_samples(unit, 1, start_us=51_000, k0=51)
    assert not only(unit.take(), "KF_ORIENTATION")[-1].status & 64


def test_reboot_command_acks_first(unit):
    frames = command(unit, 246, 1)
    assert ack(frames, 246) == 0
    assert unit.lib.kft_reboots() == 1
    assert ack(command(unit, 246, 2), 246) == 3                   # shutdown etc.: unsupported


def test_commands_for_another_unit_are_ignored(unit):
    unit.take()
    assert only(command(unit, 52500, 0, target=7), "COMMAND_ACK") == []
    assert unit.counters()["unknown_messages"] == 0


def test_timesync(unit):
    unit.advance(123_456)
    unit.send("TIMESYNC", tc1=0, ts1=987654321)
    t = only(unit.take(), "TIMESYNC")
    assert len(t) == 1 and t[0].ts1 == 987654321 and t[0].tc1 == 123_456_000
    unit.send("TIMESYNC", tc1=5, ts1=1)                           # a reply: not answered
    assert only(unit.take(), "TIMESYNC") == []


def test_clock_extends_past_32_bits(unit):
    unit.advance(0xFFFFFF00)
    unit.poll()
    unit.advance(0x200)                                           # the 32-bit HAL clock wraps
    unit.send("TIMESYNC", tc1=0, ts1=1)
    t = only(unit.take(), "TIMESYNC")[0]
    assert t.tc1 == (0xFFFFFF00 + 0x200) * 1000


def test_unit_status_reports_the_counters(unit):
    bad = bytearray(read_req(1))
    bad[11] ^= 1
    unit.feed(bytes(bad) + ENC.encode("ATTITUDE", time_boot_ms=1))
    unit.set_param("KF_ORI_RATE_HZ", 9999)
    frames = command(unit, 512, 52504)
    st = only(frames, "KF_UNIT_STATUS")[0]
    assert (st.crc_errors, st.unknown_messages, st.param_rejects) == (1, 1, 1)
    assert st.dialect_hash == struct.unpack(">I", struct.pack(">I", st.dialect_hash))[0]
    from kinefuse.host.link.dialect import DIALECT_HASH
    assert st.dialect_hash == DIALECT_HASH()
