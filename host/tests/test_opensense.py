"""``kinefuse opensense``: OpenSense quaternion tables from a unit recording."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.host.broad import EXCERPT_DIR
from kinefuse.host.opensense import read_sto, slerp_at

MINE = ("opensense_cmd", "replay_cmd")


def _one_line_error(res, text):
    code, out, err = res
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1 and text in lines[0], res


@pytest.fixture(scope="module")
def kfr(tmp_path_factory):
    from kinefuse.host.link.recorder import Recorder
    d = tmp_path_factory.mktemp("osim")
    two, lossy = d / "two.kfr", d / "lossy.kfr"
    Recorder(two, ["fake:unit=1,rate=200", "fake:unit=2,rate=100"]).run(1.0)
    Recorder(lossy, ["fake:rate=500,drop=40"]).run(0.6)
    return two, lossy


def test_slerp_of_a_rotation_about_one_axis_is_exact():
    rng = np.random.default_rng(1)
    t = np.cumsum(rng.uniform(0.005, 0.02, 60))
    w = 3.0                                                  # rad/s about z
    q = np.column_stack([np.cos(w * t / 2), 0 * t, 0 * t, np.sin(w * t / 2)])
    q[1::2] *= -1                                            # either sign of each sample
    grid = np.linspace(t[0], t[-1], 333)
    want = np.column_stack([np.cos(w * grid / 2), 0 * grid, 0 * grid, np.sin(w * grid / 2)])
    want *= np.sign(want[:, :1])
    assert np.max(np.abs(slerp_at(t, q, grid) - want)) < 1e-12


def test_two_units_on_one_grid(run, kfr, tmp_path):
    two, _ = kfr
    out = tmp_path / "walk.sto"
    code, _, err = run("opensense", two, "--imu", "1=pelvis_imu", "--imu", "2=femur_r_imu", "--out", out)
    assert code == 0, err
    header, t, cols = read_sto(out)
    assert header == {"DataRate": "100.000000", "DataType": "Quaternion", "version": "3", "OpenSimVersion": "4.5"}
    assert list(cols) == ["pelvis_imu", "femur_r_imu"]
    assert np.allclose(np.diff(t), 0.01, atol=2e-6) and np.allclose(t * 100, np.round(t * 100), atol=1e-3)
    for name, unit in (("pelvis_imu", "1"), ("femur_r_imu", "2")):
        q = cols[name]
        assert np.allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-7) and np.all(q[:, 0] >= 0)
        # each row against the replayed sample nearest in time (replay: another command's CSV)
        csv = tmp_path / f"{unit}.csv"
        assert run("replay", two, "--unit", unit, "--out", csv)[0] == 0
        rep = np.loadtxt(csv, delimiter=",", skiprows=2)
        k = np.abs(rep[:, :1] - t[None, :]).argmin(axis=0)
        dot = np.abs(np.sum(rep[k, 1:] * q, axis=1))
        ang = np.degrees(2 * np.arccos(np.clip(dot, -1, 1)))
        # the fake units turn at < 90 deg/s: <= half a 200/100 Hz step apart is < 0.5 deg
        assert ang.max() < 0.5, (name, ang.max())
    assert "sensor_to_opensim_rotations" in err
    _one_line_error(run("opensense", two, "--imu", "1=pelvis_imu", "--out", out), "exists")


@pytest.mark.parametrize("argv, text", [
    (["--imu", "pelvis_imu"], "choose one with --unit"),
    (["--imu", "1=pelvis imu"], "is not an IMU frame name"),
    (["--imu", "1=a_imu", "--imu", "2=a_imu"], "the name a_imu is given twice"),
    (["--imu", "1=a_imu", "--imu", "1=b_imu"], "unit 1 is given twice"),
    (["--imu", "1=a_imu", "--imu", "b_imu"], "give each one's unit"),
    (["--imu", "=a_imu"], "expected UNIT=NAME"),
    (["--imu", "7=a_imu"], "unit 7 is not in this recording"),
    (["--imu", "1=a_imu", "--rate", "0"], "--rate must be in (0, 10000] Hz"),
    (["--imu", "1=a_imu", "--filter", "angle-kf"], "is not an IMU orientation filter"),
    (["--imu", "1=a_imu", "--param", "nosuch=1"], "nosuch"),
])
def test_bad_options_are_one_line(run, kfr, tmp_path, argv, text):
    two, _ = kfr
    out = tmp_path / "x.sto"
    _one_line_error(run("opensense", two, "--out", out, *argv), text)
    assert not out.exists()


def test_inputs_and_gaps(run, kfr, tmp_path):
    _, lossy = kfr
    _one_line_error(run("opensense", lossy, "--imu", "a_imu", "--out", tmp_path / "x.csv"), "name it *.sto")
    _one_line_error(run("opensense", EXCERPT_DIR / "24_disturbed_tapping_A.npz", "--imu", "a_imu",
                        "--out", tmp_path / "x.sto"), "has no units to place")
    # every 40th sample lost at 500 Hz: a 4 ms gap, beyond a --max-gap of 3 ms
    code, _, err = run("opensense", lossy, "--imu", "a_imu", "--out", tmp_path / "g.sto", "--max-gap", "0.003")
    assert code == 2 and "without samples after t =" in err.strip().splitlines()[-1], err
    assert not (tmp_path / "g.sto").exists()
    code, _, err = run("opensense", lossy, "--imu", "a_imu", "--out", tmp_path / "g.sto")
    assert code == 0, err
    _, t, cols = read_sto(tmp_path / "g.sto")
    assert list(cols) == ["a_imu"] and len(t) > 200
