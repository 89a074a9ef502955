"""The simulator's output for one sensor, and its conversions.

A :class:`Recording` holds, per emitted sample i (after drops and duplicates):

=============  ======  ===================================================================
t              (N,)    time stamp, s (device clock; what a filter sees)
dt             (N,)    s, from the emitted stamps: dt[0] = 1/rate, dt[i] = t[i] − t[i−1]
gyr            (N,3)   angular rate, rad/s, sensor frame: the mean over the interval the sample
                       closes (sensor.gyr.sampling; acc and mag are instantaneous)
acc            (N,3)   specific force, m/s², sensor frame (+g upward at rest)
mag            (N,3)   magnetic field, µT, sensor frame; held between magnetometer samples
                       (NaN when the sensor has no magnetometer)
mag_valid      (N,)    bool, True where mag holds a magnetometer sample not emitted before
q_true         (N,4)   true orientation (w,x,y,z), sensor → earth, ENU, at the sampling instant
movement       (N,)    bool, designed motion phase (rest/holds are False)
pos_true       (N,3)   true sensor position, m, ENU
t_true         (N,)    true sampling instant, s (differs from t with jitter/drift)
index          (N,)    nominal sample number (gaps = drops, repeats = duplicates)
truth          dict    more per-sample truth: gyr_true (the error-free sample), gyr_inst
                       (the body rate at t_true), acc_true (rigid body, no
                       disturbances), mag_true (earth field, no disturbances), mag_disturbed,
                       acc_disturbed (bool), and the scenario's joint angles in rad
meta           dict    scenario, sensor, seed, preset, rate_hz, mag_rate_hz, units, sensor model
=============  ======  ===================================================================
"""
from __future__ import annotations

import io
import json
from dataclasses import dataclass, field

import numpy as np

from kinefuse.host.errors import KinefuseError

_ARRAYS = ("t", "dt", "gyr", "acc", "mag", "mag_valid", "q_true", "movement", "pos_true", "t_true", "index")

# C layout of firmware/app/kf_hal.h's kf_raw_sample (field order, sizes, padding: 24 bytes)
RAW_DTYPE = np.dtype([("time_us", "<u4"), ("acc", "<i2", (3,)), ("gyr", "<i2", (3,)),
                      ("mag", "<i2", (3,)), ("mag_valid", "u1")], align=True)


@dataclass
class Recording:
    t: np.ndarray
    dt: np.ndarray
    gyr: np.ndarray
    acc: np.ndarray
    mag: np.ndarray
    mag_valid: np.ndarray
    q_true: np.ndarray
    movement: np.ndarray
    pos_true: np.ndarray
    t_true: np.ndarray
    index: np.ndarray
    truth: dict = field(default_factory=dict)
    meta: dict = field(default_factory=dict)

    def __len__(self) -> int:
        return len(self.t)

    @property
    def rate_hz(self) -> float:
        return float(self.meta["rate_hz"])

    def to_broad(self, movement: str = "design") -> dict:
        """The BROAD trial layout (``imu_gyr``, ``imu_acc``, ``imu_mag``, ``opt_quat``,
        ``opt_pos``, ``movement`` (N,1) uint8, ``sampling_rate`` (1,1)), so BROAD runners and
        the BROAD metric apply unchanged.  ``movement="all"`` marks every sample for scoring
        (static scenarios have no designed motion phase).  Extra keys: ``t``, ``mag_valid``."""
        if movement not in ("design", "all"):
            raise KinefuseError(f"movement must be 'design' or 'all', got {movement!r}")
        mv = self.movement if movement == "design" else np.ones(len(self), dtype=bool)
        return {"imu_gyr": self.gyr.copy(), "imu_acc": self.acc.copy(), "imu_mag": self.mag.copy(),
                "opt_quat": self.q_true.copy(), "opt_pos": self.pos_true.copy(),
                "movement": mv.astype(np.uint8)[:, None],
                "sampling_rate": np.array([[self.rate_hz]]),
                "t": self.t.copy(), "mag_valid": self.mag_valid.astype(np.uint8)}

    def to_raw(self, lsb: dict | None = None, t0_us: int = 0) -> np.ndarray:
        """Samples as firmware ``kf_raw_sample`` records (structured array ``RAW_DTYPE``).

        Values become int16 counts with the preset's LSBs (``meta['lsb']``, SI units per
        count) unless ``lsb`` overrides them ({"acc": m/s², "gyr": rad/s, "mag": µT});
        time_us = (t0_us + round(t·1e6)) mod 2³² (wraps like the device clock).  A value that
        does not fit int16 is an error, never wrapped.
        """
        lsbs = dict(self.meta.get("lsb", {}))
        lsbs.update(lsb or {})
        out = np.zeros(len(self), dtype=RAW_DTYPE)
        out["time_us"] = ((int(t0_us) + np.round(self.t * 1e6).astype(np.int64)) % (1 << 32)).astype(np.uint32)
        for ch in ("acc", "gyr", "mag"):
            x = getattr(self, ch)
            if ch == "mag" and np.all(np.isnan(x)):
                continue
            q = lsbs.get(ch) or 0.0
            if not q > 0:
                raise KinefuseError(f"no LSB for {ch}: the sensor model does not quantise; set one "
                                    f"(scenario sensor.{ch}.lsb_*, or to_raw(lsb={{'{ch}': ...}}))")
            c = np.round(x / q)
            if np.any(c > 32767) or np.any(c < -32768) or np.any(np.isnan(c)):
                raise KinefuseError(f"{ch} does not fit int16 counts with LSB {q:g}")
            out[ch] = c.astype(np.int16)
        out["mag_valid"] = self.mag_valid.astype(np.uint8)
        return out

    # ---- files ---------------------------------------------------------------------
    def save(self, path: str) -> None:
        """Write ``.npz`` (everything, reloadable) or ``.mat`` (BROAD layout + t, mag_valid)."""
        p = str(path)
        if p.endswith(".mat"):
            import scipy.io
            d = self.to_broad()
            d["info"] = json.dumps(self.meta)
            buf = io.BytesIO()
            scipy.io.savemat(buf, d, do_compression=True)
            data = bytearray(buf.getvalue())
            # the 116-byte descriptive text held the time of writing: a fixed text keeps
            # "same seed, same bytes" (the text is free-form; it starts as the format asks)
            data[:116] = b"MATLAB 5.0 MAT-file, written by kinefuse sim".ljust(116, b"\0")
            with open(p, "wb") as f:
                f.write(data)
        elif p.endswith(".npz"):
            arrays = {k: getattr(self, k) for k in _ARRAYS}
            arrays.update({f"truth__{k}": v for k, v in self.truth.items()})
            np.savez_compressed(p, meta=np.array(json.dumps(self.meta)), **arrays)
        else:
            raise KinefuseError(f"unknown output format for {p!r}: use .npz or .mat")

    @classmethod
    def load(cls, path: str) -> "Recording":
        """Read a recording written by :meth:`save` as ``.npz``."""
        try:
            with np.load(str(path), allow_pickle=False) as z:
                kw = {k: z[k] for k in _ARRAYS}
                truth = {k[len("truth__"):]: z[k] for k in z.files if k.startswith("truth__")}
                meta = json.loads(str(z["meta"]))
        except (OSError, KeyError, ValueError) as exc:
            raise KinefuseError(f"cannot read recording {path}: {exc}") from None
        return cls(truth=truth, meta=meta, **kw)
