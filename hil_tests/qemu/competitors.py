"""Competitors' C/C++ measured on M4F and M0 exactly like our filters.

x-io Fusion (C99) and VQF (C++) are taken from their PyPI source distributions, downloaded at
benchmark time into ``~/.cache/kinefuse/competitors/`` (never committed)::

    python -m pip download --no-binary imufusion --no-deps -d <cache> imufusion==1.3.3

(``--no-binary :all:`` would also rebuild pip's build dependencies from source, which fails on
Debian 12; only the package itself has to be a source distribution.)

Each case runs ``WARMUP`` updates in the setup (past Fusion's 3 s start-up ramp and VQF's
initial filter settling) and then counts ``K`` updates on the following samples of a
deterministic synthetic motion (100 Hz, smooth rotations up to ~150 deg/s, gravity and an
Earth-like magnetic field rotated into the sensor frame, small noise).  Units follow each
library: Fusion deg/s, g, uT; VQF rad/s, m/s^2, uT.  Flags are identical to ours (``-O2``
counted, ``-Os`` and ``-O2`` sizes); VQF additionally gets ``-fno-exceptions -fno-rtti``
(all C++ builds) and ``-DNDEBUG`` (its ``assert`` would otherwise pull newlib's stdio into
the size).

Cases: ``fusion-ahrs-9d`` and ``fusion-ahrs-6d`` (x-io README settings: gain 0.5, gyroscope
range 2000 deg/s, acceleration and magnetic rejection 10 deg, rejection timeout 5 s, NWU);
``vqf-9d`` / ``vqf-6d`` (VQF defaults: double precision), ``vqf-9d-f32`` / ``vqf-6d-f32``
(``VQF_SINGLE_PRECISION``; its low-pass filter states stay double by design).
"""
from __future__ import annotations

import os
import subprocess
import sys
import tarfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Sequence

import numpy as np

from kinefuse.firmware.targets import BuildError, cache_dir
from kinefuse.hil_tests.qemu.batch import write_generated
from kinefuse.hil_tests.qemu.cost import CallCost, measure_call_cost
from kinefuse.host.errors import KinefuseError

PACKAGES = {"imufusion": "1.3.3", "vqf": "2.1.2"}
RATE_HZ = 100
WARMUP = 400           # updates before counting (4 s)
K = 1000               # counted updates
N_SAMPLES = WARMUP + K


def competitors_dir() -> Path:
    return cache_dir("competitors")


def fetch_sdist(package: str, version: str | None = None, *, quiet: bool = True) -> Path:
    """Download (once) and unpack the sdist of ``package``; returns the unpacked directory."""
    version = version or PACKAGES[package]
    d = competitors_dir()
    unpacked = d / f"{package}-{version}"
    if unpacked.is_dir() and (unpacked / ".kf-complete").is_file():
        return unpacked
    archive = d / f"{package}-{version}.tar.gz"
    if not archive.is_file():
        cmd = [sys.executable, "-m", "pip", "download", "--no-binary", package, "--no-deps",
               "--disable-pip-version-check", "-d", str(d), f"{package}=={version}"]
        proc = subprocess.run(cmd, capture_output=True, text=True)
        if proc.returncode != 0 or not archive.is_file():
            lines = (proc.stderr or proc.stdout).strip().splitlines()
            raise KinefuseError(f"could not download the {package} {version} sdist: "
                                f"{lines[-1] if lines else 'pip failed'}")
    with tarfile.open(archive) as tar:
        tar.extractall(d, filter="data")
    (unpacked / ".kf-complete").write_text("ok\n")
    return unpacked


# ---- synthetic motion --------------------------------------------------------------------

def motion(n: int = N_SAMPLES, rate_hz: float = RATE_HZ, seed: int = 7) -> dict[str, np.ndarray]:
    """Deterministic IMU samples of a smoothly rotating sensor (sensor frame, SI units).

    Returns ``gyr`` (rad/s), ``acc`` (m/s^2, specific force: +9.81 on z when level),
    ``mag`` (uT), each (n, 3) float32.  Earth frame East-North-Up; field 20 uT north,
    44 uT down.
    """
    from scipy.spatial.transform import Rotation

    sub = 10
    dt = 1.0 / (rate_hz * sub)
    t = np.arange(n * sub) * dt
    w = np.stack([1.6 * np.sin(2 * np.pi * 0.31 * t),
                  1.2 * np.sin(2 * np.pi * 0.53 * t + 1.0),
                  2.0 * np.sin(2 * np.pi * 0.17 * t + 2.0)], axis=1)        # rad/s, body frame
    rot = Rotation.identity()
    rots = []
    for i in range(n * sub):
        if i % sub == 0:
            rots.append(rot)
        rot = rot * Rotation.from_rotvec(w[i] * dt)                         # body-frame rate
    r = Rotation.concatenate(rots)
    g_up = np.array([0.0, 0.0, 9.81])
    m_earth = np.array([0.0, 20.0, -44.0])
    rng = np.random.default_rng(seed)
    gyr = w[::sub] + rng.normal(0.0, 0.005, (n, 3))
    acc = r.inv().apply(g_up) + rng.normal(0.0, 0.03, (n, 3))
    mag = r.inv().apply(m_earth) + rng.normal(0.0, 0.3, (n, 3))
    return {k: v.astype(np.float32) for k, v in (("gyr", gyr), ("acc", acc), ("mag", mag))}


TABLES: dict[str, Callable[[dict], np.ndarray]] = {
    "kf_motion_gyr_dps": lambda m: m["gyr"] * np.float32(180.0 / np.pi),
    "kf_motion_acc_g": lambda m: m["acc"] / np.float32(9.81),
    "kf_motion_gyr_rads": lambda m: m["gyr"],
    "kf_motion_acc_ms2": lambda m: m["acc"],
    "kf_motion_mag_ut": lambda m: m["mag"],
}


def motion_sources() -> tuple[Path, Path]:
    """Write ``kf_motion.c``/``.h`` (float and double tables) into the cache; returns (c, dir)."""
    m = motion()
    decl, body = [], []
    for name, fn in TABLES.items():
        a = np.asarray(fn(m), dtype=np.float32)
        rows_f = ",\n".join("{" + ", ".join(float(x).hex() + "f" for x in row) + "}" for row in a)
        rows_d = ",\n".join("{" + ", ".join(float(x).hex() for x in row) + "}" for row in a)
        decl.append(f"extern const float {name}[KF_MOTION_N][3];")
        decl.append(f"extern const double {name}_d[KF_MOTION_N][3];")
        body.append(f"const float {name}[KF_MOTION_N][3] = {{\n{rows_f}\n}};")
        body.append(f"const double {name}_d[KF_MOTION_N][3] = {{\n{rows_d}\n}};")
    header = ("/* Synthetic IMU motion for cost measurements (generated; see competitors.py). */\n"
              "#ifndef KF_MOTION_H\n#define KF_MOTION_H\n"
              f"#define KF_MOTION_N {N_SAMPLES}u\n#define KF_MOTION_RATE_HZ {RATE_HZ}\n"
              f"#define KF_WARMUP {WARMUP}u\n"
              "#ifdef __cplusplus\nextern \"C\" {\n#endif\n" + "\n".join(decl) +
              "\n#ifdef __cplusplus\n}\n#endif\n#endif\n")
    hpath = write_generated(header, "kf_motion.h")
    cpath = write_generated('#include "kf_motion.h"\n' + "\n".join(body) + "\n", "kf_motion.c")
    # the .c includes the header from its own directory: copy the header next to it
    sibling = cpath.parent / "kf_motion.h"
    if not sibling.is_file() or sibling.read_text() != header:
        tmp = sibling.with_name(f".kf_motion.h.{os.getpid()}")
        tmp.write_text(header)
        os.replace(tmp, sibling)
    return cpath, hpath.parent


# ---- cases --------------------------------------------------------------------------------

@dataclass
class Case:
    """One competitor update to measure."""

    name: str
    package: str
    language: str
    description: str
    sources: Callable[[Path], list[Path]]
    include_dirs: Callable[[Path], list[Path]]
    prelude: str
    setup: str
    call: str
    tables: Sequence[str]
    defines: dict = field(default_factory=dict)


_FUSION_PRELUDE = '#include <string.h>\n#include "Fusion.h"\n#include "kf_motion.h"\n'
_FUSION_SETUP = """
static FusionAhrs kf_ahrs;
FusionAhrsInitialise(&kf_ahrs);
const FusionAhrsSettings kf_settings = {
    .sampleRate = (float)KF_MOTION_RATE_HZ,
    .convention = FusionConventionNwu,
    .gain = 0.5f,
    .gyroscopeRange = 2000.0f,
    .accelerationRejection = 10.0f,
    .magneticRejection = 10.0f,
    .rejectionTimeout = 5.0f,
};
FusionAhrsSetSettings(&kf_ahrs, &kf_settings);
for (uint32_t w = 0u; w < KF_WARMUP; ++w) {
    %s
}
"""
_FUSION_9D = ("FusionAhrsUpdate(&kf_ahrs, *(const FusionVector *)kf_motion_gyr_dps[{i}], "
              "*(const FusionVector *)kf_motion_acc_g[{i}], *(const FusionVector *)kf_motion_mag_ut[{i}]);")
_FUSION_6D = ("FusionAhrsUpdateNoMagnetometer(&kf_ahrs, *(const FusionVector *)kf_motion_gyr_dps[{i}], "
              "*(const FusionVector *)kf_motion_acc_g[{i}]);")

_VQF_PRELUDE = '#include "vqf.hpp"\n#include "kf_motion.h"\n'
_VQF_SETUP = """
static VQF kf_vqf(1.0 / KF_MOTION_RATE_HZ, 1.0 / KF_MOTION_RATE_HZ, 1.0 / KF_MOTION_RATE_HZ);
for (uint32_t w = 0u; w < KF_WARMUP; ++w) {
    %s
}
"""


def _fusion_sources(root: Path) -> list[Path]:
    return sorted((root / "Fusion").glob("*.c"))


def _vqf_sources(root: Path) -> list[Path]:
    return [root / "vqf" / "cpp" / "vqf.cpp"]


def _vqf_call(nine: bool, suffix: str, i: str) -> str:
    args = [f"kf_motion_gyr_rads{suffix}[{i}]", f"kf_motion_acc_ms2{suffix}[{i}]"]
    if nine:
        args.append(f"kf_motion_mag_ut{suffix}[{i}]")
    return f"kf_vqf.update({', '.join(args)});"


def _fusion_case(name: str, template: str, desc: str, tables: Sequence[str]) -> Case:
    return Case(name, "imufusion", "c", desc, _fusion_sources, lambda r: [r / "Fusion"],
                _FUSION_PRELUDE, _FUSION_SETUP % template.format(i="w"),
                template.format(i="KF_WARMUP + kf_i"), tables)


def _vqf_case(name: str, nine: bool, single: bool, desc: str) -> Case:
    suffix = "" if single else "_d"
    tables = [f"kf_motion_gyr_rads{suffix}", f"kf_motion_acc_ms2{suffix}"] + \
        ([f"kf_motion_mag_ut{suffix}"] if nine else [])
    defines = {"NDEBUG": None}
    if single:
        defines["VQF_SINGLE_PRECISION"] = None
    return Case(name, "vqf", "c++", desc, _vqf_sources, lambda r: [r / "vqf" / "cpp"],
                _VQF_PRELUDE, _VQF_SETUP % _vqf_call(nine, suffix, "w"),
                _vqf_call(nine, suffix, "KF_WARMUP + kf_i"), tables, defines)


CASES: dict[str, Case] = {c.name: c for c in [
    _fusion_case("fusion-ahrs-9d", _FUSION_9D, "x-io Fusion FusionAhrsUpdate (gyro+acc+mag)",
                 ["kf_motion_gyr_dps", "kf_motion_acc_g", "kf_motion_mag_ut"]),
    _fusion_case("fusion-ahrs-6d", _FUSION_6D, "x-io Fusion FusionAhrsUpdateNoMagnetometer",
                 ["kf_motion_gyr_dps", "kf_motion_acc_g"]),
    _vqf_case("vqf-9d", True, False, "VQF::update(gyr, acc, mag), double (library default)"),
    _vqf_case("vqf-6d", False, False, "VQF::update(gyr, acc), double (library default)"),
    _vqf_case("vqf-9d-f32", True, True, "VQF::update(gyr, acc, mag), VQF_SINGLE_PRECISION"),
    _vqf_case("vqf-6d-f32", False, True, "VQF::update(gyr, acc), VQF_SINGLE_PRECISION"),
]}


@dataclass
class CaseResult:
    case: str
    target: str
    cost: CallCost | None
    error: str | None = None

    def as_dict(self) -> dict:
        d = {"case": self.case, "target": self.target, "error": self.error}
        if self.cost is not None:
            d.update(self.cost.as_dict())
        return d


def measure_case(name: str, target: str, *, size_opts: Sequence[str] = ("-Os", "-O2"),
                 opt: str = "-O2") -> CaseResult:
    """Fetch the competitor if needed, build and measure one case on one target.

    A build failure is returned as ``error`` (the compiler's first error line), not raised.
    """
    case = CASES[name]
    root = fetch_sdist(case.package)
    motion_c, motion_dir = motion_sources()
    keep = "\n".join(f"kf_keep_sink = (uintptr_t)&{t}[0][0];" for t in case.tables)
    prelude = case.prelude + "static volatile uintptr_t kf_keep_sink;\n"
    try:
        cost = measure_call_cost(
            [*case.sources(root), motion_c], case.setup, case.call, target, k=K,
            prelude=prelude, finish="kf_keep_sink = 0u;", baseline_code=keep,
            include_dirs=[*case.include_dirs(root), motion_dir], defines=case.defines, opt=opt,
            size_opts=size_opts, language=case.language)
    except BuildError as exc:
        return CaseResult(name, target, None, str(exc))
    return CaseResult(name, target, cost)


def measure_all(targets: Sequence[str] = ("m4f", "m0"), cases: Sequence[str] | None = None,
                progress: Callable[[str], None] | None = None) -> list[CaseResult]:
    """Every case on every target (about a minute when the sdists are cached)."""
    out = []
    for name in cases or list(CASES):
        for t in targets:
            if progress:
                progress(f"{name} on {t}")
            out.append(measure_case(name, t))
    return out


if __name__ == "__main__":  # pragma: no cover - manual use
    for r in measure_all(progress=lambda s: print("measuring", s, file=sys.stderr)):
        print(r.as_dict())
