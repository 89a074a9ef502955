"""Can the leg EKF run in fixed point?  A measurement, not a generated filter.

The generator's fixed-point path chooses a Q format for every value from interval analysis of
the declared ranges.  For this filter the analysis fails at once (the kinematics' dual-number
products, the LDLᵀ pivots and the covariance updates have unbounded intervals: RangeError at
the first product of the AD), and the only way through would be ``assume()`` bounds that are
not mathematical facts (bounds on covariance entries, gains, mass-matrix pivots...).

So this module measures the best any int32 Q-format assignment could do: it evaluates the
filter's optimised graph (the very operations of the generated C) sample by sample, rounding
every real value to a format chosen *from the range that value actually takes on the trial*
(an oracle: interval analysis can only choose coarser formats), with saturation.  The float32
version of the same emulation (every value rounded to binary32) checks the emulator against
the generated float32 C.
"""
from __future__ import annotations

import math

import numpy as np

from kinefuse.codegen.estimator import initial_state, trace
from kinefuse.codegen.fixed import frac_for
from kinefuse.codegen.ir import BOOL, REAL
from kinefuse.codegen.passes import eval_op, optimize


def _env_inputs(est, inputs, prm, k):
    env = {}
    for f in est.inputs.fields:
        col = np.asarray(inputs[f.name]).reshape(len(inputs["dt"]), -1)
        for i in range(f.size):
            v = col[k, i]
            env[("input", f.name, i)] = bool(v) if f.type == BOOL else float(v)
    for p in est.params:
        env[("param", p.name, 0)] = float(prm[p.name])
    return env


def emulate(est, inputs: dict, params: dict, mode: str = "float64", fracs=None, g=None):
    """Run the optimised graph over the samples with every real value rounded: mode
    'float64' (no rounding; also records max |value| per node), 'float32', or 'fixed'
    (fracs: node id -> fractional bits; saturating int32).  g: the optimised graph (traced
    here when None).  Returns (outputs, node_max, g)."""
    g = g if g is not None else optimize(trace(est))
    prm = est.resolve_params(params)
    n = len(inputs["dt"])
    state = {("state", v.name, i): val for v in est.state
             for i, val in enumerate(initial_state(est)[v.name])}
    outs = {v.name: np.zeros((n, v.size)) for v in est.outputs}
    node_max = {}
    lim = 2.0 ** 31 - 1

    def rnd(node, x):
        if node.type != REAL:
            return x
        if mode == "float32":
            return float(np.float32(x))
        if mode == "fixed":
            f = fracs[node.id]
            r = x * 2.0 ** f
            if r != r:
                return -lim * 2.0 ** -f
            r = max(-lim, min(lim, math.floor(r + 0.5)))
            return r * 2.0 ** -f
        return x

    for k in range(n):
        env = _env_inputs(est, inputs, prm, k)
        env.update(state)
        val = {}
        for node in g.nodes:
            if node.op == "const":
                v = node.value
            elif node.op == "input":
                v = env[node.attrs]
            else:
                v = eval_op(node.op, [val[a.id] for a in node.args], node.attrs)
            if node.type == REAL:
                v = rnd(node, v)      # constants, inputs and parameters too (as the C holds them)
                if mode == "float64" and v == v and abs(v) != math.inf:
                    node_max[node.id] = max(node_max.get(node.id, 0.0), abs(v))
            val[node.id] = v
        for r in g.results:
            if r.kind == "state":
                state[("state", r.name, r.index)] = val[r.node.id]
            else:
                outs[r.name][k, r.index] = float(val[r.node.id])
    return outs, node_max, g


def oracle_fracs(g, node_max: dict, margin: float = 2.0) -> dict:
    """Fractional bits per node from its observed range times `margin` (int32)."""
    out = {}
    for node in g.nodes:
        if node.type == REAL:
            r = node_max.get(node.id, abs(node.value) if node.op == "const" else 0.0)
            out[node.id] = frac_for(r * margin) if r > 0 else 30
    return out


def transfer(fracs_from: dict, g, est, trial, params) -> dict:
    """Formats chosen on one trial applied to another (a faster gait): what a fixed set of
    measured bounds does when the motion changes."""
    ref, _, _ = emulate(est, trial.inputs(), params, "float64", g=g)
    q, _, _ = emulate(est, trial.inputs(), params, "fixed", fracs=fracs_from, g=g)
    e = np.abs(q["te"] - ref["te"])[1:]
    return {"max_torque_error_nm": float(np.nanmax(e)) if np.isfinite(e).any() else None,
            "resets": int(q["resets"][-1, 0])}


def generator_attempt(g=None) -> str:
    """What the generator's fixed-point path says about the leg filter (its interval
    analysis), as one line."""
    from kinefuse.codegen.estimator import Interface
    from kinefuse.codegen.estimators.dynamics.leg import LegEKF
    from kinefuse.codegen.fixed import FixedPlan
    est = LegEKF()
    try:
        FixedPlan(g if g is not None else optimize(trace(est)), Interface(est).leaf_ranges(),
                  where=est.name)
    except ValueError as exc:          # RangeError
        return f"{type(exc).__name__}: {exc}"
    return "formats found"


def study(duration: float = 3.0, margins=(2.0, 16.0)) -> dict:
    """Torque deviation from float64 of the float32 emulation and of the oracle fixed point
    (formats from the observed ranges times each margin) on the leg trial, and of the same
    formats on a faster gait (1.4 Hz stride, other noise): a Q-format set measured on one
    motion is not safe on another."""
    from kinefuse.codegen.estimators.dynamics.leg import LegEKF
    from kinefuse.host.dynamics import truth as T
    cfg = T.LegConfig(duration=duration)
    tr = T.leg_trial(cfg)
    est = LegEKF()
    inp, prm = tr.inputs(), cfg.params()
    ref, node_max, g = emulate(est, inp, prm, "float64")
    f32, _, _ = emulate(est, inp, prm, "float32", g=g)
    k = min(int(round(cfg.rate_hz)), len(tr.t) // 2)     # after the first second
    fast = T.leg_trial(T.LegConfig(duration=duration, stride_hz=1.4, seed=1))
    pvals = [node_max[r.node.id] for r in g.results if r.kind == "state" and r.name == "P"
             and r.node.id in node_max]
    out = {"generator": generator_attempt(g), "samples": len(tr.t),
           "float32_emulation_max_torque_error_nm": float(np.abs(f32["te"] - ref["te"])[1:].max()),
           "float64_torque_rmse_vs_truth_nm": [
               float(np.sqrt(np.mean((ref["te"][k:, i] - tr.te[k:, i]) ** 2))) for i in range(2)],
           "P_entry_max_abs_range": [float(min(pvals)), float(max(pvals))] if pvals else None,
           "oracle_fixed_point": []}
    for margin in margins:
        fr = oracle_fracs(g, node_max, margin)
        q, _, _ = emulate(est, inp, prm, "fixed", fracs=fr, g=g)
        eq = np.abs(q["te"] - ref["te"])[1:]
        out["oracle_fixed_point"].append({
            "margin": margin, "fractional_bits_range": [min(fr.values()), max(fr.values())],
            "max_torque_error_nm": float(eq.max()) if np.isfinite(eq).all() else None,
            "torque_rmse_vs_truth_nm": [
                float(np.sqrt(np.mean((q["te"][k:, i] - tr.te[k:, i]) ** 2))) for i in range(2)],
            "resets": int(q["resets"][-1, 0]),
            "same_formats_on_a_faster_gait_1p4hz": transfer(fr, g, est, fast, prm)})
    return out


__all__ = ["emulate", "oracle_fracs", "study", "generator_attempt"]
