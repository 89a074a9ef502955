"""Defects of the unit application (firmware/app) found in review: each test pins one that was
fixed, on the in-process test HAL (conftest.py)."""
from __future__ import annotations

import pytest

from kinefuse.host.link.fakeunit import divider as fake_divider

SENSOR_FAULT = 4          # KF_UNIT_STATUS_FLAGS_SENSOR_FAULT (kinefuse.xml)
MAV_SEVERITY_ERROR = 3


def only(frames, name):
    return [f.msg for f in frames if f.msg._msgname == name]


def push_raw(unit, n, start_us, period_us):
    for i in range(n):
        smp = unit.ffi.new("kf_raw_sample *")
        smp.time_us = (start_us + i * period_us) & 0xFFFFFFFF
        smp.acc[2] = 1000
        smp.gyr[0] = 5 * (i % 7)
        assert unit.lib.kft_sensor_push(smp)
    unit.lib.kft_set_time((start_us + (n - 1) * period_us) & 0xFFFFFFFF)
    unit.poll(n // 64 + 4)


def hil(unit, t, sensor, **over):
    f = dict(time_usec=t, xacc=0.1, yacc=0.2, zacc=9.8, xgyro=0.01, ygyro=-0.02, zgyro=0.03,
             xmag=0.2, ymag=0.0, zmag=-0.4, abs_pressure=0.0, diff_pressure=0.0, pressure_alt=0.0,
             temperature=21.5, fields_updated=0x11FF, id=sensor)
    f.update(over)
    unit.send("HIL_SENSOR", **f)
    return unit.take()


def rejected(unit):
    arr = unit.ffi.new("uint32_t[4]")
    unit.lib.kft_rejected(unit.app, arr)
    return {"base0": arr[0], "inst0": arr[1], "base1": arr[2], "inst1": arr[3]}


# ---------------------------------------------------------------- rejection counts per sensor

def test_sensor_1_rejections_do_not_count_for_sensor_0(unit):
    """KF_ORIENTATION.rejected_samples (and KF_UNIT_STATUS) count the samples *sensor 0's*
    filter rejected.  A restart of sensor 1's instance (kf_config_reset_filter2, after a
    non-finite output) added sensor 1's rejections to sensor 0's count."""
    unit.set_param("KF_JOINT_ID", 4)
    unit.take()
    hil(unit, 10_000, 0)                    # into HIL: both filters start
    hil(unit, 10_000, 1)
    for _ in range(3):
        hil(unit, 10_000, 1)                # sensor 1: zero time steps, rejected
    r = rejected(unit)
    assert r["inst1"] == 3 and r["base0"] + r["inst0"] == 0
    unit.lib.kft_reset_filter2(unit.app)
    ori = only(hil(unit, 20_000, 0), "KF_ORIENTATION")
    assert len(ori) == 1 and ori[0].rejected_samples == 0       # was 3
    r = rejected(unit)
    assert r["base1"] == 3 and r["base0"] == 0
    # and sensor 0's own rejections are still counted
    ori = only(hil(unit, 20_000, 0), "KF_ORIENTATION")          # zero time step: rejected
    assert ori[0].rejected_samples == 1


def test_a_full_filter_reset_keeps_sensor_1_rejections_in_its_own_base(unit):
    unit.set_param("KF_JOINT_ID", 4)
    hil(unit, 10_000, 0)
    hil(unit, 10_000, 1)
    hil(unit, 10_000, 1)                    # one rejection on sensor 1
    unit.send("COMMAND_LONG", target_system=1, target_component=200, command=52502, confirmation=0,
              param1=0.0, param2=0.0, param3=0.0, param4=0.0, param5=0.0, param6=0.0, param7=0.0)
    unit.take()
    r = rejected(unit)
    assert (r["base0"], r["inst0"], r["base1"], r["inst1"]) == (0, 0, 1, 0)


# ---------------------------------------------------------------- storage errors

def test_storage_errors_are_not_a_sensor_fault(unit):
    """A failed parameter save raised KF_UNIT_STATUS_FLAGS_SENSOR_FAULT ('a sensor failed to
    respond'), for ever.  The dialect has no storage flag: the unit now says it in a STATUSTEXT
    (severity ERROR) at the next status, once per new failure."""
    unit = type(unit)(unit.ffi, unit.lib, storage_size=256)   # too small for a copy: every save fails
    unit.poll()
    assert only(unit.take(), "STATUSTEXT") == []        # the status at boot: loading found nothing wrong
    unit.set_param("KF_ORI_RATE_HZ", 50)
    assert unit.counters()["storage_errors"] == 1
    unit.advance(1_000_000)
    unit.poll(4)
    frames = unit.take()
    st = only(frames, "KF_UNIT_STATUS")
    text = only(frames, "STATUSTEXT")
    assert len(st) == 1 and not st[0].status_flags & SENSOR_FAULT
    assert len(text) == 1 and text[0].severity == MAV_SEVERITY_ERROR
    assert "storage" in text[0].text
    unit.advance(1_000_000)                             # no new failure: no new text
    unit.poll(4)
    frames = unit.take()
    assert len(only(frames, "KF_UNIT_STATUS")) == 1 and only(frames, "STATUSTEXT") == []


def test_a_working_storage_sends_no_storage_text(unit):
    unit.poll()
    unit.set_param("KF_ORI_RATE_HZ", 50)
    unit.advance(1_000_000)
    unit.poll(4)
    frames = unit.take()
    assert only(frames, "STATUSTEXT") == [] and len(only(frames, "KF_UNIT_STATUS")) == 1


# ---------------------------------------------------------------- the rate the sensor grants

def test_the_granted_sensor_rate_is_the_rate_used(unit):
    """kf_hal_sensor_configure returns the rate the sensor will deliver; it was ignored, so with
    a sensor that rounds (IMU output data rates) the unit decimated, reported and answered
    PARAM_VALUE with the rate asked for."""
    unit.lib.kft_sensor_grant(500)                      # the sensor only does 500 Hz
    frames = unit.set_param("KF_RATE_HZ", 400)
    assert unit.lib.kft_sensor_asked() == 400
    pv = only(frames, "PARAM_VALUE")
    assert len(pv) == 1 and unit.param("KF_RATE_HZ") == 500
    assert only(frames, "PARAM_ERROR") == []
    unit.send("COMMAND_LONG", target_system=1, target_component=200, command=512, confirmation=0,
              param1=52504.0, param2=0.0, param3=0.0, param4=0.0, param5=0.0, param6=0.0, param7=0.0)
    st = only(unit.take(), "KF_UNIT_STATUS")
    assert st[0].sensor_rate_requested == 500.0
    push_raw(unit, 20, 2000, 2000)                      # 500 Hz samples, KF_ORI_RATE_HZ 100
    ori = only(unit.take(), "KF_ORIENTATION")
    assert [m.sample_counter for m in ori] == [4, 9, 14, 19]   # every 5th (400 Hz: every 4th)


def test_the_granted_rate_is_used_after_a_reboot(unit):
    unit.lib.kft_sensor_grant(0)                        # a sensor that delivers what is asked
    unit.set_param("KF_RATE_HZ", 400)
    assert unit.param("KF_RATE_HZ") == 400
    unit.lib.kft_sensor_grant(500)                      # another sensor (or board) after a reboot
    unit.reboot()
    assert unit.param("KF_RATE_HZ") == 500


def test_a_granted_rate_outside_the_range_is_refused(unit):
    unit.lib.kft_sensor_grant(0)
    unit.set_param("KF_RATE_HZ", 800)
    unit.lib.kft_sensor_grant(3000)                     # above KF_RATE_HZ's 2000
    frames = unit.set_param("KF_RATE_HZ", 1600)
    err = only(frames, "PARAM_ERROR")
    assert len(err) == 1 and err[0].error == 2          # out of range
    assert unit.param("KF_RATE_HZ") == 800
    assert unit.lib.kft_sensor_asked() == 800           # asked for the old rate again


# ---------------------------------------------------------------- dividers: the fake unit agrees

@pytest.mark.parametrize("rate, ori", [(250, 100), (5, 2), (1000, 400), (30, 4), (1000, 300), (7, 7), (3, 4)])
def test_fake_unit_divider_equals_the_firmware(unit, rate, ori):
    """The firmware rounds the divider half up; the fake unit (kinefuse.host.link.fakeunit)
    rounded half to even, so at an exact half (250/100) they sent different orientations."""
    unit.set_param("KF_RATE_HZ", rate)
    unit.set_param("KF_ORI_RATE_HZ", ori)
    unit.take()
    period = 1_000_000 // rate
    push_raw(unit, 40, period, period)
    got = [m.sample_counter for m in only(unit.take(), "KF_ORIENTATION")]
    d = fake_divider(rate, ori)
    assert got == [k for k in range(40) if (k + 1) % d == 0]


def _store_value(image: bytearray, name: str, value: int, slot: int = 0):
    """Put `value` into the stored entry of `name` of the copy in `slot`, CRC made valid again."""
    import struct
    import zlib
    h = 2166136261
    for c in name.encode():
        h = ((h ^ c) * 16777619) & 0xFFFFFFFF
    base = slot * 2048
    count = struct.unpack_from("<H", image, base + 6)[0]
    for i in range(count):
        off = base + 56 + 8 * i
        if struct.unpack_from("<I", image, off)[0] == h:
            struct.pack_into("<I", image, off + 4, value)
            break
    else:
        raise AssertionError("entry not found")
    end = base + 56 + 8 * count
    struct.pack_into("<I", image, end, zlib.crc32(bytes(image[base:end])))


def test_a_stored_value_refused_at_load_is_told(unit):
    """A stored value outside its range is replaced by the default (counted, but the counter was
    reported nowhere): the configuration changed without a word.  Now a STATUSTEXT (WARNING)
    goes out with the first status after the load."""
    unit.set_param("KF_ORI_RATE_HZ", 50)
    image = bytearray(unit.storage())
    _store_value(image, "KF_ORI_RATE_HZ", 5000)
    unit.restore_storage(bytes(image))
    unit.reboot()
    unit.advance(1)
    unit.poll()
    text = only(unit.take(), "STATUSTEXT")
    assert unit.param("KF_ORI_RATE_HZ") == 100
    assert len(text) == 1 and text[0].severity == 4 and "default" in text[0].text
    unit.advance(1_000_000)
    unit.poll()
    assert only(unit.take(), "STATUSTEXT") == []        # once


def test_sys_status_does_not_call_a_disabled_magnetometer_enabled(unit):
    MAG = 4                                             # MAV_SYS_STATUS_SENSOR_3D_MAG
    unit.poll()
    unit.take()                                         # the status at boot
    unit.send("COMMAND_LONG", target_system=1, target_component=200, command=512, confirmation=0,
              param1=1.0, param2=0.0, param3=0.0, param4=0.0, param5=0.0, param6=0.0, param7=0.0)
    (s,) = only(unit.take(), "SYS_STATUS")
    assert s.onboard_control_sensors_enabled & MAG
    unit.set_param("KF_MAG_ENABLE", 0)
    unit.send("COMMAND_LONG", target_system=1, target_component=200, command=512, confirmation=0,
              param1=1.0, param2=0.0, param3=0.0, param4=0.0, param5=0.0, param6=0.0, param7=0.0)
    (s,) = only(unit.take(), "SYS_STATUS")
    assert not s.onboard_control_sensors_enabled & MAG and s.onboard_control_sensors_present & MAG
    assert s.onboard_control_sensors_enabled & 3        # gyroscope and accelerometer


@pytest.mark.parametrize("mode, used", [(1.0, True), (0.0, False)])
def test_mag_used_is_not_claimed_in_6d_mode(unit, mode, used):
    """KF_ORIENTATION_STATUS_MAG_USED ('the magnetometer corrects heading (9D)') was set whenever
    a magnetometer reading reached the filter, also with flagship in 6D mode (KF_FL_MODE 0:
    'magnetometer ignored')."""
    MAG_USED, MAG_DISTURBED = 8, 4
    unit.set_param("KF_FL_MODE", mode)
    unit.set_param("KF_ORI_RATE_HZ", 100)
    unit.take()
    for i in range(40):
        smp = unit.ffi.new("kf_raw_sample *")
        smp.time_us = 1000 + 1000 * i
        smp.acc[2] = 1000
        smp.mag[0], smp.mag[1], smp.mag[2] = 0, 190, -450      # a plain field, 0.1 uT counts
        smp.mag_valid = 1
        assert unit.lib.kft_sensor_push(smp)
    unit.lib.kft_set_time(40_000)
    unit.poll(4)
    ori = only(unit.take(), "KF_ORIENTATION")
    assert len(ori) == 4
    assert all(not m.status & MAG_DISTURBED for m in ori)
    assert all(bool(m.status & MAG_USED) == used for m in ori)


@pytest.mark.parametrize("mode, unreliable", [(1.0, False), (0.0, True)])
def test_joint_angle_heading_unreliable_in_6d_mode(unit, mode, unreliable):
    """KF_JOINT_ANGLE_STATUS_HEADING_UNRELIABLE: 'no valid heading (6D or magnetic
    disturbance)'; it was set for KF_MAG_ENABLE 0 only, not for a filter in 6D mode."""
    HEADING_UNRELIABLE = 4
    unit.set_param("KF_JOINT_ID", 4)
    unit.set_param("KF_FL_MODE", mode)
    unit.take()
    status = []
    for i in range(5):
        hil(unit, 10_000 + 10_000 * i, 1)
        status += [m.status for m in only(hil(unit, 10_000 + 10_000 * i, 0), "KF_JOINT_ANGLE")]
    assert len(status) == 5
    assert all(bool(s & HEADING_UNRELIABLE) == unreliable for s in status)


def test_no_filter_requests_no_orientation_stream(unit):
    """KF_FILTER 0 (none): no KF_ORIENTATION goes out, but KF_UNIT_STATUS said
    orientation_rate_requested = KF_ORI_RATE_HZ ('0: off')."""
    def status():
        unit.send("COMMAND_LONG", target_system=1, target_component=200, command=512, confirmation=0,
                  param1=52504.0, param2=0.0, param3=0.0, param4=0.0, param5=0.0, param6=0.0, param7=0.0)
        return only(unit.take(), "KF_UNIT_STATUS")[-1]
    assert status().orientation_rate_requested == 100.0
    unit.set_param("KF_FILTER", 0)
    push_raw(unit, 20, 1000, 1000)
    frames = unit.take()
    assert only(frames, "KF_ORIENTATION") == [] and len(only(frames, "KF_RAW_SAMPLE")) == 20
    st = status()
    assert st.orientation_rate_requested == 0.0 and st.filter_id == 0


def test_fake_unit_restarts_the_decimation_on_a_rate_change_as_the_firmware(unit):
    """KF_ORI_RATE_HZ changed mid-stream: the firmware restarts its dividers; the fake unit took
    sample_counter % divider.  Both now send the same samples' orientations."""
    from kinefuse.host.link.codec import Encoder
    from kinefuse.host.link.decoder import StreamDecoder
    from kinefuse.host.link.fakeunit import FakeUnit
    from kinefuse.host.link.params import encode_value
    unit.take()
    push_raw(unit, 15, 1000, 1000)
    got = [m.sample_counter for m in only(unit.take(), "KF_ORIENTATION")]
    unit.set_param("KF_ORI_RATE_HZ", 50)
    push_raw(unit, 25, 16_000, 1000)
    got += [m.sample_counter for m in only(unit.take(), "KF_ORIENTATION")]

    fake = FakeUnit(None, rate_hz=1000, orientation_rate_hz=100)
    fake.next_status_us = 1 << 62
    dec = StreamDecoder()
    fake.device_time_us = lambda: 14_000
    ref = [f.msg.sample_counter for f in dec.feed(b"".join(fake._emit_due())) if f.msg._msgname == "KF_ORIENTATION"]
    (ps,) = StreamDecoder().feed(Encoder(255, 190).encode(
        "PARAM_SET", target_system=1, target_component=200, param_id="KF_ORI_RATE_HZ",
        param_value=encode_value(50, 3), param_type=3))
    fake._handle(ps)
    fake.device_time_us = lambda: 39_000
    ref += [f.msg.sample_counter for f in dec.feed(b"".join(fake._emit_due())) if f.msg._msgname == "KF_ORIENTATION"]
    assert got == ref and len(got) == 2
