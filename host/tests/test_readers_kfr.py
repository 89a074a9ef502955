"""The ``kfr`` reader: units' recordings (.kfr) as Recordings for the reports.

Two kinds of files: synthetic recordings written with the recorder's own writer (known truth:
sensor values, device clocks with offset and drift, link latency, lost/repeated frames, the
simulated knee step-up), and a real in-process recording of two fake units.
"""
from __future__ import annotations

import json
import os

import numpy as np
import pytest

from kinefuse.host import cli
from kinefuse.host.kinematics import simulate
from kinefuse.host.link.batchenc import encode_batch
from kinefuse.host.link.dialect import RAW_SCALE, UNIT_COMPONENT_ID
from kinefuse.host.link.recording import FILE_HEAD, RecordingWriter, make_header
from kinefuse.host.readers import ReaderError, detect_format, kfr, kinefuse_csv, read_recording

T0_NS = 10**12          # host monotonic clock at the start of the synthetic recordings
MIN_LATENCY = 0.0008    # s, every frame reaches the host at least this long after its sample
FRAME = 46


# ----------------------------------------------------------------------------- synthetic files
def _counts(x, scale):
    return np.clip(np.round(np.asarray(x) / scale), -32768, 32767).astype(np.int64)


def _frames(t, acc, gyr, mag, *, sysid, boot_s, drift_ppm, counter0=0, flags=8 | 16 | 32, temp=2512):
    """KF_RAW_SAMPLE frames of samples taken at host times ``t`` (s since the recording started)
    by a unit whose clock read 0 at host time -boot_s and runs drift_ppm fast."""
    n = len(t)
    dev_us = np.round((np.asarray(t) + boot_s) * (1 + drift_ppm * 1e-6) * 1e6).astype(np.uint64)
    v = {"time_boot_us": dev_us, "sample_counter": ((counter0 + np.arange(n)) & 0xFFFFFFFF).astype(np.uint32),
         "temperature": np.full(n, temp), "unit_id": np.full(n, sysid, np.uint8),
         "flags": np.broadcast_to(np.asarray(flags, np.uint8), (n,)).copy()}
    for k, ax in enumerate("xyz"):
        v[f"acc_{ax}"] = _counts(acc[:, k], RAW_SCALE["acc"])
        v[f"gyro_{ax}"] = _counts(gyr[:, k], RAW_SCALE["gyro"])
        v[f"mag_{ax}"] = _counts(mag[:, k], RAW_SCALE["mag"])
    data = encode_batch("KF_RAW_SAMPLE", v, sysid=sysid, compid=UNIT_COMPONENT_ID, n=n)
    assert len(data) == FRAME * n
    return [data[k * FRAME:(k + 1) * FRAME] for k in range(n)], dev_us


def _write_kfr(path, streams, seed=0):
    """streams: [[(t_host_sample, frame bytes), ...] per unit, ...] (one stream per list); each frame
    is read by the host MIN_LATENCY + exponential jitter after its sample, 20 reads a chunk."""
    rng = np.random.default_rng(seed)
    head = make_header([{"id": k, "connection": f"synthetic{k}"} for k in range(len(streams))])
    head["start_monotonic_ns"] = T0_NS
    with RecordingWriter(path, head) as w:
        for sid, items in enumerate(streams):
            reads = []
            last = -np.inf
            for ts, fr in items:
                tr = max(last, ts + MIN_LATENCY + rng.exponential(0.002))
                last = tr
                reads.append((T0_NS + int(tr * 1e9), fr))
            for a in range(0, len(reads), 20):
                w.rx(sid, reads[a:a + 20])


def _motion(n, fs=200.0, seed=0):
    rng = np.random.default_rng(seed)
    t = np.arange(n) / fs
    acc = np.column_stack([np.sin(t), np.cos(2 * t), 9.8 + 0.1 * np.sin(3 * t)]) + 0.01 * rng.standard_normal((n, 3))
    gyr = np.column_stack([0.5 * np.sin(2 * t), 2.0 * np.cos(t), -1.0 + 0 * t]) + 0.01 * rng.standard_normal((n, 3))
    mag = np.column_stack([20 + 5 * np.sin(t), -30 + 0 * t, 40 * np.cos(t)]) + 0.3 * rng.standard_normal((n, 3))
    return t, acc, gyr, mag


@pytest.fixture(scope="module")
def two_units(tmp_path_factory):
    """Unit 1 (booted 0.5 s before the recording, +150 ppm) and unit 2 (booted 7.3 s before, -80 ppm)
    sample the same instants at 200 Hz for 10 s; unit 2 loses frames 100-104 and 300, repeats
    frame 200 and replays 50-52 after 60 (what a flaky link does)."""
    p = tmp_path_factory.mktemp("kfr") / "both.kfr"
    t, acc, gyr, mag = _motion(2000)
    f1, dev1 = _frames(t, acc, gyr, mag, sysid=1, boot_s=0.5, drift_ppm=150)
    f2, dev2 = _frames(t, -acc, gyr[:, ::-1], mag * 0.5, sysid=2, boot_s=7.3, drift_ppm=-80,
                       counter0=0xFFFFFFFF - 999)  # the counter wraps mid-recording
    order = [k for k in range(2000) if not (100 <= k <= 104 or k == 300)]
    order.insert(order.index(200) + 1, 200)
    i60 = order.index(60) + 1
    order[i60:i60] = [50, 51, 52]
    s1 = [(t[k], f1[k]) for k in range(2000)]
    s2 = [(t[k], f2[k]) for k in order]
    _write_kfr(p, [s1, s2])
    return p, t, (acc, gyr, mag), (dev1, dev2)


def test_si_values_and_channels(two_units):
    p, t, (acc, gyr, mag), _ = two_units
    r = read_recording(str(p), unit=1)
    assert r.fmt == "kfr" and len(r) == 2000 and abs(r.fs - 200) < 0.1
    for got, true, key in ((r.acc, acc, "acc"), (r.gyr, gyr, "gyro"), (r.mag, mag, "mag")):
        assert np.array_equal(got, _counts(true, RAW_SCALE[key]) * RAW_SCALE[key])  # exact SI of the ints
        assert np.abs(got - true).max() <= 0.5 * RAW_SCALE[key] + 1e-12          # half an LSB from truth
    assert RAW_SCALE["acc"] == pytest.approx(9.80665e-3) and RAW_SCALE["mag"] == 0.1  # mG, mgauss -> uT
    assert np.array_equal(r.mag_native, r.mag) and np.array_equal(r.mag_t, r.t)     # updated every sample
    assert np.allclose(r.channels["temperature_degC"], 25.12)
    assert r.channels["sample_counter"].tolist() == list(range(2000))
    assert r.metadata["unit"] == "1" and r.metadata["time_base"] == "host" and r.metadata["calibrated_on_unit"]
    assert r.warnings == []


def test_host_time_base_synchronises_the_units(two_units):
    p, t, _, (dev1, dev2) = two_units
    r1, r2 = read_recording(str(p), unit=1), read_recording(str(p), unit="2")
    # device clocks 6.8 s apart, drifting 230 ppm apart ...
    assert r2.channels["device_time_s"][0] - r1.channels["device_time_s"][0] == pytest.approx(6.8, abs=1e-3)
    # ... host times: the sample instants plus the minimum link latency, to within 0.1 ms
    assert np.abs(r1.t - (t + MIN_LATENCY)).max() < 1e-4
    kept = np.searchsorted(t, r2.t - MIN_LATENCY - 5e-4)
    assert np.abs(r2.t - (t[kept] + MIN_LATENCY)).max() < 1e-4
    assert abs(r1.t[0] - r2.t[0]) < 1e-4
    assert r1.metadata["clock"]["drift_ppm"] == pytest.approx(150, abs=5)
    assert r2.metadata["clock"]["drift_ppm"] == pytest.approx(-80, abs=5)
    assert r1.metadata["clock_id"] == r2.metadata["clock_id"]


def test_lost_samples_stay_gaps_repeats_dropped(two_units):
    p, t, (acc, _, _), _ = two_units
    r = read_recording(str(p), unit=2)
    assert len(r) == 2000 - 6
    c = r.channels["sample_counter"]
    assert np.all(np.diff(c) >= 1) and c[0] == 0xFFFFFFFF - 999 and c[-1] == 0xFFFFFFFF - 999 + 1999  # unwrapped
    k = np.array(sorted(set(range(2000)) - set(range(100, 105)) - {300}))
    assert np.array_equal(c - c[0], k)
    d = np.diff(r.t)
    assert np.sum(d > 1.5 / 200) == 2 and d.max() == pytest.approx(6 / 200, abs=1e-4)  # gaps, not filled
    assert np.array_equal(r.acc, _counts(-acc[k], RAW_SCALE["acc"]) * RAW_SCALE["acc"])
    assert r.metadata["samples_lost"] == 6 and r.metadata["duplicates_dropped"] == 4
    assert any("6 sample(s) lost in 2 gap(s)" in w for w in r.warnings)
    assert any("4 repeated" in w for w in r.warnings)


def test_reboot_and_slower_magnetometer(tmp_path):
    """The unit reboots after 2 s (clock and counter restart): each clock segment gets its own fit,
    host time runs on; the magnetometer updates every 4th sample and is held in between."""
    t, acc, gyr, mag = _motion(1000)
    upd = np.arange(1000) % 4 == 0
    flags = np.where(upd, 8 | 16, 16)
    fa, _ = _frames(t[:400], acc[:400], gyr[:400], mag[:400], sysid=3, boot_s=40.0, drift_ppm=100,
                    flags=flags[:400], counter0=5000)
    fb, _ = _frames(t[400:], acc[400:], gyr[400:], mag[400:], sysid=3, boot_s=-t[400] + 0.25, drift_ppm=100,
                    flags=flags[400:])
    p = tmp_path / "reboot.kfr"
    _write_kfr(p, [list(zip(t, fa + fb))])
    r = read_recording(str(p))
    assert len(r) == 1000 and r.metadata["device_clock_segments"] == 2
    assert np.abs(r.t - (t + MIN_LATENCY)).max() < 3e-4
    assert r.channels["device_time_s"][400] == pytest.approx(0.25 * 1.0001, abs=1e-6)  # rebooted
    assert np.array_equal(r.mag_t, r.t[upd])
    k = np.flatnonzero(upd)[np.searchsorted(np.flatnonzero(upd), np.arange(1000), side="right") - 1]
    assert np.array_equal(r.mag, _counts(mag[k], 0.1) * 0.1)  # held from the last update


def test_clock_jump_gets_its_own_fit(tmp_path):
    """The unit's clock is set one hour forward after 2 s while its sample counter runs on: one
    fit across the step mapped the samples to host times 17 s apart, 25 us steps, no warning.
    Each side now gets its own fit (host time runs on), with a warning; stats and export too."""
    from kinefuse.host.link import stats
    from kinefuse.host.link.frames import decode_file
    t, acc, gyr, mag = _motion(1000)
    fa, _ = _frames(t[:400], acc[:400], gyr[:400], mag[:400], sysid=3, boot_s=40.0, drift_ppm=100)
    fb, _ = _frames(t[400:], acc[400:], gyr[400:], mag[400:], sysid=3, boot_s=3640.0, drift_ppm=100,
                    counter0=400)
    p = tmp_path / "jump.kfr"
    _write_kfr(p, [list(zip(t, fa + fb))])
    r = read_recording(str(p))
    assert len(r) == 1000 and r.metadata["device_clock_segments"] == 2
    assert np.abs(r.t - (t + MIN_LATENCY)).max() < 3e-4
    assert any("clock jumped forward 1 time(s)" in w and "first by 3,600." in w for w in r.warnings), r.warnings
    (u,) = stats.compute(decode_file(p))["streams"][0]["units"]
    assert abs(u["clock"]["drift_ppm"] - 100) < 50 and u["messages"]["KF_RAW_SAMPLE"]["rate_hz"] == pytest.approx(
        200, rel=1e-3)
    assert any("clock jumped forward" in w for w in u["warnings"])
    segs = stats.unit_clock_segments(decode_file(p).streams[0], 3, T0_NS)
    assert len(segs) == 2 and all(abs(sg["drift_ppm"] - 100) < 50 for sg in segs)   # 2 s, 3 s: jitter


def _one_line(exc, *texts):
    msg = str(exc.value)
    assert "\n" not in msg, msg
    for s in texts:
        assert s in msg, msg


def test_unit_selection(two_units, tmp_path):
    p = str(two_units[0])
    with pytest.raises(ReaderError) as e:
        read_recording(p)
    _one_line(e, p, "2 units in this recording: 1, 2", "unit=")
    with pytest.raises(ReaderError) as e:
        read_recording(p, unit=9)
    _one_line(e, "unit 9 is not in this recording", "1 (2000 frames, stream 0", "2 (1998 frames, stream 1")
    with pytest.raises(ReaderError) as e:
        read_recording(p, unit="thigh")
    _one_line(e, "bad unit 'thigh'")
    assert read_recording(p, unit="s1").metadata["sysid"] == 2
    assert read_recording(p, unit="s0:1").metadata["sysid"] == 1
    # two ports whose units both have the (default) id 1
    t, acc, gyr, mag = _motion(50)
    fa, _ = _frames(t, acc, gyr, mag, sysid=1, boot_s=1, drift_ppm=0)
    fb, _ = _frames(t, acc * 0.5, gyr, mag, sysid=1, boot_s=2, drift_ppm=0)
    q = tmp_path / "same-id.kfr"
    _write_kfr(q, [list(zip(t, fa)), list(zip(t, fb))])
    assert [u["label"] for u in kfr.list_units(str(q))] == ["s0:1", "s1:1"]
    with pytest.raises(ReaderError) as e:
        read_recording(str(q), unit=1)
    _one_line(e, "unit 1 is ambiguous (s0:1, s1:1)")
    r = read_recording(str(q), unit="s1:1")
    assert np.allclose(r.acc[:, 2], _counts(acc[:, 2] * 0.5, RAW_SCALE["acc"]) * RAW_SCALE["acc"])
    # a single-unit file needs no unit=
    one = tmp_path / "one.kfr"
    _write_kfr(one, [list(zip(t, fa))])
    assert len(read_recording(str(one))) == 50


def test_truncated_file_reads_up_to_the_cut(two_units, tmp_path):
    p = two_units[0]
    data = p.read_bytes()
    full = read_recording(str(p), unit=1)
    cut = tmp_path / "cut.kfr"
    cut.write_bytes(data[: len(data) * 2 // 5 + 13])  # inside some chunk
    r = read_recording(str(cut), unit=1)
    assert 100 < len(r) < len(full)
    assert np.array_equal(r.acc, full.acc[: len(r)])
    assert np.array_equal(r.channels["sample_counter"], full.channels["sample_counter"][: len(r)])
    assert np.abs(r.t - full.t[: len(r)]).max() < 2e-4  # the clock fit of the part read
    assert any("truncated" in w for w in r.warnings)
    head = tmp_path / "head.kfr"
    head.write_bytes(data[: FILE_HEAD.size + 5])
    with pytest.raises(ReaderError) as e:
        read_recording(str(head))
    _one_line(e, "head.kfr", "header is truncated")


def test_detection_junk_and_raw_capture(two_units, tmp_path):
    p = two_units[0]
    assert detect_format(str(p)) == "kfr"
    other = tmp_path / "renamed.bin"
    other.write_bytes(p.read_bytes())
    assert detect_format(str(other)) == "kfr"  # by the header magic
    junk = tmp_path / "junk.kfr"
    junk.write_bytes(b"\x00garbage" * 100)
    with pytest.raises(ReaderError) as e:
        read_recording(str(junk))
    _one_line(e, "junk.kfr", "not a kinefuse recording")
    # a raw MAVLink capture (no host times): the unit's own clock
    t, acc, gyr, mag = _motion(300)
    fr, dev = _frames(t, acc, gyr, mag, sysid=4, boot_s=3.0, drift_ppm=0, flags=16)
    raw = tmp_path / "capture.bin"
    raw.write_bytes(b"\x55" * 7 + b"".join(fr))
    r = read_recording(str(raw), "kfr")
    assert r.metadata["time_base"] == "device" and "clock_id" not in r.metadata
    assert np.array_equal(r.t, dev / 1e6)
    assert r.mag is None and r.mag_t is None  # no KF_RAW_SAMPLE_FLAGS_MAG_UPDATED: no magnetometer
    assert np.isnan(r.channels["temperature_degC"]).all()  # not flagged valid


# ----------------------------------------------------------------------------- real fake units
@pytest.fixture(scope="module")
def fake_recording(tmp_path_factory):
    """1.2 s of two fake units (unit 1 drops every 25th sample, unit 2's clock runs 300 ppm fast)
    recorded by the real recorder into one .kfr."""
    from kinefuse.host.link.recorder import Recorder
    p = tmp_path_factory.mktemp("fake") / "both.kfr"
    rec = Recorder(p, ["fake:rate=500,drop=25", "fake:unit=2,rate=500,drift=300"])
    units = [st.session.conn.unit for st in rec.streams]
    start_ns = rec.header["start_monotonic_ns"]
    rec.run(1.2)
    return p, units, start_ns


def test_fake_units_against_export_and_their_clocks(fake_recording, tmp_path):
    from kinefuse.host.link.export import export_csv
    from kinefuse.host.link.frames import decode_file
    p, units, start_ns = fake_recording
    files = {os.path.basename(f["file"]): f for f in export_csv(decode_file(p), tmp_path, ["KF_RAW_SAMPLE"])}
    recs = []
    for sysid, stream, fu in ((1, 0, units[0]), (2, 1, units[1])):
        r = read_recording(str(p), unit=sysid)
        recs.append(r)
        # the export CSV of the same unit: same samples, same SI values
        csv = kinefuse_csv.read(str(tmp_path / f"KF_RAW_SAMPLE_s{stream}_u{sysid}.csv"))
        assert len(csv) == len(r) > 400
        assert np.array_equal(csv.channels["sample_counter"], r.channels["sample_counter"])
        for a, b in ((csv.acc, r.acc), (csv.gyr, r.gyr), (csv.mag, r.mag)):
            assert np.allclose(a, b, rtol=1e-5, atol=1e-9)  # the CSV holds 6 significant digits
        assert np.allclose(csv.t, r.channels["device_time_s"], atol=1e-6)
        g = np.linalg.norm(r.acc, axis=1)
        assert 9.0 < np.median(g) < 10.6 and 40 < np.median(np.linalg.norm(r.mag, axis=1)) < 58  # m/s², µT
        # host time = when the fake unit's clock read that device time (+ the link's minimum delay)
        truth = (fu.t0_ns - start_ns) / 1e9 + r.channels["device_time_s"] / (1 + fu.drift)
        err = r.t - truth
        # the clock fit runs through the fastest arrivals; on a loaded 2-core machine its drift
        # estimate over this short recording tilts the line by tens of µs at the ends (measured
        # -40 µs in a clean-clone CI run), so "never before the truth" holds to 0.2 ms
        assert -2e-4 <= err.min() and err.max() < 3e-3, (err.min(), err.max())
    # synchronised: the two units' first samples were taken when each fake unit booted
    boot_diff = (units[1].t0_ns - units[0].t0_ns) / 1e9
    assert abs((recs[1].t[0] - recs[0].t[0]) - boot_diff) < 3e-3 and abs(recs[1].t[0] - recs[0].t[0]) < 0.05
    # unit 1 drops every 25th sample: gaps of two periods, counted, nothing invented
    c = recs[0].channels["sample_counter"]
    assert np.all(np.diff(c) >= 1) and np.sum(np.diff(c) == 2) == recs[0].metadata["samples_lost"] > 10
    assert np.all((c + 1) % 25 != 0)  # the fake unit drops the frame before each multiple of 25
    big = np.diff(recs[0].t) > 3e-3
    assert np.array_equal(big, np.diff(c) == 2)
    assert recs[1].metadata["samples_lost"] == 0


# ----------------------------------------------------------------------------- the reports
def _cli(monkeypatch, capsys, module):
    """`kinefuse` with one command module; returns run(*argv) -> (code, stdout, stderr)."""
    monkeypatch.setattr(cli, "COMMAND_MODULES", [f"kinefuse.host.commands.{module}"])
    monkeypatch.setattr(cli, "BENCH_MODULES", [])

    def _run(*argv):
        code = cli.main([str(a) for a in argv])
        out, err = capsys.readouterr()
        return code, out, err
    return _run


@pytest.fixture
def run(monkeypatch, capsys):
    return _cli(monkeypatch, capsys, "report_cmd")


def _two_unit_kfr(path, thigh, shank, *, shank_late_s=0.0, seed=0):
    """Thigh (unit 1) and shank (unit 2) Recordings as one .kfr; the shank's stream starts late."""
    f1, _ = _frames(thigh.t, thigh.acc, thigh.gyr, thigh.mag, sysid=1, boot_s=12.0, drift_ppm=60)
    f2, _ = _frames(shank.t, shank.acc, shank.gyr, shank.mag, sysid=2, boot_s=3.5, drift_ppm=-40)
    late = int(round(shank_late_s * thigh.fs))
    _write_kfr(path, [list(zip(thigh.t, f1)), list(zip(shank.t[late:], f2[late:]))], seed=seed)


def test_report_knee_from_one_kfr_of_two_units(run, tmp_path):
    P = simulate.knee_protocol(seed=2, n_cycles=4)
    _two_unit_kfr(tmp_path / "both.kfr", P.task["thigh"], P.task["shank"], shank_late_s=0.4)
    _two_unit_kfr(tmp_path / "stand.kfr", P.standing["thigh"], P.standing["shank"], seed=1)
    _two_unit_kfr(tmp_path / "lie.kfr", P.lying["thigh"], P.lying["shank"], seed=2)
    out = tmp_path / "out"
    code, stdout, err = run("report", "knee", "--thigh", tmp_path / "both.kfr", "--thigh-unit", 1,
                            "--shank", tmp_path / "both.kfr", "--shank-unit", 2,
                            "--calib-standing", tmp_path / "stand.kfr", tmp_path / "stand.kfr",
                            "--calib-lying", tmp_path / "lie.kfr", tmp_path / "lie.kfr",
                            "--out", out, "--json")
    assert code == 0, err
    s = json.loads(stdout)
    assert s["n_cycles_kept"] >= 3
    for f in s["files"]:
        assert os.path.getsize(out / f) > 0
    # on the common clock the late shank start does not shift the shank against the thigh
    ts = np.loadtxt(out / "knee_timeseries.csv", delimiter=",", comments="#", skiprows=2)
    truth_t = P.truth.t + MIN_LATENCY
    i0 = np.searchsorted(truth_t, truth_t[0] + 0.4)
    flex_true = np.interp(ts[:, 0] + truth_t[i0], truth_t, P.truth.angles_deg[:, 0])
    rmse = np.sqrt(np.mean((ts[:, 1] - flex_true)[ts[:, 0] > 5] ** 2))
    assert rmse < 3.0, rmse  # 15° when the shank is aligned by its (late) start instead


def test_report_elbow_from_one_kfr(run, tmp_path):
    arm, fore, flex = simulate.elbow_flexion(n_cycles=3)
    for r in (arm, fore):
        r.mag = np.zeros_like(r.acc) if r.mag is None else r.mag
    _two_unit_kfr(tmp_path / "arm.kfr", arm, fore, shank_late_s=0.3)
    code, out, err = run("report", "elbow", "--arm", tmp_path / "arm.kfr", "--arm-unit", "1",
                         "--forearm", tmp_path / "arm.kfr", "--forearm-unit", "s1", "--out", tmp_path / "e")
    assert code == 0, err
    assert "3 of 3 cycles" in out and os.path.exists(tmp_path / "e" / "elbow_angles.png")


def test_report_knee_of_fake_units_and_errors(run, fake_recording, tmp_path):
    p = fake_recording[0]
    # the fake units' motion is no knee (both rotate alike): the report reads both units of the one
    # file and stops at the cycle detection with a one-line error, not a traceback
    code, out, err = run("report", "knee", "--thigh", p, "--thigh-unit", 1, "--shank", p, "--shank-unit", 2,
                         "--out", tmp_path / "r")
    assert code == 2 and "Traceback" not in err and len(err.strip().splitlines()) == 1
    assert "cycle" in err or "flexion" in err, err
    code, out, err = run("report", "knee", "--thigh", p, "--shank", p, "--shank-unit", 2, "--out", tmp_path / "r")
    assert code == 2 and len(err.strip().splitlines()) == 1 and "2 units in this recording: 1, 2" in err
    code, out, err = run("report", "elbow", "--arm", p, "--arm-unit", 7, "--forearm", p, "--forearm-unit", 2,
                         "--out", tmp_path / "r")
    assert code == 2 and len(err.strip().splitlines()) == 1 and "unit 7 is not in this recording" in err
    csv = tmp_path / "a.csv"
    kinefuse_csv.write(str(csv), read_recording(str(p), unit=1))
    code, out, err = run("report", "elbow", "--arm", csv, "--arm-unit", 1, "--forearm", p, "--forearm-unit", 2,
                         "--out", tmp_path / "r")
    assert code == 2 and len(err.strip().splitlines()) == 1 and "--arm-unit 1" in err and "not a .kfr" in err


def test_calibrate_selects_a_unit_of_a_kfr(monkeypatch, capsys, tmp_path):
    """`kinefuse calibrate gyro --unit ID` reads one unit of a multi-unit .kfr; without it the
    one-line error lists the units; --unit on a non-.kfr file is refused."""
    run = _cli(monkeypatch, capsys, "calibrate_cmd")
    P = simulate.knee_protocol(seed=3, n_cycles=1)
    _two_unit_kfr(tmp_path / "stand.kfr", P.standing["thigh"], P.standing["shank"], seed=4)
    biases = {}
    for unit in (1, 2):
        code, out, err = run("calibrate", "gyro", "--input", tmp_path / "stand.kfr", "--unit", unit, "--json")
        assert code == 0, err
        biases[unit] = json.loads(out)
    assert biases[1] != biases[2]          # two sensors, two readings
    code, out, err = run("calibrate", "gyro", "--input", tmp_path / "stand.kfr")
    assert code == 2 and len(err.strip().splitlines()) == 1 and "2 units in this recording" in err
    assert "--unit" in err
    csv = tmp_path / "one.csv"
    kinefuse_csv.write(str(csv), read_recording(str(tmp_path / "stand.kfr"), unit=1))
    code, out, err = run("calibrate", "gyro", "--input", csv, "--unit", 1)
    assert code == 2 and len(err.strip().splitlines()) == 1 and "not a .kfr" in err
