"""The host build (codegen/build.py): what must rebuild, and clear errors."""
from __future__ import annotations

import shutil
import stat

import pytest

from kinefuse.codegen import build as cbuild
from kinefuse.codegen.generate import GENERATED_DIR


def _fake_cc(path, version: str):
    """A C compiler wrapper reporting `version` (a compiler upgrade, same command)."""
    gcc = shutil.which("gcc")
    path.write_text(f'#!/bin/sh\nif [ "$1" = "--version" ]; then echo "{version}"; exit 0; fi\n'
                    f'exec {gcc} "$@"\n')
    path.chmod(path.stat().st_mode | stat.S_IXUSR)


def test_compiler_upgrade_rebuilds(tmp_path, monkeypatch):
    monkeypatch.setenv("KINEFUSE_CACHE", str(tmp_path / "cache"))
    cc = tmp_path / "cc"
    monkeypatch.setenv("CC", str(cc))
    monkeypatch.setattr(cbuild, "_CC_IDENTITY", {})
    src = tmp_path / "src"
    src.mkdir()
    (src / "kf_t.h").write_text("int kf_t_one(void);\n")
    (src / "kf_t.c").write_text('#include "kf_t.h"\nint kf_t_one(void) { return 1; }\n')

    def build():
        _ffi, lib = cbuild.build("kf_t", [src / "kf_t.h"], [src / "kf_t.c"], include_dirs=[src])
        assert lib.kf_t_one() == 1
        return sorted(p.name for p in cbuild.cache_dir().glob("*.so"))

    _fake_cc(cc, "fakecc 1.0")
    first = build()
    assert len(first) == 1
    assert build() == first                      # same compiler: cached
    _fake_cc(cc, "fakecc 2.0")
    monkeypatch.setattr(cbuild, "_CC_IDENTITY", {})   # a new process after the upgrade
    second = build()
    assert len(second) == 2, "the module built by the old compiler was reused"


def test_header_without_its_input_record_is_a_clear_error(tmp_path):
    text = (GENERATED_DIR / "madgwick_f32.h").read_text()
    (tmp_path / "madgwick_f32.h").write_text(text.replace('#include "kf_imu_f32.h"', ""))
    with pytest.raises(ValueError, match=r"madgwick_f32\.h does not include its input record "
                                         r"header .*run `kinefuse codegen`"):
        cbuild.build_filter("madgwick", "f32", gen_dir=tmp_path)


def test_the_same_code_in_another_folder_is_not_compiled_again(tmp_path, monkeypatch):
    """Every temporary folder (each test's generated code) compiled anew and left another .so in
    the cache, and every build left its build_<name>_<pid> folder behind."""
    monkeypatch.setenv("KINEFUSE_CACHE", str(tmp_path / "cache"))
    mods = []
    for k in range(2):
        src = tmp_path / f"gen{k}"
        src.mkdir()
        (src / "kf_u.h").write_text("int kf_u_two(void);\n")
        (src / "kf_u.c").write_text('#include "kf_u.h"\nint kf_u_two(void) { return 2; }\n')
        _ffi, lib = cbuild.build("kf_u", [src / "kf_u.h"], [src / "kf_u.c"], include_dirs=[src])
        assert lib.kf_u_two() == 2
        mods.append(sorted(p.name for p in cbuild.cache_dir().glob("*.so")))
    assert mods[0] == mods[1] and len(mods[0]) == 1
    assert not list(cbuild.cache_dir().glob("build_*"))
    # a different header content in the include folder still rebuilds
    src = tmp_path / "gen0"
    (src / "kf_extra.h").write_text("#define KF_EXTRA 1\n")
    cbuild.build("kf_u", [src / "kf_u.h"], [src / "kf_u.c"], include_dirs=[src])
    assert len(list(cbuild.cache_dir().glob("*.so"))) == 2
