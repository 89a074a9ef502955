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
carried in units of ``s_ref`` (the larger of the accelerometer tilt variance and 1/16 of the
magnetometer heading variance, rad², from the parameters): the Kalman gain is unchanged by a
common scale of P, Q and R, and the scaled values stay within [2^-10, 128], which is what one
fixed-point format for all of P needs (per-step process noise must stay well above its
resolution, 2^-23: otherwise P freezes in a dead band and loses positive definiteness).  Small-angle errors are mapped to
quaternion space with M(q) (dq = 1/2 (0, dθ) ⊗ q = 1/2 M(q) dθ, dθ an earth-frame rotation
vector); M has orthonormal columns orthogonal to q, so M Mᵀ = I − q qᵀ.
"""
from __future__ import annotations

from kinefuse.codegen.linalg import Quat, Vec3, vselect
from kinefuse.codegen.scalar import assume, clamp, fmax, rnorm, select, sqrt

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


def forward_solve4(L, inv, b, bound: float, clip: bool = False):
    """y = L⁻¹ b (forward substitution).  Every |y_i| <= ``bound``: proved by the caller
    (``clip`` False, stated with assume()), or enforced by clipping in every number system."""
    y = [0.0] * 4
    for i in range(4):
        s = b[i]
        for k in range(i):
            s = s - L[i][k] * y[k]
        v = s * inv[i]
        y[i] = clamp(v, -bound, bound) if clip else assume(v, -bound, bound)
    return y


def kf_identity_update(x: Quat, P, z: Quat, R, floor: float, s_max: float, p_max: float,
                       y_max: float):
    """One Kalman update with H = I for a quaternion state (all covariances in units of s_ref).

    S = P + R = L Lᵀ;  Y = L⁻¹ P;  y = L⁻¹ (z − x);  x⁺ = x + Yᵀ y;  P⁺ = P − Yᵀ Y
    (K = P S⁻¹ = Yᵀ L⁻¹, so K ν = Yᵀ y and K S Kᵀ = Yᵀ Y.)  Bounds used for the fixed-point
    formats, all mathematical: |L_ij| <= sqrt(S_ii) <= sqrt(s_max); (Yᵀ Y)_jj <= P_jj because
    P S⁻¹ P <= P, so |Y_ij| <= sqrt(p_max); |y|² = νᵀ S⁻¹ ν <= |ν|² / floor <= y_max² for
    unit x, z and S >= floor·I.
    Returns (x⁺ (not normalised), P⁺ as rows)."""
    S = [[P[i][j] + R[i][j] for j in range(4)] for i in range(4)]
    L, inv = cholesky4(S, floor, s_max ** 0.5)
    ybound = p_max ** 0.5
    cols = [forward_solve4(L, inv, [P[i][j] for i in range(4)], ybound) for j in range(4)]
    Y = [[cols[j][i] for j in range(4)] for i in range(4)]          # Y[i][j] = (L⁻¹P)_ij
    nu = [z[i] - x[i] for i in range(4)]
    y = forward_solve4(L, inv, nu, y_max)
    # x⁺ is normalised by the caller; the clip at ±2 (x and z are unit) only bounds the range
    xn = Quat(*(clamp(x[j] + _sum(Y[i][j] * y[i] for i in range(4)), -2.0, 2.0)
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


H_MAX = 0.5   # rad: largest half-angle step per axis of the first-order transition


def half_step(omega: Vec3, dt) -> Vec3:
    """h = ω dt / 2 per axis, limited to ±H_MAX (a first-order transition cannot represent a
    larger step anyway; the limit also bounds Φ for the fixed-point formats)."""
    return Vec3(*(clamp(w * (0.5 * dt), -H_MAX, H_MAX) for w in omega))


def predict_quaternion(q: Quat, omega: Vec3, dt) -> Quat:
    """Φ q = q + q ⊗ (0, h), normalised (seed eq. 5.2 / 5.42)."""
    return (q + q * Quat(0.0, *half_step(omega, dt))).normalized()


def kf_predict(P, q: Quat, omega: Vec3, dt, k_proc, p_max: float):
    """P⁻ = Φ P Φᵀ + k M(q) M(q)ᵀ with Φ = I + Ω(h) (q⁻ = Φ q = q + q ⊗ (0, h)), h the
    half-angle step of :func:`half_step` — the seeds' zero-order transition — and the process
    noise of a white gyroscope error (Ξ Σ_g Ξᵀ (dt/2)² = k (I − q qᵀ) for an isotropic Σ_g;
    M Mᵀ = I − q qᵀ)."""
    hx, hy, hz = half_step(omega, dt)
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


# ----------------------------------------------------------------------------------------------
# the quaternion-state Kalman filter shared by VAK and GUO (covariances in units of s_ref)

T_MIN, T_MAX = 2.0 ** -10, 16.0    # range of the tilt variance of one sample (units of s_ref)
R_HEAD_MAX = 128.0                 # heading variance cap; also the variance of "no heading"
P_MAX = 16.0                       # |P̃_ij| bound: P̃ starts at R̃ scaled to trace <= P0_TRACE and
P0_TRACE = 8.0                     # then only shrinks (P⁺ <= P⁻) or grows by k per step
K_MAX = 16.0                       # process noise per step (units of s_ref) is below this
R_FLOOR = 2.0 ** -12               # variance added to every direction of R̃ (S = P + R >= R_FLOOR I)
Y_MAX = 128.0                      # |y| = |L⁻¹ν| <= |ν| / sqrt(λmin(S)) <= 2 / sqrt(R_FLOOR)
MIN_FIELD_SIN2 = 0.0076            # sin²(5°): field closer than 5° to vertical gives no heading


def heading_sigma(t, smt, gamma, lz, use_mag, coupling=1.0):
    """Normalised covariance of the earth-frame rotation-vector error of the algebraic
    (tilt from gravity, heading from the horizontal field) measurement, as (t, s, c):
    Σ̃ = [[t, 0, 0], [0, t, c], [0, c, s]].

    First-order propagation of the sensor noise (Valenti 2016's J Σ_u Jᵀ, derived in the earth
    frame): with â, m̂ the unit vectors, t = var(â_⊥) and smt = var(m̂_⊥) (both / s_ref), the field
    direction (0, h, v) in ENU (h² = gamma, v = lz):  δθ_x = δâ_y, δθ_y = −δâ_x,
    δθ_z = (δm̂_x − v δâ_x)/h, hence s = (smt + v² t)/h² and c = cov(δθ_y, δθ_z) = t v / h.
    Without a usable field reading the heading is uninformed: s = R_HEAD_MAX, c = 0.
    ``coupling`` scales c: 1 is the exact first-order covariance; 0 treats the heading error
    as independent of the tilt error, so heading innovations (e.g. from a magnetic
    disturbance, which no white-noise model covers) never change the tilt."""
    inv_h2 = 1.0 / fmax(gamma, MIN_FIELD_SIN2)
    s_m = clamp((smt + lz * lz * t) * inv_h2, 0.0, R_HEAD_MAX)
    c_m = t * lz * sqrt(inv_h2) * coupling
    lim = sqrt(fmax(t * s_m, 0.0))
    c_m = clamp(c_m, -lim, lim)                   # keeps Σ̃ positive semidefinite after the cap
    s = select(use_mag, s_m, R_HEAD_MAX)
    c = select(use_mag, c_m, 0.0)
    return s, c


def r_from_sigma(z: Quat, t, s, c):
    """R̃ = M(z) Σ̃ M(z)ᵀ + t z zᵀ + R_FLOOR I for Σ̃ = [[t,0,0],[0,t,c],[0,c,s]]
    = (t + R_FLOOR) I + (s − t) m2 m2ᵀ + c (m1 m2ᵀ + m2 m1ᵀ)  (M Mᵀ = I − z zᵀ; m1, m2 columns
    of M).  The z zᵀ term gives the (meaningless) norm direction the tilt variance; the floor
    (1/64 of the nominal tilt variance) keeps P⁻ + R̃ >= R_FLOOR I, which bounds the whitened
    innovation for the fixed-point formats."""
    M = m_matrix(z)
    m1 = [M[i][1] for i in range(4)]
    m2 = [M[i][2] for i in range(4)]
    d = s - t
    R = [[None] * 4 for _ in range(4)]
    for i in range(4):
        for j in range(i, 4):
            v = d * (m2[i] * m2[j]) + c * (m1[i] * m2[j] + m2[i] * m1[j])
            if i == j:
                v = v + (t + R_FLOOR)
            R[i][j] = R[j][i] = assume(v, -2.0 * R_HEAD_MAX, 2.0 * R_HEAD_MAX)
    return R


def align_sign(z: Quat, ref: Quat) -> Quat:
    """±z, whichever is closer to ref (the measurement of a rotation has two quaternions)."""
    flip = z.dot(ref) < 0.0
    return Quat(*(select(flip, -c_, c_) for c_ in z))


# ----------------------------------------------------------------------------------------------
# the filter in square-root form (VAK, GUO): the state carries a lower Cholesky factor S̃ of P̃
# (kf_predict and kf_identity_update are its plain form, kept as the definition it is tested against)
#
# Why (fixed point): P̃ spans 8 s_ref (start) to ~1e-4 s_ref (steady state at BROAD's 286 Hz,
# per-step process noise k ~ 1e-7 s_ref), and its steady state is the balance of two per-step
# changes of size k.  Stored in one int32 format for |P̃| <= 16 (Q4.27... Q5.26, 1.5e-8) those
# changes are a few LSB, and their products (Yᵀ Y ~ 7e-9) round to 0: P̃ froze 20-60 % away
# from the reference, and with it the Kalman gain (the q deviation of up to 17°).  The factor
# halves the dynamic range: |S̃| <= 4 (Q2.29, 1.9e-9), steady state ~0.02 with per-step
# changes of ~1e3 LSB, and P̃ is never formed except for the innovation covariance, where
# P̃ + R̃ ~ R̃ needs no small-value precision.

S_MAX = P_MAX ** 0.5              # |S̃_ij| <= sqrt(P̃_ii) <= sqrt(P_MAX) = 4: Q2.29
U_FLOOR = 2.0 ** -18              # λmin(I − GᵀG) >= 1/(1 + λmax(P̃)/R_FLOOR) >= 1/(1 + 64·2^12)
W_FINE = 0.25                     # |Gᵀ y| carried by the fine correction path (see sr_update)
Y_FINE = 8.0                      # |y_i| carried by the fine path (BROAD: max 3.6)
S0_FLOOR = 2.0 ** -17             # P̃0 = f R̃ >= R_FLOOR / 22 > 2^-17 (f >= 8/176, tr R̃ <= 176)


def sr_state_var(p_max: float = P_MAX):
    """The state field S of a square-root quaternion filter (packed lower triangle, identity
    at start), |S̃_ij| <= sqrt(p_max)."""
    from kinefuse.codegen.estimator import Var
    s_max = p_max ** 0.5
    return Var("S", 10, -s_max, s_max, "sqrt(s_ref)",
               "lower Cholesky factor of the state covariance (P = S Sᵀ), rows 00; 10 11; "
               "20 21 22; 30 31 32 33, in units of sqrt(s_ref) (see the filter's docstring)",
               init=(1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0))


def unpack_tril(s):
    """Lower-triangular 4×4 rows from the packed rows 00; 10 11; 20 21 22; 30 31 32 33
    (structural zeros as the float literal 0.0)."""
    out, k = [[0.0] * 4 for _ in range(4)], 0
    for i in range(4):
        for j in range(i + 1):
            out[i][j] = s[k]
            k += 1
    return out


def pack_tril(S):
    return tuple(S[i][j] for i in range(4) for j in range(i + 1))


def sr_predict(S, q: Quat, omega: Vec3, dt, u_g, s_max: float = S_MAX):
    """S̃⁻ (lower triangular) with S̃⁻S̃⁻ᵀ = Φ P̃ Φᵀ + u_g² M(q) M(q)ᵀ (:func:`kf_predict`,
    k = u_g²): Givens triangularisation of the rows of [Φ S̃ | u_g M(q)]ᵀ.
    Φ S̃ = S̃ + Ω S̃ (Ω = Φ − I, entries ±h): the increment Ω S̃ is formed on its own so that the
    sum S̃ + Ω S̃ needs no rounding (both in Q2.29 and finer).  Bounds: every row of Φ S̃ and of
    the rotated pre-array has norm sqrt(P̃⁻_ii) <= S_MAX (P̃⁻ <= P_MAX, as the plain form
    assumes); |u_g M_ij| <= u_g <= 4."""
    from kinefuse.codegen.estimators.givens import givens_triangularise
    hx, hy, hz = half_step(omega, dt)
    Om = [[0.0, -hx, -hy, -hz],
          [hx, 0.0, hz, -hy],
          [hy, -hz, 0.0, hx],
          [hz, hy, -hx, 0.0]]
    FS = [[None] * 4 for _ in range(4)]
    for i in range(4):
        for j in range(4):
            terms = [Om[i][k] * S[k][j] for k in range(j, 4) if k != i]
            if not terms:
                v = S[i][j]
            elif _is_const_zero(S[i][j]):
                v = _sum(terms)
            else:
                v = S[i][j] + _sum(terms)
            FS[i][j] = assume(v, -s_max, s_max)
    Mq = m_matrix(q)
    rows = [[FS[i][j] for i in range(4)] for j in range(4)]           # columns of Φ S̃
    rows += [[assume(u_g * Mq[i][c], -s_max, s_max) for i in range(4)] for c in range(3)]
    Rt = givens_triangularise(rows, [s_max] * 4)
    return [[Rt[j][i] if j <= i else 0.0 for j in range(4)] for i in range(4)]


def sr_update(x: Quat, S, z: Quat, R, floor: float = R_FLOOR, s_max: float = S_MAX,
              r_bound: float = 2.0 * R_HEAD_MAX, y_max: float = Y_MAX):
    """The Kalman update of :func:`kf_identity_update` (H = I) on the factor:
    P̃⁻ = S̃ S̃ᵀ;  P̃⁻ + R̃ = L Lᵀ;  G = L⁻¹ S̃;  y = L⁻¹ ν;
    x⁺ = x + S̃ Gᵀ y  (= x + K ν: K = P̃⁻ (P̃⁻ + R̃)⁻¹ = S̃ Gᵀ L⁻¹);
    S̃⁺ = S̃ U with U Uᵀ = I − GᵀG  (S̃ (I − GᵀG) S̃ᵀ = P̃⁻ − P̃⁻ (P̃⁻ + R̃)⁻¹ P̃⁻).
    G and U are lower triangular (so is S̃⁺).  Bounds, all mathematical: GᵀG = S̃ᵀ(S̃S̃ᵀ + R̃)⁻¹S̃
    <= I, so |G_ij| <= 1 and the entries of GᵀG, U are within [-1, 1]; λmin(I − GᵀG) >=
    U_FLOOR; |S̃⁺_ij| <= sqrt(P̃⁺_ii) <= S_MAX.
    Q formats of the correction: S̃ Gᵀ y is ~3e-5 in steady state, but its interval bound
    (|S̃| <= 4, |y| <= 128) would put it in Q11.20.  It is split exactly into a fine part
    S̃ w_f, w_f = clamp(Gᵀ y_c, ±W_FINE), y_c = clamp(y, ±Y_FINE) (products <= 1: Q0.31), and
    the rest, which is exactly 0 unless |y_i| > Y_FINE or |(Gᵀ y_c)_j| > W_FINE (start-up),
    and clamped where the final clamp at ±2 makes that exact.  Returns (x⁺ unnormalised, S̃⁺)."""
    P = [[None] * 4 for _ in range(4)]
    for i in range(4):
        for j in range(i, 4):
            v = assume(_sum(S[i][k] * S[j][k] for k in range(i + 1)), -s_max ** 2, s_max ** 2)
            P[i][j] = P[j][i] = v
    Sinn = [[P[i][j] + R[i][j] for j in range(4)] for i in range(4)]
    L, inv = cholesky4(Sinn, floor, (s_max ** 2 + r_bound) ** 0.5)
    G = [[0.0] * 4 for _ in range(4)]
    for j in range(4):
        for i in range(j, 4):
            acc = S[i][j]
            for k in range(j, i):
                acc = acc - L[i][k] * G[k][j]
            G[i][j] = assume(acc * inv[i], -1.0, 1.0)
    nu = [z[i] - x[i] for i in range(4)]
    y = forward_solve4(L, inv, nu, y_max)
    # correction S̃ Gᵀ y, split for the fixed-point formats (docstring)
    yc = [clamp(v, -Y_FINE, Y_FINE) for v in y]
    yr = [v - c_ for v, c_ in zip(y, yc)]
    v_ = [_sum(G[i][j] * yc[i] for i in range(j, 4)) for j in range(4)]
    wf = [clamp(v, -W_FINE, W_FINE) for v in v_]
    wm = [v - f for v, f in zip(v_, wf)]
    wr = [_sum(G[i][j] * yr[i] for i in range(j, 4)) for j in range(4)]
    fine_max = 4.0 * s_max * W_FINE
    big = 3.0 + fine_max           # |x + S̃ w_f| <= 1 + fine_max: beyond ±big the clip at ±2 decides
    xs = []
    for i in range(4):
        df = _sum(S[i][j] * wf[j] for j in range(i + 1))
        dm = clamp(_sum(S[i][j] * wm[j] for j in range(i + 1)), -big, big)
        dr = clamp(_sum(S[i][j] * wr[j] for j in range(i + 1)), -big, big)
        xs.append(clamp((x[i] + df) + clamp(dm + dr, -big, big), -2.0, 2.0))
    # S̃⁺ = S̃ U, U = chol(I − GᵀG), written with the small quantities on their own:
    # e_j = 1 − U_jj², v_j = 1 − U_jj = e_j / (1 + U_jj) and S̃⁺_ij = (S̃_ij − S̃_ij v_j) + ...,
    # so that neither 1 − e nor U_jj ~ 1 − 1e-4 carries the per-step decrement (binary32
    # would keep 2-3 of its digits)
    E = [[None] * 4 for _ in range(4)]
    for i in range(4):
        for j in range(i, 4):
            gg = _sum(G[k][i] * G[k][j] for k in range(j, 4))
            E[i][j] = E[j][i] = assume(gg, 0.0 if i == j else -1.0, 1.0)
    U = [[0.0] * 4 for _ in range(4)]
    v = [None] * 4
    for j in range(4):
        e = E[j][j]
        for k in range(j):
            e = e + U[j][k] * U[j][k]
        e = assume(e, 0.0, 1.0 - U_FLOOR)      # λmin(I − GᵀG) >= U_FLOOR
        ujj = assume(sqrt(fmax(1.0 - e, U_FLOOR)), U_FLOOR ** 0.5, 1.0)
        v[j] = assume(e / (1.0 + ujj), 0.0, 1.0)
        inv = assume(1.0 / ujj, 1.0, U_FLOOR ** -0.5)
        for i in range(j + 1, 4):
            acc = -E[i][j]
            for k in range(j):
                acc = acc - U[i][k] * U[j][k]
            U[i][j] = assume(acc * inv, -1.0, 1.0)
    Sn = [[0.0] * 4 for _ in range(4)]
    for i in range(4):
        for j in range(i + 1):
            d = S[i][j] - S[i][j] * v[j]
            if i > j:
                d = d + _sum(S[i][k] * U[k][j] for k in range(j + 1, i + 1))
            Sn[i][j] = assume(d, -s_max, s_max)
    return Quat(*xs), Sn


def sr_quat_kf(x, chk, q_pred: Quat, u_g, z: Quat, R, do_update, p_max: float = P_MAX,
               r_bound: float = 2.0 * R_HEAD_MAX):
    """Predict + (optional) update of the quaternion Kalman filter in square-root form; returns
    (q, S̃ packed lower triangular).  q_pred = Φ q (normalised); the update runs where
    ``do_update``.  ``u_g`` = sqrt of the per-step process noise k (<= 4); ``p_max`` bounds
    P̃ = S̃ S̃ᵀ (|S̃_ij| <= sqrt(p_max): the state's declared range, see :func:`sr_state_var`),
    ``r_bound`` the entries of R̃ (R̃ >= R_FLOOR I is required)."""
    s_max = p_max ** 0.5
    S = unpack_tril(x.S)
    Sm = sr_predict(S, Quat(*x.q), chk.gyr, chk.dt, u_g, s_max)
    xn, Sn = sr_update(q_pred, Sm, z, R, R_FLOOR, s_max, r_bound)
    q_up = xn.normalized()
    q_new = vselect(do_update, q_up, q_pred)
    S_new = [[select(do_update, Sn[i][j], Sm[i][j]) if j <= i else 0.0 for j in range(4)]
             for i in range(4)]
    return q_new, pack_tril(S_new)


def initial_factor(R, r_trace: float = 176.0):
    """S̃0: the lower Cholesky factor of :func:`initial_covariance` (R̃ scaled to trace <= 8).
    ``r_trace`` bounds the trace of the caller's R̃ (VAK: 176; R̃ >= R_FLOOR I): then
    P̃0 >= R_FLOOR P0_TRACE / r_trace > S0_FLOOR, so the pivot floor never binds (checked
    here); |S̃0_ij| <= sqrt(8)."""
    assert R_FLOOR * P0_TRACE / r_trace > S0_FLOOR, "the initial factor's pivot floor would bind"
    L, _ = cholesky4(unpack4(initial_covariance(R)), S0_FLOOR, P0_TRACE ** 0.5)
    return pack_tril(L)


def initial_covariance(R):
    """P̃ of an initialisation: the measurement covariance R̃ of that sample, scaled down (a PSD
    matrix stays PSD) so that its trace is at most P0_TRACE.  Keeps the covariance within the
    range one fixed-point format can hold with the resolution the per-step process noise needs
    (P̃ then only shrinks with updates, or grows by k per step).  Returns packed P̃."""
    tr = R[0][0] + R[1][1] + R[2][2] + R[3][3]
    f = 1.0 / fmax(1.0, tr * (1.0 / P0_TRACE))
    return tuple(assume(f * R[i][j], -P0_TRACE, P0_TRACE) for i in range(4) for j in range(i, 4))


def capped_gram(cols, scale, cap: float):
    """f Σ_c c cᵀ with f = scale, reduced so that the trace stays <= cap (a PSD matrix scaled
    down stays PSD; every entry is then bounded by the trace).  Returns (rows, f_effective)."""
    tr = _sum(_sum(c_[i] * c_[i] for i in range(4)) for c_ in cols)
    f = scale / fmax(1.0, scale * tr * (1.0 / cap))
    G = [[None] * 4 for _ in range(4)]
    for i in range(4):
        for j in range(i, 4):
            v = assume(f * _sum(c_[i] * c_[j] for c_ in cols), -cap, cap)
            G[i][j] = G[j][i] = v
    return G


def clamp01(v):
    return clamp(v, 0.0, 1.0)


__all__ = ["tilt_quaternion", "tilt_correction", "heading_quaternion", "aqua",
           "scale_correction", "m_matrix", "sym_index", "IDX4", "unpack4", "pack4",
           "congruence", "cholesky4", "forward_solve4", "kf_identity_update", "kf_predict",
           "clamp01"]
