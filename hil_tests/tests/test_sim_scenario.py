"""Scenario format, library, outputs (BROAD layout, raw firmware samples, files) and the CLI."""
import argparse
import json

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from kinefuse.hil_tests import sim
from kinefuse.hil_tests.sim import cli_cmd
from kinefuse.hil_tests.sim import quat as Q
from kinefuse.hil_tests.sim.signals import Profile
from kinefuse.host.errors import KinefuseError

REQUIRED = {"rest", "slow_rotation", "fast_rotation", "translation", "gait", "hinge_static", "hinge_dynamic",
            "magnetic_disturbance", "tapping", "vibration", "bias_1dps", "jitter_and_drops"}


def test_library_has_the_named_set():
    assert REQUIRED <= set(sim.names())


@pytest.mark.parametrize("name", sim.names())
def test_every_library_scenario_runs(name):
    recs = sim.run(name, seed=1)
    assert recs
    for unit, r in recs.items():
        n = len(r)
        assert n > 100
        for k in ("gyr", "acc", "mag", "pos_true"):
            assert getattr(r, k).shape == (n, 3)
        assert r.q_true.shape == (n, 4)
        np.testing.assert_allclose(np.linalg.norm(r.q_true, axis=1), 1.0, atol=1e-12)
        assert np.all(np.isfinite(r.gyr)) and np.all(np.isfinite(r.acc)) and np.all(np.isfinite(r.mag))
        assert np.all(r.dt >= 0) and r.movement.dtype == bool
        assert r.meta["scenario"] == name and r.meta["sensor"] == unit
        # the JSON form reproduces the same recording
        sc = sim.Scenario.from_json(sim.scenario(name).to_json())
        again = sim.run(sc, seed=1)[unit]
        assert again.gyr.tobytes() == r.gyr.tobytes() and again.t.tobytes() == r.t.tobytes()
        break   # one unit is enough for the round trip; shapes above cover the first one


@pytest.mark.parametrize("bad,msg", [
    ({"name": "x", "motion": {"kind": "body", "segments": [{"type": "rest", "duration": 1, "speed": 2}]}}, "unknown key"),
    ({"name": "x", "motion": {"kind": "boat"}}, "motion.kind"),
    ({"name": "x", "motion": {"kind": "body", "segments": [{"type": "spin"}]}}, "unknown segment type"),
    ({"name": "x", "motion": {"kind": "body", "segments": [{"type": "rest", "duration": -1}]}}, "positive"),
    ({"name": "x", "motion": {"kind": "body", "segments": [{"type": "rest", "duration": 1}]},
      "sensor": {"preset": "bno055"}}, "unknown sensor preset"),
    ({"name": "x", "motion": {"kind": "body", "segments": [{"type": "rest", "duration": 1}]},
      "sensor": {"gyr": {"noise_rads": 1}}}, "noise_dps"),
    ({"name": "x", "motion": {"kind": "hinge", "joint": {"steps": [{"cycles": 2, "between_deg": [10, 20],
                                                                    "rate_dps": 10}]}}}, "must start at"),
    ({"name": "x", "motion": {"kind": "body", "segments": [{"type": "rest", "duration": 1}]},
      "timing": {"drop_prob": 1.5}}, "drop_prob"),
    ({"name": "x", "motion": {"kind": "body", "segments": [{"type": "rest", "duration": 1}]},
      "disturbances": [{"type": "field_scale", "t_start_s": 5, "t_end_s": 1, "factor": 2}]}, "t_end_s"),
    ({"name": "x", "motion": {"kind": "body", "segments": [{"type": "random_rotation", "duration": 5,
                                                            "n_sines": "abc"}]}}, "invalid value"),
    ({"name": "x", "motion": {"kind": "hinge", "joint": {"steps": [{"move_to_deg": 10, "rate_dps": 10,
                                                                    "blend_s": 0}]}}}, "blend"),
    # a negative rest before the walk started the gait before t = 0 (mid-stride, not from standing)
    ({"name": "x", "motion": {"kind": "gait", "duration_s": 5, "rest_before_s": -1}}, "rest_before_s: must be >= 0"),
    ({"name": "x", "motion": {"kind": "gait", "duration_s": 5, "rest_after_s": -1}}, "rest_after_s: must be >= 0"),
    # a NaN heading was an internal error (ValueError from the quaternion) at simulation time
    ({"name": "x", "motion": {"kind": "gait", "duration_s": 5, "heading_deg": float("nan")}}, "heading_deg: must be finite"),
    ({"name": "x", "motion": {"kind": "gait", "duration_s": 5, "hip_height_m": float("inf")}}, "hip_height_m: must be finite"),
    # a negative design RMS ran as its magnitude with the signs of the motion flipped
    ({"name": "x", "motion": {"kind": "body", "segments": [{"type": "random_rotation", "duration": 5,
                                                            "rms_rate_dps": -90}]}}, "rms_rate_dps: must be >= 0"),
    ({"name": "x", "motion": {"kind": "body", "segments": [{"type": "random_motion", "duration": 5,
                                                            "translation_rms_m": -0.1}]}}, "translation_rms_m: must be >= 0"),
    # 2.5 cycles ran as 2, 0 or -3 as none; a negative pause as no pause
    ({"name": "x", "motion": {"kind": "hinge", "joint": {"steps": [{"cycles": 2.5, "between_deg": [0, 20],
                                                                    "rate_dps": 10}]}}}, "cycles: must be a whole number"),
    ({"name": "x", "motion": {"kind": "hinge", "joint": {"steps": [{"cycles": 0, "between_deg": [0, 20],
                                                                    "rate_dps": 10}]}}}, "cycles: must be a whole number"),
    ({"name": "x", "motion": {"kind": "hinge", "joint": {"steps": [{"cycles": 1, "between_deg": [0, 20],
                                                                    "rate_dps": 10, "pause_s": -1}]}}}, "pause_s: must be >= 0"),
])
def test_bad_specs_give_one_line_errors(bad, msg):
    with pytest.raises(KinefuseError) as exc:
        sim.Scenario.from_dict(bad)
    assert msg in str(exc.value) and "\n" not in str(exc.value)


_REST1 = {"name": "x", "motion": {"kind": "body", "segments": [{"type": "rest", "duration": 1}]}}


@pytest.mark.parametrize("change,msg", [
    ({"seed": 1.5}, "seed: expected a whole number"),                      # ran as seed 1
    ({"sensor": []}, "sensor: expected an object"),                         # ran the default sensor
    ({"sensor": {"acc": {"noise_ref_rate_hz": 0}}}, "noise_ref_rate_hz"),   # ZeroDivisionError (exit 3)
    ({"sensor": {"acc": {"noise_ref_rate_hz": -100}}}, "noise_ref_rate_hz"),  # NaN samples
    ({"sensor": {"acc": {"noise_mg": -1}}}, "noise_mg: must be >= 0"),      # taken as +1 mg
    ({"sensor": {"gyr": {"bias_rw_dps_per_rt_s": -0.1}}}, "bias_rw_dps_per_rt_s: must be >= 0"),
    ({"sensor": {"acc": {"noise_mg": float("inf")}}}, "noise_mg: must be finite"),  # infinite samples
    ({"sensor": {"acc": {"lsb_mg": float("nan")}}}, "lsb_mg: must be a finite number"),  # no quantisation
    ({"sensor": {"mag": {"present": "no"}}}, "present: expected true or false"),  # bool("no") is True
    ({"timing": {"jitter_s": float("nan")}}, "timing.jitter_s: must be finite"),      # NaN instants
    ({"timing": {"clock_drift_ppm": float("inf")}}, "timing.clock_drift_ppm: must be finite"),
    ({"timing": {"clock_drift_ppm": -1e6}}, "clock_drift_ppm: must be > -1000000"),  # a stopped clock
    ({"earth": {"dip_deg": float("nan")}}, "earth.dip_deg: must be finite"),          # NaN field
    ({"earth": {"field_uT": float("inf")}}, "earth.field_uT: must be finite"),
    ({"earth": []}, "earth: expected an object"),                          # ran the default earth
    ({"earth": [["g", 3.7]]}, "earth: expected an object"),                 # read as {"g": 3.7}
    ({"timing": []}, "timing: expected an object"),
    ({"motion": {"kind": "hinge", "joint": {"steps": [{"hold_s": 1}]}},
      "sensor_overrides": {"distal": [["rate_hz", 50]]}}, "sensor_overrides.distal: expected an object"),                         # ran without timing errors
    ({"sensor": {"gyr": {"bits": 12.5}}}, "bits: must be a whole number"),  # ran as 12 bits
    ({"disturbances": [{"type": "taps", "times_s": [0.2, float("nan")]}]}, "times_s: must be finite"),  # no tap
    ({"disturbances": [{"type": "vibration", "t_start_s": 0, "t_end_s": 1, "ramp_s": -0.5}]},
     "ramp_s: must be >= 0"),                                              # ran without a ramp
    ({"disturbances": [{"type": "field_scale", "t_start_s": 0, "t_end_s": 1, "factor": 2,
                        "ramp_s": float("nan")}]}, "ramp_s: must be >= 0"),
])
def test_bad_sensor_and_seed_values_give_one_line_errors(change, msg):
    with pytest.raises(KinefuseError) as exc:
        sim.Scenario.from_dict({**_REST1, **change})
    assert msg in str(exc.value) and "\n" not in str(exc.value)


def test_whole_float_seed_and_valid_sensor_values_still_run():
    sc = sim.Scenario.from_dict({**_REST1, "seed": 3.0,
                                 "sensor": {"preset": "ideal", "acc": {"noise_mg": 0, "noise_ref_rate_hz": None},
                                            "mag": {"present": False}}})
    rec = sim.simulate(sc)
    assert rec.meta["seed"] == 3 and not rec.mag_valid.any()


def test_multi_unit_selection():
    with pytest.raises(KinefuseError, match="pass unit="):
        sim.simulate("gait")
    assert sim.simulate("gait", unit="shank").meta["sensor"] == "shank"


def test_to_broad_layout_and_metric_inputs():
    rec = sim.simulate("slow_rotation", seed=2)
    b = rec.to_broad()
    n = len(rec)
    assert b["imu_gyr"].shape == (n, 3) and b["imu_acc"].shape == (n, 3) and b["imu_mag"].shape == (n, 3)
    assert b["opt_quat"].shape == (n, 4) and b["opt_pos"].shape == (n, 3)
    assert b["movement"].shape == (n, 1) and b["movement"].dtype == np.uint8
    assert b["sampling_rate"].shape == (1, 1) and b["sampling_rate"][0, 0] == 100.0
    assert 0 < b["movement"].mean() < 1
    assert rec.to_broad(movement="all")["movement"].all()


def test_mat_file_loads_as_broad_trial(tmp_path):
    broad = pytest.importorskip("kinefuse.host.broad")
    rec = sim.simulate("tapping", seed=2)
    path = tmp_path / "tapping_sim.mat"
    rec.save(str(path))
    trial = broad.load_trial(path)
    np.testing.assert_array_equal(trial.gyr, rec.gyr)
    np.testing.assert_array_equal(trial.quat_ref, rec.q_true)
    np.testing.assert_array_equal(trial.movement, rec.movement)
    assert trial.rate_hz == 100.0


def test_same_seed_gives_the_same_mat_bytes(tmp_path, monkeypatch):
    """The .mat header carried the time of writing: the same seed gave different bytes."""
    import scipy.io
    import time
    rec = sim.simulate("rest", seed=3, duration_s=1.0)
    monkeypatch.setattr(time, "asctime", lambda *a: "Mon Jan  1 00:00:00 2024")
    rec.save(str(tmp_path / "a.mat"))
    monkeypatch.setattr(time, "asctime", lambda *a: "Tue Jan  2 11:11:11 2024")
    rec.save(str(tmp_path / "b.mat"))
    assert (tmp_path / "a.mat").read_bytes() == (tmp_path / "b.mat").read_bytes()
    np.testing.assert_array_equal(scipy.io.loadmat(str(tmp_path / "a.mat"))["imu_gyr"], rec.gyr)


def test_npz_round_trip(tmp_path):
    rec = sim.simulate("hinge_misaligned", seed=3, unit="distal")
    p = tmp_path / "r.npz"
    rec.save(str(p))
    back = sim.Recording.load(str(p))
    for k in ("t", "dt", "gyr", "acc", "mag", "mag_valid", "q_true", "movement", "pos_true", "t_true", "index"):
        np.testing.assert_array_equal(getattr(back, k), getattr(rec, k))
    np.testing.assert_array_equal(back.truth["joint_angle"], rec.truth["joint_angle"])
    assert back.meta == json.loads(json.dumps(rec.meta))


def test_raw_samples_match_firmware_struct():
    # kf_raw_sample: uint32 time_us; int16 acc[3], gyr[3], mag[3]; uint8 mag_valid → 24 bytes
    assert sim.RAW_DTYPE.itemsize == 24
    assert [sim.RAW_DTYPE.fields[k][1] for k in ("time_us", "acc", "gyr", "mag", "mag_valid")] == [0, 4, 10, 16, 22]
    rec = sim.simulate("jitter_and_drops", seed=4)
    raw = rec.to_raw(t0_us=2**32 - 5_000_000)          # the device clock wraps 5 s in
    lsb = rec.meta["lsb"]
    np.testing.assert_array_equal(raw["acc"], np.round(rec.acc / lsb["acc"]))
    np.testing.assert_array_equal(raw["gyr"], np.round(rec.gyr / lsb["gyr"]))
    np.testing.assert_array_equal(raw["mag"], np.round(rec.mag / lsb["mag"]))
    np.testing.assert_array_equal(raw["mag_valid"], rec.mag_valid)
    us = (np.round(rec.t * 1e6).astype(np.int64) + 2**32 - 5_000_000) % 2**32
    np.testing.assert_array_equal(raw["time_us"], us)
    assert raw["time_us"][0] > raw["time_us"][-1]       # wrapped
    with pytest.raises(KinefuseError, match="no LSB"):
        sim.simulate("rest", sensor={"preset": "ideal"}).to_raw()
    # matrix has no magnetometer: zero counts, never valid
    m = sim.simulate("rest", sensor={"preset": "matrix"}).to_raw()
    assert not m["mag"].any() and not m["mag_valid"].any()


def _cli(argv, capsys):
    p = argparse.ArgumentParser()
    cli_cmd.register(p.add_subparsers())
    args = p.parse_args(argv)
    code = args.func(args)
    return code, capsys.readouterr()


def test_cli_list_show_run(tmp_path, capsys):
    code, out = _cli(["sim", "list", "--json"], capsys)
    assert code == 0 and REQUIRED <= set(json.loads(out.out)["scenarios"])
    code, out = _cli(["sim", "show", "hinge_dynamic_fast"], capsys)
    spec = tmp_path / "h.json"
    spec.write_text(out.out)
    code, out = _cli(["sim", "run", str(spec), "--seed", "5", "--preset", "xsens_dot", "--rate", "60",
                      "--out", str(tmp_path / "h.npz"), "--json"], capsys)
    summary = json.loads(out.out)
    assert code == 0 and set(summary["sensors"]) == {"proximal", "distal"}
    back = sim.Recording.load(summary["sensors"]["distal"]["file"])
    ref = sim.simulate("hinge_dynamic_fast", seed=5, unit="distal", sensor={"preset": "xsens_dot", "rate_hz": 60})
    np.testing.assert_array_equal(back.gyr, ref.gyr)
    code, out = _cli(["sim", "run", "rest", "--out", str(tmp_path / "r.bin"), "--json"], capsys)
    raw = np.frombuffer((tmp_path / "r.bin").read_bytes(), dtype=sim.RAW_DTYPE)
    assert len(raw) == json.loads(out.out)["sensors"]["imu"]["samples"] == 3001
    with pytest.raises(KinefuseError, match="unknown scenario"):
        _cli(["sim", "run", "no_such_scenario"], capsys)
    with pytest.raises(KinefuseError, match=".npz, .mat or .bin"):
        _cli(["sim", "run", "rest", "--out", str(tmp_path / "r.csv")], capsys)
    # an earlier file is kept: every sensor's file is checked before the first is written
    (tmp_path / "h_distal.npz").write_bytes(b"earlier")
    before = (tmp_path / "h_proximal.npz").stat().st_mtime_ns
    with pytest.raises(KinefuseError, match="h_proximal.npz exists \\(use --force"):
        _cli(["sim", "run", str(spec), "--out", str(tmp_path / "h.npz")], capsys)
    assert (tmp_path / "h_distal.npz").read_bytes() == b"earlier"
    assert (tmp_path / "h_proximal.npz").stat().st_mtime_ns == before
    code, out = _cli(["sim", "run", str(spec), "--out", str(tmp_path / "h.npz"), "--force"], capsys)
    assert code == 0 and sim.Recording.load(str(tmp_path / "h_distal.npz")).gyr.shape[1] == 3


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(["hold", "rate", "dur"]), st.floats(-200, 200), st.floats(0.05, 5.0),
                          st.floats(1e-3, 0.5)), min_size=1, max_size=6))
def test_profile_hits_targets_and_respects_rates(steps):
    """Profiles reach every target, never exceed the plateau rate, and are C² at breakpoints."""
    p = Profile(0.0)
    targets = []
    for kind, target, x, blend in steps:
        t_before = p.end_time
        if kind == "hold":
            p.hold(x)
        elif kind == "rate":
            p.move_to(target, rate=10 * x, blend=blend)
        else:
            p.move_to(target, duration=x, blend=blend)
        targets.append((p.end_time, p.end_value, kind, target, 10 * x, t_before))
    sig = p.build()
    for t_end, val, kind, target, rate, t_before in targets:
        if kind != "hold":
            assert abs(sig(np.array([t_end]))[0][0] - target) < 1e-9 * max(1.0, abs(target))
        if kind == "rate":
            tt = np.linspace(t_before, t_end, 201)
            assert np.abs(sig(tt)[1]).max() <= rate * (1 + 1e-9)
    # C¹ (in fact C²): each polynomial piece ends with the value, slope and curvature the next
    # one starts with
    pp = sig.pp
    for der in range(3):
        d = pp.derivative(der) if der else pp
        for i in range(len(pp.x) - 2):
            end = np.polyval(d.c[:, i], pp.x[i + 1] - pp.x[i])
            start = d.c[-1, i + 1]
            scale = max(1.0, np.polyval(np.abs(d.c[:, i]), pp.x[i + 1] - pp.x[i]))  # size of the terms
            assert abs(end - start) <= 1e-9 * scale, (der, i, end, start)


def _broad_errors_deg(q_est, q_ref, mask):
    """BROAD metric (Laidig et al. 2021), written out here: e = q_est ⊗ q_ref⁻¹."""
    e = Q.mul(Q.normalize(q_est), Q.conj(q_ref))
    total = 2 * np.arccos(np.clip(np.abs(e[:, 0]), 0, 1))
    heading = 2 * np.arctan(np.abs(e[:, 3] / e[:, 0]))
    incl = 2 * np.arccos(np.clip(np.sqrt(e[:, 0] ** 2 + e[:, 3] ** 2), 0, 1))
    return [float(np.degrees(np.sqrt(np.mean(x[mask] ** 2)))) for x in (total, heading, incl)]


@pytest.mark.parametrize("name,unit,max_total", [("slow_rotation", None, 1.5), ("gait", "shank", 3.0),
                                                 ("hinge_dynamic", "distal", 1.0)])
def test_reference_filter_agrees_with_truth(name, unit, max_total):
    """VQF (an independent implementation with the same ENU / +g / sensor→earth conventions)
    tracks q_true closely on simulated data: any frame, sign or unit slip in the simulator
    would show up as tens of degrees.  Measured (seed 1): 0.69°, 1.38°, 0.31° total RMSE."""
    vqf = pytest.importorskip("vqf")
    r = sim.simulate(name, seed=1, unit=unit)
    out = vqf.VQF(1.0 / r.rate_hz).updateBatch(np.ascontiguousarray(r.gyr), np.ascontiguousarray(r.acc),
                                               np.ascontiguousarray(r.mag))
    total, heading, incl = _broad_errors_deg(out["quat9D"], r.q_true, r.movement)
    assert total < max_total, (total, heading, incl)


def test_cli_refuses_a_rate_that_would_exhaust_memory(tmp_path, capsys):
    """--rate 1e9 used to allocate until the process was killed (exit 137, no message)."""
    with pytest.raises(KinefuseError, match="samples for sensor imu; at most"):
        _cli(["sim", "run", "rest", "--rate", "1e9", "--duration", "1",
              "--out", str(tmp_path / "r.npz")], capsys)
    with pytest.raises(KinefuseError, match="at most"):
        _cli(["sim", "run", "rest", "--mag-rate", "1e8", "--out", str(tmp_path / "r.npz")], capsys)
    assert not (tmp_path / "r.npz").exists()


def test_cli_refuses_a_mag_rate_for_a_sensor_without_magnetometer(tmp_path, capsys):
    """--mag-rate on the MATRIX preset (no magnetometer) was ignored, and the summary listed it."""
    with pytest.raises(KinefuseError, match="--mag-rate: the matrix sensor has no magnetometer"):
        _cli(["sim", "run", "rest", "--preset", "matrix", "--mag-rate", "50", "--duration", "1",
              "--out", str(tmp_path / "r.npz")], capsys)
    assert not (tmp_path / "r.npz").exists()


def test_cli_summary_counts_drops_at_the_end(tmp_path, capsys):
    """Samples dropped after the last delivered one were not counted (nominal count taken as
    the last delivered index + 1): a 1 s run with a gap over its second half said 0 drops."""
    f = tmp_path / "s.json"
    f.write_text(json.dumps({**_REST1, "timing": {"gaps_s": [[0.5, 2.0]]}}))
    code, out = _cli(["sim", "run", str(f), "--json"], capsys)
    s = json.loads(out.out)["sensors"]["imu"]
    assert code == 0 and s["samples"] == 50
    assert s["dropped"] == 51 and s["duplicated"] == 0       # nominal samples 50..100 of 0..100


def test_cli_refuses_a_scenario_file_that_is_not_text(tmp_path, capsys):
    """A scenario file in another encoding (or a binary file) was an internal error."""
    f = tmp_path / "latin1.json"
    f.write_bytes('{"name": "r\xe9sum\xe9"}'.encode("latin-1"))
    with pytest.raises(KinefuseError, match="not UTF-8 text") as exc:
        _cli(["sim", "run", str(f)], capsys)
    assert "\n" not in str(exc.value)


@pytest.mark.parametrize("disturbances,stream", [
    ([{"type": "field_scale", "t_start_s": 0, "t_end_s": 1, "factor": float("nan")}], "mag"),
    ([{"type": "taps", "times_s": [0.5], "acc_peak_ms2": float("nan")}], "acc"),
])
def test_nan_in_a_disturbance_is_refused_not_simulated(disturbances, stream):
    # (NaN magnetometer / accelerometer samples, and `kinefuse sim run` exited 0)
    with pytest.raises(KinefuseError) as exc:
        sim.simulate({**_REST1, "disturbances": disturbances})
    assert f"non-finite {stream}" in str(exc.value) and "\n" not in str(exc.value)


def test_an_overflowing_motion_is_one_error_without_numpy_warnings():
    """An absurd value (1e308 m at 1e10 Hz) printed a dozen numpy RuntimeWarnings with source
    lines on stderr before the one-line error."""
    import warnings
    spec = {"name": "x", "motion": {"kind": "body", "segments": [
        {"type": "translate", "direction": [1, 0, 0], "amplitude_m": 1e308, "freq_hz": 1e10, "duration": 1}]}}
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(KinefuseError, match="non-finite acc"):
            sim.simulate(spec)


def test_disturbances_must_be_a_list():
    # a single object was read as its keys: "disturbances[0]: expected an object with a 'type'"
    with pytest.raises(KinefuseError, match="disturbances: expected a list"):
        sim.Scenario.from_dict({**_REST1, "disturbances": {"type": "field_scale"}})


def test_a_sensor_without_magnetometer_is_not_refused_for_its_nan_field():
    rec = sim.simulate({**_REST1, "sensor": {"preset": "matrix"}})
    assert not rec.mag_valid.any() and np.all(np.isfinite(rec.acc))


# ---- counts that cannot hold the range (a tiny LSB) -------------------------------------------

_TINY_LSB = ("sensor.gyr: lsb_dps 0.001 × 32767 counts (16-bit words) is a full scale of ±32.77 °/s, "
             "below range_dps 2000 °/s")


@pytest.mark.parametrize("spec, argv, text", [
    # the scenario's own sensor: int16 counts of 0.001 °/s end at ±32.8 °/s, the range is ±2000
    ({"sensor": {"preset": "xsens_dot", "gyr": {"lsb_dps": 0.001}}}, [], _TINY_LSB),
    # a per-sensor LSB that holds the scenario's ±4 g (metamotionr) but not --preset matrix's ±16 g
    ({"sensor_overrides": {"imu": {"acc": {"lsb_mg": 0.13}}}}, [], None),
    ({"sensor_overrides": {"imu": {"acc": {"lsb_mg": 0.13}}}}, ["--preset", "matrix"],
     "sensor_overrides.imu.acc: lsb_mg 0.13 × 32767 counts (16-bit words) is a full scale of ±4.26 g, "
     "below range_g 16 g"),
    # fewer bits at the preset's LSB
    ({"sensor": {"preset": "metamotionr", "gyr": {"bits": 12}}}, [],
     "sensor.gyr: lsb_dps 0.01524 × 2047 counts (12-bit words) is a full scale of ±31.2 °/s, "
     "below range_dps 500 °/s"),
])
def test_counts_that_cannot_reach_the_range_are_refused(tmp_path, capsys, spec, argv, text):
    """A tiny LSB silently made the full scale LSB × 32767 (the int16 counts) instead of the range:
    the output clipped at ±32.8 °/s while the sensor claimed ±2000 °/s."""
    from kinefuse.host.cli import main
    f = tmp_path / "s.json"
    f.write_text(json.dumps({**_REST1, **spec}))
    out = tmp_path / "s.npz"
    code = main(["sim", "run", str(f), *argv, "--out", str(out)])
    err = capsys.readouterr().err
    if text is None:
        assert code == 0, err
        return
    assert code == 2 and "Traceback" not in err and len(err.strip().splitlines()) == 1, err
    assert text in err and "give lsb_" in err, err
    assert not out.exists()


def test_every_preset_reaches_its_range():
    """Data-sheet sensitivities are rounded (±2000 °/s at 16.4 LSB/(°/s) ends at 1998 °/s): the
    presets' own counts are accepted, and a range a whole count beyond them is not."""
    from kinefuse.hil_tests.sim.presets import PRESET_NAMES, preset
    for name in PRESET_NAMES:
        for ch in ("gyr", "acc", "mag"):
            getattr(preset(name), ch).check(f"{name}.{ch}")
    with pytest.raises(KinefuseError, match="range_dps 2020 °/s"):
        sim.simulate(_REST1, sensor={"preset": "xsens_dot", "gyr": {"range_dps": 2020}})
