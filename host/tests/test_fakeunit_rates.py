"""The fake unit (kinefuse.host.link.fakeunit) decimates and rounds message intervals as the
firmware does (kf_config.c divider, kf_handle.c set_interval): half up, not Python's half to
even.  (firmware/tests/test_app_defects.py compares the divider with the firmware itself.)"""
from __future__ import annotations

from kinefuse.host.link.codec import Encoder
from kinefuse.host.link.decoder import StreamDecoder
from kinefuse.host.link.fakeunit import FakeUnit, divider, interval_rate
from kinefuse.host.link.params import encode_value


def _decode(frames):
    return StreamDecoder().feed(b"".join(frames))


def test_orientation_divider_at_an_exact_half_rounds_up():
    """250 Hz / 100 Hz = 2.5: the unit sends every 3rd sample's orientation (counters 2, 5, 8),
    the fake unit sent every 2nd."""
    u = FakeUnit(None, rate_hz=250, orientation_rate_hz=100)
    u.next_status_us = 1 << 62                      # no status frames in the way
    u.device_time_us = lambda: 36_000               # samples at 0, 4000, ..., 36000 us: 10
    ori = [f.msg.sample_counter for f in _decode(u._emit_due()) if f.msg._msgname == "KF_ORIENTATION"]
    assert ori == [2, 5, 8]
    assert divider(250, 100) == 3 and divider(1000, 400) == 3 and divider(5, 2) == 3
    assert divider(1000, 0) == 0 and divider(100, 1000) == 1


def _set_interval(u, msgid, interval):
    enc = Encoder(255, 190)
    f = StreamDecoder().feed(enc.encode("COMMAND_LONG", target_system=1, target_component=200, command=511,
                                        confirmation=0, param1=float(msgid), param2=float(interval),
                                        param3=0.0, param4=0.0, param5=0.0, param6=0.0, param7=0.0))[0]
    (ack,) = _decode(u._handle(f))
    return ack.msg.result


def test_message_interval_rounds_half_up_and_refuses_like_the_unit():
    u = FakeUnit(None)
    assert _set_interval(u, 52501, 400_000) == 0    # 2.5 Hz
    assert u.params["KF_ORI_RATE_HZ"] == 3          # half up (half to even gave 2)
    assert _set_interval(u, 52501, 3e6) == 2        # 0.33 Hz: DENIED (it turned the stream off)
    assert _set_interval(u, 52501, float("inf")) == 2
    assert _set_interval(u, 52501, float("nan")) == 2   # it killed the fake unit's thread
    assert u.params["KF_ORI_RATE_HZ"] == 3
    assert _set_interval(u, 52501, -1) == 0 and u.params["KF_ORI_RATE_HZ"] == 0
    assert interval_rate(50) is None and interval_rate(1e6) == 1


def test_status_samples_count_since_boot_not_since_a_counter_reset():
    """KF_UNIT_STATUS counters 'count since boot' (the firmware's samples do); the fake unit
    reported the stream's sample_counter, which MAV_CMD_KF_STREAM p2 resets."""
    enc = Encoder(255, 190)
    u = FakeUnit(None, rate_hz=1000)
    u.next_status_us = 1 << 62
    u.device_time_us = lambda: 9_000                # 10 samples
    u._emit_due()
    f = StreamDecoder().feed(enc.encode("COMMAND_LONG", target_system=1, target_component=200, command=52500,
                                        confirmation=0, param1=1.0, param2=1.0, param3=0.0, param4=0.0,
                                        param5=0.0, param6=0.0, param7=0.0))[0]
    u._handle(f)                                    # streaming on, counter reset
    assert u.sample_counter == 0
    (st,) = _decode([u._status(9_000)])
    assert st.msg.samples == 10


def test_reading_an_unknown_parameter_is_answered_like_the_unit():
    """The unit answers PARAM_REQUEST_READ of an unknown index or name with PARAM_ERROR (1) and
    does not count it as a rejected PARAM_SET; the fake unit said nothing for an index (the host
    waited for its timeout) and counted the name case in param_rejects."""
    enc = Encoder(255, 190)
    u = FakeUnit(None)
    for index, name in ((99, ""), (-1, "KF_NOPE")):
        f = StreamDecoder().feed(enc.encode("PARAM_REQUEST_READ", target_system=1, target_component=200,
                                            param_id=name, param_index=index))[0]
        (err,) = _decode(u._handle(f))
        assert err.msg._msgname == "PARAM_ERROR" and err.msg.error == 1 and err.msg.param_index == index
    assert u.counters["param_rejects"] == 0


def test_a_rate_change_restarts_the_orientation_decimation_like_the_unit():
    """The firmware restarts its dividers when a rate changes (kf_config_apply_rates): after
    KF_ORI_RATE_HZ 100 -> 50 at sample 15 of a 1 kHz stream the next KF_ORIENTATION is the 20th
    sample after the change (counter 34); the fake unit took sample_counter % 20 (19, 39)."""
    enc = Encoder(255, 190)
    u = FakeUnit(None, rate_hz=1000, orientation_rate_hz=100)
    u.next_status_us = 1 << 62
    u.device_time_us = lambda: 14_000                # samples 0..14
    ori = [f.msg.sample_counter for f in _decode(u._emit_due()) if f.msg._msgname == "KF_ORIENTATION"]
    f = StreamDecoder().feed(enc.encode("PARAM_SET", target_system=1, target_component=200,
                                        param_id="KF_ORI_RATE_HZ", param_value=encode_value(50, 3),
                                        param_type=3))[0]
    u._handle(f)
    u.device_time_us = lambda: 39_000                # samples 15..39
    ori += [f.msg.sample_counter for f in _decode(u._emit_due()) if f.msg._msgname == "KF_ORIENTATION"]
    assert ori == [9, 34]
