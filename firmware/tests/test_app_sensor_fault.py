"""KF_UNIT_STATUS_FLAGS_SENSOR_FAULT: no HAL call reported a fault, so the flag was never set.
kf_hal_sensor_read has no error return; what the unit can honestly see is a configured sensor
(kf_hal_sensor_configure granted a rate) that stops delivering: nothing for 4 sample periods, and
at least 100 ms.  The flag is set in every 1 Hz status whose interval had such a silence and is
clear again from the first interval with samples throughout."""
from __future__ import annotations

import time

SENSOR_FAULT = 4          # KF_UNIT_STATUS_FLAGS_SENSOR_FAULT (kinefuse.xml)


def only(frames, name):
    return [f.msg for f in frames if f.msg._msgname == name]


def sensor_unit(unit, grant=0):
    """A unit whose HAL has a sensor (granting the rate asked for, or `grant` Hz)."""
    unit.lib.kft_sensor_grant(grant)
    unit.reboot()                                   # kf_config_apply_rates at reset
    unit.poll()
    unit.take()
    return unit


def run(unit, t_end_us, period_us=1000, sensor=True):
    """Step the clock to t_end_us in sample periods, with a sample each step when `sensor`;
    returns the KF_UNIT_STATUS flags sent meanwhile as (time_us, flags)."""
    out = []
    while unit.time_us + period_us <= t_end_us:
        unit.advance(period_us)
        if sensor:
            smp = unit.ffi.new("kf_raw_sample *")
            smp.time_us = unit.time_us
            smp.acc[2] = 1000
            assert unit.lib.kft_sensor_push(smp)
        unit.lib.kft_app_poll(unit.app)
        out += [(unit.time_us, m.status_flags) for m in only(unit.take(), "KF_UNIT_STATUS")]
    return out


def faults(statuses):
    return [bool(f & SENSOR_FAULT) for _, f in statuses]


def test_a_silent_sensor_sets_sensor_fault_until_samples_resume(unit):
    u = sensor_unit(unit)                            # 1000 Hz: timeout 100 ms
    st = run(u, 1_500_000)                           # samples: status at 1 s clear
    assert faults(st) == [False]
    st = run(u, 3_500_000, sensor=False)             # silent from 1.5 s: statuses at 2 s, 3 s
    assert faults(st) == [True, True]
    st = run(u, 6_500_000)                           # samples again from 3.5 s
    assert faults(st) == [True, False, False]        # 4 s: its interval had the silence


def test_sys_status_health_follows_sensor_fault(unit):
    """Generic ground stations read SYS_STATUS: gyro, accelerometer and magnetometer (bits
    0x1, 0x2, 0x4) are unhealthy in the status of a second with the silence, healthy again
    after it."""
    u = sensor_unit(unit)
    health = []
    for t_end, on in ((1_500_000, True), (3_500_000, False), (5_500_000, True)):
        while u.time_us + 1000 <= t_end:
            u.advance(1000)
            if on:
                smp = u.ffi.new("kf_raw_sample *")
                smp.time_us = u.time_us
                smp.acc[2] = 1000
                assert u.lib.kft_sensor_push(smp)
            u.lib.kft_app_poll(u.app)
            health += [m.onboard_control_sensors_health & 7 for m in only(u.take(), "SYS_STATUS")]
    assert health == [7, 0, 0, 0, 7]                 # 1 s; 2, 3 s silent; 4 s had it; 5 s


def test_the_timeout_is_100_ms_at_1_khz(unit):
    u = sensor_unit(unit)
    run(u, 1_100_000)                                # past the status at 1 s
    run(u, 1_190_000, sensor=False)                  # 90 ms without a sample: not a fault
    st = run(u, 2_100_000)
    assert faults(st) == [False]
    run(u, 2_250_000, sensor=False)                  # 150 ms: a fault, cleared by the next sample
    st = run(u, 4_100_000)
    assert faults(st) == [True, False]               # told once, at 3 s


def test_the_timeout_is_4_periods_at_low_rates(unit):
    u = sensor_unit(unit, grant=10)                  # the sensor delivers 10 Hz: 400 ms
    assert u.param("KF_RATE_HZ") == 10
    run(u, 1_100_000, period_us=100_000)
    run(u, 1_400_000, period_us=100_000, sensor=False)   # 300 ms (a sample was due at 1.2 s)
    st = run(u, 2_100_000, period_us=100_000)
    assert faults(st) == [False]
    run(u, 2_600_000, period_us=100_000, sensor=False)   # 500 ms
    st = run(u, 3_100_000, period_us=100_000)
    assert faults(st) == [True]


def test_a_late_main_loop_is_not_a_sensor_fault(unit):
    """The FIFO is read before the silence is judged: a turn 200 ms late that finds the samples
    of those 200 ms waiting is not a fault."""
    u = sensor_unit(unit)
    run(u, 1_100_000)
    for i in range(1, 201):                          # 200 samples queue up, nobody polls
        smp = u.ffi.new("kf_raw_sample *")
        smp.time_us = 1_100_000 + 1000 * i
        assert u.lib.kft_sensor_push(smp)
    u.advance(200_000)
    u.poll(8)
    st = run(u, 2_500_000)
    assert faults(st) == [False]


def test_no_sensor_no_fault(unit):
    """Boards without a sensor (kf_hal_sensor_configure -1: QEMU, HIL) never report one."""
    unit.poll()
    unit.take()
    st = run(unit, 3_500_000, sensor=False)
    assert len(st) == 3 and faults(st) == [False, False, False]


def test_a_rate_change_restarts_the_watch(unit):
    """The sensor may take a moment to start at a new rate: the timeout counts from the change."""
    u = sensor_unit(unit)
    run(u, 1_100_000)
    run(u, 1_190_000, sensor=False)                  # 90 ms silent, then a new rate
    u.set_param("KF_RATE_HZ", 500)
    st = run(u, 1_280_000, sensor=False)             # 90 ms since the change: no fault yet
    st += run(u, 2_100_000, period_us=2000)
    assert faults(st) == [False]


def test_host_build_sets_and_clears_sensor_fault():
    """kinefuse-unit whose synthetic sensor stalls (--sensor-gap: after 1,500 samples at
    1 kHz, 2.5 s without any): the statuses during the silence say SENSOR_FAULT, those before
    and from the second after the samples resumed do not."""
    from kinefuse.firmware.hostunit import HostUnit
    with HostUnit(extra=["--sensor-gap", "1500:2500"]) as unit:
        s = unit.session()
        st = []
        deadline = time.monotonic() + 12
        while time.monotonic() < deadline and (not st or st[-1][0] < 6.5):
            f = s.wait_for(lambda f: f.msgid == 52504, timeout=2)
            if f is not None:
                st.append((f.msg.time_boot_us * 1e-6, bool(f.msg.status_flags & SENSOR_FAULT),
                           f.msg.sensor_rate_achieved))
    assert st and st[-1][0] >= 6.5, st
    # the gap: from the 1,500th sample (about 1.5 s) to 2.5 s later; a status tells the second
    # before it.  Wide margins: the machine may be loaded.
    silent = [(t, fault) for t, fault, hz in st if hz < 1.0]
    assert silent and all(fault for _, fault in silent), st
    first_silent = min(t for t, _ in silent)
    last_silent = max(t for t, _ in silent)
    before = [fault for t, fault, _ in st if 0.5 < t < first_silent - 1.2]
    after = [fault for t, fault, _ in st if t > last_silent + 2.2]
    assert before and not any(before), st
    assert after and not any(after), st


def run2(unit, t_end_us, period_us=1000, sensors=(True, True)):
    """`run` for a two-sensor unit: each step a sample of sensor 0 and/or sensor 1."""
    out = []
    while unit.time_us + period_us <= t_end_us:
        unit.advance(period_us)
        for push, on in zip((unit.lib.kft_sensor_push, unit.lib.kft_sensor2_push), sensors):
            if on:
                smp = unit.ffi.new("kf_raw_sample *")
                smp.time_us = unit.time_us
                smp.acc[2] = 1000
                assert push(smp)
        unit.lib.kft_app_poll(unit.app)
        out += [(unit.time_us, m.status_flags) for m in only(unit.take(), "KF_UNIT_STATUS")]
    return out


def two_sensor_unit(unit):
    u = sensor_unit(unit)
    u.set_param("KF_JOINT_ID", 4)
    assert u.param("KF_JOINT_ID") == 4
    return u


def test_a_silent_second_sensor_sets_sensor_fault(unit):
    """Two-sensor mode: sensor 1 (kf_hal_sensor2_read) is watched like sensor 0; a silent
    distal sensor used to leave the flag clear while no joint angle could be formed."""
    u = two_sensor_unit(unit)
    st = run2(u, 1_500_000)
    assert faults(st) == [False]
    st = run2(u, 3_500_000, sensors=(True, False))   # sensor 1 silent from 1.5 s
    assert faults(st) == [True, True]
    st = run2(u, 5_500_000)
    assert faults(st) == [True, False]               # 4 s: its interval had the silence
    st = run2(u, 7_500_000, sensors=(False, True))   # and sensor 0 silent, as before
    assert faults(st) == [True, True]


def test_the_second_sensor_is_watched_from_the_start_of_two_sensor_mode(unit):
    """A unit switched to two-sensor mode gets the timeout to see its second sensor start;
    a unit without one (outside HIL mode) reports the fault."""
    u = sensor_unit(unit)
    run2(u, 1_100_000, sensors=(True, False))        # one sensor, no second: fine
    u.set_param("KF_JOINT_ID", 4)
    st = run2(u, 1_190_000, sensors=(True, False))   # 90 ms into two-sensor mode
    st += run2(u, 2_100_000)
    assert faults(st) == [False]
    st = run2(u, 4_100_000, sensors=(True, False))
    assert faults(st) == [True, True]


def test_hil_mode_does_not_watch_the_second_sensor(unit):
    """In HIL mode HIL_SENSOR id 1 stands in for sensor 1 (the board may have none); sensor 0
    is still read and watched."""
    u = two_sensor_unit(unit)
    run2(u, 1_100_000)
    u.send("HIL_SENSOR", time_usec=1_100_000, xacc=0.0, yacc=0.0, zacc=9.81, xgyro=0.0,
           ygyro=0.0, zgyro=0.0, xmag=0.2, ymag=0.0, zmag=-0.4, abs_pressure=0.0,
           diff_pressure=0.0, pressure_alt=0.0, temperature=0.0, fields_updated=0x1FF, id=0)
    u.take()
    st = run2(u, 3_100_000, sensors=(True, False))
    assert faults(st) == [False, False]
    st = run2(u, 5_100_000, sensors=(False, False))
    assert faults(st) == [True, True]
