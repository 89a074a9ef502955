"""``fake:sensor_gap=N:MS``: the fake unit's sensor stalls once, as the host build's
``--sensor-gap N:MS``, and its KF_UNIT_STATUS says SENSOR_FAULT as the firmware does
(firmware/tests/test_app_sensor_fault.py): a silence of 4 periods and at least 100 ms sets the
flag in every status whose interval had it.  Driven on a made-up clock (no threads)."""
from __future__ import annotations

import pytest

from kinefuse.host.link.decoder import StreamDecoder
from kinefuse.host.link.fakeunit import FakeConnection, FakeUnit

SENSOR_FAULT = 4          # KF_UNIT_STATUS_FLAGS_SENSOR_FAULT


def _run(u, end_us, step_us=1000):
    """(status time, SENSOR_FAULT) of the periodic statuses and the KF_RAW_SAMPLE times up to end_us."""
    clock = [0]
    u.device_time_us = lambda: clock[0]
    st, raw = [], []
    for now in range(0, end_us + 1, step_us):
        clock[0] = now
        for f in StreamDecoder().feed(b"".join(u._emit_due())):
            if f.msgid == 52504:
                st.append((f.msg.time_boot_us, bool(f.msg.status_flags & SENSOR_FAULT)))
            elif f.msgid == 52500:
                raw.append(f.msg.time_boot_us)
    return st, raw


def test_a_gap_sets_sensor_fault_until_samples_resume():
    u = FakeUnit(None, rate_hz=1000, sensor_gap=(1500, 2000))     # silent from 1.5 s to 3.5 s
    st, raw = _run(u, 6_500_000)
    assert st == [(0, False), (1_000_000, False), (2_000_000, True), (3_000_000, True),
                  (4_000_000, True), (5_000_000, False), (6_000_000, False)]
    assert not [t for t in raw if 1_500_000 <= t < 3_500_000] and len(raw) == 6501 - 2000
    assert u.sent_samples == 4501


def test_a_short_gap_is_no_fault_and_the_timeout_is_4_periods_at_low_rates():
    st, _ = _run(FakeUnit(None, rate_hz=1000, sensor_gap=(1100, 90)), 3_500_000)   # 90 ms < 100 ms
    assert not any(f for _, f in st)
    st, _ = _run(FakeUnit(None, rate_hz=10, sensor_gap=(12, 300)), 3_500_000, 10_000)   # 10 Hz: 400 ms
    assert not any(f for _, f in st)
    st, _ = _run(FakeUnit(None, rate_hz=10, sensor_gap=(12, 500)), 3_500_000, 10_000)
    assert [f for _, f in st] == [False, False, True, False]


def test_no_gap_no_fault():
    st, raw = _run(FakeUnit(None, rate_hz=1000), 2_500_000)
    assert not any(f for _, f in st) and len(raw) == 2501


@pytest.mark.parametrize("value", ["5", "5:0", "x:5", "5:3600001", "-1:5", "5:"])
def test_bad_sensor_gap_option_is_one_line(value):
    from kinefuse.host.errors import KinefuseError
    with pytest.raises(KinefuseError, match="sensor_gap.*expected N:MS"):
        FakeConnection(f"sensor_gap={value}")


def test_sensor_gap_option():
    c = FakeConnection("rate=500,sensor_gap=200:150")
    try:
        assert c.unit.sensor_gap == (200, 150)
    finally:
        c.close()


def test_low_battery_follows_the_threshold_as_on_the_firmware():
    # the fake unit's cell reads 3,900 mV: above KF_BATT_LOW_MV's default (3,400), below 4,000
    u = FakeUnit(None, rate_hz=100)
    flags = []
    for low_mv in (3400, 4000, 0):
        u.params["KF_BATT_LOW_MV"] = low_mv
        f, = StreamDecoder().feed(u._status(0))
        assert f.msg.battery_voltage == 3900
        flags.append(bool(f.msg.status_flags & 16))       # KF_UNIT_STATUS_FLAGS_LOW_BATTERY
    assert flags == [False, True, False]
