"""Quaternions from vector observations, and the quaternion-measurement Kalman update.

Shared by the seed-001/002 catalogue (``vac``, ``vak``, ``guo``, ``ecompass``, ``triad``).

Conventions (as everywhere in kinefuse): quaternions (w, x, y, z), Hamilton product, an
orientation q maps sensor-frame vectors to the earth frame East-North-Up (v_e = q ⊗ v_s ⊗ q*).
The accelerometer reads +g along the sensor's up direction at rest.  Published formulas written
for other conventions (Valenti: the conjugate, global frame North-West-Up; Guo: North-East-Down)
were re-derived here for ours; every formula below was checked numerically (see
``codegen/tests/test_catalogue*.py``).

Algebraic quaternion (Valenti, Dryanovski, Xiao, Sensors 15(8), 2015, "AQUA"):
  q_am = q_mag ⊗ q_acc, where q_acc rotates the measured up direction onto +z (tilt, no
  rotation about z) and q_mag is a rotation about the earth's z axis that turns the horizontal
  part l_h of the tilt-corrected field l = q_acc ⊗ m ⊗ q_acc* onto north (+y).  Both use
  Valenti's two-branch half-angle formulas (the branch keeps every denominator >= sqrt 2, so
  nothing divides by ~0 and the fixed-point path needs no dynamic range); seed 001's eq. 5.13
  misprint (sqrt(l_y) for l_y) does not occur.

Quaternion-measurement Kalman update (Valenti 2016 "VAK", Guo 2017 "GUO"): state x = q (4),
measurement z = a quaternion from accelerometer (+ magnetometer), H = I.  Covariances are
carried in units of ``s_ref`` (the tilt variance, rad^2, of one accelerometer measurement at
|a| = g): the Kalman gain is unchanged by a common scale of P, Q and R, and the scaled values
stay near 1, which is what a fixed-point format needs.  Small-angle errors are mapped to
quaternion space with M(q) (dq = 1/2 (0, dθ) ⊗ q = 1/2 M(q) dθ, dθ an earth-frame rotation
vector); M has orthonormal columns orthogonal to q, so M Mᵀ = I − q qᵀ.
"""
from __future__ import annotations

from kinefuse.codegen.linalg import Quat, Vec3, vselect
from kinefuse.codegen.scalar import assume, clamp, fmax, rnorm, sqrt

SQRT_HALF = 0.7071067811865476

# ----------------------------------------------------------------------------------------------
# algebraic quaternions


def tilt_quaternion(up: Vec3) -> Quat:
    """The rotation (no component about the earth's z) that maps the unit vector ``up`` (sensor
    frame, measured up direction) onto the earth's +z.

    Valenti's q_acc, conjugated for our convention:
      u_z >= 0:  (λ, u_y/(2λ), −u_x/(2λ), 0),   λ = sqrt((1 + u_z)/2)   (the smallest rotation)
      u_z <  0:  (−u_y/(2μ), −μ, 0, −u_x/(2μ)),  μ = sqrt((1 − u_z)/2)
    The second branch adds a half turn about z (it has no singularity at u_z = −1); it changes
    the heading, which the magnetometer quaternion sets anyway.
    """
    ux, uy, uz = up
    upper = uz >= 0.0
    lam = sqrt(fmax(0.5 * (1.0 + uz), 0.5))      # branch u_z >= 0: 1 + u_z >= 1
    mu = sqrt(fmax(0.5 * (1.0 - uz), 0.5))       # branch u_z < 0: 1 − u_z > 1
    k1 = 0.5 / lam
    k2 = 0.5 / mu
    q1 = Quat(lam, assume(uy * k1, -1.0, 1.0), assume(-ux * k1, -1.0, 1.0), 0.0)
    q2 = Quat(assume(-uy * k2, -1.0, 1.0), -mu, 0.0, assume(-ux * k2, -1.0, 1.0))
    return vselect(upper, q1, q2)


def tilt_correction(g_p: Vec3, eps: float = 1e-9) -> Quat:
    """The smallest rotation (earth frame) that maps the unit vector ``g_p`` (the measured up
    direction rotated into the earth frame by a predicted orientation) onto +z: Valenti's
    Δq_acc = (λ, g_y/(2λ), −g_x/(2λ), 0), λ = sqrt((1 + g_z)/2), written as the normalised
    (1 + g_z, g_y, −g_x, 0) so that it stays accurate for any g_z (an estimate up to 180° off);
    w >= 0 always.  Exactly upside down (|.|² = 2(1 + g_z) < eps) it is a half turn about x."""
    gx, gy, gz = g_p
    v = Quat(1.0 + gz, gy, -gx, 0.0)
    k, n2 = rnorm(v, eps)
    dq = Quat(*(assume(c * k, -1.0, 1.0) for c in v))
    return vselect(n2 > eps, dq, Quat(0.0, 1.0, 0.0, 0.0))


def heading_quaternion(lx, ly, eps: float = 1e-6):
    """Rotation about the earth's z axis that turns the horizontal direction (lx, ly) onto
    north (+y).  Returns (q, gamma): gamma = lx² + ly² (before normalisation); when gamma is
    below eps the direction is undefined and q is the identity.

    With (cx, cy) = (lx, ly)/sqrt(gamma) and ψ the turn (cos ψ = cy, sin ψ = cx):
      cy >= 0: (λ, 0, 0, cx/(2λ)), λ = sqrt((1 + cy)/2)
      cy <  0: (cx/(2μ), 0, 0, μ),  μ = sqrt((1 − cy)/2)
    """
    k, gamma = rnorm((lx, ly), eps)
    cx = assume(lx * k, -1.0, 1.0)
    cy = assume(ly * k, -1.0, 1.0)
    north = cy >= 0.0
    lam = sqrt(fmax(0.5 * (1.0 + cy), 0.5))
    mu = sqrt(fmax(0.5 * (1.0 - cy), 0.5))
    q1 = Quat(lam, 0.0, 0.0, assume(cx * (0.5 / lam), -1.0, 1.0))
    q2 = Quat(assume(cx * (0.5 / mu), -1.0, 1.0), 0.0, 0.0, mu)
    q = vselect(north, q1, q2)
    ok = gamma > eps
    return vselect(ok, q, Quat(1.0, 0.0, 0.0, 0.0)), gamma


def aqua(acc_unit: Vec3, mag_unit: Vec3, eps: float = 1e-4):
    """Valenti's algebraic quaternion from a unit up direction and a unit field direction
    (sensor frame).  Returns (q_am, q_acc, l, gamma): q_am = q_mag ⊗ q_acc maps sensor to ENU;
    l = q_acc ⊗ m ⊗ q_acc* is the tilt-corrected field (earth frame, unit); gamma = l_x² + l_y²
    is the squared horizontal field, sin² of the angle between field and vertical (the
    degeneracy measure: gamma < eps means field ∥ gravity and no heading is defined)."""
    q_acc = tilt_quaternion(acc_unit)
    l = q_acc.rotate(mag_unit)
    l = Vec3(*(assume(c, -1.0, 1.0) for c in l))
    q_mag, gamma = heading_quaternion(l.x, l.y, eps)
    return q_mag * q_acc, q_acc, l, gamma


# ----------------------------------------------------------------------------------------------
# interpolation toward the identity (Valenti's LERP / SLERP of a correction quaternion)


def scale_correction(dq: Quat, gain, threshold):
    """Valenti's filtered correction: the fraction ``gain`` (in [0, 1]) of the rotation dq
    (dq.w >= 0), by LERP + normalisation when dq.w > threshold, else by SLERP.

    SLERP toward the identity: (sin((1−α)Ω) + sin(αΩ) cos Ω, sin(αΩ) v̂ ... ) / sin Ω with
    Ω = acos(dq.w); it is only selected for dq.w <= threshold <= 0.95, so sin Ω >= 0.31 there
    (the guard below only protects the unselected branch)."""
    from kinefuse.codegen.mathlib import acos, sin
    one_m = 1.0 - gain
    lerp = Quat(one_m + gain * dq.w, gain * dq.x, gain * dq.y, gain * dq.z).normalized()
    omega = acos(dq.w)
    s_om = sin(omega)
    inv = 1.0 / fmax(s_om, 0.3)
    a = sin(one_m * omega) * inv
    b = sin(gain * omega) * inv
    slerp = Quat(assume(a + b * dq.w, -1.0, 1.0), assume(b * dq.x, -1.0, 1.0),
                 assume(b * dq.y, -1.0, 1.0), assume(b * dq.z, -1.0, 1.0))
    return vselect(dq.w > threshold, lerp, slerp)


# ----------------------------------------------------------------------------------------------
# small-angle maps and the identity-measurement Kalman update


def m_matrix(q: Quat):
    """M(q) (4×3): 1/2 M(q) dθ = 1/2 (0, dθ) ⊗ q, the change of q for a small earth-frame
    rotation dθ.  Columns are orthonormal and orthogonal to a unit q."""
    w, x, y, z = q
    return [[-x, -y, -z],
            [w, z, -y],
            [-z, w, x],
            [y, -x, w]]


def sym_index(n: int):
    """Packed upper-triangle index of a symmetric n×n matrix: idx[i][j] for every i, j."""
    idx = [[0] * n for _ in range(n)]
    k = 0
    for i in range(n):
        for j in range(i, n):
            idx[i][j] = idx[j][i] = k
            k += 1
    return idx


IDX4 = sym_index(4)


def unpack4(p):
    return [[p[IDX4[i][j]] for j in range(4)] for i in range(4)]


def pack4(P):
    return tuple(P[i][j] for i in range(4) for j in range(i, 4))


def congruence(A, C):
    """A C Aᵀ for A (n×m), C (m×m) symmetric, as a full symmetric n×n (upper triangle computed
    and mirrored).  Zero entries of C given as the float 0.0 literal are skipped at trace time
    by the caller's choice of C (plain Python floats fold)."""
    n, m = len(A), len(C)
    AC = [[_sum(A[i][k] * C[k][j] for k in range(m) if not _is_const_zero(C[k][j]))
           for j in range(m)] for i in range(n)]
    out = [[None] * n for _ in range(n)]
    for i in range(n):
        for j in range(i, n):
            v = _sum(AC[i][k] * A[j][k] for k in range(m))
            out[i][j] = out[j][i] = v
    return out


def _is_const_zero(v):
    return isinstance(v, float) and v == 0.0


def _sum(terms):
    out = None
    for t in terms:
        out = t if out is None else out + t
    return 0.0 if out is None else out


def cholesky4(S, floor: float, bound: float):
    """Lower Cholesky factor of the 4×4 SPD matrix S (list of rows) and the reciprocals of its
    diagonal.  Pivots are floored at ``floor`` (S is at least floor·I by construction: the
    callers' R has eigenvalues >= floor).  |L_ij| <= sqrt(S_ii) <= ``bound`` holds for any
    Cholesky factor (Σ_j L_ij² = S_ii): stated with assume() for the fixed-point path."""
    L = [[0.0] * 4 for _ in range(4)]
    inv = [0.0] * 4
    for j in range(4):
        d = S[j][j]
        for k in range(j):
            d = d - L[j][k] * L[j][k]
        ljj = sqrt(fmax(d, floor))
        L[j][j] = assume(ljj, floor ** 0.5, bound)
        inv[j] = assume(1.0 / L[j][j], 1.0 / bound, floor ** -0.5)
        for i in range(j + 1, 4):
            s = S[i][j]
            for k in range(j):
                s = s - L[i][k] * L[j][k]
            L[i][j] = assume(s * inv[j], -bound, bound)
    return L, inv


def forward_solve4(L, inv, b, bound: float):
    """y = L⁻¹ b (forward substitution); every |y_i| <= ``bound`` (caller's proof)."""
    y = [0.0] * 4
    for i in range(4):
        s = b[i]
        for k in range(i):
            s = s - L[i][k] * y[k]
        y[i] = assume(s * inv[i], -bound, bound)
    return y


def kf_identity_update(x: Quat, P, z: Quat, R, floor: float, s_max: float, p_max: float,
                       y_max: float):
    """One Kalman update with H = I for a quaternion state (all covariances in units of s_ref).

    S = P + R = L Lᵀ;  Y = L⁻¹ P;  y = L⁻¹ (z − x);  x⁺ = x + Yᵀ y;  P⁺ = P − Yᵀ Y.
    (K = P S⁻¹ = Yᵀ L⁻¹, so K ν = Yᵀ y and K S Kᵀ = Yᵀ Y.)  Bounds used for the fixed-point
    formats, all mathematical: |L_ij| <= sqrt(S_ii) <= sqrt(s_max); (Yᵀ Y)_jj <= P_jj because
    P S⁻¹ P <= P, so |Y_ij| <= sqrt(p_max); |y|² = νᵀ S⁻¹ ν <= |ν|²/floor <= y_max².
    Returns (x⁺ (not normalised), P⁺ as rows)."""
    S = [[P[i][j] + R[i][j] for j in range(4)] for i in range(4)]
    L, inv = cholesky4(S, floor, s_max ** 0.5)
    ybound = p_max ** 0.5
    cols = [forward_solve4(L, inv, [P[i][j] for i in range(4)], ybound) for j in range(4)]
    Y = [[cols[j][i] for j in range(4)] for i in range(4)]          # Y[i][j] = (L⁻¹P)_ij
    nu = [z[i] - x[i] for i in range(4)]
    y = forward_solve4(L, inv, nu, y_max)
    xn = Quat(*(assume(x[j] + _sum(Y[i][j] * y[i] for i in range(4)), -2.0, 2.0)
                for j in range(4)))
    Pn = [[None] * 4 for _ in range(4)]
    for i in range(4):
        for j in range(i, 4):
            v = P[i][j] - _sum(Y[k][i] * Y[k][j] for k in range(4))
            if i == j:
                v = fmax(v, 0.0)
            v = assume(v, -p_max, p_max)
            Pn[i][j] = Pn[j][i] = v
    return xn, Pn


def kf_predict(P, q: Quat, omega: Vec3, dt, k_proc, p_max: float):
    """P⁻ = Φ P Φᵀ + k M(q) M(q)ᵀ with Φ = I + dt/2 Ω(ω) (q⁻ = Φ q = q + dt/2 q ⊗ (0, ω)),
    the seeds' zero-order transition, and the process noise of a white gyroscope error
    (Ξ Σ_g Ξᵀ (dt/2)² = k (I − q qᵀ) for an isotropic Σ_g; M Mᵀ = I − q qᵀ)."""
    hx, hy, hz = omega.x * (0.5 * dt), omega.y * (0.5 * dt), omega.z * (0.5 * dt)
    # q ⊗ (0, h) = Ω(h) q with Ω(h) the right-multiplication matrix
    Phi = [[1.0, -hx, -hy, -hz],
           [hx, 1.0, hz, -hy],
           [hy, -hz, 1.0, hx],
           [hz, hy, -hx, 1.0]]
    PP = congruence(Phi, P)
    Mq = m_matrix(q)
    out = [[None] * 4 for _ in range(4)]
    for i in range(4):
        for j in range(i, 4):
            mm = Mq[i][0] * Mq[j][0] + Mq[i][1] * Mq[j][1] + Mq[i][2] * Mq[j][2]
            v = assume(PP[i][j] + k_proc * assume(mm, -1.0, 1.0), -p_max, p_max)
            out[i][j] = out[j][i] = v
    return out


def clamp01(v):
    return clamp(v, 0.0, 1.0)


__all__ = ["tilt_quaternion", "tilt_correction", "heading_quaternion", "aqua",
           "scale_correction", "m_matrix", "sym_index", "IDX4", "unpack4", "pack4",
           "congruence", "cholesky4", "forward_solve4", "kf_identity_update", "kf_predict",
           "clamp01"]
