"""The battery warning: KF_UNIT_STATUS LOW_BATTERY from the 1 Hz reading of kf_hal_battery_mv()
against KF_BATT_LOW_MV (with 100 mV of hysteresis), a STATUSTEXT once per fall, and the battery
in SYS_STATUS where the board measures it (in-process test HAL, whose battery reads as set)."""
from __future__ import annotations

LOW_BATTERY = 16                  # KF_UNIT_STATUS_FLAGS_LOW_BATTERY (kinefuse.xml)
SENSOR_BATTERY = 0x02000000       # MAV_SYS_STATUS_SENSOR_BATTERY (common.xml)
MAV_SEVERITY_WARNING = 4


def only(frames, name):
    return [f.msg for f in frames if f.msg._msgname == name]


def second(unit, mv):
    """One 1 Hz status with the battery reading mv: (KF_UNIT_STATUS, SYS_STATUS, STATUSTEXTs)."""
    unit.lib.kft_set_battery_mv(mv)
    unit.advance(1_000_000)
    unit.poll(4)
    frames = unit.take()
    st, sy = only(frames, "KF_UNIT_STATUS"), only(frames, "SYS_STATUS")
    assert len(st) == 1 and len(sy) == 1
    return st[0], sy[0], [m.text for m in only(frames, "STATUSTEXT")]


def test_low_battery_is_set_below_the_threshold_with_hysteresis(unit):
    unit.poll(4)
    unit.take()
    assert unit.param("KF_BATT_LOW_MV") == 3400            # the default: one Li-ion/LiPo cell
    seen = []
    for mv in (3900, 3401, 3400, 3399, 3300, 3450, 3499, 3500, 3600, 3390):
        st, sy, texts = second(unit, mv)
        assert st.battery_voltage == mv and sy.voltage_battery == mv
        seen.append((bool(st.status_flags & LOW_BATTERY), len([t for t in texts if "battery low" in t])))
    assert seen == [(False, 0), (False, 0), (False, 0), (True, 1), (True, 0), (True, 0),
                    (True, 0), (False, 0), (False, 0), (True, 1)]   # told again after recovery


def test_sys_status_reports_the_battery_and_its_health(unit):
    unit.poll(4)
    unit.take()
    _st, sy, _ = second(unit, 0xFFFF)                         # the board does not measure it
    assert sy.onboard_control_sensors_present & SENSOR_BATTERY == 0
    for mv, healthy in ((3800, True), (3200, False)):
        _st, sy, texts = second(unit, mv)
        assert sy.onboard_control_sensors_present & SENSOR_BATTERY
        assert sy.onboard_control_sensors_enabled & SENSOR_BATTERY
        assert bool(sy.onboard_control_sensors_health & SENSOR_BATTERY) == healthy
    warn = [f.msg for f in unit.take() if f.msg._msgname == "STATUSTEXT"]
    assert not warn                                            # (told in its second, above)


def test_low_battery_never_without_a_reading_or_with_the_warning_off(unit):
    unit.poll(4)
    unit.take()
    st, _sy, texts = second(unit, 0xFFFF)                      # not measured: never low
    assert not st.status_flags & LOW_BATTERY and not texts
    st, _sy, texts = second(unit, 3000)
    assert st.status_flags & LOW_BATTERY and texts == ["battery low: recharge the unit"]
    unit.set_param("KF_BATT_LOW_MV", 0)                        # off: clears at the next second
    assert unit.param("KF_BATT_LOW_MV") == 0
    st, _sy, texts = second(unit, 3000)
    assert not st.status_flags & LOW_BATTERY and not texts
    frames = unit.set_param("KF_BATT_LOW_MV", 5001)            # out of range: refused
    assert unit.param("KF_BATT_LOW_MV") == 0
    assert only(frames, "PARAM_ERROR") or only(frames, "PARAM_VALUE")


def test_the_battery_text_is_told_once_however_full_the_link_was(unit):
    # the UART takes nothing for a minute (the 4 kB transmit buffer fills and frames are
    # dropped), the battery goes low meanwhile: once the link drains, the warning has been told
    # exactly once (queued then, or sent in a later second), and the flag stays set
    unit.poll(4)
    unit.take()
    unit.lib.kft_tx_limit(0)
    for k in range(63):
        unit.lib.kft_set_battery_mv(3900 if k < 60 else 3000)
        unit.advance(1_000_000)
        unit.poll(4)
    unit.lib.kft_tx_limit(1 << 20)
    unit.poll(8)
    frames = unit.take()
    texts = [m.text for m in only(frames, "STATUSTEXT")]
    for _ in range(3):
        st, _sy, t = second(unit, 3000)
        assert st.status_flags & LOW_BATTERY
        texts += t
    assert texts.count("battery low: recharge the unit") == 1
