"""``kinefuse bench seed004``: the servo protocol with a stated measurement model."""
from __future__ import annotations

import argparse
import io
import json
import math
from contextlib import redirect_stdout

import numpy as np
import pytest

from kinefuse.host import cli
from kinefuse.host.bench import seed004


def _args(**kw):
    d = dict(seed=0, rate_hz=35.0, duration_s=20.0, amplitude_deg=20.0, noise_deg=1.8,
             latency_ms=23.0, takes=1)
    d.update(kw)
    return argparse.Namespace(**d)


def _phase(t, y, w):
    """Phase φ of y = A sin(w t + φ) by least squares."""
    b, _, _, _ = np.linalg.lstsq(np.stack([np.sin(w * t), np.cos(w * t)], 1), y, rcond=None)
    return math.atan2(b[1], b[0]), math.hypot(b[0], b[1])


def test_take_follows_the_stated_model():
    w = 10.0
    t, truth, z = seed004.make_take(w, 0, _args(noise_deg=0.0))
    assert np.isclose(t[1] - t[0], 1 / 35.0)
    p_truth, a_truth = _phase(t, truth, w)
    p_z, a_z = _phase(t, z, w)
    assert abs(a_truth - math.radians(20.0)) < 1e-9 and abs(a_z - math.radians(20.0)) < 1e-9
    lag = ((p_truth - p_z) % (2 * math.pi)) / w                    # z is the truth, late
    assert abs(lag - 0.023) < 1e-9
    _, _, z2 = seed004.make_take(w, 0, _args(noise_deg=0.0))
    assert np.array_equal(z, z2)                                   # reproducible


def test_raw_rmse_equals_noise_without_latency():
    vals = []
    for k in range(3):
        t, truth, z = seed004.make_take(5.0, k, _args(latency_ms=0.0, duration_s=60.0))
        vals.append(seed004.rmse_deg(z, truth, t))
    assert abs(np.mean(vals) - 1.8) < 0.1


def test_bench_json_and_filters_beat_raw_noise():
    buf = io.StringIO()
    with redirect_stdout(buf):
        code = cli.main(["bench", "seed004", "--json", "--takes", "2", "--duration-s", "12",
                         "--latency-ms", "0", "--omegas", "1,10", "--bitexact"])
    assert code == 0
    text = buf.getvalue().strip()
    assert text.count("\n") == 0
    d = json.loads(text)
    assert d["finite"] and set(d["rmse_deg"]) == {"1", "10"}
    for w in ("1", "10"):
        r = d["rmse_deg"][w]
        assert set(r) == {"RAW", "KF", "EKF", "UKF", "SR-UKF"}
        for k in ("EKF", "UKF", "SR-UKF"):
            assert r[k] < r["RAW"]                # white noise, no latency: smoothing helps
    for name, r in d["bitexact"].items():
        assert r["f32"]["differing"] == 0 and r["q"]["differing"] == 0, name


def test_bad_arguments_are_one_line_errors(capsys):
    assert cli.main(["bench", "seed004", "--omegas", "a,b"]) == 2
    assert cli.main(["bench", "seed004", "--filters", "vac"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and all(e.startswith("kinefuse: error:") for e in err)


@pytest.mark.parametrize("argv, text", [
    (["--omegas", "-1"], "--omegas -1: each must be a positive angular frequency"),   # was a ValueError
    (["--omegas", "nan"], "--omegas nan:"),                                          # was a ValueError
    (["--omegas", "200"], "below the sampling limit π·rate = 110"),
    (["--takes", "0"], "--takes 0: must be 1 to 1000"),                              # was NaN RMSEs
    (["--rate-hz", "nan"], "--rate-hz nan"),
    (["--amplitude-deg", "0"], "--amplitude-deg 0"),
    (["--duration-s", "2.5"], "the first 2 s are warm-up"),
    (["--noise-deg", "inf"], "--noise-deg inf"),
    (["--latency-ms", "5000"], "within the warm-up"),
    (["--filters", ","], "--filters ',': names no filter"),                         # ran RAW alone
    (["--filters", "angle-kf,angle-kf", "--takes", "1", "--duration-s", "4", "--omegas", "1"],
     "--filters names angle-kf twice"),                     # each take filtered twice, one mean
    (["--omegas", "1,1.0", "--takes", "1", "--duration-s", "4"],
     "--omegas names 1 twice"),                             # simulated twice, one row shown
])
def test_bad_protocols_are_one_line_errors_before_any_work(capsys, argv, text):
    assert cli.main(["bench", "seed004", "--json", *argv]) == 2
    out, err = capsys.readouterr()
    lines = err.strip().splitlines()
    assert out == "" and len(lines) == 1 and lines[0].startswith("kinefuse: error:") and text in lines[0], err
