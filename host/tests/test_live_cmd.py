"""``kinefuse live`` with stdout not a terminal: plain periodic lines, clean ends, one-line errors."""
from __future__ import annotations

import re
import time

import numpy as np
import pytest


MINE = ("live_cmd",)
LINE = re.compile(r"\[\s*([\d.]+) s\] unit (\d+) \((.+?)\): rate ([\d.]+) Hz \(requested (\S+?)(?: Hz)?\), lost (\d+), "
                  r"CRC errors (\d+), (.+?), battery (.+?), (.+)$")


def _units(out):
    return [LINE.match(l).groups() for l in out.splitlines() if LINE.match(l)]


def test_fake_unit_lines(run):
    t0, c0 = time.monotonic(), time.process_time()
    code, out, err = run("live", "--port", "fake:rate=200", "--seconds", "2")
    wall, cpu = time.monotonic() - t0, time.process_time() - c0
    assert code == 0, err
    assert 1.9 < wall < 4.0
    assert cpu < 0.8 * wall, (cpu, wall)        # blocking waits, no busy loop
    rows = _units(out)
    assert len(rows) >= 2, out                  # periodic lines (1 s) and the final one
    el, unit, conn, rate, req, lost, crc, ori, battery, status = rows[-1]
    assert unit == "1" and conn == "fake:rate=200"
    assert abs(float(rate) - 200) < 10 and req == "200"
    assert lost == "0" and crc == "0"
    assert re.match(r"roll\s+[+-][\d.]+ pitch\s+[+-][\d.]+ yaw\s+[+-][\d.]+ deg \(ENU\)", ori), ori
    assert battery == "3.90 V 80 %" and "streaming" in status
    assert out.strip().splitlines()[-1] == "live view done"


def test_losses_and_unit_choice(run):
    code, out, err = run("live", "--port", "fake:rate=200,drop=20,unit=3", "--port", "fake:unit=4,rate=100,ori=0",
                         "--unit", "3", "--seconds", "1.2", "--interval", "0.5")
    assert code == 0, err
    rows = _units(out)
    assert rows and {r[1] for r in rows} == {"3"}
    last = rows[-1]
    assert int(last[5]) >= 8                   # every 20th of ~240 samples lost
    assert abs(float(last[3]) - 190) < 10      # 19 of 20 frames arrive
    assert "fake:unit=4,rate=100,ori=0: no unit 3 data yet" in out


def test_loss_on_a_link_losing_most_frames():
    """The stride was the most common of the first 16 steps: 2 here, so only half the lost
    samples were counted (fake:corrupt=0.004 showed lost 137 of about 1,100)."""
    from types import SimpleNamespace
    from kinefuse.host.commands.live_cmd import UnitView
    steps = [2, 2, 3, 2, 4, 2, 3, 2, 5, 2, 3, 2, 2, 4, 3, 2] + [1, 3, 2, 6, 2, 1, 4] * 20
    counters = (2**32 - 40 + np.concatenate([[0], np.cumsum(steps)])) & 0xFFFFFFFF   # wraps too
    u = UnitView(0, 1, "fake:")
    for k, c in enumerate(counters):
        u.raw(SimpleNamespace(time_boot_us=1000 * k, sample_counter=int(c)))
        if k % 10 == 9:
            u.settle_counters()
    u.settle_counters(final=True)
    assert u.stride == 1 and u.lost == sum(steps) - len(steps) and u.resets == 0


def test_the_table_keeps_its_numbers_on_an_80_column_terminal():
    """On 80 columns roll and yaw read '-1…' / '+1…' and the battery and status columns were
    cut off."""
    from types import SimpleNamespace
    from rich.console import Console
    from kinefuse.host.commands.live_cmd import LiveMonitor, UnitView
    s = SimpleNamespace(conn=SimpleNamespace(url="fake:rate=200,unit=3"),
                        decoder=SimpleNamespace(counters=SimpleNamespace(crc_errors=7, bytes_in=0)))
    mon = LiveMonitor([s])
    u = mon.units[(0, 3)] = UnitView(0, 3, s.conn.url)
    u.window.extend([0, 5000, 10000])
    u.requested_hz, u.rpy_deg, u.earth_frame, u.lost = 1000.0, (-179.9, -88.8, 123.4), "ENU", 12345
    u.status = SimpleNamespace(battery_voltage=3900, battery_remaining=80, status_flags=35, firmware_version=65536,
                               samples_dropped=0)
    con = Console(width=80, record=True, color_system=None)
    con.print(mon.table())
    text = con.export_text()
    for want in ("200.0", "1000", "12345", " 7 ", "-179.9", "-88.8", "+123.4", "ENU", "3.90 V", "stream"):
        assert want in text, (want, text)


def test_frames_read_while_start_waits_are_counted(run, tmp_path):
    """A connection that ended while --start waited for ACKs (a capture file) said 'no kinefuse
    unit data received' for its 2,000 frames: the loop ended without feeding what was queued."""
    from kinefuse.host.link.fakeunit import raw_frames
    cap = tmp_path / "cap.bin"
    cap.write_bytes(raw_frames(2000))
    code, out, err = run("live", "--port", f"file:{cap}", "--start", "--seconds", "5")
    assert code == 0, err
    assert _units(out) and _units(out)[-1][1] == "1" and _units(out)[-1][5] == "0", out


def test_ctrl_c_ends_cleanly(run, monkeypatch):
    from kinefuse.host.commands import live_cmd
    calls = {"n": 0}
    feed = live_cmd.LiveMonitor.feed

    def interrupting_feed(self, sid, frames):
        calls["n"] += 1
        if calls["n"] == 20:
            raise KeyboardInterrupt
        return feed(self, sid, frames)
    monkeypatch.setattr(live_cmd.LiveMonitor, "feed", interrupting_feed)
    closed = []
    from kinefuse.host.link.session import Session
    orig_close = Session.close
    monkeypatch.setattr(Session, "close", lambda self: (closed.append(self.conn.url), orig_close(self))[1])
    code, out, err = run("live", "--port", "fake:rate=200", "--seconds", "30")
    assert code == 0, err
    assert "live view interrupted" in out and "Traceback" not in err
    assert closed == ["fake:rate=200"]


@pytest.mark.parametrize("argv, text", [
    (["live", "--port", "fake:", "--seconds", "0"], "--seconds must be positive"),
    (["live", "--port", "tcp:127.0.0.1:1", "--seconds", "1"], "cannot connect"),
    (["live", "--port", "fake:bogus=1"], "bad fake unit option"),
    (["live", "--port", "file:{tmp}/empty.bin", "--seconds", "1"], "no kinefuse unit data received"),
    (["live", "--port", "fake:rate=100", "--unit", "9", "--seconds", "0.5"], "no unit 9 data received"),
    # two readers of one port split its bytes (both streams lose frames)
    (["live", "--port", "/dev/kinefuse-nope", "--port", "/dev/kinefuse-nope", "--seconds", "1"],
     "give each port once"),
])
def test_bad_input_gives_one_line(run, tmp_path, argv, text):
    (tmp_path / "empty.bin").write_bytes(b"")
    code, out, err = run(*[a.format(tmp=tmp_path) for a in argv])
    assert code == 2, (code, out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("kinefuse: error:") and text in lines[0], err


def test_plain_line_states_requested_rate_off_without_unit():
    """A unit streaming with its raw rate off printed '(requested off Hz)'."""
    from types import SimpleNamespace
    from kinefuse.host.commands.live_cmd import LiveMonitor, UnitView
    s = SimpleNamespace(conn=SimpleNamespace(url="fake:"),
                        decoder=SimpleNamespace(counters=SimpleNamespace(crc_errors=0, bytes_in=0)))
    mon = LiveMonitor([s])
    u = mon.units[(0, 1)] = UnitView(0, 1, s.conn.url)
    u.requested_hz = 0.0
    assert "(requested off)" in mon.lines()[0], mon.lines()
    u.requested_hz = 250.0
    assert "(requested 250 Hz)" in mon.lines()[0], mon.lines()


def test_a_late_replay_is_not_loss_or_a_reset():
    """Frames 50-52 delivered again after 60 (a flaky link): live counted a counter reset and,
    from 52 back to 61, 8 samples lost (stats already took them for repeats)."""
    from types import SimpleNamespace
    from kinefuse.host.commands.live_cmd import UnitView
    order = list(range(100))
    order[61:61] = [50, 51, 52]
    u = UnitView(0, 1, "fake:")
    for k, c in enumerate(order):
        u.raw(SimpleNamespace(time_boot_us=5000 * c, sample_counter=c))
        if k % 10 == 9:
            u.settle_counters()
    u.settle_counters(final=True)
    assert u.lost == 0 and u.resets == 0 and u.repeats == 3
    assert u.rate_hz == pytest.approx(200.0)
    # a reboot (device time back to a time not sent) still restarts the rate window
    u.raw(SimpleNamespace(time_boot_us=400_000, sample_counter=0))
    u.settle_counters(final=True)
    assert u.resets == 1 and len(u.window) == 1


def test_a_refused_start_stops_the_units_already_started(run, monkeypatch):
    """``live --start`` with two connections: the first unit started streaming, the second
    refused; the error left the first one streaming (its sessions were only closed)."""
    from kinefuse.host.commands import live_cmd
    from kinefuse.host.link import command as C
    started, stopped = [], []

    def start(sessions, rate_hz):
        started.append(sessions[0].conn.url)      # the first one answered, the second refused
        raise C.CommandError(f"{sessions[1].conn.url}: unit 2 refused MAV_CMD_KF_STREAM", 4)

    monkeypatch.setattr(live_cmd, "start_streaming", start)
    monkeypatch.setattr(live_cmd, "stop_streaming", lambda sessions: stopped.extend(s.conn.url for s in sessions))
    code, out, err = run("live", "--port", "fake:rate=200", "--port", "fake:unit=2,rate=200", "--start",
                         "--seconds", "1")
    assert code == 2 and "refused" in err and "Traceback" not in err
    assert started == ["fake:rate=200"] and "fake:rate=200" in stopped
