"""`kinefuse filters | run | codegen | bench bitexact | bench speed` as a user calls them."""
from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

from kinefuse.host import broad


def kf(*args, timeout=600):
    return subprocess.run([sys.executable, "-m", "kinefuse.host.cli", *args], capture_output=True,
                          text=True, timeout=timeout)


@pytest.fixture(scope="module")
def short_trial(tmp_path_factory):
    """A 20 s cut of a bundled trial, saved in the bundled format."""
    t = broad.load_trial(broad.bundled_trials()[0])
    src = np.load(broad.bundled_trials()[0])
    path = tmp_path_factory.mktemp("data") / f"{t.name}.npz"
    n = int(20 * t.rate_hz)
    np.savez(path, **{k: (v[:n] if getattr(v, "ndim", 0) and len(v) == t.n else v)
                      for k, v in src.items()})
    return path


def test_filters_lists_parameters_with_units_and_defaults():
    r = kf("filters", "--json")
    assert r.returncode == 0, r.stderr
    info = json.loads(r.stdout)
    for name in ("madgwick", "mahony", "complementary"):
        p = info[name]["params"]
        assert p and all({"name", "default", "unit", "min", "max", "doc"} <= set(x) for x in p)
    assert info["madgwick"]["presets"]["seed001"]["beta"] == 0.03


def test_filters_names_one_filter_or_gives_one_line():
    """`kinefuse filters guo` was 'unrecognized arguments'."""
    r = kf("filters", "--json", "guo", "vac", "guo")
    assert r.returncode == 0, r.stderr
    assert list(json.loads(r.stdout)) == ["guo", "vac"]
    r = kf("filters", "guo")
    assert r.returncode == 0 and "guo — " in r.stdout and "madgwick" not in r.stdout, r.stdout
    r = kf("filters", "gou")
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "unknown filter 'gou'" in r.stderr, r.stderr


def test_run_writes_one_row_per_sample(short_trial, tmp_path):
    out = tmp_path / "est.csv"
    r = kf("run", "--filter", "madgwick", "--impl", "q", "--input", str(short_trial), "--out", str(out))
    assert r.returncode == 0, r.stderr
    lines = out.read_text().splitlines()
    assert lines[0].startswith("#") and lines[1] == "t,w,x,y,z"
    data = np.loadtxt(out, delimiter=",", skiprows=2)
    t = broad.load_trial(short_trial)
    assert data.shape == (t.n, 5)
    assert np.allclose(np.linalg.norm(data[:, 1:], axis=1), 1.0, atol=1e-3)


def test_run_points_a_unit_recording_to_replay(tmp_path):
    """`run` takes BROAD trials; a .kfr or a vendor CSV got "unsupported trial format '.kfr'"."""
    rec = tmp_path / "walk.kfr"
    rec.write_bytes(b"\x00" * 64)
    dot = tmp_path / "dot.csv"
    dot.write_text("PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z\n")
    for path, what in ((rec, "a kinefuse unit recording (.kfr)"), (dot, "an Xsens DOT export")):
        r = kf("run", "--filter", "vac", "--input", str(path), "--out", str(tmp_path / "o.csv"))
        assert r.returncode == 2 and r.stderr.count("\n") == 1, r.stderr
        assert f"{path} is {what}; run takes a BROAD trial: use kinefuse replay {path} --out " \
               f"{tmp_path / 'o.csv'} --filter vac" in r.stderr
    assert not (tmp_path / "o.csv").exists()


def test_run_replay_hint_carries_the_options(tmp_path, capsys):
    """The suggested `kinefuse replay` dropped --impl/--param/--preset/--status: pasted, it
    computed something else. Parsed back, it must ask replay for what run was asked."""
    import shlex
    from kinefuse.host import cli
    d = tmp_path / "my data"
    d.mkdir()
    dot = d / "dot export.csv"
    dot.write_text("PacketCounter,SampleTimeFine,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z\n")
    out = d / "est 1.csv"
    argv = ["run", "--filter", "madgwick", "--impl", "q", "--preset", "seed001", "--param",
            "beta=0.05", "--param", "zeta=0.01", "--status", "--frame", "ned", "--input",
            str(dot), "--out", str(out)]
    assert cli.main(argv) == 2
    err = capsys.readouterr().err
    assert "use kinefuse replay " in err, err
    words = shlex.split(err.split("use ", 1)[1].strip())
    assert words[:2] == ["kinefuse", "replay"]
    replay = cli.build_parser().parse_args(words[1:])
    run = cli.build_parser().parse_args(argv)
    assert replay.rec == str(dot) and replay.out == str(out)
    for opt in ("filter", "impl", "preset", "param", "status", "frame", "force"):
        assert getattr(replay, opt) == getattr(run, opt), opt
    assert not out.exists()


@pytest.mark.parametrize("args,needle", [
    (["run", "--filter", "nope", "--input", "x.mat", "--out", "o.csv"], "unknown filter"),
    (["run", "--filter", "madgwick", "--input", "/does/not/exist.mat", "--out", "o.csv"], "exist"),
    (["run", "--filter", "madgwick", "--param", "beta=abc", "--input", "x", "--out", "o"], ""),
    (["run", "--filter", "madgwick", "--impl", "float", "--input", "x", "--out", "o"], "invalid choice"),
    (["bench", "bitexact", "--filter", "nope"], "unknown filter"),
])
def test_bad_input_gives_one_line_error(args, needle, short_trial):
    if "--input" in args and args[args.index("--input") + 1] == "x":
        args[args.index("--input") + 1] = str(short_trial)
    r = kf(*args)
    assert r.returncode == 2
    assert "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert needle in r.stderr


def test_parameter_out_of_range_is_refused(short_trial, tmp_path):
    r = kf("run", "--filter", "madgwick", "--param", "beta=99", "--input", str(short_trial),
           "--out", str(tmp_path / "o.csv"))
    assert r.returncode == 2 and "beta" in r.stderr and "Traceback" not in r.stderr


def test_codegen_check_passes_on_committed_files():
    r = kf("codegen", "--check")
    assert r.returncode == 0, r.stderr


def test_codegen_check_honours_filter(tmp_path, monkeypatch, capsys):
    # --filter was ignored by --check: every filter was checked and an unknown name passed
    from kinefuse.codegen import generate
    from kinefuse.host import cli
    assert cli.main(["codegen", "--check", "--filter", "nosuch"]) == 2
    assert "unknown filter 'nosuch'" in capsys.readouterr().err
    monkeypatch.setattr(generate, "GENERATED_DIR", tmp_path)     # nothing generated there
    assert cli.main(["codegen", "--check", "--filter", "madgwick"]) == 1
    err = capsys.readouterr().err
    assert "madgwick_f32.c" in err and "madgwick_q.c" in err and "flagship" not in err


def test_bench_bitexact_json(short_trial):
    r = kf("bench", "bitexact", "--data", str(short_trial), "--filter", "complementary", "--json")
    assert r.returncode == 0, r.stderr
    res = json.loads(r.stdout)
    assert res["filter"] == "complementary"
    for system in ("f32", "q"):
        assert set(res[system]) == {"samples", "differing", "rms_deg", "max_deg"}
        assert res[system]["differing"] == 0 and res[system]["samples"] > 5000


def test_bench_speed_json(short_trial):
    r = kf("bench", "speed", "--data", str(short_trial), "--filter", "madgwick", "--repeat", "1",
           "--model-samples", "300", "--json")
    assert r.returncode == 0, r.stderr
    sps = json.loads(r.stdout)["samples_per_s"]
    assert set(sps) == {"f32_c", "f32_model", "q_c", "q_model", "ref", "imufusion", "vqf"}
    assert sps["f32_c"] > sps["f32_model"] > 0


def test_bench_speed_instruction_counts_are_deterministic(short_trial):
    """--instructions: valgrind counts inside the three batch functions (ours, Fusion, VQF); the
    same count twice."""
    runs = []
    for _ in range(2):
        r = kf("bench", "speed", "--data", str(short_trial), "--filter", "complementary",
               "--repeat", "1", "--model-samples", "100", "--instructions", "--json")
        assert r.returncode == 0, r.stderr
        runs.append(json.loads(r.stdout)["instructions_per_sample"])
    assert runs[0] == runs[1]
    assert set(runs[0]) == {"f32_c", "imufusion", "vqf"}
    # a 9D update is hundreds of instructions, not a handful (a wrong function) nor 10^5
    assert all(100 < v < 5000 for v in runs[0].values()), runs[0]


def test_run_writes_ned_on_request(short_trial, tmp_path):
    """--frame ned: the same orientation with the earth axes swapped (x North, y East, z Down):
    the earth-frame images of the sensor axes must be the ENU ones with x<->y and z negated."""
    from kinefuse.host.kinematics import quat as Q
    outs = {}
    for frame in ("enu", "ned"):
        out = tmp_path / f"{frame}.csv"
        r = kf("run", "--input", str(short_trial), "--out", str(out), "--frame", frame)
        assert r.returncode == 0, r.stderr
        assert ("earth frame " + frame.upper()) in out.read_text().splitlines()[0]
        outs[frame] = np.loadtxt(out, delimiter=",", skiprows=2)[:, 1:5]
    r_enu, r_ned = Q.to_matrix(outs["enu"]), Q.to_matrix(outs["ned"])
    swap = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])
    assert np.allclose(swap @ r_enu, r_ned, atol=1e-6)
    assert np.all(outs["ned"][:, 0] >= 0)


def test_bench_bitexact_no_ref_compares_bits_only(short_trial):
    r = kf("bench", "bitexact", "--data", str(short_trial), "--filter", "vac", "--no-ref", "--json")
    assert r.returncode == 0, r.stderr
    res = json.loads(r.stdout)
    for system in ("f32", "q"):
        assert res[system]["differing"] == 0 and res[system]["samples"] > 5000
        assert res[system]["rms_deg"] is None and res[system]["max_deg"] is None


@pytest.mark.parametrize("opt, text", [(["--repeat", "0"], "--repeat 0: must be at least 1"),
                                       (["--model-samples", "0"], "--model-samples 0: must be"),
                                       (["--model-samples", "-5"], "--model-samples -5: must be")])
def test_bench_speed_refuses_non_positive_counts(short_trial, opt, text):
    """--repeat 0 printed '-' for Fusion and VQF and exit 0; --model-samples 0 was an internal
    error, -5 timed all but the last 5 samples."""
    r = kf("bench", "speed", "--data", str(short_trial), "--filter", "madgwick", *opt)
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and text in r.stderr, r.stderr


def test_run_ned_status_columns_follow_the_frame(short_trial, tmp_path):
    """--frame ned --status wrote q6/q9 (flagship) and cov_att (eskf) still in ENU under a
    header saying NED, and the status columns' units were nowhere in the file."""
    from kinefuse.host.kinematics import quat as Q
    swap = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])
    cols = {}
    for filt in ("flagship", "eskf"):
        for frame in ("enu", "ned"):
            out = tmp_path / f"{filt}-{frame}.csv"
            r = kf("run", "--filter", filt, "--input", str(short_trial), "--out", str(out), "--frame",
                   frame, "--status")
            assert r.returncode == 0, r.stderr
            comment, header = out.read_text().splitlines()[:2]
            cols[filt, frame] = dict(zip(header.split(","), np.loadtxt(out, delimiter=",", skiprows=2).T))
            cols[filt, frame]["#"] = comment
    for frame in ("enu", "ned"):
        c = cols["flagship", frame]
        assert "bias rad/s" in c["#"] and "rejected samples" in c["#"]
        assert f"q6, q9 sensor->{frame.upper()}" in c["#"]
    for k in ("q6", "q9"):
        q_enu = np.column_stack([cols["flagship", "enu"][f"{k}_{i}"] for i in range(4)])
        q_ned = np.column_stack([cols["flagship", "ned"][f"{k}_{i}"] for i in range(4)])
        assert np.allclose(swap @ Q.to_matrix(q_enu), Q.to_matrix(q_ned), atol=1e-6)
    e, n = cols["eskf", "enu"], cols["eskf", "ned"]
    assert "cov_att rad^2" in n["#"] and "cov_att in the NED frame" in n["#"]
    idx = [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]

    def full(c):
        P = np.zeros((len(c["t"]), 3, 3))
        for m, (i, j) in enumerate(idx):
            P[:, i, j] = P[:, j, i] = c[f"cov_att_{m}"]
        return P
    P_enu, P_ned = full(e), full(n)
    assert np.abs(P_enu[:, 0, 2]).max() > 0                    # not a diagonal covariance throughout
    np.testing.assert_allclose(swap @ P_enu @ swap.T, P_ned, rtol=0, atol=1e-12)


@pytest.mark.parametrize("cmd", [["plot", "--input", "{trial}", "--out", "{out}"],
                                 ["bench", "accuracy", "--data", "{trial}"]])
def test_impl_for_a_competitor_is_refused_not_ignored(cmd, short_trial, tmp_path):
    """--filter vqf --impl q ran VQF's own implementation and said nothing."""
    args = [a.format(trial=short_trial, out=tmp_path / "p.png") for a in cmd]
    r = kf(*args, "--filter", "vqf", "--impl", "q")
    assert r.returncode == 2 and r.stderr.count("\n") == 1 \
        and "vqf is a competitor and runs its own implementation" in r.stderr, r.stderr


def test_run_writes_a_simulator_mat_s_own_sample_times(tmp_path):
    """run wrote t = index / rate for a simulator .mat with jitter, drops and a 0.5 s gap (1.26 s
    off at the end) while its filter already ran on the file's own times (as replay writes)."""
    from kinefuse.hil_tests import sim
    rec = sim.simulate("jitter_and_drops", seed=0, duration_s=25.0)
    rec.save(str(tmp_path / "j.mat"))
    out = tmp_path / "j.csv"
    r = kf("run", "--filter", "madgwick", "--input", str(tmp_path / "j.mat"), "--out", str(out))
    assert r.returncode == 0, r.stderr
    x = np.loadtxt(out, delimiter=",", skiprows=2)
    assert np.allclose(x[:, 0], rec.t, rtol=0, atol=1e-6) and x[-1, 0] > 24.9


def test_an_empty_output_folder_is_refused():
    """check_output_dir("") was the current folder (export and report guarded it themselves)."""
    from kinefuse.host.errors import KinefuseError
    from kinefuse.host.outputs import check_output_dir
    for empty in ("", "  "):
        with pytest.raises(KinefuseError, match="--out is empty"):
            check_output_dir(empty, force=True)
