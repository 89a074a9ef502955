"""The loops a filter runs in, one scenario format (:class:`~.scenarios.Case`) for all.

============================  =======================================================  ========
loop                          what runs                                                outputs
============================  =======================================================  ========
``ref``                       the estimator's Python code on float64 (reference)       float64
``f32-model`` / ``q-model``   the generated Python models (model loop)                 storage
``host-f32`` / ``host-q``     the generated C compiled for the host (cffi)             storage
``qemu-m4f-f32``              generated C, Cortex-M4F (``mps2-an386``), batch driver   storage
``qemu-m4f-q``                fixed-point C on the M4F                                 storage
``qemu-m0-q``                 fixed-point C on the Cortex-M0 (``mps2-an385``)          storage
``qemu-m0-f32``               float32 C with soft float on the M0 (extra)              storage
``sil-*`` / ``pil-*``         the firmware application over its UART (:mod:`.firmware`)
============================  =======================================================  ========

"storage" outputs are the number system's own values (binary32, or int64 holding the Q-format
raw integer): these are compared bit for bit (:mod:`.compare`).  Every loop of one number
system receives the *same* encoded inputs (binary32 rounding or Q-format conversion done once,
by :mod:`kinefuse.codegen.runner`).
"""
from __future__ import annotations

import numpy as np

from kinefuse.codegen import estimators, runner as cg
from kinefuse.host.errors import KinefuseError

MODEL_LOOPS = ("f32-model", "q-model")
HOST_LOOPS = ("host-f32", "host-q")
QEMU_LOOPS = ("qemu-m4f-f32", "qemu-m4f-q", "qemu-m0-q", "qemu-m0-f32")
#: loops whose outputs must be identical in bits, per number system (the issue's requirement;
#: firmware loops are appended by :func:`bitexact_loops` when the firmware exists)
BITEXACT = {"f32": ("f32-model", "host-f32", "qemu-m4f-f32"),
            "q": ("q-model", "host-q", "qemu-m4f-q", "qemu-m0-q")}


def system_of(loop: str) -> str:
    if loop == "ref":
        return "ref"
    return loop.rsplit("-", 1)[-1] if not loop.endswith("-model") else loop.split("-")[0]


def systems(name: str) -> tuple[str, ...]:
    """Number systems a registered estimator is generated in."""
    cls = estimators.ESTIMATORS[name]
    return tuple(getattr(cls, "systems", ("f32", "q")))


def imu_filters() -> list[str]:
    """Registered IMU filters (new registry entries are covered automatically)."""
    return [n for n, cls in estimators.ESTIMATORS.items() if cls.inputs.name == "imu"]


def encode(name: str, system: str, inputs: dict, params: dict | None = None):
    """(ModelInfo, Encoded) for the loops of one number system."""
    est = estimators.get(name)
    prm = est.resolve_params(params)
    info = cg.runner(name, f"{system}-model")
    return info, info.encode(inputs, prm)


def sample_count(name: str, inputs: dict) -> int:
    """Samples in ``inputs`` (the length of ``dt``, else of the first input); KinefuseError for
    none: an empty run has nothing to compare, so it must not reach a comparison that then
    finds "no difference"."""
    if not inputs:
        raise KinefuseError(f"{name}: no inputs given")
    first = inputs["dt"] if "dt" in inputs else next(iter(inputs.values()))
    n = len(np.asarray(first))
    if n == 0:
        raise KinefuseError(f"{name}: the input has no samples; give at least one")
    return n


def run_loop(loop: str, name: str, inputs: dict, params: dict | None = None) -> dict[str, np.ndarray]:
    """Outputs of filter ``name`` over ``inputs`` in ``loop`` (storage values; float64 for ref)."""
    sample_count(name, inputs)
    if loop == "ref":
        return cg.run(name, "ref", inputs, params)
    system = system_of(loop)
    if system not in systems(name):
        raise KinefuseError(f"filter {name} has no {system} implementation")
    info, e = encode(name, system, inputs, params)
    if loop.endswith("-model"):
        return cg.runner(name, loop).run_encoded(e)
    if loop.startswith("host-"):
        return cg.runner(name, system).run_encoded(e)
    if loop.startswith("qemu-"):
        from kinefuse.hil_tests.harness.qemu_filter import filter_program
        target = loop.split("-")[1]
        return filter_program(name, system, target, e.params).run_encoded(e)
    if loop.startswith(("sil-", "pil-")):
        from kinefuse.hil_tests.harness import firmware
        return firmware.run_firmware_loop(loop, name, info, e)
    raise KinefuseError(f"unknown loop {loop!r}")


def decode(name: str, loop: str, outputs: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """Storage values -> float64 host values (identity for ``ref``)."""
    if loop == "ref":
        return outputs
    info = cg.runner(name, f"{system_of(loop)}-model")
    return {k: info.decode_values("output", k, typ, outputs[k])
            for k, size, typ in info.fields["output"]}


def bitexact_loops(name: str, system: str, qemu: bool = True, firmware: bool = False) -> list[str]:
    """Loops that must agree in bits for ``name`` in ``system``."""
    loops = [lp for lp in BITEXACT[system] if qemu or not lp.startswith("qemu-")]
    if firmware:
        from kinefuse.hil_tests.harness import firmware as fw
        loops += fw.firmware_loops(name, system)
    return loops
