"""The walkthrough of codegen/README.md ("Writing an estimator") as a new contributor follows it.

The two code blocks marked ``<!-- walkthrough: ... -->`` are taken from the README and executed
as they stand (line numbers kept, so an error names the README line): the estimator is generated
into a temporary directory (never firmware/generated/), its float32 C and fixed-point C are built
on the host, and every output sample of each is compared bit for bit with its generated Python
model on a few hundred random and hostile inputs.  A README example that stops tracing, compiling,
matching its models or filtering is a failure here, so the document cannot drift from the code.
"""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from kinefuse.codegen.estimator import Estimator, run_reference
from kinefuse.codegen.runner import bits
from kinefuse.codegen.testing import build_adhoc

README = Path(__file__).resolve().parent.parent / "README.md"
N = 400


def readme_block(tag: str, readme: Path | None = None) -> str:
    """The ```python block right after ``<!-- walkthrough: tag -->``, padded with blank lines so
    that its line numbers are the README's."""
    readme = readme or README
    text = readme.read_text(encoding="utf-8")
    marker = f"<!-- walkthrough: {tag} -->"
    assert text.count(marker) == 1, f"{readme}: expected one {marker!r}"
    m = re.compile(re.escape(marker) + r"\s*\n```python\n(.*?)\n```", re.S).search(text)
    assert m is not None, f"{readme}: no ```python block right after {marker!r}"
    first_line = text[:m.start(1)].count("\n")
    return "\n" * first_line + m.group(1) + "\n"


def exec_block(tag: str, ns: dict, readme: Path | None = None, replace=()) -> dict:
    readme = readme or README
    code = readme_block(tag, readme)
    for old, new in replace:
        assert code.count(old) == 1, f"README {tag} block: expected {old!r} once"
        code = code.replace(old, new)
    exec(compile(code, str(readme), "exec"), ns)
    return ns


def readme_estimator(readme: Path | None = None) -> tuple[type[Estimator], dict]:
    ns = exec_block("estimator", {"__name__": "readme_walkthrough"}, readme)
    defined = [v for v in ns.values() if isinstance(v, type) and issubclass(v, Estimator)
               and v is not Estimator and v.__module__ == "readme_walkthrough"]
    assert len(defined) == 1, f"the README's estimator block defines {len(defined)} estimators"
    return defined[0], ns


def hostile_inputs(est: Estimator, seed: int) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """Random inputs over (and beyond) the declared ranges, and which samples are invalid by the
    declaration (angle or dt non-finite or outside its declared range, dt not > 0)."""
    rng = np.random.default_rng(seed)
    a, dt = est.inputs.field("angle"), est.inputs.field("dt")
    angle = rng.uniform(a.lo, a.hi, N)
    step = rng.uniform(0.0, dt.hi, N)
    valid = rng.random(N) < 0.8
    pick = rng.random(N) < 0.1
    angle[pick] = rng.choice(np.array([np.nan, np.inf, -np.inf, 2.0 * a.hi, -1e30]), pick.sum())
    pick = rng.random(N) < 0.05
    step[pick] = rng.choice(np.array([np.nan, 0.0, -0.01, 2.0 * dt.hi, np.inf]), pick.sum())
    with np.errstate(invalid="ignore"):
        bad = ~((np.abs(angle) <= a.hi) & (step > 0.0) & (step <= dt.hi))
    return {"angle": angle, "angle_valid": valid, "dt": step}, bad


def test_readme_estimator_c_equals_its_models_bit_for_bit(tmp_path):
    cls, _ = readme_estimator()
    est = cls()
    built = build_adhoc(est, tmp_path / "gen")
    assert set(built) == {"f32", "q"}
    # generated into the temporary directory, nowhere else
    assert (tmp_path / "gen" / f"{est.name.replace('-', '_')}_q.c").is_file()
    tau = est.param("tau")
    for seed, params in ((1, est.resolve_params()),
                         (2, est.resolve_params({"tau": tau.lo})),
                         (3, est.resolve_params({"tau": float(np.random.default_rng(3).uniform(
                             tau.lo, tau.hi))}))):
        inputs, bad = hostile_inputs(est, seed)
        assert 0 < bad.sum() < N // 2
        ref, _ = run_reference(est, inputs, params)
        assert np.all(np.isfinite(ref["angle"]))
        for system, (c, model) in built.items():
            enc = c.encode(inputs, params)
            out_c, out_m = c.run_encoded(enc), model.run_encoded(enc)
            assert set(out_c) == set(out_m) == {v.name for v in est.outputs}
            for key in out_c:
                bc = bits(out_c[key]).reshape(N, -1)
                bm = bits(out_m[key]).reshape(N, -1)
                diff = np.flatnonzero(np.any(bc != bm, axis=1))
                assert diff.size == 0, (f"{system} {key} (seed {seed}): C and model differ at "
                                        f"samples {diff[:5]}: C {bc[diff[0]]} model {bm[diff[0]]}")
            # every invalid sample counted, none other
            assert out_c["rejected"][:, 0].tolist() == np.cumsum(bad).tolist(), system
            # a rejected sample or one without a measurement (angle_valid 0) keeps the state
            hold = np.flatnonzero(bad | ~inputs["angle_valid"])
            raw = bits(out_c["angle"])[:, 0]
            prev = np.concatenate([bits(np.asarray(c.initial_state()["angle"], raw.dtype
                                                   if system == "q" else np.float32)), raw[:-1]])
            moved = hold[raw[hold] != prev[hold]]
            assert moved.size == 0, f"{system}: samples {moved[:5]} changed the held angle"
            y = c.decode_values("output", "angle", "real", out_c["angle"])[:, 0]
            assert np.all(np.isfinite(y)), system
            # and it is still the low-pass: the number systems follow the float64 reference far
            # below a joint angle's resolution (measured here: f32 <= 5e-7 rad, q <= 2.9e-6 rad,
            # the latter at tau = 0.001 s, where tau's own Q4.27 rounding is 4e-6 of it)
            dev = np.max(np.abs(y - ref["angle"][:, 0]))
            assert dev < 1e-5, f"{system} (seed {seed}): {dev:.3g} rad from the reference"


def test_readme_check_block_runs_as_written(tmp_path, capsys):
    _, ns = readme_estimator()
    exec_block("check", ns, replace=[('"/tmp/angle_lowpass"', repr(str(tmp_path / "check")))])
    printed = capsys.readouterr().out
    assert re.search(r"^f32 bit-exact", printed, re.M), printed
    assert re.search(r"^q bit-exact", printed, re.M), printed
    assert (tmp_path / "check" / "angle_lowpass_f32.c").is_file()


def test_a_broken_readme_example_fails_here(tmp_path):
    """The extraction really runs the README: a step() that breaks a rule is refused."""
    text = README.read_text(encoding="utf-8")
    broken = text.replace("        y = select(logical_and(ok, u.angle_valid), y, x.angle)\n",
                          "        y = y if ok else x.angle\n")
    assert broken != text, "the README example no longer has the line this test breaks"
    bad_readme = tmp_path / "README.md"
    bad_readme.write_text(broken, encoding="utf-8")
    cls, _ = readme_estimator(bad_readme)
    with pytest.raises(TypeError, match=r"README\.md:\d+.*select\(cond, a, b\)"):
        build_adhoc(cls(), tmp_path / "gen")
