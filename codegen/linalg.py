"""Small vector and quaternion helpers written with the scalar interface.

They read as mathematics and run unchanged on floats (reference) and traced values.  The order of
operations written here *is* the order of the generated C, so every formula is spelled out.

Conventions: quaternions are (w, x, y, z), Hamilton product, and an orientation quaternion q maps
sensor-frame vectors to the earth frame: v_earth = q ⊗ v_sensor ⊗ q*.
"""
from __future__ import annotations

from kinefuse.codegen.scalar import assume, rnorm, select


class Vec3(tuple):
    """A 3-vector of scalars."""

    __slots__ = ()

    def __new__(cls, x, y, z):
        return tuple.__new__(cls, (x, y, z))

    x = property(lambda s: s[0])
    y = property(lambda s: s[1])
    z = property(lambda s: s[2])

    def __add__(self, o):
        return Vec3(self[0] + o[0], self[1] + o[1], self[2] + o[2])

    def __sub__(self, o):
        return Vec3(self[0] - o[0], self[1] - o[1], self[2] - o[2])

    def __neg__(self):
        return Vec3(-self[0], -self[1], -self[2])

    def __mul__(self, k):
        """Scale by a scalar."""
        return Vec3(self[0] * k, self[1] * k, self[2] * k)

    __rmul__ = __mul__

    def dot(self, o):
        return self[0] * o[0] + self[1] * o[1] + self[2] * o[2]

    def cross(self, o):
        return Vec3(self[1] * o[2] - self[2] * o[1],
                    self[2] * o[0] - self[0] * o[2],
                    self[0] * o[1] - self[1] * o[0])

    def norm_sq(self):
        return self[0] * self[0] + self[1] * self[1] + self[2] * self[2]

    def normalized(self, eps: float):
        """(unit vector, squared norm).  The squared norm is floored at eps before 1/sqrt, so the
        result is finite for a zero vector (callers reject such samples)."""
        k, n2 = rnorm(self, eps)
        return Vec3(*(assume(c * k, -1.0, 1.0) for c in self)), n2


def rotation_rows(q) -> list:
    """Rotation matrix of a unit quaternion (w, x, y, z) as rows (sensor -> earth for an
    orientation quaternion)."""
    w, x, y, z = q
    xx, yy, zz = x * x, y * y, z * z
    xy, xz, yz = x * y, x * z, y * z
    wx, wy, wz = w * x, w * y, w * z
    return [[1.0 - 2.0 * (yy + zz), 2.0 * (xy - wz), 2.0 * (xz + wy)],
            [2.0 * (xy + wz), 1.0 - 2.0 * (xx + zz), 2.0 * (yz - wx)],
            [2.0 * (xz - wy), 2.0 * (yz + wx), 1.0 - 2.0 * (xx + yy)]]


def _literal_zero(v) -> bool:
    return isinstance(v, (int, float)) and v == 0


def _sum_products(*terms):
    """±a·b ± c·d ..., left to right, skipping products with a literal zero factor."""
    acc = None
    for sign, a, b in terms:
        if _literal_zero(a) or _literal_zero(b):
            continue
        p = a * b
        acc = (p if sign > 0 else -p) if acc is None else (acc + p if sign > 0 else acc - p)
    return 0.0 if acc is None else acc


def vselect(cond, a, b):
    """Element-wise select of two equally long tuples (Vec3 or Quat)."""
    return type(a)(*(select(cond, x, y) for x, y in zip(a, b)))


class Quat(tuple):
    """A quaternion (w, x, y, z)."""

    __slots__ = ()

    def __new__(cls, w, x, y, z):
        return tuple.__new__(cls, (w, x, y, z))

    w = property(lambda s: s[0])
    x = property(lambda s: s[1])
    y = property(lambda s: s[2])
    z = property(lambda s: s[3])

    @property
    def vec(self) -> Vec3:
        return Vec3(self[1], self[2], self[3])

    def __mul__(self, o):
        """Hamilton product self ⊗ o.  Terms with a literal 0 factor (a pure quaternion
        (0, v) written in the code) are left out rather than multiplied by zero."""
        aw, ax, ay, az = self
        bw, bx, by, bz = o
        return Quat(_sum_products((1, aw, bw), (-1, ax, bx), (-1, ay, by), (-1, az, bz)),
                    _sum_products((1, aw, bx), (1, ax, bw), (1, ay, bz), (-1, az, by)),
                    _sum_products((1, aw, by), (-1, ax, bz), (1, ay, bw), (1, az, bx)),
                    _sum_products((1, aw, bz), (1, ax, by), (-1, ay, bx), (1, az, bw)))

    def __add__(self, o):
        return Quat(self[0] + o[0], self[1] + o[1], self[2] + o[2], self[3] + o[3])

    def __sub__(self, o):
        return Quat(self[0] - o[0], self[1] - o[1], self[2] - o[2], self[3] - o[3])

    def scale(self, k):
        return Quat(self[0] * k, self[1] * k, self[2] * k, self[3] * k)

    def conj(self):
        return Quat(self[0], -self[1], -self[2], -self[3])

    def dot(self, o):
        return self[0] * o[0] + self[1] * o[1] + self[2] * o[2] + self[3] * o[3]

    def norm_sq(self):
        return self[0] * self[0] + self[1] * self[1] + self[2] * self[2] + self[3] * self[3]

    def normalized(self, eps: float = 1e-6, split: bool = False):
        """Unit quaternion (components assumed within [-1, 1]); split: see scalar.rnorm."""
        k, _ = rnorm(self, eps, split)
        return Quat(*(assume(c * k, -1.0, 1.0) for c in self))

    def rotate(self, v: Vec3) -> Vec3:
        """q ⊗ v ⊗ q*  (sensor → earth for an orientation quaternion)."""
        w, x, y, z = self
        # t = 2 q_v × v ;  v' = v + w t + q_v × t
        tx = 2.0 * (y * v[2] - z * v[1])
        ty = 2.0 * (z * v[0] - x * v[2])
        tz = 2.0 * (x * v[1] - y * v[0])
        return Vec3(v[0] + w * tx + (y * tz - z * ty),
                    v[1] + w * ty + (z * tx - x * tz),
                    v[2] + w * tz + (x * ty - y * tx))

    def rotate_inv(self, v: Vec3) -> Vec3:
        """q* ⊗ v ⊗ q  (earth → sensor)."""
        return self.conj().rotate(v)

    def earth_z_in_sensor(self) -> Vec3:
        """Third row of the rotation matrix: the earth's vertical axis in sensor coordinates."""
        w, x, y, z = self
        return Vec3(2.0 * (x * z - w * y),
                    2.0 * (y * z + w * x),
                    w * w - x * x - y * y + z * z)


def quat_from_rotvec_small(hx, hy, hz) -> Quat:
    """Unnormalised quaternion of a small rotation with half-angle vector (hx, hy, hz):
    (1, h).  Callers normalise; exact to second order, which is what a strapdown step needs."""
    return Quat(1.0, hx, hy, hz)


# -- small dense matrices with structural zeros -------------------------------------------------
#
# A matrix is a list of rows (lists).  Entries that are the singleton ZERO are *structural*
# zeros: products and sums skip them, in the reference and in the traced graph alike, so sparse
# Jacobians cost nothing.  A computed value that happens to be 0.0 is an ordinary number.

class _StructuralZero(float):
    """The structural zero (a float 0.0 that matrix helpers recognise by identity)."""

    __slots__ = ()

    def __repr__(self):
        return "ZERO"


ZERO = _StructuralZero(0.0)


def is_zero(x) -> bool:
    return x is ZERO


def sadd(a, b):
    """a + b skipping structural zeros."""
    if a is ZERO:
        return b
    if b is ZERO:
        return a
    return a + b


def ssub(a, b):
    if b is ZERO:
        return a
    if a is ZERO:
        return -b
    return a - b


def smul(a, b):
    """a * b; ZERO if either factor is a structural zero."""
    if a is ZERO or b is ZERO:
        return ZERO
    return a * b


def ssum(terms):
    """Left-to-right sum of the terms that are not structural zeros (ZERO if none)."""
    out = ZERO
    for t in terms:
        out = sadd(out, t)
    return out


def zeros(r: int, c: int):
    return [[ZERO] * c for _ in range(r)]


def eye(n: int):
    return [[1.0 if i == j else ZERO for j in range(n)] for i in range(n)]


def diag(values):
    n = len(values)
    return [[values[i] if i == j else ZERO for j in range(n)] for i in range(n)]


def transpose(A):
    return [list(col) for col in zip(*A)]


def matmul(A, B):
    """A @ B with terms summed left to right over k, structural zeros skipped."""
    bt = transpose(B)
    return [[ssum(smul(a, b) for a, b in zip(row, col)) for col in bt] for row in A]


def matvec(A, v):
    return [ssum(smul(a, x) for a, x in zip(row, v)) for row in A]


def matadd(A, B):
    return [[sadd(a, b) for a, b in zip(ra, rb)] for ra, rb in zip(A, B)]


def matsub(A, B):
    return [[ssub(a, b) for a, b in zip(ra, rb)] for ra, rb in zip(A, B)]


def matscale(A, k):
    return [[smul(a, k) for a in row] for row in A]


def symmetrize(A):
    """(A + A^T) / 2, computed once per pair: keeps a covariance exactly symmetric."""
    n = len(A)
    out = [row[:] for row in A]
    for i in range(n):
        for j in range(i + 1, n):
            if A[i][j] is ZERO and A[j][i] is ZERO:
                continue
            s = smul(sadd(A[i][j], A[j][i]), 0.5)
            out[i][j] = s
            out[j][i] = s
    return out


def quadform(A, P):
    """A P A^T (the covariance propagation pattern), symmetric by construction: only the upper
    triangle is computed and mirrored."""
    AP = matmul(A, P)
    n = len(A)
    out = zeros(n, n)
    for i in range(n):
        for j in range(i, n):
            v = ssum(smul(AP[i][k], A[j][k]) for k in range(len(P)))
            out[i][j] = v
            out[j][i] = v
    return out
