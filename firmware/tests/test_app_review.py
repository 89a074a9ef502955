"""Review of the unit application (firmware/app): each test pins a defect that was fixed, on
the in-process test HAL (conftest.py)."""
from __future__ import annotations

from kinefuse.host.link.codec import Encoder

ENC = Encoder(255, 190)
TX_OVERFLOW = 64          # KF_UNIT_STATUS_FLAGS_TX_OVERFLOW (kinefuse.xml)


def only(frames, name):
    return [f.msg for f in frames if f.msg._msgname == name]


def push_raw(unit, n, start_us, period_us=1000):
    for i in range(n):
        smp = unit.ffi.new("kf_raw_sample *")
        smp.time_us = (start_us + i * period_us) & 0xFFFFFFFF
        smp.acc[2] = 1000
        assert unit.lib.kft_sensor_push(smp)


def test_tx_overflow_flag_is_per_status_interval(unit):
    """KF_UNIT_STATUS_FLAGS_TX_OVERFLOW: 'overflowed since the previous status'.  It was set
    from the cumulative frames_dropped, so one overflow marked every later status."""
    unit.set_param("KF_ORI_RATE_HZ", 1000)
    unit.take()
    unit.lib.kft_tx_limit(0)                       # the UART takes nothing: the queue fills
    t = 0
    for _ in range(12):                            # 12 x 250 samples x (raw + orientation) > 64 KiB
        push_raw(unit, 250, t)
        t += 250 * 1000
        unit.lib.kft_set_time(t)
        unit.poll(8)
    unit.lib.kft_tx_limit(65536)
    unit.poll(4)
    assert unit.counters()["frames_dropped"] > 0
    unit.take()
    unit.lib.kft_set_time(t + 1_000_000)           # the status of the interval with the drops
    unit.poll(4)
    st = only(unit.take(), "KF_UNIT_STATUS")
    assert len(st) == 1 and st[0].status_flags & TX_OVERFLOW
    dropped = st[0].frames_dropped
    unit.lib.kft_set_time(t + 2_000_000)           # a second without drops
    unit.poll(4)
    st = only(unit.take(), "KF_UNIT_STATUS")
    assert len(st) == 1 and st[0].frames_dropped == dropped
    assert not st[0].status_flags & TX_OVERFLOW


def hil_sample(unit, time_usec, **over):
    f = dict(time_usec=time_usec, xacc=0.1, yacc=0.2, zacc=9.8, xgyro=0.01, ygyro=-0.02, zgyro=0.03,
             xmag=0.2, ymag=0.0, zmag=-0.4, abs_pressure=0.0, diff_pressure=0.0, pressure_alt=0.0,
             temperature=21.5, fields_updated=0x11FF, id=0)
    f.update(over)
    unit.send("HIL_SENSOR", **f)
    return unit.take()


def test_hil_nan_temperature_is_not_reported_as_a_measurement(unit):
    """HIL_SENSOR with temperature NaN but its fields_updated bit set: KF_RAW_SAMPLE carried 0
    cdegC flagged TEMPERATURE_VALID ('holds a measurement'), HIGHRES_IMU its updated bit."""
    temp_valid = 32                                # KF_RAW_SAMPLE_FLAGS_TEMPERATURE_VALID
    unit.take()
    raw = only(hil_sample(unit, 1000), "KF_RAW_SAMPLE")
    assert len(raw) == 1 and raw[0].flags & temp_valid and raw[0].temperature == 2150
    raw = only(hil_sample(unit, 2000, temperature=float("nan")), "KF_RAW_SAMPLE")
    assert len(raw) == 1 and raw[0].temperature == 0
    assert not raw[0].flags & temp_valid
    unit.set_param("KF_HRIMU_RATE", 1000)          # HIGHRES_IMU with every (streamed) sample
    unit.take()
    hr = only(hil_sample(unit, 3000, temperature=float("nan")), "HIGHRES_IMU")
    assert len(hr) == 1 and not hr[0].fields_updated & 0x1000


def unit_status(unit):
    unit.poll()
    unit.take()                                    # the 1 Hz status of the start, if any
    unit.send("COMMAND_LONG", target_system=1, target_component=200, command=512, param1=52504.0)
    st = only(unit.take(), "KF_UNIT_STATUS")
    assert len(st) == 1
    return st[0]


def test_calibrated_flag_compares_values_not_bit_patterns(unit):
    """A bias of -0.0 is the default map (cal = M (counts scale - b) gives the same numbers),
    yet the bit-pattern comparison set KF_UNIT_STATUS_FLAGS_CALIBRATED."""
    calibrated = 32                                # KF_UNIT_STATUS_FLAGS_CALIBRATED
    assert not unit_status(unit).status_flags & calibrated
    unit.set_param("KF_ACC_B0", -0.0)
    assert unit.param_raw("KF_ACC_B0") == 0x80000000          # taken as sent
    assert not unit_status(unit).status_flags & calibrated
    unit.reboot()                                  # the same at load
    assert not unit_status(unit).status_flags & calibrated
    unit.set_param("KF_ACC_B0", 0.25)              # a real calibration is still flagged
    assert unit_status(unit).status_flags & calibrated


def test_setting_the_key_again_does_not_reopen_replays(unit):
    """SETUP_SIGNING cleared the signing streams and restarted the accepted timestamp from the
    stored floor: with the same key and an older initial_timestamp, frames accepted since the
    last save (here a signed TIMESYNC) were accepted a second time when replayed."""
    import hashlib
    from kinefuse.host.link.codec import frame_from_payload
    key = hashlib.sha256(b"kinefuse review key").digest()
    enc = Encoder(255, 190)

    def signed(name, ts, **fields):
        spec, payload = enc.payload(name, fields)
        return frame_from_payload(spec, payload, 255, 190, 0, key=key, link_id=0, timestamp=ts)

    setup = dict(target_system=1, target_component=200, secret_key=list(key))
    unit.feed(enc.encode("SETUP_SIGNING", initial_timestamp=1000, **setup))   # first key: unsigned
    assert unit.param("KF_SIGNING") == 1
    unit.take()
    ping = signed("TIMESYNC", 5000, tc1=0, ts1=77)
    unit.feed(ping)
    assert [m.ts1 for m in only(unit.take(), "TIMESYNC")] == [77]
    unit.feed(ping)                                # a replay in the same stream: dropped
    assert only(unit.take(), "TIMESYNC") == []
    failures = unit.counters()["signature_failures"]
    assert failures == 1
    unit.feed(signed("SETUP_SIGNING", 6000, initial_timestamp=0, **setup))    # the same key again
    assert unit.param("KF_SIGNING") == 1
    unit.take()
    unit.feed(ping)                                # the replay after the new setup
    assert only(unit.take(), "TIMESYNC") == []
    assert unit.counters()["signature_failures"] == failures + 1
    unit.feed(signed("TIMESYNC", 7000, tc1=0, ts1=78))                        # newer: accepted
    assert [m.ts1 for m in only(unit.take(), "TIMESYNC")] == [78]


def test_stream_counter_reset_keeps_efforts_on_the_orientation_samples(unit):
    """MAV_CMD_KF_STREAM p2 (reset the counter) restarted the decimation of KF_ORIENTATION,
    HIGHRES_IMU and ATTITUDE_QUATERNION but not of KF_EFFORTS: at the same rate KF_EFFORTS no
    longer went out with KF_ORIENTATION (same sample_counter) after a reset."""
    unit.set_param("KF_JOINT_ID", 4)               # two-sensor mode (no sensor 1 here: 'lost')
    unit.set_param("KF_EFF_RATE_HZ", 100)
    assert unit.param("KF_EFF_RATE_HZ") == 100 and unit.param("KF_ORI_RATE_HZ") == 100
    unit.take()
    push_raw(unit, 15, 1000)
    unit.lib.kft_set_time(15 * 1000)
    unit.poll(4)
    fr = unit.take()
    assert [m.sample_counter for m in only(fr, "KF_ORIENTATION")] == [9]
    assert [m.sample_counter for m in only(fr, "KF_EFFORTS")] == [9]
    unit.send("COMMAND_LONG", target_system=1, target_component=200, command=52500, param1=1.0, param2=1.0)
    assert [m.result for m in only(unit.take(), "COMMAND_ACK")] == [0]
    push_raw(unit, 20, 20_000)
    unit.lib.kft_set_time(40_000)
    unit.poll(4)
    fr = unit.take()
    assert [m.sample_counter for m in only(fr, "KF_ORIENTATION")] == [9, 19]
    assert [m.sample_counter for m in only(fr, "KF_EFFORTS")] == [9, 19]


def test_filter_reset_keeps_efforts_on_the_orientation_samples(unit):
    """MAV_CMD_KF_FILTER_RESET restarts the leg EKF with the filters; it also restarted the
    KF_EFFORTS decimation alone, so KF_EFFORTS left KF_ORIENTATION's samples."""
    unit.set_param("KF_JOINT_ID", 4)
    unit.set_param("KF_EFF_RATE_HZ", 100)
    unit.take()
    push_raw(unit, 15, 1000)
    unit.lib.kft_set_time(15 * 1000)
    unit.poll(4)
    fr = unit.take()
    assert [m.sample_counter for m in only(fr, "KF_EFFORTS")] == [9]
    unit.send("COMMAND_LONG", target_system=1, target_component=200, command=52502)
    assert [m.result for m in only(unit.take(), "COMMAND_ACK")] == [0]
    push_raw(unit, 20, 16_000)
    unit.lib.kft_set_time(36_000)
    unit.poll(4)
    fr = unit.take()
    assert [m.sample_counter for m in only(fr, "KF_ORIENTATION")] == [19, 29]
    assert [m.sample_counter for m in only(fr, "KF_EFFORTS")] == [19, 29]
    unit.set_param("KF_JOINT_ID", 0)               # leg EKF off for 7 samples, then on again
    push_raw(unit, 7, 36_000)
    unit.lib.kft_set_time(43_000)
    unit.poll(4)
    assert [m.sample_counter for m in only(unit.take(), "KF_EFFORTS")] == []
    unit.set_param("KF_JOINT_ID", 4)
    push_raw(unit, 20, 43_000)
    unit.lib.kft_set_time(63_000)
    unit.poll(4)
    fr = unit.take()
    assert [m.sample_counter for m in only(fr, "KF_ORIENTATION")] == [49, 59]
    assert [m.sample_counter for m in only(fr, "KF_EFFORTS")] == [49, 59]
