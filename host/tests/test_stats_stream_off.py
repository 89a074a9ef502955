"""A requested rate of 0 in KF_UNIT_STATUS is the stream turned off, not a rate change.

``kinefuse record --start`` stops the stream at the end; the unit's last status often comes
after the stop and says raw_rate_requested = 0.  Stats counted that as a requested rate change
at the end of the recording and measured the rate "from the change on" (no samples: no rate),
and took the 0 for a missing value (``0 or None``), so the requested rate shown was the header's
--rate (400) instead of what the unit granted (500).  The recordings here are made with the
fake unit driven step by step on a made-up clock (no threads, no timing luck)."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.host.link import stats
from kinefuse.host.link.codec import Encoder
from kinefuse.host.link.decoder import StreamDecoder
from kinefuse.host.link.fakeunit import FakeUnit
from kinefuse.host.link.frames import decode_file
from kinefuse.host.link.recording import RecordingWriter, make_header

MINE = ("stats_cmd",)
STEP_US = 5_000
DELAY_NS = 2_000_000


def _command(command, *params):
    p = [float(x) for x in params] + [0.0] * (7 - len(params))
    (f,) = StreamDecoder().feed(Encoder(255, 190).encode(
        "COMMAND_LONG", target_system=1, target_component=200, command=command, confirmation=0,
        param1=p[0], param2=p[1], param3=p[2], param4=p[3], param5=p[4], param6=p[5], param7=p[6]))
    return f


def start():
    return _command(52500, 1)


def stop():
    return _command(52500, 0)


def rate(hz):
    return _command(511, 52500, 1e6 / hz)


def _record(path, unit: FakeUnit, end_us: int, commands: dict, header_rate=None):
    """A .kfr of ``unit`` run on a made-up clock from 0 to ``end_us`` in STEP_US steps,
    ``commands`` {device us: [frames]} handled at those times (the acks recorded too); host
    time = device time + 2 ms."""
    info = {"id": 0, "connection": "fake:test"}
    if header_rate is not None:
        info["requested_rates_hz"] = {"KF_RAW_SAMPLE": header_rate}     # as the recorder's --rate
    head = make_header([info])
    t0 = head["start_monotonic_ns"]
    clock = [0]
    unit.device_time_us = lambda: clock[0]
    reads = []
    for now in range(0, end_us + 1, STEP_US):
        clock[0] = now
        out = []
        for f in commands.get(now, ()):
            out += unit._handle(f)
        out += unit._emit_due()
        if out:
            reads.append((t0 + 1000 * now + DELAY_NS, b"".join(out)))
    with RecordingWriter(path, head) as w:
        for a in range(0, len(reads), 50):
            w.rx(0, reads[a:a + 50])
    return path


def _statuses(path):
    st = decode_file(path).streams[0].arrays[52504]
    return [(int(t), float(r)) for t, r in zip(st["time_boot_us"], st["raw_rate_requested"])]


def _messages(path):
    return stats.compute(decode_file(path))["streams"][0]["units"][0]["messages"]


@pytest.fixture
def stopped_at_end(tmp_path):
    """``record --port fake:rate=200,grant=500,stream=0 --rate 400 --start``: the unit grants
    500 Hz, streams from 0.1 s to 2.6 s; its status at 3.0 s, after the stop, says 0."""
    u = FakeUnit(None, rate_hz=200, sensor_grant_hz=500, streaming=False)
    path = _record(tmp_path / "stop.kfr", u, 3_200_000, {100_000: [rate(400), start()], 2_600_000: [stop()]},
                   header_rate=400)
    assert _statuses(path) == [(0, 0.0), (1_000_000, 500.0), (2_000_000, 500.0), (3_000_000, 0.0)]
    return path


def test_a_stop_after_the_last_samples_is_no_rate_change(stopped_at_end):
    m = _messages(stopped_at_end)["KF_RAW_SAMPLE"]
    # the unit's 500 Hz, not the header's --rate 400 (0 from the last status taken for missing)
    assert m["requested_hz"] == 500.0
    # the rate of the samples, not none (measured from the "change" to 0 on: no samples there)
    assert m["rate_hz"] == pytest.approx(500.0, rel=1e-9) and m["rate_ratio"] == pytest.approx(1.0, rel=1e-9)
    assert m["count"] == 1251                       # 0.1 s .. 2.6 s at 500 Hz
    assert not m.get("requested_changes") and "rate_from_device_s" not in m
    assert m["stopped_at_end"] is True and m["rate_until_device_s"] == 3.0
    ori = _messages(stopped_at_end)["KF_ORIENTATION"]
    assert ori["requested_hz"] == 100.0 and ori["rate_hz"] == pytest.approx(100.0, rel=1e-9)
    assert not ori.get("requested_changes") and ori["stopped_at_end"] is True


def test_stats_says_the_stream_was_off_at_the_end(stopped_at_end, run):
    code, out, err = run("stats", stopped_at_end)
    assert code == 0, err
    row = next(line for line in out.splitlines() if line.lstrip().startswith("KF_RAW_SAMPLE"))
    assert row.split()[1:5] == ["1,251", "500.0", "500.0", "1.000"], out
    assert "requested rate changed" not in out
    assert "KF_RAW_SAMPLE: streaming off at the end (stopped before unit time 3.0 s)" in out, out


def test_stop_and_start_at_another_rate_within_one_recording(tmp_path, run):
    """Streaming at 200 Hz from 0.1 s, off from 3.5 s, on at 400 Hz from 5.5 s, off again from
    8.5 s: the rate is that of the 400 Hz run (not measured from the final stop on, nor over
    the off gap), one requested rate change (200 -> 400), one restart."""
    u = FakeUnit(None, rate_hz=200, streaming=False)
    path = _record(tmp_path / "cycle.kfr", u, 9_200_000, {
        100_000: [start()], 3_500_000: [stop()], 5_500_000: [rate(400), start()], 8_500_000: [stop()]})
    req = [r for _, r in _statuses(path)]
    assert req == [0, 200, 200, 200, 0, 0, 400, 400, 400, 0]
    m = _messages(path)["KF_RAW_SAMPLE"]
    assert m["requested_hz"] == 400.0
    assert m["rate_hz"] == pytest.approx(400.0, rel=1e-9)
    assert m["requested_changes"] == 1 and m["restarts"] == 1
    assert m["rate_from_device_s"] == 5.0 and m["rate_until_device_s"] == 9.0 and m["stopped_at_end"] is True
    assert m["count"] == (3_500_000 - 100_000) // 5000 + 1 + (8_500_000 - 5_500_000) // 2500 + 1
    code, out, err = run("stats", path)
    assert code == 0, err
    assert ("KF_RAW_SAMPLE: the requested rate changed 1 time(s), streaming turned off and on again 1 "
            "time(s); its rate is that from unit time 5.0 s on, until it stopped before 9.0 s") in out, out


def test_stop_and_start_again_at_the_same_rate(tmp_path):
    """200 Hz, off, 200 Hz again, still on at the end: no rate change, one restart, the rate
    measured over the last run (not over the off gap: 200 * 6.4 / 8.9 Hz)."""
    u = FakeUnit(None, rate_hz=200, streaming=False)
    path = _record(tmp_path / "again.kfr", u, 9_000_000, {
        100_000: [start()], 3_500_000: [stop()], 5_500_000: [start()]})
    m = _messages(path)["KF_RAW_SAMPLE"]
    assert m["requested_hz"] == 200.0 and m["rate_hz"] == pytest.approx(200.0, rel=1e-9)
    assert not m.get("requested_changes") and m["restarts"] == 1 and m["rate_from_device_s"] == 5.0
    assert "stopped_at_end" not in m and "rate_until_device_s" not in m


def test_statuses_that_all_say_off_fall_back_to_the_header(tmp_path):
    """Statuses only before the start and after the stop (a short recording): the unit never
    said what it was asked for; the header's --rate is the requested rate, all samples count."""
    u = FakeUnit(None, rate_hz=250, streaming=False)
    path = _record(tmp_path / "short.kfr", u, 1_100_000, {100_000: [rate(250), start()], 900_000: [stop()]},
                   header_rate=250)
    assert [r for _, r in _statuses(path)] == [0, 0]
    m = _messages(path)["KF_RAW_SAMPLE"]
    assert m["requested_hz"] == 250.0 and m["rate_hz"] == pytest.approx(250.0, rel=1e-9)
    assert m["count"] == 201 and m["stopped_at_end"] is True


def test_an_orientation_stream_turned_off_by_its_interval_keeps_its_rate(tmp_path):
    """KF_ORIENTATION off (SET_MESSAGE_INTERVAL -1: KF_ORI_RATE_HZ 0) with the raw stream running
    on: orientation_rate_requested 0 is its stop, not a change to a rate of 0."""
    u = FakeUnit(None, rate_hz=500, orientation_rate_hz=50)
    path = _record(tmp_path / "ori.kfr", u, 4_100_000, {2_500_000: [_command(511, 52501, -1)]})
    st = decode_file(path).streams[0].arrays[52504]
    assert list(np.asarray(st["orientation_rate_requested"])) == [50, 50, 50, 0, 0]
    m = _messages(path)
    ori, raw = m["KF_ORIENTATION"], m["KF_RAW_SAMPLE"]
    assert ori["requested_hz"] == 50.0 and ori["rate_hz"] == pytest.approx(50.0, rel=1e-9)
    assert ori["stopped_at_end"] is True and ori["rate_until_device_s"] == 3.0
    assert raw["requested_hz"] == 500.0 and raw["rate_hz"] == pytest.approx(500.0, rel=1e-9)
    assert "stopped_at_end" not in raw


def test_on_again_after_the_last_status(tmp_path, run):
    """Off at the last status (3.0 s), on again at 3.3 s: the samples after it are at a rate no
    status told (not counted in the rate, said so); the stream is not off at the end."""
    u = FakeUnit(None, rate_hz=200, streaming=False)
    path = _record(tmp_path / "late.kfr", u, 3_800_000, {100_000: [start()], 2_500_000: [stop()],
                                                         3_300_000: [rate(400), start()]})
    assert [r for _, r in _statuses(path)] == [0, 200, 200, 0]
    m = _messages(path)["KF_RAW_SAMPLE"]
    assert m["requested_hz"] == 200.0 and m["rate_hz"] == pytest.approx(200.0, rel=1e-9)
    assert m["rate_until_device_s"] == 3.0 and "stopped_at_end" not in m
    assert m["count"] == 481 + 203                   # 3.295 .. 3.8 s at 400 Hz counted, not in the rate
    code, out, err = run("stats", path, "--json")
    assert code == 0, err
    code, out, err = run("stats", path)
    assert ("KF_RAW_SAMPLE: its rate is that until it stopped before unit time 3.0 s (on again after the "
            "unit's last status: those samples not counted)") in out, out
