"""Runners and model modules cached per process follow the generated files' content."""
from __future__ import annotations

import os
import shutil
import sys

from kinefuse.codegen import generate, runner


def test_regenerated_files_get_a_new_runner(tmp_path, monkeypatch):
    gen = tmp_path / "generated"
    (gen / "models").mkdir(parents=True)
    for rel in ("madgwick_f32.c", "madgwick_f32.h", "kf_imu_f32.h", "kf_fixed.h",
                "models/madgwick_f32.py"):
        shutil.copy(generate.GENERATED_DIR / rel, gen / rel)
    monkeypatch.setattr(generate, "GENERATED_DIR", gen)
    monkeypatch.setattr(runner, "_RUNNERS", {})
    first = runner.runner("madgwick", "f32-model")
    assert runner.runner("madgwick", "f32-model") is first          # cached
    for rel in ("madgwick_f32.c", "kf_imu_f32.h", "models/madgwick_f32.py"):
        (gen / rel).write_text((gen / rel).read_text() + "\n/* regenerated */\n"
                               if rel.endswith(("c", "h")) else
                               (gen / rel).read_text() + "\n# regenerated\n")
        again = runner.runner("madgwick", "f32-model")
        assert again is not first, f"{rel} changed: the old runner was reused"
        first = again


def test_a_changed_model_module_is_reloaded(tmp_path, monkeypatch):
    pkg = tmp_path / "kf_tmp_models_pkg"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    mod = pkg / "m_f32.py"
    mod.write_text("FIELDS = {'input': [('x', 1, 'real')]}\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.setattr(sys, "dont_write_bytecode", False)     # as on a user's machine
    name = "kf_tmp_models_pkg.m_f32"
    try:
        assert runner.current_module(name).FIELDS["input"] == [("x", 1, "real")]
        assert runner.current_module(name).FIELDS["input"] == [("x", 1, "real")]
        # regenerated within the same second, same size: the bytecode cache cannot tell
        st = mod.stat()
        mod.write_text("FIELDS = {'input': [('y', 2, 'real')]}\n")
        os.utime(mod, ns=(st.st_atime_ns, st.st_mtime_ns))
        assert mod.stat().st_size == st.st_size
        assert runner.current_module(name).FIELDS["input"] == [("y", 2, "real")]
    finally:
        for m in (name, "kf_tmp_models_pkg"):
            sys.modules.pop(m, None)
