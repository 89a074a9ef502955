"""Reader validation beyond the layouts: non-finite values, misplaced time columns, impossible
time stamps and unexpected rates each give one line naming the file, the line and the problem
(or a one-line warning for a rate), and never a Python warning or an internal error."""
import warnings

import numpy as np
import pytest

from kinefuse.host import cli
from kinefuse.host.readers import ReaderError, read_recording
from kinefuse.host.tests.test_readers import DOT, MB_HEAD, matrix_text, metabase_text


@pytest.fixture(autouse=True)
def _no_python_warnings():
    with warnings.catch_warnings():
        warnings.simplefilter("error")          # a RuntimeWarning (e.g. a bad cast) fails the test
        yield


def write(tmp_path, name, text):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return str(p)


def error(path, *parts):
    with pytest.raises(ReaderError) as e:
        read_recording(path)
    msg = str(e.value)
    assert "\n" not in msg and msg.startswith(path), msg
    for part in parts:
        assert part in msg, msg
    return msg


# ----------------------------------------------------------------------------- MATRIX
@pytest.mark.parametrize("cell", ["nan", "inf", "-inf", "1e400"])
def test_matrix_non_finite_values_refused(tmp_path, cell):
    rows = matrix_text(5).splitlines()
    rows[3] = rows[3].replace("-2.13623047", cell)          # gyr_y of the 3rd sample, line 4
    error(write(tmp_path, "m.csv", "\n".join(rows) + "\n"), "line 4", "gyr_y", "not a finite number")


def test_matrix_all_nan_file_refused(tmp_path):
    rows = matrix_text(5).splitlines()
    for i in range(1, len(rows)):
        cells = rows[i].split(",")
        cells[1:7] = ["nan"] * 6
        rows[i] = ",".join(cells)
    error(write(tmp_path, "allnan.csv", "\n".join(rows) + "\n"), "line 2", "acc_x", "not a finite number")


# ----------------------------------------------------------------------------- MetaBase
def test_metabase_magnetometer_without_its_time_column(tmp_path):
    head = ("x-axis (T),y-axis (T),z-axis (T),elapsed (s),x-axis (g),y-axis (g),z-axis (g),"
            "x-axis (deg/s),y-axis (deg/s),z-axis (deg/s)")
    rows = [head] + [f"1e-5,2e-5,-3e-5,{i / 100:.2f},0,0,1,0.1,0.2,0.3" for i in range(50)]
    error(write(tmp_path, "mb.csv", "\n".join(rows) + "\n"), "line 1", "'x-axis (T)'", "no 'elapsed (s)' column before it")
    head = ("temperature (C),elapsed (s),x-axis (g),y-axis (g),z-axis (g),"
            "x-axis (deg/s),y-axis (deg/s),z-axis (deg/s)")
    rows = [head] + [f"24.6,{i / 100:.2f},0,0,1,0.1,0.2,0.3" for i in range(50)]
    error(write(tmp_path, "mbt.csv", "\n".join(rows) + "\n"), "line 1", "'temperature (C)'", "no 'elapsed (s)'")


@pytest.mark.parametrize("cell", ["nan", "inf", "1e400"])
def test_metabase_non_finite_is_not_an_incomplete_row(tmp_path, cell):
    rows = metabase_text(40).splitlines()
    cells = rows[5].split(",")
    cells[2] = cell                                           # y-axis (g), line 6
    rows[5] = ",".join(cells)
    msg = error(write(tmp_path, "mb.csv", "\n".join(rows) + "\n"), "line 6", "y-axis (g)", "not a finite number")
    assert "incomplete" not in msg


def test_metabase_rates_warned(tmp_path):
    r = read_recording(write(tmp_path, "ok.csv", metabase_text(200)))
    assert not any("rate is" in w for w in r.warnings), r.warnings          # 100 Hz, magnetometer 20 Hz
    rows = [MB_HEAD]                                                         # the same at 50 Hz / 10 Hz
    for i, line in enumerate(metabase_text(200).splitlines()[1:]):
        c = line.split(",")
        c[0] = f"{i / 50:.2f}"
        if c[7]:
            c[7] = f"{i * 0.1:.2f}"
        rows.append(",".join(c))
    r = read_recording(write(tmp_path, "slow.csv", "\n".join(rows) + "\n"))
    rate = [w for w in r.warnings if "rate is" in w]
    assert len(rate) == 2 and all("\n" not in w and w.startswith(str(tmp_path)) for w in rate), r.warnings
    assert any("magnetometer rate is 10 Hz, not the expected 20 Hz" in w for w in rate)
    assert any("accelerometer/gyroscope rate is 50 Hz, not the expected 100 Hz" in w for w in rate)


# ----------------------------------------------------------------------------- Xsens DOT
@pytest.mark.parametrize("value, line", [("1e30", 4), ("-16667", 4), ("4294967296", 4), ("1296799150.5", 4)])
def test_dot_sample_time_fine_must_be_a_uint32(tmp_path, value, line):
    p = write(tmp_path, "dot.csv", DOT.replace("1296799150", value))
    error(p, f"line {line}", "SampleTimeFine", "not a 32-bit microsecond count")


def test_dot_rate_warned(tmp_path):
    r = read_recording(write(tmp_path, "dot60.csv", DOT))
    assert not any("rate is" in w for w in r.warnings)
    rows = DOT.splitlines()
    fast = [rows[0]] + [",".join([c.split(",", 2)[0], str(1_000_000 + 10_000 * i), c.split(",", 2)[2]])
                        for i, c in enumerate(rows[1:])]
    r = read_recording(write(tmp_path, "dot100.csv", "\n".join(fast) + "\n"))
    assert any("rate is 100 Hz, not the expected 60 or 120 Hz" in w for w in r.warnings), r.warnings


# ----------------------------------------------------------------------------- static detection
def test_too_short_for_static_detection_names_the_file(tmp_path, monkeypatch, capsys):
    rows = DOT.splitlines()
    p = write(tmp_path, "two.csv", "\n".join([rows[0], rows[2], rows[3]]) + "\n")
    monkeypatch.setattr(cli, "COMMAND_MODULES", ["kinefuse.host.commands.calibrate_cmd"])
    monkeypatch.setattr(cli, "BENCH_MODULES", [])
    code = cli.main(["calibrate", "gyro", "--input", p])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1, err
    assert f"{p}: recording too short for static detection" in err
    from kinefuse.host.calib import static
    with pytest.raises(Exception, match="x.csv: recording too short"):
        static.detect_static(np.arange(2.0), np.zeros((2, 3)), source="x.csv")
