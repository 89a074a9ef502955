"""``kinefuse report knee|elbow`` end to end from files, through the real CLI entry point."""
import json
import os

import numpy as np
import pytest

from kinefuse.host.kinematics import simulate
from kinefuse.host.readers import kinefuse_csv


MINE = ("calibrate_cmd", "report_cmd")


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("knee")
    P = simulate.knee_protocol(seed=2, n_cycles=5)
    for seg in ("thigh", "shank"):
        for task, rec in (("step", P.task), ("stand", P.standing), ("lie", P.lying), ("fig8", P.mag)):
            kinefuse_csv.write(str(d / f"{task}-{seg}.csv"), rec[seg])
    return d, P


def test_report_knee_json_and_files(run, files):
    d, P = files
    out_dir = d / "out"
    code, out, err = run("report", "knee", "--thigh", d / "step-thigh.csv", "--shank", d / "step-shank.csv",
                         "--calib-standing", d / "stand-thigh.csv", d / "stand-shank.csv",
                         "--calib-lying", d / "lie-thigh.csv", d / "lie-shank.csv",
                         "--mag-cal", d / "fig8-thigh.csv", d / "fig8-shank.csv", "--field-norm", 22.6,
                         "--out", out_dir, "--json")
    assert code == 0, err
    s = json.loads(out)
    assert s["n_cycles_kept"] == 5
    assert "Grood & Suntay" in s["convention"]
    for f in s["files"]:
        assert os.path.exists(out_dir / f)
    truth = P.truth.angles_deg[P.truth.cycle_starts[0]:]
    rom = s["range_of_motion_deg"]["flexion_deg"]["mean"]
    assert abs(rom - np.ptp(truth[:, 0])) < 6.0
    ts = np.loadtxt(out_dir / "knee_timeseries.csv", delimiter=",", comments="#", skiprows=2)
    e = ts[:, 1:4] - P.truth.angles_deg[: len(ts)]
    assert np.sqrt((e[:, 0] ** 2).mean()) <= 2.0


def test_report_knee_errors(run, files):
    d, _ = files
    code, out, err = run("report", "knee", "--thigh", d / "step-thigh.csv", "--shank", d / "step-shank.csv",
                         "--calib-standing", d / "stand-thigh.csv", d / "stand-shank.csv", "--out", d / "o")
    assert code == 2 and "go together" in err and err.count("\n") == 1
    code, out, err = run("report", "knee", "--thigh", d / "nope.csv", "--shank", d / "step-shank.csv",
                         "--out", d / "o")
    assert code == 2 and "nope.csv" in err and "not found" in err
    # the lying recording given as standing: the two postures are the same direction
    code, out, err = run("report", "knee", "--thigh", d / "step-thigh.csv", "--shank", d / "step-shank.csv",
                         "--calib-standing", d / "lie-thigh.csv", d / "lie-shank.csv",
                         "--calib-lying", d / "lie-thigh.csv", d / "lie-shank.csv", "--out", d / "o")
    assert code == 2 and "postures must differ" in err


def test_report_elbow(run, tmp_path):
    arm, fore, _ = simulate.elbow_flexion()
    kinefuse_csv.write(str(tmp_path / "arm.csv"), arm)
    kinefuse_csv.write(str(tmp_path / "fore.csv"), fore)
    code, out, err = run("report", "elbow", "--arm", tmp_path / "arm.csv", "--forearm", tmp_path / "fore.csv",
                         "--out", tmp_path / "e")
    assert code == 0, err
    assert "6 of 6 cycles" in out and "X-Y'-Z''" in out
    assert os.path.exists(tmp_path / "e" / "elbow_angles.png")


def test_report_keeps_an_earlier_report_unless_forced(run, tmp_path):
    """A second report into the same folder replaced the first patient's files without a word:
    refused before any work unless --force; another joint's report may share the folder."""
    arm, fore, _ = simulate.elbow_flexion()
    kinefuse_csv.write(str(tmp_path / "arm.csv"), arm)
    kinefuse_csv.write(str(tmp_path / "fore.csv"), fore)
    out = tmp_path / "e"
    argv = ("report", "elbow", "--arm", tmp_path / "arm.csv", "--forearm", tmp_path / "fore.csv", "--out", out)
    assert run(*argv)[0] == 0
    before = {f.name: f.read_bytes() for f in out.iterdir()}
    assert len(before) == 5
    (out / "knee_notes.txt").write_text("not ours")
    code, stdout, err = run(*argv)
    assert code == 2 and stdout == "" and err.count("\n") == 1
    assert f"{out} already holds elbow_angles.png, elbow_cycles.csv, elbow_mean_sd.csv and 2 more" in err
    assert {f.name: f.read_bytes() for f in out.iterdir() if f.name != "knee_notes.txt"} == before
    code, _, err = run(*argv, "--force")
    assert code == 0, err
    code, _, err = run("report", "elbow", "--arm", tmp_path / "arm.csv", "--forearm", tmp_path / "fore.csv",
                       "--out", tmp_path / "arm.csv")
    assert code == 2 and "is a file, not a folder" in err


def test_mag_options_without_a_mag_calibration_are_refused(run, files):
    """--mag-gate and --field-norm without --mag-cal were accepted and silently ignored (the
    report ran 6-D, ungated, and did not say the option had no effect)."""
    d, _ = files
    base = ("report", "knee", "--thigh", d / "step-thigh.csv", "--shank", d / "step-shank.csv")
    for extra, text in ((["--mag-gate", 0.5], "--mag-gate gates the calibrated magnetometer: give --mag-cal"),
                        (["--field-norm", 22.6], "--field-norm scales the figure-eight magnetometer fit")):
        code, out, err = run(*base, *extra, "--out", d / "nomag")
        assert code == 2 and out == "" and err.count("\n") == 1, (code, out, err)
        assert err.startswith("kinefuse: error:") and text in err, err
        assert not (d / "nomag").exists()
    code, out, err = run(*base, "--mag-cal", d / "fig8-thigh.csv", d / "fig8-shank.csv", "--mag-gate", 0.5,
                         "--out", d / "gated", "--json")
    assert code == 0, err
    p = json.loads(out)["processing"]
    assert 0 < p["thigh_mag_gated_fraction"] < 0.2 and 0 < p["shank_mag_gated_fraction"] < 0.2


def test_one_unit_calibration_for_both_segments_is_refused(run, files):
    """--unit-cal cal.json cal.json was accepted: the shank's sensor corrected with the thigh
    sensor's biases and scales, without a word (one recording for both segments is refused)."""
    import shutil
    from kinefuse.host.calib import unitfile
    d, _ = files
    for name, bias in (("thigh.json", 0.01), ("shank.json", -0.02)):
        doc = unitfile.new("DOT-7")
        unitfile.set_sensor(doc, "gyro", np.eye(3), [bias, 0.0, 0.0], method="static")
        unitfile.save(doc, str(d / name))
    shutil.copy(d / "thigh.json", d / "copy.json")
    base = ("report", "knee", "--thigh", d / "step-thigh.csv", "--shank", d / "step-shank.csv")
    for second in (d / "thigh.json", f"{d}/./thigh.json"):
        for joint in (base, ("report", "elbow", "--arm", d / "step-thigh.csv", "--forearm",
                             d / "step-shank.csv")):
            code, out, err = run(*joint, "--unit-cal", d / "thigh.json", second, "--out", d / "onecal")
            assert code == 2 and out == "" and err.count("\n") == 1, (code, out, err)
            segs = "(thigh and shank)" if joint is base else "(arm and forearm)"
            assert (f"--unit-cal: {d / 'thigh.json'} given for both segments {segs}; each sensor has "
                    f"its own calibration file") in err, err
            assert not (d / "onecal").exists()
    # a copy under another name: computed, with a warning naming both files
    code, out, err = run(*base, "--unit-cal", d / "thigh.json", d / "copy.json", "--out", d / "copycal",
                         "--json")
    assert code == 0, err
    text = (f"--unit-cal: {d / 'thigh.json'} and {d / 'copy.json'} hold the same calibration (gyro)")
    assert f"kinefuse: warning: {text}" in err, err
    assert any(w.startswith(text) for w in json.loads(out)["warnings"])      # and in the summary
    assert text in (d / "copycal" / "knee_summary.md").read_text()
    # two units' own files (a two-sensor unit's two IMUs share the serial): no warning
    code, out, err = run(*base, "--unit-cal", d / "thigh.json", d / "shank.json", "--out", d / "twocal",
                         "--json")
    assert code == 0 and "--unit-cal" not in err, err


def test_one_unit_of_a_kfr_for_both_segments_is_refused(run, tmp_path):
    """--thigh-unit "" (an unset variable) read as no unit, and two spellings of one unit (1 and
    s0:1, or none and 1 on a one-unit file) passed the both-segments check: both segments got
    one sensor's data, reported as 'flexion varies by only 0.0°'."""
    from kinefuse.host.link.recorder import Recorder
    one, two = tmp_path / "one.kfr", tmp_path / "two.kfr"
    Recorder(one, ["fake:rate=200"]).run(0.4)
    Recorder(two, ["fake:rate=200", "fake:unit=2,rate=200"]).run(0.4)
    cases = [
        (["knee", "--thigh", one, "--thigh-unit", " ", "--shank", one, "--shank-unit", ""],
         "--thigh-unit is empty: give a unit (system) id"),
        (["elbow", "--arm", two, "--arm-unit", "1", "--forearm", two, "--forearm-unit", ""],
         "--forearm-unit is empty"),
        (["knee", "--thigh", two, "--thigh-unit", "1", "--shank", two, "--shank-unit", "s0:1"],
         f"--thigh and --shank: {two} unit 1 given for both segments"),
        (["elbow", "--arm", one, "--forearm", one, "--forearm-unit", "1"],
         f"--arm and --forearm: {one} unit 1 given for both segments"),
    ]
    for argv, text in cases:
        code, out, err = run("report", *argv, "--out", tmp_path / "r")
        assert code == 2 and out == "" and err.count("\n") == 1 and text in err, (argv, err)
        assert not (tmp_path / "r").exists()
    code, out, err = run("calibrate", "gyro", "--input", one, "--unit", "")
    assert code == 2 and "--unit is empty" in err, err
