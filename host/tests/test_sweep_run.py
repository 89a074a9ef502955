"""Defect sweep of `kinefuse run` / `demo` (and the CSV writer they share): time stamps keep
their precision, a failed write leaves nothing half-written, options that do not apply are
refused, and the demo's numbers state their unit."""
from __future__ import annotations

import errno
import json
import os

import numpy as np
import pytest

from kinefuse.host import runner
from kinefuse.host.errors import KinefuseError
from test_accuracy import FAKE, kf  # noqa: F401 - stand-in runner and CLI fixture (demo)

MINE = ("run_cmd",)


def _one_line_error(code, err, text):
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("kinefuse: error:") and text in lines[0], err


def _rows(path):
    with open(path) as f:
        lines = f.read().splitlines()
    return lines[0], lines[1].split(","), [line.split(",") for line in lines[2:]]


# --------------------------------------------------------------------------- t column precision
def test_angle_series_with_epoch_time_stamps_keeps_every_time(run, tmp_path):
    # a logger writing Unix time: 1733250000.00, .03, .06 s; 9 significant digits made every
    # row 1.73325e+09
    src = tmp_path / "epoch.csv"
    src.write_text("t,angle_deg\n1733250000.00,10\n1733250000.03,11\n1733250000.06,12\n")
    out = tmp_path / "smooth.csv"
    code, _, err = run("run", "--filter", "angle-kf", "--impl", "ref", "--input", src, "--out", out)
    assert code == 0, err
    _, header, rows = _rows(out)
    assert header[0] == "t"
    assert [float(r[0]) for r in rows] == [1733250000.00, 1733250000.03, 1733250000.06]


def test_estimates_csv_keeps_the_fraction_of_large_times(tmp_path):
    # a unit clock after 30 days (2,592,000 s) at 100 Hz, and epoch seconds
    t = np.array([2592000.00, 2592000.01, 2592000.02, 1733250000.125])
    q = np.tile([1.0, 0.0, 0.0, 0.0], (4, 1))
    res = runner.FilterResult(q=q, outputs={"q": q})
    out = tmp_path / "est.csv"
    assert runner.write_estimates_csv(out, t, res, "test") == 4
    _, _, rows = _rows(out)
    assert [float(r[0]) for r in rows] == [2592000.00, 2592000.01, 2592000.02, 1733250000.125]
    assert [r[1:] for r in rows] == [["1", "0", "0", "0"]] * 4


# --------------------------------------------------------------------------- failed writes
def _failing_savetxt(real):
    def savetxt(f, data, *a, **k):
        real(f, data[:1], *a, **k)          # one row out, then the disk is full
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    return savetxt


def test_failed_write_leaves_no_half_written_file(tmp_path, monkeypatch):
    monkeypatch.setattr(np, "savetxt", _failing_savetxt(np.savetxt))
    q = np.tile([1.0, 0.0, 0.0, 0.0], (3, 1))
    res = runner.FilterResult(q=q, outputs={"q": q})
    out = tmp_path / "est.csv"
    with pytest.raises(KinefuseError, match="cannot write .*No space left"):
        runner.write_estimates_csv(out, np.arange(3) * 0.01, res, "test")
    assert list(tmp_path.iterdir()) == []


def test_failed_forced_write_keeps_the_earlier_file(tmp_path, monkeypatch):
    out = tmp_path / "est.csv"
    out.write_text("earlier results\n")
    monkeypatch.setattr(np, "savetxt", _failing_savetxt(np.savetxt))
    q = np.tile([1.0, 0.0, 0.0, 0.0], (3, 1))
    with pytest.raises(KinefuseError, match="cannot write"):
        runner.write_estimates_csv(out, np.arange(3) * 0.01, runner.FilterResult(q=q, outputs={"q": q}), "x")
    assert out.read_text() == "earlier results\n"
    assert [p.name for p in tmp_path.iterdir()] == ["est.csv"]


def test_forced_rewrite_keeps_the_file_mode(tmp_path):
    out = tmp_path / "est.csv"
    out.write_text("earlier\n")
    out.chmod(0o640)
    q = np.tile([1.0, 0.0, 0.0, 0.0], (2, 1))
    runner.write_estimates_csv(out, [0.0, 0.01], runner.FilterResult(q=q, outputs={"q": q}), "x")
    assert (out.stat().st_mode & 0o777) == 0o640
    assert out.read_text().splitlines()[1:] == ["t,w,x,y,z", "0,1,0,0,0", "0.01,1,0,0,0"]


# --------------------------------------------------------------------------- options that do not apply
@pytest.mark.parametrize("frame", ["ned", "enu"])
def test_frame_with_an_angle_smoother_is_refused(run, tmp_path, frame):
    src = tmp_path / "a.csv"
    src.write_text("t,angle_deg\n0,10\n0.03,11\n")
    out = tmp_path / "o.csv"
    code, _, err = run("run", "--filter", "angle-kf", "--frame", frame, "--input", src, "--out", out)
    _one_line_error(code, err, "--frame")
    assert not out.exists()


def test_filter_of_another_input_kind_is_named_not_the_file(run, tmp_path):
    src = tmp_path / "a.csv"
    src.write_text("t,angle_deg\n0,10\n0.03,11\n")
    out = tmp_path / "o.csv"
    code, _, err = run("run", "--filter", "joint-angle", "--input", src, "--out", out)
    _one_line_error(code, err, "'joint-angle' takes joint inputs")
    assert "unsupported trial format" not in err and not out.exists()


# --------------------------------------------------------------------------- demo
def test_demo_refuses_a_nan_budget_before_work(kf, tmp_path):
    # NaN > 0 and NaN <= 0 are both false: it passed the check and set no budget at all
    code, out, err = kf("demo", "--out", str(tmp_path / "d"), "--budget", "nan")
    _one_line_error(code, err, "--budget must be a positive number of seconds")
    assert not (tmp_path / "d").exists()


def test_demo_json_states_its_unit(kf, tmp_path):
    code, out, err = kf("demo", "--out", str(tmp_path), "--jobs", "1", "--budget", "0.001")
    assert code == 0, err
    d = json.loads((tmp_path / "accuracy.json").read_text())
    assert d["units"].startswith("deg: RMSE")


# --------------------------------------------------------------------------- all samples rejected
def test_every_sample_rejected_is_an_error_not_a_csv_of_zeros(run, tmp_path):
    # 1 s between samples: beyond the smoothers' 0.2 s limit, so each sample keeps the initial
    # state and the CSV held 0° and 0°/s throughout (a warning on stderr, exit 0)
    src = tmp_path / "slow.csv"
    src.write_text("t,angle_deg\n0,10\n1,11\n2,12\n")
    out = tmp_path / "o.csv"
    code, _, err = run("run", "--filter", "angle-kf", "--impl", "ref", "--input", src, "--out", out)
    _one_line_error(code, err, "rejected every one of the 3 samples")
    assert not out.exists()


def test_seed004_rate_below_5_hz_names_the_step(run, tmp_path):
    src = tmp_path / "servo.csv"
    src.write_text("".join(f"{10 + k:.4f},{-k:.4f},0.0\n" for k in range(12)))
    out = tmp_path / "o.csv"
    code, _, err = run("run", "--filter", "angle-kf", "--impl", "ref", "--input", src, "--out",
                       out, "--fs", "4")
    _one_line_error(code, err, "at --fs 4 Hz a step is 0.25 s")
    assert not out.exists()
    # at 5 Hz (0.2 s, the limit itself) every sample is filtered
    assert run("run", "--filter", "angle-kf", "--impl", "ref", "--input", src, "--out", out,
               "--fs", "5")[0] == 0
    rows = _rows(out)[2]
    assert len(rows) == 12 and float(rows[-1][1]) > 15.0


# --------------------------------------------------------------------------- bench dynamics
def test_dynamics_pendulum_table_states_its_units(capsys, monkeypatch):
    from kinefuse.host.bench import dynamics
    monkeypatch.setenv("COLUMNS", "200")
    row = {"integrator": "fe", "phi": "se", "sigma": "ct", "sensitivity": "full",
           "rms_z": 0.01, "rms_zdot": 0.2, "rms_fe": 14.0, "rms_tau1": 9.0, "rt_factor_ref": 2.0,
           "f32": {"rms_fe": 14.0}, "rt_factor_f32_c": 4000.0, "ops": 9198}
    dynamics._print({"pendulum": [row]})
    out = " ".join(capsys.readouterr().out.split())
    for unit in ("x0, y0 (m), θ1, θ2 (rad)", "(m/s)", "(rad/s)", "(N·m, N, N, N·m)",
                 "τ1 in N·m", "real-time factor"):
        assert unit in out, unit


# --------------------------------------------------------------------------- status columns
def test_status_flags_say_they_are_0_1_and_counts_are_integers(tmp_path):
    import types
    n = 6
    trial = types.SimpleNamespace(gyr=np.zeros((n, 3)), acc=np.tile([0.0, 0.0, 9.81], (n, 1)),
                                  mag=np.tile([0.0, 20.0, -40.0], (n, 1)), dt=0.01, rate_hz=100.0,
                                  n=n)
    trial.acc[2] = np.nan                                  # one unusable reading: counted
    res = runner.run_filter("flagship", "ref", trial)
    out = tmp_path / "est.csv"
    runner.write_estimates_csv(out, np.arange(n) * 0.01, res, "test", status=True)
    comment, header, rows = _rows(out)
    assert "rest (0/1)" in comment and "mag_disturbed (0/1)" in comment
    assert "rejected samples" in comment and "bias rad/s" in comment
    for name in ("rest", "mag_disturbed", "rejected"):
        col = [r[header.index(name)] for r in rows]
        assert all(c.isdigit() for c in col), (name, col)
    assert [r[header.index("rejected")] for r in rows] == ["0", "0", "1", "1", "1", "1"]


def test_special_files_and_symlinks_are_written_not_replaced(tmp_path):
    # the write-then-rename of a regular file must not rename over /dev/null (or a pipe behind
    # /dev/stdout), nor replace a symlink by a file
    q = np.tile([1.0, 0.0, 0.0, 0.0], (2, 1))
    res = runner.FilterResult(q=q, outputs={"q": q})
    runner.write_estimates_csv("/dev/null", [0.0, 0.01], res, "x")
    assert os.path.exists("/dev/null") and not os.path.isfile("/dev/null")
    target = tmp_path / "real.csv"
    link = tmp_path / "link.csv"
    link.symlink_to(target.name)
    runner.write_estimates_csv(link, [0.0, 0.01], res, "x")
    assert link.is_symlink() and target.read_text().splitlines()[1] == "t,w,x,y,z"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.csv", "real.csv"]


def test_run_reports_rejected_samples(run, tmp_path):
    from kinefuse.host.broad import EXCERPT_DIR
    z = dict(np.load(EXCERPT_DIR / "24_disturbed_tapping_A.npz"))
    n = 60
    for k in ("gyr", "acc", "mag", "quat_ref", "movement"):
        z[k] = z[k][:n].copy()
    z["gyr"][[10, 20, 30]] = 100.0                    # rad/s, beyond the ±2000 °/s range
    src = tmp_path / "short.npz"
    np.savez(src, **z)
    out = tmp_path / "o.csv"
    code, _, err = run("run", "--filter", "madgwick", "--impl", "ref", "--input", src, "--out",
                       out, "--status")
    assert code == 0, err
    assert "3 sample(s) or sensor reading(s) rejected" in err
    rows = _rows(out)[2]
    assert len(rows) == n and rows[-1][-1] == "3"
