"""File-format readers: common structure, unit conversion, one-line errors with file and line."""
import os

import numpy as np
import pytest

from kinefuse.host.readers import ReaderError, Recording, detect_format, read_recording
from kinefuse.host.readers import kinefuse_csv

DEG = np.pi / 180
G = 9.80665

# --- seed 002 Table 5.2 (Xsens DOT 7): the first row is the empty first sample of an export
DOT = """PacketCounter,SampleTimeFine,Quat_W,Quat_X,Quat_Y,Quat_Z,Acc_X,Acc_Y,Acc_Z,Gyr_X,Gyr_Y,Gyr_Z
1,1296765816,0.308877,-0.304444,-0.650356,0.623656,-0.001530,0.103020,-0.006737,-0.123482,-0.067595,-0.015765
2,1296782483,0.308961,-0.304368,-0.650093,0.623925,0.230834,-9.812376,-0.302961,0.872452,-1.218473,0.667858
3,1296799150,0.309023,-0.304255,-0.649977,0.624070,0.238591,-9.804417,-0.307012,0.870672,-1.167478,0.588420
4,1296815817,0.309052,-0.304140,-0.649957,0.624133,0.243156,-9.813269,-0.309342,0.755043,-1.144337,0.634574
5,1296832484,0.309073,-0.304026,-0.649963,0.624172,0.225606,-9.806728,-0.293527,0.834532,-1.139855,0.591660
6,1296849151,0.309060,-0.303952,-0.649934,0.624244,0.236724,-9.807701,-0.321841,0.802721,-1.151099,0.635701
"""


def write(tmp_path, name, text):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return str(p)


def one_line(exc, *parts):
    msg = str(exc.value)
    assert "\n" not in msg
    for part in parts:
        assert part in msg, msg


def test_xsens_dot_seed_rows(tmp_path):
    p = write(tmp_path, "dot.csv", DOT)
    assert detect_format(p) == "xsens-dot"
    r = read_recording(p)
    assert isinstance(r, Recording) and r.fmt == "xsens-dot"
    assert len(r) == 5                                   # empty first sample dropped
    assert any("first sample" in w and "line 2" in w for w in r.warnings)
    assert r.fs == pytest.approx(1e6 / 16667, rel=1e-6)  # 60 Hz
    assert r.t[0] == pytest.approx(1296.782483)
    np.testing.assert_allclose(r.acc[0], [0.230834, -9.812376, -0.302961])
    np.testing.assert_allclose(r.gyr[0], np.array([0.872452, -1.218473, 0.667858]) * DEG)
    np.testing.assert_allclose(np.linalg.norm(r.quat, axis=1), 1.0)


def test_a_path_object_reads_like_its_string(tmp_path):
    """read_recording(Path) was an AttributeError (path.lower()) inside format detection."""
    p = write(tmp_path, "dot.csv", DOT)
    from pathlib import Path
    assert detect_format(Path(p)) == "xsens-dot"
    r = read_recording(Path(p))
    np.testing.assert_array_equal(r.acc, read_recording(p).acc)


def test_xsens_dot_errors_name_file_and_line(tmp_path):
    rows = DOT.splitlines()
    back = rows[:4] + [rows[4].replace("1296815817", "1296700000")] + rows[5:]
    p = write(tmp_path, "back.csv", "\n".join(back) + "\n")
    with pytest.raises(ReaderError) as e:
        read_recording(p)
    one_line(e, "back.csv", "line 5", "goes backwards")
    p = write(tmp_path, "nan.csv", DOT.replace("-9.804417", "abc"))
    with pytest.raises(ReaderError) as e:
        read_recording(p)
    one_line(e, "nan.csv", "line 4", "'Acc_Y'", "not a number")
    # acceleration exported in g instead of m/s²
    g_rows = [rows[0]] + [",".join(c if i not in (6, 7, 8) else str(float(c) / 9.81)
                                   for i, c in enumerate(r.split(","))) for r in rows[2:]]
    p = write(tmp_path, "g.csv", "\n".join(g_rows) + "\n")
    with pytest.raises(ReaderError) as e:
        read_recording(p)
    one_line(e, "g.csv", "looks like g")
    p = write(tmp_path, "dps.csv", DOT.replace("0.870672", "3000.5"))
    with pytest.raises(ReaderError) as e:
        read_recording(p)
    one_line(e, "dps.csv", "line 4", "wrong unit")


def test_xsens_dot_counter_wrap_and_preamble(tmp_path):
    st = (2**32 - 33334) + 16667 * np.arange(6)
    st = st % 2**32
    lines = ["DOT 7 export", "", "SampleTimeFine,Acc_X,Acc_Y,Acc_Z"]
    lines += [f"{s},0.1,0.2,9.8" for s in st]
    r = read_recording(write(tmp_path, "wrap.csv", "\n".join(lines) + "\n"))
    np.testing.assert_allclose(np.diff(r.t), 0.016667)
    assert any("wrapped" in w for w in r.warnings)
    assert r.metadata["preamble"][0] == "DOT 7 export"


# --- seed 002 Table 5.3 (MATRIX): minute-resolution dateTime, sentinel 8191, remarks
def matrix_text(n, fs=100.0, start="04/05/2023 09:16", gap_at=None, gap_s=30.0):
    import datetime as dt
    t0 = dt.datetime.strptime(start, "%d/%m/%Y %H:%M") + dt.timedelta(seconds=17)
    head = "dateTime,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,bodySurface_temp,Ambient_temp,hr_raw,hr,remarks"
    out = [head]
    k = 0
    for i in range(n):
        if gap_at is not None and i == gap_at:
            k += int(gap_s * fs)                # samples lost
        stamp = (t0 + dt.timedelta(seconds=k / fs)).strftime("%d/%m/%Y %H:%M")
        extra = "20.0,18.0,8191,0,Medida del antebrazo" if i == 0 else ",,8191,0,"
        out.append(f"{stamp},0.99319437,-0.00073242,0.01562548,0.36622211,-2.13623047,1.40385144,{extra}")
        k += 1
    return "\n".join(out) + "\n"


def test_matrix_units_sentinel_and_clock(tmp_path):
    # 3 min 10 s; 20 Hz keeps the test fast (the app records 100 Hz, the reader's default)
    p = write(tmp_path, "m.csv", matrix_text(3800, fs=20.0))
    assert detect_format(p) == "matrix"
    r = read_recording(p, fs=20.0)
    assert r.fs == 20.0 and len(r) == 3800
    np.testing.assert_allclose(r.acc[0], np.array([0.99319437, -0.00073242, 0.01562548]) * G)
    np.testing.assert_allclose(r.gyr[0], np.array([0.36622211, -2.13623047, 1.40385144]) * DEG)
    assert np.all(np.isnan(r.channels["hr_raw"]))          # 8191 = no reading
    assert r.metadata["remarks"] == ["Medida del antebrazo"]
    assert r.metadata["body_surface_temp_C"] == 20.0
    assert r.metadata["fs_from_clock"] == pytest.approx(20.0)
    # the wrong nominal rate contradicts the clock (the default 100 Hz here)
    with pytest.raises(ReaderError) as e:
        read_recording(p)
    one_line(e, "m.csv", "rate")
    # 2 min of samples missing: the time base disagrees with the minute stamps
    p = write(tmp_path, "gap.csv", matrix_text(1800, fs=20.0, gap_at=600, gap_s=150.0))
    with pytest.raises(ReaderError) as e:
        read_recording(p, fs=20.0)
    one_line(e, "gap.csv", "line 602", "clock says", "samples missing")
    # 30 s missing is within a minute stamp's resolution but shows in the per-minute count
    p = write(tmp_path, "gap30.csv", matrix_text(3800, fs=20.0, gap_at=1400))
    with pytest.raises(ReaderError) as e:
        read_recording(p, fs=20.0)
    one_line(e, "gap30.csv", "line", "samples")


def test_matrix_sentinel_in_sensor_column_and_decimal_comma(tmp_path):
    text = matrix_text(5).splitlines()
    text[3] = text[3].replace("0.99319437", "8191")
    with pytest.raises(ReaderError) as e:
        read_recording(write(tmp_path, "s.csv", "\n".join(text) + "\n"))
    one_line(e, "s.csv", "line 4", "8191")
    semi = matrix_text(5).replace(",", ";").replace("0.99319437", "0,99319437")
    semi = semi.replace("0.", "0,").replace("1.", "1,").replace("2.", "2,").replace("18.0", "18,0").replace("20.0", "20,0")
    r = read_recording(write(tmp_path, "semi.csv", semi))
    assert r.acc[0, 0] == pytest.approx(0.99319437 * G)


# --- seed 001 Fig. 8.6 (MetaBase combined sheet)
MB_HEAD = ("elapsed (s),x-axis (g),y-axis (g),z-axis (g),x-axis (deg/s),y-axis (deg/s),z-axis (deg/s),"
           "elapsed (s),x-axis (T),y-axis (T),z-axis (T),elapsed (s),temperature (C)")


def metabase_text(n=200, step=0.061, mag_unit=1e-6):
    rng = np.random.default_rng(0)
    lines = [MB_HEAD]
    for i in range(n):
        acc = f"{-0.065:.3f},{0.449:.3f},{0.885:.3f}"
        gy = ",".join(f"{v:.3f}" for v in np.round(rng.normal(0, 5, 3) / step) * step)
        row = f"{i / 100:.2f},{acc},{gy}"
        # magnetometer (20 Hz) and thermometer (1 Hz) samples fill the top rows of their
        # columns and end early, as in the seed's sheet
        if i < n // 5:
            row += f",{i * 0.05:.2f},{-12.75 * mag_unit:.6g},{-6.875 * mag_unit:.6g},{-1.5 * mag_unit:.6g}"
        else:
            row += ",,,,"
        row += f",{i:.0f},24.6" if i < n // 100 else ",,"
        lines.append(row)
    return "\n".join(lines) + "\n"


def test_metabase_combined_sheet(tmp_path):
    p = write(tmp_path, "step-muslo.csv", metabase_text())
    assert detect_format(p) == "metabase"
    r = read_recording(p, gyro_range_dps=500)
    assert r.fs == pytest.approx(100.0)
    np.testing.assert_allclose(r.acc[0], np.array([-0.065, 0.449, 0.885]) * G)
    np.testing.assert_allclose(r.mag_native[0], [-12.75, -6.875, -1.5])        # T → µT
    assert len(r.mag_native) == 40 and r.metadata["mag_fs"] == pytest.approx(20.0)
    np.testing.assert_allclose(r.mag[3], r.mag_native[0])                      # held
    # quantised at the ±2000 °/s step although ±500 °/s was configured (seed 001)
    assert any("±2000 °/s range, but ±500 °/s was configured" in w for w in r.warnings), r.warnings
    assert r.metadata["gyr_range_dps_inferred"] == pytest.approx(0.061 * 32768, rel=0.01)


def test_metabase_errors(tmp_path):
    p = write(tmp_path, "ut.csv", metabase_text(mag_unit=1.0))    # µT values under a T header
    with pytest.raises(ReaderError) as e:
        read_recording(p)
    one_line(e, "ut.csv", "tesla")
    rows = metabase_text(20).splitlines()
    cells = rows[6].split(",")
    cells[2] = ""
    rows[6] = ",".join(cells)
    with pytest.raises(ReaderError) as e:
        read_recording(write(tmp_path, "hole.csv", "\n".join(rows) + "\n"))
    one_line(e, "hole.csv", "line 7")


def test_metabase_native_session_files(tmp_path):
    n = 300
    hdr = "epoc (ms),timestamp (-03:00),elapsed (s),x-axis ({u}),y-axis ({u}),z-axis ({u})"
    def f(sensor, rate, unit, vals, m):
        name = f"MetaWear_2023-03-13T10.11.12.123_C8AB_{sensor}_{rate}Hz_1.7.3.csv"
        rows = [hdr.format(u=unit)] + [f"{1678712000000 + 10 * i},2023-03-13T10.11.12.{i:03d},{i / float(rate):.3f},"
                                       + ",".join(f"{v:.6g}" for v in vals) for i in range(m)]
        return write(tmp_path, name, "\n".join(rows) + "\n")
    pa = f("Accelerometer", "100.000", "g", [0.0, 0.0, 1.0], n)
    f("Gyroscope", "100.000", "deg/s", [1.0, 0.0, 0.0], n - 3)
    f("Magnetometer", "25.000", "T", [2e-5, 0.0, -1e-5], n // 4)
    r = read_recording(pa)
    assert len(r) == n - 3 and any("cut to" in w for w in r.warnings)
    np.testing.assert_allclose(r.gyr[0], [DEG, 0, 0])
    np.testing.assert_allclose(r.mag[0], [20.0, 0, -10.0])
    assert set(r.metadata["files"]) == {"Accelerometer", "Gyroscope", "Magnetometer"}


# --- seed 004 Arduino serial CSV
def test_seed004_arduino(tmp_path):
    p = write(tmp_path, "elbow.txt", "10.5,11.2,10.9\n12.1,12.0,11.8\n13.0,12.7,12.9\n")
    assert detect_format(p) == "seed004-arduino"
    r = read_recording(p)
    assert r.fs == 35.0 and r.acc is None
    np.testing.assert_allclose(r.channels["angle_ukf_deg"], [11.2, 12.0, 12.7])
    np.testing.assert_allclose(np.diff(r.t), 1 / 35)
    with pytest.raises(ReaderError) as e:
        read_recording(p.replace("elbow", "elbow"), fmt="seed004-arduino", fs=-1)
    bad = write(tmp_path, "bad.txt", "RAW,UKF,EKF\n1,2,3\n4,5\n")
    with pytest.raises(ReaderError) as e:
        read_recording(bad, fmt="seed004-arduino")
    one_line(e, "bad.txt", "line 3", "3 comma-separated")
    huge = write(tmp_path, "huge.txt", "1,2,3\n4,5,900\n")
    with pytest.raises(ReaderError) as e:
        read_recording(huge, fmt="seed004-arduino")
    one_line(e, "huge.txt", "line 2", "angle")


# --- BROAD and the kinefuse CSV
BROAD = "/work/shared/data/broad/01_undisturbed_slow_rotation_A.mat"


@pytest.mark.skipif(not os.path.exists(BROAD), reason="BROAD data not present")
def test_broad_mat():
    r = read_recording(BROAD)
    assert r.fmt == "broad-mat" and r.fs == pytest.approx(285.714, abs=1e-3)
    assert r.acc.shape == r.gyr.shape == r.mag.shape == (len(r), 3)
    assert 9.0 < np.median(np.linalg.norm(r.acc, axis=1)) < 10.6
    assert r.channels["opt_quat_wxyz"].shape == (len(r), 4)


def test_bundled_npz_trial_reads_like_its_mat(tmp_path):
    """calibrate/report take the bundled excerpt's .npz trials; same arrays as load_trial."""
    from kinefuse.host.broad import bundled_trials, load_trial
    p = str(bundled_trials()[0])
    r, tr = read_recording(p), load_trial(p)
    assert r.fmt == "broad-mat" and r.fs == tr.rate_hz and len(r) == tr.n
    for a, b in ((r.acc, tr.acc), (r.gyr, tr.gyr), (r.mag, tr.mag), (r.t, tr.t)):
        assert np.array_equal(a, b)
    assert np.array_equal(r.channels["opt_quat_wxyz"], tr.quat_ref, equal_nan=True)
    np.savez(tmp_path / "other.npz", x=np.zeros(3))
    with pytest.raises(ReaderError) as e:
        read_recording(str(tmp_path / "other.npz"))
    one_line(e, "other.npz", "missing")


def test_kinefuse_csv_roundtrip_and_errors(tmp_path):
    t = np.arange(50) / 100.0
    rec = Recording(t=t, acc=np.tile([0, 0, 9.81], (50, 1)), gyr=np.zeros((50, 3)),
                    quat=np.tile([1.0, 0, 0, 0], (50, 1)), channels={"temp_C": np.full(50, 25.0)})
    p = str(tmp_path / "k.csv")
    kinefuse_csv.write(p, rec, comments=["simulated"])
    r = read_recording(p)
    assert r.fmt == "kinefuse-csv" and r.mag is None and r.metadata["comments"] == ["simulated"]
    np.testing.assert_allclose(r.acc, rec.acc)
    np.testing.assert_allclose(r.channels["temp_C"], 25.0)
    text = open(p).read().replace("acc_z_mps2", "accz")
    with pytest.raises(ReaderError) as e:
        read_recording(write(tmp_path, "inc.csv", text))
    one_line(e, "inc.csv", "incomplete acc")
    with pytest.raises(ReaderError) as e:
        read_recording(write(tmp_path, "dup.csv", "t_s,acc_x_mps2,acc_y_mps2,acc_z_mps2\n0,0,0,9.8\n0,0,0,9.8\n"))
    one_line(e, "dup.csv", "line 3", "repeats")
    # a gyroscope in deg/s under its own name was read as "no gyroscope data"
    deg = open(p).read().replace("gyr_x_radps", "gyr_x_dps").replace("gyr_y_radps", "gyr_y_dps") \
        .replace("gyr_z_radps", "gyr_z_dps")
    with pytest.raises(ReaderError) as e:
        read_recording(write(tmp_path, "deg.csv", deg))
    one_line(e, "deg.csv", "column gyr_x_dps", "gyr_x_radps")


def test_unknown_format_and_missing_file(tmp_path):
    with pytest.raises(ReaderError) as e:
        read_recording(write(tmp_path, "x.csv", "hello,world\nfoo,bar\n"))
    one_line(e, "x.csv", "unknown recording format")
    with pytest.raises(ReaderError) as e:
        read_recording(str(tmp_path / "nope.csv"))
    one_line(e, "nope.csv", "not found")
    with pytest.raises(ReaderError) as e:          # was: "unknown recording format"
        read_recording(write(tmp_path, "empty.csv", ""))
    one_line(e, "empty.csv", "file is empty (0 bytes)")


def test_cr_line_endings_and_a_stray_cr(tmp_path):
    """Excel's "CSV (Macintosh)" ends lines with a lone \\r, and a damaged file may hold one
    inside a line: read (or a one-line error with the line), not csv.Error's internal error."""
    t = np.arange(20) / 100.0
    rec = Recording(t=t, acc=np.tile([0, 0, 9.81], (20, 1)), gyr=np.zeros((20, 3)))
    p = str(tmp_path / "k.csv")
    kinefuse_csv.write(p, rec)
    text = open(p).read()
    cr = tmp_path / "mac.csv"
    cr.write_bytes(text.replace("\n", "\r").encode())
    r = read_recording(str(cr))
    np.testing.assert_allclose(r.t, t)
    lines = text.splitlines()
    k = next(i for i, ln in enumerate(lines) if ln.startswith("0.05"))
    lines[k] = lines[k].replace(",0", ",\r0", 1)          # a stray \r inside row k
    bad = tmp_path / "cr_in_row.csv"
    bad.write_bytes("\n".join(lines).encode())
    with pytest.raises(ReaderError) as e:
        read_recording(str(bad))
    one_line(e, "cr_in_row.csv", f"line {k + 2}: t_s goes backwards")   # its second half
