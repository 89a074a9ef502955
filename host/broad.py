"""Access to BROAD orientation-benchmark trials (full ``.mat`` files and the bundled excerpt).

BROAD: D. Laidig, M. Caruso, A. Cereatti, T. Seel, "BROAD - A Benchmark for Robust Inertial
Orientation Estimation", Data 6(7):72, 2021, doi:10.3390/data6070072, CC BY 4.0.

Units and frames of a :class:`Trial` (identical to the BROAD files):

* ``gyr`` rad/s, ``acc`` m/s² (reads +g upward at rest), ``mag`` µT, all in the sensor frame;
* ``quat_ref`` optical reference (w, x, y, z) rotating sensor coordinates into the earth frame,
  earth frame East-North-Up aligned with magnetic north; NaN rows where markers were lost;
* ``movement`` True in the motion phases, the only samples the BROAD metric scores;
* ``t`` seconds from the first sample, derived from the constant sampling rate; a simulator
  ``.mat`` (``kinefuse sim run --out x.mat``) with timing effects keeps its own ``t`` and gives
  the filters its per-sample ``steps`` (and ``mag_valid``, its slower magnetometer's new readings).
"""
from __future__ import annotations

import dataclasses
import functools
import json
import os
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError

#: The bundled excerpt (a few cut trials, see data/broad_excerpt/README.md).
EXCERPT_DIR = Path(__file__).resolve().parent / "data" / "broad_excerpt"
#: Metadata of all 39 BROAD trials (groups, descriptions), copied from the dataset.
BUNDLED_TRIALS_JSON = EXCERPT_DIR / "trials.json"
TRIAL_SUFFIXES = (".mat", ".npz")

#: Groups reported by the accuracy benchmark, in BROAD's order, with readable titles.
GROUP_TITLES = {
    "rotation": "undisturbed rotation",
    "translation": "undisturbed translation",
    "combined": "undisturbed combined",
    "tapping": "tapping",
    "vibration": "vibration",
    "stationary_magnet": "stationary magnet",
    "attached_magnet": "attached magnet",
    "office_environment": "office environment",
    "mixed": "mixed",
}

_MAT_KEYS = ("imu_gyr", "imu_acc", "imu_mag", "opt_quat", "movement", "sampling_rate")
_NPZ_KEYS = ("gyr", "acc", "mag", "quat_ref", "movement", "rate_hz")


@dataclasses.dataclass(eq=False)
class Trial:
    """One recording: IMU samples, optical reference and scoring mask (units in module doc)."""

    name: str
    rate_hz: float
    t: np.ndarray = dataclasses.field(repr=False)          # (N,) s
    gyr: np.ndarray = dataclasses.field(repr=False)        # (N,3) rad/s, sensor frame
    acc: np.ndarray = dataclasses.field(repr=False)        # (N,3) m/s², sensor frame
    mag: np.ndarray = dataclasses.field(repr=False)        # (N,3) µT, sensor frame
    quat_ref: np.ndarray = dataclasses.field(repr=False)   # (N,4) w,x,y,z sensor->ENU, NaN = lost
    movement: np.ndarray = dataclasses.field(repr=False)   # (N,) bool, scored samples
    groups: tuple[str, ...] = ()
    source: Path | None = None
    description: str = ""
    #: (N,) bool, True on samples carrying a new magnetometer reading (a simulator .mat's
    #: ``mag_valid``: the magnetometer may be slower, the others repeat the last value);
    #: None = every sample (BROAD)
    mag_valid: np.ndarray | None = dataclasses.field(default=None, repr=False)
    #: (N,) s, the step to each sample from the one before (the first: the median step) when the
    #: file has sample times of its own (a simulator .mat's ``t``: jitter, drops, duplicates,
    #: gaps); None = the constant rate (BROAD).  ``t`` is then the file's times.
    steps: np.ndarray | None = dataclasses.field(default=None, repr=False)

    @property
    def n(self) -> int:
        """Number of samples."""
        return int(self.gyr.shape[0])

    @property
    def dt(self) -> float:
        """Sample period in s (BROAD has one constant rate per trial)."""
        return 1.0 / self.rate_hz

    @property
    def duration_s(self) -> float:
        return self.n / self.rate_hz

    def group(self) -> str | None:
        """The trial's benchmark group (rotation, translation, ..., attached_magnet) or None."""
        for g in GROUP_TITLES:
            if g in self.groups:
                return g
        return None

    def window(self, start: int, stop: int) -> "Trial":
        """Samples ``start:stop`` as a new trial; time restarts at 0 s."""
        if not 0 <= start < stop <= self.n:
            raise KinefuseError(f"{self.name}: sample window {start}:{stop} outside 0:{self.n}")
        sl = slice(start, stop)
        t = np.arange(stop - start) / self.rate_hz if self.steps is None else self.t[sl] - self.t[start]
        return dataclasses.replace(
            self, t=t, steps=None if self.steps is None else self.steps[sl].copy(), gyr=self.gyr[sl].copy(),
            acc=self.acc[sl].copy(), mag=self.mag[sl].copy(), quat_ref=self.quat_ref[sl].copy(),
            movement=self.movement[sl].copy(),
            mag_valid=None if self.mag_valid is None else self.mag_valid[sl].copy())


def load_trial(path: str | os.PathLike) -> Trial:
    """Read a BROAD ``.mat`` trial or a bundled-excerpt ``.npz`` trial.

    Raises KinefuseError (one line naming the file and the problem) for a missing, unreadable or
    malformed file.
    """
    path = Path(path)
    if not path.exists():
        raise KinefuseError(f"{path}: no such file")
    if path.is_dir():
        raise KinefuseError(f"{path}: is a directory, expected a trial file (.mat or .npz)")
    suffix = path.suffix.lower()
    if suffix == ".mat":
        raw = _read_mat(path)
    elif suffix == ".npz":
        raw = _read_npz(path)
    else:
        raise KinefuseError(f"{path}: unsupported trial format {suffix or '(no suffix)'!r}, "
                            f"expected a BROAD .mat file or a kinefuse excerpt .npz")
    return _build_trial(path, raw)


def find_trials(path: str | os.PathLike) -> list[Path]:
    """Trial files in ``path``: every ``.mat``/``.npz`` in a directory (sorted), or the file itself."""
    path = Path(path)
    if not path.exists():
        raise KinefuseError(f"{path}: no such file or directory")
    if path.is_file():
        return [path]
    files = sorted(p for p in path.iterdir()
                   if p.is_file() and p.suffix.lower() in TRIAL_SUFFIXES)
    if not files:
        raise KinefuseError(f"{path}: no trial files (.mat or .npz) in this directory")
    stems = [p.stem for p in files]
    twice = [p for k, p in enumerate(files) if p.stem in stems[:k]]
    if twice:   # (one trial's scores replaced the other's: fewer trials scored, without a word)
        first = files[stems.index(twice[0].stem)]
        raise KinefuseError(f"{path}: {first.name} and {twice[0].name} are the same trial "
                            f"{twice[0].stem}; keep one of them in the folder")
    return files


def shared_broad_dir() -> Path | None:
    """The full BROAD folder: ``$KINEFUSE_BROAD`` if set, else the shared data folder if present."""
    env = os.environ.get("KINEFUSE_BROAD")
    if env:
        return Path(env)
    repo = Path(__file__).resolve().parent.parent
    for cand in (Path("/work/shared/data/broad"), repo.parent / "shared" / "data" / "broad"):
        if cand.is_dir():
            return cand
    return None


def bundled_trials() -> list[Path]:
    """Trial files of the excerpt shipped with kinefuse (always present)."""
    return sorted(EXCERPT_DIR.glob("*.npz"))


def default_data() -> tuple[list[Path], str]:
    """Trials used when the user names none: the shared BROAD folder, else the bundled excerpt.

    Returns the files and a short description of where they come from.  A ``$KINEFUSE_BROAD``
    that names no folder is an error rather than a silent fallback.
    """
    env = os.environ.get("KINEFUSE_BROAD")
    shared = shared_broad_dir()
    if env and not Path(env).is_dir():
        raise KinefuseError(f"KINEFUSE_BROAD={env}: no such directory")
    if shared is not None:
        return find_trials(shared), f"BROAD trials in {shared}"
    return bundled_trials(), f"bundled BROAD excerpt in {EXCERPT_DIR}"


@functools.lru_cache(maxsize=8)
def _metadata(json_path: Path) -> dict:
    try:
        with open(json_path, encoding="utf-8") as fh:
            return json.load(fh).get("trials", {})
    except (OSError, ValueError):
        return {}


def trial_metadata(name: str, near: Path | None = None) -> dict:
    """Groups and description of a BROAD trial from trials.json next to the file or bundled."""
    for cand in ([near.parent / "trials.json"] if near is not None else []) + [BUNDLED_TRIALS_JSON]:
        meta = _metadata(cand.resolve()) if cand.is_file() else {}
        if name in meta:
            return meta[name]
    return {}


def _read_mat(path: Path) -> dict:
    import scipy.io

    try:
        mat = scipy.io.loadmat(str(path))
    except NotImplementedError:
        raise KinefuseError(f"{path}: MATLAB v7.3 (HDF5) files are not supported; "
                            f"save as v5 (-v7) like the BROAD files") from None
    except Exception as exc:  # scipy raises ValueError, TypeError, OSError... for garbage
        raise KinefuseError(f"{path}: not a readable MATLAB file ({_short(exc)})") from None
    missing = [k for k in _MAT_KEYS if k not in mat]
    if missing:
        raise KinefuseError(f"{path}: not a BROAD trial, missing {', '.join(missing)}")
    info = mat.get("info")
    return {"gyr": mat["imu_gyr"], "acc": mat["imu_acc"], "mag": mat["imu_mag"],
            "quat_ref": mat["opt_quat"], "movement": mat["movement"],
            "rate_hz": mat["sampling_rate"], "name": path.stem,
            "description": _info_description(info),
            **{k: mat[k] for k in ("mag_valid", "t") if k in mat},
            "_keys": {"gyr": "imu_gyr", "acc": "imu_acc", "mag": "imu_mag", "quat_ref": "opt_quat"}}


def _read_npz(path: Path) -> dict:
    # np.load takes anything that is neither a zip nor an .npy for a pickle (and with
    # allow_pickle=False says so): tell what the file is before it gets there
    try:
        with open(path, "rb") as fh:
            head = fh.read(6)
    except OSError as exc:
        raise KinefuseError(f"cannot read {path}: {exc.strerror or exc}") from None
    if not head:
        raise KinefuseError(f"{path}: not a readable .npz file (the file is empty)")
    if head == b"\x93NUMPY":
        raise KinefuseError(f"{path}: a single .npy array, not an .npz archive of trial arrays")
    if head[:4] not in (b"PK\x03\x04", b"PK\x05\x06"):
        raise KinefuseError(f"{path}: not a readable .npz file (not a zip archive)")
    try:
        with np.load(path, allow_pickle=False) as z:
            raw = {k: z[k] for k in z.files}
    except Exception as exc:  # BadZipFile, EOFError, zlib.error, tokenize.TokenError... for damage
        if isinstance(exc, ValueError) and "allow_pickle" in str(exc):   # numpy says a paragraph
            raise KinefuseError(f"{path}: holds pickled Python objects, which kinefuse does not load "
                                f"(a trial excerpt has numeric arrays only)") from None
        raise KinefuseError(f"{path}: not a readable .npz file ({_short(exc)})") from None
    missing = [k for k in _NPZ_KEYS if k not in raw]
    if missing and {"q_true", "t_true", "meta"} <= set(raw):
        raise KinefuseError(f"{path}: a simulator recording (kinefuse sim run --out .npz), not a trial "
                            f"excerpt; write it as .mat (kinefuse sim run NAME --out {path.stem}.mat), "
                            f"the BROAD layout the filters and benchmarks read")
    if missing:
        raise KinefuseError(f"{path}: not a kinefuse trial excerpt, missing {', '.join(missing)}")
    raw["name"] = str(raw["name"]) if "name" in raw else path.stem
    raw["description"] = str(raw.get("description", ""))
    return raw


def _build_trial(path: Path, raw: dict) -> Trial:
    keys = raw.get("_keys", {})  # names as the file spells them, for messages

    def arr(key: str, cols: int) -> np.ndarray:
        try:
            a = np.asarray(raw[key], dtype=np.float64)
        except (TypeError, ValueError):
            raise KinefuseError(f"{path}: {keys.get(key, key)} is not numeric") from None
        if a.ndim != 2 or a.shape[1] != cols:
            raise KinefuseError(f"{path}: {keys.get(key, key)} has shape {a.shape}, "
                                f"expected (N, {cols})")
        return np.ascontiguousarray(a)

    gyr, acc, mag, quat = arr("gyr", 3), arr("acc", 3), arr("mag", 3), arr("quat_ref", 4)
    n = gyr.shape[0]
    movement = np.asarray(raw["movement"]).reshape(-1)
    if n == 0:
        raise KinefuseError(f"{path}: the trial has no samples")
    for key, a in (("acc", acc), ("mag", mag), ("quat_ref", quat), ("movement", movement)):
        if a.shape[0] != n:
            raise KinefuseError(f"{path}: {keys.get(key, key)} has {a.shape[0]} samples, "
                                f"{keys.get('gyr', 'gyr')} has {n}")
    for key, a in (("gyr", gyr), ("acc", acc)):
        if not np.all(np.isfinite(a)):
            raise KinefuseError(f"{path}: {keys.get(key, key)} contains NaN or infinite samples")
    try:
        rate = float(np.asarray(raw["rate_hz"], dtype=np.float64).reshape(-1)[0])
    except (TypeError, ValueError, IndexError):
        raise KinefuseError(f"{path}: unreadable sampling rate") from None
    if not (np.isfinite(rate) and rate > 0):
        raise KinefuseError(f"{path}: invalid sampling rate {rate!r} Hz")
    mag_valid = None
    if "mag_valid" in raw:      # the simulator's .mat: which samples hold a new magnetometer reading
        try:
            mag_valid = np.asarray(raw["mag_valid"], dtype=np.float64).reshape(-1)
        except (TypeError, ValueError):
            raise KinefuseError(f"{path}: mag_valid is not numeric") from None
        if mag_valid.shape[0] != n or not np.all(np.isin(mag_valid, (0.0, 1.0))):
            raise KinefuseError(f"{path}: mag_valid must hold one 0/1 flag per sample ({n})")
        mag_valid = mag_valid.astype(bool)
        # a simulated sensor without a magnetometer (or between its readings) may hold NaN there:
        # those samples carry no reading, so zeros, never NaN, reach the filters
        blank = ~mag_valid & ~np.all(np.isfinite(mag), axis=1)
        if np.any(blank):
            mag = np.where(blank[:, None], 0.0, mag)
    if not np.all(np.isfinite(mag)):
        raise KinefuseError(f"{path}: {keys.get('mag', 'mag')} contains NaN or infinite samples"
                            + (" where mag_valid flags a reading" if mag_valid is not None else ""))
    t, steps = np.arange(n) / rate, None
    if "t" in raw and "mag_valid" in raw:   # the simulator's .mat: its own sample times
        try:
            tf = np.asarray(raw["t"], dtype=np.float64).reshape(-1)
        except (TypeError, ValueError):
            raise KinefuseError(f"{path}: t is not numeric") from None
        d = np.diff(tf)
        if tf.shape[0] != n or not np.all(np.isfinite(tf)) or np.any(d < 0):
            raise KinefuseError(f"{path}: t must hold one finite, non-decreasing time (s) per "
                                f"sample ({n})")
        if n > 1 and np.ptp(d) > 1e-9 * max(1.0, abs(float(tf[-1]))):   # not the constant rate
            t, steps = tf, np.concatenate([[float(np.median(d))], d])
    name = raw["name"]
    meta = trial_metadata(name, path)
    return Trial(name=name, rate_hz=rate, t=t, steps=steps, gyr=gyr, acc=acc, mag=mag,
                 quat_ref=quat, movement=movement.astype(bool), groups=tuple(meta.get("groups", ())),
                 source=path, description=raw.get("description") or meta.get("description", ""),
                 mag_valid=mag_valid)


def _info_description(info) -> str:
    """Second paragraph line of the BROAD ``info`` text (the trial description), if present."""
    try:
        text = str(np.asarray(info).reshape(-1)[0])
    except Exception:  # absent or odd: the description is optional
        return ""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.startswith("Trial:") and i + 1 < len(lines):
            return lines[i + 1].strip()
    return ""


def _short(exc: BaseException) -> str:
    return (str(exc).splitlines() or [type(exc).__name__])[0][:120] or type(exc).__name__
