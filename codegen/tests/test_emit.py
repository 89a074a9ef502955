"""Rules of the emitted C and models (checked on every registered filter's committed files)."""
from __future__ import annotations

import inspect
import os
import re
import subprocess

import pytest

from kinefuse.codegen import estimators
from kinefuse.codegen.generate import GENERATED_DIR, check, graph_of, lowered

FILTERS = list(estimators.ESTIMATORS)
LIBM = {"sin", "cos", "tan", "asin", "acos", "atan", "atan2", "exp", "log", "pow", "fmod", "floor",
        "ceil", "round", "trunc", "sqrt", "fabs", "hypot", "cbrt", "exp2", "log2", "log10",
        "lrint", "rint", "nearbyint", "fma", "fmin", "fmax", "copysign", "ldexp", "frexp"}
ALLOWED_CALLS = {"sqrtf", "fabsf"}


def stem(name, system):
    return lowered(name, system).prefix      # C identifiers: '-' in registry names becomes '_'


def sources(name):
    return [GENERATED_DIR / f"{stem(name, s)}.c" for s in estimators.get(name).systems]


def test_generated_files_are_up_to_date():
    stale = check()
    assert not stale, f"run `kinefuse codegen`: stale {stale}"


@pytest.mark.parametrize("name", FILTERS)
def test_c_guards_constants_and_library_calls(name):
    for path in sources(name):
        text = path.read_text()
        assert "#if !defined(FLT_EVAL_METHOD) || (FLT_EVAL_METHOD != 0)" in text
        assert "#ifdef __FAST_MATH__" in text
        assert "malloc" not in text and "free(" not in text
        calls = set(re.findall(r"\b([a-z_][a-z0-9_]*)\s*\(", text))
        libm = {c for c in calls if c in LIBM or (c.endswith("f") and c[:-1] in LIBM)}
        assert libm <= ALLOWED_CALLS, f"{path.name} calls {libm - ALLOWED_CALLS}"
        # binary32 constants are exact hex floats; only zero is written in decimal
        decimals = re.findall(r"(?<![\w.])(\d+\.\d*(?:[eE][-+]?\d+)?f)\b", text)
        assert set(decimals) <= {"0.0f"}, f"{path.name}: decimal float constants {set(decimals)}"
        # no file-scope variables (state lives in the caller's struct)
        body = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
        file_scope = [ln for ln in body.splitlines()
                      if re.match(r"^(static\s+)?(const\s+)?(float|int32_t|int64_t|int)\s+\w+\s*(=|;|\[)", ln)]
        assert not file_scope, file_scope


@pytest.mark.parametrize("name", FILTERS)
def test_c_compiles_warning_free_pedantic(name, tmp_path):
    for path in sources(name):
        r = subprocess.run(["gcc", "-std=c99", "-pedantic", "-Wall", "-Wextra", "-Werror",
                            "-Wconversion", "-Wno-sign-conversion", "-ffp-contract=off", "-O0",
                            f"-I{GENERATED_DIR}", "-c", str(path), "-o", str(tmp_path / "x.o")],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr[:2000]


def test_f32_refuses_gnu_mode_contraction(tmp_path):
    """GNU C modes fuse a*b+c (the M4F has vfma): the generated float32 C refuses to build there
    unless -ffp-contract=off is declared; ISO C99 builds, and on the M4F it has no fused op."""
    import shutil
    path = GENERATED_DIR / f"{stem('complementary', 'f32')}.c"
    base = ["gcc", "-O2", f"-I{GENERATED_DIR}", "-c", str(path), "-o", str(tmp_path / "x.o")]
    r = subprocess.run(base + ["-std=gnu99"], capture_output=True, text=True)
    assert r.returncode != 0 and "GNU C modes fuse" in r.stderr
    assert subprocess.run(base + ["-std=gnu99", "-ffp-contract=off", "-DKF_FP_CONTRACT_OFF"]).returncode == 0
    assert subprocess.run(base + ["-std=c99"]).returncode == 0
    if shutil.which("arm-none-eabi-gcc") and shutil.which("arm-none-eabi-objdump"):
        obj = tmp_path / "m4f.o"
        subprocess.run(["arm-none-eabi-gcc", "-mcpu=cortex-m4", "-mthumb", "-mfpu=fpv4-sp-d16",
                        "-mfloat-abi=hard", "-O2", "-std=c99", f"-I{GENERATED_DIR}", "-c", str(path),
                        "-o", str(obj)], check=True)
        dis = subprocess.run(["arm-none-eabi-objdump", "-d", str(obj)], capture_output=True,
                             text=True, check=True).stdout
        assert "vmul.f32" in dis and not re.search(r"\bv(fma|fms|fnma|fnms|mla|mls|nmla|nmls)\.", dis)


@pytest.mark.parametrize("name", [f for f in FILTERS if "q" in estimators.get(f).systems])
def test_q_header_lists_every_state_format(name):
    text = (GENERATED_DIR / f"{stem(name, 'q')}.h").read_text()
    state = text[text.index("params;", text.index("typedef struct {\n    " + stem(name, "q")
                                                   + "_params params;")):]
    state = state[:state.index("_q_state;")]
    for line in state.splitlines():
        if "int32_t" in line and "[" not in line.split("int32_t")[0]:
            est = estimators.get(name)
            var = line.split("int32_t")[1].split(";")[0].split("[")[0].strip()
            if any(v.name == var and v.type == "real" for v in est.state):
                assert re.search(r"Q-?\d+\.\d+: value = raw \* 2\^", line), line


@pytest.mark.parametrize("name", FILTERS)
def test_statements_are_one_operation_in_graph_order(name):
    """Every f32 statement holds at most one arithmetic operation; the model has the same
    statements (its assignment targets appear in the same order as the C's)."""
    text = (GENERATED_DIR / f"{stem(name, 'f32')}.c").read_text()
    upd = text[text.index("_update("):]
    for ln in upd.splitlines():
        m = re.match(r"\s+(?:const float )?(t\d+\w*) = (.*);", ln)
        if m:
            expr = re.sub(r"/\*.*", "", m.group(2))
            ops = len(re.findall(r"(?<![eEx(])[-+*/](?![0-9a-fp]*f\b)|sqrtf|fabsf", expr))
            assert ops <= 2, ln   # a - b, or a select with one comparison
    c_names = re.findall(r"\b(t\d+(?:_[a-z0-9]+)?) = ", upd)
    model = (GENERATED_DIR / "models" / f"{stem(name, 'f32')}.py").read_text()
    m_names = set(re.findall(r"\b(t\d+(?:_[a-z0-9]+)?) = ", model))
    assert all(n in m_names for n in c_names)


REFERENCE_DIR = os.path.dirname(inspect.getsourcefile(estimators))
REFERENCE_FILES = {f: len(open(os.path.join(d, f)).read().splitlines())
                   for d, _, fs in os.walk(REFERENCE_DIR) for f in fs
                   if f.endswith(".py") and f not in ("ad.py", "__init__.py")}


@pytest.mark.parametrize("name", FILTERS)
def test_operation_locations_name_reference_lines(name):
    """Each operation's location (the C comments, `bench cost --profile`) is a line of the
    reference (the estimator or a shared reference module), never of the generator or of the
    dynamics filters' automatic differentiation, whose dual numbers record every derivative's
    operations (their locations were all ad.py:N)."""
    locs = {n.loc for n in graph_of(name).nodes if n.op not in ("const", "input")}
    bad = sorted(loc for loc in locs if loc.split(":")[0] not in REFERENCE_FILES
                 or not 0 < int(loc.split(":")[1]) <= REFERENCE_FILES[loc.split(":")[0]])
    assert locs and not bad, f"{name}: locations outside the reference: {bad[:8]}"
    own = os.path.basename(inspect.getsourcefile(type(estimators.get(name))))
    assert any(loc.startswith(own + ":") for loc in locs), f"{name}: none in {own}"
    for path in sources(name):
        files = set(re.findall(r"/\* ([\w.-]+\.py):\d+", path.read_text()))
        assert files and files <= set(REFERENCE_FILES), f"{path.name}: {files}"


def test_op_count_table_lists_every_filter():
    table = (GENERATED_DIR / "OPS.md").read_text()
    for name in FILTERS:
        for system in estimators.get(name).systems:
            assert f"| {name} | {system} |" in table
        # q counts every graph operation; f32 leaves out what it emits nothing for (bound)
        if "q" in estimators.get(name).systems:
            assert lowered(name, "q").op_summary() == graph_of(name).op_summary()
        assert lowered(name, "f32").op_summary() == graph_of(name).op_summary(
            lambda n: "bound" in n.attrs)
