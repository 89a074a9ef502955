"""The generated filters on real data (the bundled BROAD excerpt; the 12 full trials when the
shared folder exists): C == model in every bit, deviation from the float64 reference, rejection of
bad samples, no NaN ever, accuracy and frames on BROAD."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.codegen import estimators
from kinefuse.codegen import runner as cg
from kinefuse.codegen.testing import random_imu
from kinefuse.host.bench.common import quat_angle_deg

IMU_FILTERS = [n for n, c in estimators.ESTIMATORS.items() if c.inputs.name == "imu"]
FIRST = ["madgwick", "mahony", "complementary"]
N = 4000


@pytest.fixture(scope="module")
def excerpt():
    from kinefuse.host import broad, runner
    out = []
    for f in broad.bundled_trials():
        t = broad.load_trial(f)
        inp = runner.imu_inputs(t)
        out.append((t.name, {k: v[:N] for k, v in inp.items()}))
    assert len(out) >= 2
    return out


def _differing(a: dict, b: dict) -> int:
    n = len(next(iter(a.values())))
    bad = np.zeros(n, bool)
    for k in a:
        bad |= np.any(cg.bits(a[k]).reshape(n, -1) != cg.bits(b[k]).reshape(n, -1), axis=1)
    return int(bad.sum())


@pytest.mark.parametrize("name", IMU_FILTERS)
def test_c_equals_model_on_broad_excerpt(name, excerpt):
    est = estimators.get(name)
    for system in est.systems:
        for trial, inp in excerpt:
            c = cg.run(name, system, inp, raw=True)
            m = cg.run(name, f"{system}-model", inp, raw=True)
            assert _differing(c, m) == 0, f"{name} {system} on {trial}"


@pytest.mark.parametrize("name", FIRST)
def test_deviation_from_reference_within_targets(name, excerpt):
    """Issue targets: f32 RMS <= 0.005 deg, max <= 0.05 deg; q RMS <= 0.05 deg, max <= 0.5 deg."""
    sq = {"f32": [], "q": []}
    for _, inp in excerpt:
        ref = cg.run(name, "ref", {k: v[:2000] for k, v in inp.items()})["q"]
        for system in ("f32", "q"):
            q = cg.run(name, system, {k: v[:2000] for k, v in inp.items()})["q"]
            sq[system].append(quat_angle_deg(ref, q))
    for system, (rms_max, max_max) in {"f32": (0.005, 0.05), "q": (0.05, 0.5)}.items():
        d = np.concatenate(sq[system])
        assert np.sqrt(np.mean(d ** 2)) <= rms_max and d.max() <= max_max, (system, d.max())


def _gyro_ok(inp) -> np.ndarray:
    g, dt = np.asarray(inp["gyr"], float), np.asarray(inp["dt"], float)
    return np.all(np.abs(g) <= 2000 * np.pi / 180, 1) & (dt > 0) & (dt <= 1.0)


def _expected_bad(inp) -> np.ndarray:
    """Independent count of the samples a filter must reject (or whose magnetometer it must drop)."""
    a, m = np.asarray(inp["acc"], float), np.asarray(inp["mag"], float)
    ok = _gyro_ok(inp) & np.all(np.abs(a) <= 16 * 9.80665, 1)
    mag_bad = inp["mag_valid"] & ~np.all(np.abs(m) <= 4900, 1)
    return ~ok | mag_bad


# Filters that judge each sensor on its own: a bad accelerometer reading drops only the
# accelerometer correction (the gyro still integrates, a good magnetometer still corrects), so
# only a bad gyro reading or time step holds the whole state.
PER_SENSOR = {"flagship", "eskf"}


@pytest.mark.parametrize("name", IMU_FILTERS)
def test_bad_samples_rejected_counted_and_never_nan(name):
    est = estimators.get(name)
    inp = random_imu(3000, seed=11, bad_fraction=0.1)
    bad = _expected_bad(inp)
    assert 100 < bad.sum() < 900
    for impl in ("ref",) + est.systems:
        out = cg.run(name, impl, inp)
        q = np.asarray(out["q"], float)
        assert np.all(np.isfinite(q)), impl
        assert np.allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-4 if impl != "q" else 2e-3)
        assert out["rejected"][-1, 0] == bad.sum(), impl
        # the state is kept on a rejected sample: the orientation does not move
        core_bad = bad & ~(inp["mag_valid"] & ~np.all(np.abs(inp["mag"]) <= 4900, 1))
        if name in PER_SENSOR:
            core_bad = ~_gyro_ok(inp)
        i = np.flatnonzero(core_bad[1:])[:50] + 1
        assert len(i) >= 20
        if name in PER_SENSOR:
            # the output is recomposed from the held state every sample (inclination ⊗ heading)
            assert np.abs(q[i] - q[i - 1]).max() <= {"ref": 1e-15}.get(impl, 2 ** -22), impl
        else:
            assert np.array_equal(q[i], q[i - 1]), impl


@pytest.mark.broad_full
def test_madgwick_on_the_12_trials_matches_the_published_filter():
    """Default gain, 12 BROAD trials, float32 C: total RMSE <= 6.28 deg (the ahrs package's
    Madgwick there, measured independently: notes/broad.md) and the frames right."""
    from kinefuse.host import broad, metrics, runner
    d = broad.shared_broad_dir()
    if d is None:
        pytest.skip("the 12 full BROAD trials are not available")
    totals, heads = [], []
    for f in broad.find_trials(d):
        t = broad.load_trial(f)
        res = runner.run_filter("madgwick", "f32", t)
        e = metrics.score(res.q, t.quat_ref, t.movement)
        totals.append(e["total"])
        heads.append(e["heading"])
    assert np.mean(totals) <= 6.285, np.mean(totals)
    assert max(heads) < 45.0          # a frame error shows up as ~90 or 180 deg of heading


def _full_trials() -> list:
    """The 12 full BROAD trials when the shared folder exists (else one placeholder that skips)."""
    from kinefuse.host import broad
    d = broad.shared_broad_dir()
    if d is None or not d.is_dir():
        return [pytest.param(None, id="no-broad")]
    try:
        return [pytest.param(f, id=f.stem) for f in broad.find_trials(d)]
    except Exception as exc:           # reported by the test, not as a collection error
        return [pytest.param(f"{d}: {exc}", id="broad-unreadable")]


FULL_TRIALS = _full_trials()
# the float64 reference runs ~8-10k samples/s, so its deviation is checked on the first REF_N
# samples (~35 s at BROAD's 285.7 Hz: the rest phase and the start of the movement) of every
# trial; the bits of C and model are compared on every sample
REF_N = 10_000
TARGETS = {"f32": (0.005, 0.05), "q": (0.05, 0.5)}   # (RMS, max) deviation from the reference, deg


@pytest.mark.broad_full
@pytest.mark.parametrize("path", FULL_TRIALS)
@pytest.mark.parametrize("name", FIRST)
def test_full_trial_bit_exact(name, path):
    """Issue targets on each of the 12 full BROAD trials (parametrised so xdist spreads them):
    every output sample of the generated C (f32 and q) has the bits of its Python model, and the
    orientation deviates from the float64 reference by f32 RMS <= 0.005 deg, max <= 0.05 deg, q
    RMS <= 0.05 deg, max <= 0.5 deg on the trial's first REF_N samples (each trial's RMS: stricter
    than the RMS over all trials that the issue states)."""
    from kinefuse.host import broad, runner
    if path is None:
        pytest.skip("the 12 full BROAD trials are not available")
    if isinstance(path, str):
        pytest.fail(path)
    assert len(FULL_TRIALS) == 12, [p.id for p in FULL_TRIALS]
    inp = runner.imu_inputs(broad.load_trial(path))
    assert len(inp["dt"]) > REF_N
    sub = {k: v[:REF_N] for k, v in inp.items()}
    ref = cg.run(name, "ref", sub)["q"]
    for system in ("f32", "q"):
        n_diff = _differing(cg.run(name, system, inp, raw=True),
                            cg.run(name, f"{system}-model", inp, raw=True))
        assert n_diff == 0, f"{name} {system} on {path.stem}: {n_diff} of {len(inp['dt'])} differ"
        d = quat_angle_deg(ref, cg.run(name, system, sub)["q"])
        rms, mx = float(np.sqrt(np.mean(d ** 2))), float(d.max())
        rms_max, max_max = TARGETS[system]
        assert rms <= rms_max and mx <= max_max, \
            f"{name} {system} on {path.stem}: RMS {rms:.3g} deg, max {mx:.3g} deg from the reference"


_H = 0.7071067811865476
START_ATTITUDES = [(1, 0, 0, 0), (0, 0, 0, 1), (0, 1, 0, 0), (0, 0, 1, 0), (_H, 0, 0, _H),
                   (_H, 0, 0, -_H), (0, _H, _H, 0), (0, _H, -_H, 0), (0.01, 0.99995, 0, 0)]


@pytest.mark.parametrize("system", ["ref", "f32", "q"])
@pytest.mark.parametrize("name", IMU_FILTERS)
def test_first_sample_gives_the_orientation_for_any_attitude(name, system):
    """The orientation taken from the first sample (gravity + field, at rest) is right for every
    attitude, including upside down and facing magnetic south, where half-angle quaternion
    forms degenerate (the eskf started at the identity there)."""
    from kinefuse.hil_tests.harness import motion
    if system != "ref" and system not in getattr(estimators.get(name), "systems", ("f32", "q")):
        pytest.skip(f"{name} has no {system} build")
    rng = np.random.default_rng(7)
    quats = [np.array(q, float) / np.linalg.norm(q) for q in START_ATTITUDES]
    quats += [q / np.linalg.norm(q) for q in rng.normal(size=(12, 4))]
    for q0 in quats:
        ins, _ = motion.synth(q0, np.zeros((3, 3)), 0.01, field=motion.field_enu(0.0))
        q = cg.run(name, system, ins, estimators.get(name).default_params())["q"][0]
        err = float(quat_angle_deg(q[None, :], q0[None, :])[0])
        assert err < 0.2, f"started at {np.round(q0, 4)}: first estimate {np.round(q, 4)} ({err:.2f} deg off)"


@pytest.mark.parametrize("system", ["f32", "q"])
@pytest.mark.parametrize("name", FIRST)
def test_start_waits_for_a_magnetometer_reading(name, system):
    """With the magnetometer at 20 Hz, a stream that begins on a sample without a reading
    started from gravity alone: 33-34 deg of heading error, still 17-25 deg after 35 s (their
    magnetic corrections are slow).  The start now waits (up to MAG_WAIT_S) for a reading."""
    from kinefuse.codegen.estimators.common import MAG_WAIT_S
    from kinefuse.hil_tests.harness.motion import errors_deg
    from kinefuse.hil_tests.harness.scenarios import sim_case

    case = sim_case("slow_rotation", seconds=4.0)
    first = int(np.flatnonzero(~case.inputs["mag_valid"].astype(bool))[0])
    c = case.window(first, case.n)                    # starts on a sample without a reading
    wait = int(np.flatnonzero(c.inputs["mag_valid"].astype(bool))[0])
    assert 0 < wait < 10
    out = cg.run(name, system, c.inputs)
    tot, _head, _inc = errors_deg(np.asarray(out["q"], float), c.q_true)
    idle = out["q"][0]                  # the output before the start (madgwick's frame turn of 1)
    assert np.all(out["q"][:wait] == idle) and np.any(out["q"][wait] != idle)
    assert tot[wait:].max() < 3.0, tot[wait:].max()
    # without any reading the start comes after MAG_WAIT_S of samples, from gravity (6D)
    no_mag = dict(c.inputs, mag_valid=np.zeros(c.n, bool))
    q6 = cg.run(name, system, no_mag)["q"]
    k = int(np.flatnonzero(np.any(q6 != idle, axis=1))[0])
    assert MAG_WAIT_S <= np.sum(no_mag["dt"][:k]) <= MAG_WAIT_S + 3 * np.median(no_mag["dt"])
