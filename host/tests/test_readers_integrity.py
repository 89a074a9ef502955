"""Vendor files as real exports come: decimal commas with a tab or a first row of whole
numbers, UTF-16 (Excel's "Unicode Text"), two exports joined into one file."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.host.readers import ReaderError, detect_format, read_recording

from test_readers import DOT, matrix_text, one_line, write


def test_tab_separated_decimal_comma_reads_like_the_dot_file(tmp_path):
    """A tab-separated export with decimal commas (a comma-decimal locale): refused as
    "'-0,001530' is not a number"; only ';' files took a decimal comma."""
    want = read_recording(write(tmp_path, "dot.csv", DOT))
    p = write(tmp_path, "tab.csv", DOT.replace(",", "\t").replace(".", ","))
    got = read_recording(p)
    np.testing.assert_array_equal(got.t, want.t)
    np.testing.assert_array_equal(got.acc, want.acc)
    np.testing.assert_array_equal(got.quat, want.quat)


def test_decimal_comma_after_a_first_row_of_whole_numbers(tmp_path):
    """The decimal comma was judged from the first data row alone: a first row of whole
    numbers made "0,99" below it "not a number"."""
    rows = matrix_text(6).splitlines()
    first = rows[1].split(",")
    first[1:9] = ["1", "0", "0", "0", "0", "0", "20", "18"]
    rows[1] = ",".join(first)
    semi = "\n".join(r.replace(",", ";") for r in rows) + "\n"
    semi = semi.replace("0.", "0,").replace("1.", "1,").replace("2.", "2,")
    assert "," not in semi.splitlines()[1]
    r = read_recording(write(tmp_path, "semi.csv", semi))
    assert r.acc[0, 0] == pytest.approx(9.80665)
    assert r.acc[1, 0] == pytest.approx(0.99319437 * 9.80665)
    assert r.gyr[1, 1] == pytest.approx(np.radians(-2.13623047))


def test_utf16_export_reads_like_utf8(tmp_path):
    """Excel's "Unicode Text" saves UTF-16 with a BOM: an unknown recording format."""
    want = read_recording(write(tmp_path, "dot.csv", DOT))
    for enc in ("utf-16", "utf-16-be"):
        p = tmp_path / f"dot_{enc}.csv"
        p.write_bytes((b"\xfe\xff" if enc == "utf-16-be" else b"") + DOT.replace("\n", "\r\n").encode(enc))
        assert detect_format(str(p)) == "xsens-dot"
        got = read_recording(str(p))
        np.testing.assert_array_equal(got.acc, want.acc)
        np.testing.assert_array_equal(got.t, want.t)


def test_a_repeated_header_says_so(tmp_path):
    """Two exports joined into one file: "'SampleTimeFine' is not a number"."""
    lines = DOT.splitlines(True)
    p = write(tmp_path, "joined.csv", "".join(lines + lines))
    with pytest.raises(ReaderError) as e:
        read_recording(p)
    one_line(e, "joined.csv", "line 8", "header line repeats")


def test_dot_clock_restart_is_not_unwrapped_as_a_wrap(tmp_path):
    """SampleTimeFine falling from 4.0e9 to 1000 us (the sensor restarted its clock) was taken
    for a wrap of the 32-bit counter: the samples after it were silently placed ~5 minutes
    later (a "gap").  A true wrap still unwraps."""
    st = np.concatenate([4_000_000_000 + 16667 * np.arange(6), 1000 + 16667 * np.arange(6)])
    lines = ["SampleTimeFine,Acc_X,Acc_Y,Acc_Z"] + [f"{s},0.1,0.2,9.8" for s in st]
    with pytest.raises(ReaderError) as e:
        read_recording(write(tmp_path, "restart.csv", "\n".join(lines) + "\n"))
    one_line(e, "restart.csv", "line 8", "goes backwards", "not a wrap")
    st = (2**32 - 3 * 16667 + 5 + 16667 * np.arange(8)) % 2**32
    lines = ["SampleTimeFine,Acc_X,Acc_Y,Acc_Z"] + [f"{s},0.1,0.2,9.8" for s in st]
    r = read_recording(write(tmp_path, "wrap.csv", "\n".join(lines) + "\n"))
    np.testing.assert_allclose(np.diff(r.t), 0.016667)


def test_metabase_samples_lost_inside_the_gyroscope_file_do_not_shift_the_pairs(tmp_path):
    """Native MetaBase files are paired sample by sample: five gyroscope samples lost at 0.5 s
    (BLE) made every later gyroscope sample pair with the accelerometer sample 50 ms later
    (the turn at 1 s placed 5 samples early, silently)."""
    e0 = 1_678_712_000_000
    hdr = "epoc (ms),timestamp (-03:00),elapsed (s),x-axis ({u}),y-axis ({u}),z-axis ({u})"

    def f(sensor, unit, value, lost=()):
        name = f"MetaWear_2023-03-13T10.11.12.123_C8AB_{sensor}_100.000Hz_1.7.3.csv"
        rows = [hdr.format(u=unit)]
        for i in range(300):
            if i in lost:
                continue
            ep = e0 + 10 * i
            rows.append(f"{ep},2023-03-13T10.11.12.000,{i / 100:.3f}," + ",".join(f"{v:.6g}" for v in value(ep)))
        (tmp_path / name).write_text("\n".join(rows) + "\n")
        return str(tmp_path / name)
    step = e0 + 1000
    pa = f("Accelerometer", "g", lambda ep: [0.5 if ep >= step else 0.0, 0.0, 1.0])
    f("Gyroscope", "deg/s", lambda ep: [90.0 if ep >= step else 0.0, 0.0, 0.0], lost=range(50, 55))
    r = read_recording(pa)
    ia = int(np.argmax(r.acc[:, 0] > 1.0))
    ig = int(np.argmax(r.gyr[:, 0] > 0.5))
    assert ia == ig and r.t[ia] == pytest.approx(1.0, abs=1e-9)
    assert len(r) == 295 and not np.any((r.t > 0.495) & (r.t < 0.545))   # no invented pairs there
    assert any("paired by time" in w and "5 accelerometer" in w for w in r.warnings), r.warnings


@pytest.mark.parametrize("sep", [";", "\t"])
def test_decimal_commas_in_every_cell_do_not_make_the_comma_the_separator(tmp_path, sep):
    """With a decimal comma in every cell a line holds one comma more than separators: the
    comma was taken for the separator and the file read as one column ("no recognisable
    header")."""
    from kinefuse.host.readers import kinefuse_csv
    t = 0.005 * np.arange(1, 41)
    rows = ["t_s,acc_x_mps2,acc_y_mps2,acc_z_mps2"] + [f"{x:.3f},0.125,-0.25,9.806" for x in t]
    want = read_recording(write(tmp_path, "dot.csv", "\n".join(rows) + "\n"), fmt="kinefuse-csv")
    text = "\n".join(r.replace(",", sep).replace(".", ",") for r in rows) + "\n"
    p = write(tmp_path, "comma.csv", text)
    assert detect_format(p) == "kinefuse-csv"
    got = read_recording(p)
    np.testing.assert_array_equal(got.t, want.t)
    np.testing.assert_array_equal(got.acc, want.acc)
