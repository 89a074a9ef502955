"""``kinefuse demo`` and ``kinefuse plot`` with the stand-in runner of test_accuracy."""
import json

import numpy as np
import pytest

from kinefuse.host import broad, competitors, plots
from kinefuse.host.bench import accuracy
from kinefuse.host.errors import KinefuseError
from test_accuracy import FAKE, kf  # noqa: F401 - shared stand-in runner and CLI fixture

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


@pytest.fixture
def two_filters(monkeypatch):
    monkeypatch.setattr(FAKE, "imu_filter_names", lambda: ["perfect", "tilted"])


def test_demo_writes_table_json_and_plot(kf, two_filters, tmp_path):
    code, out, err = kf("demo", "--out", str(tmp_path / "d"), "--jobs", "2")
    assert code == 0, err
    for label in ("perfect (f32)", "perfect (q)", "perfect (ref)", "tilted (ref)", "tilted (f32)"):
        assert label in out
    d = json.loads((tmp_path / "d" / "accuracy.json").read_text())
    assert d["trials"] == [p.stem for p in broad.bundled_trials()]
    assert d["estimators"]["tilted (ref)"]["mean"]["heading"] == pytest.approx(10.0, abs=1e-6)
    assert "tilted (q)" in d["not_available"] and "tilted (q)" not in d["estimators"]
    assert "not available: tilted (q)" in err.replace("\n", " ")
    for c in ("vqf", "imufusion"):
        assert (c in d["estimators"]) == competitors.available(c)
        if competitors.available(c):      # the settings each competitor ran with are stated
            desc = competitors.get(c).description
            assert d["estimators"][c]["settings"] == desc
            assert f"{c}: {desc}" in " ".join(out.split())
    pngs = list((tmp_path / "d").glob("*.png"))
    assert [p.name for p in pngs] == ["32_disturbed_attached_magnet_1cm_perfect_f32.png"]
    assert pngs[0].read_bytes()[:8] == PNG_MAGIC and str(pngs[0]) in out.replace("\n", "")


def test_demo_without_kinefuse_filters(kf, monkeypatch, tmp_path):
    if not competitors.available("vqf"):
        pytest.skip("vqf not installed")

    def missing():
        raise KinefuseError("kinefuse filters are not available (test)")
    monkeypatch.setattr(accuracy, "load_runner", missing)
    code, out, err = kf("demo", "--out", str(tmp_path), "--jobs", "1")
    assert code == 0, err
    assert "kinefuse filters are not available" in err and "vqf" in out
    assert (tmp_path / "32_disturbed_attached_magnet_1cm_vqf.png").exists()


def test_demo_budget_keeps_the_first_estimator(kf, two_filters, tmp_path):
    code, out, err = kf("demo", "--out", str(tmp_path), "--jobs", "1", "--budget", "0.001")
    assert code == 0, err
    d = json.loads((tmp_path / "accuracy.json").read_text())
    assert list(d["estimators"]) == ["perfect (f32)"]
    assert "tilted (ref)" in d["skipped"] and "skipped (time budget" in err


def test_demo_bad_output_folder(kf, tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    code, out, err = kf("demo", "--out", str(blocker / "sub"))
    assert code == 2 and "cannot create the output folder" in err


def test_plot_file_and_name_lookup(kf, tmp_path, monkeypatch):
    monkeypatch.setattr(broad, "shared_broad_dir", lambda: None)
    out_png = tmp_path / "p.png"
    path = broad.bundled_trials()[1]
    code, out, err = kf("plot", "--input", str(path), "--filter", "tilted", "--out", str(out_png))
    assert code == 0, err
    assert out.strip() == str(out_png) and out_png.read_bytes()[:8] == PNG_MAGIC
    assert "RMSE total 10.00°" in err
    # a trial number resolves in the default data (here the excerpt); default file name
    monkeypatch.chdir(tmp_path)
    code, out, err = kf("plot", "--input", "24", "--start", "40", "--end", "60")
    assert code == 0, err
    assert (tmp_path / "24_disturbed_tapping_A_perfect_ref.png").exists()
    code, out, err = kf("plot", "--help")      # the default named in the help is the one written
    assert "<trial>_<filter>_<impl>.png" in " ".join(out.split())


def test_plot_keeps_an_earlier_png_unless_forced(kf, tmp_path, monkeypatch):
    monkeypatch.setattr(broad, "shared_broad_dir", lambda: None)
    out_png = tmp_path / "p.png"
    out_png.write_bytes(b"an earlier plot")
    argv = ("plot", "--input", "24", "--filter", "tilted", "--out", str(out_png))
    code, out, err = kf(*argv)
    assert code == 2 and "exists (use --force" in err and err.count("\n") == 1
    assert out_png.read_bytes() == b"an earlier plot"       # refused before any work
    code, out, err = kf(*argv, "--force")
    assert code == 0, err
    assert out_png.read_bytes()[:8] == PNG_MAGIC


@pytest.mark.parametrize("argv, message", [
    (["--input", "nosuchtrial"], "no such file, and no trial of that name"),
    (["--input", "/no/such/file.mat"], "/no/such/file.mat: no such file"),
    (["--input", "24", "--filter", "all"], "plot takes one filter"),
    (["--input", "24", "--out", "x.jpg"], "name it *.png"),
    (["--input", "24", "--start", "30", "--end", "10"], "need start < end, got 30 and 10"),
    (["--input", "24", "--start", "999"], "the trial ends at 75.0 s"),
    (["--input", "24", "--filter", "bogus"], "unknown filter 'bogus'"),
])
def test_plot_errors(kf, monkeypatch, argv, message):
    monkeypatch.setattr(broad, "shared_broad_dir", lambda: None)
    code, out, err = kf("plot", *argv)
    assert code == 2 and message in err
    assert err.count("\n") == 1 and "Traceback" not in err


def test_euler_zyx_from_hand_built_quaternions():
    import math

    def q_axis(axis, deg):
        h = math.radians(deg) / 2
        return np.r_[math.cos(h), math.sin(h) * np.asarray(axis, float)]

    def mul(a, b):
        w1, x1, y1, z1 = a
        w2, x2, y2, z2 = b
        return np.array([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                         w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2])

    # R = Rz(yaw)·Ry(pitch)·Rx(roll) is the quaternion product qz ⊗ qy ⊗ qx
    q = mul(mul(q_axis([0, 0, 1], 130.0), q_axis([0, 1, 0], -35.0)), q_axis([1, 0, 0], 60.0))
    assert plots.euler_zyx_deg(q[None])[0] == pytest.approx([130.0, -35.0, 60.0], abs=1e-9)
    assert np.isnan(plots.euler_zyx_deg(np.full((1, 4), np.nan))).all()


def test_plot_states_the_pitch_and_roll_signs(tmp_path, monkeypatch):
    """ZYX of sensor->ENU gives pitch > 0 with the sensor x axis below the horizontal (the
    opposite of the nose-up pitch of NED, which `kinefuse live` shows for a NED unit); the figure
    said only 'ZYX of sensor->ENU', and the signs are checked here on hand-built poses."""
    import math
    from matplotlib.figure import Figure
    h = math.radians(30) / 2
    nose_down = np.array([[math.cos(h), 0.0, math.sin(h), 0.0]])     # +30° about y: x·Up = -0.5
    y_up = np.array([[math.cos(h), math.sin(h), 0.0, 0.0]])          # +30° about x: y·Up = +0.5
    assert plots.euler_zyx_deg(nose_down)[0] == pytest.approx([0.0, 30.0, 0.0], abs=1e-9)
    assert plots.euler_zyx_deg(y_up)[0] == pytest.approx([0.0, 0.0, 30.0], abs=1e-9)
    titles = []
    monkeypatch.setattr(Figure, "savefig", lambda self, *a, **k: titles.append(self._suptitle.get_text()))
    trial = broad.load_trial(broad.bundled_trials()[0]).window(0, 500)
    plots.plot_estimate(trial, trial.quat_ref, "reference", tmp_path / "p.png")
    assert "pitch > 0: sensor x below the horizontal" in titles[0], titles
    assert "roll > 0: sensor y above it" in titles[0], titles


def test_demo_removes_its_own_earlier_plot_only(kf, two_filters, tmp_path, monkeypatch):
    """An earlier run plotted 'perfect (f32)'; when this run plots another estimator (the first
    one failed), that PNG stayed beside the new one and passed for this run's plot.  The user's
    own files -- a `kinefuse plot` PNG of the same default name pattern among them -- stay."""
    d = tmp_path / "d"
    assert kf("demo", "--out", str(d), "--jobs", "1", "--budget", "0.001")[0] == 0
    first = d / "32_disturbed_attached_magnet_1cm_perfect_f32.png"
    assert first.exists()
    mine = {d / "32_disturbed_attached_magnet_1cm_tilted_ref.png": b"user's kinefuse plot",
            d / "notes.png": b"user's picture", d / "notes.txt": b"user's notes"}
    for path, data in mine.items():
        path.write_bytes(data)
    # the default filter now is 'tilted' (e.g. 'perfect' no longer built)
    monkeypatch.setattr(FAKE, "default_filter", lambda: "tilted")
    code, out, err = kf("demo", "--out", str(d), "--jobs", "1", "--budget", "0.001")
    assert code == 0, err
    second = d / "32_disturbed_attached_magnet_1cm_tilted_f32.png"
    assert second.read_bytes()[:8] == PNG_MAGIC
    assert not first.exists(), "the earlier run's plot of another filter was left behind"
    assert json.loads((d / "accuracy.json").read_text())["plot"] == second.name
    assert all(path.read_bytes() == data for path, data in mine.items())
    assert sorted(p.name for p in d.glob("*.png")) == sorted(
        [second.name, "32_disturbed_attached_magnet_1cm_tilted_ref.png", "notes.png"])


@pytest.mark.parametrize("recorded", [
    {"data": "bundled BROAD excerpt", "plot": "../outside.png"},     # not a name in the folder
    {"data": "bundled BROAD excerpt", "plot": "notes.txt"},          # not a PNG
    {"data": "something else", "plot": "notes.png"},                 # not a demo's JSON
    {"data": "bundled BROAD excerpt", "plot": "sub.png"},            # a folder, not a file
])
def test_demo_removes_nothing_a_json_does_not_name_as_its_plot(kf, two_filters, tmp_path, recorded):
    d = tmp_path / "d"
    d.mkdir()
    (d / "accuracy.json").write_text(json.dumps(recorded))
    keep = [tmp_path / "outside.png", d / "notes.txt", d / "notes.png"]
    for path in keep:
        path.write_bytes(b"user data")
    (d / "sub.png").mkdir()
    assert kf("demo", "--out", str(d), "--jobs", "1", "--budget", "0.001")[0] == 0
    assert all(path.read_bytes() == b"user data" for path in keep) and (d / "sub.png").is_dir()
