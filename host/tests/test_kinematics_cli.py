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
