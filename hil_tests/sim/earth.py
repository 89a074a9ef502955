"""Earth model: gravity and the geomagnetic field in the East-North-Up frame.

Specific force measured by an accelerometer: f = Rᵀ (a_lin + g·e_z), so a unit at rest reads
+g along its upward axis.  Magnetic field: intensity B (µT) with dip (inclination, positive
downward, degrees) and declination (degrees east of true north; 0 puts magnetic north on +y):

    m_ENU = B · (cos(dip)·sin(decl), cos(dip)·cos(decl), −sin(dip))

Defaults: g = 9.81 m/s² (the seeds mix 9.8066, 9.80665 and 9.81; configurable), B = 49 µT,
dip = 64° (central Europe).  Seed 001's Montevideo reference is 22.6 µT; BROAD's lab field
reads ≈ 43 µT.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from .segments import SpecError, take


@dataclass(frozen=True)
class Earth:
    g: float = 9.81                 # m/s²
    field_uT: float = 49.0          # µT
    dip_deg: float = 64.0           # degrees, positive = field points down
    declination_deg: float = 0.0    # degrees east

    @property
    def gravity_up(self) -> np.ndarray:
        """The reaction to gravity as an accelerometer senses it at rest, ENU (m/s²)."""
        return np.array([0.0, 0.0, self.g])

    @property
    def field(self) -> np.ndarray:
        """Geomagnetic field vector, ENU (µT)."""
        dip, dec = np.radians(self.dip_deg), np.radians(self.declination_deg)
        return self.field_uT * np.array([np.cos(dip) * np.sin(dec), np.cos(dip) * np.cos(dec), -np.sin(dip)])

    @classmethod
    def from_dict(cls, d: dict | None) -> "Earth":
        if d is not None and not isinstance(d, dict):   # ([] ran the default earth)
            raise SpecError(f"earth: expected an object, got {type(d).__name__}")
        d = dict(d or {})
        take(d, "earth", [], ["g", "field_uT", "dip_deg", "declination_deg"])
        try:
            e = cls(**{k: float(v) for k, v in d.items()})
        except (TypeError, ValueError):
            raise SpecError(f"earth: values must be numbers, got {d!r}") from None
        bad = [k for k, v in asdict(e).items() if not np.isfinite(v)]
        if bad:                 # (a NaN dip or an infinite field: NaN magnetometer samples)
            raise SpecError(f"earth.{bad[0]}: must be finite")
        if not (e.g > 0 and e.field_uT >= 0):
            raise SpecError("earth: g must be > 0 and field_uT >= 0")
        return e

    def to_dict(self) -> dict:
        return asdict(self)
