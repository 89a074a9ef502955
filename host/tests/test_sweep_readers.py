"""Defect sweep of decode / export / stats and the readers: each test fails without its fix."""
from __future__ import annotations

import json

import numpy as np
import pytest

from kinefuse.host import cli
from kinefuse.host.tests.test_readers_kfr import MIN_LATENCY, _frames, _motion, _write_kfr

MINE = ("decode_cmd", "export_cmd", "stats_cmd")


def _one_line_error(code, out, err, text):
    assert code == 2, (code, out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("kinefuse: error:") and text in lines[0], err
    assert "Traceback" not in err and out == ""


@pytest.fixture(scope="module")
def small(tmp_path_factory):
    """A one-unit .kfr: 400 samples at 200 Hz, nothing lost."""
    p = tmp_path_factory.mktemp("sweep") / "one.kfr"
    t, acc, gyr, mag = _motion(400)
    fr, _ = _frames(t, acc, gyr, mag, sysid=1, boot_s=0.5, drift_ppm=0)
    _write_kfr(p, [[(t[k], fr[k]) for k in range(400)]])
    return p


# ----------------------------------------------------------------------------- --raw on a recording
@pytest.mark.parametrize("cmd", ["decode", "stats", "export"])
def test_raw_on_a_kfr_is_refused(run, small, tmp_path, cmd):
    """--raw was ignored for a .kfr: the recording's summary / statistics / CSVs (with host
    times) came back, exit 0, instead of a raw capture's."""
    extra = ["--out", tmp_path / "csv"] if cmd == "export" else []
    _one_line_error(*run(cmd, small, "--raw", *extra), "is a kinefuse recording (.kfr), not a plain MAVLink capture")
    assert not (tmp_path / "csv").exists()
    # the same recording under another name: recognised by its magic, not its name
    other = tmp_path / "capture.bin"
    other.write_bytes(small.read_bytes())
    _one_line_error(*run(cmd, other, "--raw", *extra), "leave out --raw")
    assert not (tmp_path / "csv").exists()
    assert run(cmd, small, *extra)[0] == 0          # without --raw it reads


def test_raw_on_a_tlog_is_refused(run, tmp_path):
    from kinefuse.host.link.fakeunit import raw_frames
    import struct
    frames = raw_frames(50, unit_id=2, rate_hz=100, seed=1)
    log = b"".join(struct.pack(">Q", 1_700_000_000_000_000 + 10_000 * k) + frames[k * 46:(k + 1) * 46]
                   for k in range(50))
    (tmp_path / "x.tlog").write_bytes(log)
    _one_line_error(*run("decode", tmp_path / "x.tlog", "--raw"), "telemetry log")
    assert run("decode", tmp_path / "x.tlog", "--json")[0] == 0


# ----------------------------------------------------------------------------- empty inputs
@pytest.mark.parametrize("cmd", ["decode", "stats", "export"])
def test_empty_file_and_empty_arguments(run, tmp_path, cmd, monkeypatch):
    """An empty .kfr was 'not a kinefuse recording; use --raw', and with --raw (or as a .bin)
    summarised as 0 frames with exit 0; an empty FILE argument was read as the current folder."""
    extra = ["--out", tmp_path / "csv"] if cmd == "export" else []
    (tmp_path / "e.kfr").write_bytes(b"")
    (tmp_path / "e.bin").write_bytes(b"")
    _one_line_error(*run(cmd, tmp_path / "e.kfr", *extra), "is empty (0 bytes)")
    _one_line_error(*run(cmd, tmp_path / "e.bin", "--raw", *extra), "is empty (0 bytes)")
    _one_line_error(*run(cmd, "", *extra), "FILE is empty")
    assert not (tmp_path / "csv").exists()


def test_export_to_an_empty_out_is_refused(run, small, tmp_path, monkeypatch):
    """--out "" wrote the CSVs into the current folder."""
    monkeypatch.chdir(tmp_path)
    _one_line_error(*run("export", small, "--out", ""), "--out is empty")
    assert list(tmp_path.iterdir()) == []


# ----------------------------------------------------------------------------- stats: repeats are not resets
def test_stats_counts_a_late_replay_as_repeats_not_a_reset(run, tmp_path):
    """Unit frames 100-104 and 300 lost, 200 repeated, 50-52 delivered again after 60: stats said
    14 lost (the step 52 -> 61 counted 8) and 1 reset, and took its rate from after the replay."""
    p = tmp_path / "rep.kfr"
    n = 2000
    t, acc, gyr, mag = _motion(n)
    fr, dev = _frames(t, acc, gyr, mag, sysid=2, boot_s=7.3, drift_ppm=-80)
    lost = set(range(100, 105)) | {300}
    order = [k for k in range(n) if k not in lost]
    order.insert(order.index(200) + 1, 200)
    i60 = order.index(60) + 1
    order[i60:i60] = [50, 51, 52]
    _write_kfr(p, [[(t[k], fr[k]) for k in order]])
    code, out, err = run("stats", p, "--json")
    assert code == 0, err
    u = json.loads(out)["streams"][0]["units"][0]
    m = u["messages"]["KF_RAW_SAMPLE"]
    assert m["count"] == len(order) == n - 6 + 4
    assert m["samples_lost"] == len(lost) == 6
    assert m["duplicates"] == 4 and m["resets"] == 0
    assert m["loss_fraction"] == pytest.approx(6 / n)
    # rate: distinct samples received over the unit-clock span of the whole recording
    span = (int(dev[n - 1]) - int(dev[0])) / 1e6
    assert m["rate_hz"] == pytest.approx((n - 6 - 1) / span, rel=1e-9)
    assert m["device_span_s"] == pytest.approx(span, abs=1e-9)
    # the reader says the same of the same file
    from kinefuse.host.readers import read_recording
    r = read_recording(str(p))
    assert r.metadata["samples_lost"] == 6 and r.metadata["duplicates_dropped"] == 4
    # and the export's host_fit_s maps every sample (replays too) to its host sample time
    code, out, err = run("export", p, "--out", tmp_path / "csv", "--messages", "KF_RAW_SAMPLE", "--json")
    assert code == 0, err
    rows = [ln.split(",") for ln in (tmp_path / "csv" / "KF_RAW_SAMPLE.csv").read_text().splitlines()
            if not ln.startswith("#")]
    head = rows[0]
    counter = np.array([int(r[head.index("sample_counter")]) for r in rows[1:]])
    fit = np.array([float(r[head.index("host_fit_s")]) for r in rows[1:]])
    assert np.abs(fit - (t[counter] + MIN_LATENCY)).max() < 1e-4


# ----------------------------------------------------------------------------- export: no cut CSVs
def test_a_failed_export_leaves_no_partial_csvs(run, tmp_path, monkeypatch):
    """A disk that filled up part-way left the CSVs before it and a cut one (which read as a
    whole export); with --force it had already replaced the earlier export's files."""
    import builtins
    import errno
    from kinefuse.host.link import export
    p = tmp_path / "two.kfr"
    t, acc, gyr, mag = _motion(300)
    f1, _ = _frames(t, acc, gyr, mag, sysid=1, boot_s=0.5, drift_ppm=0)
    f2, _ = _frames(t, acc, gyr, mag, sysid=2, boot_s=1.5, drift_ppm=0)
    _write_kfr(p, [[(t[k], f1[k]) for k in range(300)], [(t[k], f2[k]) for k in range(300)]])
    real_open = builtins.open
    opened = []

    class Full:
        def __init__(self, f):
            self._f, self.room = f, 3000

        def write(self, b):
            if len(b) > self.room:
                self._f.write(b[:self.room])
                raise OSError(errno.ENOSPC, "No space left on device")
            self.room -= len(b)
            return self._f.write(b)

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self._f.close()

    def fake_open(path, *a, **k):
        f = real_open(path, *a, **k)
        opened.append(path)
        return Full(f) if len(opened) == 2 else f     # the second CSV hits a full disk
    out = tmp_path / "new" / "csv"
    monkeypatch.setattr(export, "open", fake_open, raising=False)
    _one_line_error(*run("export", p, "--out", out), "No space left on device")
    assert len(opened) == 2
    assert not (tmp_path / "new").exists()                   # nothing left, not even the folder
    # over an earlier export with --force: that one stays as it was
    monkeypatch.undo()
    monkeypatch.setattr(cli, "COMMAND_MODULES", [m for m in cli.COMMAND_MODULES if m.rsplit(".", 1)[-1] in MINE])
    out = tmp_path / "old"
    assert run("export", p, "--out", out)[0] == 0
    before = {f.name: f.read_bytes() for f in out.iterdir()}
    assert sorted(before) == ["KF_RAW_SAMPLE_s0_u1.csv", "KF_RAW_SAMPLE_s1_u2.csv"]
    opened.clear()
    monkeypatch.setattr(export, "open", fake_open, raising=False)
    _one_line_error(*run("export", p, "--out", out, "--force"), "nothing exported")
    assert {f.name: f.read_bytes() for f in out.iterdir()} == before


# ----------------------------------------------------------------------------- export: invalid temperature
def test_export_writes_nan_for_a_temperature_not_flagged_valid(run, tmp_path):
    """The temperature field was exported as degrees (here 25.12) in samples whose flags say it
    holds no measurement (KF_RAW_SAMPLE_FLAGS_TEMPERATURE_VALID = 32 clear)."""
    p = tmp_path / "temp.kfr"
    t, acc, gyr, mag = _motion(100)
    flags = np.where(np.arange(100) % 2 == 0, 8 | 16 | 32, 8 | 16)
    fr, _ = _frames(t, acc, gyr, mag, sysid=1, boot_s=0.5, drift_ppm=0, flags=flags, temp=2512)
    _write_kfr(p, [[(t[k], fr[k]) for k in range(100)]])
    assert run("export", p, "--out", tmp_path / "csv")[0] == 0
    text = (tmp_path / "csv" / "KF_RAW_SAMPLE.csv").read_text().splitlines()
    assert any(ln.startswith("#") and "specific force" in ln and "along the sensor axes" in ln for ln in text)
    rows = [ln.split(",") for ln in text if not ln.startswith("#")]
    head = rows[0]
    got_flags = np.array([int(r[head.index("flags")]) for r in rows[1:]])
    temp = np.array([float(r[head.index("temperature_degC")]) for r in rows[1:]])
    assert np.array_equal(got_flags, flags)
    assert np.all(np.isnan(temp[1::2]))
    assert np.all(temp[::2] == 25.12)                        # 2512 cdegC
    # the reader agrees
    from kinefuse.host.readers import read_recording
    r = read_recording(str(p))
    assert np.array_equal(np.isnan(r.channels["temperature_degC"]), np.isnan(temp))


# ----------------------------------------------------------------------------- readers
def test_a_folder_with_an_explicit_format_is_a_one_line_error(tmp_path):
    """read_recording(folder, fmt=...) (kinefuse calibrate --format) was an internal
    IsADirectoryError for the CSV formats and 'file not found' for broad-mat."""
    from kinefuse.host.readers import READERS, ReaderError, read_recording
    folder = tmp_path / "session.csv"
    folder.mkdir()
    for fmt in READERS:
        with pytest.raises(ReaderError) as e:
            read_recording(str(folder), fmt=fmt)
        assert "directory" in str(e.value) and "\n" not in str(e.value), (fmt, str(e.value))


def _dot_quat_only(path, first_zero: bool) -> list[float]:
    """An orientation-only Xsens DOT export (no Acc_*, Gyr_*): 8 samples at 60 Hz."""
    rows = ["PacketCounter,SampleTimeFine,Quat_W,Quat_X,Quat_Y,Quat_Z"]
    if first_zero:
        rows.append("0,983333,0,0,0,0")
    times = []
    for k in range(8):
        a = 0.1 * k
        times.append((1_000_000 + 16_667 * k) / 1e6)
        rows.append(f"{k + 1},{1_000_000 + 16_667 * k},{np.cos(a / 2):.6f},{np.sin(a / 2):.6f},0,0")
    path.write_text("\n".join(rows) + "\n")
    return times


def test_dot_orientation_only_export_keeps_its_first_sample(tmp_path):
    """Without Acc_* and Gyr_* the first sample was always taken for the empty one and dropped."""
    from kinefuse.host.readers import read_recording
    times = _dot_quat_only(tmp_path / "q.csv", first_zero=False)
    r = read_recording(str(tmp_path / "q.csv"))
    assert r.fmt == "xsens-dot" and len(r) == 8 and r.warnings == []
    assert np.allclose(r.t, times) and r.quat[0] == pytest.approx([1, 0, 0, 0])
    # an all-zero first quaternion is still the empty first sample
    _dot_quat_only(tmp_path / "q0.csv", first_zero=True)
    r = read_recording(str(tmp_path / "q0.csv"))
    assert len(r) == 8 and np.allclose(r.t, times) and any("first sample is empty" in w for w in r.warnings)


def test_broad_mat_refuses_nan_magnetometer_and_misshapen_reference(tmp_path):
    """NaN in imu_mag was passed on as magnetometer data; an opt_quat or movement of the wrong
    shape became a reference channel that no longer lines up with the samples."""
    import scipy.io
    from kinefuse.host.readers import ReaderError, read_recording
    n = 50
    rng = np.random.default_rng(0)
    good = {"imu_acc": np.tile([0.0, 0.0, 9.81], (n, 1)) + 0.01 * rng.standard_normal((n, 3)),
            "imu_gyr": 0.01 * rng.standard_normal((n, 3)), "imu_mag": np.tile([20.0, 0.0, -40.0], (n, 1)),
            "opt_quat": np.tile([1.0, 0, 0, 0], (n, 1)), "movement": np.ones((n, 1), np.uint8),
            "sampling_rate": np.array([[285.714]])}
    scipy.io.savemat(tmp_path / "ok.mat", good)
    r = read_recording(str(tmp_path / "ok.mat"))
    assert len(r) == n and r.t[1] == pytest.approx(1 / 285.714) and r.mag.shape == (n, 3)
    for name, change, text in (("nanmag", {"imu_mag": np.where(np.arange(n)[:, None] == 7, np.nan, good["imu_mag"])},
                                "imu_mag has non-finite values"),
                               ("quat3", {"opt_quat": good["opt_quat"][:, :3]}, "opt_quat has shape"),
                               ("shortq", {"opt_quat": good["opt_quat"][:-5]}, "opt_quat has shape"),
                               ("move", {"movement": good["movement"][:-1]}, "movement has 49 values"),
                               ("inf", {"sampling_rate": np.array([[np.inf]])}, "not a positive number")):
        scipy.io.savemat(tmp_path / f"{name}.mat", {**good, **change})
        with pytest.raises(ReaderError) as e:
            read_recording(str(tmp_path / f"{name}.mat"))
        assert text in str(e.value) and f"{name}.mat" in str(e.value), str(e.value)
    # NaN rows of the optical reference are lost markers: allowed
    q = good["opt_quat"].copy()
    q[3:6] = np.nan
    scipy.io.savemat(tmp_path / "lost.mat", {**good, "opt_quat": q})
    assert np.isnan(read_recording(str(tmp_path / "lost.mat")).channels["opt_quat_wxyz"][3:6]).all()


def test_metabase_native_files_are_aligned_on_their_epoch(tmp_path):
    """Each native file's elapsed (s) starts at its own first sample: a gyroscope file starting
    50 ms after the accelerometer's was paired sample by sample with it (a motion 5 samples
    apart in the two), and the magnetometer held on as if it had started with them."""
    from kinefuse.host.readers import read_recording
    e0 = 1_678_712_000_000            # ms: the accelerometer's first sample
    hdr = "epoc (ms),timestamp (-03:00),elapsed (s),x-axis ({u}),y-axis ({u}),z-axis ({u})"

    def f(sensor, rate, unit, start_ms, m, value):
        """``value(epoch ms)`` -> xyz; the samples every 1000/rate ms from start_ms."""
        name = f"MetaWear_2023-03-13T10.11.12.123_C8AB_{sensor}_{rate:.3f}Hz_1.7.3.csv"
        rows = [hdr.format(u=unit)]
        for i in range(m):
            ep = start_ms + i * 1000 / rate
            rows.append(f"{ep:.0f},2023-03-13T10.11.12.000,{i / rate:.3f}," + ",".join(f"{v:.6g}" for v in value(ep)))
        (tmp_path / name).write_text("\n".join(rows) + "\n")
        return str(tmp_path / name)
    step_ms = e0 + 1000               # the unit turns (gyro) and is bumped (acc x) 1 s after e0
    pa = f("Accelerometer", 100, "g", e0, 300, lambda ep: [0.5 if ep >= step_ms else 0.0, 0.0, 1.0])
    f("Gyroscope", 100, "deg/s", e0 + 50, 300, lambda ep: [90.0 if ep >= step_ms else 0.0, 0.0, 0.0])
    f("Magnetometer", 25, "T", e0 + 200, 60, lambda ep: [4e-5 if ep >= step_ms else 2e-5, 0.0, -1e-5])
    r = read_recording(pa)
    ia = int(np.argmax(r.acc[:, 0] > 1.0))
    ig = int(np.argmax(r.gyr[:, 0] > 0.5))
    assert ia == ig                                            # the same sample
    assert r.t[ia] == pytest.approx(1.0, abs=1e-9)            # 1 s after the accelerometer's start
    assert r.t[0] == pytest.approx(0.05, abs=1e-9)            # the first sample both have
    im = int(np.argmax(r.mag[:, 0] > 30.0))
    assert r.t[im] == pytest.approx(1.0, abs=1e-9)            # the magnetometer step at the same time
    assert r.mag_t[0] == pytest.approx(0.2, abs=1e-9)
    assert any("starts 50 ms after" in w and "first 5 accelerometer" in w for w in r.warnings), r.warnings


@pytest.mark.parametrize("fmt", ["matrix", "seed004-arduino"])
def test_an_infinite_rate_is_refused(tmp_path, fmt):
    """fs=inf passed the 'positive' check and timed every sample at t = 0."""
    from kinefuse.host.readers import ReaderError, read_recording
    from kinefuse.host.tests.test_readers import matrix_text
    p = tmp_path / "x.csv"
    p.write_text(matrix_text(300) if fmt == "matrix" else "".join(f"{k},{k + 1},{k + 2}\n" for k in range(50)))
    assert len(read_recording(str(p), fmt=fmt).t) > 2        # the file itself reads
    with pytest.raises(ReaderError, match="sampling rate must be"):
        read_recording(str(p), fmt=fmt, fs=float("inf"))


class _FifoWriter:
    """Feeds ``data`` into the FIFO each time a reader opens it, so that code which does read
    it (as before the fix) finishes instead of waiting for a writer forever."""

    def __init__(self, path, data: bytes):
        import threading
        self.path, self.data, self.stop = path, data, threading.Event()
        self.thread = threading.Thread(target=self._run, daemon=True)

    def _run(self):
        import os
        while not self.stop.is_set():
            try:
                fd = os.open(self.path, os.O_WRONLY | os.O_NONBLOCK)
            except OSError:          # no reader yet
                self.stop.wait(0.01)
                continue
            os.set_blocking(fd, True)
            try:
                os.write(fd, self.data)
            except OSError:
                pass
            finally:
                os.close(fd)

    def __enter__(self):
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.stop.set()
        self.thread.join(5)


@pytest.mark.parametrize("cmd", ["decode", "stats", "export"])
def test_a_pipe_or_a_device_is_refused(run, tmp_path, cmd):
    """A pipe (cat cap.bin | kinefuse decode /dev/stdin --raw) was opened twice and its first
    read kept a buffer's worth: 10 of 100 frames decoded, exit 0.  A device (a serial port,
    /dev/zero) given with --raw was read to an end that never came (/dev/null: 0 frames)."""
    import os
    from kinefuse.host.link.fakeunit import raw_frames
    extra = ["--out", tmp_path / "csv"] if cmd == "export" else []
    fifo = tmp_path / "cap.fifo"
    os.mkfifo(fifo)
    with _FifoWriter(fifo, raw_frames(100)):
        _one_line_error(*run(cmd, fifo, "--raw", *extra), "is a pipe, not a file")
    if os.path.exists("/dev/null"):
        _one_line_error(*run(cmd, "/dev/null", "--raw", *extra), "is a device, not a file")
    assert not (tmp_path / "csv").exists()


def test_readers_refuse_a_pipe(tmp_path):
    import os
    from kinefuse.host.readers import ReaderError, read_recording
    from kinefuse.host.tests.test_readers import DOT
    fifo = tmp_path / "dot.csv"
    os.mkfifo(fifo)
    with _FifoWriter(fifo, DOT.encode()):
        for fmt in (None, "xsens-dot", "kfr"):
            with pytest.raises(ReaderError, match="not a regular file"):
                read_recording(str(fifo), fmt=fmt)


def test_export_orientation_without_covariance_is_nan_and_frames_are_stated(run, tmp_path):
    """KF_ORIENTATION's cov all zero means "not provided" (kinefuse.xml); it was exported as a
    zero covariance, i.e. a perfectly certain orientation.  Nor did the CSVs say in which frames
    their vectors and quaternion are."""
    from kinefuse.host.link.batchenc import encode_batch
    from kinefuse.host.link.dialect import UNIT_COMPONENT_ID
    n = 40
    t = np.arange(n) / 100.0
    cov = np.zeros((n, 6), np.float32)
    cov[1::2] = [1e-4, 2e-6, 0, 1e-4, 0, 4e-4]               # every other estimate carries one
    half = np.float32(np.sqrt(0.5))
    v = {"time_boot_us": np.round((t + 0.5) * 1e6).astype(np.uint64), "sample_counter": np.arange(n, dtype=np.uint32),
         "q_w": np.full(n, half, np.float32), "q_x": np.zeros(n, np.float32), "q_y": np.zeros(n, np.float32),
         "q_z": np.full(n, half, np.float32), "earth_frame": np.full(n, 1, np.uint8), "filter_id": np.full(n, 5, np.uint8),
         "unit_id": np.full(n, 1, np.uint8), "cov": cov}
    data = encode_batch("KF_ORIENTATION", v, sysid=1, compid=UNIT_COMPONENT_ID, n=n)
    from kinefuse.host.link.batch import decode_all
    offs = decode_all(data).arrays[52501]["_offset"].tolist() + [len(data)]
    frames = [data[a:b] for a, b in zip(offs[:-1], offs[1:])]
    assert len(frames) == n
    p = tmp_path / "ori.kfr"
    _write_kfr(p, [[(t[i], frames[i]) for i in range(n)]])
    assert run("export", p, "--out", tmp_path / "csv")[0] == 0
    text = (tmp_path / "csv" / "KF_ORIENTATION.csv").read_text().splitlines()
    comments = [ln for ln in text if ln.startswith("#")]
    rows = [ln.split(",") for ln in text if not ln.startswith("#")]
    head = rows[0]
    got = np.array([[float(r[head.index(f"cov_{c}_rad2")]) for c in ("xx", "xy", "xz", "yy", "yz", "zz")]
                    for r in rows[1:]])
    assert np.all(np.isnan(got[0::2]))
    assert np.allclose(got[1::2], cov[1::2], rtol=1e-6, atol=0) and not np.isnan(got[1::2]).any()
    assert float(rows[1][head.index("quat_w")]) == pytest.approx(float(half))
    assert any("rotation sensor -> earth frame" in c and "1 ENU" in c for c in comments), comments


def test_export_unit_status_unknown_battery_is_nan(run, tmp_path):
    """battery_voltage UINT16_MAX and battery_remaining -1 mean "unknown" (kinefuse.xml): they
    were exported as a 65535 mV battery and a -1 % charge."""
    from kinefuse.host.link.batch import decode_all
    from kinefuse.host.link.batchenc import encode_batch
    from kinefuse.host.link.dialect import UNIT_COMPONENT_ID
    n = 12
    t = np.arange(n) * 0.5
    volts = np.where(np.arange(n) % 3 == 0, 0xFFFF, 3700 + np.arange(n)).astype(np.uint16)
    charge = np.where(np.arange(n) % 4 == 1, -1, 50 + np.arange(n)).astype(np.int8)
    v = {"time_boot_us": np.round((t + 1.0) * 1e6).astype(np.uint64), "battery_voltage": volts,
         "battery_remaining": charge, "unit_id": np.full(n, 1, np.uint8)}
    data = encode_batch("KF_UNIT_STATUS", v, sysid=1, compid=UNIT_COMPONENT_ID, n=n)
    offs = decode_all(data).arrays[52504]["_offset"].tolist() + [len(data)]
    frames = [data[a:b] for a, b in zip(offs[:-1], offs[1:])]
    p = tmp_path / "st.kfr"
    _write_kfr(p, [[(t[i], frames[i]) for i in range(n)]])
    assert run("export", p, "--out", tmp_path / "csv")[0] == 0
    rows = [ln.split(",") for ln in (tmp_path / "csv" / "KF_UNIT_STATUS.csv").read_text().splitlines()
            if not ln.startswith("#")]
    head = rows[0]
    mv = np.array([float(r[head.index("battery_voltage_mV")]) for r in rows[1:]])
    pct = np.array([float(r[head.index("battery_remaining_pct")]) for r in rows[1:]])
    unknown_v = np.arange(n) % 3 == 0
    unknown_c = np.arange(n) % 4 == 1
    assert np.array_equal(np.isnan(mv), unknown_v) and np.array_equal(mv[~unknown_v], 3700 + np.arange(n)[~unknown_v])
    assert np.array_equal(np.isnan(pct), unknown_c) and np.array_equal(pct[~unknown_c], 50 + np.arange(n)[~unknown_c])


def test_recording_start_utc_is_not_a_second_late(monkeypatch):
    """The header's start_utc took its seconds from unix_ns / 1e9, which rounds up to the next
    second within 0.12 us of it: 17:47:03.99999995 was stamped 17:47:04.999999Z."""
    import time
    from kinefuse.host.link import recording
    unix = 1_796_320_023_999_999_950            # 2026-12-03T17:47:03.99999995Z
    monkeypatch.setattr(time, "time_ns", lambda: unix)
    head = recording.make_header([])
    assert head["start_unix_ns"] == unix
    assert head["start_utc"] == "2026-12-03T17:47:03.999999Z"
