"""The kinematic baseline of seed 000 §3.1 ("FCDI"): a DWNA extended Kalman filter on the
positions and velocities of the independent coordinates, observed by the markers; the
accelerations by finite differences of the estimated velocities (eq. 3.7); the joint torque and
the base residual by inverse dynamics with the measured reactions (eq. 3.12).

Host-side reference implementation (numpy, float64): it is the competitor of the dynamic EKF in
the benchmarks, not a firmware filter.  Units: m, rad, s, N, N·m.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from kinefuse.host.dynamics import truth as T


def marker_matrix(L: float) -> np.ndarray:
    """C (8×6) with markers = C q for the natural coordinates q = [x0 y0 x1 y1 x2 y2]
    (marker = (1 − s) a + s b + (d/L) perp(b − a), perp(x, y) = (−y, x))."""
    C = np.zeros((8, 6))
    for i, (bar, s, d) in enumerate(T.MARKERS):
        a, b = 2 * (bar - 1), 2 * bar
        k = d / L
        # x: (1-s) ax + s bx - k (by - ay);  y: (1-s) ay + s by + k (bx - ax)
        C[2 * i, a] += 1 - s
        C[2 * i, b] += s
        C[2 * i, b + 1] += -k
        C[2 * i, a + 1] += k
        C[2 * i + 1, a + 1] += 1 - s
        C[2 * i + 1, b + 1] += s
        C[2 * i + 1, b] += k
        C[2 * i + 1, a] += -k
    return C


def z_from_markers(mk: np.ndarray, L: float) -> np.ndarray:
    """z = [x0 y0 θ1 θ2] from one frame of the four markers (same geometry as the filter)."""
    out = []
    first = None
    for bar in (1, 2):
        (ia, (_, sa, da)), (ib, (_, sb, db)) = [(i, m) for i, m in enumerate(T.MARKERS)
                                                if m[0] == bar]
        ax, ay = mk[2 * ia], mk[2 * ia + 1]
        bx, by = mk[2 * ib], mk[2 * ib + 1]
        delta = math.atan2(db - da, (sb - sa) * L)
        th = math.atan2(by - ay, bx - ax) - delta + math.pi / 2
        if th > math.pi:
            th -= 2 * math.pi
        out.append(th)
        if bar == 1:
            first = (ax, ay, sa, da)
    ax, ay, sa, da = first
    t1 = out[0]
    x0 = ax - sa * L * math.sin(t1) - da * math.cos(t1)
    y0 = ay + sa * L * math.cos(t1) - da * math.sin(t1)
    return np.array([x0, y0, out[0], out[1]])


@dataclasses.dataclass
class FcdiConfig:
    m1: float = 50.0
    m2: float = 35.0
    L: float = 0.8
    g: float = 9.81
    sigma_a: float = 30.0        # DWNA acceleration noise (m/s² and rad/s² per DOF)
    sigma_marker: float = 1e-3   # m
    p0_pos: float = 0.02
    p0_vel: float = 1.0


def fcdi(markers: np.ndarray, marker_valid: np.ndarray, plate: np.ndarray, dt: np.ndarray,
         cfg: FcdiConfig) -> dict[str, np.ndarray]:
    """Run FCDI over a trial.  plate: (N, 3) measured Fx, Fy, T2.  Returns z, zd, zdd (N, 4),
    te (N, 4: τ1 from inverse dynamics, then the plate as measured) and residual (N, 3)."""
    n = len(markers)
    C = marker_matrix(cfg.L)
    z = np.zeros((n, 4))
    zd = np.zeros((n, 4))
    x = None
    P = None
    for k in range(n):
        valid = np.repeat(np.asarray(marker_valid[k], bool), 2) & np.isfinite(markers[k])
        if x is None:
            if not valid.all():
                continue
            x = np.concatenate([z_from_markers(markers[k], cfg.L), np.zeros(4)])
            P = np.diag([cfg.p0_pos ** 2] * 4 + [cfg.p0_vel ** 2] * 4)
        else:
            h = dt[k]
            Phi = np.eye(8)
            Phi[:4, 4:] = np.eye(4) * h
            q = cfg.sigma_a ** 2
            Q = np.zeros((8, 8))
            Q[:4, :4] = np.eye(4) * h ** 4 / 4 * q
            Q[:4, 4:] = Q[4:, :4] = np.eye(4) * h ** 3 / 2 * q
            Q[4:, 4:] = np.eye(4) * h ** 2 * q
            x = Phi @ x
            P = Phi @ P @ Phi.T + Q
            if valid.any():
                R = T.pendulum_R(x[:4], cfg.L)
                qn = np.array(_points(x[:4], cfg.L))
                hx = C @ qn
                H = np.zeros((8, 8))
                H[:, :4] = C @ R
                H, nu = H[valid], (markers[k] - hx)[valid]
                S = H @ P @ H.T + np.eye(int(valid.sum())) * cfg.sigma_marker ** 2
                K = np.linalg.solve(S, H @ P).T
                x = x + K @ nu
                IKH = np.eye(8) - K @ H
                P = IKH @ P @ IKH.T + K @ K.T * cfg.sigma_marker ** 2
        z[k], zd[k] = x[:4], x[4:]
    zdd = np.zeros_like(zd)
    zdd[1:] = (zd[1:] - zd[:-1]) / dt[1:, None]
    te = np.zeros((n, 4))
    res = np.zeros((n, 3))
    for k in range(n):
        M, Qg = T.pendulum_M_Qg(z[k], zd[k], cfg.m1, cfg.m2, cfg.L, cfg.g)
        Bt = T.pendulum_Bt(z[k], cfg.L)
        rhs = M @ zdd[k] - Qg - Bt[:, 1:] @ plate[k]
        # B_dᵀ [τ1 Frx Fry Mr] = rhs with columns [0 0 -1 1], e_x0, e_y0, e_θ1
        tau1 = rhs[3]
        res[k] = [rhs[0], rhs[1], rhs[2] + tau1]
        te[k] = [tau1, *plate[k]]
    return {"z": z, "zd": zd, "zdd": zdd, "te": te, "residual": res}


def _points(z, L):
    x0, y0, t1, t2 = z
    x1, y1 = x0 + L * math.sin(t1), y0 - L * math.cos(t1)
    return [x0, y0, x1, y1, x1 + L * math.sin(t2), y1 - L * math.cos(t2)]


__all__ = ["FcdiConfig", "fcdi", "marker_matrix", "z_from_markers"]
