"""``kinefuse calibrate`` through the real CLI entry point (one-line errors, exit codes, JSON)."""
import json

import numpy as np
import pytest

from kinefuse.host.kinematics import quat as Q
from kinefuse.host.kinematics import simulate
from kinefuse.host.readers import kinefuse_csv

RAW = """# seed 002 Annex G, mean raw acceleration per pose (m/s²)
ax,ay,az
7.6467,6.1838,-0.2367
6.3236,-7.5506,-0.2625
0.0265,-0.0547,9.6081
0.0657,-0.0071,-10.0659
-7.5156,-6.2212,-0.2421
7.6009,6.2452,-0.2297
"""
G = 9.80665
TARGETS = "\n".join(",".join(f"{v:.5f}" for v in r) for r in
                    [[-G, 0, 0], [0, -G, 0], [0, 0, -G], [0, 0, G], [G, 0, 0], [-G, 0, 0]]) + "\n"


MINE = ("calibrate_cmd", "report_cmd")


def test_accel_poses_json_exact(run, tmp_path):
    (tmp_path / "p.csv").write_text(RAW)
    (tmp_path / "t.csv").write_text(TARGETS)
    code, out, err = run("calibrate", "accel", "--poses", tmp_path / "p.csv", "--targets", tmp_path / "t.csv",
                         "--method", "ls", "--json")
    assert code == 0, err
    obj = json.loads(out)                      # exactly one JSON object on stdout
    assert list(obj) == ["R", "bias", "det", "residual_rms"]
    assert obj["bias"] is None
    np.testing.assert_allclose(obj["R"], [[-0.7665, -0.6419, -0.0032], [-0.6310, 0.7702, 0.0004],
                                          [-0.0230, 0.0160, -0.9956]], atol=5e-5)
    assert round(obj["det"], 4) == 0.9910
    code, out, _ = run("calibrate", "accel", "--poses", tmp_path / "p.csv", "--targets", tmp_path / "t.csv",
                       "--method", "full", "--json")
    obj = json.loads(out)
    assert len(obj["bias"]) == 3 and obj["residual_rms"] < 0.05
    code, out, _ = run("calibrate", "accel", "--poses", tmp_path / "p.csv", "--targets", tmp_path / "t.csv",
                       "--method", "procrustes")
    assert code == 0 and "det = 1.00000" in out


def test_accel_cli_errors_are_one_line_exit_2(run, tmp_path):
    (tmp_path / "p.csv").write_text(RAW)
    (tmp_path / "t5.csv").write_text("\n".join(TARGETS.splitlines()[:5]) + "\n")
    (tmp_path / "bad.csv").write_text("1,2,3\n4,x,6\n")
    (tmp_path / "p2.csv").write_text("\n".join(",".join(r.split(",")[:2]) for r in RAW.splitlines()[1:]) + "\n")
    (tmp_path / "t.csv").write_text(TARGETS)
    cases = [
        (["--poses", tmp_path / "p.csv", "--targets", tmp_path / "t5.csv"], "5 targets of 3 columns for 6 poses"),
        # said '6 targets for 6 poses (2 columns each)': the counts agreed, the columns did not
        (["--poses", tmp_path / "p2.csv", "--targets", tmp_path / "t.csv"],
         "6 targets of 3 columns for 6 poses of 2 columns"),
        (["--poses", tmp_path / "bad.csv", "--targets", tmp_path / "t5.csv"], "line 2"),
        (["--poses", tmp_path / "p.csv"], "needs --targets"),
        (["--poses", tmp_path / "missing.csv", "--targets", tmp_path / "t5.csv"], "not found"),
        ([], "give --poses"),
    ]
    for args, msg in cases:
        code, out, err = run("calibrate", "accel", *args, "--json")
        assert code == 2 and out == ""
        assert err.count("\n") == 1 and err.startswith("kinefuse: error:") and msg in err, err


@pytest.mark.parametrize("method", ["ls", "procrustes", "full"])
def test_accel_all_zero_poses_one_line_no_warnings(run, tmp_path, method):
    import warnings
    (tmp_path / "z.csv").write_text("0,0,0\n" * 6)
    (tmp_path / "t.csv").write_text(TARGETS)
    with warnings.catch_warnings():
        warnings.simplefilter("error")          # a RuntimeWarning would be an internal error (exit 3)
        for poses, targets in (("z.csv", "z.csv"), ("z.csv", "t.csv")):
            code, out, err = run("calibrate", "accel", "--poses", tmp_path / poses, "--targets",
                                 tmp_path / targets, "--method", method, "--json")
            assert code == 2 and out == "", (code, out, err)
            assert err.count("\n") == 1 and "zero" in err and "Warning" not in err, err


@pytest.mark.parametrize("g, text", [("nan", "nan is not in (0, inf]"),      # was an internal error (exit 3)
                                     ("-9.81", "-9.81 is not in (0, inf]"),  # was 'poorly excited pose set'
                                     ("0", "0 is not in (0, inf]")])
def test_accel_bad_gravity_is_a_usage_error(run, capsys, tmp_path, g, text):
    (tmp_path / "p.csv").write_text(RAW)
    with pytest.raises(SystemExit) as exc:      # an argparse usage error, before any work
        run("calibrate", "accel", "--poses", tmp_path / "p.csv", "--method", "full", f"--g={g}", "--json")
    out, err = capsys.readouterr()
    assert exc.value.code == 2 and out == "" and err.count("\n") == 1, (out, err)
    assert err.startswith("kinefuse: error: argument --g:") and text in err, err


def test_accel_options_that_do_nothing_are_refused(run, tmp_path):
    """--g with --targets (the fit matches the targets), and the recording options (--fs, --unit,
    --format, static detection) with --poses, were accepted and ignored: the same result as
    without them, no word said."""
    (tmp_path / "p.csv").write_text(RAW)
    (tmp_path / "t.csv").write_text(TARGETS)
    base = ("calibrate", "accel", "--poses", tmp_path / "p.csv")
    for extra, text in (
            (["--targets", tmp_path / "t.csv", "--g", 9.81],
             "--g 9.81 sets |acc| = g of the fit without --targets"),
            (["--targets", tmp_path / "t.csv", "--method", "full", "--g", 9.81], "--g 9.81 sets"),
            (["--targets", tmp_path / "t.csv", "--fs", 50], "--fs: option(s) of --input RECORDING"),
            (["--targets", tmp_path / "t.csv", "--unit", 2, "--static-window", 1.5],
             "--unit, --static-window: option(s) of --input RECORDING"),
            (["--method", "full", "--min-duration", 3, "--format", "xsens-dot"],
             "--format, --min-duration: option(s) of --input RECORDING")):
        code, out, err = run(*base, *extra, "--json")
        assert code == 2 and out == "" and err.count("\n") == 1, (code, out, err)
        assert err.startswith("kinefuse: error:") and text in err, err
    # --g where it is used, and the defaults written out, still work
    code, out, err = run(*base, "--method", "full", "--g", 9.81, "--static-window", 0.5, "--json")
    assert code == 0, err


def test_accel_poses_in_g_against_m_s2_are_refused(run, tmp_path):
    """A pose table in g (seed 002 Annex G / 9.80665) was fitted against m/s² targets or g =
    9.80665 to a scale of 9.8, printed and written without a word."""
    raw = np.array([[float(v) for v in line.split(",")] for line in RAW.splitlines()[2:]]) / G
    (tmp_path / "pg.csv").write_text("\n".join(",".join(f"{v:.6f}" for v in r) for r in raw) + "\n")
    (tmp_path / "t.csv").write_text(TARGETS)
    for extra, what in ((["--targets", tmp_path / "t.csv"], "the targets' (9.807)"),
                        (["--method", "full"], "--g 9.80665")):
        code, out, err = run("calibrate", "accel", "--poses", tmp_path / "pg.csv", *extra, "--json")
        assert code == 2 and out == "" and err.count("\n") == 1, (code, out, err)
        assert "median |acc| is 1.00" in err and what in err and "not the same unit" in err, err
    # the same poses with --g 1: one unit throughout
    code, out, err = run("calibrate", "accel", "--poses", tmp_path / "pg.csv", "--method", "full", "--g", 1,
                         "--json")
    assert code == 0, err


def test_serial_without_out_is_refused(run, tmp_path):
    """--serial without --out was accepted and ignored (--range without --out was refused)."""
    (tmp_path / "p.csv").write_text(RAW)
    (tmp_path / "t.csv").write_text(TARGETS)
    code, out, err = run("calibrate", "accel", "--poses", tmp_path / "p.csv", "--targets", tmp_path / "t.csv",
                         "--serial", "7", "--json")
    assert code == 2 and out == "" and err.count("\n") == 1, (code, out, err)
    assert "--serial names the unit in the calibration file: give --out" in err, err


@pytest.mark.parametrize("timeout", ["nan", "-1", "0", "inf"])
def test_apply_bad_timeout_is_a_usage_error(run, capsys, tmp_path, timeout):
    """calibrate apply --timeout took any float: -1 gave 'no HEARTBEAT within -1 s', NaN a
    deadline that never passed."""
    with pytest.raises(SystemExit) as exc:
        run("calibrate", "apply", "--calib", tmp_path / "u.json", "--port", "fake:unit=2", f"--timeout={timeout}")
    out, err = capsys.readouterr()
    assert exc.value.code == 2 and out == "" and err.count("\n") == 1, (out, err)
    assert err.startswith("kinefuse: error: argument --timeout:") and "is not in (0, 3600]" in err, err


def _six_pose_recording(path, rng):
    """Six still poses (±x, ±y, ±z up) joined by 2 s rotations, with accelerometer errors."""
    poses = [Q.identity(), Q.elementary("X", np.pi), Q.elementary("X", np.pi / 2),
             Q.elementary("X", -np.pi / 2), Q.elementary("Y", np.pi / 2), Q.elementary("Y", -np.pi / 2)]
    fs, hold, move = 100.0, 4.0, 2.0
    qs = []
    for k, q in enumerate(poses):
        qs.append(np.broadcast_to(q, (int(hold * fs), 4)))
        if k + 1 < len(poses):
            rv = Q.to_rotvec(Q.mul(Q.conj(q), poses[k + 1]))
            s = np.linspace(0, 1, int(move * fs))
            s = 0.5 - 0.5 * np.cos(np.pi * s)
            qs.append(Q.mul(q, Q.from_rotvec(s[:, None] * rv)))
    q = np.vstack(qs)
    t = np.arange(len(q)) / fs
    rec = simulate.imu(t, q, rng=rng, acc_noise=0.02)
    M_err = np.array([[1.02, 0.01, 0], [0, 0.98, -0.01], [0, 0, 1.01]])
    b = np.array([0.1, -0.2, 0.15])
    rec.acc = rec.acc @ M_err.T + b
    kinefuse_csv.write(str(path), rec)
    return M_err, b


def test_accel_from_recording_and_unit_file(run, tmp_path):
    rng = np.random.default_rng(0)
    M_err, b = _six_pose_recording(tmp_path / "six.csv", rng)
    tg = np.array([[0, 0, 1], [0, 0, -1], [0, 1, 0], [0, -1, 0], [-1, 0, 0], [1, 0, 0]]) * 9.81
    np.savetxt(tmp_path / "tg.csv", tg, delimiter=",")
    out_json = tmp_path / "unit.json"
    code, out, err = run("calibrate", "accel", "--input", tmp_path / "six.csv", "--targets", tmp_path / "tg.csv",
                         "--method", "full", "--json", "--out", out_json, "--serial", "U1", "--range", "acc_g=8")
    assert code == 0, err
    obj = json.loads(out)
    np.testing.assert_allclose(obj["bias"], b, atol=0.02)
    np.testing.assert_allclose(obj["R"], np.linalg.inv(M_err), atol=0.005)
    doc = json.loads(out_json.read_text())
    assert doc["serial"] == "U1" and doc["sensor_ranges"] == {"acc_g": 8.0}
    assert doc["sensors"]["accel"]["n_poses"] == 6 and doc["sensors"]["accel"]["units"] == "m/s^2"
    # |acc| = g with only six poses: diagonal model (documented), still a JSON object
    code, out, err = run("calibrate", "accel", "--input", tmp_path / "six.csv", "--json")
    assert code == 0 and len(json.loads(out)["bias"]) == 3
    # gyro bias into the same unit file
    code, out, err = run("calibrate", "gyro", "--input", tmp_path / "six.csv", "--json", "--out", out_json)
    assert code == 0, err
    g = json.loads(out)
    assert g["n_windows"] == 6 and g["units"] == "rad/s"
    first = json.loads(out_json.read_text())
    assert set(first["sensors"]) == {"accel", "gyro"} and "history" not in first
    # a new gyro calibration replaced the current one without trace; now the earlier one is kept
    code, out, err = run("calibrate", "gyro", "--input", tmp_path / "six.csv", "--out", out_json)
    assert code == 0 and "kept under history.gyro" in out, (out, err)
    second = json.loads(out_json.read_text())
    assert second["history"] == {"gyro": [first["sensors"]["gyro"]]}
    assert second["sensors"]["accel"] == first["sensors"]["accel"]
    code, out, err = run("calibrate", "gyro", "--input", tmp_path / "six.csv", "--out", out_json)
    third = json.loads(out_json.read_text())
    assert third["history"]["gyro"] == [first["sensors"]["gyro"], second["sensors"]["gyro"]]


def test_mag_cli(run, tmp_path):
    rec = simulate.tumble(60.0, 50.0, rng=np.random.default_rng(1), hard_iron=[15.05, 9.45, -19.7],
                          soft_iron=np.eye(3) * 1.05)
    kinefuse_csv.write(str(tmp_path / "fig8.csv"), rec)
    code, out, err = run("calibrate", "mag", "--input", tmp_path / "fig8.csv", "--field-norm", 22.6, "--json",
                         "--gate", 0.5)
    assert code == 0, err
    obj = json.loads(out)
    assert 0.0 <= obj["gated_fraction"] < 0.05            # 0.2 µT noise: few samples beyond ±0.5 µT
    assert np.linalg.norm(np.array(obj["bias"]) - [15.05, 9.45, -19.7]) < 0.5
    assert obj["spread_reduction"] >= 10 and obj["warnings"] == []
    # a recording without magnetometer: one-line error
    rec.mag = None
    kinefuse_csv.write(str(tmp_path / "nomag.csv"), rec)
    code, out, err = run("calibrate", "mag", "--input", tmp_path / "nomag.csv")
    assert code == 2 and "no magnetometer" in err and err.count("\n") == 1


def test_too_few_windows_names_the_mean_rate_threshold(run, tmp_path):
    """A still unit whose gyroscope has a 0.5 rad/s bias fails the mean-|gyro| test only; the
    error used to list the other thresholds and not that one (nor the flags to change)."""
    t = np.arange(0, 10, 0.01)
    rec = simulate.imu(t, np.broadcast_to(Q.identity(), (len(t), 4)), rng=np.random.default_rng(2),
                       gyr_bias=[0.5, 0.0, 0.0])
    kinefuse_csv.write(str(tmp_path / "biased.csv"), rec)
    code, out, err = run("calibrate", "gyro", "--input", tmp_path / "biased.csv")
    assert code == 2 and err.count("\n") == 1, err
    assert "mean |gyro| ≤ 0.35 rad/s" in err and "--gyr-abs-max" in err, err
    code, out, err = run("calibrate", "gyro", "--input", tmp_path / "biased.csv", "--gyr-abs-max", "0.6",
                         "--json")
    assert code == 0, err
    assert abs(json.loads(out)["bias"][0] - 0.5) < 0.01


@pytest.mark.parametrize("argv, text", [
    (["gyro", "--static-window", "0"], "window_s must be positive and finite, got 0 (--static-window)"),
    (["gyro", "--static-window", "inf"], "(--static-window)"),         # was an internal error (exit 3)
    (["gyro", "--min-duration", "nan"], "(--min-duration)"),           # was accepted: every run a window
    (["gyro", "--gyr-std-max", "-1"], "(--gyr-std-max)"),
    (["accel", "--acc-std-max", "0"], "acc_std_max must be positive"),
    (["mag", "--gate", "-1"], "gate must be a positive number of µT, got -1"),
    (["mag", "--gate", "nan"], "gate must be a positive number"),
])
def test_bad_static_and_gate_values_are_one_line_errors(run, tmp_path, argv, text):
    """calibrate took --static-window 0/-1 and --min-duration nan silently (report refused them)."""
    rng = np.random.default_rng(0)
    rec = simulate.tumble(20.0, 50.0, rng=rng)
    kinefuse_csv.write(str(tmp_path / "r.csv"), rec)
    code, out, err = run("calibrate", argv[0], "--input", tmp_path / "r.csv", *argv[1:])
    assert code == 2 and out == "" and err.count("\n") == 1, (code, out, err)
    assert err.startswith("kinefuse: error:") and text in err, err


def test_unit_file_paths_that_cannot_be_read_or_written(run, tmp_path):
    """--out in a missing folder, --out/--calib naming a folder, --calib naming a binary file:
    each was an internal error (FileNotFoundError, IsADirectoryError, UnicodeDecodeError)."""
    rec = simulate.tumble(20.0, 50.0, rng=np.random.default_rng(0))
    kinefuse_csv.write(str(tmp_path / "r.csv"), rec)
    (tmp_path / "folder").mkdir()
    (tmp_path / "bin.json").write_bytes(b"\x89HDF\r\n\x1a\n" + bytes(range(256)))
    cases = [
        (["mag", "--input", tmp_path / "r.csv", "--out", tmp_path / "no" / "u.json", "--serial", "7"],
         "cannot write"),
        (["mag", "--input", tmp_path / "r.csv", "--out", tmp_path / "folder", "--serial", "7"],
         "Is a directory"),
        (["apply", "--calib", tmp_path / "bin.json", "--dry-run"], "not a calibration file"),
        (["apply", "--calib", tmp_path / "folder", "--dry-run"], "cannot read"),
    ]
    for argv, text in cases:
        code, out, err = run("calibrate", *argv)
        assert code == 2 and err.count("\n") == 1 and text in err, (argv, code, err)
    assert not list((tmp_path / "folder").iterdir()) and not (tmp_path / "no").exists()


def test_unit_file_problems_are_said_before_the_work(run, tmp_path):
    """--out naming a folder, a missing folder, another unit's file or a new file without
    --serial was refused only after the recording had been read and fitted."""
    from kinefuse.host.calib import unitfile
    unitfile.save(unitfile.new("DOT-7"), str(tmp_path / "dot7.json"))
    (tmp_path / "folder").mkdir()
    missing = tmp_path / "not-recorded-yet.csv"        # never read: the --out problem comes first
    for out, serial, text in ((tmp_path / "folder", ["--serial", "7"], "is a folder (Is a directory)"),
                              (tmp_path / "no" / "u.json", ["--serial", "7"], "cannot write"),
                              (tmp_path / "dot7.json", ["--serial", "DOT-8"], "belongs to unit 'DOT-7'"),
                              (tmp_path / "new.json", [], "does not exist yet: give the unit's serial")):
        for sensor in ("gyro", "mag", "accel"):
            code, stdout, err = run("calibrate", sensor, "--input", missing, "--out", out, *serial)
            assert code == 2 and stdout == "" and err.count("\n") == 1 and text in err, (sensor, out, err)
            assert "not found" not in err
    assert not (tmp_path / "new.json").exists() and not (tmp_path / "no").exists()
