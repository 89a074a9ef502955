"""BROAD trial access: excerpt and .mat reading, errors, discovery, excerpt provenance."""
import hashlib
import json
from pathlib import Path

import numpy as np
import pytest
import scipy.io

from kinefuse.host import broad
from kinefuse.host.errors import KinefuseError

SHARED = broad.shared_broad_dir()
needs_shared = pytest.mark.skipif(SHARED is None or not Path(SHARED).is_dir(),
                                  reason="full BROAD trials not present")


def test_bundled_excerpt_is_small_and_complete():
    files = broad.bundled_trials()
    assert [f.stem[:2] for f in files] == ["08", "15", "24", "32"]
    total = sum(p.stat().st_size for p in broad.EXCERPT_DIR.iterdir() if p.is_file())
    assert total <= 5_000_000
    readme = (broad.EXCERPT_DIR / "README.md").read_text()
    assert "CC BY 4.0" in readme and "10.3390/data6070072" in readme
    assert json.loads(broad.BUNDLED_TRIALS_JSON.read_text())["trials"]


def test_excerpt_trial_contents():
    groups = set()
    for path in broad.bundled_trials():
        t = broad.load_trial(path)
        assert t.name == path.stem
        assert t.rate_hz == pytest.approx(285.714, abs=1e-3)
        assert t.dt == pytest.approx(1 / 285.714, rel=1e-5)
        n = t.n
        assert t.gyr.shape == t.acc.shape == t.mag.shape == (n, 3)
        assert t.quat_ref.shape == (n, 4) and t.movement.shape == (n,)
        assert t.gyr.dtype == np.float64 and t.movement.dtype == bool
        assert t.t[0] == 0.0 and t.t[-1] == pytest.approx((n - 1) / t.rate_hz)
        assert 60 <= t.duration_s <= 80
        # starts at rest (filters initialise), then moves
        assert not t.movement[: int(20 * t.rate_hz)].any() and t.movement.sum() > 20 * t.rate_hz
        # physical units: gravity in m/s², earth field in µT, quaternion unit norm
        assert np.linalg.norm(t.acc[:100], axis=1).mean() == pytest.approx(9.81, abs=0.3)
        assert 30 < np.linalg.norm(t.mag[:100], axis=1).mean() < 60
        ok = ~np.isnan(t.quat_ref).any(axis=1)
        assert np.allclose(np.linalg.norm(t.quat_ref[ok], axis=1), 1.0, atol=1e-6)
        groups.add(t.group())
    assert groups == {"rotation", "translation", "tapping", "attached_magnet"}


@pytest.mark.broad_full
@needs_shared
def test_excerpt_is_bit_identical_to_source():
    for path in broad.bundled_trials():
        with np.load(path) as z:
            src = Path(SHARED) / str(z["source_file"])
            sha = str(z["source_sha256"])
            start, stop = int(z["start_sample"]), int(z["stop_sample"])
        assert hashlib.sha256(src.read_bytes()).hexdigest() == sha
        part, full = broad.load_trial(path), broad.load_trial(src)
        for key in ("gyr", "acc", "mag", "quat_ref"):
            assert getattr(part, key).tobytes() == getattr(full, key)[start:stop].tobytes()
        assert np.array_equal(part.movement, full.movement[start:stop])
        assert part.groups == full.groups and part.rate_hz == full.rate_hz


@needs_shared
def test_load_full_mat_trial():
    path = sorted(Path(SHARED).glob("01_*.mat"))[0]
    t = broad.load_trial(path)
    raw = scipy.io.loadmat(path)
    assert t.name == "01_undisturbed_slow_rotation_A" and t.n == raw["imu_gyr"].shape[0]
    assert np.array_equal(t.quat_ref, raw["opt_quat"], equal_nan=True)
    assert t.groups == ("all_trials", "undisturbed", "rotation", "slow", "no_breaks")
    assert t.description.startswith("slow rotation")
    assert t.source == path


def test_find_trials(tmp_path):
    files = broad.find_trials(broad.EXCERPT_DIR)
    assert files == sorted(files) and len(files) == 4
    assert broad.find_trials(files[1]) == [files[1]]
    with pytest.raises(KinefuseError, match="no trial files"):
        broad.find_trials(tmp_path)
    with pytest.raises(KinefuseError, match="no such file"):
        broad.find_trials(tmp_path / "missing")


def test_shared_dir_from_environment(monkeypatch, tmp_path):
    monkeypatch.setenv("KINEFUSE_BROAD", str(tmp_path))
    assert broad.shared_broad_dir() == tmp_path
    with pytest.raises(KinefuseError, match="no trial files"):
        broad.default_data()  # an empty folder named explicitly is not silently replaced
    monkeypatch.setenv("KINEFUSE_BROAD", str(tmp_path / "nope"))
    with pytest.raises(KinefuseError, match="KINEFUSE_BROAD=.*no such directory"):
        broad.default_data()
    monkeypatch.setenv("KINEFUSE_BROAD", str(broad.EXCERPT_DIR))
    assert broad.default_data()[0] == broad.bundled_trials()


def test_default_data_without_shared_folder(monkeypatch):
    monkeypatch.delenv("KINEFUSE_BROAD", raising=False)
    monkeypatch.setattr(broad, "shared_broad_dir", lambda: None)
    files, where = broad.default_data()
    assert files == broad.bundled_trials() and "bundled" in where


def _one_line(exc_info):
    msg = str(exc_info.value)
    assert "\n" not in msg
    return msg


def test_load_errors(tmp_path):
    with pytest.raises(KinefuseError) as e:
        broad.load_trial(tmp_path / "x.mat")
    assert "no such file" in _one_line(e)
    with pytest.raises(KinefuseError, match="is a directory"):
        broad.load_trial(tmp_path)
    (tmp_path / "x.csv").write_text("1,2,3\n")
    with pytest.raises(KinefuseError, match="unsupported trial format"):
        broad.load_trial(tmp_path / "x.csv")
    (tmp_path / "bad.mat").write_bytes(b"this is not a MATLAB file at all" * 10)
    with pytest.raises(KinefuseError) as e:
        broad.load_trial(tmp_path / "bad.mat")
    assert "bad.mat" in _one_line(e) and "MATLAB" in str(e.value)
    (tmp_path / "bad.npz").write_bytes(b"PK\x03\x04 truncated")
    with pytest.raises(KinefuseError) as e:
        broad.load_trial(tmp_path / "bad.npz")
    assert "bad.npz" in _one_line(e)


@pytest.mark.parametrize("at, junk", [(200, b"\xff" * 32), (120, b"\x00" * 8), (60, b"\x13" * 4)])
def test_damaged_npz_is_one_line(tmp_path, at, junk):
    """A damaged compressed .npz raised zlib.error or tokenize.TokenError: an internal error."""
    rng = np.random.default_rng(0)
    np.savez_compressed(tmp_path / "t.npz", gyr=rng.normal(size=(2000, 3)), acc=rng.normal(size=(2000, 3)))
    d = bytearray((tmp_path / "t.npz").read_bytes())
    d[at:at + len(junk)] = junk
    (tmp_path / "d.npz").write_bytes(bytes(d))
    with pytest.raises(KinefuseError) as e:
        broad.load_trial(tmp_path / "d.npz")
    assert "d.npz" in _one_line(e)


def _mat(path, n=50, **override):
    d = {"imu_gyr": np.zeros((n, 3)), "imu_acc": np.tile([0, 0, 9.81], (n, 1)),
         "imu_mag": np.tile([0, 20, -40.0], (n, 1)), "opt_quat": np.tile([1.0, 0, 0, 0], (n, 1)),
         "movement": np.ones((n, 1), dtype=np.uint8), "sampling_rate": np.array([[100.0]])}
    d.update(override)
    d = {k: v for k, v in d.items() if v is not None}
    scipy.io.savemat(path, d)
    return path


def test_malformed_mat_files(tmp_path):
    t = broad.load_trial(_mat(tmp_path / "ok.mat"))
    assert t.n == 50 and t.rate_hz == 100.0 and t.groups == ()
    with pytest.raises(KinefuseError, match="missing imu_mag"):
        broad.load_trial(_mat(tmp_path / "a.mat", imu_mag=None))
    with pytest.raises(KinefuseError, match=r"opt_quat has shape \(50, 3\)"):
        broad.load_trial(_mat(tmp_path / "b.mat", opt_quat=np.zeros((50, 3))))
    with pytest.raises(KinefuseError, match="imu_acc has 49 samples, imu_gyr has 50"):
        broad.load_trial(_mat(tmp_path / "c.mat", imu_acc=np.zeros((49, 3))))
    with pytest.raises(KinefuseError, match="sampling rate"):
        broad.load_trial(_mat(tmp_path / "d.mat", sampling_rate=np.array([[0.0]])))
    gyr = np.zeros((50, 3))
    gyr[3, 1] = np.nan
    with pytest.raises(KinefuseError, match="imu_gyr contains NaN"):
        broad.load_trial(_mat(tmp_path / "e.mat", imu_gyr=gyr))


def test_npz_missing_keys(tmp_path):
    np.savez(tmp_path / "x.npz", gyr=np.zeros((5, 3)))
    with pytest.raises(KinefuseError, match="missing acc, mag, quat_ref, movement, rate_hz"):
        broad.load_trial(tmp_path / "x.npz")


def test_window():
    t = broad.load_trial(broad.bundled_trials()[0])
    w = t.window(100, 300)
    assert w.n == 200 and w.t[0] == 0.0
    assert np.array_equal(w.gyr, t.gyr[100:300]) and w.name == t.name
    with pytest.raises(KinefuseError):
        t.window(10, t.n + 1)


def test_simulator_npz_names_the_mat_output(tmp_path):
    """kinefuse run --input x.npz from `kinefuse sim run --out x.npz` said only 'missing quat_ref,
    rate_hz'; the .mat output is the one the filters read."""
    from kinefuse.hil_tests import sim
    rec = sim.simulate("rest", seed=0, duration_s=1.0)
    rec.save(str(tmp_path / "rest.npz"))
    with pytest.raises(KinefuseError, match=r"a simulator recording .*--out rest\.mat"):
        broad.load_trial(tmp_path / "rest.npz")
    rec.save(str(tmp_path / "rest.mat"))
    assert broad.load_trial(tmp_path / "rest.mat").n == len(rec)


def test_pickled_npz_is_refused_in_one_whole_line(tmp_path):
    """numpy's allow_pickle message is a paragraph; cut at 120 characters it ended mid-word."""
    np.savez(tmp_path / "p.npz", gyr=np.array([{"a": 1}], dtype=object))
    with pytest.raises(KinefuseError) as e:
        broad.load_trial(tmp_path / "p.npz")
    msg = str(e.value)
    assert "\n" not in msg and msg.endswith("(a trial excerpt has numeric arrays only)") \
        and "pickled Python objects" in msg, msg


def test_simulator_mat_keeps_the_slower_magnetometer(tmp_path):
    """A simulator .mat holds mag_valid (the magnetometer at 20 Hz, its value repeated on the
    samples between): load_trial dropped it, so `kinefuse run`/`replay`/`plot` fed every repeated
    (stale) reading to the filter as new. constant_rotation (90 °/s) with an ideal sensor and a
    20 Hz magnetometer: flagship error 3.2° at 10 s with the stale readings, 0.16° with 100 Hz
    readings."""
    from kinefuse.hil_tests import sim
    from kinefuse.host import runner
    rec = sim.simulate("constant_rotation", seed=0, sensor={"preset": "ideal", "mag_rate_hz": 20})
    assert 0.15 < rec.mag_valid.mean() < 0.25
    rec.save(str(tmp_path / "c.mat"))
    trial = broad.load_trial(tmp_path / "c.mat")
    assert np.array_equal(trial.mag_valid, rec.mag_valid)
    assert np.array_equal(trial.window(100, 300).mag_valid, rec.mag_valid[100:300])
    assert np.array_equal(runner.imu_inputs(trial)["mag_valid"], rec.mag_valid)
    res = runner.run_filter("flagship", "ref", trial)
    dot = np.abs(np.sum(res.q * rec.q_true, axis=1)).clip(0, 1)
    err = np.degrees(2 * np.arccos(dot))
    assert err[len(err) // 3:].max() < 1.0, err.max()
    # a BROAD file has no mag_valid: every sample holds a reading
    assert broad.load_trial(broad.bundled_trials()[0]).mag_valid is None
    scipy.io.savemat(tmp_path / "bad.mat", {**{k: v for k, v in scipy.io.loadmat(tmp_path / "c.mat").items()
                                               if not k.startswith("__")}, "mag_valid": np.full(5, 1)})
    with pytest.raises(KinefuseError, match="mag_valid must hold one 0/1 flag per sample"):
        broad.load_trial(tmp_path / "bad.mat")


def test_simulator_mat_keeps_its_sample_times(tmp_path):
    """A simulator .mat's t (jitter, drops, duplicates, a 0.5 s gap) was replaced by index / rate,
    so the filters integrated the gap as one 10 ms step; a constant-rate file keeps steps None
    (the BROAD path, bit for bit)."""
    from kinefuse.hil_tests import sim
    from kinefuse.host import runner
    rec = sim.simulate("jitter_and_drops", seed=0, duration_s=25.0)
    rec.save(str(tmp_path / "j.mat"))
    trial = broad.load_trial(tmp_path / "j.mat")
    assert np.array_equal(trial.t, rec.t)
    d = np.diff(rec.t)
    assert np.array_equal(trial.steps[1:], d) and trial.steps[0] == np.median(d) and d.max() > 0.45
    assert np.array_equal(runner.imu_inputs(trial)["dt"], trial.steps)
    w = trial.window(10, 50)
    assert np.array_equal(w.steps, trial.steps[10:50]) and w.t[0] == 0.0
    assert np.allclose(w.t, rec.t[10:50] - rec.t[10], rtol=0, atol=1e-12)
    sim.simulate("rest", seed=0, duration_s=2.0).save(str(tmp_path / "r.mat"))
    r = broad.load_trial(tmp_path / "r.mat")
    assert r.steps is None and np.array_equal(runner.imu_inputs(r)["dt"], np.full(r.n, 0.01))
    m = {k: v for k, v in scipy.io.loadmat(tmp_path / "j.mat").items() if not k.startswith("__")}
    m["t"] = m["t"][:, ::-1]
    scipy.io.savemat(tmp_path / "bad.mat", m)
    with pytest.raises(KinefuseError, match="t must hold one finite, non-decreasing time"):
        broad.load_trial(tmp_path / "bad.mat")


def test_simulator_mat_without_a_magnetometer_reads_back(tmp_path):
    """`sim run --preset matrix --out x.mat` (no magnetometer) wrote imu_mag as NaN with mag_valid
    all 0, and load_trial refused it ("imu_mag contains NaN"), though the .npz error tells users
    to write a .mat.  The samples without a reading carry zeros; a NaN where mag_valid flags a
    reading is still refused; `sil report --broad` gets the file's flags and times."""
    from kinefuse.hil_tests import sim
    from kinefuse.hil_tests.harness import scenarios
    rec = sim.simulate("jitter_and_drops", seed=0, duration_s=8.0, sensor={"preset": "matrix"})
    assert not rec.mag_valid.any() and np.isnan(rec.mag).all()
    rec.save(str(tmp_path / "m.mat"))
    trial = broad.load_trial(tmp_path / "m.mat")
    assert not trial.mag_valid.any() and np.all(trial.mag == 0.0)
    case = scenarios.broad_case(tmp_path / "m.mat")
    assert not case.inputs["mag_valid"].any() and np.allclose(case.inputs["dt"][1:], np.diff(rec.t))
    raw = {k: v for k, v in scipy.io.loadmat(tmp_path / "m.mat").items() if not k.startswith("__")}
    raw["mag_valid"] = np.ones_like(raw["mag_valid"])
    scipy.io.savemat(tmp_path / "bad.mat", raw)
    with pytest.raises(KinefuseError, match="contains NaN or infinite samples where mag_valid flags a reading"):
        broad.load_trial(tmp_path / "bad.mat")
