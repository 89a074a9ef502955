"""What the unit counts it also tells: KF_UNIT_STATUS extension fields (numeric_resets,
hil_invalid, rejected_samples2), the flags STORAGE_ERROR and MAG_PRESENT, each sensor's own
NUMERIC_RESET, and KF_HIL_MODE values refused where they do nothing (in-process test HAL)."""
from __future__ import annotations

import math

import pytest

MAG_PRESENT = 2           # KF_UNIT_STATUS_FLAGS (kinefuse.xml)
STORAGE_ERROR = 128
ORI_NUMERIC_RESET = 256   # KF_ORIENTATION_STATUS_NUMERIC_RESET
JA_NUMERIC_RESET = 8      # KF_JOINT_ANGLE_STATUS_NUMERIC_RESET
MAV_SEVERITY_ERROR = 3


def only(frames, name):
    return [f.msg for f in frames if f.msg._msgname == name]


def hil(unit, t, sensor, **over):
    f = dict(time_usec=t, xacc=0.1, yacc=0.2, zacc=9.8, xgyro=0.01, ygyro=-0.02, zgyro=0.03,
             xmag=0.2, ymag=0.0, zmag=-0.4, temperature=21.5, fields_updated=0x11FF, id=sensor)
    f.update(over)
    unit.send("HIL_SENSOR", **f)
    return unit.take()


def status(unit):
    """KF_UNIT_STATUS on MAV_CMD_REQUEST_MESSAGE (does not start a new status interval)."""
    unit.send("COMMAND_LONG", target_system=1, target_component=200, command=512, confirmation=0,
              param1=52504.0, param2=0.0, param3=0.0, param4=0.0, param5=0.0, param6=0.0, param7=0.0)
    st = only(unit.take(), "KF_UNIT_STATUS")
    assert st                                       # (after the one at boot if not taken yet)
    return st[-1]


def next_status(unit):
    """The periodic KF_UNIT_STATUS one second later (and the STATUSTEXTs sent with it)."""
    unit.advance(1_000_000)
    unit.poll(4)
    frames = unit.take()
    st = only(frames, "KF_UNIT_STATUS")
    assert len(st) == 1
    return st[0], only(frames, "STATUSTEXT")


def two_sensor_hil(unit, filter_id=3):
    unit.set_param("KF_FILTER", filter_id)
    unit.set_param("KF_JOINT_ID", 4)
    unit.take()
    hil(unit, 10_000, 1)
    hil(unit, 10_000, 0)


# ---------------------------------------------------------------- counters in KF_UNIT_STATUS

def test_unit_status_sends_hil_invalid(unit):
    """HIL_SENSOR with NaN or an unknown sensor id was counted and never reported."""
    hil(unit, 10_000, 0)
    assert status(unit).hil_invalid == 0
    hil(unit, 20_000, 2)                            # no sensor 2
    hil(unit, 20_000, 1)                            # sensor 1 on a one-sensor unit
    hil(unit, 20_000, 0, ygyro=math.nan)
    assert status(unit).hil_invalid == 3


def test_unit_status_sends_sensor_1_rejections(unit):
    """Sensor 1's rejection count was kept (across its filter's restarts) but sent nowhere."""
    two_sensor_hil(unit)
    for _ in range(3):
        hil(unit, 10_000, 1)                        # zero time steps: sensor 1's filter rejects them
    st = status(unit)
    assert (st.rejected_samples2, st.rejected_samples) == (3, 0)
    unit.lib.kft_reset_filter2(unit.app)            # its restart keeps the count
    assert status(unit).rejected_samples2 == 3
    hil(unit, 20_000, 1)
    hil(unit, 20_000, 1)                            # one more after the restart
    assert status(unit).rejected_samples2 == 4


@pytest.mark.parametrize("sensor", [0, 1])
def test_unit_status_sends_numeric_resets(unit, sensor):
    two_sensor_hil(unit)
    assert status(unit).numeric_resets == 0
    unit.lib.kft_poison_filter(unit.app, sensor)    # the next update gives a non-finite quaternion
    for k in range(3):
        hil(unit, 20_000 + 1000 * k, 1)
        hil(unit, 20_000 + 1000 * k, 0)
    assert status(unit).numeric_resets == 1


# ---------------------------------------------------------------- STORAGE_ERROR

def test_a_failed_save_sets_storage_error_for_one_status(unit):
    """Storage errors went out only as a STATUSTEXT: a host reading KF_UNIT_STATUS (or a
    recording's status table) could not see them."""
    unit = type(unit)(unit.ffi, unit.lib, storage_size=256)   # too small for a copy: every save fails
    unit.poll()
    boot = only(unit.take(), "KF_UNIT_STATUS")
    assert len(boot) == 1 and not boot[0].status_flags & STORAGE_ERROR
    unit.set_param("KF_ORI_RATE_HZ", 50)
    assert unit.counters()["storage_errors"] == 1
    assert status(unit).status_flags & STORAGE_ERROR   # requested in between: already told
    st, text = next_status(unit)
    assert st.status_flags & STORAGE_ERROR
    assert len(text) == 1 and text[0].severity == MAV_SEVERITY_ERROR   # the STATUSTEXT stays
    st, text = next_status(unit)                        # no new failure in this interval
    assert not st.status_flags & STORAGE_ERROR and text == []
    unit.set_param("KF_ORI_RATE_HZ", 20)                # a new failure: the flag again
    st, _ = next_status(unit)
    assert st.status_flags & STORAGE_ERROR


def test_a_working_storage_never_sets_storage_error(unit):
    unit.poll()
    unit.set_param("KF_ORI_RATE_HZ", 50)
    st, _ = next_status(unit)
    assert not st.status_flags & STORAGE_ERROR


# ---------------------------------------------------------------- NUMERIC_RESET per sensor

def _run(unit, t0, n):
    ori, ja = [], []
    for k in range(n):
        hil(unit, t0 + 1000 * k, 1)
        fr = hil(unit, t0 + 1000 * k, 0)
        ori += only(fr, "KF_ORIENTATION")
        ja += only(fr, "KF_JOINT_ANGLE")
    assert len(ori) == len(ja) == n
    return [m.status for m in ori], [m.status for m in ja]


@pytest.mark.parametrize("filter_id", [3, 5])
def test_sensor_1_numeric_reset_is_not_sensor_0s(unit, filter_id):
    """A non-finite state of sensor 1's filter set NUMERIC_RESET in KF_ORIENTATION, which is
    sensor 0's estimate (whose filter was fine); now KF_JOINT_ANGLE says it, once."""
    two_sensor_hil(unit, filter_id)
    unit.lib.kft_poison_filter(unit.app, 1)
    ori, ja = _run(unit, 20_000, 4)
    assert not any(s & ORI_NUMERIC_RESET for s in ori)
    assert [bool(s & JA_NUMERIC_RESET) for s in ja].count(True) == 1


@pytest.mark.parametrize("filter_id", [3, 5])
def test_sensor_0_numeric_reset_is_told_in_both_messages(unit, filter_id):
    two_sensor_hil(unit, filter_id)
    unit.lib.kft_poison_filter(unit.app, 0)
    ori, ja = _run(unit, 20_000, 4)
    got_ori = [bool(s & ORI_NUMERIC_RESET) for s in ori]
    assert got_ori.count(True) == 1
    assert [bool(s & JA_NUMERIC_RESET) for s in ja] == got_ori   # the same sample's pair


# ---------------------------------------------------------------- MAG_PRESENT

def test_mag_present_once_a_hil_mag_reading_arrived(unit):
    """MAG_PRESENT was never set."""
    assert not status(unit).status_flags & MAG_PRESENT
    hil(unit, 10_000, 0, fields_updated=0x103F)     # acc, gyro, temperature: no magnetometer
    assert not status(unit).status_flags & MAG_PRESENT
    hil(unit, 20_000, 0)                            # with magnetometer values
    assert status(unit).status_flags & MAG_PRESENT
    hil(unit, 30_000, 0, fields_updated=0x103F)     # since boot: stays
    assert status(unit).status_flags & MAG_PRESENT


@pytest.mark.parametrize("mag_valid", [0, 1])
def test_mag_present_from_the_sensor_even_with_the_mag_disabled(unit, mag_valid):
    unit.set_param("KF_MAG_ENABLE", 0)              # not used by the filter, but present
    for i in range(4):
        smp = unit.ffi.new("kf_raw_sample *")
        smp.time_us = 1000 * (i + 1)
        smp.acc[2] = 1000
        smp.mag[0] = 200
        smp.mag_valid = mag_valid
        assert unit.lib.kft_sensor_push(smp)
    unit.lib.kft_set_time(4000)
    unit.poll(4)
    unit.take()
    assert bool(status(unit).status_flags & MAG_PRESENT) == bool(mag_valid)


# ---------------------------------------------------------------- KF_HIL_MODE per build

def test_hil_mode_raw_q_bit_is_refused_on_float32_builds(unit):
    """KF_HIL_MODE 2/3 (raw Q quaternion out) were accepted on float32 builds, where there is
    no Q quaternion: the user asked for output that never came."""
    for v in (2, 3):
        frames = unit.set_param("KF_HIL_MODE", v)
        err = only(frames, "PARAM_ERROR")
        assert len(err) == 1 and err[0].error == 2          # out of range
        pv = only(frames, "PARAM_VALUE")
        assert len(pv) == 1 and unit.param("KF_HIL_MODE") == 0
    frames = unit.set_param("KF_HIL_MODE", 1)
    assert only(frames, "PARAM_ERROR") == [] and unit.param("KF_HIL_MODE") == 1


def test_hil_mode_raw_q_bit_is_accepted_on_fixed_point_builds(inproc_builder, unit_type):
    ffi, lib = inproc_builder("q")
    unit = unit_type(ffi, lib)
    for v in (2, 3, 0):
        frames = unit.set_param("KF_HIL_MODE", v)
        assert only(frames, "PARAM_ERROR") == [] and unit.param("KF_HIL_MODE") == v


def test_a_stored_raw_q_hil_mode_is_refused_at_load_on_float32(unit, inproc_builder, unit_type):
    """A fixed-point firmware's stored KF_HIL_MODE 2, loaded by a float32 firmware: the
    default runs and the unit warns (a value this build would ignore is not taken silently)."""
    qffi, qlib = inproc_builder("q")
    qunit = unit_type(qffi, qlib)
    qunit.set_param("KF_HIL_MODE", 3)
    image = qunit.storage()
    unit.restore_storage(image)
    unit.reboot()
    assert unit.param("KF_HIL_MODE") == 0
    assert unit.counters()["stored_rejects"] == 1
