"""Observability test of seed 000 (§3.3.4, ch. 4): rank [H; HF; ...; HF^(n-1)] = n, evaluated
with the filter's own linearisation (F and H from the reference code, i.e. the same forward-mode
AD as the generated filter) at a given state, with the rows of lost sensors zeroed.

The rank is numerical: the matrix is first scaled so that every state is expressed in a typical
unit of its own (columns), every sensor in its noise (rows) and every block H F^k to unit norm
(row scalings leave the rank unchanged), then singular values below
``tol`` times the largest count as zero.  The smallest scaled singular value is reported too:
a system can be observable in exact arithmetic and still be poorly observable in practice.
"""
from __future__ import annotations

import dataclasses
from types import SimpleNamespace

import numpy as np

from kinefuse.codegen.estimators.dynamics.ekf import build_F, measurement_jacobian
from kinefuse.codegen.estimators.dynamics.mbs import Dynamics


@dataclasses.dataclass
class Observability:
    rank: int
    n: int
    singular_values: np.ndarray        # of the scaled observability matrix, descending

    @property
    def observable(self) -> bool:
        return self.rank == self.n

    @property
    def condition(self) -> float:
        s = self.singular_values
        return float(s[0] / s[-1]) if s[-1] > 0 else float("inf")

    def as_dict(self) -> dict:
        return {"rank": self.rank, "n": self.n, "observable": self.observable,
                "smallest_relative_singular_value": float(self.singular_values[-1]
                                                          / self.singular_values[0])}


def linearisation(est, z, zd, te, params: dict):
    """(F, H, sensor noise std) of an estimator instance (PendulumEKF / LegEKF) at a state,
    in float64 through the reference code."""
    p = SimpleNamespace(**est.resolve_params(params))
    model = est.model
    n, ne = len(z), len(te)
    D = Dynamics(model, list(z), list(zd), list(te), p)
    A_z, A_zd, A_T = D.sensitivity(full=True)
    F = np.array([[float(v) for v in row] for row in build_F(A_z, A_zd, A_T, n, ne)])
    needs_acc = est.name.startswith("leg")
    sens = (A_z, A_zd, A_T) if needs_acc else None
    _, H = measurement_jacobian(est.h_fn, list(z), list(zd), list(te),
                                D.zdd if needs_acc else None, sens, p)
    H = np.array([[float(v) for v in row] for row in H])
    return F, H


def observability(F: np.ndarray, H: np.ndarray, lost_rows=(), state_scale=None,
                  sensor_scale=None, tol: float = 1e-9) -> Observability:
    """Rank of the observability matrix with the rows `lost_rows` of H zeroed."""
    H = H.copy()
    H[list(lost_rows), :] = 0.0
    n = F.shape[0]
    S = np.diag(state_scale) if state_scale is not None else np.eye(n)
    Sinv = np.linalg.inv(S)
    Fs = Sinv @ F @ S
    Hs = H @ S
    if sensor_scale is not None:
        Hs = Hs / np.asarray(sensor_scale, float)[:, None]
    blocks = [Hs]
    for _ in range(n - 1):
        blocks.append(blocks[-1] @ Fs)
    # each block H F^k scaled to unit norm: rows scale freely without changing the rank, and
    # F^k spans many orders of magnitude for k up to n - 1
    blocks = [b / np.linalg.norm(b) if np.linalg.norm(b) > 0 else b for b in blocks]
    O = np.vstack(blocks)
    sv = np.linalg.svd(O, compute_uv=False)
    rank = int(np.sum(sv > tol * sv[0])) if sv[0] > 0 else 0
    return Observability(rank, n, sv)


__all__ = ["Observability", "observability", "linearisation"]
