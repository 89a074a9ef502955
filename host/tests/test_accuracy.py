"""``kinefuse bench accuracy`` end to end on the bundled excerpt, with a stand-in filter runner.

The stand-in filters have errors known by construction: ``perfect`` returns the reference,
``tilted`` the reference turned by ``deg`` (default 10°) about the earth's Up axis, so the
benchmark must report 0/0/0 and deg/deg/0 whatever the trial.
"""
import json
import math
import types

import numpy as np
import pytest

from kinefuse.host import broad, cli, competitors, metrics
from kinefuse.host.bench import accuracy
from kinefuse.host.errors import KinefuseError

EXCERPT = str(broad.EXCERPT_DIR)
NAMES = [p.stem for p in broad.bundled_trials()]


def _ref(trial):
    q = trial.quat_ref.copy()
    q[np.isnan(q).any(axis=1)] = [1.0, 0.0, 0.0, 0.0]  # filters never output NaN here
    return q


def fake_run_filter(name, impl, trial, params=None):
    params = params or {}
    if name == "perfect":
        q = _ref(trial)
    elif name == "tilted":
        if impl == "q":
            raise KinefuseError("no fixed-point build of tilted")
        h = math.radians(params.get("deg", 10.0)) / 2
        q = metrics.quat_mul([math.cos(h), 0.0, 0.0, math.sin(h)], _ref(trial))
    elif name == "nanny":
        q = _ref(trial)
        q[np.flatnonzero(trial.movement)[5]] = np.nan
    elif name == "shapeless":
        q = np.zeros((3, 4))
    else:
        raise KinefuseError(f"unknown filter {name!r}")
    return types.SimpleNamespace(q=q, status={"rest": ~trial.movement})


FAKE = types.SimpleNamespace(
    filter_names=lambda: ["perfect", "tilted", "nanny", "shapeless", "anglefilter"],
    imu_filter_names=lambda: ["perfect", "tilted", "nanny", "shapeless"],
    default_filter=lambda: "perfect",
    run_filter=fake_run_filter)


@pytest.fixture
def kf(monkeypatch, capsys):
    """Run the CLI with only this part's commands and the stand-in runner."""
    monkeypatch.setattr(accuracy, "load_runner", lambda: FAKE)
    monkeypatch.setattr(cli, "COMMAND_MODULES", ["kinefuse.host.commands.demo_cmd",
                                                 "kinefuse.host.commands.plot_cmd"])
    monkeypatch.setattr(cli, "BENCH_MODULES", ["kinefuse.host.bench.accuracy"])
    monkeypatch.delenv("KINEFUSE_BROAD", raising=False)

    def run(*argv):
        try:
            code = cli.main(list(argv))
        except SystemExit as exc:  # argparse errors
            code = exc.code
        out, err = capsys.readouterr()
        return code, out, err
    return run


def test_json_exact_shape_and_known_errors(kf):
    code, out, err = kf("bench", "accuracy", "--data", EXCERPT, "--filter", "tilted",
                        "--jobs", "1", "--json")
    assert code == 0, err
    assert len(out.strip().splitlines()) == 1
    d = json.loads(out)
    assert set(d) == {"filter", "impl", "trials", "groups", "mean", "units"} and d["units"].startswith("deg: RMSE")
    # the group means (one excerpt trial per group here), as the tables give them
    assert set(d["groups"]) == {"rotation", "translation", "tapping", "attached_magnet"}
    assert d["groups"]["tapping"] == d["trials"]["24_disturbed_tapping_A"]
    assert (d["filter"], d["impl"]) == ("tilted", "ref")
    assert list(d["trials"]) == NAMES
    for s in list(d["trials"].values()) + [d["mean"]]:
        assert set(s) == {"total", "heading", "inclination"}
        assert s["total"] == pytest.approx(10.0, abs=1e-6)
        assert s["heading"] == pytest.approx(10.0, abs=1e-6)
        assert s["inclination"] == pytest.approx(0.0, abs=1e-5)
    assert "data: 4 trial file(s)" in err


def test_params_and_impl_reach_the_filter(kf):
    code, out, err = kf("bench", "accuracy", "--data", EXCERPT, "--filter", "tilted",
                        "--param", "deg=20", "--impl", "f32", "--json", "--jobs", "1")
    assert code == 0, err
    d = json.loads(out)
    assert d["impl"] == "f32" and d["mean"]["heading"] == pytest.approx(20.0, abs=1e-6)


def test_compare_naming_no_filter_is_refused(kf):
    """--compare ',' was accepted and ignored: the run scored the main filter alone."""
    for arg in (",", "", " , "):
        code, out, err = kf("bench", "accuracy", "--data", EXCERPT, "--filter", "tilted", "--compare", arg,
                            "--jobs", "1", "--json")
        assert code == 2 and out == "" and err.count("\n") == 1, (code, out, err)
        assert err.startswith("kinefuse: error: --compare") and "names no filter" in err, err


def test_compare_side_by_side_in_parallel(kf):
    comps = [c for c in ("vqf", "imufusion") if competitors.available(c)]
    if not comps:
        pytest.skip("neither vqf nor imufusion installed")
    one = broad.bundled_trials()[-1]
    code, out, err = kf("bench", "accuracy", "--data", str(one.parent), "--filter", "perfect",
                        "--compare", ",".join(["tilted"] + comps), "--json", "--jobs", "2")
    assert code == 0, err
    d = json.loads(out)
    assert set(d) == {"filter", "impl", "trials", "groups", "mean", "compare", "units"}
    # each competitor's settings are stated with its scores
    for c in comps:
        assert d["compare"][c]["settings"] == competitors.get(c).description
        assert d["compare"][c]["params"] == competitors.get(c).params
    # acos near 1 resolves ~1e-6°: the published formula's floor, far below any real error
    assert d["mean"] == pytest.approx({"total": 0.0, "heading": 0.0, "inclination": 0.0}, abs=1e-5)
    assert set(d["compare"]) == {"tilted", *comps}
    assert d["compare"]["tilted"]["mean"]["total"] == pytest.approx(10.0, abs=1e-6)
    # the worker processes scored the right trial with the right competitor
    trial = broad.load_trial(one)
    direct = metrics.score_trial(competitors.run_competitor(comps[0], trial).q, trial)
    assert d["compare"][comps[0]]["trials"][trial.name] == pytest.approx(direct, rel=1e-12)


def test_filter_all_uses_imu_filters(kf):
    code, out, err = kf("bench", "accuracy", "--data", str(broad.bundled_trials()[0]),
                        "--filter", "all", "--json", "--jobs", "1")
    # 'shapeless' returns the wrong shape: the whole run must fail with one line
    assert code == 2 and "shapeless (ref) returned quaternions of shape (3, 4)" in err
    assert err.count("kinefuse: error:") == 1 and "Traceback" not in err
    assert "nanny (ref) produced NaN" in err  # filters before it did run


def test_filter_all(kf, monkeypatch):
    monkeypatch.setattr(FAKE, "imu_filter_names", lambda: ["perfect", "tilted"])
    code, out, err = kf("bench", "accuracy", "--data", str(broad.bundled_trials()[0]),
                        "--filter", "all", "--json", "--jobs", "2")
    assert code == 0, err
    d = json.loads(out)
    assert d["filter"] == "all" and set(d["filters"]) == {"perfect", "tilted"}
    assert d["filters"]["tilted"]["mean"]["heading"] == pytest.approx(10.0, abs=1e-6)


def test_nan_estimate_is_reported(kf):
    code, out, err = kf("bench", "accuracy", "--data", EXCERPT, "--filter", "nanny", "--json",
                        "--jobs", "1")
    assert code == 0
    d = json.loads(out)
    assert all(v["total"] is None for v in d["trials"].values()) and d["mean"]["total"] is None
    assert "nanny (ref) produced NaN quaternions" in err


def test_tables(kf):
    code, out, err = kf("bench", "accuracy", "--data", EXCERPT, "--filter", "tilted",
                        "--compare", "perfect", "--jobs", "1")
    assert code == 0, err
    for title in ("undisturbed rotation", "undisturbed translation", "tapping",
                  "attached magnet", "summary", "all trials (4)"):
        assert title in out
    assert "10.00 / 10.00 / 0.00" in out and "0.00 / 0.00 / 0.00" in out
    assert "tilted (ref)" in out and "perfect (ref)" in out


def test_default_data_is_named(kf, monkeypatch):
    monkeypatch.setattr(broad, "shared_broad_dir", lambda: None)
    code, out, err = kf("bench", "accuracy", "--filter", "perfect", "--json", "--jobs", "1")
    assert code == 0
    assert "bundled BROAD excerpt" in err and "not comparable" in err
    assert list(json.loads(out)["trials"]) == NAMES


@pytest.mark.parametrize("argv, message", [
    (["--filter", "nosuch"], "unknown filter 'nosuch'"),
    (["--filter", "anglefilter"], "unknown filter 'anglefilter'"),
    (["--filter", "perfect", "--compare", "vqf,nosuch"], "unknown filter 'nosuch'"),
    (["--filter", "perfect", "--param", "beta"], "--param expects KEY=NUMBER"),
    (["--filter", "perfect", "--param", "beta=abc"], "'abc' is not a number"),
    (["--filter", "perfect", "--data", "/nonexistent/broad"], "no such file or directory"),
    (["--filter", "perfect", "--jobs", "0"], "--jobs must be at least 1"),
    (["--filter", "perfect", "--impl", "f64"], "invalid choice"),
    (["--filter", "vqf", "--param", "gain=0.1"], "vqf: unknown parameter gain"),
    (["--filter", "tilted", "--impl", "q"], "no fixed-point build of tilted"),
])
def test_bad_arguments_give_one_line(kf, argv, message):
    if "vqf" in argv[1] + " ".join(argv) and not competitors.available("vqf"):
        pytest.skip("vqf not installed")
    code, out, err = kf("bench", "accuracy", "--data", EXCERPT, "--jobs", "1", *argv)
    assert code == 2
    assert message in err
    assert len(err.strip().splitlines()) <= 2 and "Traceback" not in err
    assert out == ""


def test_unreadable_trial_file(kf, tmp_path):
    bad = tmp_path / "01_x.mat"
    bad.write_bytes(b"garbage" * 100)
    code, out, err = kf("bench", "accuracy", "--data", str(tmp_path), "--filter", "perfect",
                        "--jobs", "1")
    assert code == 2 and "01_x.mat: not a readable MATLAB file" in err


def test_runner_missing(monkeypatch, kf):
    def missing():
        raise KinefuseError("kinefuse filters are not available (no module)")
    monkeypatch.setattr(accuracy, "load_runner", missing)
    code, out, err = kf("bench", "accuracy", "--data", EXCERPT, "--jobs", "1")
    assert code == 2 and "kinefuse filters are not available" in err
    if competitors.available("vqf"):
        code, out, err = kf("bench", "accuracy", "--data", str(broad.bundled_trials()[0]),
                            "--filter", "vqf", "--json", "--jobs", "1")
        assert code == 0 and json.loads(out)["filter"] == "vqf"


def test_6d_kinefuse_filter_heading_is_flagged(kf, monkeypatch):
    # a kinefuse filter run with mode=6d had its heading scored against north without a word
    # (only 6D competitors got the note)
    six = types.SimpleNamespace(**vars(FAKE), check_params=lambda name, p: {
        "mode": 0.0 if p.get("mode") in ("6d", 0.0) else 1.0, **{k: v for k, v in p.items() if k != "mode"}})
    monkeypatch.setattr(accuracy, "load_runner", lambda: six)
    one = str(broad.bundled_trials()[0])
    code, out, err = kf("bench", "accuracy", "--data", one, "--filter", "perfect", "--param", "mode=6d",
                        "--jobs", "1")
    assert code == 0, err
    assert "perfect (ref) estimate heading without a magnetometer" in " ".join(out.split())
    code, out, err = kf("bench", "accuracy", "--data", one, "--filter", "perfect", "--param", "mode=6d",
                        "--jobs", "1", "--json")
    assert code == 0, err
    assert json.loads(out)["heading_referenced"] is False
    assert json.loads(out)["params"] == {"mode": 0.0}      # what it ran with, resolved
    code, out, err = kf("bench", "accuracy", "--data", one, "--filter", "perfect", "--jobs", "1")
    assert code == 0 and "without a magnetometer" not in out


def test_excerpt_named_with_data_is_flagged(kf):
    # the "not comparable with full-trial figures" note came for the default data only
    code, out, err = kf("bench", "accuracy", "--data", EXCERPT, "--filter", "perfect", "--jobs", "1",
                        "--json")
    assert code == 0, err
    assert "excerpt scores are not comparable" in err


def test_a_trial_twice_in_the_folder_is_refused(kf, tmp_path):
    # 01.mat and 01.npz: the second's scores replaced the first's, one trial fewer, no word
    import shutil
    src = broad.bundled_trials()[0]
    shutil.copy(src, tmp_path / src.name)
    (tmp_path / f"{src.stem}.mat").write_bytes(b"")
    code, out, err = kf("bench", "accuracy", "--data", str(tmp_path), "--filter", "perfect", "--jobs", "1")
    assert code == 2 and out == "" and err.count("\n") == 1, err
    assert "the same trial" in err and src.stem in err
