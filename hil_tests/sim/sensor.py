"""Sensor error model, one instance per channel (gyroscope, accelerometer, magnetometer).

For true input x (sensor frame, SI: rad/s, m/s², µT) at sample instants t:

    mag only:  x ← soft_iron · x + hard_iron
    y = misalignment · diag(scale) · x + bias + b_rw(t) + n,     n ~ N(0, σ²)
    y ← clip(y, −range, +range);   y ← lsb · round(y / lsb), counts kept inside ±range and
                                    inside the signed ``bits``-bit word (16: −32768…32767)

* ``noise_std`` σ_tot is the per-axis standard deviation of the output at rest as a static
  capture measures it, i.e. of the *quantised* counts when ``lsb`` > 0 (the seed tables are
  such measurements).  The white noise added before quantisation is therefore
  σ = √(σ_tot² − lsb²/12) (uniform rounding error of variance lsb²/12 on top of it gives σ_tot
  back); σ_tot = 0 means no white noise (quantisation only), and 0 < σ_tot < lsb/√12 (a total
  below the rounding noise alone) is refused.  σ applies at ``noise_ref_rate_hz``; at another
  output rate f the white part becomes σ·√(f / f_ref) (constant noise density, i.e. the
  sensor's bandwidth follows its output rate; the rounding noise does not scale).
  ``noise_ref_rate_hz = None`` keeps σ fixed.
* With ``lsb`` > 0 the counts' full scale lsb·(2^(bits−1) − 1) must reach ``range`` (to within
  0.5 %, the rounding of data-sheet sensitivities: 16.4 LSB/(°/s) reaches 1998 of ±2000 °/s);
  a smaller LSB, which would clip the signal at a full scale below the range, is refused.
* b_rw is a bias random walk with σ_rw (unit/√s): increments N(0, σ_rw²·Δt).
* All randomness comes from the numpy Generator handed in: same seed, same arrays.

Dict form (scenario files) names units in the keys:
  gyr: noise_dps, bias_dps, bias_rw_dps_per_rt_s, range_dps, lsb_dps
  acc: noise_mg, bias_mg, bias_rw_mg_per_rt_s, range_g, lsb_mg
  mag: noise_uT, bias_uT, bias_rw_uT_per_rt_s, range_uT, lsb_uT, hard_iron_uT, soft_iron, present
  gyr also: sampling ("mean" | "rotation" | "instant": what a sample is, see GYR_SAMPLING)
  all: scale (per-axis factor, 1 = exact), misalignment (3×3), noise_ref_rate_hz, bits
A scalar is broadcast to the three axes.  1 g (unit) = 9.80665 m/s² (standard gravity).
"""
from __future__ import annotations

import copy
from dataclasses import dataclass, field

import numpy as np

from .segments import SpecError, take

G_N = 9.80665  # m/s² per g, the unit (independent of the simulated local gravity)
# the counts' full scale may fall this much short of the range: data-sheet sensitivities are
# rounded (±2000 °/s at 16.4 LSB/(°/s) reaches 1998 °/s; ±500 °/s at 65.6: 499.5 °/s)
FULL_SCALE_TOLERANCE = 0.005
_SHOWN = {"gyr": "°/s", "acc": "g", "mag": "µT"}   # the unit of range_dps, range_g, range_uT
#: what a gyroscope sample reports (``gyr.sampling``; the accelerometer and magnetometer are
#: always instantaneous): "mean" the mean body rate over the interval that ends at the sample,
#: ∫ω dt / Δt over (t[k−1], t[k]] (an integrating MEMS gyroscope; the default); "rotation" the
#: rotation vector of q(t[k−1])⁻¹ ⊗ q(t[k]) / Δt (equal to "mean" about a fixed axis; in
#: multi-axis motion it differs by the coning term, and a plain strapdown step ω_k·Δt_k then
#: reproduces q exactly); "instant" the rate at t[k] (before 2026-12-04: the filters, which
#: integrate it over the step before, ran about ω·Δt/2 ahead)
GYR_SAMPLING = ("mean", "rotation", "instant")

# key suffix → (internal field, factor from the dict unit to SI)
_UNITS = {
    "gyr": {"dps": np.pi / 180.0, "range": ("range_dps", np.pi / 180.0)},
    "acc": {"mg": G_N / 1000.0, "range": ("range_g", G_N)},
    "mag": {"uT": 1.0, "range": ("range_uT", 1.0)},
}


def _v3(x, where):
    v = np.broadcast_to(np.asarray(x, dtype=float), (3,)).copy()
    if np.any(np.isnan(v)):
        raise SpecError(f"{where}: NaN not allowed")
    return v


@dataclass
class ChannelModel:
    """Error model of one 3-axis channel, SI units of that channel (rad/s, m/s², µT)."""
    kind: str                                   # "gyr", "acc" or "mag"
    noise_std: np.ndarray = field(default_factory=lambda: np.zeros(3))
    noise_ref_rate_hz: float | None = None
    bias: np.ndarray = field(default_factory=lambda: np.zeros(3))
    bias_rw: np.ndarray = field(default_factory=lambda: np.zeros(3))
    scale: np.ndarray = field(default_factory=lambda: np.ones(3))
    misalignment: np.ndarray = field(default_factory=lambda: np.eye(3))
    range: np.ndarray = field(default_factory=lambda: np.full(3, np.inf))
    lsb: float = 0.0
    bits: int = 16                              # signed output word when lsb > 0
    hard_iron: np.ndarray = field(default_factory=lambda: np.zeros(3))
    soft_iron: np.ndarray = field(default_factory=lambda: np.eye(3))
    present: bool = True
    sampling: str = "mean"                      # gyr only: what a sample is, see GYR_SAMPLING

    def quantisation_std(self) -> float:
        """Std of the rounding error (SI), lsb/√12; 0 without quantisation."""
        return self.lsb / np.sqrt(12.0) if self.lsb > 0 else 0.0

    def white_std(self) -> np.ndarray:
        """Per-axis std (SI, at ``noise_ref_rate_hz``) of the white noise added before
        quantisation: √(noise_std² − lsb²/12), so that the quantised total is ``noise_std``."""
        q = self.quantisation_std()
        below = (self.noise_std > 0) & (self.noise_std < q)
        if self.present and np.any(below):
            raise SpecError(self._noise_below_text(q))
        return np.sqrt(np.maximum(self.noise_std ** 2 - q ** 2, 0.0))

    def noise_at(self, rate_hz: float) -> np.ndarray:
        """Per-axis white-noise std (SI) at output rate ``rate_hz`` (before quantisation)."""
        white = self.white_std()
        if self.noise_ref_rate_hz is None:
            return white
        return white * np.sqrt(rate_hz / self.noise_ref_rate_hz)

    # ---- checks of a channel's settings (one-line SpecErrors naming the values) -------
    def _names(self):
        u = _UNITS[self.kind]
        unit = next(k for k in u if k != "range")
        rkey, rf = u["range"]
        return unit, u[unit], rkey, rf, _SHOWN[self.kind]

    def _noise_below_text(self, q: float, where: str = "") -> str:
        unit, f, _, _, _ = self._names()
        i = int(np.argmax((self.noise_std > 0) & (self.noise_std < q)))
        return (f"{where + ': ' if where else ''}noise_{unit} {self.noise_std[i] / f:.4g} ({'xyz'[i]} axis) is "
                f"below the quantisation noise of lsb_{unit} {self.lsb / f:.4g} (lsb/√12 = {q / f:.4g}): "
                f"noise_{unit} is the total noise of the quantised output at rest, so it "
                f"cannot be smaller; give 0 (quantisation only) or at least {q / f:.4g}")

    def check(self, where: str) -> None:
        """Refuse settings the model cannot honour: counts whose full scale falls short of the
        range (a tiny LSB), a total noise below the LSB's rounding noise."""
        if not self.present or not self.lsb > 0:
            return
        unit, f, rkey, rf, shown = self._names()
        counts = 2 ** (self.bits - 1) - 1
        top = self.lsb * counts
        short = top < self.range * (1.0 - FULL_SCALE_TOLERANCE)
        if np.any(short):
            r = float(np.max(self.range))
            raise SpecError(
                f"{where}: lsb_{unit} {self.lsb / f:.4g} × {counts} counts ({self.bits}-bit words) is a "
                f"full scale of ±{top / rf:.4g} {shown}, below {rkey} {r / rf:.4g} {shown}: the counts cannot "
                f"reach the range (the output would clip at ±{top / rf:.4g}); give lsb_{unit} >= "
                f"{r * (1.0 - FULL_SCALE_TOLERANCE) / counts / f:.4g}, {rkey} <= {top / rf:.4g} or more bits")
        q = self.quantisation_std()
        if np.any((self.noise_std > 0) & (self.noise_std < q)):
            raise SpecError(self._noise_below_text(q, where))

    def apply(self, x: np.ndarray, t: np.ndarray, rate_hz: float, rng: np.random.Generator) -> np.ndarray:
        """Measured values for true input x (N,3) at instants t (N,), SI units."""
        x = np.asarray(x, dtype=float)
        n = len(x)
        # draw every random stream unconditionally, in a fixed order, so that switching one
        # error term on or off does not change the others' realisation
        white = rng.standard_normal((n, 3))
        steps = rng.standard_normal((n, 3))
        if not self.present:
            return np.full((n, 3), np.nan)
        if self.kind == "mag":
            x = x @ self.soft_iron.T + self.hard_iron
        y = (x * self.scale) @ self.misalignment.T + self.bias
        if np.any(self.bias_rw):
            dt = np.diff(np.asarray(t, dtype=float), prepend=float(t[0]) if n else 0.0)
            y = y + np.cumsum(steps * np.sqrt(np.maximum(dt, 0.0))[:, None], axis=0) * self.bias_rw
        y = y + white * self.noise_at(rate_hz)
        y = np.clip(y, -self.range, self.range)
        if self.lsb > 0:
            # the count range is the smaller of the full scale and the signed output word
            word = float(2 ** (self.bits - 1))
            top = np.minimum(np.floor(self.range / self.lsb), word - 1)
            bottom = np.minimum(np.floor(self.range / self.lsb), word)
            y = np.clip(np.round(y / self.lsb), -bottom, top) * self.lsb
        return y

    # ---- dict form -----------------------------------------------------------------
    def updated(self, d: dict, where: str) -> "ChannelModel":
        """A copy with the dict-form overrides applied (units named in the keys)."""
        u = _UNITS[self.kind]
        unit = next(k for k in u if k != "range")
        f = u[unit]
        rkey, rf = u["range"]
        keys = {f"noise_{unit}": ("noise_std", f), f"bias_{unit}": ("bias", f),
                f"bias_rw_{unit}_per_rt_s": ("bias_rw", f), rkey: ("range", rf),
                f"lsb_{unit}": ("lsb", f), "scale": ("scale", 1.0)}
        extra = ["misalignment", "noise_ref_rate_hz", "bits"]
        if self.kind == "gyr":
            extra.append("sampling")
        if self.kind == "mag":
            keys["hard_iron_uT"] = ("hard_iron", 1.0)
            extra += ["soft_iron", "present"]
        take(d, where, [], list(keys) + extra)
        c = copy.deepcopy(self)
        for k, v in d.items():
            w = f"{where}.{k}"
            if k in keys:
                name, fac = keys[k]
                if name == "lsb":
                    c.lsb = float(v) * fac
                    if not (np.isfinite(c.lsb) and c.lsb >= 0):     # (NaN: no quantisation)
                        raise SpecError(f"{w}: must be a finite number >= 0")
                else:
                    val = _v3(v, w) * fac
                    if name in ("range",) and np.any(val <= 0):
                        raise SpecError(f"{w}: must be > 0")
                    # (an infinite noise, bias or scale gave infinite samples; a negative
                    # standard deviation or random-walk density was taken as its magnitude)
                    if name != "range" and not np.all(np.isfinite(val)):
                        raise SpecError(f"{w}: must be finite")
                    if name in ("noise_std", "bias_rw") and np.any(val < 0):
                        raise SpecError(f"{w}: must be >= 0 (a standard deviation)")
                    setattr(c, name, val)
            elif k in ("misalignment", "soft_iron"):
                m = np.asarray(v, dtype=float)
                if m.shape != (3, 3) or not np.all(np.isfinite(m)):
                    raise SpecError(f"{w}: expected a finite 3×3 matrix")
                setattr(c, k, m)
            elif k == "bits":
                if isinstance(v, bool) or not float(v).is_integer():   # (12.5 ran as 12)
                    raise SpecError(f"{w}: must be a whole number of bits, got {v!r}")
                c.bits = int(v)
                if not 2 <= c.bits <= 32:
                    raise SpecError(f"{w}: must be in 2..32")
            elif k == "noise_ref_rate_hz":
                c.noise_ref_rate_hz = None if v is None else float(v)
                # (0 was a ZeroDivisionError, a negative or NaN rate NaN samples)
                if c.noise_ref_rate_hz is not None and not (np.isfinite(c.noise_ref_rate_hz)
                                                            and c.noise_ref_rate_hz > 0):
                    raise SpecError(f"{w}: must be a rate > 0 Hz, or null (noise fixed)")
            elif k == "sampling":
                if not isinstance(v, str) or v not in GYR_SAMPLING:
                    raise SpecError(f"{w}: expected one of {', '.join(GYR_SAMPLING)}, got {v!r}")
                c.sampling = v
            elif k == "present":
                if not isinstance(v, (bool, np.bool_)):    # (bool("no") is True)
                    raise SpecError(f"{w}: expected true or false")
                c.present = bool(v)
        c.check(where)
        return c

    def to_dict(self) -> dict:
        """Dict form (units named in the keys); inverse of ``updated`` on a blank channel."""
        u = _UNITS[self.kind]
        unit = next(k for k in u if k != "range")
        f = u[unit]
        rkey, rf = u["range"]

        def lst(a, fac):
            return [float(x) / fac if np.isfinite(x) else None for x in np.asarray(a)]
        d = {f"noise_{unit}": lst(self.noise_std, f), "noise_ref_rate_hz": self.noise_ref_rate_hz,
             f"bias_{unit}": lst(self.bias, f), f"bias_rw_{unit}_per_rt_s": lst(self.bias_rw, f),
             "scale": lst(self.scale, 1.0), "misalignment": self.misalignment.tolist(),
             rkey: lst(self.range, rf), f"lsb_{unit}": self.lsb / f, "bits": self.bits}
        if self.kind == "gyr":
            d["sampling"] = self.sampling
        if self.kind == "mag":
            d.update(hard_iron_uT=lst(self.hard_iron, 1.0), soft_iron=self.soft_iron.tolist(),
                     present=self.present)
        return d


@dataclass
class SensorModel:
    """A complete IMU: three channels plus its output rates (Hz)."""
    name: str
    gyr: ChannelModel
    acc: ChannelModel
    mag: ChannelModel
    rate_hz: float = 100.0          # accelerometer and gyroscope
    mag_rate_hz: float | None = None  # magnetometer (held between its samples); None = rate_hz
    source: str = ""

    def updated(self, d: dict | None, where: str = "sensor") -> "SensorModel":
        d = dict(d or {})
        take(d, where, [], ["preset", "gyr", "acc", "mag", "rate_hz", "mag_rate_hz"])
        c = copy.deepcopy(self)
        for ch in ("gyr", "acc", "mag"):
            if ch in d:
                setattr(c, ch, getattr(c, ch).updated(d[ch], f"{where}.{ch}"))
        for k in ("rate_hz", "mag_rate_hz"):
            if k in d and d[k] is not None:
                try:
                    v = float(d[k])
                except (TypeError, ValueError):
                    raise SpecError(f"{where}.{k}: expected a number") from None
                if not (v > 0 and np.isfinite(v)):
                    raise SpecError(f"{where}.{k}: must be > 0")
                setattr(c, k, v)
        return c

    @property
    def mag_rate(self) -> float:
        return self.rate_hz if self.mag_rate_hz is None else self.mag_rate_hz

    def to_dict(self) -> dict:
        return {"preset": self.name, "rate_hz": self.rate_hz, "mag_rate_hz": self.mag_rate_hz,
                "gyr": self.gyr.to_dict(), "acc": self.acc.to_dict(), "mag": self.mag.to_dict()}
