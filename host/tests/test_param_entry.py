"""Every place a parameter enters on the host refuses what the filter would interpret
arbitrarily, in one line with exit status 2: ``--param`` of run, replay, bench accuracy, bench
bitexact and plot (choices such as the flagship's mode, labels of another parameter, unknown
names, NaN/inf, out of range, duplicates, malformed items), ``calibrate --range`` (unknown
names) and ``params --set`` (duplicates, non-finite, choices)."""
from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from kinefuse.host import broad, runner
from kinefuse.host.errors import KinefuseError


def kf(*args, timeout=300):
    return subprocess.run([sys.executable, "-m", "kinefuse.host.cli", *args], capture_output=True,
                          text=True, timeout=timeout)


def one_line_error(r, *words):
    assert r.returncode == 2, (r.returncode, r.stdout, r.stderr)
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("kinefuse: error:"), r.stderr
    for w in words:
        assert w in lines[0], (w, lines[0])


@pytest.fixture(scope="module")
def short_trial(tmp_path_factory):
    """A 5 s cut of a bundled trial, saved in the bundled format."""
    t = broad.load_trial(broad.bundled_trials()[0])
    src = np.load(broad.bundled_trials()[0])
    path = tmp_path_factory.mktemp("data") / f"{t.name}.npz"
    n = int(5 * t.rate_hz)
    np.savez(path, **{k: (v[:n] if getattr(v, "ndim", 0) and len(v) == t.n else v)
                      for k, v in src.items()})
    return path


# ----------------------------------------------------------------------------- parsing

@pytest.mark.parametrize("items, words", [
    (["mode"], ["name=value"]), (["=3"], ["name=value"]), (["mode="], ["name=value"]),
    (["beta=0.1", "beta=0.2"], ["beta", "twice"]), (["beta=nan"], ["finite"]),
    (["beta=inf"], ["finite"]), (["beta=-inf"], ["finite"]),
])
def test_param_items_are_parsed_strictly(items, words):
    with pytest.raises(KinefuseError) as exc:
        runner.parse_params(items)
    assert all(w in str(exc.value) for w in words)


@pytest.mark.parametrize("name, prm, words", [
    ("flagship", {"mode": 0.5}, ["mode=0.5", "choices", "6d", "9d"]),
    ("flagship", {"mode": 0.7}, ["mode=0.7"]),
    ("flagship", {"mode": "7d"}, ["not a number"]),
    ("madgwick", {"beta": "6d"}, ["beta", "not a number"]),     # was silently beta = 0
    ("madgwick", {"bta": 0.1}, ["no parameter 'bta'"]),
    ("madgwick", {"beta": 50.0}, ["outside"]),
    ("vac", {"adaptive": 0.5}, ["adaptive"]),
])
def test_check_params_refuses(name, prm, words):
    with pytest.raises(KinefuseError) as exc:
        runner.check_params(name, prm)
    assert all(w in str(exc.value) for w in words) and "\n" not in str(exc.value)


def test_labels_and_preset_precedence():
    assert runner.check_params("flagship", runner.parse_params(["mode=6d"]))["mode"] == 0.0
    assert runner.check_params("flagship", runner.parse_params(["mode=9D"]))["mode"] == 1.0
    prm = runner.check_params("madgwick", runner.parse_params(["beta=0.05"]), "seed001")
    assert prm["beta"] == 0.05 and prm["beta_start"] == 2.0          # the override wins
    with pytest.raises(KinefuseError, match="no preset"):
        runner.check_params("madgwick", None, "seed01")


# ------------------------------------------------------------------------ the commands

@pytest.mark.parametrize("params, words", [
    (["mode=0.5"], ["mode=0.5", "choices", "0 (6d), 1 (9d)"]), (["mode=0.7"], ["mode=0.7"]),
    (["mode=nan"], ["finite"]), (["mode=6e"], ["not a number"]),
    (["mode=1", "mode=0"], ["mode", "twice"]),
])
def test_run_refuses_a_mode_that_is_not_a_choice(short_trial, tmp_path, params, words):
    out = tmp_path / "o.csv"
    args = ["run", "--filter", "flagship", "--impl", "ref", "--input", str(short_trial), "--out", str(out)]
    for p in params:
        args += ["--param", p]
    one_line_error(kf(*args), *words)
    assert not out.exists()


def test_run_takes_the_documented_mode_labels(short_trial, tmp_path):
    out = tmp_path / "o.csv"
    r = kf("run", "--filter", "flagship", "--impl", "f32", "--input", str(short_trial), "--out", str(out),
           "--param", "mode=6d")
    assert r.returncode == 0, r.stderr
    assert out.exists()


def test_run_refuses_the_mode_label_for_another_parameter(short_trial, tmp_path):
    r = kf("run", "--filter", "madgwick", "--impl", "ref", "--input", str(short_trial),
           "--out", str(tmp_path / "o.csv"), "--param", "beta=6d")
    one_line_error(r, "beta", "not a number")


def test_replay_refuses_a_mode_that_is_not_a_choice(short_trial, tmp_path):
    r = kf("replay", str(short_trial), "--filter", "flagship", "--out", str(tmp_path / "o.csv"),
           "--param", "mode=0.5")
    one_line_error(r, "mode=0.5", "choices")


@pytest.mark.parametrize("cmd", [["bench", "accuracy", "--filter", "flagship", "--jobs", "2"],
                                 ["bench", "bitexact", "--filter", "flagship", "--jobs", "2"],
                                 ["plot", "--filter", "flagship"]])
@pytest.mark.parametrize("param, word", [("mode=0.5", "choices"), ("tau_acc=0", "outside"),
                                         ("tau_ac=3", "no parameter")])
def test_bench_and_plot_refuse_bad_parameters_before_any_work(short_trial, tmp_path, cmd, param, word):
    where = ["--input", str(short_trial), "--out", str(tmp_path / "p.png")] if cmd[0] == "plot" \
        else ["--data", str(short_trial)]
    r = kf(*cmd, *where, "--param", param)
    one_line_error(r, word)


def test_bench_accuracy_competitor_takes_numbers_only(short_trial):
    r = kf("bench", "accuracy", "--filter", "vqf", "--data", str(short_trial), "--param", "tauAcc=6d")
    one_line_error(r, "tauAcc", "not a number")


def test_vqf_switches_take_0_or_1():
    from kinefuse.host import competitors
    with pytest.raises(KinefuseError, match="restBiasEstEnabled"):
        competitors._vqf_kwargs({**competitors._VQF_PARAMS, "restBiasEstEnabled": 0.5})
    assert competitors._vqf_kwargs(dict(competitors._VQF_PARAMS))["restBiasEstEnabled"] is True


# ---------------------------------------------------------------------- calibrate --range

@pytest.fixture
def poses(tmp_path):
    p = tmp_path / "poses.csv"
    p.write_text("0,0,9.8\n0,0,-9.8\n9.8,0,0\n-9.8,0,0\n0,9.8,0\n0,-9.8,0\n")
    return p


@pytest.mark.parametrize("ranges, words", [
    (["foo=3"], ["foo", "acc_g, gyr_dps, mag_uT"]),
    (["acc_g=nan"], ["finite"]), (["gyr_dps=inf"], ["finite"]), (["acc_g=-8"], ["positive"]),
    (["acc_g=8", "acc_g=16"], ["twice"]), (["acc_g"], ["NAME=VALUE"]), (["acc_g=x"], ["not a number"]),
])
def test_calibrate_range_is_checked(poses, tmp_path, ranges, words):
    out = tmp_path / "unit.json"
    args = ["calibrate", "accel", "--poses", str(poses), "--method", "full", "--out", str(out),
            "--serial", "7"]
    for r_ in ranges:
        args += ["--range", r_]
    r = kf(*args)
    one_line_error(r, *words)
    assert not out.exists()


def test_calibrate_range_is_stored(poses, tmp_path):
    import json
    out = tmp_path / "unit.json"
    r = kf("calibrate", "accel", "--poses", str(poses), "--method", "full", "--out", str(out),
           "--serial", "7", "--range", "acc_g=8", "--range", "gyr_dps=2000")
    assert r.returncode == 0, r.stderr
    assert json.loads(out.read_text())["sensor_ranges"] == {"acc_g": 8.0, "gyr_dps": 2000.0}
    r = kf("calibrate", "accel", "--poses", str(poses), "--method", "full", "--range", "acc_g=8")
    one_line_error(r, "--out")                                     # else it would be dropped


# --------------------------------------------------------------------------- params --set

@pytest.mark.parametrize("sets, words", [
    (["KF_RATE_HZ=nan"], ["finite"]),            # was an internal error (int(nan))
    (["KF_RATE_HZ=inf"], ["finite"]),
    (["KF_RATE_HZ=500", "KF_RATE_HZ=600"], ["twice"]),
    (["KF_RATE_HZ="], ["NAME=VALUE"]),
    (["KF_FL_MODE=0.5"], ["KF_FL_MODE", "choice", "0, 1"]),
    (["KF_JA_SEQUENCE=1.5"], ["KF_JA_SEQUENCE", "0, 1, 2"]),
])
def test_params_set_is_checked_before_writing(sets, words):
    args = ["params", "--port", "fake:rate=200"]
    for s in sets:
        args += ["--set", s]
    one_line_error(kf(*args, timeout=60), *words)


def test_encode_value_refuses_non_finite_integers():
    from kinefuse.host.link.params import ParamError, encode_value
    for v in (float("nan"), float("inf")):
        with pytest.raises(ParamError):
            encode_value(v, 3)
