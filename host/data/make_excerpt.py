"""Cut the bundled BROAD excerpt (host/data/broad_excerpt/) from the full BROAD trials.

    python -m kinefuse.host.data.make_excerpt [--src DIR] [--out DIR]

Each excerpt is one contiguous block of samples taken from the very first sample of a trial (the
rest phase there lets filters initialise) up to a fixed time inside the first motion phase.
Values are copied unchanged (float64, bit for bit) into a compressed .npz; the script re-reads
every file and checks that.  Source file, its SHA-256 and the sample range are stored in the
.npz so the cut can be traced.  Data: BROAD (Laidig et al., Data 2021), CC BY 4.0.
"""
from __future__ import annotations

import argparse
import hashlib
import sys
from pathlib import Path

import numpy as np

from kinefuse.host.broad import EXCERPT_DIR, load_trial, shared_broad_dir

#: trial -> (end time in s, why this trial and this end).  Start is always sample 0.
CUTS: dict[str, tuple[float, str]] = {
    "08_undisturbed_fast_rotation_with_breaks_A":
        (80.0, "fast rotation; motion from 28.5 s, a 10 s break at 65.5-75.9 s (rest detection)"),
    "15_undisturbed_fast_translation_A":
        (70.0, "fast translation (up to 4 g); motion from 40.5 s"),
    "24_disturbed_tapping_A":
        (75.0, "tapping disturbance (acceleration spikes); motion from 44.8 s"),
    "32_disturbed_attached_magnet_1cm":
        (75.0, "magnet attached 1 cm from the sensor from about 38 s; motion from 41.3 s"),
}


def sha256(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def cut(src_dir: Path, out_dir: Path) -> list[Path]:
    out_dir.mkdir(parents=True, exist_ok=True)
    written = []
    for name, (end_s, why) in CUTS.items():
        src = src_dir / f"{name}.mat"
        full = load_trial(src)
        stop = int(round(end_s * full.rate_hz))
        part = full.window(0, stop)
        if not part.movement.any():
            raise SystemExit(f"{name}: the excerpt 0-{end_s} s has no motion phase")
        dst = out_dir / f"{name}.npz"
        np.savez_compressed(
            dst, gyr=part.gyr, acc=part.acc, mag=part.mag, quat_ref=part.quat_ref,
            movement=part.movement, rate_hz=np.float64(full.rate_hz), name=np.str_(name),
            description=np.str_(full.description), why=np.str_(why),
            source_file=np.str_(src.name), source_sha256=np.str_(sha256(src)),
            start_sample=np.int64(0), stop_sample=np.int64(stop), source_samples=np.int64(full.n))
        back = load_trial(dst)  # the copy must be bit-identical to the source slice
        for key in ("gyr", "acc", "mag", "quat_ref"):
            a, b = getattr(back, key), getattr(full, key)[:stop]
            if a.tobytes() != b.tobytes():
                raise SystemExit(f"{name}: {key} changed in the excerpt")
        if not np.array_equal(back.movement, full.movement[:stop]):
            raise SystemExit(f"{name}: movement changed in the excerpt")
        print(f"{dst.name}: samples 0-{stop} of {full.n} ({stop / full.rate_hz:.1f} s), "
              f"{dst.stat().st_size / 1e6:.2f} MB")
        written.append(dst)
    return written


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--src", type=Path, default=shared_broad_dir(), help="full BROAD folder")
    ap.add_argument("--out", type=Path, default=EXCERPT_DIR, help="output folder")
    args = ap.parse_args(argv)
    if args.src is None:
        ap.error("no BROAD folder found; pass --src")
    files = cut(args.src, args.out)
    total = sum(p.stat().st_size for p in files)
    print(f"{len(files)} trials, {total / 1e6:.2f} MB in {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
