"""Scalar time signals with exact first and second derivatives.

Every signal is a callable ``s(t) -> (f, f', f'')`` over an array of times t (s).  Motion is
built from these so that angular velocity and linear acceleration are analytic, never
finite differences.  Building blocks:

* :class:`Const`, :class:`SineSum`, :class:`Fourier` (periodic series),
* :class:`PPolySignal` (exact piecewise polynomials; made by :class:`Profile` and
  :func:`window`), and the combinators ``a + b``, ``k * a``, ``a * b`` (product rule).

A :class:`Profile` is a C² piecewise-polynomial history made of holds and moves (constant
rate with smooth acceleration blends), used for joint angles and rotation angles.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.polynomial import Polynomial as P
from scipy.interpolate import PPoly

from .errors import SpecError


class ScalarSignal:
    """Base class: ``__call__(t)`` returns ``(f, df/dt, d²f/dt²)`` as float64 arrays."""

    def __call__(self, t):  # pragma: no cover - abstract
        raise NotImplementedError

    def value(self, t):
        return self(t)[0]

    def moving(self, t) -> np.ndarray:
        """Design flag: True where this signal is meant to be in motion (default: always)."""
        return np.ones(np.shape(t), dtype=bool)

    def __add__(self, other):
        return _Sum(self, _as_signal(other))

    __radd__ = __add__

    def __sub__(self, other):
        return _Sum(self, _Scaled(_as_signal(other), -1.0))

    def __neg__(self):
        return _Scaled(self, -1.0)

    def __mul__(self, other):
        if isinstance(other, ScalarSignal):
            return _Product(self, other)
        return _Scaled(self, float(other))

    __rmul__ = __mul__


def _as_signal(x) -> ScalarSignal:
    return x if isinstance(x, ScalarSignal) else Const(float(x))


@dataclass(frozen=True)
class Const(ScalarSignal):
    c: float = 0.0

    def __call__(self, t):
        t = np.asarray(t, dtype=float)
        z = np.zeros_like(t)
        return z + self.c, z, z.copy()

    def moving(self, t):
        return np.zeros(np.shape(t), dtype=bool)


@dataclass(frozen=True)
class _Sum(ScalarSignal):
    a: ScalarSignal
    b: ScalarSignal

    def __call__(self, t):
        fa, da, aa = self.a(t)
        fb, db, ab = self.b(t)
        return fa + fb, da + db, aa + ab

    def moving(self, t):
        return self.a.moving(t) | self.b.moving(t)


@dataclass(frozen=True)
class _Scaled(ScalarSignal):
    a: ScalarSignal
    k: float

    def __call__(self, t):
        f, d, a = self.a(t)
        return self.k * f, self.k * d, self.k * a

    def moving(self, t):
        return self.a.moving(t) & (self.k != 0.0)


@dataclass(frozen=True)
class _Product(ScalarSignal):
    a: ScalarSignal
    b: ScalarSignal

    def __call__(self, t):
        fa, da, aa = self.a(t)
        fb, db, ab = self.b(t)
        return fa * fb, da * fb + fa * db, aa * fb + 2.0 * da * db + fa * ab

    def moving(self, t):
        return self.a.moving(t) & self.b.moving(t)


@dataclass(frozen=True)
class SineSum(ScalarSignal):
    """offset + Σ amp_k · sin(2π freq_k · t + phase_k); amp in the signal's unit, freq in Hz."""
    amps: tuple
    freqs_hz: tuple
    phases: tuple
    offset: float = 0.0

    def __call__(self, t):
        t = np.asarray(t, dtype=float)
        a = np.asarray(self.amps, dtype=float)
        w = 2.0 * np.pi * np.asarray(self.freqs_hz, dtype=float)
        arg = t[..., None] * w + np.asarray(self.phases, dtype=float)
        s, c = np.sin(arg), np.cos(arg)
        return (self.offset + s @ a, c @ (a * w), -(s @ (a * w * w)))


@dataclass(frozen=True)
class Fourier(ScalarSignal):
    """a0 + Σ_k a_k cos(2πk t/T) + b_k sin(2πk t/T), k = 1..K (period T in s)."""
    period_s: float
    a0: float
    a: tuple
    b: tuple
    phase_s: float = 0.0  # time shift: evaluates the series at t + phase_s

    def __call__(self, t):
        t = np.asarray(t, dtype=float) + self.phase_s
        k = np.arange(1, len(self.a) + 1)
        w = 2.0 * np.pi * k / self.period_s
        arg = t[..., None] * w
        s, c = np.sin(arg), np.cos(arg)
        a = np.asarray(self.a, dtype=float)
        b = np.asarray(self.b, dtype=float)
        f = self.a0 + c @ a + s @ b
        d = s @ (-a * w) + c @ (b * w)
        dd = -(c @ (a * w * w) + s @ (b * w * w))
        return f, d, dd


class PPolySignal(ScalarSignal):
    """Exact piecewise polynomial.  Outside its breakpoints it holds the end values and has
    zero derivatives (every builder here ends its pieces at rest, so this is exact)."""

    def __init__(self, pp: PPoly, moving_intervals=()):
        self.pp = pp
        self.d1 = pp.derivative(1)
        self.d2 = pp.derivative(2)
        self.t0 = float(pp.x[0])
        self.t1 = float(pp.x[-1])
        self.moving_intervals = tuple((float(a), float(b)) for a, b in moving_intervals)

    def __call__(self, t):
        t = np.asarray(t, dtype=float)
        tc = np.clip(t, self.t0, self.t1)
        inside = (t >= self.t0) & (t <= self.t1)
        return self.pp(tc), np.where(inside, self.d1(tc), 0.0), np.where(inside, self.d2(tc), 0.0)

    def moving(self, t):
        t = np.asarray(t, dtype=float)
        m = np.zeros(t.shape, dtype=bool)
        for a, b in self.moving_intervals:
            m |= (t >= a) & (t < b)
        return m

    def antiderivative(self) -> "PPolySignal":
        """∫ from t0 (extrapolated as constant-slope-zero only if the integrand ends at 0)."""
        return PPolySignal(self.pp.antiderivative(), self.moving_intervals)

    @property
    def duration(self) -> float:
        return self.t1 - self.t0


MIN_BLEND_S = 1e-3


def _smoothstep5() -> P:
    """S(x) = 10x³ − 15x⁴ + 6x⁵: S, S', S'' vanish at 0; S(1) = 1, S'(1) = S''(1) = 0."""
    return P([0, 0, 0, 10, -15, 6])


def _pieces_to_ppoly(breaks, polys) -> PPoly:
    """PPoly from local-variable polynomials (numpy Polynomial, lowest power first)."""
    deg = max(p.degree() for p in polys)
    c = np.zeros((deg + 1, len(polys)))
    for i, p in enumerate(polys):
        coef = np.zeros(deg + 1)
        coef[: len(p.coef)] = p.coef
        c[:, i] = coef[::-1]
    return PPoly(c, np.asarray(breaks, dtype=float))


def window(duration: float, ramp: float, t_start: float = 0.0) -> PPolySignal:
    """Plateau window: 0 → 1 over ``ramp`` s (quintic smoothstep, C²), 1, then 1 → 0.

    Zero before ``t_start`` and after ``t_start + duration``.
    """
    if duration <= 0:
        raise SpecError("window duration must be positive")
    r = min(float(ramp), duration / 2.0)
    s = _smoothstep5()
    if r <= 0:
        raise SpecError("ramp_s must be positive")
    breaks = [t_start, t_start + r]
    polys = [s(P([0, 1.0 / r]))]
    if duration - 2 * r > 1e-12:
        breaks.append(t_start + duration - r)
        polys.append(P([1.0]))
    breaks.append(t_start + duration)
    polys.append(1.0 - s(P([0, 1.0 / r])))
    return PPolySignal(_pieces_to_ppoly(breaks, polys), [(t_start, t_start + duration)])


@dataclass
class Profile:
    """A C² history built from holds and moves, in any unit (callers state it).

    >>> p = Profile(0.0).hold(2.0).move_to(90.0, rate=45.0, blend=0.1).hold(1.0)

    ``move_to(target, rate=r)`` moves at the constant rate ``r`` (unit/s) with smooth
    acceleration blends of ``blend`` s at both ends (velocity follows 3x²−2x³); it lasts
    |Δ|/r + blend (a move shorter than that is one S-curve of 2·blend s with a lower peak).  ``move_to(target, duration=T)`` fixes the duration instead (plateau rate
    Δ/(T − blend)).  Holds are flagged as not moving; moves as moving.
    """
    start: float = 0.0
    t_start: float = 0.0
    _breaks: list = field(default_factory=list)
    _polys: list = field(default_factory=list)
    _moving: list = field(default_factory=list)

    def __post_init__(self):
        self._value = float(self.start)
        self._t = float(self.t_start)
        self._breaks = [self._t]

    @property
    def end_value(self) -> float:
        return self._value

    @property
    def end_time(self) -> float:
        return self._t

    @property
    def duration(self) -> float:
        return self._t - self.t_start

    def _add(self, dur: float, poly: P, moving: bool):
        if dur <= 0:
            return
        if moving:
            self._moving.append((self._t, self._t + dur))
        self._t += dur
        self._breaks.append(self._t)
        self._polys.append(poly)
        self._value = float(poly(dur))

    def hold(self, duration: float) -> "Profile":
        if not duration >= 0:
            raise SpecError("hold duration must be >= 0")
        self._add(float(duration), P([self._value]), False)
        return self

    def move_to(self, target: float, rate: float | None = None, duration: float | None = None,
                blend: float = 0.1) -> "Profile":
        delta = float(target) - self._value
        if (rate is None) == (duration is None):
            raise SpecError("move_to needs exactly one of rate or duration")
        if not blend >= MIN_BLEND_S:
            # a zero blend would step the rate: infinite angular acceleration at the joint
            raise SpecError(f"blend must be >= {MIN_BLEND_S} s, got {blend!r}")
        if delta == 0.0:
            return self.hold(duration if duration is not None else 0.0)
        b = float(blend)
        if rate is not None:
            if not rate > 0:
                raise SpecError("move rate must be positive")
            t_lin = abs(delta) / rate
            if t_lin < b:       # too short for a constant-rate part: one S-curve, lower peak
                total = 2 * b
                v = delta / b
            else:
                total = t_lin + b
                v = np.sign(delta) * rate
        else:
            total = float(duration)
            if not total >= 2 * MIN_BLEND_S:
                raise SpecError(f"move duration must be >= {2 * MIN_BLEND_S} s, got {duration!r}")
            b = min(b, total / 2.0)
            v = delta / (total - b)
        x0 = self._value
        if b > 0:
            # ramp up: v·(x³/b² − x⁴/(2b³)); constant; ramp down mirrored
            up = P([x0, 0, 0, v / b ** 2, -v / (2 * b ** 3)])
            self._add(b, up, True)
        t_const = total - 2 * b
        if t_const > 1e-12:
            self._add(t_const, P([self._value, v]), True)
        if b > 0:
            down = P([self._value, v, 0, -v / b ** 2, v / (2 * b ** 3)])
            self._add(b, down, True)
        return self

    def build(self) -> PPolySignal:
        if not self._polys:   # an empty profile: a constant
            pp = _pieces_to_ppoly([self.t_start, self.t_start + 1e-9], [P([self._value])])
            return PPolySignal(pp, [])
        return PPolySignal(_pieces_to_ppoly(self._breaks, self._polys), self._moving)
