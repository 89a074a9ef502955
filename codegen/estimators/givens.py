"""Givens triangularisation for square-root covariance filters (``vak``, ``angle-srukf``).

A square-root filter never forms a covariance P: it carries a factor S (P = S Sᵀ) and gets the
factor of a sum of outer products, Σ_k a_k a_kᵀ, by rotating the rows a_kᵀ of a pre-array until
it is upper triangular.  Each rotation turns the pair (a, b) = (pivot, entry below it) into
(r, 0), r = |(a, b)|, with c = a/r and s = b/r.

Written for fixed point as much as for floating point:

* 1/r comes from ``rnorm`` (the fixed-point path block-scales the pair, so a pair of any size,
  however far below the bounds of its format, gives c and s to full precision).  A square root
  of a² + b² would square values of 1e-2 in a format that must hold the square of the bound
  (16 s_ref in VAK): the squares, and everything after them, would keep 10-15 significant bits.
* r = a c + b s (not sqrt(a² + b²)): the same value, from the precise c and s.
* Every rotated entry keeps its column's bound (a rotation does not change a row's norm, and
  the caller's bounds are bounds on those norms), stated with ``assume`` so the products and
  sums of a rotation keep the column's format.
* A pair that is exactly (0, 0) — or so small that 1/r is floored at 1/sqrt(eps) in a number
  system — has no rotation: c, s would not satisfy c² + s² = 1 there, and the identity is used
  instead (the pair's entries are zero, or below 1e-15: nothing is lost).
"""
from __future__ import annotations

from kinefuse.codegen.scalar import assume, fabs, rnorm, select

RNORM_EPS = 1e-30     # only exact zeros (and, in float32, |(a, b)| < 1e-15) reach the floor


def _zero(v) -> bool:
    return isinstance(v, float) and v == 0.0


def rotation(a, b, bound: float):
    """(t, s, r) of the rotation [[c, s], [−s, c]] taking (a, b) to (r, 0), with c = 1 − t >= 0
    (r has the sign of a; identity for a null pair).  ``bound`` bounds |r| (a row norm)."""
    k, _ = rnorm((a, b), RNORM_EPS)
    c = assume(fabs(a) * k, 0.0, 1.0)
    s = assume(b * k, -1.0, 1.0)
    s = select(a < 0.0, -s, s)
    ok = c * c + s * s > 0.5            # c² + s² = 1 unless 1/r was floored (null pair)
    s = select(ok, s, 0.0)
    t = select(ok, (s * s) / (1.0 + c), 0.0)      # 1 − c without cancellation (c >= 0)
    r = assume(a * select(ok, c, 1.0) + b * s, -bound, bound)   # = ±|(a, b)|
    return t, s, r


def givens_triangularise(rows, bounds):
    """Upper-triangular R (n×n) with RᵀR = AᵀA for the m×n matrix A given as rows (m >= n).
    ``bounds[k]`` bounds |A_ik| of every row (after any rotation: it is a bound on row norms of
    the factor, see the module docstring).  Entries given as the float literal 0.0 are
    structural zeros: no rotation for them.  Returns R as rows."""
    A = [list(r) for r in rows]
    n = len(A[0])
    for j in range(n):
        for i in range(j + 1, len(A)):
            a, b = A[j][j], A[i][j]
            if _zero(b):
                continue
            t, s, r = rotation(a, b, bounds[j])
            A[j][j] = r
            A[i][j] = 0.0
            for k in range(j + 1, n):
                ajk, aik = A[j][k], A[i][k]
                if _zero(ajk) and _zero(aik):
                    continue
                # c x + s y = x − (t x − s y), c y − s x = y − (t y + s x)
                A[j][k] = assume(_upd(ajk, t, s, aik, -1.0), -bounds[k], bounds[k])
                A[i][k] = assume(_upd(aik, t, s, ajk, 1.0), -bounds[k], bounds[k])
    return [A[i][:n] for i in range(n)]


def _upd(x, t, s, y, sign):
    """x − (t x + sign s y) with structural zeros skipped."""
    if _zero(y):
        return x - t * x
    if _zero(x):
        return -(s * y) if sign > 0 else s * y
    return x - (t * x + s * y) if sign > 0 else x - (t * x - s * y)
