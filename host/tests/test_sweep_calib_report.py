"""Defect sweep of `kinefuse calibrate` and `kinefuse report`: integer cycle numbers and units in
the report CSVs, a report that is written whole or not at all, standard deviations of one cycle,
doubtful results warned about (another sensor's figure-eight, thigh and shank swapped, no still
reference period), and options whose empty or nonsense values were taken without a word."""
import json
import os
import re

import numpy as np
import pytest

from kinefuse.host.calib import mag as mag_cal
from kinefuse.host.calib import unitfile
from kinefuse.host.errors import KinefuseError
from kinefuse.host.kinematics import cycles, report, simulate
from kinefuse.host.kinematics import quat as Q
from kinefuse.host.readers import kinefuse_csv


MINE = ("calibrate_cmd", "report_cmd")


@pytest.fixture(scope="module")
def protocol():
    return simulate.knee_protocol(seed=2, n_cycles=5)


@pytest.fixture(scope="module")
def files(tmp_path_factory, protocol):
    d = tmp_path_factory.mktemp("sweep")
    P = protocol
    for seg in ("thigh", "shank"):
        for task, rec in (("step", P.task), ("stand", P.standing), ("lie", P.lying), ("fig8", P.mag)):
            kinefuse_csv.write(str(d / f"{task}-{seg}.csv"), rec[seg])
    arm, fore, _ = simulate.elbow_flexion()
    kinefuse_csv.write(str(d / "arm.csv"), arm)
    kinefuse_csv.write(str(d / "fore.csv"), fore)
    t = np.arange(0, 10, 0.01)
    still = simulate.imu(t, np.broadcast_to(Q.identity(), (len(t), 4)), rng=np.random.default_rng(4),
                         gyr_bias=[0.01, -0.02, 0.005])
    kinefuse_csv.write(str(d / "still.csv"), still)
    return d


def pair(x):
    return x["thigh"], x["shank"]


def _knee(d, *extra):
    return ["report", "knee", "--thigh", d / "step-thigh.csv", "--shank", d / "step-shank.csv",
            "--calib-standing", d / "stand-thigh.csv", d / "stand-shank.csv",
            "--calib-lying", d / "lie-thigh.csv", d / "lie-shank.csv", *extra]


def _one_line_error(code, out, err):
    assert code == 2 and out == "" and err.count("\n") == 1, (code, out, err)
    assert err.startswith("kinefuse: error:") and "Traceback" not in err, err


def _rows(path):
    lines = open(path, encoding="utf-8").read().splitlines()
    assert lines[0].startswith("# ")
    return lines[1].split(","), [line.split(",") for line in lines[2:]]


INT = re.compile(r"^-?\d+$")


# ----------------------------------------------------------------------------- CSVs
def test_report_csvs_write_counts_as_integers_and_name_units(run, files):
    """knee_timeseries.csv and knee_cycles.csv wrote the cycle number as 3.0000 (and -1.0000),
    the percent grid as 57.0000: counts and grid points are integers."""
    d = files
    out = d / "ints"
    code, stdout, err = run(*_knee(d, "--out", out, "--json"))
    assert code == 0, err
    n_kept = json.loads(stdout)["n_cycles_kept"]
    assert n_kept == 5
    unit = re.compile(r".+_(s|deg)$")
    head, rows = _rows(out / "knee_timeseries.csv")
    assert head == ["t_s", "flexion_deg", "adduction_deg", "internal_rotation_deg", "cycle"]
    assert all(INT.match(r[4]) for r in rows), [r[4] for r in rows if not INT.match(r[4])][:3]
    assert {int(r[4]) for r in rows} == {-1, 1, 2, 3, 4, 5}
    head, rows = _rows(out / "knee_cycles.csv")
    assert head[:2] == ["cycle", "percent"] and all(unit.match(c) for c in head[2:])
    assert all(INT.match(r[0]) and INT.match(r[1]) for r in rows)
    assert [int(r[1]) for r in rows] == list(range(101)) * 5                 # 0, 1, ..., 100 % per cycle
    assert [int(r[0]) for r in rows] == [k for k in range(1, 6) for _ in range(101)]
    head, rows = _rows(out / "knee_mean_sd.csv")
    assert head[0] == "percent" and all(unit.match(c) for c in head[1:])
    assert [r[0] for r in rows] == [str(k) for k in range(101)]
    # the angles keep their 4 decimals
    assert all(re.match(r"^-?\d+\.\d{4}$", v) for r in rows for v in r[1:])


# ----------------------------------------------------------------------------- writing
def _synthetic(n_cycles):
    """A flexion of n_cycles raised-cosine cycles of 3 s at 100 Hz (0-60°), other angles 0."""
    t = np.arange(0, 3 * n_cycles + 0.005, 0.01)
    flex = 30 - 30 * np.cos(2 * np.pi * t / 3)
    ang = np.column_stack([flex, np.zeros_like(t), np.zeros_like(t)])
    res = report.JointResult(t, ang, report.ELBOW_COLUMNS, "elbow, degrees; synthetic", np.tile(Q.identity(), (len(t), 1)))
    bounds = [(300 * k, 300 * k + 301) for k in range(n_cycles)]
    return res, cycles.normalise(t, ang, bounds)


def test_one_cycle_has_no_standard_deviation(tmp_path):
    """One kept cycle was reported as 'ROM 60.0 ± 0.0°' (and SD columns of 0): a perfectly
    repeatable subject, where no SD can be computed."""
    res, cs = _synthetic(1)
    s = report.write_report(str(tmp_path), "elbow", res, cs, title="t", inputs={})
    rom = s["range_of_motion_deg"]["flexion_deg"]
    assert rom["sd"] is None and abs(rom["mean"] - 60.0) < 1e-9 and s["cycle_duration_s"]["sd"] is None
    assert any(w.startswith("only 1 cycle kept: standard deviations") for w in s["warnings"])
    json.dumps(s, allow_nan=False)                                  # strict JSON still
    md = (tmp_path / "elbow_summary.md").read_text()
    assert "| flexion | 60.0 ± n/a |" in md and "3.00 ± n/a s" in md
    msd = np.genfromtxt(tmp_path / "elbow_mean_sd.csv", delimiter=",", skip_header=2)
    assert np.all(np.isnan(msd[:, 2::2])) and np.all(np.isfinite(msd[:, 1::2]))
    # two cycles: a number (both cycles are equal, so 0 is right here)
    res, cs = _synthetic(2)
    s = report.write_report(str(tmp_path / "two"), "elbow", res, cs, title="t", inputs={})
    assert s["range_of_motion_deg"]["flexion_deg"]["sd"] == pytest.approx(0.0, abs=1e-9)
    assert not any("only" in w for w in s["warnings"])


def test_one_cycle_through_the_cli(run, files):
    """The CLI's ROM lines printed the SD: with one cycle that is 'n/a' (and no crash on null)."""
    d = files
    code, out, err = run("report", "knee", "--thigh", d / "stand-thigh.csv", "--shank", d / "step-shank.csv",
                         "--out", d / "one")
    assert code == 0, err
    assert "1 of 1 cycles" in out and "± n/a°" in out and "only 1 cycle kept" in err


def test_a_failed_write_leaves_the_folder_as_it_was(tmp_path, monkeypatch):
    """write_report wrote the CSVs, then failed on the PNG (or a folder named knee_summary.md):
    a report half of this run and half of an earlier one, and an internal error."""
    res, cs = _synthetic(3)
    report.write_report(str(tmp_path), "elbow", res, cs, title="first", inputs={})
    before = {f.name: f.read_bytes() for f in tmp_path.iterdir()}
    assert len(before) == 5

    def broken(path, *a, **k):
        raise OSError(28, "No space left on device")
    monkeypatch.setattr(report, "_plot", broken)
    res2, cs2 = _synthetic(2)
    with pytest.raises(KinefuseError, match="cannot write the elbow report in .*No space left on device"):
        report.write_report(str(tmp_path), "elbow", res2, cs2, title="second", inputs={})
    assert {f.name: f.read_bytes() for f in tmp_path.iterdir()} == before     # no temporary files either
    # a folder it had to create is not left behind, empty
    with pytest.raises(KinefuseError, match="No space left on device"):
        report.write_report(str(tmp_path / "new" / "sub"), "elbow", res2, cs2, title="second", inputs={})
    assert not (tmp_path / "new" / "sub").exists()


def test_a_folder_in_the_way_is_refused_before_the_work(run, files):
    d = files
    out = d / "clash"
    (out / "knee_summary.md").mkdir(parents=True)
    code, stdout, err = run(*_knee(d, "--out", out, "--force"))
    _one_line_error(code, stdout, err)
    assert "knee_summary.md: a folder of that name is in the way" in err
    assert [p.name for p in out.iterdir()] == ["knee_summary.md"]


@pytest.mark.parametrize("out, text", [("", "--out is empty"), (" ", "--out is empty"),
                                       ("{d}/still.csv/r", "still.csv is a file")])
def test_impossible_report_folders(run, files, monkeypatch, out, text):
    d = files
    monkeypatch.chdir(d)
    before = sorted(os.listdir(d))
    code, stdout, err = run("report", "elbow", "--arm", d / "arm.csv", "--forearm", d / "fore.csv",
                            "--out", out.format(d=d))
    _one_line_error(code, stdout, err)
    assert text in err and sorted(os.listdir(d)) == before


# ----------------------------------------------------------------------------- doubtful results
def _rmse(res, P):
    truth = P.truth.angles_deg[: len(res.t)]
    return np.sqrt(((res.angles - truth) ** 2).mean(axis=0))


def test_another_sensors_figure_eight_is_not_used(protocol):
    """The thigh's and shank's figure-eight recordings given the other way round: each task
    magnetometer calibrated with the other sensor's offsets (|m| ≈ 87 µT for a 22.6 µT fit) ran
    the 9-D filter to internal rotation errors of 120°, without a warning."""
    P = protocol
    stand, lie = pair(P.standing), pair(P.lying)
    swapped = (P.mag["shank"], P.mag["thigh"])
    res = report.knee_from_recordings(*pair(P.task), standing=stand, lying=lie, mag_recordings=swapped,
                                      field_norm=22.6)
    for seg in ("thigh", "shank"):
        w = [w for w in res.warnings if w.startswith(f"{seg} magnetometer calibration does not fit")]
        assert len(w) == 1 and "× the 22.6 µT field of the figure-eight fit" in w[0], res.warnings
        assert res.info[f"{seg}_orientation"].endswith("(6-D)")
    assert res.info["heading_alignment"]["reference"].startswith("first still period")
    e = _rmse(res, P)
    assert e[0] <= 2.0 and e[1] <= 3.0 and e[2] <= 3.0, e
    # the right way round: 9-D, no such warning
    ok = report.knee_from_recordings(*pair(P.task), standing=stand, lying=lie, mag_recordings=pair(P.mag),
                                     field_norm=22.6)
    assert not any("does not fit" in w for w in ok.warnings)
    assert ok.info["heading_alignment"].startswith("none (both sensors referenced to magnetic north)")


def test_thigh_and_shank_swapped_is_warned(protocol, tmp_path):
    """Thigh and shank recordings given the other way round gave a knee 'flexing' from -81° to
    -2°, reported without a word."""
    P = protocol
    sw = lambda x: (x["shank"], x["thigh"])                                    # noqa: E731
    res = report.knee_from_recordings(*sw(P.task), standing=sw(P.standing), lying=sw(P.lying))
    s = report.write_report(str(tmp_path), "knee", res, report.detect_cycles(res, "knee"), title="t", inputs={})
    w = [w for w in s["warnings"] if "swapped" in w]
    assert len(w) == 1 and "hyperextension beyond 15°" in w[0], s["warnings"]
    lo = s["range_of_motion_deg"]["flexion_deg"]["min_mean"]
    assert lo < -60 and f"reaches {lo:.0f}°" in w[0]
    res = report.knee_from_recordings(*pair(P.task), standing=pair(P.standing), lying=pair(P.lying))
    s = report.write_report(str(tmp_path / "ok"), "knee", res, report.detect_cycles(res, "knee"), title="t",
                            inputs={})
    assert not any("swapped" in w for w in s["warnings"])


def test_elbow_without_a_still_period_is_warned():
    """Recordings that start and end in motion: the 'zero-at-start' reference was the first
    0.5 s, at 81° of flexion, and every angle was 81° off, without a warning."""
    arm, fore, flex = simulate.elbow_flexion()
    i, j = 400, 1750                                   # 4.0-17.5 s: inside the first and last cycle
    res = report.elbow_from_recordings(arm.slice(i, j), fore.slice(i, j))
    w = [w for w in res.warnings if w.startswith("no period ≥ 1 s where arm and forearm are both still")]
    assert len(w) == 1 and "--init zero-at-start" in w[0], res.warnings
    assert flex[i] > 80 and abs(res.angles[0, 0]) < 10                     # the offset warned about
    assert not report.elbow_from_recordings(arm.slice(i, j), fore.slice(i, j), init="none").warnings
    full = report.elbow_from_recordings(arm, fore)
    assert not full.warnings
    assert np.sqrt(np.mean((full.angles[:, 0] - flex[: len(full.t)]) ** 2)) < 2.0


def test_knee_heading_without_a_still_period_is_warned(protocol):
    P = protocol
    th, sh = pair(P.task)
    i, j = 450, len(th.t) - 450                        # the 4 s rests at both ends cut off
    res = report.knee_from_recordings(th.slice(i, j), sh.slice(i, j), standing=pair(P.standing),
                                      lying=pair(P.lying))
    assert res.info["heading_alignment"]["reference"] == "first 0.5 s of the task (no still period found)"
    assert any(w.startswith("no period ≥ 1 s where thigh and shank are both still") for w in res.warnings)
    res = report.knee_from_recordings(th, sh, standing=pair(P.standing), lying=pair(P.lying))
    assert not any("both still" in w for w in res.warnings)


def test_drop_edge_cycles_error_names_the_counts():
    t = np.arange(0, 15.005, 0.01)
    a = np.column_stack([30 - 30 * np.cos(2 * np.pi * t / 3)] * 3)
    bounds = [(300 * k, 300 * k + 301) for k in range(5)]
    with pytest.raises(KinefuseError, match=r"5 cycle\(s\) detected, dropping 3 at each end"):
        cycles.normalise(t, a, bounds, drop_edge=3)


# ----------------------------------------------------------------------------- options
@pytest.mark.parametrize("cmd", [["calibrate", "mag", "--input", "{d}/fig8-thigh.csv"],
                                 ["report", "knee", "--thigh", "{d}/step-thigh.csv", "--shank",
                                  "{d}/step-shank.csv", "--mag-cal", "{d}/fig8-thigh.csv", "{d}/fig8-shank.csv",
                                  "--out", "{d}/fn"]])
@pytest.mark.parametrize("value", ["inf", "nan", "0", "-22.6"])
def test_field_norm_must_be_finite_and_positive(run, capsys, files, cmd, value):
    """--field-norm inf passed the '> 0' test and ended in an internal error (LinAlgError)."""
    with pytest.raises(SystemExit) as exc:
        run(*[a.format(d=files) for a in cmd], f"--field-norm={value}")
    out, err = capsys.readouterr()
    assert exc.value.code == 2 and out == "" and err.count("\n") == 1, (out, err)
    assert err.startswith("kinefuse: error: argument --field-norm:"), err
    with pytest.raises(KinefuseError, match="positive, finite number of µT, got inf"):
        mag_cal.calibrate(np.random.default_rng(0).normal(size=(200, 3)) * 20, field_norm=float("inf"))


def test_field_norm_in_another_unit_is_warned(run, files):
    """22 600 (nT) or 0.226 (gauss) was taken as µT without a word."""
    for v in (22600, 0.226):
        code, out, err = run("calibrate", "mag", "--input", files / "fig8-thigh.csv", "--field-norm", v, "--json")
        assert code == 0, err
        assert "is outside the Earth's field (20–70 µT): is it in nT or gauss?" in err
        assert json.loads(out)["field_norm"] == pytest.approx(v)
    code, out, err = run("calibrate", "mag", "--input", files / "fig8-thigh.csv", "--field-norm", 22.6, "--json")
    assert code == 0 and "Earth's field" not in err


def test_gyro_bias_from_one_window_has_no_spread(run, files):
    """One static window was reported with 'spread of window means = 0.000000 rad/s' (no drift),
    which one window cannot show."""
    code, out, err = run("calibrate", "gyro", "--input", files / "still.csv", "--json")
    assert code == 0, err
    obj = json.loads(out)
    assert obj["n_windows"] == 1 and obj["window_spread"] is None
    np.testing.assert_allclose(obj["bias"], [0.01, -0.02, 0.005], atol=2e-3)   # the simulated bias
    code, out, err = run("calibrate", "gyro", "--input", files / "still.csv")
    assert "spread of window means = n/a (one static window" in out
    # several windows: a number (the standing/lying recordings hold one each; the task several)
    code, out, err = run("calibrate", "gyro", "--input", files / "step-thigh.csv", "--json")
    obj = json.loads(out)
    assert code == 0 and obj["n_windows"] > 1 and obj["window_spread"] > 0


def test_empty_out_and_blank_serial_are_refused(run, files, tmp_path):
    """calibrate --out '' was taken as no --out: the calibration printed, nothing written, no
    word; --serial ' ' was written as the unit's serial (and ' 7' was another unit than '7')."""
    base = ("calibrate", "gyro", "--input", files / "still.csv")
    code, out, err = run(*base, "--out", "")
    _one_line_error(code, out, err)
    assert "--out is empty" in err
    u = tmp_path / "u.json"
    code, out, err = run(*base, "--out", u, "--serial", "  ")
    _one_line_error(code, out, err)
    assert "--serial '  ' is blank" in err and not u.exists()
    code, out, err = run(*base, "--out", u, "--serial", " 7 ")
    assert code == 0, err
    assert json.loads(u.read_text())["serial"] == "7"
    code, out, err = run(*base, "--out", u, "--serial", "7")        # the same unit
    assert code == 0, err
    doc = json.loads(u.read_text())
    doc["serial"] = " "
    u.write_text(json.dumps(doc))
    with pytest.raises(KinefuseError, match="'serial' must be a non-empty string"):
        unitfile.load(str(u))


@pytest.mark.parametrize("cmd", [["calibrate", "gyro", "--input", "{d}/still.csv"],
                                 ["report", "elbow", "--arm", "{d}/arm.csv", "--forearm", "{d}/fore.csv",
                                  "--out", "{d}/fs"]])
def test_fs_for_a_recording_with_time_stamps_is_refused(run, files, cmd):
    """--fs 50 with a time-stamped recording (kinefuse CSV at 100 Hz) was ignored without a word."""
    code, out, err = run(*[a.format(d=files) for a in cmd], "--fs", "50")
    _one_line_error(code, out, err)
    assert "--fs 50:" in err and "(kinefuse-csv) has its own time stamps" in err
    assert not (files / "fs").exists()


def test_exactly_determined_accel_fit_is_warned(run, tmp_path):
    """Six poses for the six unknowns of the |acc| = g diagonal model: 'residual_rms = 0.00000
    m/s²' was printed as if the fit were perfect; it is 0 by construction."""
    G = 9.80665
    rng = np.random.default_rng(5)
    dirs = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]
    scale, bias = np.array([1.02, 0.98, 1.01]), np.array([0.1, -0.2, 0.15])
    raw = np.array(dirs, float) * G * scale + bias + 0.01 * rng.standard_normal((6, 3))
    np.savetxt(tmp_path / "six.csv", raw, delimiter=",")
    code, out, err = run("calibrate", "accel", "--poses", tmp_path / "six.csv", "--method", "full", "--json")
    assert code == 0, err
    assert json.loads(out)["residual_rms"] < 1e-6
    assert err.count("\n") == 1 and "6 poses for the 6 unknowns of the diagonal model" in err, err
    # a seventh pose (gravity between +x and +y): over-determined, a real residual, no warning
    d7 = np.array([1, 1, 0]) / np.sqrt(2)
    raw7 = np.vstack([raw, d7 * G * scale + bias + 0.01 * rng.standard_normal(3)])
    np.savetxt(tmp_path / "seven.csv", raw7, delimiter=",")
    code, out, err = run("calibrate", "accel", "--poses", tmp_path / "seven.csv", "--method", "full", "--json")
    assert code == 0 and err == "", err
    assert json.loads(out)["residual_rms"] > 1e-4


def test_rate_windows_in_degrees_are_refused(run, tmp_path):
    """Known rates written in °/s for a gyroscope read in rad/s: M ≈ 56·I was printed as a
    calibration (and --out refused it only as 'M value 56.18 outside the unit's range')."""
    from kinefuse.host.readers.recording import Recording
    fs, b = 100.0, np.array([0.01, 0.0, -0.01])
    t = np.arange(0, 32, 1 / fs)
    w = np.zeros((len(t), 3))
    spans = [(2, 6, [1.0, 0, 0]), (8, 12, [0, 1.0, 0]), (14, 18, [0, 0, 1.0]), (20, 24, [-1.0, 0, 0])]
    for a, e, v in spans:
        w[(t >= a) & (t < e)] = v
    rng = np.random.default_rng(0)
    gyr = w * 1.02 + b + 0.003 * rng.standard_normal(w.shape)
    acc = np.tile([0, 0, 9.81], (len(t), 1)) + 0.02 * rng.standard_normal(w.shape)
    kinefuse_csv.write(str(tmp_path / "turntable.csv"), Recording(t=t, acc=acc, gyr=gyr))
    for name, k in (("rad.csv", 1.0), ("deg.csv", 180 / np.pi)):
        (tmp_path / name).write_text("\n".join(",".join(str(x) for x in (a + 0.5, e - 0.5, *(k * np.array(v))))
                                               for a, e, v in spans) + "\n")
    code, out, err = run("calibrate", "gyro", "--input", tmp_path / "turntable.csv", "--rate-windows",
                         tmp_path / "deg.csv", "--json")
    _one_line_error(code, out, err)
    assert "not the same unit (°/s instead of rad/s?)" in err, err
    code, out, err = run("calibrate", "gyro", "--input", tmp_path / "turntable.csv", "--rate-windows",
                         tmp_path / "rad.csv", "--json")
    assert code == 0, err
    np.testing.assert_allclose(np.diag(json.loads(out)["M"]), 1 / 1.02, atol=5e-3)   # the simulated scale


@pytest.mark.parametrize("argv, text", [
    (["report", "elbow", "--arm", "{d}/arm.csv", "--forearm", "{d}/./arm.csv", "--out", "{d}/same"],
     "--arm and --forearm: {d}/arm.csv given for both segments"),
    (["report", "knee", "--thigh", "{d}/step-thigh.csv", "--shank", "{d}/step-thigh.csv", "--out", "{d}/same"],
     "--thigh and --shank: {d}/step-thigh.csv given for both segments"),
    (["report", "knee", "--thigh", "{d}/step-thigh.csv", "--shank", "{d}/step-shank.csv",
      "--mag-cal", "{d}/fig8-thigh.csv", "{d}/fig8-thigh.csv", "--out", "{d}/same"],
     "--mag-cal: {d}/fig8-thigh.csv given for both segments"),
])
def test_one_recording_for_both_segments_is_refused(run, files, argv, text):
    """The same recording for both segments: 'flexion varies by only 0.0°' (or, for a
    calibration pair, one sensor's figure-eight fitted to both, silently)."""
    code, out, err = run(*[a.format(d=files) for a in argv])
    _one_line_error(code, out, err)
    assert text.format(d=files) in err, err
    assert not (files / "same").exists()


def test_angle_series_without_any_angle_is_refused(tmp_path):
    """A t,angle_deg CSV whose angles are all empty/nan was filtered to a series of 0° (the
    filter's initial state, 'predicted only'), written as the joint angle."""
    from kinefuse.host import angle_series
    p = tmp_path / "none.csv"
    p.write_text("t,angle_deg\n0,nan\n0.1,\n0.2,NaN\n")
    with pytest.raises(KinefuseError, match=r"none.csv: no angle in any of the 3 rows"):
        angle_series.load(p)
    p.write_text("t,angle_deg\n0,nan\n0.1,12.5\n0.2,\n")                       # one angle is enough
    s = angle_series.load(p)
    assert np.isnan(s.angle[0]) and s.angle[1] == pytest.approx(np.radians(12.5)) and np.isnan(s.angle[2])


@pytest.mark.parametrize("scale, text", [(0.01, "are they in gauss (1 G = 100 µT)?"),
                                         (1000.0, "are they in nT (1 µT = 1000 nT)?")])
def test_magnetometer_readings_not_in_microtesla_are_refused(scale, text):
    """Figure-eight readings in gauss were refused as 'the unit was not turned' (std 0.2 µT);
    in nT they were fitted and written with offsets in nT labelled µT."""
    rec = simulate.tumble(60.0, 50.0, rng=np.random.default_rng(1), hard_iron=[15.05, 9.45, -19.7])
    cal = mag_cal.calibrate(rec.mag)                                          # µT: fitted
    np.testing.assert_allclose(cal.b, [15.05, 9.45, -19.7], atol=0.5)
    with pytest.raises(KinefuseError, match=re.escape(text)):
        mag_cal.calibrate(rec.mag * scale)


def test_the_summary_states_the_static_thresholds(run, files):
    """--acc-std-max and the other static-detection thresholds changed the postures, biases and
    reference periods, but the summary did not state them."""
    d = files
    code, out, err = run("report", "elbow", "--arm", d / "arm.csv", "--forearm", d / "fore.csv", "--out",
                         d / "thr", "--acc-std-max", "0.4", "--min-duration", "1.5", "--json")
    assert code == 0, err
    st = json.loads(out)["processing"]["static_detection"]
    assert st == {"window_s": 0.5, "gyr_std_max_rad_s": 0.035, "gyr_abs_max_rad_s": 0.35,
                  "acc_std_max_m_s2": 0.4, "min_duration_s": 1.5, "trim_s": 0.1}
    assert "acc std max m s2 0.400; min duration s 1.500" in (d / "thr" / "elbow_summary.md").read_text()


def test_accel_in_g_is_not_written_as_m_s2(run, tmp_path):
    """Poses in g fitted with --g 1 wrote their bias (in g) to the unit file's accelerometer
    entry, whose unit is m/s²; and the printed bias carried no unit at all."""
    G = 9.80665
    dirs = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1], [0.6, 0.8, 0]], float)
    bias = np.array([0.1, -0.2, 0.15])                                       # m/s²
    raw = dirs * G * np.array([1.02, 0.98, 1.01]) + bias
    np.savetxt(tmp_path / "pm.csv", raw, delimiter=",")
    np.savetxt(tmp_path / "pg.csv", raw / G, delimiter=",")
    u = tmp_path / "u.json"
    code, out, err = run("calibrate", "accel", "--poses", tmp_path / "pg.csv", "--method", "full", "--g", 1,
                         "--out", u, "--serial", "7")
    _one_line_error(code, out, err)
    assert "--g 1: the poses are not in m/s²" in err and not u.exists()
    code, out, err = run("calibrate", "accel", "--poses", tmp_path / "pg.csv", "--method", "full", "--g", 1)
    assert code == 0 and "(the poses' unit)" in out and "m/s²" not in out, out
    code, out, err = run("calibrate", "accel", "--poses", tmp_path / "pm.csv", "--method", "full",
                         "--out", u, "--serial", "7")
    assert code == 0, err
    line = next(x for x in out.splitlines() if x.startswith("bias = "))
    assert line.endswith(" m/s²")
    np.testing.assert_allclose([float(v) for v in line[7:-5].split(",")], bias, atol=1e-3)
    np.testing.assert_allclose(json.loads(u.read_text())["sensors"]["accel"]["b"], bias, atol=1e-3)
