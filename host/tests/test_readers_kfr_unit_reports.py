"""What a unit said about itself reaches the recording the kfr reader returns: its STATUSTEXTs
(``metadata["unit_messages"]``, with time) and the KF_UNIT_STATUS / KF_ORIENTATION status bits
seen (``metadata["status_flags"]``); the reader dropped both."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.host.link.codec import Encoder
from kinefuse.host.readers import read_recording

from test_readers_kfr import MIN_LATENCY, _frames, _motion, _write_kfr

STORAGE = "parameter storage error: settings may be lost"
RANGE = "stored parameter out of range: default used"
AT = {150: ("STATUSTEXT", 3, STORAGE), 300: ("STATUSTEXT", 6, "calibration loaded"),
      420: ("STATUSTEXT", 4, RANGE)}          # after raw sample k, unit 1 says ...


def _unit_file(path):
    """Unit 1 at 200 Hz for 3 s with three statuses (STORAGE_ERROR in the second, LOW_BATTERY in
    the third), five
    orientations (two INPUT_CLIPPED) and three STATUSTEXTs; unit 9 (no samples) says something
    and reports a SENSOR_FAULT on the same link."""
    t, acc, gyr, mag = _motion(600)
    fr, dev = _frames(t, acc, gyr, mag, sysid=1, boot_s=2.0, drift_ppm=0)
    enc, other = Encoder(sysid=1, compid=200), Encoder(sysid=9, compid=200)
    items = []
    for k in range(600):
        items.append((t[k], fr[k]))
        if k in AT:
            _, sev, text = AT[k]
            items.append((t[k], enc.encode("STATUSTEXT", severity=sev, text=text, id=0, chunk_seq=0)))
        if k % 200 == 10:
            flags = 1 | 32 | (128 if k == 210 else 0) | (16 if k == 410 else 0)
            items.append((t[k], enc.encode("KF_UNIT_STATUS", time_boot_us=int(dev[k]), status_flags=flags,
                                           unit_id=1)))
            items.append((t[k], other.encode("KF_UNIT_STATUS", time_boot_us=5, status_flags=4, unit_id=9)))
        if k % 100 == 50 and k < 500:
            items.append((t[k], enc.encode("KF_ORIENTATION", time_boot_us=int(dev[k]), sample_counter=k, q_w=1.0,
                                           status=1 | (128 if k in (150, 250) else 0), unit_id=1)))
    items.append((t[599], other.encode("STATUSTEXT", severity=2, text="not unit 1", id=0, chunk_seq=0)))
    _write_kfr(path, [items])
    return t, dev


def test_statustexts_and_status_flags_in_the_metadata(tmp_path):
    p = tmp_path / "u.kfr"
    t, dev = _unit_file(p)
    r = read_recording(str(p))
    msgs = r.metadata["unit_messages"]
    assert [(m["severity"], m["severity_name"], m["text"]) for m in msgs] == \
        [(s, n, x) for (_, s, x), n in zip(AT.values(), ("ERROR", "INFO", "WARNING"))]
    ks = list(AT)
    assert [m["device_time_s"] for m in msgs] == [dev[k] / 1e6 for k in ks]   # the unit's latest sample
    # t: received on the recording's (host) time base, just after that sample's t
    k_t = np.array([r.t[k] for k in ks])
    assert np.all(np.array([m["t"] for m in msgs]) >= k_t - 1e-4)
    assert np.abs(np.array([m["t"] for m in msgs]) - (t[ks] + MIN_LATENCY)).max() < 0.03
    assert r.metadata["status_flags"] == {"KF_UNIT_STATUS": {"STREAMING": 3, "CALIBRATED": 3, "STORAGE_ERROR": 1,
                                                             "LOW_BATTERY": 1},
                                          "KF_ORIENTATION": {"INITIALISED": 5, "INPUT_CLIPPED": 2}}
    assert any(f"unit 1 said ERROR: {STORAGE}" in w for w in r.warnings), r.warnings
    assert any(f"unit 1 said WARNING: {RANGE}" in w for w in r.warnings)
    assert not any("calibration loaded" in w or "not unit 1" in w for w in r.warnings)   # INFO; unit 9
    assert any("STORAGE_ERROR in 1 of 3, LOW_BATTERY in 1 of 3 status message(s)" in w
               for w in r.warnings), r.warnings


def test_a_raw_capture_gives_the_device_time(tmp_path):
    """Without host times ``t`` is the unit's own clock, as the samples' ``t``."""
    from kinefuse.host.link.fakeunit import raw_frames
    data = raw_frames(100, rate_hz=200.0)
    data += Encoder(sysid=1, compid=200).encode("STATUSTEXT", severity=3, text=STORAGE, id=0, chunk_seq=0)
    p = tmp_path / "cap.bin"
    p.write_bytes(data)
    r = read_recording(str(p), fmt="kfr")
    (m,) = r.metadata["unit_messages"]
    assert m["t"] == m["device_time_s"] == pytest.approx(r.t[-1]) and m["text"] == STORAGE
    assert r.metadata["status_flags"] == {}
