"""The generated C of every filter, in both number systems, built with UndefinedBehaviorSanitizer
(+ float-cast-overflow, float-divide-by-zero) and AddressSanitizer and driven with random, extreme
and non-finite inputs: no report, and the same outputs as the normal build, field by field."""
from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest

from kinefuse.codegen import estimators
from kinefuse.codegen import runner as cg
from kinefuse.codegen.generate import GENERATED_DIR, lowered

SAN = ["-fsanitize=undefined,float-cast-overflow,float-divide-by-zero,address",
       "-fno-sanitize-recover=all", "-fno-omit-frame-pointer"]
DRIVER = r"""
#include <stdio.h>
#include <stdlib.h>
#include "@P@.h"
int main(int argc, char **argv)
{
    FILE *f = fopen(argv[1], "rb");
    long size;
    size_t n;
    @IN@ *in;
    @P@_output *out;
    @P@_params p;
    @P@_state s;
    if (f == NULL || argc < 3) return 2;
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    rewind(f);
    n = (size_t)size / sizeof(@IN@);
    in = malloc(n * sizeof(@IN@));
    out = calloc(n, sizeof(@P@_output));
    if (fread(in, sizeof(@IN@), n, f) != n) return 3;
    fclose(f);
    @P@_default_params(&p);
    @P@_init(&s, &p);
    @P@_run(&s, in, out, (uint32_t)n);
    f = fopen(argv[2], "wb");
    fwrite(out, sizeof(@P@_output), n, f);
    fclose(f);
    free(in);
    free(out);
    return 0;
}
"""
CASES = [(name, system) for name in estimators.ESTIMATORS
         for system in estimators.get(name).systems]


def random_inputs(est, n: int, seed: int = 0) -> dict[str, np.ndarray]:
    """Inputs over (and beyond) each field's declared range, with NaN/inf/extremes mixed in."""
    rng = np.random.default_rng(seed)
    out = {}
    for f in est.inputs.fields:
        if f.type == "bool":
            out[f.name] = rng.random((n, f.size)) < 0.5
        elif f.type == "int":
            out[f.name] = rng.integers(int(f.lo), int(f.hi) + 1, (n, f.size))
        else:
            span = max(abs(f.lo), abs(f.hi))
            v = rng.uniform(f.lo, f.hi, (n, f.size))
            pick = rng.random((n, f.size)) < 0.08
            specials = np.array([np.nan, np.inf, -np.inf, 0.0, -0.0, 1e-40, 3.0e38, -3.0e38,
                                 2.0 * span, -2.0 * span, f.lo, f.hi])
            v[pick] = rng.choice(specials, pick.sum())
            out[f.name] = v
    return out


@pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")
@pytest.mark.parametrize("name,system", CASES)
def test_generated_c_is_free_of_undefined_behaviour(name, system, tmp_path):
    est = estimators.get(name)
    r = cg.runner(name, system)                       # the normal build (cffi)
    enc = r.encode(random_inputs(est, 1500), est.resolve_params())
    want = r.run_encoded(enc)
    in_dt = r._dtype(r.in_type, "input")
    out_dt = r._dtype(f"{r.P}_output", "output")
    rec = np.zeros(enc.n, dtype=in_dt)
    for fname, size, typ in r.fields["input"]:
        v = enc.inputs[fname]
        rec[fname] = (v.reshape(enc.n) if size == 1 else v).astype(in_dt[fname].base)
    (tmp_path / "in.bin").write_bytes(rec.tobytes())
    P = lowered(name, system).prefix
    (tmp_path / "drv.c").write_text(DRIVER.replace("@P@", P).replace("@IN@", r.in_type))
    exe = tmp_path / "drv"
    subprocess.run(["gcc", "-std=c99", "-O0", "-ffp-contract=off", *SAN,
                    f"-I{GENERATED_DIR}", str(tmp_path / "drv.c"), str(GENERATED_DIR / f"{P}.c"),
                    "-lm", "-o", str(exe)], check=True, capture_output=True)
    res = subprocess.run([str(exe), str(tmp_path / "in.bin"), str(tmp_path / "out.bin")],
                         capture_output=True, text=True, timeout=300)
    assert res.returncode == 0 and "runtime error" not in res.stderr, res.stderr[-3000:]
    got = np.frombuffer((tmp_path / "out.bin").read_bytes(), dtype=out_dt)
    for fname, size, typ in r.fields["output"]:
        g = got[fname].reshape(enc.n, size)
        w = want[fname].reshape(enc.n, size)
        if typ == "real" and system == "f32":
            assert np.array_equal(cg.bits(g.astype(np.float32)), cg.bits(w)), fname
        else:
            assert np.array_equal(g.astype(np.int64), w.astype(np.int64)), fname
