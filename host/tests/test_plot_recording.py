"""``kinefuse plot`` of a unit recording (no reference): replayed orientation, sensor magnitudes,
lost samples, status and the unit's own KF_ORIENTATION; and its one-line errors."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.host.broad import EXCERPT_DIR
from kinefuse.host.plots import lost_before, status_flags

MINE = ("plot_cmd", "cli_cmd")   # cli_cmd: kinefuse sim
TRIAL = EXCERPT_DIR / "24_disturbed_tapping_A.npz"


def _one_line_error(res, text):
    code, out, err = res
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1 and text in lines[0], res
    assert "Traceback" not in err


@pytest.fixture(scope="module")
def kfr_files(tmp_path_factory):
    from kinefuse.host.link.recorder import Recorder
    d = tmp_path_factory.mktemp("plotrec")
    one, two = d / "one.kfr", d / "two.kfr"
    Recorder(one, ["fake:rate=500,drop=40"]).run(1.0)
    Recorder(two, ["fake:rate=200", "fake:unit=2,rate=200"]).run(0.5)
    return one, two


def test_lost_samples_and_status_flags():
    dt = np.full(100, 0.002)
    dt[[10, 50, 51]] = [0.004, 0.006, 0.0031]
    assert np.flatnonzero(lost_before(dt)).tolist() == [10, 50, 51]
    flags = status_flags({"rest": np.array([0, 1, 1, 0, 0]), "rejected": np.array([0, 0, 1, 1, 3]),
                          "bias": np.zeros((5, 3)), "mag_disturbed": np.array([True, False] * 2 + [True])}, 5)
    assert list(flags) == ["rest", "rejected", "mag disturbed"]
    assert flags["rest"].tolist() == [False, True, True, False, False]
    # a running count: the samples where it grows (it was painted on every sample after the first)
    assert flags["rejected"].tolist() == [False, False, True, False, True]


def test_plot_of_a_unit_recording(run, kfr_files, tmp_path):
    one, two = kfr_files
    out = tmp_path / "one.png"
    code, stdout, err = run("plot", "--input", one, "--out", out)     # a recording: f32 by default
    assert code == 0, err
    assert stdout.strip() == str(out) and out.stat().st_size > 20_000
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "flagship (f32) on one.kfr unit 1:" in err and "rejected by the filter" in err
    _one_line_error(run("plot", "--input", one, "--impl", "f32", "--out", out), "exists")
    # a two-unit file: the unit is chosen, and the default name says which
    _one_line_error(run("plot", "--input", two, "--out", tmp_path / "t.png"), "choose one with --unit")
    code, stdout, err = run("plot", "--input", two, "--unit", "2", "--impl", "f32",
                            "--start", "0.1", "--end", "0.4")
    assert code == 0, err
    made = stdout.strip()
    assert made.endswith("two_u2_flagship_f32.png"), made
    import os
    os.remove(made)


@pytest.mark.parametrize("argv, text", [
    (["--filter", "vqf"], "competitors are run on BROAD trials"),
    (["--unit", " "], "--unit is empty"),
    (["--start", "99"], "--start 99: the recording ends at"),
    (["--end", "inf"], "--end must be a finite time"),
    (["--start", "0.5", "--end", "0.2"], "need start < end, got 0.5 and 0.2"),
    (["--end", "-1"], "the recording runs from 0.0 to"),
    (["--filter", "angle-kf"], "angle-kf"),
])
def test_recording_errors_are_one_line(run, kfr_files, tmp_path, argv, text):
    one, _ = kfr_files
    _one_line_error(run("plot", "--input", one, "--out", tmp_path / "x.png", *argv), text)
    assert not (tmp_path / "x.png").exists()


def test_unit_option_is_refused_for_a_broad_trial(run, tmp_path):
    _one_line_error(run("plot", "--input", TRIAL, "--unit", "2", "--out", tmp_path / "b.png"),
                    "--unit applies to .kfr unit recordings")


def test_a_trial_without_movement_phases_says_so(run, tmp_path):
    """A simulated trial at rest printed "RMSE total nan°, heading nan°, inclination nan°"."""
    mat = tmp_path / "rest.mat"
    code, _, err = run("sim", "run", "rest", "--duration", "3", "--out", mat)
    assert code == 0, err
    code, _, err = run("plot", "--input", mat, "--filter", "madgwick", "--impl", "f32",
                       "--out", tmp_path / "rest.png")
    assert code == 0, err
    assert "no movement phase with a reference to score" in err and "nan" not in err, err


# ------------------------------------------------------------------ review fixes (2026-12-04)
@pytest.mark.parametrize("samples", [0, 1])
def test_a_window_without_two_samples_is_one_line(run, kfr_files, tmp_path, samples):
    """A window between two samples was an internal IndexError; one with a single sample gave an
    empty plot.  The one-unit file is sampled at 500 Hz (2 ms)."""
    from kinefuse.host.readers import read_recording
    one, _ = kfr_files
    t = read_recording(str(one)).t
    k = int(np.searchsorted(t, 0.5))
    mid = (t[k] + t[k + 1]) / 2 if samples == 0 else t[k]       # 0.4 ms either side: 0 or 1 sample
    start, end = f"{mid - 0.0004:.6f}", f"{mid + 0.0004:.6f}"
    out = tmp_path / "w.png"
    code, _, err = run("plot", "--input", one, "--out", out, "--start", start, "--end", end)
    last = err.strip().splitlines()[-1]
    assert code == 2 and f"{samples} sample(s) of the recording between" in last, err
    assert "at least two" in last
    assert "Traceback" not in err and "internal error" not in err and not out.exists()


def test_a_trial_window_without_samples_is_one_line(run, tmp_path):
    out = tmp_path / "t.png"
    _one_line_error(run("plot", "--input", TRIAL, "--filter", "madgwick", "--impl", "f32", "--out", out,
                        "--start", "5", "--end", "5.0001"), "0 sample(s) of the trial between 5 and 5.0001 s")
    assert not out.exists()


def test_a_failed_save_leaves_the_earlier_plot(run, kfr_files, tmp_path, monkeypatch):
    """The PNG was saved in place: a save that failed half-way (a full disk) left a cut file,
    and with --force the earlier plot was already gone."""
    from pathlib import Path
    one, _ = kfr_files
    out = tmp_path / "p.png"
    out.write_bytes(b"an earlier plot")
    write = Path.write_bytes

    def full(self, data):
        write(self, data[:100])
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(Path, "write_bytes", full)
    code, _, err = run("plot", "--input", one, "--out", out, "--force")
    assert code == 2 and "No space left on device" in err.strip().splitlines()[-1], err
    assert out.read_bytes() == b"an earlier plot"
    assert [p.name for p in tmp_path.iterdir()] == ["p.png"]


def test_default_names_of_two_units_with_one_id(run, tmp_path, monkeypatch):
    """Two units that both have id 1 (on two ports) both got <file>_u1_...png: the second plot
    was refused as existing."""
    from kinefuse.host.link.recorder import Recorder
    rec = tmp_path / "same.kfr"
    Recorder(rec, ["fake:rate=200", "fake:rate=200"]).run(0.3)
    monkeypatch.chdir(tmp_path)
    made = []
    for unit in ("s0:1", "s1:1"):
        code, stdout, err = run("plot", "--input", rec, "--unit", unit)
        assert code == 0, err
        made.append(stdout.strip())
    assert made == ["same_s0_u1_flagship_f32.png", "same_s1_u1_flagship_f32.png"]


def test_a_kfr_is_decoded_once(run, kfr_files, tmp_path, monkeypatch):
    """The reader decoded the file for the samples, then ``unit_orientation`` decoded it again
    for the unit's KF_ORIENTATION (the costly part of a long recording, done twice)."""
    from kinefuse.host import plots
    from kinefuse.host.link import frames
    one, _ = kfr_files
    calls, drawn = [], {}
    decode, draw = frames.decode_file, plots.plot_recording

    def counting(*a, **k):
        calls.append(str(a[0]))
        return decode(*a, **k)

    def drawing(*a, **k):
        drawn.update(k)
        return draw(*a, **k)
    monkeypatch.setattr(frames, "decode_file", counting)
    monkeypatch.setattr(plots, "plot_recording", drawing)
    code, _, err = run("plot", "--input", one, "--out", tmp_path / "once.png")
    assert code == 0, err
    assert drawn["unit_q"] is not None and len(drawn["unit_q"][0]) > 50     # still drawn
    assert calls == [str(one)], calls
