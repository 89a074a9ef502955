"""Exported CSVs of several units share a host-time column from each unit's device -> host
clock fit (``host_fit_s``), and name their unit in ``#`` lines; the files stay "plain kinefuse
CSV" for the readers."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from kinefuse.host.link.export import export_csv
from kinefuse.host.link.frames import decode_file
from kinefuse.host.readers import kinefuse_csv, read_recording


@pytest.fixture(scope="module")
def two_units(tmp_path_factory):
    from kinefuse.host.link.recorder import Recorder
    p = tmp_path_factory.mktemp("fit") / "both.kfr"
    rec = Recorder(p, ["fake:rate=500", "fake:unit=2,rate=500,drift=300"])
    units = [st.session.conn.unit for st in rec.streams]
    start_ns = rec.header["start_monotonic_ns"]
    rec.run(1.2)
    return p, units, start_ns


def _csv(path):
    lines = path.read_text().splitlines()
    comments = [ln for ln in lines if ln.startswith("#")]
    rows = [ln for ln in lines if not ln.startswith("#")]
    head = rows[0].split(",")
    data = np.array([[float(x) for x in r.split(",")] for r in rows[1:]])
    return comments, {h: data[:, k] for k, h in enumerate(head)}


def test_host_fit_column_aligns_the_units(two_units, tmp_path):
    p, units, start_ns = two_units
    export_csv(decode_file(p), tmp_path, ["KF_RAW_SAMPLE", "KF_ORIENTATION"])
    firsts = []
    for sysid, stream, fu in ((1, 0, units[0]), (2, 1, units[1])):
        f = tmp_path / f"KF_RAW_SAMPLE_s{stream}_u{sysid}.csv"
        comments, c = _csv(f)
        assert any(f"unit: system id {sysid}, stream {stream}" in x and "clock fit: host =" in x for x in comments)
        assert list(c)[:4] == ["t_s", "host_time_s", "host_unix_s", "host_fit_s"]
        # the same time base as the .kfr reader (replay, reports) ...
        r = read_recording(str(p), unit=sysid)
        assert np.allclose(c["host_fit_s"], r.t, atol=2e-6)
        # ... which is when the fake unit's clock read that device time (+ the minimum delay)
        truth = (fu.t0_ns - start_ns) / 1e9 + c["t_s"] / (1 + fu.drift)
        err = c["host_fit_s"] - truth
        assert -2e-4 <= err.min() and err.max() < 3e-3, (err.min(), err.max())   # as test_readers_kfr
        # never after the frame was received (up to the fit's end-point tilt)
        assert np.all(c["host_fit_s"] <= c["host_time_s"] + 2e-4)
        ori = _csv(tmp_path / f"KF_ORIENTATION_s{stream}_u{sysid}.csv")[1]
        assert np.all(np.isfinite(ori["host_fit_s"]))                # the same unit clock for its other messages
        firsts.append(c["host_fit_s"][0])
        # still a "plain kinefuse CSV" (comments before the header)
        assert len(kinefuse_csv.read(str(f))) == c["t_s"].size
    boot_diff = (units[1].t0_ns - units[0].t0_ns) / 1e9
    assert abs((firsts[1] - firsts[0]) - boot_diff) < 3e-3


def test_a_raw_capture_is_not_said_to_start_at_none(tmp_path):
    from kinefuse.host.link.fakeunit import raw_frames
    cap = tmp_path / "cap.bin"
    cap.write_bytes(raw_frames(50))
    (f,) = export_csv(decode_file(cap, raw=True), tmp_path / "csv")
    first = open(f["file"]).readline()
    assert first == f"# kinefuse export of {cap} (raw MAVLink capture): KF_RAW_SAMPLE\n", first


def test_a_unit_without_a_clock_fit_says_what_host_fit_s_holds(tmp_path):
    """The comment said 'host_fit_s empty' above rows holding nan."""
    import time
    from kinefuse.host.link.fakeunit import raw_frames
    from kinefuse.host.link.recording import RecordingWriter, make_header
    p = tmp_path / "one.kfr"
    w = RecordingWriter(p, make_header([{"id": 0, "connection": "x"}]))
    w.rx(0, [(time.monotonic_ns(), raw_frames(1))])
    w.close()
    (f,) = export_csv(decode_file(p), tmp_path / "csv")
    comments, cols = _csv(Path(f["file"]))
    assert np.isnan(cols["host_fit_s"]).all()
    assert any("no clock fit (too few samples): host_fit_s is nan" in c for c in comments), comments


def test_fake_unit_orientation_names_the_sample_it_follows(two_units, tmp_path):
    """KF_ORIENTATION's time_boot_us and sample_counter are those of the newest KF_RAW_SAMPLE used
    (dialect): the fake unit sent the time of sample k with counter k + 1 (one sample off, so a
    match on the counter paired each quaternion with the next sample)."""
    p, _, _ = two_units
    export_csv(decode_file(p), tmp_path, ["KF_RAW_SAMPLE", "KF_ORIENTATION"])
    raw = _csv(tmp_path / "KF_RAW_SAMPLE_s0_u1.csv")[1]
    ori = _csv(tmp_path / "KF_ORIENTATION_s0_u1.csv")[1]
    time_of = dict(zip(raw["sample_counter"], raw["time_boot_us"]))
    pairs = [(c, t) for c, t in zip(ori["sample_counter"], ori["time_boot_us"]) if c in time_of]
    assert len(pairs) > 0.9 * ori["sample_counter"].size > 0
    assert all(time_of[c] == t for c, t in pairs), pairs[:3]
    # and the quaternion is sensor -> ENU: it turns that sample's specific force to +g up
    # and its field to north and down (the fake unit's earth field 0, 19, -45 µT)
    ix = {c: k for k, c in enumerate(raw["sample_counter"])}
    k = np.array([ix[c] for c, _ in pairs])
    om = np.array([list(ori["sample_counter"]).index(c) for c, _ in pairs])
    q = np.column_stack([ori[f"quat_{a}"][om] for a in "wxyz"])
    for ch, unit, want, tol in (("acc", "mps2", (0, 0, 9.80665), 0.15), ("mag", "uT", (0, 19, -45), 1.5)):
        v = np.column_stack([raw[f"{ch}_{a}_{unit}"][k] for a in "xyz"])
        w, u = q[:, :1], q[:, 1:]
        t = 2 * np.cross(u, v)
        earth = v + w * t + np.cross(u, t)           # q v q*
        assert np.abs(earth.mean(axis=0) - want).max() < tol, (ch, earth.mean(axis=0))
