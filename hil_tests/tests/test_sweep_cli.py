"""Command-line sweep of ``kinefuse sim``, ``kinefuse sil report`` and ``kinefuse bench``: an
option given but empty (``--parts ""``, ``--filter ""``: an unset shell variable), or naming
nothing, is a one-line error with exit status 2 before any work, never a silent default or a
run that measures nothing.

Nothing expensive runs here: QEMU is switched off (its absence is then the only other error a
command could give, so a test without the fix fails on the message), data folders are missing
or empty, and the simulated cases are a fraction of a second.
"""
from __future__ import annotations

import json

import pytest

from kinefuse.host import broad
from kinefuse.host.cli import main

NO_QEMU = "QEMU switched off by the test"


@pytest.fixture
def no_qemu(monkeypatch):
    import kinefuse.hil_tests.qemu as q
    monkeypatch.setattr(q, "qemu_unavailable", lambda *a, **k: NO_QEMU)


def _one_line_error(capsys, *needles):
    err = capsys.readouterr().err.strip()
    assert "Traceback" not in err and len(err.splitlines()) == 1, err
    assert err.startswith("kinefuse: error:"), err
    for n in needles:
        assert n in err, err
    return err


# ---- bench qemu / bench cost ---------------------------------------------------------------

@pytest.mark.parametrize("option", ["--parts", "--targets", "--cases"])
@pytest.mark.parametrize("value", ["", " , "])
def test_bench_qemu_refuses_an_empty_list(no_qemu, capsys, option, value):
    # --parts "" / --targets "" measured nothing and exited 0; --cases "" meant every case
    assert main(["bench", "qemu", option, value]) == 2
    _one_line_error(capsys, option, "names nothing")


@pytest.mark.parametrize("option,value", [("--parts", "loop,loop"), ("--targets", "m4f,m4f"),
                                          ("--cases", "vqf-9d,vqf-9d")])
def test_bench_qemu_refuses_a_name_given_twice(no_qemu, capsys, option, value):
    assert main(["bench", "qemu", option, value]) == 2
    _one_line_error(capsys, option, "twice")


@pytest.mark.parametrize("argv,option", [(["--parts", "loop", "--records", "100"], "--records"),
                                         (["--parts", "batch", "--uart-bytes", "100"], "--uart-bytes"),
                                         (["--parts", "uart", "--cases", "vqf-9d"], "--cases")])
def test_bench_qemu_refuses_an_option_of_a_part_not_run(no_qemu, capsys, argv, option):
    # (was ignored: --parts loop --records 100 measured the loop and nothing else)
    assert main(["bench", "qemu", *argv]) == 2
    _one_line_error(capsys, option, "part not run")


def test_bench_cost_refuses_top_without_profile(no_qemu, capsys):
    # (--top was ignored without --profile)
    assert main(["bench", "cost", "--filters", "madgwick", "--top", "5"]) == 2
    _one_line_error(capsys, "--top", "--profile")


def test_bench_qemu_good_options_reach_the_qemu_check(no_qemu, capsys):
    assert main(["bench", "qemu", "--parts", "loop", "--targets", "m4f"]) == 2
    _one_line_error(capsys, NO_QEMU)
    assert main(["bench", "qemu", "--parts", "batch,uart", "--records", "10", "--uart-bytes", "5"]) == 2
    _one_line_error(capsys, NO_QEMU)
    assert main(["bench", "cost", "--filters", "madgwick", "--profile", "--top", "5"]) == 2
    _one_line_error(capsys, NO_QEMU)


@pytest.mark.parametrize("value", ["", " "])
def test_bench_cost_refuses_empty_filters(no_qemu, capsys, value):
    # an empty --filters meant every filter (the longest cost run there is)
    assert main(["bench", "cost", "--filters", value, "--formats", "f32", "--targets", "m4f",
                 "--no-competitors", "--no-mix"]) == 2
    _one_line_error(capsys, "--filters", "names nothing")


# ---- bench accuracy / speed / bitexact ------------------------------------------------------

@pytest.mark.parametrize("bench", ["accuracy", "speed", "bitexact"])
@pytest.mark.parametrize("value", ["", "  "])
def test_bench_refuses_an_empty_filter(capsys, tmp_path, bench, value):
    # (was the default filter; the missing data would then have been the error)
    assert main(["bench", bench, "--filter", value, "--data", str(tmp_path / "missing")]) == 2
    _one_line_error(capsys, "--filter", "empty")


def test_bench_accuracy_refuses_empty_data(capsys, monkeypatch):
    # (was the default data: the whole shared BROAD set); no default data here, so a run that
    # ignores the empty value fails on "no trials found" instead
    monkeypatch.setattr(broad, "default_data", lambda *a, **k: ([], "nowhere"))
    assert main(["bench", "accuracy", "--filter", "madgwick", "--data", ""]) == 2
    _one_line_error(capsys, "--data", "empty")


@pytest.mark.parametrize("bench", ["speed", "bitexact"])
def test_bench_refuses_empty_data(capsys, tmp_path, monkeypatch, bench):
    # (was the current folder: "no trial files (.mat or .npz) in this directory")
    monkeypatch.chdir(tmp_path)
    assert main(["bench", bench, "--filter", "madgwick", "--data", ""]) == 2
    _one_line_error(capsys, "--data", "empty")


# ---- sil report -----------------------------------------------------------------------------

_SIL = ["sil", "report", "--no-qemu", "--broad", "none", "--seconds", "0.05"]


@pytest.mark.parametrize("option,extra", [("--filters", ["--scenarios", "nosuch"]),
                                          ("--scenarios", ["--filters", "madgwick"])])
def test_sil_report_refuses_an_empty_list(capsys, tmp_path, option, extra):
    # an empty --filters meant every filter, an empty --scenarios the whole scenario set
    out = tmp_path / "rep"
    assert main([*_SIL, option, "", *extra, "--out", str(out)]) == 2
    _one_line_error(capsys, option, "names nothing")
    assert not out.exists()


@pytest.mark.parametrize("option", ["--broad", "--cost"])
def test_sil_report_refuses_an_empty_file_name(capsys, tmp_path, option):
    # --broad "" meant the default BROAD trial, --cost "" no cost table
    out = tmp_path / "rep"
    argv = ["sil", "report", "--no-qemu", "--filters", "madgwick", "--scenarios", "rest",
            "--seconds", "0.05", option, "", "--out", str(out)]
    assert main(argv) == 2
    _one_line_error(capsys, option, "empty")
    assert not out.exists()


def test_sil_report_refuses_an_empty_out(capsys, tmp_path, monkeypatch):
    # (--out "" wrote the report into the current folder)
    monkeypatch.chdir(tmp_path)
    assert main([*_SIL, "--filters", "madgwick", "--scenarios", "rest", "--out", ""]) == 2
    _one_line_error(capsys, "--out", "empty")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("what", ["missing", "folder"])
def test_sil_report_checks_the_broad_trial_before_simulating(capsys, tmp_path, monkeypatch, what):
    from kinefuse.hil_tests.harness import scenarios

    def no_sim(*a, **k):
        raise AssertionError("simulated before the --broad file was checked")
    monkeypatch.setattr(scenarios, "sim_case", no_sim)
    monkeypatch.setattr(scenarios, "ci_case", no_sim)
    path = tmp_path / "trial.mat" if what == "missing" else tmp_path
    out = tmp_path / "rep"
    assert main(["sil", "report", "--no-qemu", "--filters", "madgwick", "--scenarios", "rest",
                 "--broad", str(path), "--out", str(out)]) == 2
    _one_line_error(capsys, str(path), "not found" if what == "missing" else "folder")
    assert not out.exists()


def test_sil_report_refuses_a_cost_file_without_rows(capsys, tmp_path):
    # a `bench cost --json` object with no rows: the report had no cost table, without a word
    cost = tmp_path / "cost.json"
    cost.write_text(json.dumps({"rows": [], "clock_hz": 64_000_000}))
    out = tmp_path / "rep"
    assert main([*_SIL, "--filters", "madgwick", "--scenarios", "rest", "--cost", str(cost),
                 "--out", str(out)]) == 2
    _one_line_error(capsys, str(cost), "empty")
    assert not out.exists()


# ---- sim run --------------------------------------------------------------------------------

@pytest.mark.parametrize("option", ["--preset", "--out"])
def test_sim_run_refuses_an_empty_option(capsys, tmp_path, monkeypatch, option):
    # --preset "" kept the scenario's sensor, --out "" wrote nothing; both exited 0
    monkeypatch.chdir(tmp_path)
    assert main(["sim", "run", "rest", "--duration", "0.1", option, ""]) == 2
    _one_line_error(capsys, option, "empty")
    assert list(tmp_path.iterdir()) == []


def test_sim_run_empty_scenario_name(capsys, tmp_path, monkeypatch):
    # was read as the current folder: "cannot read scenario file : Is a directory"
    monkeypatch.chdir(tmp_path)
    assert main(["sim", "run", ""]) == 2
    err = _one_line_error(capsys, "scenario ''", "empty", "kinefuse sim list")
    assert "directory" not in err.lower()


# ---- sil report: a case without any reference sample ----------------------------------------

def _case_without_reference(n=50):
    import numpy as np
    from kinefuse.hil_tests.harness.scenarios import Case
    z = np.zeros((n, 3))
    return Case(name="no_ref", source="broad", rate_hz=100.0,
                inputs={"gyr": z, "acc": z + [0, 0, 9.81], "mag": z + [0, 20, -40],
                        "mag_valid": np.ones(n, bool), "dt": np.full(n, 0.01)},
                q_true=np.full((n, 4), np.nan), movement=np.ones(n, bool), t=np.arange(n) / 100.0)


def test_report_scores_a_case_without_reference_as_not_available(tmp_path, recwarn):
    # (the head of BROAD trial 21 has no optical reference for 4.8 s: NaN cells, numpy's
    # "Mean of empty slice" warnings on stderr and NaN, not JSON, in sil_report.json)
    import numpy as np
    from kinefuse.hil_tests.harness import report
    case = _case_without_reference()
    e = report.rmse_errors(np.tile([1.0, 0, 0, 0], (case.n, 1)), case)
    assert e == {"total": None, "heading": None, "inclination": None, "scored": 0}
    assert not [w for w in recwarn if issubclass(w.category, RuntimeWarning)]
    rep = report.Report(["no_ref", "ok"], ["madgwick"])
    rep.errors[("madgwick", "no_ref", "f32")] = e
    rep.errors[("madgwick", "ok", "f32")] = {"total": 3.0, "heading": 2.0, "inclination": 1.0, "scored": 9}
    md = report.write_markdown(rep, tmp_path, None).read_text()
    assert "| no_ref | n/a (no reference sample) |" in md
    assert "| ok | 3.00 (h 2.00, i 1.00) |" in md and "h heading, i inclination" in md
    json.loads(json.dumps(rep.as_dict()), parse_constant=lambda c: pytest.fail(f"{c} in the JSON"))
    assert report.write_png(rep, tmp_path).exists()


def test_sim_run_leaves_no_file_when_a_later_write_fails(capsys, tmp_path, monkeypatch):
    # two sensor units: the second file cannot be written (disk full); the first one stayed
    from kinefuse.hil_tests.sim.recording import Recording
    real, calls = Recording.save, []

    def save(self, path):
        calls.append(path)
        if len(calls) == 2:
            raise OSError(28, "No space left on device")
        real(self, path)
    monkeypatch.setattr(Recording, "save", save)
    assert main(["sim", "run", "hinge_static", "--duration", "0.1", "--out", str(tmp_path / "h.npz")]) == 2
    _one_line_error(capsys, "cannot write", "h_distal.npz", "No space left")
    assert len(calls) == 2 and list(tmp_path.iterdir()) == []
    # and a run that succeeds leaves exactly the two files
    monkeypatch.setattr(Recording, "save", real)
    assert main(["sim", "run", "hinge_static", "--duration", "0.1", "--out", str(tmp_path / "h.npz")]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["h_distal.npz", "h_proximal.npz"]
    assert len(Recording.load(str(tmp_path / "h_distal.npz"))) == 11


def test_bench_speed_instructions_without_valgrind_fails_before_any_work(capsys, monkeypatch):
    # (the missing valgrind was reported after the whole timing run)
    import shutil
    from kinefuse.host.bench import speed
    which = shutil.which
    monkeypatch.setattr(shutil, "which", lambda n, *a, **k: None if n == "valgrind" else which(n, *a, **k))

    def no_work(*a, **k):
        raise AssertionError("the timings started")
    monkeypatch.setattr(speed, "trial_files", no_work)
    monkeypatch.setattr(speed, "_best_interleaved", no_work)
    assert main(["bench", "speed", "--filter", "madgwick", "--instructions"]) == 2
    _one_line_error(capsys, "--instructions needs valgrind")


@pytest.mark.parametrize("preset,mag_rate", [("matrix", None), ("metamotionr", 20.0)])
def test_sim_run_lists_no_magnetometer_rate_without_magnetometer(capsys, preset, mag_rate):
    # the Matrix unit has no magnetometer; its summary said "100/100" Hz acc/mag
    assert main(["sim", "run", "rest", "--duration", "0.1", "--preset", preset, "--json"]) == 0
    s = json.loads(capsys.readouterr().out)["sensors"]["imu"]
    assert s["rate_hz"] == 100.0 and s["mag_rate_hz"] == mag_rate
    assert (s["mag_norm_min"] is None) == (mag_rate is None)


def test_sim_run_preset_keeps_the_scenarios_error_terms(tmp_path):
    """`sim run bias_1dps --preset xsens_dot` lost the scenario's 1 °/s gyro bias: the preset
    replaced the whole sensor section.  The preset gives the noise, the scenario its bias."""
    from kinefuse.hil_tests.sim.recording import Recording
    out = tmp_path / "b.npz"
    assert main(["sim", "run", "bias_1dps", "--duration", "5", "--preset", "xsens_dot",
                 "--out", str(out)]) == 0
    import numpy as np
    r = Recording.load(str(out))
    bias_dps = np.degrees(np.mean(r.gyr - r.truth["gyr_true"], axis=0))
    np.testing.assert_allclose(bias_dps, [1.0, 1.0, 1.0], atol=0.05)   # at rest: the bias
    assert r.meta["preset"] == "xsens_dot"
