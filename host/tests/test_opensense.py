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
        # each row on the arc between the two replayed samples around it, as far along it as
        # its time is between theirs (a bound of 0.5 deg to the nearest sample failed about one
        # run in six: the flagship's first step after its start can be 1.8 deg)
        k = np.searchsorted(rep[:, 0], t, side="right") - 1
        assert k.min() >= 0 and k.max() < len(rep) - 1
        a, b = rep[k, 1:], rep[k + 1, 1:]

        def ang(x, y):      # deg, from the vector part of conj(x)*y (arccos is coarse near 0)
            w = np.sum(x * y, axis=1)
            v = x[:, :1] * y[:, 1:] - y[:, :1] * x[:, 1:] - np.cross(x[:, 1:], y[:, 1:])
            return np.degrees(2 * np.arctan2(np.linalg.norm(v, axis=1), np.abs(w)))

        ab, ar, rb = ang(a, b), ang(a, q), ang(q, b)
        assert np.max(ar + rb - ab) < 1e-4, (name, np.max(ar + rb - ab))
        u = (t - rep[k, 0]) / (rep[k + 1, 0] - rep[k, 0])
        far = ab > 0.2
        assert np.max(np.abs(ar[far] - u[far] * ab[far])) < 1e-4, name
    assert "sensor_to_opensim_rotations" in err
    _one_line_error(run("opensense", two, "--imu", "1=pelvis_imu", "--out", out), "exists")


@pytest.mark.parametrize("argv, text", [
    (["--imu", "pelvis_imu"], "choose one with --unit"),
    (["--imu", "1=pelvis imu"], "is not an IMU frame name"),
    (["--imu", "1=a_imu", "--imu", "2=a_imu"], "the name a_imu is given twice"),
    (["--imu", "1=a_imu", "--imu", "1=b_imu"], "unit 1 is given twice"),
    (["--imu", "1=a_imu", "--imu", "b_imu"], "give each one's unit"),
    (["--imu", "=a_imu"], "expected UNIT=NAME"),
    (["--imu", "1=time"], "'time' names the table's time column"),     # was a second time column
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


# ------------------------------------------------------------------ review fixes (2026-12-04)
@pytest.fixture(scope="module")
def three(tmp_path_factory):
    from kinefuse.host.link.recorder import Recorder
    p = tmp_path_factory.mktemp("osim3") / "three.kfr"
    Recorder(p, ["fake:unit=1,rate=200", "fake:unit=2,rate=100", "fake:unit=3,rate=100"]).run(1.0)
    return p


def _cells(path):
    """{column: {time text: cell text}} of a written table, as the file holds them."""
    lines = path.read_text().splitlines()
    end = lines.index("endheader")
    names = lines[end + 1].split("\t")
    rows = [ln.split("\t") for ln in lines[end + 2:]]
    return {n: {r[0]: r[j] for r in rows} for j, n in enumerate(names) if j}


def test_a_kfr_is_decoded_once_for_all_its_units(run, three, tmp_path, monkeypatch):
    """Three units decoded the whole file three times; the table is the same as each unit's own."""
    from kinefuse.host.link import frames
    calls = []
    decode = frames.decode_file

    def counting(*a, **k):
        calls.append(a[0])
        return decode(*a, **k)

    monkeypatch.setattr(frames, "decode_file", counting)
    out = tmp_path / "all.sto"
    imus = ("1=pelvis_imu", "2=femur_r_imu", "3=tibia_r_imu")
    code, _, err = run("opensense", three, *[a for i in imus for a in ("--imu", i)], "--rate", "100",
                       "--out", out)
    assert code == 0, err
    assert len(calls) == 1, calls
    together = _cells(out)
    assert list(together) == ["pelvis_imu", "femur_r_imu", "tibia_r_imu"]
    # each unit alone (one decode each either way) gives the same cells on the same 100 Hz rows
    for imu in imus:
        one = tmp_path / f"{imu.split('=')[1]}.sto"
        assert run("opensense", three, "--imu", imu, "--rate", "100", "--out", one)[0] == 0
        name = imu.split("=")[1]
        alone = _cells(one)[name]
        assert together[name] and set(together[name]) <= set(alone)
        assert all(alone[t] == cell for t, cell in together[name].items()), name


def test_one_unit_under_two_spellings_is_refused(run, kfr, tmp_path):
    two, _ = kfr
    out = tmp_path / "d.sto"
    _one_line_error(run("opensense", two, "--imu", "1=a_imu", "--imu", "s0:1=b_imu", "--out", out),
                    "unit 1 is already given as a_imu")
    assert not out.exists()


def test_a_gap_just_before_the_common_span_is_found(run, kfr, tmp_path, monkeypatch):
    """Unit 1 has no samples 0.30..0.55 s and unit 2 starts at 0.45 s: the first rows were
    interpolated over the 0.25 s gap (only samples within one row of the span were checked)."""
    from kinefuse.host.commands import replay_cmd
    from kinefuse.host.readers.recording import Recording
    two, _ = kfr
    read = replay_cmd.read_imu_recording

    kept = {}

    def cut(path, unit):
        rec = read(path, unit)
        t = rec.t
        keep = (t < 0.30) | (t > 0.55) if unit == "1" else t >= 0.45
        kept[unit] = t[keep]
        r = Recording(t[keep], rec.acc[keep], rec.gyr[keep], None if rec.mag is None else rec.mag[keep],
                      None, {k: v[keep] for k, v in rec.channels.items()}, rec.fs, rec.source, rec.fmt,
                      dict(rec.metadata), list(rec.warnings))
        if rec.mag_t is not None:
            sel = np.isin(rec.mag_t, r.t)
            r.mag_t, r.mag_native = rec.mag_t[sel], rec.mag_native[sel]
        return r

    monkeypatch.setattr(replay_cmd, "read_imu_recording", cut)
    out = tmp_path / "gap.sto"
    code, _, err = run("opensense", two, "--imu", "1=a_imu", "--imu", "2=b_imu", "--out", out)
    assert code == 2 and not out.exists(), err
    last = err.strip().splitlines()[-1]
    import re
    m = re.search(r"a_imu: ([\d.]+) s without samples after t = ([\d.]+) s", last)
    t1 = kept["1"]
    before = t1[t1 < 0.30][-1]                  # the gap made above, from the samples kept
    after = t1[t1 > 0.55][0]
    assert m and abs(float(m[1]) - (after - before)) < 6e-4 and abs(float(m[2]) - before) < 6e-4, last


def test_a_failed_write_leaves_the_earlier_table(run, kfr, tmp_path, monkeypatch):
    """The table was written in place: a write that failed half-way (a full disk) left a cut
    file, and with --force the earlier table was already gone."""
    from kinefuse.host import opensense
    _, lossy = kfr
    out = tmp_path / "w.sto"
    out.write_text("an earlier table\n")

    class Full:
        def __format__(self, spec):
            raise OSError(28, "No space left on device")

    monkeypatch.setattr(opensense, "OPENSIM_VERSION", Full())
    code, _, err = run("opensense", lossy, "--imu", "a_imu", "--out", out, "--force")
    assert code == 2 and "w.sto: No space left on device" in err.strip().splitlines()[-1], err
    assert out.read_text() == "an earlier table\n"
    assert [p.name for p in tmp_path.iterdir()] == ["w.sto"]


def test_one_imu_too_short_for_two_rows_says_so(run, kfr, tmp_path):
    """One IMU: "the IMUs' recordings overlap in time by less than two rows" named recordings
    that were not there."""
    _, lossy = kfr
    code, _, err = run("opensense", lossy, "--imu", "a_imu", "--out", tmp_path / "r.sto", "--rate", "1")
    last = err.strip().splitlines()[-1]
    assert code == 2 and "a_imu's samples span 0." in last and "less than two rows at 1 Hz" in last, err
    assert "overlap" not in err


def test_a_warning_about_the_file_is_given_once(run, three, tmp_path):
    """A truncated file was reported once per unit read from it."""
    data = three.read_bytes()
    cut = tmp_path / "cut.kfr"
    cut.write_bytes(data[:len(data) * 2 // 3])
    code, _, err = run("opensense", cut, "--imu", "1=a_imu", "--imu", "2=b_imu", "--imu", "3=c_imu",
                       "--out", tmp_path / "c.sto")
    assert code == 0, err
    assert err.count("the recording is truncated") == 1, err
