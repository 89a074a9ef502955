"""The fake unit's KF_UNIT_STATUS follows the firmware (firmware/tests/test_app_unit_status.py):
MAG_PRESENT only once a magnetometer reading arrived, HIL_SENSOR with NaN or another sensor id
not processed and counted in the hil_invalid extension field."""
from __future__ import annotations

import math

from kinefuse.host.link.codec import Encoder
from kinefuse.host.link.decoder import StreamDecoder
from kinefuse.host.link.fakeunit import FakeUnit

MAG_PRESENT = 2


def _decode(frames):
    return StreamDecoder().feed(b"".join(frames))


def _status(u):
    (st,) = [f.msg for f in _decode([u._status(0)])]
    return st


def _hil(u, **over):
    f = dict(time_usec=1000, xacc=0.1, yacc=0.2, zacc=9.8, xgyro=0.01, ygyro=-0.02, zgyro=0.03,
             xmag=0.2, ymag=0.0, zmag=-0.4, temperature=21.5, fields_updated=0x11FF, id=0)
    f.update(over)
    (frame,) = StreamDecoder().feed(Encoder(255, 190).encode("HIL_SENSOR", **f))
    return [g.msg._msgname for g in _decode(u._handle(frame))]


def test_mag_present_only_after_a_streamed_sample():
    """The fake unit always said MAG_PRESENT, the firmware only once a reading arrived."""
    u = FakeUnit(None, rate_hz=1000)
    u.next_status_us = 1 << 62
    assert not _status(u).status_flags & MAG_PRESENT
    u.device_time_us = lambda: 3_000
    u._emit_due()
    assert _status(u).status_flags & MAG_PRESENT


def test_mag_present_from_hil_only_with_magnetometer_fields():
    u = FakeUnit(None, streaming=False)
    assert _hil(u, fields_updated=0x103F) == ["KF_RAW_SAMPLE"]
    assert not _status(u).status_flags & MAG_PRESENT
    _hil(u)
    assert _status(u).status_flags & MAG_PRESENT


def test_invalid_hil_samples_are_not_answered_and_counted():
    """The fake unit answered HIL_SENSOR id 1 (a sensor it does not have) and NaN values."""
    u = FakeUnit(None, streaming=False)
    assert _hil(u, id=1) == []
    assert _hil(u, xgyro=math.nan) == []
    assert not u.hil                                # nothing was processed
    st = _status(u)
    assert st.hil_invalid == 2 and st.numeric_resets == 0 and st.rejected_samples2 == 0


def test_a_nan_hil_temperature_is_not_measured():
    """As the firmware: processed, temperature 0 and not flagged valid (it cast NaN to int16)."""
    u = FakeUnit(None, streaming=False)
    (frame,) = StreamDecoder().feed(Encoder(255, 190).encode(
        "HIL_SENSOR", time_usec=1000, zacc=9.8, temperature=math.nan, fields_updated=0x11FF))
    (raw,) = [f.msg for f in _decode(u._handle(frame))]
    assert raw.temperature == 0 and not raw.flags & 32     # KF_RAW_SAMPLE_FLAGS_TEMPERATURE_VALID
