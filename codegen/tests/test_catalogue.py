"""The seed catalogue (issue 7): algebraic quaternions, VAC/VAK/GUO, TRIAD, eCompass, and the
joint-angle Kalman filters — checked against independent constructions (rotation matrices,
finite differences, the `ahrs` package) and against simulated ground truth."""
from __future__ import annotations

import math

import numpy as np
import pytest

from kinefuse.codegen import estimators, runner
from kinefuse.codegen.estimators import algebraic as alg
from kinefuse.codegen.estimators.guo import guo_measurement
from kinefuse.codegen.linalg import Quat, Vec3

RNG = np.random.default_rng(20240607)
CATALOGUE = ("vac", "vak", "guo", "triad", "ecompass", "angle-kf", "angle-ekf", "angle-ukf",
             "angle-srukf")


def rot(q) -> np.ndarray:
    """Rotation matrix (sensor → earth) of a unit quaternion, written independently of linalg."""
    w, x, y, z = np.asarray(q, float) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def random_unit(n=3):
    v = RNG.normal(size=n)
    return v / np.linalg.norm(v)


def angle_deg(a, b) -> float:
    """Rotation angle between two orientations, 2 atan2(|v|, |w|) of a* ⊗ b (accurate near 0)."""
    a = np.asarray(a, float) / np.linalg.norm(a)
    b = np.asarray(b, float) / np.linalg.norm(b)
    e = np.array(Quat(*a).conj() * Quat(*b))
    return math.degrees(2.0 * math.atan2(np.linalg.norm(e[1:]), abs(e[0])))


def field(dip_deg: float) -> np.ndarray:
    d = math.radians(dip_deg)
    return np.array([0.0, math.cos(d), -math.sin(d)])          # ENU, dip positive downward


# ------------------------------------------------------------------------------------------------
# algebraic quaternions


def test_tilt_quaternion_maps_up_to_z_on_both_branches():
    seen = set()
    for _ in range(500):
        u = random_unit()
        q = np.array(alg.tilt_quaternion(Vec3(*u)))
        assert abs(np.linalg.norm(q) - 1.0) < 1e-12
        assert np.allclose(rot(q) @ u, [0.0, 0.0, 1.0], atol=1e-12)
        seen.add(u[2] >= 0.0)
    assert seen == {True, False}
    # exactly upside down: still a rotation taking -z to +z
    q = np.array(alg.tilt_quaternion(Vec3(0.0, 0.0, -1.0)))
    assert np.allclose(rot(q) @ [0.0, 0.0, -1.0], [0.0, 0.0, 1.0], atol=1e-12)


def test_tilt_correction_is_the_smallest_rotation():
    for _ in range(300):
        g = random_unit()
        dq = np.array(alg.tilt_correction(Vec3(*g)))
        assert dq[0] >= 0.0 and dq[3] == 0.0                      # no turn about the vertical
        assert np.allclose(rot(dq) @ g, [0.0, 0.0, 1.0], atol=1e-12)
        # the angle equals the angle between g and z: nothing more than needed
        assert abs(math.degrees(2 * math.acos(dq[0]))
                   - math.degrees(math.acos(np.clip(g[2], -1, 1)))) < 1e-8


def test_aqua_exact_tilt_and_north():
    for _ in range(300):
        q_true = random_unit(4)
        dip = RNG.uniform(-80.0, 80.0)
        a = rot(q_true).T @ [0.0, 0.0, 1.0]
        m = rot(q_true).T @ field(dip)
        q, _, l, gamma = alg.aqua(Vec3(*a), Vec3(*m))
        assert angle_deg(q, q_true) < 1e-6
        assert abs(gamma - math.cos(math.radians(dip)) ** 2) < 1e-9


def test_heading_quaternion_turns_to_north_and_flags_vertical_field():
    for _ in range(200):
        lx, ly = RNG.normal(size=2)
        q, gamma = alg.heading_quaternion(lx, ly)
        v = rot(q) @ [lx, ly, 0.0]
        assert abs(v[0]) < 1e-12 and v[1] > 0.0
        assert abs(q[1]) == 0.0 and abs(q[2]) == 0.0
    q, gamma = alg.heading_quaternion(1e-5, 0.0)
    assert gamma < 1e-6 and tuple(q) == (1.0, 0.0, 0.0, 0.0)


@pytest.mark.parametrize("angle_deg_", [10.0, 40.0, 120.0])
@pytest.mark.parametrize("gain", [0.0, 0.02, 0.5, 1.0])
def test_scale_correction_takes_the_fraction_of_the_rotation(angle_deg_, gain):
    """LERP (small rotations) and SLERP (large ones) both give a rotation about the same axis;
    SLERP gives exactly gain × angle, LERP its chordal approximation."""
    axis = random_unit()
    h = math.radians(angle_deg_) / 2.0
    dq = Quat(math.cos(h), *(math.sin(h) * axis))
    r = np.array(alg.scale_correction(dq, gain, 0.9))
    assert abs(np.linalg.norm(r) - 1.0) < 1e-9
    got = 2.0 * math.degrees(math.acos(min(1.0, r[0])))
    if dq.w <= 0.9:                                                 # SLERP: exact fraction
        assert abs(got - gain * angle_deg_) < 1e-6
    else:                                                           # LERP: within 2 %
        assert abs(got - gain * angle_deg_) <= 0.02 * angle_deg_ + 1e-9
    if gain > 0:
        assert np.allclose(r[1:] / np.linalg.norm(r[1:]), axis, atol=1e-9)


def test_m_matrix_is_the_small_rotation_map():
    q = random_unit(4)
    M = np.array(alg.m_matrix(Quat(*q)))
    assert np.allclose(M.T @ M, np.eye(3), atol=1e-12)
    assert np.allclose(M.T @ q, 0.0, atol=1e-12)
    assert np.allclose(M @ M.T, np.eye(4) - np.outer(q, q), atol=1e-12)
    d = 1e-7 * random_unit()
    dq = np.array(Quat(0.0, *d) * Quat(*q)) * 0.5
    assert np.allclose(dq, 0.5 * M @ d, atol=1e-20)


def test_heading_sigma_is_the_first_order_covariance_of_the_algebraic_quaternion():
    """Σ̃ of algebraic.heading_sigma against J Σ Jᵀ from finite differences of aqua()."""
    q_true = random_unit(4)
    dip = 55.0
    a = rot(q_true).T @ [0.0, 0.0, 1.0]
    m = rot(q_true).T @ field(dip)
    q0 = np.array(alg.aqua(Vec3(*a), Vec3(*m))[0])
    R = rot(q0)
    J = np.zeros((3, 6))
    h = 1e-7
    for k in range(6):
        aa, mm = a.copy(), m.copy()
        (aa if k < 3 else mm)[k % 3] += h
        q1 = np.array(alg.aqua(Vec3(*(aa / np.linalg.norm(aa))), Vec3(*(mm / np.linalg.norm(mm))))[0])
        q1 = q1 if np.dot(q1, q0) > 0 else -q1
        dq = Quat(*q1) * Quat(*q0).conj()
        J[:, k] = 2.0 * np.array(dq[1:]) / h                        # earth-frame rotation vector
    var_a, var_m = 2.0e-5, 7.0e-5                                   # per component, unit vectors
    cov = J @ np.diag([var_a] * 3 + [var_m] * 3) @ J.T
    lz = float((R @ m)[2])
    gamma = 1.0 - lz * lz
    t, smt = 1.0, var_m / var_a
    s, c = alg.heading_sigma(t, smt, gamma, lz, True)
    expect = var_a * np.array([[t, 0, 0], [0, t, c], [0, c, s]])
    assert np.allclose(cov, expect, rtol=1e-4, atol=1e-10)     # finite-difference noise ~1e-12
    # and the decoupled variant only drops the correlation
    s0, c0 = alg.heading_sigma(t, smt, gamma, lz, True, coupling=0.0)
    assert c0 == 0.0 and abs(s0 - s) < 1e-12


def test_guo_measurement_projects_onto_the_constraints_and_converges():
    q_true = random_unit(4)
    a = rot(q_true).T @ [0.0, 0.0, 1.0]
    m = rot(q_true).T @ field(64.0)
    q = q_true + 0.3 * RNG.normal(size=4)
    q /= np.linalg.norm(q)
    errs = []
    for _ in range(120):
        z, p2, ja, jm = guo_measurement(Quat(*q), Vec3(*a), Vec3(*m), True)
        q = np.array(z)
        assert np.allclose(rot(q) @ a, [0, 0, 1], atol=1e-10)       # the acc projector is exact
        errs.append(angle_deg(q, q_true))
    # alternating projections converge (linearly, at a rate set by the angle between the
    # two constraint spaces) to the exact solution
    assert errs[-1] < 1e-3 and all(b <= a + 1e-9 for a, b in zip(errs, errs[1:]))
    # Jacobian columns against finite differences (J = columns / |p|)
    z0, p20, ja, jm = guo_measurement(Quat(*q_true), Vec3(*a), Vec3(*m), True)
    for k in range(6):
        aa, mm = a.copy(), m.copy()
        (aa if k < 3 else mm)[k % 3] += 1e-7
        z1 = np.array(guo_measurement(Quat(*q_true), Vec3(*aa), Vec3(*mm), True)[0])
        fd = (z1 - np.array(z0)) / 1e-7
        col = np.array((ja if k < 3 else jm)[k % 3]) / math.sqrt(p20)
        assert np.allclose(fd, col, atol=2e-6)


def test_kf_update_matches_the_textbook_kalman_update():
    """algebraic.kf_identity_update (Cholesky, whitened) against K = P (P + R)⁻¹ in numpy."""
    A = RNG.normal(size=(4, 4))
    P = A @ A.T * 0.01
    B = RNG.normal(size=(4, 4))
    R = B @ B.T * 0.02 + 0.01 * np.eye(4)
    x = random_unit(4)
    z = random_unit(4)
    xn, Pn = alg.kf_identity_update(Quat(*x), P.tolist(), Quat(*z), R.tolist(), 1e-6, 1e3,
                                    1e3, 1e3)
    K = P @ np.linalg.inv(P + R)
    assert np.allclose(np.array(xn), x + K @ (z - x), atol=1e-12)
    assert np.allclose(np.array(Pn), (np.eye(4) - K) @ P, atol=1e-12)


def test_square_root_form_equals_the_plain_kalman_filter():
    """sr_predict / sr_update (VAK's and GUO's filter) carry a factor S of exactly the P that
    kf_predict / kf_identity_update (the plain form) give, and the same updated state."""
    for _ in range(5):
        A = RNG.normal(size=(4, 4))
        P = A @ A.T * 0.05 + 1e-3 * np.eye(4)
        B = RNG.normal(size=(4, 4))
        R = B @ B.T * 0.02 + 0.01 * np.eye(4)
        q = Quat(*random_unit(4))
        z = random_unit(4)
        x = q + Quat(*(0.01 * RNG.normal(size=4)))
        omega, dt, u_g = Vec3(*RNG.normal(size=3)), 0.01, 0.05
        S = np.linalg.cholesky(P)
        Sm = alg.sr_predict(S.tolist(), q, omega, dt, u_g)
        Pm = np.array(alg.kf_predict(P.tolist(), q, omega, dt, u_g * u_g, 1e3))
        assert np.allclose(np.array(Sm) @ np.array(Sm).T, Pm, atol=1e-12)
        assert np.allclose(np.triu(np.array(Sm), 1), 0.0)
        xs, Sn = alg.sr_update(Quat(*x), Sm, Quat(*z), R.tolist())
        xp, Pn = alg.kf_identity_update(Quat(*x), Pm.tolist(), Quat(*z), R.tolist(), alg.R_FLOOR,
                                        1e3, 1e3, alg.Y_MAX)
        assert np.allclose(np.array(xs), np.array(xp), atol=1e-12)
        assert np.allclose(np.array(Sn) @ np.array(Sn).T, np.array(Pn), atol=1e-12)


# ------------------------------------------------------------------------------------------------
# registry, presets


def test_catalogue_is_registered_with_the_seed_presets():
    for name in CATALOGUE:
        assert name in estimators.ESTIMATORS
    assert estimators.get("vac").resolve_params(None, "seed001") == pytest.approx(
        {**estimators.get("vac").default_params(), "gain_acc": 0.01, "gain_mag": 0.001,
         "adaptive": 1.0, "t1": 0.05, "t2": 0.15})
    vak = estimators.get("vak").resolve_params(None, "seed001")
    assert (vak["sigma_acc"], vak["sigma_gyr"], vak["sigma_mag"]) == (0.014, 0.004, 0.05)
    guo = estimators.get("guo").resolve_params(None, "seed001")
    assert (guo["var_acc"], guo["var_gyr"], guo["var_mag"]) == (0.001, 0.3, 0.4)
    mad = estimators.get("madgwick").resolve_params(None, "seed001")
    assert (mad["beta_start"], mad["start_time"], mad["beta"]) == (2.0, 2.0, 0.03)
    for name in ("angle-kf", "angle-ekf", "angle-ukf", "angle-srukf"):
        assert estimators.ESTIMATORS[name].inputs.name == "angle"


def test_adaptive_gain_erratum():
    """Just above t1 the factor is 1 (Valenti's printed (t2 - e)/t1 gives 1.98 there)."""
    from kinefuse.codegen.estimators.vac import adaptive_factor
    g, t1, t2 = 9.81, 0.05, 0.15
    assert adaptive_factor(g * (1 + 0.0501), g, t1, t2) == pytest.approx(0.999, abs=2e-3)
    assert adaptive_factor(g * 1.10, g, t1, t2) == pytest.approx(0.5, abs=1e-9)
    assert adaptive_factor(g * 1.20, g, t1, t2) == 0.0
    assert adaptive_factor(g, g, t1, t2) == 1.0


# ------------------------------------------------------------------------------------------------
# against an independent implementation and against ground truth


def _sim(name="slow_rotation", seed=3, **sensor):
    from kinefuse.hil_tests import sim
    s = {"preset": "metamotionr"}
    s.update(sensor)
    return sim.simulate(name, seed=seed, sensor=s)


def _inputs(rec, n=None):
    n = len(rec) if n is None else n
    return {"gyr": rec.gyr[:n], "acc": rec.acc[:n], "mag": rec.mag[:n],
            "mag_valid": rec.mag_valid[:n], "dt": rec.dt[:n]}


def _angles(q, ref):
    from kinefuse.host.bench.common import quat_angle_deg
    return quat_angle_deg(np.asarray(q, float), np.asarray(ref, float))


def test_vac_reproduces_the_ahrs_package_aqua():
    """With AQUA's constant gains, our VAC reference equals ahrs' AQUA (an independent Python
    implementation, NWU earth frame, earth→sensor quaternion) to rounding."""
    ahrs = pytest.importorskip("ahrs")
    rec = _sim(mag_rate_hz=100.0)
    n = 800
    Q = ahrs.filters.AQUA(gyr=rec.gyr[:n], acc=rec.acc[:n], mag=rec.mag[:n],
                          frequency=rec.rate_hz, alpha=0.01, beta=0.01, adaptive=False).Q
    nwu_to_enu = Quat(math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5))
    qa = np.array([tuple(nwu_to_enu * Quat(*q).conj()) for q in Q])
    q = runner.run("vac", "ref", _inputs(rec, n), estimators.get("vac").resolve_params(
        None, "valenti2015"))["q"]
    assert np.max(_angles(q, qa)) < 1e-9


@pytest.mark.parametrize("name", ("vac", "vak", "guo"))
def test_fusion_filters_track_the_truth_with_a_20hz_magnetometer(name):
    """Metamotionr sensor: gyroscope/accelerometer 100 Hz, magnetometer 20 Hz (mag_valid one
    sample in five); orientation from the first sample; slow random rotation."""
    rec = _sim()
    assert 0.15 < rec.mag_valid.mean() < 0.25
    q = runner.run(name, "f32", _inputs(rec))["q"]
    err = _angles(q, rec.q_true)
    assert err[0] < 1.5                                  # initialised from acc + mag at once
    assert np.sqrt(np.mean(err ** 2)) < 3.0
    assert np.all(np.isfinite(q))


@pytest.mark.parametrize("name", ("vac", "vak", "guo"))
def test_heading_set_by_the_first_field_reading_after_a_start_without_one(name):
    rec = _sim("rest", seed=5)
    inp = _inputs(rec, 1000)
    inp["mag_valid"] = inp["mag_valid"].copy()
    inp["mag_valid"][:300] = False                        # no magnetometer for 3 s
    q = runner.run(name, "f32", inp)["q"]
    err = _angles(q, rec.q_true[:1000])
    assert err[310] < 1.0 and err[-1] < 1.0


def test_triad_gravity_primary_equals_ecompass_and_field_primary_is_exact_with_the_right_dip():
    rec = _sim("rest", seed=2, mag_rate_hz=100.0, acc={"noise_mg": 0}, gyr={"noise_dps": 0},
               mag={"noise_uT": 0, "lsb_uT": 0}, )
    n = 50
    inp = _inputs(rec, n)
    qe = runner.run("ecompass", "ref", inp)["q"]
    qt = runner.run("triad", "ref", inp)["q"]
    assert np.max(_angles(qe, qt)) < 1e-6                 # two constructions, one rotation
    dip = rec.meta["earth"]["dip_deg"]
    qm = runner.run("triad", "ref", inp, {"primary": 1.0, "dip_deg": dip})["q"]
    assert np.max(_angles(qm, rec.q_true[:n])) < 0.05     # residual: acc quantisation only
    qw = runner.run("triad", "ref", inp, {"primary": 1.0, "dip_deg": dip - 10.0})["q"]
    assert np.min(_angles(qw, rec.q_true[:n])) > 5.0      # a wrong dip tilts field-primary TRIAD


@pytest.mark.parametrize("name", ("ecompass", "triad"))
def test_degenerate_means_parallel_only_and_held_says_why_q_was_kept(name):
    """degenerate: gravity and field within min_angle_deg of parallel; held: q is the last valid
    orientation (parallel, no magnetometer reading, free fall, rejected sample)."""
    n = 7
    acc = np.tile([0.0, 0.0, 9.81], (n, 1))
    acc[4] = [0.0, 0.0, 0.3]                     # free fall: gravity not observable
    acc[5] = [np.nan, 0.0, 9.81]                 # rejected sample
    mag = np.tile([0.0, 20.0, -40.0], (n, 1))
    mag[1] = [0.0, 0.5, -45.0]                   # 0.6 deg from the vertical
    mag[3] = [0.0, -30.0, -40.0]                 # turned: a different orientation
    inp = {"gyr": np.zeros((n, 3)), "acc": acc, "mag": mag, "mag_valid": [1, 1, 0, 1, 1, 1, 1],
           "dt": np.full(n, 0.01)}
    for impl in ("ref", "f32", "q"):
        out = runner.run(name, impl, inp)
        assert out["degenerate"][:, 0].tolist() == [False, True, False, False, False, False, False], impl
        assert out["held"][:, 0].tolist() == [False, True, True, False, True, True, False], impl
        assert out["rejected"][:, 0].tolist() == [0, 0, 0, 0, 0, 1, 1], impl
        assert np.allclose(out["q"][1], out["q"][0], atol=1e-6)   # held
        assert np.allclose(out["q"][2], out["q"][0], atol=1e-6)
        assert np.max(_angles(out["q"][3:4], out["q"][0:1])) > 30.0   # a new orientation ...
        assert np.allclose(out["q"][4], out["q"][3], atol=1e-6)      # ... then held twice
        assert np.allclose(out["q"][5], out["q"][3], atol=1e-6)
    # before the first valid orientation: the identity, held
    out = runner.run(name, "ref", {k: v[1:2] if k != "mag_valid" else [1] for k, v in inp.items()})
    assert out["held"][0, 0] and np.allclose(out["q"][0], [1.0, 0.0, 0.0, 0.0])


@pytest.mark.parametrize("name", ("angle-kf", "angle-ekf", "angle-ukf", "angle-srukf"))
def test_angle_filters_reduce_white_noise_on_a_sine(name):
    fs, w, a = 35.0, 5.0, math.radians(20.0)
    t = np.arange(700) / fs
    truth = a * np.sin(w * t)
    rng = np.random.default_rng(4)
    z = truth + rng.normal(0.0, math.radians(2.0), len(t))
    inp = {"angle": z, "angle_valid": np.ones(len(t), bool), "dt": np.full(len(t), 1 / fs)}
    est = runner.run(name, "f32", inp)["angle"][:, 0]
    m = t > 2.0
    raw = np.sqrt(np.mean((z - truth)[m] ** 2))
    got = np.sqrt(np.mean((est - truth)[m] ** 2))
    assert got < (0.95 if name == "angle-kf" else 0.75) * raw


def test_square_root_ukf_equals_the_ukf():
    """Same model and weights: the square-root form propagates S with P = S Sᵀ, so both give
    the same estimates up to rounding (float64 reference)."""
    fs = 35.0
    t = np.arange(300) / fs
    rng = np.random.default_rng(8)
    z = 0.3 * np.sin(7.0 * t) + 0.1 + rng.normal(0.0, 0.03, len(t))
    inp = {"angle": z, "angle_valid": np.ones(len(t), bool), "dt": np.full(len(t), 1 / fs)}
    a = runner.run("angle-ukf", "ref", inp)
    b = runner.run("angle-srukf", "ref", inp)
    assert np.max(np.abs(a["angle"] - b["angle"])) < 1e-9
    assert np.max(np.abs(a["omega"] - b["omega"])) < 1e-7
