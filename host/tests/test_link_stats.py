"""Link statistics on synthetic data with known loss, drift, offset and latency."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.host.link import stats
from kinefuse.host.link.codec import Encoder
from kinefuse.host.link.frames import decode_file
from kinefuse.host.link.recording import RecordingWriter, make_header


def test_counter_loss_is_wrap_safe():
    c = np.array([2**32 - 3, 2**32 - 2, 2**32 - 1, 0, 1, 3, 4], dtype=np.uint32)
    r = stats.counter_analysis(c)
    assert r["stride"] == 1 and r["samples_lost"] == 1 and r["resets"] == 0


def test_decimated_stream_is_not_loss_and_resets_are_counted():
    c = np.concatenate([np.arange(0, 500, 5), np.arange(510, 700, 5), np.arange(0, 100, 5), [95]])
    r = stats.counter_analysis(c.astype(np.uint32))
    assert r["stride"] == 5 and r["samples_lost"] == 2  # 500 and 505 missing
    assert r["resets"] == 1 and r["duplicates"] == 1


def test_a_stride_change_is_not_loss():
    """KF_ORIENTATION at 100 Hz counts samples: step 10 at 1 kHz, then 5 after `record --rate
    500`; the 10-steps were counted as lost (37 of 377 in a SIL recording).  One real loss in
    each part."""
    c = np.concatenate([np.arange(0, 1000, 10), np.arange(1010, 2000, 10),    # 1000 missing
                        np.arange(2000, 3505, 5), np.arange(3510, 5000, 5)])  # 3505 missing
    r = stats.counter_analysis(c.astype(np.uint32))
    assert r["samples_lost"] == 2 and r["stride"] == 5 and r["resets"] == 0
    every_50th = np.delete(np.arange(2001), np.arange(49, 2000, 50))           # fake:drop=50
    assert stats.counter_analysis(every_50th)["samples_lost"] == 40


def test_heavy_loss_is_not_taken_for_a_longer_stride():
    """A third to a half of the frames lost (a bad radio link, fake:corrupt=0.002): the median
    of the steps around each one was 2 or more, so stats reported 428 of 783 lost samples."""
    rng = np.random.default_rng(3)
    for stride, keep in ((1, 0.66), (1, 0.5), (10, 0.5), (1, 0.03)):
        sent = np.arange(0, 200_000, stride)
        got = sent[rng.random(sent.size) < keep]
        r = stats.counter_analysis(got.astype(np.uint32))
        assert r["samples_lost"] == (got[-1] - got[0]) // stride + 1 - got.size, (stride, keep)
    # the firmware restarts its divider on a rate change: the step across it is neither stride
    c = np.concatenate([np.arange(0, 2000, 10), np.arange(1997, 4000, 5)])
    assert stats.counter_analysis(c.astype(np.uint32))["samples_lost"] == 0
    # next to a change of stride each side keeps its own: 10 -> 5 with 30 % loss
    sent = np.concatenate([np.arange(0, 5000, 10), np.arange(5000, 10000, 5)])
    got = sent[rng.random(sent.size) < 0.7]
    assert stats.counter_analysis(got.astype(np.uint32))["samples_lost"] == \
        np.count_nonzero(~np.isin(sent[(sent >= got[0]) & (sent <= got[-1])], got))


def test_clock_fit_is_robust_to_delay_spikes():
    rng = np.random.default_rng(0)
    device = np.arange(0, 60, 0.005)                          # 200 Hz for 60 s
    drift = 30e-6                                              # unit clock 30 ppm fast
    delay = 0.002 + rng.exponential(0.0005, device.size)
    delay[-2000:] += rng.uniform(0, 0.05, 2000)                # congestion at the end
    host = 5.0 + device / (1 + drift) + delay
    fit = stats.fit_clock(device, host)
    assert abs(fit["drift_ppm"] - 30) < 1.0
    assert abs(fit["offset_s"] - 5.002) < 2e-4
    assert fit["delay_above_min_ms"]["median"] == pytest.approx(np.median(delay - 0.002) * 1e3, abs=0.1)
    slope_ls = np.polyfit(device, host, 1)[0]                  # ordinary least squares is pulled away
    assert abs((1 / slope_ls - 1) * 1e6 - 30) > 3.0


@pytest.fixture(scope="module")
def synthetic(tmp_path_factory):
    """200 Hz samples for 40 s, unit clock +50 ppm, 3 samples lost, counter wrapping, 1 Hz TIMESYNC."""
    rng = np.random.default_rng(1)
    path = tmp_path_factory.mktemp("stats") / "s.kfr"
    head = make_header([{"id": 0, "connection": "synthetic"}])
    t0 = head["start_monotonic_ns"]
    enc = Encoder(sysid=3, compid=200)
    n = 8000
    counters = (np.arange(n, dtype=np.int64) + 2**32 - 4000) & 0xFFFFFFFF
    keep = np.ones(n, bool)
    keep[[100, 101, 5000]] = False
    reads, last = [], t0
    for k in np.flatnonzero(keep):
        dev_us = 1_000_000 + 5000 * int(k)
        host = t0 + 250_000_000 + int(dev_us * 1000 / (1 + 50e-6)) + 1_500_000 + int(rng.exponential(400_000))
        last = max(last + 1, host)
        frame = enc.encode("KF_RAW_SAMPLE", time_boot_us=dev_us, sample_counter=int(counters[k]), acc_z=1000, flags=8)
        if k % 200 == 0:  # once a second: a TIMESYNC answer (round trip 3 ms + jitter) and a unit status
            rtt = 3_000_000 + int(rng.exponential(300_000))
            frame += enc.encode("TIMESYNC", tc1=dev_us * 1000, ts1=last - rtt)
            frame += enc.encode("KF_UNIT_STATUS", time_boot_us=dev_us, firmware_version=(1 << 24) | (2 << 16),
                                raw_rate_requested=200.0, frames_dropped=3, dialect_hash=0)
        reads.append((last, frame))
    with RecordingWriter(path, head) as w:
        for a in range(0, len(reads), 50):
            w.rx(0, reads[a:a + 50])
    return path


def test_stats_recover_known_values(synthetic):
    r = stats.compute(decode_file(synthetic))
    (s,) = r["streams"]
    ticks = 39  # k % 200 == 0 for k < 8000, minus the lost k = 5000
    assert s["frames_ok"] == 8000 - 3 + 2 * ticks and s["crc_errors"] == 0
    (u,) = s["units"]
    assert u["sysid"] == 3 and u["firmware_version"] == "1.2.0-dev" and u["dialect_match"] is False
    m = u["messages"]["KF_RAW_SAMPLE"]
    assert m["count"] == 7997 and m["samples_lost"] == 3 and m["resets"] == 0 and m["stride"] == 1
    assert m["requested_hz"] == 200.0
    assert m["rate_hz"] == pytest.approx(7996 / 39.995, rel=1e-9)  # received frames per unit second
    clock = u["clock"]
    assert abs(clock["drift_ppm"] - 50) < 2.0
    assert clock["offset_s"] == pytest.approx(0.25 + 0.0015, abs=3e-4)
    lat = u["latency"]
    assert 3.0 <= lat["timesync_rtt_ms"]["min"] < 3.1 and lat["timesync_rtt_ms"]["count"] == ticks
    assert lat["one_way_estimate_ms"] == pytest.approx(1.5 + clock["delay_above_min_ms"]["median"], abs=0.05)
    assert u["unit_reported"]["frames_dropped"] == 3


def test_rate_after_a_requested_rate_change(tmp_path):
    """A unit asked for 100 Hz, then 400 Hz after 10 s: stats compared the 10 + 10 s average
    (250 Hz) with 400 Hz and flagged a 0.62 ratio; the rate now holds from the change on."""
    path = tmp_path / "c.kfr"
    head = make_header([{"id": 0, "connection": "synthetic"}])
    t0 = head["start_monotonic_ns"]
    enc = Encoder(sysid=4, compid=200)
    reads, dev_us, k = [], 0, 0
    last_status = -1
    while dev_us < 20_000_000:
        req = 100.0 if dev_us < 10_000_000 else 400.0
        frame = enc.encode("KF_RAW_SAMPLE", time_boot_us=dev_us, sample_counter=k, acc_z=1000, flags=8)
        if dev_us // 1_000_000 != last_status:          # one status a second, with the rate asked
            last_status = dev_us // 1_000_000
            frame += enc.encode("KF_UNIT_STATUS", time_boot_us=dev_us, raw_rate_requested=req, dialect_hash=0)
        reads.append((t0 + 1000 * dev_us + 2_000_000, frame))
        dev_us += int(1e6 / req)
        k += 1
    with RecordingWriter(path, head) as w:
        for a in range(0, len(reads), 50):
            w.rx(0, reads[a:a + 50])
    r = stats.compute(decode_file(path))
    m = r["streams"][0]["units"][0]["messages"]["KF_RAW_SAMPLE"]
    assert m["requested_hz"] == 400.0 and m["requested_changes"] == 1 and m["rate_from_device_s"] == 10.0
    assert m["rate_hz"] == pytest.approx(400.0, rel=1e-9) and m["rate_ratio"] == pytest.approx(1.0, rel=1e-9)
    assert m["count"] == 1000 + 4000


def _status_recording(path, statuses, texts=()):
    """A recording of unit 5: 1 Hz KF_UNIT_STATUS (``statuses``: field dicts) and STATUSTEXTs
    ``texts`` [(second, severity, text)], host time = 2 ms after device time."""
    head = make_header([{"id": 0, "connection": "synthetic"}])
    t0 = head["start_monotonic_ns"]
    enc = Encoder(sysid=5, compid=200)
    reads = []
    for k, fields in enumerate(statuses):
        dev_us = 1_000_000 * (k + 1)
        frame = enc.encode("KF_UNIT_STATUS", time_boot_us=dev_us, firmware_version=1 << 24, **fields)
        frame += b"".join(enc.encode("STATUSTEXT", severity=sev, text=text, id=0, chunk_seq=0)
                          for s, sev, text in texts if s == k)
        reads.append((t0 + 1000 * dev_us + 2_000_000, frame))
    with RecordingWriter(path, head) as w:
        w.rx(0, reads)
    return path


def test_status_extension_counters_and_older_firmware(tmp_path):
    """numeric_resets, hil_invalid, rejected_samples2 are reported; an older firmware (83-byte
    statuses, another dialect) has none: None ("n/a"), not a claimed 0."""
    from kinefuse.host.link.dialect import DIALECT_HASH
    new = _status_recording(tmp_path / "new.kfr", [
        {"dialect_hash": 0, "numeric_resets": 0},
        {"dialect_hash": 0, "numeric_resets": 2, "hil_invalid": 1, "rejected_samples2": 7}])
    rep = stats.compute(decode_file(new))["streams"][0]["units"][0]["unit_reported"]
    assert (rep["numeric_resets"], rep["hil_invalid"], rep["rejected_samples2"]) == (2, 1, 7)
    old = _status_recording(tmp_path / "old.kfr", [{"dialect_hash": 0, "samples": 9}] * 3)
    rep = stats.compute(decode_file(old))["streams"][0]["units"][0]["unit_reported"]
    assert rep["samples"] == 9
    assert rep["numeric_resets"] is None and rep["hil_invalid"] is None and rep["rejected_samples2"] is None
    # the same dialect: the unit knows the fields, zeros (trailing zeros truncated) are real zeros
    same = _status_recording(tmp_path / "same.kfr", [{"dialect_hash": DIALECT_HASH()}] * 2)
    rep = stats.compute(decode_file(same))["streams"][0]["units"][0]["unit_reported"]
    assert rep["numeric_resets"] == 0 and rep["rejected_samples2"] == 0


def test_stats_lists_the_units_statustexts(tmp_path, run):
    path = _status_recording(tmp_path / "t.kfr", [{"dialect_hash": 0}] * 5, texts=[
        (0, 3, "parameter storage error: settings may be lost"),
        (1, 4, "stored parameter out of range: default used"),
        (3, 3, "parameter storage error: settings may be lost")])
    (s,) = stats.compute(decode_file(path))["streams"]
    err, warn = s["statustexts"]
    assert err["severity_name"] == "ERROR" and err["count"] == 2 and err["sysid"] == 5
    assert err["text"] == "parameter storage error: settings may be lost"
    assert err["first_s"] == pytest.approx(1.002, abs=1e-6) and err["last_s"] == pytest.approx(4.002, abs=1e-6)
    assert warn["severity_name"] == "WARNING" and warn["count"] == 1
    code, out, _ = run("stats", str(path))
    assert code == 0
    assert "unit 5 said ERROR: parameter storage error: settings may be lost (2 times, 1.0 s .. 4.0 s)" in out, out
    assert "unit 5 said WARNING: stored parameter out of range: default used at 2.0 s" in out
    assert "numeric_resets n/a" in out
