"""``kinefuse replay``: BROAD trials as ``kinefuse run``, .kfr unit recordings, reader formats, errors."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.host.broad import EXCERPT_DIR

MINE = ("replay_cmd", "run_cmd")
TRIAL = EXCERPT_DIR / "24_disturbed_tapping_A.npz"


def _one_line_error(code, out, err, text):
    assert code == 2, (code, out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("kinefuse: error:") and text in lines[0], err
    assert "Traceback" not in err


def _csv(path):
    with open(path) as f:
        comment = f.readline()
        header = f.readline().strip().split(",")
    return comment, header, np.loadtxt(path, delimiter=",", skiprows=2, ndmin=2)


@pytest.fixture(scope="module")
def kfr_files(tmp_path_factory):
    """A 1.2 s recording of one fake unit (500 Hz, every 40th sample lost, KF_ORIENTATION at 100 Hz)
    and one of two fake units, both made by the real recorder in-process."""
    from kinefuse.host.link.recorder import Recorder
    d = tmp_path_factory.mktemp("replay")
    one, two = d / "one.kfr", d / "two.kfr"
    Recorder(one, ["fake:rate=500,drop=40"]).run(1.2)
    Recorder(two, ["fake:rate=200", "fake:unit=2,rate=200"]).run(0.6)
    return one, two


def test_broad_excerpt_equals_kinefuse_run(run, tmp_path):
    a, b = tmp_path / "replay.csv", tmp_path / "run.csv"
    code, _, err = run("replay", TRIAL, "--out", a, "--filter", "madgwick", "--impl", "q", "--status")
    assert code == 0, err
    assert "0 sample(s) rejected" in err
    assert run("run", "--input", TRIAL, "--out", b, "--filter", "madgwick", "--impl", "q", "--status")[0] == 0
    ca, ha, xa = _csv(a)
    cb, hb, xb = _csv(b)
    assert ha == hb == ["t", "w", "x", "y", "z", "rejected"]
    assert np.array_equal(xa, xb)
    assert a.read_text().splitlines()[1:] == b.read_text().splitlines()[1:]   # byte-identical rows
    assert "sensor->earth" in ca and "ENU" in ca and "t in s" in ca


def test_kfr_one_row_per_received_sample_and_unit_comparison(run, kfr_files, tmp_path):
    from kinefuse.host.link.frames import decode_file
    one, _ = kfr_files
    out = tmp_path / "est.csv"
    code, stdout, err = run("replay", one, "--out", out, "--compare-unit")
    assert code == 0, err
    received = decode_file(one).streams[0].arrays[52500]
    comment, header, x = _csv(out)
    assert header == ["t", "w", "x", "y", "z"]
    assert len(x) == received.size > 400                     # lost samples stay missing, nothing invented
    q = x[:, 1:5]
    assert np.all(np.isfinite(x)) and np.allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-5)
    assert np.all(np.diff(x[:, 0]) > 0)
    gaps = np.diff(x[:, 0])
    assert np.sum(gaps > 1.5 / 500) >= 10                    # the dropped samples are gaps in t
    assert "host clock" in comment and "unit 1" in comment and "w,x,y,z sensor->earth" in comment
    assert f"wrote {received.size} rows" in err and "0 sample(s) rejected" in err
    # the fake unit's own quaternion is its true orientation: the replay converges to it
    line = stdout.strip().splitlines()[-1]
    assert line.startswith("unit 1 on-board orientation vs replay") and "angle RMS" in line, stdout
    rms = float(line.split("angle RMS ")[1].split(" deg")[0])
    assert rms < 10.0


def test_compare_unit_decodes_the_recording_once(run, kfr_files, tmp_path, monkeypatch):
    """The reader decoded the file for the samples, then --compare-unit decoded it again for the
    unit's KF_ORIENTATION (the costly part of a long recording, done twice)."""
    from kinefuse.host.link import frames
    one, _ = kfr_files
    calls, decode = [], frames.decode_file
    monkeypatch.setattr(frames, "decode_file", lambda *a, **k: calls.append(a[0]) or decode(*a, **k))
    code, stdout, err = run("replay", one, "--out", tmp_path / "est.csv", "--compare-unit")
    assert code == 0, err
    assert "on-board orientation vs replay" in stdout
    assert len(calls) == 1, calls


def test_kfr_unit_choice(run, kfr_files, tmp_path):
    _, two = kfr_files
    _one_line_error(*run("replay", two, "--out", tmp_path / "x.csv"), "choose one with --unit")
    code, _, err = run("replay", two, "--out", tmp_path / "u2.csv", "--unit", "2", "--impl", "ref",
                       "--filter", "madgwick")
    assert code == 0, err
    comment, _, x = _csv(tmp_path / "u2.csv")
    assert "unit 2" in comment and len(x) > 50 and np.all(np.isfinite(x))


def test_gap_longer_than_a_second_is_rejected_and_reported(run, tmp_path):
    """A kinefuse CSV (reader format) with a 2 s hole: the sample after it is rejected by the filter."""
    fs, n = 100.0, 300
    t = np.arange(n) / fs
    t[150:] += 2.0
    rng = np.random.default_rng(1)
    acc = np.array([0.0, 0.0, 9.81]) + 0.01 * rng.standard_normal((n, 3))
    gyr = 0.01 * rng.standard_normal((n, 3))
    src = tmp_path / "gap.csv"
    with open(src, "w") as f:
        f.write("t_s,acc_x_mps2,acc_y_mps2,acc_z_mps2,gyr_x_radps,gyr_y_radps,gyr_z_radps\n")
        np.savetxt(f, np.column_stack([t, acc, gyr]), delimiter=",", fmt="%.6f")
    out = tmp_path / "est.csv"
    code, _, err = run("replay", src, "--out", out, "--filter", "madgwick", "--status")
    assert code == 0, err
    assert "1 sample(s) rejected by the filter (1 after a gap longer than 1 s)" in err
    _, header, x = _csv(out)
    assert len(x) == n and np.allclose(x[:, 0], t, atol=1e-6)
    rejected = x[:, header.index("rejected")]
    assert rejected[149] == 0 and rejected[150] == 1 and rejected[-1] == 1


@pytest.mark.parametrize("argv, text", [
    (["replay", "{tmp}/missing.kfr", "--out", "{tmp}/o.csv"], "file not found"),
    (["replay", "{tmp}/missing.npz", "--out", "{tmp}/o.csv"], "no such file"),
    (["replay", "{trial}", "--out", "{tmp}/o.csv", "--filter", "nope"], "unknown filter 'nope'"),
    (["replay", "{trial}", "--out", "{tmp}/o.csv", "--filter", "angle-kf"], "not IMU samples"),
    (["replay", "{trial}", "--out", "{tmp}/o.csv", "--param", "beta"], "expects name=value"),
    (["replay", "{trial}", "--out", "{tmp}/o.csv", "--unit", "2"], "--unit applies to .kfr"),
    (["replay", "{trial}", "--out", "{tmp}/o.csv", "--compare-unit"], "needs a .kfr"),
    (["replay", "{trial}", "--out", "{tmp}/no/such/dir/o.csv"], "does not exist"),
    (["replay", "{tmp}/junk.kfr", "--out", "{tmp}/o.csv"], "not a kinefuse recording"),
])
def test_bad_input_gives_one_line(run, tmp_path, argv, text):
    (tmp_path / "junk.kfr").write_bytes(b"\x00garbage" * 100)
    _one_line_error(*run(*[a.format(tmp=tmp_path, trial=TRIAL) for a in argv]), text)


def test_kfr_errors(run, kfr_files, tmp_path):
    one, _ = kfr_files
    _one_line_error(*run("replay", one, "--out", tmp_path / "o.csv", "--unit", "7"), "unit 7 is not in this recording")
    # --unit "" (an unset variable) replayed the file's only unit as if no --unit were given
    _one_line_error(*run("replay", one, "--out", tmp_path / "e.csv", "--unit", " "), "--unit is empty")
    assert not (tmp_path / "e.csv").exists()


def test_out_naming_the_recording_itself_is_refused(run, kfr_files, tmp_path):
    """`replay walk.kfr --out walk.kfr` wrote the CSV over the recording (it was lost)."""
    import shutil
    rec = tmp_path / "walk.kfr"
    shutil.copy(kfr_files[0], rec)
    data = rec.read_bytes()
    _one_line_error(*run("replay", rec, "--out", rec), "is the input")
    _one_line_error(*run("replay", rec, "--out", tmp_path / "." / "walk.kfr"), "is the input")
    assert rec.read_bytes() == data


def test_unit_recording_steps_come_from_the_unit_clock_and_host_steps_bridge_a_reboot():
    """A unit recording's time steps are those of its sample clock (what its filter used), not
    of the fitted host times (frames read from a backlog crowd together there); where the unit
    clock restarts (a reboot) the host-time step is kept."""
    from kinefuse.host import runner
    from kinefuse.host.readers.recording import Recording
    dev = np.array([0.000, 0.001, 0.002, 0.003, 0.004, 0.0001, 0.0011])   # reboot after 4
    host = np.array([1.0000, 1.00003, 1.00006, 1.00009, 1.0040, 1.5000, 1.5010])
    n = len(dev)
    rec = Recording(t=host, acc=np.zeros((n, 3)), gyr=np.zeros((n, 3)), fmt="kfr",
                    channels={"device_time_s": dev})
    dt = runner.recording_inputs(rec).dt
    assert np.allclose(dt[1:5], 0.001) and np.isclose(dt[5], 1.5000 - 1.0040) \
        and np.isclose(dt[6], 0.001)
    rec_no_clock = Recording(t=host, acc=np.zeros((n, 3)), gyr=np.zeros((n, 3)), fmt="csv")
    assert np.allclose(runner.recording_inputs(rec_no_clock).dt[1:], np.diff(host))


def test_an_existing_output_is_kept_unless_forced(run, tmp_path):
    """`run` and `replay` wrote over an earlier result without a word; now an existing --out is
    refused (left as it was) unless --force, a folder is refused, and the input is refused even
    with --force."""
    import shutil
    trial = tmp_path / TRIAL.name
    shutil.copy(TRIAL, trial)
    data = trial.read_bytes()
    out = tmp_path / "est.csv"
    out.write_text("earlier results\n")
    for argv in (("run", "--input", trial, "--out", out), ("replay", trial, "--out", out)):
        _one_line_error(*run(*argv), f"{out} exists (use --force")
        assert out.read_text() == "earlier results\n"
        code, _, err = run(*argv, "--force")
        assert code == 0, err
        _, header, x = _csv(out)
        assert header[:5] == ["t", "w", "x", "y", "z"] and len(x) > 100
        out.write_text("earlier results\n")
    _one_line_error(*run("run", "--input", trial, "--out", tmp_path, "--force"), "is a folder")
    _one_line_error(*run("replay", trial, "--out", tmp_path, "--force"), "is a folder")
    _one_line_error(*run("run", "--input", trial, "--out", trial, "--force"), "is the input")
    _one_line_error(*run("replay", trial, "--out", trial, "--force"), "is the input")
    assert trial.read_bytes() == data


def test_a_tlog_is_replayed(run, tmp_path):
    """A MAVProxy/QGC telemetry log (decode, stats and export read it) was an 'unknown
    recording format' for replay; its stamps are the host time base."""
    import struct
    from kinefuse.host.link.fakeunit import raw_frames
    frames = raw_frames(600, rate_hz=500)
    t0 = 1_700_000_000_000_000
    tlog = tmp_path / "x.tlog"
    tlog.write_bytes(b"".join(struct.pack(">Q", t0 + 2000 * k + 300) + frames[46 * k:46 * (k + 1)]
                              for k in range(600)))
    code, _, err = run("replay", tlog, "--out", tmp_path / "e.csv")
    assert code == 0, err
    comment, header, data = _csv(tmp_path / "e.csv")
    assert header == ["t", "w", "x", "y", "z"] and data.shape == (600, 5)
    assert np.allclose(np.diff(data[:, 0]), 0.002, atol=1e-6) and "host clock" in comment


def test_simulator_mat_replays_on_its_own_sample_times(run, tmp_path):
    """A simulator .mat with timing effects (jitter_and_drops: 0.5 ms jitter, 2 % drops, 1 %
    duplicates, a 0.5 s gap at 20 s) was replayed at the constant rate: the t column was
    index / 100 Hz (1.26 s off at the end) and the filter integrated the 0.5 s gap as 10 ms
    (flagship error median 4.2°, max 62°). Its own times: median 0.44°, max 12°; the duplicates
    (step 0) are rejected."""
    from kinefuse.hil_tests import sim
    rec = sim.simulate("jitter_and_drops", seed=0)
    rec.save(str(tmp_path / "j.mat"))
    out = tmp_path / "j.csv"
    code, _, err = run("replay", tmp_path / "j.mat", "--out", out, "--impl", "f32", "--status")
    assert code == 0, err
    comment, header, x = _csv(out)
    assert "the file's sample times" in comment
    assert np.allclose(x[:, 0], rec.t, rtol=0, atol=1e-6)
    dot = np.abs(np.sum(x[:, 1:5] * rec.q_true, axis=1)).clip(0, 1)
    err_deg = np.degrees(2 * np.arccos(dot))
    assert np.median(err_deg) < 1.0 and err_deg.max() < 20.0, (np.median(err_deg), err_deg.max())
    assert x[-1, header.index("rejected")] >= np.count_nonzero(np.diff(rec.t) == 0)


@pytest.mark.parametrize("filt, notes", [
    ("flagship", ["q6_0..3, q9_0..3 = w, x, y, z", "bias_0..2 = x, y, z of the sensor frame"]),
    ("eskf", ["cov_att_0..5 = xx, xy, xz, yy, yz, zz",
              "bias_0..2, var_bias_0..2, lin_acc_0..2 = x, y, z of the sensor frame"]),
])
def test_status_comment_says_what_the_numbered_columns_hold(run, tmp_path, filt, notes):
    """--status wrote q6_0..q6_3, cov_att_0..cov_att_5, bias_0..2, lin_acc_0..2 with units but not
    which component each number is (cov_att: six of nine entries in an unnamed order) nor that
    bias and lin_acc are along the sensor axes (they stay so with --frame ned)."""
    for frame in ("enu", "ned"):
        out = tmp_path / f"{filt}-{frame}.csv"
        code, _, err = run("run", "--input", TRIAL, "--out", out, "--filter", filt, "--status",
                           "--frame", frame)
        assert code == 0, err
        comment = _csv(out)[0]
        for note in notes:
            assert note in comment, comment


def test_non_imu_filters_and_angle_series_point_to_run(run, tmp_path):
    """A joint-angle series given to replay was "unknown recording format", and a smoother was
    refused only after the whole recording had been read: both name the `run` that takes them."""
    import shlex
    series = tmp_path / "knee angle.csv"
    series.write_text("t,angle_deg\n0,1\n0.01,2\n0.02,3\n")
    out = tmp_path / "smoothed.csv"
    code, stdout, err = run("replay", series, "--out", out, "--impl", "q", "--status")
    _one_line_error(code, stdout, err, "is a joint-angle series (t, angle_deg), not IMU samples")
    cmd = shlex.split(err.split("e.g. ", 1)[1])
    assert cmd == ["kinefuse", "run", "--filter", "angle-kf", "--input", str(series), "--out", str(out),
                   "--impl", "q", "--status"], err
    assert run(*cmd[1:])[0] == 0 and out.exists()       # the suggested command does the job
    # a smoother or another non-IMU filter: refused before the recording is read (a missing
    # file is not even looked at)
    for name, extra in (("angle-kf", "kinefuse run --filter angle-kf --input SERIES.csv"),
                        ("pendulum", "replay runs the IMU filters (")):
        code, stdout, err = run("replay", tmp_path / "missing.kfr", "--out", tmp_path / "o.csv",
                                "--filter", name)
        _one_line_error(code, stdout, err, "not IMU samples")
        assert extra in err and "not found" not in err, err
