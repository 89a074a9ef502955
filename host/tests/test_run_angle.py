"""``kinefuse run`` with the seed-004 joint-angle smoothers: seed-004 Arduino CSV and plain
``t,angle_deg`` CSV in, ``t,angle_deg,rate_deg_s[,omega_rad_s]`` out, wrong input kinds refused."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.host import angle_series, cli
from kinefuse.host.broad import EXCERPT_DIR

MINE = ("run_cmd", "replay_cmd")
TRIAL = EXCERPT_DIR / "24_disturbed_tapping_A.npz"
FILTERS = ("angle-kf", "angle-ekf", "angle-ukf", "angle-srukf")
FS = 35.0


def _one_line_error(code, out, err, text):
    assert code == 2, (code, out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("kinefuse: error:") and text in lines[0], err


def _csv(path):
    with open(path) as f:
        comment = f.readline()
        header = f.readline().strip().split(",")
    return comment, header, np.loadtxt(path, delimiter=",", skiprows=2, ndmin=2)


def _sine(n=420, omega=5.0, noise_deg=1.8, seed=3):
    rng = np.random.default_rng(seed)
    t = np.arange(n) / FS
    truth = 20.0 * np.sin(omega * t + 0.4)
    return t, truth, truth + rng.normal(0.0, noise_deg, n)


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    """The same measured angles as a seed-004 Arduino CSV (RAW column; the UKF/EKF columns are
    deliberately different) and as a plain t,angle_deg CSV."""
    d = tmp_path_factory.mktemp("angle")
    t, truth, z = _sine()
    s004 = d / "servo.csv"
    with open(s004, "w") as f:
        for v in z:
            f.write(f"{v:.4f},{-v:.4f},0.0\n")
    plain = d / "plain.csv"
    with open(plain, "w") as f:
        f.write("# a comment line\nt,angle_deg,extra\n")
        for tt, v in zip(t, np.round(z, 4)):
            f.write(f"{float(tt)!r},{v:.4f},7\n")
    return t, truth, z, s004, plain


@pytest.mark.parametrize("name", FILTERS)
def test_every_implementation_runs_and_writes_degrees(run, files, tmp_path, name):
    t, truth, z, s004, _ = files
    outs = {}
    for impl in ("ref", "f32", "q"):
        out = tmp_path / f"{impl}.csv"
        code, _, err = run("run", "--filter", name, "--impl", impl, "--input", s004, "--out", out)
        assert code == 0, err
        comment, header, x = _csv(out)
        oscillator = name != "angle-kf"
        assert header == ["t", "angle_deg", "rate_deg_s"] + (["omega_rad_s"] if oscillator else [])
        assert "t s, angle_deg deg, rate_deg_s deg/s" in comment and "seed004-arduino" in comment
        assert len(x) == len(z) and np.allclose(x[:, 0], t, atol=1e-9) and np.all(np.isfinite(x))
        outs[impl] = x
    # units: the CSV is the filter's radian output in degrees (ref run in-process)
    ref = angle_series.run(name, "ref", angle_series.inputs(angle_series.AngleSeries(t, np.radians(np.round(z, 4)))))
    assert np.allclose(outs["ref"][:, 1], np.degrees(ref["angle"][:, 0]), atol=1e-6)
    assert np.allclose(outs["ref"][:, 2], np.degrees(ref["rate"][:, 0]), atol=1e-5)
    # generated float32 C follows the reference closely; fixed point within a degree
    assert np.max(np.abs(outs["f32"][:, 1] - outs["ref"][:, 1])) < 1e-3
    assert np.max(np.abs(outs["q"][:, 1] - outs["ref"][:, 1])) < 1.0
    # and it smooths: closer to the truth than the measurement after a 2 s warm-up
    m = t >= 2.0
    rmse = lambda a: float(np.sqrt(np.mean((a[m] - truth[m]) ** 2)))  # noqa: E731
    assert rmse(outs["f32"][:, 1]) < (0.95 if name == "angle-kf" else 0.8) * rmse(z)


def test_plain_csv_equals_seed004_raw_column(run, files, tmp_path):
    _, _, _, s004, plain = files
    a, b = tmp_path / "a.csv", tmp_path / "b.csv"
    assert run("run", "--filter", "angle-ekf", "--input", s004, "--out", a)[0] == 0
    assert run("run", "--filter", "angle-ekf", "--input", plain, "--out", b)[0] == 0
    _, _, xa = _csv(a)
    comment, _, xb = _csv(b)
    assert "angle-csv" in comment
    assert np.allclose(xa, xb, atol=1e-6)


def test_fs_sets_the_seed004_time_base(run, files, tmp_path, capsys):
    _, _, z, s004, plain = files
    out = tmp_path / "o.csv"
    assert run("run", "--filter", "angle-kf", "--input", s004, "--out", out, "--fs", "20")[0] == 0
    _, _, x = _csv(out)
    assert np.allclose(x[:, 0], np.arange(len(z)) / 20.0)
    _one_line_error(*run("run", "--filter", "angle-kf", "--input", plain, "--out", out, "--fs", "20",
                         "--force"),
                    "--fs applies to the seed-004 Arduino CSV")
    # inf timed every sample at t = 0; 0, negative and NaN are usage errors too
    for bad in ("inf", "0", "-35", "nan"):
        with pytest.raises(SystemExit) as exc:          # argparse's usage error
            run("run", "--filter", "angle-kf", "--input", s004, "--out", out, "--fs", bad, "--force")
        assert exc.value.code == 2
        assert f"argument --fs: {bad} is not in (0, inf)" in capsys.readouterr().err


def test_missing_angle_predicts_and_bad_samples_are_rejected(run, tmp_path):
    src = tmp_path / "gaps.csv"
    t = np.arange(60) * 0.02
    rows = [f"{tt:.2f},{10.0 + 30.0 * tt:.4f}" for tt in t]
    rows[30] = f"{t[30]:.2f},"                       # no measurement
    rows[40] = f"{t[40]:.2f},250"                    # beyond ±183°: rejected
    src.write_text("t,angle_deg\n" + "\n".join(rows) + "\n")
    out = tmp_path / "o.csv"
    code, _, err = run("run", "--filter", "angle-kf", "--input", src, "--out", out, "--status")
    assert code == 0, err
    assert "1 sample(s) rejected" in err and "1 sample(s) without an angle" in err
    # the limit in the input's unit too: the series is in degrees, the filter's limit in rad
    assert "angle beyond ±3.2 rad = ±183°" in err, err
    _, header, x = _csv(out)
    assert header == ["t", "angle_deg", "rate_deg_s", "rejected"]
    # sample 30: constant-rate prediction only (rate kept, angle advanced by rate·dt)
    assert x[30, 2] == pytest.approx(x[29, 2], abs=1e-6)
    assert x[30, 1] == pytest.approx(x[29, 1] + x[29, 2] * 0.02, abs=1e-4)
    # sample 40: rejected, state (and output) kept, counter at 1 from there on
    assert np.array_equal(x[40, 1:3], x[39, 1:3]) and x[39, 3] == 0 and x[40, 3] == 1 and x[-1, 3] == 1
    assert x[-1, 2] == pytest.approx(30.0, abs=1.0)          # the ramp's rate, deg/s


def test_out_naming_the_input_is_refused_and_the_input_kept(run, files, tmp_path, monkeypatch):
    import shutil
    src = tmp_path / "plain.csv"
    shutil.copy(files[4], src)
    before = src.read_bytes()
    for out in (src, tmp_path / "." / "plain.csv"):
        code, out_txt, err = run("run", "--filter", "angle-kf", "--input", src, "--out", out)
        _one_line_error(code, out_txt, err, "is the input")
    monkeypatch.chdir(tmp_path)        # a relative name for the same file
    code, out_txt, err = run("run", "--filter", "angle-kf", "--input", "plain.csv", "--out", src)
    _one_line_error(code, out_txt, err, "is the input")
    assert src.read_bytes() == before


def test_wrong_input_kinds_give_one_line(run, files, tmp_path):
    _, _, _, s004, plain = files
    out = tmp_path / "o.csv"
    _one_line_error(*run("run", "--filter", "angle-ukf", "--input", TRIAL, "--out", out),
                    "is an IMU recording")
    imu_csv = tmp_path / "imu.csv"
    imu_csv.write_text("t_s,acc_x_mps2,acc_y_mps2,acc_z_mps2,gyr_x_radps,gyr_y_radps,gyr_z_radps\n"
                       "0,0,0,9.81,0,0,0\n0.01,0,0,9.81,0,0,0\n")
    _one_line_error(*run("run", "--filter", "angle-kf", "--input", imu_csv, "--out", out),
                    "is an IMU recording (kinefuse-csv)")
    for src in (s004, plain):
        _one_line_error(*run("run", "--filter", "madgwick", "--input", src, "--out", out),
                        "is a joint-angle series")
    bad = tmp_path / "bad.csv"
    bad.write_text("t,angle_deg\n0,1\n0.1,2\n0.1,3\n")
    _one_line_error(*run("run", "--filter", "angle-kf", "--input", bad, "--out", out), "line 4: t = 0.1 s does not increase")
    bad.write_text("t,angle_deg\n0,1\n0.1,x\n")
    _one_line_error(*run("run", "--filter", "angle-kf", "--input", bad, "--out", out), "line 3: angle_deg: 'x' is not a number")
    other = tmp_path / "other.csv"
    other.write_text("a,b\n1,2\n")
    _one_line_error(*run("run", "--filter", "angle-kf", "--input", other, "--out", out), "not a joint-angle series")
    _one_line_error(*run("run", "--filter", "angle-kf", "--input", tmp_path / "none.csv", "--out", out), "no such file")
    _one_line_error(*run("run", "--filter", "angle-kf", "--input", plain, "--out", out, "--param", "sigma_meas=9"),
                    "sigma_meas")
    # replay takes IMU recordings only and keeps refusing the smoothers
    _one_line_error(*run("replay", TRIAL, "--out", out, "--filter", "angle-kf"), "not IMU samples")


# ---- benches: speed, bitexact, cost on the smoothers ---------------------------------------

@pytest.fixture
def bench(monkeypatch, capsys):
    monkeypatch.setattr(cli, "COMMAND_MODULES", [])
    monkeypatch.setattr(cli, "BENCH_MODULES", [m for m in cli.BENCH_MODULES if m.rsplit(".", 1)[-1]
                                               in ("bitexact", "speed", "cost", "seed004")])

    def _run(*argv):
        code = cli.main(["bench", *[str(a) for a in argv]])
        out, err = capsys.readouterr()
        return code, out, err
    return _run


def test_bench_bitexact_on_an_angle_series(bench, files):
    import json
    _, _, z, s004, _ = files
    code, out, err = bench("bitexact", "--filter", "angle-srukf", "--data", s004, "--json")
    assert code == 0, err
    r = json.loads(out)
    assert r["deviation_of"].startswith("filtered angle")
    for system in ("f32", "q"):
        assert r[system]["samples"] == len(z) and r[system]["differing"] == 0
        assert 0.0 < r[system]["rms_deg"] <= r[system]["max_deg"] < 5.0
    assert r["f32"]["max_deg"] < 1e-3


def test_bench_bitexact_default_data_is_the_servo_protocol():
    from kinefuse.host.bench import bitexact
    series, where = bitexact._angle_data(None)
    assert len(series) == 20 and all(len(inp["dt"]) == 1050 for _, inp in series)
    assert "servo protocol" in where


def test_bench_speed_on_an_angle_series(bench, files):
    import json
    _, _, z, _, plain = files
    code, out, err = bench("speed", "--filter", "angle-ukf", "--data", plain, "--repeat", "1",
                           "--model-samples", "50", "--json")
    assert code == 0, err
    sps = json.loads(out)["samples_per_s"]
    assert set(sps) == {"f32_c", "q_c", "f32_model", "q_model", "ref"}      # no IMU competitor
    assert sps["f32_c"] > sps["f32_model"] > 0 and sps["q_c"] > 0


def test_bench_speed_and_bitexact_refuse_other_input_kinds(bench):
    for cmd in ("speed", "bitexact"):
        code, _, err = bench(cmd, "--filter", "joint-angle")
        _one_line_error(code, "", err, "takes")


def test_bench_cost_covers_the_smoothers(bench):
    import json
    from kinefuse.hil_tests.qemu import qemu_unavailable
    if qemu_unavailable():
        pytest.skip(qemu_unavailable())
    code, out, err = bench("cost", "--filters", "angle-kf", "--formats", "f32", "--targets", "m4f",
                           "--no-competitors", "--no-mix", "--k", "20", "--json")
    assert code == 0, err
    (row,) = json.loads(out)["rows"]
    assert row["filter"] == "angle-kf" and not row.get("error")
    # a 2-state Kalman step is some tens to hundreds of instructions, not a handful nor 10^4
    assert 40 < row["instructions_per_update"] < 2000, row
    assert row["own_flash_bytes"] > 100


@pytest.mark.parametrize("opt", ["--formats", "--targets"])
def test_bench_cost_refuses_an_empty_format_or_target_list(bench, opt):
    # `--formats ""` (or `--formats ,`) measured nothing and exited 0 with an empty table
    from kinefuse.hil_tests.qemu import qemu_unavailable
    if qemu_unavailable():
        pytest.skip(qemu_unavailable())
    code, out, err = bench("cost", "--filters", "angle-kf", "--no-competitors", "--no-mix", "--k", "10",
                           opt, ",", "--json")
    _one_line_error(code, out, err, "--formats takes f32,q and --targets m4f,m0")


@pytest.mark.parametrize("opt, value", [("--filters", "angle-kf,angle-kf"), ("--formats", "f32,f32"),
                                        ("--targets", "m4f, m4f")])
def test_bench_cost_refuses_a_name_given_twice(bench, opt, value):
    # each row was measured and listed twice
    from kinefuse.hil_tests.qemu import qemu_unavailable
    if qemu_unavailable():
        pytest.skip(qemu_unavailable())
    argv = {"--filters": "angle-kf", "--formats": "f32", "--targets": "m4f", opt: value}
    code, out, err = bench("cost", *[x for kv in argv.items() for x in kv], "--no-competitors", "--no-mix",
                           "--k", "10", "--json")
    _one_line_error(code, out, err, f"{opt} names {value.split(',')[0]} twice")


# angle-kf: the smallest update, so the single-step traces take seconds (angle-ekf q on the M0: 38 s)
@pytest.mark.parametrize("fmt,target", [("f32", "m4f"), ("q", "m4f"), ("f32", "m0")])
def test_bench_cost_profile_accounts_for_every_instruction(bench, fmt, target):
    import json
    from kinefuse.hil_tests.qemu import qemu_unavailable
    if qemu_unavailable():
        pytest.skip(qemu_unavailable())
    code, out, err = bench("cost", "--filters", "angle-kf", "--formats", fmt, "--targets", target,
                           "--no-competitors", "--k", "20", "--profile", "--top", "50", "--json")
    assert code == 0, err
    (row,) = json.loads(out)["rows"]
    prof = row["profile"]
    total = prof["traced_instructions_per_update"]
    # the trace and the counting plugin see the same program: the same count within the driver
    # loop's few instructions
    assert abs(total - row["instructions_per_update"]) < 10, (total, row["instructions_per_update"])
    fns, lines = prof["functions"], prof["reference_lines"]
    upd = [f for f in fns if f["name"] == f"angle_kf_{fmt}_update"]
    assert upd and upd[0]["calls_per_update"] == 1, fns
    if target == "m4f":   # with an FPU the update body is the largest part
        assert fns[0] is upd[0], fns
    assert sum(f["instructions_per_update"] for f in fns) == pytest.approx(total)
    assert sum(g["instructions_per_update"] for g in lines) == pytest.approx(total)
    # the update's own instructions (its inlined helpers included) are exactly those attributed to
    # lines of the reference or to the generated glue; most of them to reference lines
    ref = sum(g["instructions_per_update"] for g in lines if g["where"].startswith("angle_kf.py:"))
    glue = sum(g["instructions_per_update"] for g in lines
               if g["where"].startswith(f"angle_kf_{fmt}.c: generated glue"))
    assert ref + glue == pytest.approx(upd[0]["instructions_per_update"]), lines
    assert ref > 0.5 * upd[0]["instructions_per_update"], lines
    if target == "m0":   # no FPU: libgcc's soft-float routines do part of it, with their calls
        soft = [f for f in fns if f["name"].startswith("__aeabi_f")]
        assert soft and all(f["calls_per_update"] >= 1 for f in soft), fns
        assert any(g["where"] == f"in {soft[0]['name']} (out of line)" for g in lines), lines


def test_the_comment_line_names_only_the_columns_written(run, tmp_path, monkeypatch):
    """A smoother without a rate output (a contributor's low-pass) got 'rate_deg_s deg/s' in the
    comment line of a file without that column."""
    real = angle_series.run

    def angle_only(*a, **k):
        out = real(*a, **k)
        return {k2: v for k2, v in out.items() if k2 != "rate"}
    monkeypatch.setattr(angle_series, "run", angle_only)
    src = tmp_path / "a.csv"
    src.write_text("t,angle_deg\n" + "\n".join(f"{i * 0.02:.2f},{i * 0.5:.3f}" for i in range(20)) + "\n")
    out = tmp_path / "o.csv"
    code, _, err = run("run", "--filter", "angle-kf", "--input", src, "--out", out)
    assert code == 0, err
    comment, header, _ = _csv(out)
    assert header == ["t", "angle_deg"]
    assert "rate_deg_s" not in comment and "angle_deg deg" in comment


def test_an_imu_filter_without_q_is_one_line(monkeypatch, tmp_path):
    """run_filter on an IMU estimator without a q output was an internal KeyError after the run."""
    import dataclasses

    from kinefuse.codegen import estimators
    from kinefuse.host import runner
    from kinefuse.host.errors import KinefuseError
    real = estimators.get("madgwick")

    class NoQ(real.__class__):
        outputs = tuple(v for v in real.outputs if v.name != "q")
    monkeypatch.setattr(estimators, "get", lambda name: NoQ() if name == "madgwick" else real)
    trial = dataclasses.make_dataclass("T", ["gyr", "acc", "mag", "dt", "rate_hz"])(
        np.zeros((3, 3)), np.zeros((3, 3)), np.zeros((3, 3)), 0.01, 100.0)
    with pytest.raises(KinefuseError, match="no 'q' output"):
        runner.run_filter("madgwick", "ref", trial)
