"""Planar multibody dynamics in the velocity-transformation (R-matrix) formulation, with every
derivative produced by forward-mode AD (:mod:`.ad`), written with the scalar interface.

A model (see :mod:`.models`) gives position-level functions only:

* ``phi(z, p)``: the dependent coordinates q(z) (natural coordinates of points, or the centre of
  mass and angle of each body), whose constant mass matrix M̄ and applied-force vector Q̄
  (gravity) are ``mbar(p)`` / ``qbar(p)``;
* ``conj(z, p)``: for every effort of T_e the coordinate s_e(z) it does virtual work on
  (a joint angle for a joint torque, a point's x or y for a force), so that the velocity
  transformation of the efforts is B = ds/dz and their generalised forces are Bᵀ T_e
  (seed 000 eqs. 3.9-3.11);
* ``sensors``: measured quantities as functions of z, ż, z̈ and T_e.

From these, by differentiation (never typed by hand):

* R = dφ/dz and Ṙż = d²φ[ż, ż] (two nested forward passes: :func:`kinematics`);
* M(z) = Rᵀ M̄ R and Q_g(z, ż) = Rᵀ (Q̄ − M̄ Ṙ ż) (seed eqs. 2.16-2.17, 3.37);
* Bᵀ(z);
* the sensitivity blocks of z̈ = M⁻¹(Q_g + Bᵀ T_e) (seed eqs. 3.42-3.50) as
  M⁻¹ [∂r/∂z, ∂r/∂ż, Bᵀ] with r(z, ż) = Q_g + Bᵀ T_e − M z̈ at fixed z̈ and T_e, which equals
  (M⁻¹)_z (Q_g + BᵀT_e) − M⁻¹[K − (Bᵀ)_z T_e] and −M⁻¹ C of the seed, since
  (M⁻¹)_z = −M⁻¹ M_z M⁻¹ (eq. 3.49): one factorisation of M serves z̈ and all derivatives.
"""
from __future__ import annotations

from kinefuse.codegen.linalg import ZERO, sadd, smul, ssub, ssum
from kinefuse.codegen.scalar import fmax
from kinefuse.codegen.estimators.dynamics.ad import Dual, new_tag, tangent, value


def unit(n: int, i: int):
    return tuple(1.0 if j == i else ZERO for j in range(n))


def kinematics(fn, z, zd, p):
    """(q, R, Rdz) for the position function fn(z, p) -> list: q = fn(z), R[k][j] = ∂q_k/∂z_j,
    Rdz[k] = Σ_ij ∂²q_k/∂z_i∂z_j ż_i ż_j  (= Ṙ ż, the velocity-dependent part of q̈).

    Level a differentiates along the n unit vectors and along ż; level b (on top) along ż;
    the mixed a(ż)-b(ż) derivative is d²q[ż, ż]."""
    n = len(z)
    ta = new_tag()
    tb = new_tag()
    za = [Dual(z[i], unit(n, i) + (zd[i],), ta) for i in range(n)]
    zb = [Dual(za[i], (zd[i],), tb) for i in range(n)]
    ys = fn(zb, p)
    q, R, Rdz = [], [], []
    for y in ys:
        vb = value(y, tb)
        db = tangent(y, 0, tb)
        q.append(value(vb, ta))
        R.append([tangent(vb, j, ta) for j in range(n)])
        Rdz.append(tangent(db, n, ta))
    return q, R, Rdz


def jacobian_of(fn, z, p):
    """(s, J) with J[e][j] = ∂s_e/∂z_j for s = fn(z, p)."""
    n = len(z)
    t = new_tag()
    zs = [Dual(z[i], unit(n, i), t) for i in range(n)]
    ys = fn(zs, p)
    return [value(y, t) for y in ys], [[tangent(y, j, t) for j in range(n)] for y in ys]


def matvec(A, v):
    return [ssum(smul(a, x) for a, x in zip(row, v)) for row in A]


def mass_and_bias(R, Rdz, mbar, qbar):
    """M = Rᵀ M̄ R (symmetric: upper triangle computed, mirrored) and Q_g = Rᵀ(Q̄ − M̄ Ṙż)."""
    nq, n = len(R), len(R[0])
    MR = [[ssum(smul(mbar[k][l], R[l][j]) for l in range(nq)) for j in range(n)]
          for k in range(nq)]
    M = [[ZERO] * n for _ in range(n)]
    for i in range(n):
        for j in range(i, n):
            v = ssum(smul(R[k][i], MR[k][j]) for k in range(nq))
            M[i][j] = v
            M[j][i] = v
    mrd = matvec(mbar, Rdz)
    w = [ssub(qbar[k], mrd[k]) for k in range(nq)]
    Qg = [ssum(smul(R[k][i], w[k]) for k in range(nq)) for i in range(n)]
    return M, Qg


class Dynamics:
    """Everything the filter needs from a model at one state (z, ż, T_e)."""

    def __init__(self, model, z, zd, te, p, pivot_eps: float = 1e-9):
        self.model = model
        self.n = len(z)
        self.z, self.zd, self.te, self.p = list(z), list(zd), list(te), p
        _, R, Rdz = kinematics(model.phi, self.z, self.zd, p)
        self.M, self.Qg = mass_and_bias(R, Rdz, model.mbar(p), model.qbar(p))
        _, B = jacobian_of(model.conj, self.z, p)
        self.Bt = [[B[e][i] for e in range(len(B))] for i in range(self.n)]
        self.rhs = [sadd(self.Qg[i], ssum(smul(self.Bt[i][e], te[e]) for e in range(len(te))))
                    for i in range(self.n)]
        self.L, self.dinv = ldl(self.M, pivot_eps)
        self.zdd = ldl_solve(self.L, self.dinv, self.rhs)

    def solve(self, b):
        """M⁻¹ b with the factorisation of this state."""
        return ldl_solve(self.L, self.dinv, b)

    def sensitivity(self, full: bool = True):
        """(z̈_z, z̈_ż, z̈_T) as n×n, n×n, n×n_e lists (ZERO blocks when not full)."""
        n, ne = self.n, len(self.te)
        zdd_t = [self.solve([self.Bt[i][e] for i in range(n)]) for e in range(ne)]
        A_T = [[zdd_t[e][i] for e in range(ne)] for i in range(n)]
        if not full:
            zero = [[ZERO] * n for _ in range(n)]
            return zero, [row[:] for row in zero], A_T
        r_x = residual_jacobian(self.model, self.z, self.zd, self.zdd, self.te, self.p)
        cols = [self.solve([r_x[i][j] for i in range(n)]) for j in range(2 * n)]
        A_z = [[cols[j][i] for j in range(n)] for i in range(n)]
        A_zd = [[cols[n + j][i] for j in range(n)] for i in range(n)]
        return A_z, A_zd, A_T


def residual(model, z, zd, zdd, te, p):
    """r = Q_g(z, ż) + Bᵀ(z) T_e − M(z) z̈ (zero on the equations of motion)."""
    _, R, Rdz = kinematics(model.phi, z, zd, p)
    M, Qg = mass_and_bias(R, Rdz, model.mbar(p), model.qbar(p))
    _, B = jacobian_of(model.conj, z, p)
    n = len(z)
    out = []
    for i in range(n):
        f = ssum(smul(B[e][i], te[e]) for e in range(len(te)))
        mz = ssum(smul(M[i][j], zdd[j]) for j in range(n))
        out.append(ssub(sadd(Qg[i], f), mz))
    return out


def residual_jacobian(model, z, zd, zdd, te, p):
    """∂r/∂[z, ż] at fixed z̈ and T_e: n × 2n."""
    n = len(z)
    t = new_tag()
    zs = [Dual(z[i], unit(2 * n, i), t) for i in range(n)]
    zds = [Dual(zd[i], unit(2 * n, n + i), t) for i in range(n)]
    r = residual(model, zs, zds, zdd, te, p)
    return [[tangent(ri, j, t) for j in range(2 * n)] for ri in r]


def ldl(M, eps: float):
    """M = L D Lᵀ for a symmetric positive definite M; returns (L, 1/D).  Pivots are floored
    at eps (a mass matrix has pivots of the order of the smallest inertia, far above it)."""
    n = len(M)
    L = [[ZERO] * n for _ in range(n)]
    D, dinv = [None] * n, [None] * n
    for j in range(n):
        acc = M[j][j]
        for k in range(j):
            acc = ssub(acc, smul(smul(L[j][k], L[j][k]), D[k]))
        D[j] = acc
        dinv[j] = 1.0 / fmax(acc, eps)
        for i in range(j + 1, n):
            a = M[i][j]
            for k in range(j):
                a = ssub(a, smul(smul(L[i][k], L[j][k]), D[k]))
            L[i][j] = smul(a, dinv[j])
    return L, dinv


def ldl_solve(L, dinv, b):
    n = len(L)
    y = list(b)
    for i in range(n):
        for k in range(i):
            y[i] = ssub(y[i], smul(L[i][k], y[k]))
    y = [smul(y[i], dinv[i]) for i in range(n)]
    x = list(y)
    for i in reversed(range(n)):
        for k in range(i + 1, n):
            x[i] = ssub(x[i], smul(L[k][i], x[k]))
    return x


def zdd_of(model, z, zd, te, p):
    """Forward dynamics z̈ = M⁻¹ (Q_g + Bᵀ T_e)."""
    return Dynamics(model, z, zd, te, p).zdd


def point_kinematics(fn, z, zd, zdd, p):
    """Positions, velocities and accelerations of the points fn(z, p) -> [x0, y0, x1, y1, ...]:
    r, J ż and J z̈ + J̇ ż."""
    r, J, Jdz = kinematics(fn, z, zd, p)
    vel = matvec(J, zd)
    acc = [sadd(a, b) for a, b in zip(matvec(J, zdd), Jdz)]
    return r, vel, acc


__all__ = ["kinematics", "jacobian_of", "mass_and_bias", "Dynamics", "residual",
           "residual_jacobian", "ldl", "ldl_solve", "zdd_of", "point_kinematics"]


def static_efforts(model, z, zd, te_known, unknown, p, eps: float = 1e-9, zdd=None):
    """Efforts `unknown` (indices, 1 or 2 of them) that balance the others at z̈ = zdd (None:
    z̈ = 0): least squares of B_uᵀ u = M z̈ − (Q_g(z, ż) + Σ_known Bᵀ T_e) — a starting value for
    efforts without a sensor (inverse dynamics at the given z̈; quasi-static without it: the
    inertial terms are ignored).  te_known holds the known efforts (unknown entries ignored)."""
    from kinefuse.codegen.scalar import fmax
    te = [ZERO if i in unknown else v for i, v in enumerate(te_known)]
    _, R, Rdz = kinematics(model.phi, list(z), list(zd), p)
    M, Qg = mass_and_bias(R, Rdz, model.mbar(p), model.qbar(p))
    _, B = jacobian_of(model.conj, list(z), p)
    n = len(z)
    r = [ssub(_inertial(M, zdd, i), sadd(Qg[i], ssum(smul(B[e][i], te[e]) for e in range(len(te)))))
         for i in range(n)]
    cols = [[B[e][i] for i in range(n)] for e in unknown]
    # normal equations (k x k, k <= 2)
    g = [[ssum(smul(a, b) for a, b in zip(ca, cb)) for cb in cols] for ca in cols]
    rhs = [ssum(smul(a, b) for a, b in zip(ca, r)) for ca in cols]
    if len(unknown) == 1:
        return [smul(rhs[0], 1.0 / fmax(g[0][0], eps))]
    if len(unknown) == 2:
        det = ssub(smul(g[0][0], g[1][1]), smul(g[0][1], g[1][0]))
        inv = 1.0 / fmax(det, eps)     # Gram matrix: det >= 0
        return [smul(ssub(smul(g[1][1], rhs[0]), smul(g[0][1], rhs[1])), inv),
                smul(ssub(smul(g[0][0], rhs[1]), smul(g[1][0], rhs[0])), inv)]
    raise ValueError("static_efforts handles 1 or 2 unknown efforts")


def _inertial(M, zdd, i):
    """(M z̈)_i, or ZERO for the quasi-static balance (zdd None)."""
    return ZERO if zdd is None else ssum(smul(M[i][j], zdd[j]) for j in range(len(zdd)))
