"""Sensor presets: noise levels measured in the seed documents, ranges from their data sheets.

Noise values are per-axis standard deviations (x, y, z) of a static recording, at the rate the
source recorded them (``noise_ref_rate_hz``).  Those recordings were of the sensors' quantised
output, so the simulated quantised output has these std's: the white noise added before
rounding is √(σ² − LSB²/12) (Xsens DOT gyro z: 0.0303 °/s, which with 1/16.4 °/s counts gives
the table's 0.035 °/s; adding 0.035 °/s and then rounding gave 0.039 °/s).  The white part
scales as √(rate / ref) at other rates (see :mod:`.sensor`).  Biases, scale errors and
misalignment are zero in every preset: a scenario adds the ones it wants.

=============  =========================  ==========================  =========================
preset         accelerometer              gyroscope                   magnetometer
=============  =========================  ==========================  =========================
xsens_dot      0.74 0.755 1.18 mg @60 Hz  0.04 0.04 0.035 °/s @60 Hz  0.07 0.08 0.085 µT @60 Hz
               ±16 g, 1/2048 g LSB        ±2000 °/s, 1/16.4 °/s LSB   ±800 µT, 0.025 µT LSB
matrix         2.695 2.95 2.70 mg @100Hz  0.135 0.08 0.07 °/s @100Hz  none (NaN, mag_valid 0)
               ±16 g, 1/2048 g LSB        ±2000 °/s, 1/16.4 °/s LSB*
metamotionr    1.35 1.35 1.55 mg @100 Hz  0.07 0.05 0.045 °/s @100Hz  0.56 0.485 0.42 µT @20 Hz
               ±4 g, 1/8192 g LSB         ±500 °/s, 1/65.6 °/s LSB    ±1300/1300/2500 µT, 0.3 µT
ideal          0                          0                           0  (±16 g, ±2000 °/s,
                                                                         ±4900 µT, no LSB)
=============  =========================  ==========================  =========================

Sources
* xsens_dot: seed 002 (calibration thesis) Table 5.1, mean of devices #1 and #2, 1-min static
  captures at 60 Hz; ranges/resolutions from its Tables 4.1–4.3 (±16 g at 2048 LSB/g, ±2000 °/s
  at 16.4 LSB/(°/s) — the table's "LSB/g" unit is an erratum, ±8 G with 0.25 mG resolution).
  Cross-check: the data-sheet densities of Table 4.1/4.2 (120 µg/√Hz, 0.007 °/s/√Hz) over a
  30 Hz bandwidth give 0.66 mg and 0.038 °/s, close to the measured values.  Rate 60 Hz.
* matrix: seed 002 Table 5.1, mean of MATRIX #1 and #2 at 100 Hz, except the gyroscope y axis:
  device #1 reads 0.72 °/s there (9× its twin and its own other axes), treated as an outlier,
  so 0.08 °/s (#2) is used.  Table 4.4: ±16 g, 16 bit (ICM-40607).  The seed gives no gyro
  range; ±2000 °/s at 16.4 LSB/(°/s) is the ICM-40607 maximum (*assumed).  No magnetometer.
* metamotionr: seed 001 (ChakaMo knee thesis) Table 7.2, mean of units DA and C8 (static test
  at 0°); configuration of its §7.2: acc 100 Hz ±4 g, gyro 100 Hz ±500 °/s, magnetometer
  20 Hz (so its noise is referenced to 20 Hz).  LSBs: 16-bit BMI160 at those ranges; BMM150
  range ±1300 µT (x, y), ±2500 µT (z) and 0.3 µT resolution from the Bosch data sheet.
* ideal: no noise or quantisation; the default full scales (±2000 °/s, ±16 g, ±4900 µT).
"""
from __future__ import annotations

import copy

import numpy as np

from .sensor import G_N, ChannelModel, SensorModel

DPS = np.pi / 180.0
MG = G_N / 1000.0

DEFAULT_RANGES = {"gyr": 2000.0 * DPS, "acc": 16.0 * G_N, "mag": 4900.0}


def _ch(kind, noise, ref, rng, lsb, present=True):
    return ChannelModel(kind=kind, noise_std=np.asarray(noise, dtype=float), noise_ref_rate_hz=ref,
                        range=np.broadcast_to(np.asarray(rng, dtype=float), (3,)).copy(), lsb=float(lsb),
                        present=present)


_PRESETS = {
    "xsens_dot": SensorModel(
        name="xsens_dot",
        acc=_ch("acc", np.array([0.74, 0.755, 1.18]) * MG, 60.0, 16 * G_N, G_N / 2048),
        gyr=_ch("gyr", np.array([0.04, 0.04, 0.035]) * DPS, 60.0, 2000 * DPS, DPS / 16.4),
        mag=_ch("mag", [0.07, 0.08, 0.085], 60.0, 800.0, 0.025),
        rate_hz=60.0, mag_rate_hz=None,
        source="seed 002 Table 5.1 (noise), Tables 4.1-4.3 (ranges)"),
    "matrix": SensorModel(
        name="matrix",
        acc=_ch("acc", np.array([2.695, 2.95, 2.70]) * MG, 100.0, 16 * G_N, G_N / 2048),
        gyr=_ch("gyr", np.array([0.135, 0.08, 0.07]) * DPS, 100.0, 2000 * DPS, DPS / 16.4),
        mag=_ch("mag", [0.0, 0.0, 0.0], None, 4900.0, 0.0, present=False),
        rate_hz=100.0, mag_rate_hz=None,
        source="seed 002 Table 5.1 (noise, gyro y outlier of unit #1 excluded), Table 4.4"),
    "metamotionr": SensorModel(
        name="metamotionr",
        acc=_ch("acc", np.array([1.35, 1.35, 1.55]) * MG, 100.0, 4 * G_N, G_N / 8192),
        gyr=_ch("gyr", np.array([0.07, 0.05, 0.045]) * DPS, 100.0, 500 * DPS, DPS / 65.6),
        mag=_ch("mag", [0.56, 0.485, 0.42], 20.0, [1300.0, 1300.0, 2500.0], 0.3),
        rate_hz=100.0, mag_rate_hz=20.0,
        source="seed 001 Table 7.2 (noise), section 7.2 (rates, ranges); BMM150 data sheet"),
    "ideal": SensorModel(
        name="ideal",
        acc=_ch("acc", np.zeros(3), None, DEFAULT_RANGES["acc"], 0.0),
        gyr=_ch("gyr", np.zeros(3), None, DEFAULT_RANGES["gyr"], 0.0),
        mag=_ch("mag", np.zeros(3), None, DEFAULT_RANGES["mag"], 0.0),
        rate_hz=100.0, mag_rate_hz=None, source="noise-free"),
}

PRESET_NAMES = tuple(_PRESETS)


def preset(name: str) -> SensorModel:
    """A fresh copy of a named preset (``xsens_dot``, ``matrix``, ``metamotionr``, ``ideal``)."""
    from .segments import SpecError
    try:
        return copy.deepcopy(_PRESETS[name])
    except KeyError:
        raise SpecError(f"unknown sensor preset {name!r}; known: {', '.join(_PRESETS)}") from None
