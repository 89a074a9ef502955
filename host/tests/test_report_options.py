"""`kinefuse report` and `kinefuse calibrate` options through the real CLI: functional
calibration (--calib-functional), static-detection thresholds in the report, the filter named in
the Processing section, the cycle-rejection threshold stated as given, strict JSON from
`calibrate gyro --rate-windows`, and reflections refused alike with and without --out."""
import json

import numpy as np
import pytest

from kinefuse.host.kinematics import quat as Q
from kinefuse.host.kinematics import simulate
from kinefuse.host.readers import kinefuse_csv
from kinefuse.host.readers.recording import Recording


MINE = ("calibrate_cmd", "report_cmd")


def _squats(P, rng):
    """Functional trial: 4 squats (knee 0-80 deg, hip 0-40 deg, both about the segments' X)."""
    return simulate.squats(P.q_SB, rng=rng)


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("knee-options")
    P = simulate.knee_protocol(seed=3, n_cycles=5)
    sq = _squats(P, np.random.default_rng(103))
    for seg in ("thigh", "shank"):
        for task, rec in (("step", P.task), ("stand", P.standing), ("fig8", P.mag), ("squat", sq)):
            kinefuse_csv.write(str(d / f"{task}-{seg}.csv"), rec[seg])
    return d, P


def _knee(d, *extra):
    return ["report", "knee", "--thigh", d / "step-thigh.csv", "--shank", d / "step-shank.csv",
            "--mag-cal", d / "fig8-thigh.csv", d / "fig8-shank.csv", "--field-norm", 22.6, *extra]


def test_functional_calibration_in_the_knee_report(run, files):
    d, P = files
    out = d / "func"
    code, stdout, err = run(*_knee(d, "--calib-standing", d / "stand-thigh.csv", d / "stand-shank.csv",
                                   "--calib-functional", d / "squat-thigh.csv", d / "squat-shank.csv",
                                   "--max-cycle-rmse", 7.5, "--out", out, "--json"))
    assert code == 0, err
    s = json.loads(stdout)
    assert s["processing"]["alignment"].startswith("functional")
    assert s["inputs"]["functional"].endswith("squat-shank.csv")
    ts = np.loadtxt(out / "knee_timeseries.csv", delimiter=",", comments="#", skiprows=2)
    e = ts[:, 1:4] - P.truth.angles_deg[: len(ts)]
    rmse = np.sqrt((e ** 2).mean(axis=0))
    assert rmse[0] <= 2.0 and rmse[1] <= 3.0 and rmse[2] <= 3.0, rmse      # the figures
    # without any calibration the 10° mounting error shows (the functional one did the work)
    code, stdout, err = run(*_knee(d, "--out", d / "nocal", "--json"))
    ts0 = np.loadtxt(d / "nocal" / "knee_timeseries.csv", delimiter=",", comments="#", skiprows=2)
    e0 = ts0[:, 1:4] - P.truth.angles_deg[: len(ts0)]
    assert np.sqrt((e0[:, 1] ** 2).mean()) > 2 * rmse[1]
    # Markdown: the filter is named, and the threshold is the one given
    md = (out / "knee_summary.md").read_text()
    assert "filter 'flagship'" in md and "custom" not in md
    assert "> 7.5° RMS" in md and "> 10° RMS" not in md
    assert s["max_cycle_rmse_deg"] == 7.5


def test_functional_calibration_errors(run, files):
    d, _ = files
    code, _, err = run(*_knee(d, "--calib-functional", d / "squat-thigh.csv", d / "squat-shank.csv", "--out", d / "x"))
    assert code == 2 and "needs --calib-standing" in err and err.count("\n") == 1
    code, _, err = run(*_knee(d, "--calib-standing", d / "stand-thigh.csv", d / "stand-shank.csv",
                              "--calib-functional", d / "stand-thigh.csv", d / "stand-shank.csv", "--out", d / "x"))
    assert code == 2 and "stand-thigh.csv: thigh functional calibration" in err and err.count("\n") == 1


def test_static_thresholds_reach_the_report(run, files):
    d, _ = files
    args = _knee(d, "--calib-standing", d / "stand-thigh.csv", d / "stand-shank.csv",
                 "--calib-functional", d / "squat-thigh.csv", d / "squat-shank.csv", "--out", d / "st")
    code, _, err = run(*args, "--min-duration", 60)          # the standing recordings last 10 s
    assert code == 2 and err.count("\n") == 1
    assert "static window" in err and "still ≥ 60 s" in err, err
    code, _, err = run(*args, "--acc-std-max", 0)
    assert code == 2 and "acc_std_max must be positive" in err


def test_gyro_rate_windows_json_is_strict(run, tmp_path):
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
    (tmp_path / "rates.csv").write_text("\n".join(",".join(str(x) for x in (a + 0.5, e - 0.5, *v))
                                                  for a, e, v in spans) + "\n")
    code, out, err = run("calibrate", "gyro", "--input", tmp_path / "turntable.csv",
                         "--rate-windows", tmp_path / "rates.csv", "--json")
    assert code == 0, err

    def no_constants(c):
        raise AssertionError(f"{c} is not JSON")
    obj = json.loads(out, parse_constant=no_constants)
    assert obj["method"] == "known-rates" and obj["window_spread"] is None
    np.testing.assert_allclose(obj["bias"], b, atol=3e-3)


def test_reflection_refused_with_and_without_out(run, tmp_path):
    from kinefuse.host.tests.test_calib_cli import RAW, TARGETS
    (tmp_path / "p.csv").write_text(RAW)
    mirrored = "\n".join(",".join(str(-float(v)) if j == 0 else v for j, v in enumerate(line.split(",")))
                         for line in TARGETS.strip().splitlines()) + "\n"
    (tmp_path / "t.csv").write_text(mirrored)                 # x axis of the targets flipped
    base = ["calibrate", "accel", "--poses", tmp_path / "p.csv", "--targets", tmp_path / "t.csv", "--method", "ls"]
    errs = []
    for extra in (["--json"], ["--out", tmp_path / "u.json", "--serial", "7"]):
        code, out, err = run(*base, *extra)
        assert code == 2 and out == "" and err.count("\n") == 1, (code, out, err)
        assert "a reflection" in err and "det = -0.99" in err, err
        errs.append(err)
    assert errs[0] == errs[1] and not (tmp_path / "u.json").exists()


@pytest.mark.parametrize("extra, text", [
    (["--drop-edge-cycles", "-1"], "--drop-edge-cycles -1: must be 0 or more"),   # reported 1 of 1 cycles
    (["--max-cycle-rmse", "nan"], "--max-cycle-rmse nan: must be a positive"),    # kept 2 of 5 silently
    (["--max-cycle-rmse", "0"], "--max-cycle-rmse 0: must be a positive"),
    (["--filter", "flagsip"], "use a kinefuse IMU filter (madgwick"),            # listed only 'simple'
    (["--orientation", "device", "--filter", "madgwick"],                          # --filter ignored
     "--filter madgwick: not used with --orientation device"),
])
def test_bad_cycle_and_filter_options_are_refused(run, files, extra, text):
    d, _ = files
    out = d / f"bad{abs(hash(tuple(extra)))}"
    code, stdout, err = run(*_knee(d, *extra, "--out", out))
    assert code == 2 and stdout == "" and err.count("\n") == 1, (code, err)
    assert err.startswith("kinefuse: error:") and text in err, err
    assert not out.exists()


@pytest.mark.parametrize("extra", [["--max-cycle-rmse", "1.5"],
                                   ["--drop-edge-cycles", "1", "--max-cycle-rmse", "1"]])
def test_cycle_numbers_agree_between_summary_and_csvs(run, files, extra):
    """The CSVs renumbered the kept cycles 1..n while the summary named the rejected ones by their
    detected number (kept 1 and 5 were written as 1 and 2, 'rejected cycle 2' was another cycle),
    and --drop-edge-cycles lowered 'detected' to the cycles left after dropping, unmentioned."""
    d, _ = files
    out = d / f"num{len(extra)}"
    code, stdout, err = run(*_knee(d, *extra, "--out", out, "--json"))
    assert code == 0, err
    s = json.loads(stdout)
    drop = 1 if "--drop-edge-cycles" in extra else 0
    assert s["n_cycles_detected"] == 5 and s["n_edge_cycles_dropped"] == 2 * drop
    rejected = {r["cycle"] for r in s["rejected_cycles"]}
    assert rejected and s["n_cycles_kept"] == 5 - 2 * drop - len(rejected)
    ts = np.loadtxt(out / "knee_timeseries.csv", delimiter=",", comments="#", skiprows=2)
    cyc = np.loadtxt(out / "knee_cycles.csv", delimiter=",", comments="#", skiprows=2)
    kept = set(np.unique(ts[:, 4]).astype(int)) - {-1}
    assert kept == set(np.unique(cyc[:, 0]).astype(int))
    assert len(kept) == s["n_cycles_kept"] and not kept & rejected
    assert kept | rejected == set(range(1 + drop, 6 - drop))
    md = (out / "knee_summary.md").read_text()
    assert f"- detected: 5, kept: {s['n_cycles_kept']}" in md
    assert ("edge cycles dropped: 1 at each end" in md) == bool(drop)


@pytest.mark.parametrize("cmd", [["report", "elbow", "--arm", "{d}/a.csv", "--forearm", "{d}/b.csv", "--out", "{d}/o"],
                                 ["calibrate", "gyro", "--input", "{d}/a.csv"]])
@pytest.mark.parametrize("fs", ["0", "-100", "nan", "inf"])
def test_bad_sampling_rate_is_a_usage_error(run, capsys, tmp_path, cmd, fs):
    """--fs 0 was taken as 'not given' (a MATRIX file was timed at its default 100 Hz without a
    word) and a negative, NaN or infinite rate reached the readers."""
    with pytest.raises(SystemExit) as exc:
        run(*[a.format(d=tmp_path) for a in cmd], f"--fs={fs}")
    out, err = capsys.readouterr()
    assert exc.value.code == 2 and out == "" and err.count("\n") == 1, (out, err)
    assert err.startswith("kinefuse: error: argument --fs:") and "is not in (0, inf]" in err, err
