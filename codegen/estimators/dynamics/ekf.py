"""The reduced dynamic EKF of seed 000 §3.2 on any :mod:`.models` model, with its variants.

State x = [z; ż; T_e]: independent coordinates, their rates and the efforts, which follow a
random walk (Ṫ_e = w, continuous white noise of power spectral density Σ^P = diag(q)).
Plant ẋ = f(x) = [ż; z̈(x); 0] with z̈ = M⁻¹(Q_g + Bᵀ T_e) (:mod:`.mbs`).

Per sample (seed §2.3.1.4): prediction with F = ∂f/∂x at the last estimate,
x⁻ = x + ∫f (integrator), P⁻ = Φ P Φᵀ + Σ_k; then the update with the sensors that arrived.

Variants (:class:`Variant`):

* integrator for the mean: ``fe`` forward Euler (1 evaluation of z̈), ``heun`` (2), ``tf``
  trapezoidal rule solved by fixed-point iteration, ``tn`` trapezoidal rule solved by
  Newton-Raphson (``iterations`` sweeps each, a fixed cap: no data-dependent loop, so the cost
  is constant), ``rk4`` classical Runge-Kutta (4);
* Φ: ``pe`` I + FΔt, ``se`` I + FΔt + F²Δt²/2, ``ex`` exp(FΔt);
* Σ_k: ``ct`` Taylor/Gibbs Σ_xΔt + (FΣ_x + Σ_xFᵀ)Δt²/2 + FΣ_xFᵀΔt³/3 (seed eq. 2.45),
  ``vl`` Van Loan's exact discrete covariance ∫₀^Δt e^{Fs} Σ_x e^{Fᵀs} ds (seed eqs. 2.43-2.44);
* sensitivity: ``full`` F, or ``simplified`` (only z̈_T = M⁻¹Bᵀ, seed Table A.3).

Matrix exponentials (``ex``, ``vl``) are generated in basic operations: Taylor series of order
:data:`EXP_ORDER` on FΔt/2^:data:`EXP_SQUARINGS`, then squaring.  For Van Loan the blocks of
exp([[−F, Σ_x], [0, Fᵀ]]Δt) are evaluated blockwise: the same Taylor series gives
Σ(h) = Σ_k h^{k+1}/(k+1)! 𝓛^k(Σ_x) with 𝓛(X) = FX + XFᵀ, and the squaring of the block matrix
becomes Σ(2h) = Σ(h) + Φ(h) Σ(h) Φ(h)ᵀ.  Truncation error ~1e-12 (relative) at ‖FΔt‖₁ ≈ 0.9
(the pendulum at 100 Hz), ~1e-10 at ‖FΔt‖₁ ≈ 4; the tests compare with scipy's expm of F and
of the full Van Loan matrix.

Update: the sensors are independent (diagonal noise), so the update is done one scalar
measurement at a time in Joseph form, P ← (I − k h)P(I − k h)ᵀ + k r kᵀ, with the measurement
Jacobian and prediction taken at the prior and the innovation corrected for the earlier scalar
updates (ν_i − H_i(x − x⁻)): this equals the batch EKF update exactly in exact arithmetic and
needs no matrix inverse.  A lost sensor keeps its row of H (sizes never change): its
innovation and its gain are set to zero, so that scalar update leaves x and P exactly as they
were (P + k wᵀ − PHᵀ kᵀ with k = 0), the same as the batch update without that row.  An
innovation variance h P hᵀ + r that is not above half the sensor variance r (P lost positive
definiteness) gates that scalar update the same way (zero gain) and is reported as skipped.
"""
from __future__ import annotations

import dataclasses
import math

from kinefuse.codegen.linalg import ZERO, sadd, smul, ssub, ssum
from kinefuse.codegen.scalar import (all_of, fabs, fmax, logical_and, logical_not, logical_or,
                                     select)
from kinefuse.codegen.estimators.dynamics.ad import Dual, new_tag, tangent, value
from kinefuse.codegen.estimators.dynamics.mbs import Dynamics, unit, zdd_of

EXP_ORDER = 6
EXP_SQUARINGS = 2

INTEGRATORS = ("fe", "heun", "tf", "tn", "rk4")
PHIS = ("pe", "se", "ex")
SIGMAS = ("ct", "vl")
SENSITIVITIES = ("full", "simplified")


@dataclasses.dataclass(frozen=True)
class Variant:
    integrator: str = "fe"
    phi: str = "se"
    sigma: str = "ct"
    sensitivity: str = "full"
    iterations: int = 3          # cap of the tf / tn iterations

    def __post_init__(self):
        for v, allowed, what in ((self.integrator, INTEGRATORS, "integrator"),
                                 (self.phi, PHIS, "phi"), (self.sigma, SIGMAS, "sigma"),
                                 (self.sensitivity, SENSITIVITIES, "sensitivity")):
            if v not in allowed:
                raise ValueError(f"{what} must be one of {', '.join(allowed)}, not {v!r}")
        if not 1 <= self.iterations <= 10:
            raise ValueError("iterations must be 1..10")

    @property
    def tag(self) -> str:
        """Short name, e.g. 'fe_se_ct' (+ '_simp' for the simplified sensitivity)."""
        s = f"{self.integrator}_{self.phi}_{self.sigma}"
        return s + ("_simp" if self.sensitivity == "simplified" else "")


# -- symmetric matrices stored as their upper triangle, row by row ---------------------------

def tri_size(n: int) -> int:
    return n * (n + 1) // 2


def unpack_sym(v, n: int):
    P = [[None] * n for _ in range(n)]
    k = 0
    for i in range(n):
        for j in range(i, n):
            P[i][j] = v[k]
            P[j][i] = v[k]
            k += 1
    return P


def pack_sym(P):
    n = len(P)
    return [P[i][j] for i in range(n) for j in range(i, n)]


def diag_sym_init(diag) -> tuple:
    n = len(diag)
    return tuple(diag[i] if i == j else 0.0 for i in range(n) for j in range(i, n))


# -- small dense algebra with structural zeros ------------------------------------------------

def mm(A, B):
    """A @ B (left-to-right sums, structural zeros skipped)."""
    cols = list(zip(*B))
    return [[ssum(smul(a, b) for a, b in zip(row, col)) for col in cols] for row in A]


def madd(A, B):
    return [[sadd(a, b) for a, b in zip(ra, rb)] for ra, rb in zip(A, B)]


def mscale(A, k):
    return [[smul(a, k) for a in row] for row in A]


def eye(n):
    return [[1.0 if i == j else ZERO for j in range(n)] for i in range(n)]


def transpose(A):
    return [list(c) for c in zip(*A)]


def sym_quad(A, P):
    """A P Aᵀ, upper triangle computed and mirrored (exactly symmetric)."""
    AP = mm(A, P)
    n = len(A)
    out = [[ZERO] * n for _ in range(n)]
    for i in range(n):
        for j in range(i, n):
            v = ssum(smul(AP[i][k], A[j][k]) for k in range(len(P)))
            out[i][j] = v
            out[j][i] = v
    return out


def sym_add_transpose(X):
    """X + Xᵀ, exactly symmetric."""
    n = len(X)
    out = [[ZERO] * n for _ in range(n)]
    for i in range(n):
        for j in range(i, n):
            v = sadd(X[i][j], X[j][i])
            out[i][j] = v
            out[j][i] = v
    return out


# -- F, Φ, Σ_k -------------------------------------------------------------------------------

def build_F(A_z, A_zd, A_T, n: int, ne: int):
    """F = [[0, I, 0], [z̈_z, z̈_ż, z̈_T], [0, 0, 0]] with structural zeros."""
    N = 2 * n + ne
    F = [[ZERO] * N for _ in range(N)]
    for i in range(n):
        F[i][n + i] = 1.0
        for j in range(n):
            F[n + i][j] = A_z[i][j]
            F[n + i][n + j] = A_zd[i][j]
        for e in range(ne):
            F[n + i][2 * n + e] = A_T[i][e]
    return F


def expm_taylor(F, dt, order: int = EXP_ORDER, squarings: int = EXP_SQUARINGS):
    """exp(F dt): Taylor series of F h, h = dt / 2^squarings, then squaring.  Returns
    (Φ(dt), Φ(h), h)."""
    N = len(F)
    h = dt * (1.0 / 2.0 ** squarings)
    Fh = mscale(F, h)
    E = eye(N)
    for k in range(order, 0, -1):          # Horner: I + Fh/1 (I + Fh/2 (I + ...))
        E = madd(eye(N), mscale(mm(Fh, E), 1.0 / k))
    Eh = E
    for _ in range(squarings):
        E = mm(E, E)
    return E, Eh, h


def van_loan(F, Sx, dt, order: int = EXP_ORDER, squarings: int = EXP_SQUARINGS):
    """(Φ, Σ_k) from the blocks of exp([[−F, Σ_x], [0, Fᵀ]] dt) (Van Loan 1978), evaluated
    blockwise by Taylor series and squaring (see module docstring)."""
    N = len(F)
    _, Phi, h = expm_taylor(F, dt, order, squarings)
    # Σ(h) = Σ_{k=0}^{order-1} h^{k+1}/(k+1)! L^k(Σ_x), Horner in h
    terms = [Sx]
    X = Sx
    for _ in range(order - 1):
        X = sym_add_transpose(mm(F, X))
        terms.append(X)
    S = [[ZERO] * N for _ in range(N)]
    for k in range(order - 1, -1, -1):
        # Horner: S <- (S + T_k/(k+1)!) h multiplies T_k by h^(k+1) in the end
        S = mscale(madd(S, mscale(terms[k], 1.0 / math.factorial(k + 1))), h)
    for _ in range(squarings):
        S = madd(S, sym_quad(Phi, S))
        Phi = mm(Phi, Phi)
    return Phi, S


def phi_matrix(F, dt, kind: str):
    N = len(F)
    if kind == "pe":
        return madd(eye(N), mscale(F, dt))
    if kind == "se":
        return madd(madd(eye(N), mscale(F, dt)), mscale(mm(F, F), dt * dt * 0.5))
    if kind == "ex":
        return expm_taylor(F, dt)[0]
    raise ValueError(kind)


def sigma_ct(F, Sx, dt):
    """Seed eq. 2.45 (Gibbs): Σ_xΔt + (FΣ_x + Σ_xFᵀ)Δt²/2 + FΣ_xFᵀΔt³/3."""
    FS = mm(F, Sx)
    t1 = mscale(Sx, dt)
    t2 = mscale(sym_add_transpose(FS), dt * dt * 0.5)
    t3 = mscale(sym_quad(F, Sx), dt * dt * dt * (1.0 / 3.0))
    return madd(madd(t1, t2), t3)


def noise_matrix(qdiag, n: int):
    """Σ_x = G Σ^P Gᵀ: the effort PSDs on the diagonal of the T_e block."""
    ne = len(qdiag)
    N = 2 * n + ne
    S = [[ZERO] * N for _ in range(N)]
    for e in range(ne):
        S[2 * n + e][2 * n + e] = qdiag[e]
    return S


# -- integrators -----------------------------------------------------------------------------

def _axpy(x, a, y):
    return [xi + a * yi for xi, yi in zip(x, y)]


def integrate(model, v: Variant, z, zd, te, zdd0, p, dt):
    """(z⁺, ż⁺) from (z, ż, T_e) over dt; zdd0 = z̈ at the start (already computed)."""
    if v.integrator == "fe":
        return _axpy(z, dt, zd), _axpy(zd, dt, zdd0)
    if v.integrator == "heun":
        z1, zd1 = _axpy(z, dt, zd), _axpy(zd, dt, zdd0)
        zdd1 = zdd_of(model, z1, zd1, te, p)
        h = dt * 0.5
        return ([a + h * (b + c) for a, b, c in zip(z, zd, zd1)],
                [a + h * (b + c) for a, b, c in zip(zd, zdd0, zdd1)])
    if v.integrator == "rk4":
        h = dt * 0.5
        k1z, k1v = zd, zdd0
        z2, v2 = _axpy(z, h, k1z), _axpy(zd, h, k1v)
        k2z, k2v = v2, zdd_of(model, z2, v2, te, p)
        z3, v3 = _axpy(z, h, k2z), _axpy(zd, h, k2v)
        k3z, k3v = v3, zdd_of(model, z3, v3, te, p)
        z4, v4 = _axpy(z, dt, k3z), _axpy(zd, dt, k3v)
        k4z, k4v = v4, zdd_of(model, z4, v4, te, p)
        s = dt * (1.0 / 6.0)
        return ([a + s * (b + 2.0 * c + 2.0 * d + e)
                 for a, b, c, d, e in zip(z, k1z, k2z, k3z, k4z)],
                [a + s * (b + 2.0 * c + 2.0 * d + e)
                 for a, b, c, d, e in zip(zd, k1v, k2v, k3v, k4v)])
    h = dt * 0.5
    zn, zdn = _axpy(z, dt, zd), _axpy(zd, dt, zdd0)       # forward-Euler predictor
    if v.integrator == "tf":
        for _ in range(v.iterations):
            zdd_n = zdd_of(model, zn, zdn, te, p)
            zn, zdn = ([a + h * (b + c) for a, b, c in zip(z, zd, zdn)],
                       [a + h * (b + c) for a, b, c in zip(zd, zdd0, zdd_n)])
        return zn, zdn
    if v.integrator == "tn":
        n = len(z)
        for _ in range(v.iterations):
            D = Dynamics(model, zn, zdn, te, p)
            A_z, A_zd, _ = D.sensitivity(full=True)
            g1 = [zn[i] - z[i] - h * (zd[i] + zdn[i]) for i in range(n)]
            g2 = [zdn[i] - zd[i] - h * (zdd0[i] + D.zdd[i]) for i in range(n)]
            # J = [[I, -hI], [-h A_z, I - h A_zd]];  J d = -g  ->  Schur complement in dż
            S = [[(1.0 if i == j else 0.0) - h * A_zd[i][j] - (h * h) * A_z[i][j]
                  for j in range(n)] for i in range(n)]
            rhs = [-(g2[i]) - h * ssum(smul(A_z[i][j], g1[j]) for j in range(n))
                   for i in range(n)]
            dzd = gauss_solve(S, rhs)
            dz = [-(g1[i]) + h * dzd[i] for i in range(n)]
            zn = [a + b for a, b in zip(zn, dz)]
            zdn = [a + b for a, b in zip(zdn, dzd)]
        return zn, zdn
    raise ValueError(v.integrator)


def gauss_solve(A, b):
    """A x = b by Gaussian elimination without pivoting, for a matrix close to the identity
    (the Newton matrix I − hz̈_ż − h²z̈_z with h = Δt/2 small)."""
    n = len(A)
    A = [row[:] for row in A]
    b = list(b)
    for k in range(n):
        inv = 1.0 / fmax(A[k][k], 0.5)
        for i in range(k + 1, n):
            f = A[i][k] * inv
            for j in range(k + 1, n):
                A[i][j] = A[i][j] - f * A[k][j]
            b[i] = b[i] - f * b[k]
        A[k] = [a * inv if j >= k else a for j, a in enumerate(A[k])]
        b[k] = b[k] * inv
    x = [None] * n
    for i in reversed(range(n)):
        acc = b[i]
        for j in range(i + 1, n):
            acc = acc - A[i][j] * x[j]
        x[i] = acc
    return x


# -- prediction and update --------------------------------------------------------------------

def predict(model, v: Variant, z, zd, te, P, qdiag, p, dt):
    """(z⁻, ż⁻, P⁻, z̈ at the start).  F, Φ and Σ_k at the current estimate."""
    n, ne = len(z), len(te)
    D = Dynamics(model, z, zd, te, p)
    A_z, A_zd, A_T = D.sensitivity(full=(v.sensitivity == "full"))
    F = build_F(A_z, A_zd, A_T, n, ne)
    Sx = noise_matrix(qdiag, n)
    if v.sigma == "vl":
        Phi_vl, Sig = van_loan(F, Sx, dt)
        Phi = Phi_vl if v.phi == "ex" else phi_matrix(F, dt, v.phi)
    else:
        Sig = sigma_ct(F, Sx, dt)
        Phi = phi_matrix(F, dt, v.phi)
    Pp = madd(sym_quad(Phi, P), Sig)
    zn, zdn = integrate(model, v, z, zd, te, D.zdd, p, dt)
    return zn, zdn, Pp, D.zdd


def measurement_jacobian(h_fn, z, zd, te, zdd, sens, p):
    """(h, H) of h_fn(z, ż, T_e, z̈, p) -> list at the prior.  H = ∂h/∂x at fixed z̈ plus, for
    sensors that depend on z̈ (accelerometers), ∂h/∂z̈ · [z̈_z, z̈_ż, z̈_T] (sens; None when the
    sensors do not depend on z̈)."""
    n, ne = len(z), len(te)
    N = 2 * n + ne
    K = N + (n if sens is not None else 0)
    t = new_tag()
    zs = [Dual(z[i], unit(K, i), t) for i in range(n)]
    zds = [Dual(zd[i], unit(K, n + i), t) for i in range(n)]
    tes = [Dual(te[i], unit(K, 2 * n + i), t) for i in range(ne)]
    if sens is not None:
        zdds = [Dual(zdd[i], unit(K, N + i), t) for i in range(n)]
    else:
        zdds = list(zdd) if zdd is not None else None
    ys = h_fn(zs, zds, tes, zdds, p)
    h = [value(y, t) for y in ys]
    H = []
    for y in ys:
        row = [tangent(y, j, t) for j in range(N)]
        if sens is not None:
            A_z, A_zd, A_T = sens
            dacc = [tangent(y, N + i, t) for i in range(n)]
            for j in range(n):
                row[j] = sadd(row[j], ssum(smul(dacc[i], A_z[i][j]) for i in range(n)))
                row[n + j] = sadd(row[n + j], ssum(smul(dacc[i], A_zd[i][j]) for i in range(n)))
            for e in range(ne):
                row[2 * n + e] = sadd(row[2 * n + e],
                                      ssum(smul(dacc[i], A_T[i][e]) for i in range(n)))
        H.append(row)
    return h, H


def sequential_update(xv, P, innov, H, rvar, use):
    """Scalar Joseph-form updates in order.  xv: state list (prior), P: full symmetric prior,
    innov: y − h(x⁻) per measurement, H: rows, rvar: sensor variances, use: bool per
    measurement (valid sample).  A measurement with use false, or whose innovation variance is
    not above rvar/2, gets a zero gain (its H row is not zeroed).  Returns (x, P, skipped_any:
    a used measurement was skipped for its innovation variance)."""
    N = len(xv)
    x0 = list(xv)
    x = list(xv)
    P = [row[:] for row in P]
    skipped = False
    for i in range(len(innov)):
        h = H[i]
        cols = [j for j in range(N) if h[j] is not ZERO]
        # innovation corrected for the updates already applied (linear in x: batch-equivalent)
        nu = innov[i]
        if i > 0:
            for j in cols:
                nu = nu - h[j] * (x[j] - x0[j])
        PHt = [ssum(smul(P[r][j], h[j]) for j in cols) for r in range(N)]
        s = sadd(ssum(smul(h[j], PHt[j]) for j in cols), rvar[i])
        ok = s > rvar[i] * 0.5
        ok_use = logical_and(use[i], ok)
        skipped = logical_or(skipped, logical_and(use[i], logical_not(ok)))
        sinv = 1.0 / select(ok, s, rvar[i])
        gain = [select(ok_use, smul(PHt[r], sinv), 0.0) if PHt[r] is not ZERO else ZERO
                for r in range(N)]
        nu_u = select(use[i], nu, 0.0)
        x = [sadd(x[r], smul(gain[r], nu_u)) for r in range(N)]
        # Joseph form for one scalar: P - k PHtᵀ - PHt kᵀ + s k kᵀ, associated as
        # P + k wᵀ - PHt kᵀ with w = s k - PHt (≈ 0: the first-order gain-error terms cancel)
        w = [ssub(smul(s, gain[c]), PHt[c]) for c in range(N)]
        Pn = [[None] * N for _ in range(N)]
        for r in range(N):
            for c in range(r, N):
                a = ssub(sadd(P[r][c], smul(gain[r], w[c])), smul(PHt[r], gain[c]))
                Pn[r][c] = a
                Pn[c][r] = a
        P = Pn
    return x, P, skipped


__all__ = ["Variant", "predict", "sequential_update", "measurement_jacobian", "integrate",
           "phi_matrix", "sigma_ct", "van_loan", "expm_taylor", "build_F", "noise_matrix",
           "unpack_sym", "pack_sym", "tri_size", "diag_sym_init", "start_run_or_hold"]


def start_run_or_hold(initialised, do_init, run, x_init, P0diag, x_upd, P_upd, x_old, P_old,
                      lims, p_lim):
    """The next state of a filter step: started (do_init: x_init, diagonal P0), updated (run),
    or held; then the sanity check (every value finite and within lims, every variance in
    [0, p_lim]) that resets a filter whose estimate broke down.  Returns
    (x, P, initialised, reset_now)."""
    N = len(x_old)
    xs = [select(do_init, a, select(run, b, c)) for a, b, c in zip(x_init, x_upd, x_old)]
    Pn = [[None] * N for _ in range(N)]
    for i in range(N):
        for j in range(i, N):
            p0 = P0diag[i] if i == j else 0.0
            v = select(do_init, p0, select(run, P_upd[i][j], P_old[i][j]))
            Pn[i][j] = v
            Pn[j][i] = v
    init_next = logical_or(initialised, do_init)
    sane = all_of(*(fabs(a) <= lim for a, lim in zip(xs, lims)),
                  *(logical_and(Pn[i][i] >= 0.0, Pn[i][i] <= p_lim) for i in range(N)))
    reset_now = logical_and(init_next, logical_not(sane))
    xs = [select(reset_now, 0.0, a) for a in xs]
    for i in range(N):
        for j in range(i, N):
            p0 = P0diag[i] if i == j else 0.0
            v = select(reset_now, p0, Pn[i][j])
            Pn[i][j] = v
            Pn[j][i] = v
    return xs, Pn, logical_and(init_next, logical_not(reset_now)), reset_now
