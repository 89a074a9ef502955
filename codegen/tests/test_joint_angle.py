"""The unit's joint angles (generated `joint-angle`) against the host's kinematics (independent
numpy code: kinefuse.host.kinematics), and its C against its models bit for bit."""
from __future__ import annotations

import numpy as np
import pytest

from kinefuse.codegen import runner as cg
from kinefuse.codegen.runner import bits
from kinefuse.host.kinematics import joint as J
from kinefuse.host.kinematics import quat as Q

SEQ = {0: "XZY", 1: "XYZ", 2: "ZYX"}
TOL_DEG = {"ref": 1e-6, "f32": 2e-3, "q": 2e-3}


def _unit(rng, n):
    q = rng.normal(size=(n, 4))
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def _wrap_deg(d):
    return np.degrees(np.abs(np.angle(np.exp(1j * d))))


@pytest.fixture(scope="module")
def pair():
    rng = np.random.default_rng(7)
    qp = _unit(rng, 3000)
    # known joint angles (the middle one away from the gimbal lock) -> distal orientation
    ang = np.column_stack([rng.uniform(-np.pi, np.pi, 3000), rng.uniform(-1.5, 1.5, 3000),
                           rng.uniform(-np.pi, np.pi, 3000)])
    return rng, qp, ang


@pytest.mark.parametrize("impl", ["ref", "f32", "q"])
@pytest.mark.parametrize("seq", [0, 1, 2])
def test_angles_equal_the_hosts_decomposition(pair, seq, impl):
    rng, qp, ang = pair
    off_p, off_d = _unit(rng, 1)[0], _unit(rng, 1)[0]
    # q_dist such that (qp ⊗ off_p)* ⊗ (qd ⊗ off_d) = q_joint(ang)
    qj = Q.from_euler(ang, SEQ[seq])
    qd = Q.mul(Q.mul(Q.mul(qp, off_p), qj), Q.conj(off_d))
    params = {"sequence": seq, **{f"prox_{c}": v for c, v in zip("wxyz", off_p)},
              **{f"dist_{c}": v for c, v in zip("wxyz", off_d)}}
    out = cg.run("joint-angle", impl, {"q_prox": qp, "q_dist": qd}, params=params)
    got = np.asarray(out["angles"], float)
    assert _wrap_deg(got - ang).max() <= TOL_DEG[impl]
    # and the host's own pipeline on the same quaternions agrees
    host = Q.to_euler(J.joint_quaternion(qp, qd, off_p, off_d), SEQ[seq])
    assert _wrap_deg(got - host).max() <= TOL_DEG[impl] + 1e-6
    assert np.all(np.asarray(out["valid"])) and out["rejected"][-1, 0] == 0


@pytest.mark.parametrize("impl", ["f32", "q"])
def test_left_knee_mirrors_adduction_and_rotation(pair, impl):
    rng, qp, ang = pair
    qd = Q.mul(qp, Q.from_euler(ang, "XZY"))
    out = cg.run("joint-angle", impl, {"q_prox": qp, "q_dist": qd}, params={"mirror": 1})
    host = J.knee_angles(J.joint_quaternion(qp, qd), side="left")
    assert _wrap_deg(np.radians(host) - np.asarray(out["angles"], float)).max() <= 2e-3


def test_bad_samples_hold_the_last_angles_and_count():
    rng = np.random.default_rng(3)
    qp, qd = _unit(rng, 400), _unit(rng, 400)
    bad = rng.random(400) < 0.1
    bad[0] = False
    kinds = [np.nan, np.inf, 0.0, 0.3, 1.5]
    for k, i in enumerate(np.flatnonzero(bad)):
        qp[i] = qp[i] * kinds[k % 5] if kinds[k % 5] not in (np.nan, np.inf) else kinds[k % 5]
    for impl in ("ref", "f32", "q"):
        out = cg.run("joint-angle", impl, {"q_prox": qp, "q_dist": qd})
        a = np.asarray(out["angles"], float)
        assert np.all(np.isfinite(a)), impl
        i = np.flatnonzero(bad)
        assert np.array_equal(a[i], a[i - 1]), impl
        assert out["rejected"][-1, 0] == bad.sum(), impl


@pytest.mark.parametrize("system", ["f32", "q"])
def test_c_equals_model_in_every_bit(pair, system):
    rng, qp, _ = pair
    qd = _unit(rng, len(qp))
    qd[::97] = np.nan
    qp[::89] *= 3.0
    inp = {"q_prox": qp, "q_dist": qd}
    for seq in (0, 1, 2):
        c = cg.run("joint-angle", system, inp, params={"sequence": seq, "mirror": seq == 1})
        m = cg.run("joint-angle", f"{system}-model", inp, params={"sequence": seq,
                                                                   "mirror": seq == 1})
        for k in c:
            assert np.array_equal(bits(c[k]), bits(m[k])), (system, seq, k)
