"""Generate the application's bindings to the generated filters (``firmware/app/*_gen.*``).

Inputs: ``firmware/app/kf_filter_list.h`` (one ``KF_FILTER_ENTRY(name, id, tag)`` line per wired
filter) and, for every listed filter and for ``calib_apply``, its generated Python models
(``firmware/generated/models/<name>_{f32,q}.py``: field layout, defaults, Q formats) plus the
estimator's declared parameter ranges.  Outputs:

* ``kf_filters_gen.h`` - state/params unions, the input record type of the build's number
  system, Q formats of the shared records;
* ``kf_filters_gen.c`` - per filter: build its parameter struct from float32 values (the q
  build converts with ``kf_q_from_f32``), init (the generated range check), live parameter
  change, update; the calibration binding; the direct float32 -> input record conversion;
* ``kf_params_gen.inc`` - the MAVLink parameter rows of calibration and filter parameters,
  then those of the joint-angle step (``joint_angle``, two-sensor mode, ``KF_JA_*``), then those
  of the wearable leg EKF (``leg``, two-sensor mode with ``KF_EFF_RATE_HZ`` != 0, ``KF_LEG_*``),
  then sensor 1's own calibration map (two-sensor mode: the ``calib_apply`` rows again as
  ``KF_ACC2_*``, ``KF_GYR2_*``, ``KF_MAG2_*``, same order, ranges and defaults).  Every group is
  appended after the existing ones, so the indices of the older rows do not move (storage keys
  are name hashes anyway, see ``kf_store.h``).

The joint-angle binding (two-sensor mode) converts the filters' quaternion outputs into the
joint step's input record: f32 builds pass the float32 values; q builds requantise the raw
filter output (every wired filter's ``q`` has the same format, checked here) to the joint
input format with one rounding shift (round half up, as the generated code rounds).

The leg EKF (``codegen/estimators/dynamics/leg.py``) is generated in float32 only: its binding
(``kf_gen_leg_init``, the type ``kf_leg_state``, ``KF_HAVE_LEG``) exists in f32 builds that do
not define ``KF_WITHOUT_LEG``; its parameter rows are in every build's table (as the rows of a
filter left out of a build), the application refuses to turn it on where it is not built.

    python -m kinefuse.firmware.build tables          # write
    python -m kinefuse.firmware.build tables --check  # exit 1 when stale (CI)
"""
from __future__ import annotations

import importlib
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError

FIRMWARE_DIR = Path(__file__).resolve().parent
APP_DIR = FIRMWARE_DIR / "app"
LIST_FILE = APP_DIR / "kf_filter_list.h"
SYSTEMS = ("f32", "q")
CALIB = "calib_apply"
JOINT = "joint_angle"          # two-sensor mode: the joint step (parameters KF_JA_*), its files
JOINT_ESTIMATOR = "joint-angle"   # ... and its registry name
JOINT_TAG = "JA"
LEG = "leg"                    # two-sensor mode: the wearable leg EKF (float32 only), KF_LEG_*
LEG_TAG = "LEG"
NAME_MAX = 16
RAW_MAX = 2 ** 31 - 1

# Readable short names where the automatic abbreviation would be cryptic (<= 10 characters).
SHORT_NAMES = {
    "min_angle_deg": "MIN_ANGLE", "slerp_threshold": "SLERP_TH", "rest_th_gyr": "REST_TH_G",
    "rest_th_acc": "REST_TH_A", "incl_rate_ref": "INCL_RATE", "incl_vel_ref": "INCL_VEL", "bias_sigma_init": "BIAS_SIG0", "bias_sigma_rest": "BIAS_SIG_R",
    "bias_forget_time": "BIAS_FORGT", "tau_mag_noise": "TAU_MAG_N", "mag_sigma_gate": "MAG_SIG_GT",
    "tau_mag_ref": "TAU_MAG_RF", "mag_new_time": "MAG_NEW_T", "mag_new_min_rate": "MAG_NEW_MR",
    "mag_reject_time": "MAG_REJ_T", "mag_min_undisturbed": "MAG_MIN_UD",
    "gyr_rate_err": "RATE_ERR", "init_sigma_att": "ATT_SIG0",
}
# calibration parameter prefixes: sensor -> MAVLink name part
CALIB_SENSORS = {"acc": "ACC", "gyr": "GYR", "mag": "MAG"}
# two-sensor mode: sensor 1's calibration map, KF_<S><suffix>_* (KF_ACC2_M00 ...)
CALIB2_SUFFIX = "2"


def calib_param_name(field: str, sensor: int = 0) -> str:
    """MAVLink name of calib_apply parameter ``field`` (e.g. ``acc_m01``) of sensor 0 (KF_ACC_M01)
    or sensor 1 (KF_ACC2_M01)."""
    tag = CALIB_SENSORS[field[:3]] + (CALIB2_SUFFIX if sensor else "")
    return f"KF_{tag}_" + field[4:].upper()
# optional filter outputs the application reports as KF_ORIENTATION status bits
OPTIONAL_OUTPUTS = ("rest", "mag_disturbed")
# optional attitude error covariance (rad^2, earth frame, xx xy xz yy yz zz): KF_ORIENTATION.cov
COV_OUTPUT = "cov_att"

_ENTRY = re.compile(r"^\s*KF_FILTER_ENTRY\(\s*(\w+)\s*,\s*(\d+)\s*,\s*(\w+)\s*\)", re.M)


@dataclass(frozen=True)
class Entry:
    name: str
    id: int
    tag: str


def read_list(path: Path = LIST_FILE) -> list[Entry]:
    entries = [Entry(m.group(1), int(m.group(2)), m.group(3)) for m in _ENTRY.finditer(path.read_text())]
    if not entries:
        raise KinefuseError(f"{path}: no KF_FILTER_ENTRY line")
    for key in ("name", "id", "tag"):
        vals = [getattr(e, key) for e in entries]
        dup = {v for v in vals if vals.count(v) > 1}
        if dup:
            raise KinefuseError(f"{path.name}: duplicate filter {key} {sorted(dup)[0]}")
    for e in entries:
        if not 1 <= e.id <= 255:
            raise KinefuseError(f"{path.name}: filter id {e.id} of {e.name} outside 1..255")
        if not re.fullmatch(r"[A-Z0-9]{1,3}", e.tag):
            raise KinefuseError(f"{path.name}: tag {e.tag!r} of {e.name}: 1-3 capitals/digits")
    return entries


def abbreviate(name: str, width: int) -> str:
    """Upper-case ``name`` shortened to ``width`` characters (longest word trimmed first)."""
    if name in SHORT_NAMES and len(SHORT_NAMES[name]) <= width:
        return SHORT_NAMES[name]
    words = name.upper().split("_")
    while len("_".join(words)) > width:
        i = max(range(len(words)), key=lambda k: (len(words[k]), k))
        if len(words[i]) <= 1:
            break
        words[i] = words[i][:-1]
    out = "_".join(words)
    return out[:width]


def _model(name: str, system: str):
    try:
        return importlib.import_module(f"kinefuse.firmware.generated.models.{name}_{system}")
    except ModuleNotFoundError:
        raise KinefuseError(f"no generated model {name}_{system}: run `kinefuse codegen` "
                            f"(or remove {name} from {LIST_FILE.name})") from None


def _estimator(name: str):
    from kinefuse.codegen import estimators
    try:
        return estimators.get(name)
    except ValueError as exc:
        raise KinefuseError(str(exc)) from None


def _f32(v: float) -> str:
    f = float(np.float32(v))
    if not np.isfinite(f):
        raise KinefuseError(f"non-finite constant {v}")
    if f == 0.0:
        return "-0.0f" if np.signbit(f) else "0.0f"
    return _hex(f) + "f"


def _hex(x: float) -> str:
    """C99 hex float without trailing zero digits (0x1.8p+1)."""
    h = float.hex(x)
    m, e = h.split("p")
    m = m.rstrip("0").rstrip(".")
    return f"{m}p{e}"


def _c_str(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


@dataclass
class FilterInfo:
    entry: Entry
    params: list            # Param objects (declaration order = struct order)
    names: list[str]        # MAVLink names
    q_frac: dict[str, tuple]  # param -> (fractional bits, raw lo, raw hi) (q model)
    out_q_frac: int         # fractional bits of output q (q model)
    optional: tuple[str, ...]
    has_rejected: bool
    cov_frac: int | None     # q model: fractional bits of cov_att; None: no covariance output
    has_cov: bool


def _param_names(prefix: str, params) -> list[str]:
    width = NAME_MAX - len(prefix)
    names = [prefix + abbreviate(p.name, width) for p in params]
    seen: dict[str, int] = {}
    out = []
    for n in names:       # a clash (after abbreviation) gets a digit
        k = seen.get(n, 0)
        seen[n] = k + 1
        out.append(n if k == 0 else n[:NAME_MAX - 1] + str(k))
    if len(set(out)) != len(out):
        raise KinefuseError(f"parameter names of {prefix} clash after abbreviation")
    return out


def collect(entries: list[Entry]) -> tuple[list[FilterInfo], dict]:
    filters = []
    imu_formats = None
    for e in entries:
        est = _estimator(e.name)
        if est.inputs.name != "imu":
            raise KinefuseError(f"{e.name} is not an IMU filter (input record {est.inputs.name!r})")
        mf, mq = _model(e.name, "f32"), _model(e.name, "q")
        for m in (mf, mq):
            got = [p[0] for p in m.FIELDS["param"]]
            if got != [p.name for p in est.params]:
                raise KinefuseError(f"model {m.__name__} is stale (parameters differ from "
                                    f"{e.name}.py): run `kinefuse codegen`")
        outs = {o[0]: o for o in mf.FIELDS["output"]}
        if "q" not in outs or outs["q"][1:] != (4, "real"):
            raise KinefuseError(f"{e.name} has no output q[4]")
        fmts = {k: v for k, v in mq.FORMATS.items() if k.startswith("input.")}
        if imu_formats is None:
            imu_formats = fmts
        elif fmts != imu_formats:
            raise KinefuseError(f"{e.name}: IMU input formats differ from the other filters'")
        optional = tuple(o for o in OPTIONAL_OUTPUTS if o in outs and outs[o][1:] == (1, "bool"))
        has_cov = COV_OUTPUT in outs and outs[COV_OUTPUT][1:] == (6, "real")
        filters.append(FilterInfo(
            e, list(est.params), _param_names(f"KF_{e.tag}_", est.params),
            {p.name: tuple(mq.FORMATS[f"param.{p.name}"]) for p in est.params},
            mq.FORMATS["output.q"][0], optional,
            "rejected" in outs and outs["rejected"][1:] == (1, "int"),
            mq.FORMATS[f"output.{COV_OUTPUT}"][0] if has_cov else None, has_cov))
    # calibration: its outputs must be in exactly the formats of the filters' input record
    cf, cq = _model(CALIB, "f32"), _model(CALIB, "q")
    for fld in ("gyr", "acc", "mag", "dt"):
        if cq.FORMATS[f"output.{fld}"][0] != imu_formats[f"input.{fld}"][0]:
            raise KinefuseError(f"{CALIB} output {fld} is Q..{cq.FORMATS[f'output.{fld}'][0]} but the "
                                f"filters read Q..{imu_formats[f'input.{fld}'][0]}: fix the declared ranges")
    cal = _estimator(CALIB)
    calib = {"params": list(cal.params), "q_frac": {p.name: tuple(cq.FORMATS[f"param.{p.name}"]) for p in cal.params},
             "names": [calib_param_name(p.name) for p in cal.params],
             "names2": [calib_param_name(p.name, 1) for p in cal.params],
             "in_frac": {k.split(".")[1]: v[0] for k, v in cq.FORMATS.items() if k.startswith("input.")},
             "imu_frac": {k.split(".")[1]: v[0] for k, v in imu_formats.items()}}
    for n in calib["names"] + calib["names2"]:
        if len(n) > NAME_MAX:
            raise KinefuseError(f"calibration parameter name {n} is longer than {NAME_MAX}")
    calib["joint"] = _collect_joint(filters)
    calib["leg"] = _collect_leg()
    return filters, calib


def _collect_leg() -> dict:
    """The leg EKF's parameters (stored in the calib dict's "leg"); float32 model only."""
    est = _estimator(LEG)
    m = _model(LEG, "f32")
    if [p[0] for p in m.FIELDS["param"]] != [p.name for p in est.params]:
        raise KinefuseError(f"model {m.__name__} is stale (parameters differ from {LEG}.py): run `kinefuse codegen`")
    if "q" in getattr(est, "systems", ("f32", "q")):
        raise KinefuseError(f"{LEG} is generated in fixed point too: its binding assumes float32 only")
    outs = {o[0]: o[1:] for o in m.FIELDS["output"]}
    for name, shape in (("te", (2, "real")), ("te_std", (2, "real")), ("initialised", (1, "bool"))):
        if outs.get(name) != shape:
            raise KinefuseError(f"{LEG}: output {name} is not {shape} (the application reads it)")
    return {"params": list(est.params), "names": _param_names(f"KF_{LEG_TAG}_", est.params)}


def _collect_joint(filters: list[FilterInfo]) -> dict:
    """The joint-angle step's parameters and formats (stored in the calib dict's "joint")."""
    est = _estimator(JOINT_ESTIMATOR)
    jf, jq = _model(JOINT, "f32"), _model(JOINT, "q")
    for m in (jf, jq):
        if [p[0] for p in m.FIELDS["param"]] != [p.name for p in est.params]:
            raise KinefuseError(f"model {m.__name__} is stale (parameters differ from {JOINT}.py): "
                                f"run `kinefuse codegen`")
    qout = {f.out_q_frac for f in filters}
    if len(qout) != 1:
        raise KinefuseError(f"the wired filters output q in different formats {sorted(qout)}: the "
                            f"joint-angle binding needs one")
    fin = {jq.FORMATS["input.q_prox"][0], jq.FORMATS["input.q_dist"][0]}
    if len(fin) != 1:
        raise KinefuseError(f"{JOINT}: q_prox and q_dist have different formats")
    return {"params": list(est.params), "names": _param_names(f"KF_{JOINT_TAG}_", est.params),
            "q_frac": {p.name: tuple(jq.FORMATS[f"param.{p.name}"]) for p in est.params},
            "qout_frac": qout.pop(), "in_frac": fin.pop(), "in_range": tuple(jq.FORMATS["input.q_prox"][1:]),
            "angles_frac": jq.FORMATS["output.angles"][0], "qj_frac": jq.FORMATS["output.q_joint"][0]}


# ---------------------------------------------------------------------------------- rendering

HEAD = ("/*\n * {file} - {what}\n *\n * Generated by `python -m kinefuse.firmware.build tables` from "
        "kf_filter_list.h and the\n * generated filters' models (firmware/generated/models) - do not edit.\n */\n")


def render_header(filters: list[FilterInfo], calib: dict) -> str:
    L = [HEAD.format(file="kf_filters_gen.h", what="types of the filters wired into the application."),
         "#ifndef KF_FILTERS_GEN_H", "#define KF_FILTERS_GEN_H", "", "#include <stdint.h>", "",
         f"#define KF_GEN_FILTER_COUNT {len(filters)}",
         f"#define KF_GEN_CALIB_PARAM_COUNT {len(calib['params'])}",
         f"#define KF_GEN_FILTER_PARAM_COUNT {sum(len(f.params) for f in filters)}",
         f"#define KF_GEN_FILTER_PARAM_MAX {max(len(f.params) for f in filters)}", ""]
    L += ["/* A build may leave filters out with -DKF_WITHOUT_<NAME> (e.g. KF_WITHOUT_GUO): their rows",
          " * stay in the tables (parameters keep their names and values) with no functions. */", ""]
    L += ["/* Fixed-point formats (fractional bits) of the shared IMU input record (q builds) and of",
          " * the calibration inputs (integer counts and microseconds, exact). */"]
    for k in ("gyr", "acc", "mag", "dt"):
        L.append(f"#define KF_GEN_FRAC_{k.upper()} {calib['imu_frac'][k]}")
    J = calib["joint"]
    L.append(f"#define KF_GEN_FRAC_COUNTS {calib['in_frac']['acc_raw']}")
    L.append(f"#define KF_GEN_FRAC_QOUT {J['qout_frac']}      /* every filter's output q */")
    L.append(f"#define KF_GEN_FRAC_JOINT_Q {J['in_frac']}   /* joint-angle inputs q_prox, q_dist */")
    L.append(f"#define KF_GEN_FRAC_JOINT_ANGLES {J['angles_frac']}")
    L.append(f"#define KF_GEN_JOINT_PARAM_COUNT {len(J['params'])}")
    L.append(f"#define KF_GEN_JOINT_P_SEQUENCE {[p.name for p in J['params']].index('sequence')}"
             f"   /* index of KF_JA_SEQUENCE */")
    jn = [p.name for p in J["params"]]
    off = jn.index("prox_w")
    if jn[off:off + 8] != [f"{s}_{c}" for s in ("prox", "dist") for c in "wxyz"]:
        raise KinefuseError(f"{JOINT}: the offsets prox_w..z, dist_w..z are not consecutive parameters")
    L.append(f"#define KF_GEN_JOINT_P_OFFSETS {off}   /* index of KF_JA_PROX_W (then PROX_X..Z, DIST_W..Z) */")
    L.append(f"#define KF_GEN_FRAC_DT_US {calib['in_frac']['dt_us']}")
    L.append(f"#define KF_GEN_LEG_PARAM_COUNT {len(calib['leg']['params'])}   /* KF_LEG_*, in every build's table */")
    L.append(f"#define KF_GEN_CALIB2_PARAM_COUNT {len(calib['names2'])}   /* sensor 1's map (KF_ACC2_* ...), "
             f"the calibration rows again */")
    for k in ("gyr_raw", "mag_raw"):
        if calib["in_frac"][k] != calib["in_frac"]["acc_raw"]:
            raise KinefuseError("calibration count inputs have different formats")
    L.append("")
    for sysname, cond in (("q", "#if KF_NUMERIC_Q"), ("f32", "#else")):
        L.append(cond)
        L.append(f'#include "kf_imu_{sysname}.h"')
        L.append(f'#include "{CALIB}_{sysname}.h"')
        for f in filters:
            L += [_guard(f), f'#include "{f.entry.name}_{sysname}.h"', "#endif"]
        L.append(f"typedef kf_imu_input_{sysname} kf_imu_input;")
        L.append(f"typedef kf_calib_input_{sysname} kf_calib_input;")
        L.append(f"typedef {CALIB}_{sysname}_state kf_calib_state;")
        L.append(f"typedef {CALIB}_{sysname}_params kf_calib_params;")
        L.append(f'#include "{JOINT}_{sysname}.h"')
        L.append(f"typedef {JOINT}_{sysname}_state kf_joint_state;")
        if sysname == "f32":
            L += ["/* the leg EKF (two-sensor mode, KF_EFFORTS): float32 builds only, unless KF_WITHOUT_LEG */",
                  "#ifndef KF_WITHOUT_LEG", "#define KF_HAVE_LEG 1", f'#include "{LEG}_f32.h"',
                  f"typedef {LEG}_f32_state kf_leg_state;", f"typedef {LEG}_f32_output kf_leg_output;",
                  f"typedef kf_leg_input_f32 kf_leg_input;", "#endif"]
        for what in ("state", "params"):
            L.append("typedef union {")
            L.append("    uint8_t none;   /* every filter may be left out of a build */")
            for f in filters:
                L += [_guard(f), f"    {f.entry.name}_{sysname}_{what} {f.entry.name};", "#endif"]
            L.append(f"}} kf_filter_{what}_u;")
    L += ["#endif", "", "#ifndef KF_HAVE_LEG", "#define KF_HAVE_LEG 0   /* fixed-point build, or KF_WITHOUT_LEG */",
          "#endif", "", "#endif /* KF_FILTERS_GEN_H */", ""]
    return "\n".join(L)


def _conv(system: str, value: str, fmt: tuple) -> str:
    """float32 value -> the number system's parameter value.  q: round half away from zero and
    saturate to the parameter's declared raw range (the application has already checked the
    float32 value against the float32-rounded range, which may lie one raw step outside)."""
    if system == "f32":
        return value
    frac, lo, hi = fmt
    return f"q_param({value}, {frac}, {_i32(lo)}, {_i32(hi)})"


def _i32(v: int) -> str:
    return "(-2147483647 - 1)" if v == -2 ** 31 else str(v)


def _guard(f: FilterInfo) -> str:
    return f"#ifndef KF_WITHOUT_{f.entry.name.upper()}"


def render_source(filters: list[FilterInfo], calib: dict) -> str:
    L = [HEAD.format(file="kf_filters_gen.c", what="bindings of the generated filters and the calibration map."),
         '#include <stddef.h>', '#include <stdint.h>', "", '#include "kf_filters.h"', '#include "kf_fixed.h"', ""]
    for sysname, cond in (("q", "#if KF_NUMERIC_Q"), ("f32", "#else")):
        L.append(cond)
        L.append("")
        if sysname == "q":
            L += ["/* one out-of-line conversion instead of an inlined one per parameter (flash) */",
                  "#ifdef __GNUC__", "__attribute__((noinline))", "#endif",
                  "static int32_t q_param(float v, int32_t f, int32_t lo, int32_t hi)", "{",
                  "    return kf_q_from_f32(v, f, lo, hi);", "}", ""]
        for f in filters:
            n = f.entry.name
            P = f"{n}_{sysname}"
            L.append(_guard(f))
            L.append(f"/* {n}: {len(f.params)} parameters ({', '.join(f.names)}) */")
            L.append(f"static void {n}_build(const float *v, void *params)")
            L.append("{")
            L.append(f"    {P}_params *p = ({P}_params *)params;")
            L.append(f"    {P}_default_params(p);")
            for i, p in enumerate(f.params):
                L.append(f"    p->{p.name} = {_conv(sysname, f'v[{i}]', f.q_frac[p.name])};")
            if not f.params:
                L.append("    (void)v;")
            L.append("}")
            L.append(f"static int {n}_init(void *state, const void *params)")
            L.append("{")
            L.append(f"    return {P}_init(({P}_state *)state, (const {P}_params *)params);")
            L.append("}")
            L.append(f"static void {n}_set(void *state, const void *params)")
            L.append("{")
            L.append(f"    (({P}_state *)state)->params = *(const {P}_params *)params;")
            L.append("}")
            L.append(f"static void {n}_update(void *state, const kf_imu_input *in, kf_filter_out *o)")
            L.append("{")
            L.append(f"    {P}_output out;")
            L.append(f"    {P}_update(({P}_state *)state, in, &out);")
            L.append("    for (int i = 0; i < 4; i++) {")
            if sysname == "f32":
                L.append("        o->q[i] = out.q[i];")
                L.append("        o->q_raw[i] = 0;")
            else:
                L.append(f"        o->q[i] = (float)out.q[i] * {_hex(2.0 ** -f.out_q_frac)}f;  /* exact scaling */")
                L.append("        o->q_raw[i] = out.q[i];")
            L.append("    }")
            L.append(f"    o->rejected = {'out.rejected' if f.has_rejected else '0'};")
            for opt in OPTIONAL_OUTPUTS:
                L.append(f"    o->{opt} = {'out.' + opt if opt in f.optional else '0u'};")
            if f.has_cov:
                L.append("    for (int i = 0; i < 6; i++) {")
                if sysname == "f32":
                    L.append(f"        o->cov[i] = out.{COV_OUTPUT}[i];")
                else:
                    L.append(f"        o->cov[i] = (float)out.{COV_OUTPUT}[i] * {_hex(2.0 ** -f.cov_frac)}f;")
                L.append("    }")
            L.append(f"    o->has_cov = {'1u' if f.has_cov else '0u'};")
            L.append("}")
            L.append("#endif")
            L.append("")
        L.append(f"const kf_filter_ops kf_gen_filters[KF_GEN_FILTER_COUNT] = {{")
        first = 0
        for f in filters:
            n = f.entry.name
            L.append(_guard(f))
            L.append(f"    {{{_c_str(n)}, {f.entry.id}u, {first}u, {len(f.params)}u, "
                     f"{n}_build, {n}_init, {n}_set, {n}_update}},")
            L.append("#else")
            L.append(f"    {{{_c_str(n)}, {f.entry.id}u, {first}u, {len(f.params)}u, NULL, NULL, NULL, NULL}},")
            L.append("#endif")
            first += len(f.params)
        L.append("};")
        L.append("")
        P = f"{CALIB}_{sysname}"
        L.append("int kf_gen_calib_init(kf_calib_state *s, const float *v)")
        L.append("{")
        L.append(f"    {P}_params p;")
        L.append(f"    {P}_default_params(&p);")
        for i, p in enumerate(calib["params"]):
            L.append(f"    p.{p.name} = {_conv(sysname, f'v[{i}]', calib['q_frac'][p.name])};")
        L.append(f"    return {P}_init(s, &p);")
        L.append("}")
        L.append("")
        L.append("void kf_gen_calib_apply(kf_calib_state *s, const int16_t acc[3], const int16_t gyr[3],")
        L.append("                        const int16_t mag[3], uint32_t dt_us, kf_imu_input *out)")
        L.append("{")
        L.append(f"    kf_calib_input_{sysname} in;")
        L.append(f"    {P}_output o;")
        L.append("    for (int i = 0; i < 3; i++) {")
        if sysname == "f32":
            L.append("        in.acc_raw[i] = (float)acc[i];   /* exact: |counts| < 2^24 */")
            L.append("        in.gyr_raw[i] = (float)gyr[i];")
            L.append("        in.mag_raw[i] = (float)mag[i];")
        else:
            L.append("        in.acc_raw[i] = (int32_t)acc[i] * ((int32_t)1 << KF_GEN_FRAC_COUNTS);   /* exact */")
            L.append("        in.gyr_raw[i] = (int32_t)gyr[i] * ((int32_t)1 << KF_GEN_FRAC_COUNTS);")
            L.append("        in.mag_raw[i] = (int32_t)mag[i] * ((int32_t)1 << KF_GEN_FRAC_COUNTS);")
        L.append("    }")
        L.append("    if (dt_us > 1000000u) {")
        L.append("        dt_us = 1000000u;   /* the declared input range: the map clamps there too */")
        L.append("    }")
        if sysname == "f32":
            L.append("    in.dt_us = (float)dt_us;   /* exact below 2^24 */")
        else:
            L.append("    in.dt_us = (int32_t)dt_us * ((int32_t)1 << KF_GEN_FRAC_DT_US);   /* <= 1e6 * 2^10: fits */")
        L.append(f"    {P}_update(s, &in, &o);")
        L.append("    for (int i = 0; i < 3; i++) {   /* same formats as the filters' input record */")
        L.append("        out->gyr[i] = o.gyr[i];")
        L.append("        out->acc[i] = o.acc[i];")
        L.append("        out->mag[i] = o.mag[i];")
        L.append("    }")
        L.append("    out->dt = o.dt;")
        L.append("}")
        L.append("")
        L.append("void kf_gen_imu_from_f32(const float gyr[3], const float acc[3], const float mag[3], float dt,")
        L.append("                         kf_imu_input *out)")
        L.append("{")
        L.append("    for (int i = 0; i < 3; i++) {")
        for k in ("gyr", "acc", "mag"):
            if sysname == "f32":
                L.append(f"        out->{k}[i] = {k}[i];")
            else:
                L.append(f"        out->{k}[i] = kf_q_from_f32({k}[i], KF_GEN_FRAC_{k.upper()}, -2147483647, 2147483647);")
        L.append("    }")
        L.append("    out->dt = " + ("dt;" if sysname == "f32" else
                                    "kf_q_from_f32(dt, KF_GEN_FRAC_DT, -2147483647, 2147483647);"))
        L.append("}")
        L.append("")
        L += _render_joint(sysname, calib["joint"])
        if sysname == "f32":
            L += _render_leg(calib["leg"])
    L += ["#endif", ""]
    return "\n".join(L)


def _render_joint(sysname: str, J: dict) -> list[str]:
    """kf_gen_joint_init / kf_gen_joint_update (two-sensor mode)."""
    P = f"{JOINT}_{sysname}"
    L = ["int kf_gen_joint_init(kf_joint_state *s, const float *v)", "{",
         f"    {P}_params p;", f"    {P}_default_params(&p);"]
    for i, p in enumerate(J["params"]):
        L.append(f"    p.{p.name} = {_conv(sysname, f'v[{i}]', J['q_frac'][p.name])};")
    L += [f"    return {P}_init(s, &p);", "}", "",
          "void kf_gen_joint_update(kf_joint_state *s, const kf_filter_out *prox, const kf_filter_out *dist,",
          "                         kf_joint_out *out)", "{",
          f"    kf_joint_input_{sysname} in;", f"    {P}_output o;", "    for (int i = 0; i < 4; i++) {"]
    if sysname == "f32":
        L += ["        in.q_prox[i] = prox->q[i];", "        in.q_dist[i] = dist->q[i];"]
    else:
        d = J["qout_frac"] - J["in_frac"]
        lo, hi = (_i32(v) for v in J["in_range"])
        for side in ("prox", "dist"):
            if d > 0:
                L.append(f"        in.q_{side}[i] = (int32_t)(((int64_t){side}->q_raw[i] + ((int64_t)1 << {d - 1})) >> {d});"
                         f"   /* Q..{J['qout_frac']} -> Q..{J['in_frac']}, round half up */")
            elif d < 0:
                L.append(f"        in.q_{side}[i] = kf_lsh_sat({side}->q_raw[i], {-d}, {lo}, {hi});")
            else:
                L.append(f"        in.q_{side}[i] = {side}->q_raw[i];")
    L += ["    }", f"    {P}_update(s, &in, &o);", "    for (int i = 0; i < 3; i++) {"]
    if sysname == "f32":
        L.append("        out->angles[i] = o.angles[i];")
    else:
        L.append(f"        out->angles[i] = (float)o.angles[i] * {_hex(2.0 ** -J['angles_frac'])}f;  /* exact scaling */")
    L += ["    }", "    for (int i = 0; i < 4; i++) {"]
    if sysname == "f32":
        L.append("        out->q[i] = o.q_joint[i];")
    else:
        L.append(f"        out->q[i] = (float)o.q_joint[i] * {_hex(2.0 ** -J['qj_frac'])}f;")
    L += ["    }", "    out->valid = o.valid;", "    out->rejected = o.rejected;", "}", ""]
    return L


def _render_leg(G: dict) -> list[str]:
    """kf_gen_leg_init (f32 builds with the leg EKF)."""
    P = f"{LEG}_f32"
    L = ["#if KF_HAVE_LEG", "int kf_gen_leg_init(kf_leg_state *s, const float *v)", "{",
         f"    {P}_params p;", f"    {P}_default_params(&p);"]
    for i, p in enumerate(G["params"]):
        L.append(f"    p.{p.name} = v[{i}];")
    L += [f"    return {P}_init(s, &p);", "}", "#endif", ""]
    return L


def _row(p) -> str:
    """KF_PARAM_ROW, or KF_CHOICE_ROW for a parameter declared with choices (a switch such as
    flagship.mode: only the whole numbers min..max are accepted, ``Param.choices``)."""
    if not p.choices:
        return "KF_PARAM_ROW"
    if tuple(p.choices) != tuple(float(v) for v in range(int(p.lo), int(p.hi) + 1)):
        raise KinefuseError(f"parameter {p.name}: the unit's table holds choices as the whole "
                            f"numbers min..max only, got {p.choices}")
    return "KF_CHOICE_ROW"


def render_params(filters: list[FilterInfo], calib: dict) -> str:
    L = ["/*", " * kf_params_gen.inc - MAVLink parameter rows of the calibration and of every wired filter,",
         " * the joint step, the leg EKF, then sensor 1's calibration (two-sensor mode):",
         " * KF_PARAM_ROW(name, group, filter, index, default, min, max), all REAL32;",
         " * KF_CHOICE_ROW(...) the same for a choice (a switch): only the whole numbers min..max.",
         " *", " * Generated by `python -m kinefuse.firmware.build tables` - do not edit.", " */"]
    for i, (p, n) in enumerate(zip(calib["params"], calib["names"])):
        L.append(f"{_row(p)}({_c_str(n)}, KF_PG_CALIB, 0u, {i}u, {_f32(p.default)}, {_f32(p.lo)}, "
                 f"{_f32(p.hi)})  /* {p.name} [{p.unit or '-'}] */")
    for k, f in enumerate(filters):
        for i, (p, n) in enumerate(zip(f.params, f.names)):
            L.append(f"{_row(p)}({_c_str(n)}, KF_PG_FILTER, {k}u, {i}u, {_f32(p.default)}, {_f32(p.lo)}, "
                     f"{_f32(p.hi)})  /* {f.entry.name}.{p.name} [{p.unit or '-'}] */")
    J = calib["joint"]
    for i, (p, n) in enumerate(zip(J["params"], J["names"])):
        L.append(f"{_row(p)}({_c_str(n)}, KF_PG_JOINT, 0u, {i}u, {_f32(p.default)}, {_f32(p.lo)}, "
                 f"{_f32(p.hi)})  /* {JOINT}.{p.name} [{p.unit or '-'}] */")
    G = calib["leg"]
    for i, (p, n) in enumerate(zip(G["params"], G["names"])):
        L.append(f"{_row(p)}({_c_str(n)}, KF_PG_LEG, 0u, {i}u, {_f32(p.default)}, {_f32(p.lo)}, "
                 f"{_f32(p.hi)})  /* {LEG}.{p.name} [{p.unit or '-'}] */")
    for i, (p, n) in enumerate(zip(calib["params"], calib["names2"])):
        L.append(f"{_row(p)}({_c_str(n)}, KF_PG_CALIB2, 0u, {i}u, {_f32(p.default)}, {_f32(p.lo)}, "
                 f"{_f32(p.hi)})  /* sensor 1: {p.name} [{p.unit or '-'}] */")
    return "\n".join(L) + "\n"


def render_all() -> dict[str, str]:
    filters, calib = collect(read_list())
    return {"kf_filters_gen.h": render_header(filters, calib),
            "kf_filters_gen.c": render_source(filters, calib),
            "kf_params_gen.inc": render_params(filters, calib)}


def parameter_table() -> list[dict]:
    """Every generated parameter in table order (calibration, filters, joint step, leg EKF, sensor
    1's calibration with ``"sensor": 1``): name, owner, field, default, range, unit, doc (the
    estimator's), choices (empty: any value in the range; else a switch, exactly these values)."""
    filters, calib = collect(read_list())

    def rows_of(owner, params, names, **extra):
        return [{"name": n, "owner": owner, "field": p.name, "default": p.default, "min": p.lo,
                 "max": p.hi, "unit": p.unit, "doc": p.doc, "choices": tuple(p.choices), **extra}
                for p, n in zip(params, names)]

    rows = rows_of(CALIB, calib["params"], calib["names"])
    for f in filters:
        rows += rows_of(f.entry.name, f.params, f.names)
    rows += rows_of(JOINT, calib["joint"]["params"], calib["joint"]["names"])
    rows += rows_of(LEG, calib["leg"]["params"], calib["leg"]["names"])
    rows += rows_of(CALIB, calib["params"], calib["names2"], sensor=1)
    return rows


def app_parameters(app_dir: Path = APP_DIR) -> dict[str, dict]:
    """The application's own parameters (KF_RATE_HZ, ...): MAVLink name -> default, min, max
    (from the ``KF_APP_ROW`` lines of ``kf_params.c``) and meaning (the comments of the
    ``KF_P_*`` enum in ``kf_params.h``), read from the C where they are written."""
    text = (app_dir / "kf_params.h").read_text()
    body = text[text.index("enum {", text.index("Application parameters")):]
    body = body[:body.index("KF_P_APP_COUNT")]
    docs = {"KF_" + m.group(1): " ".join(w for w in m.group(2).split() if w != "*")
            for m in re.finditer(r"KF_P_(\w+),\s*/\*(.*?)\*/", body, re.S)}
    out = {}
    row = re.compile(r'KF_APP_ROW\("(\w+)",\s*KF_PT_\w+,\s*(\w+),\s*(\w+),\s*(\w+),')
    for m in row.finditer((app_dir / "kf_params.c").read_text()):
        default, lo, hi = (int(v.rstrip("uU"), 0) for v in m.group(2, 3, 4))
        out[m.group(1)] = {"default": default, "min": lo, "max": hi, "doc": docs.get(m.group(1), "")}
    return out


def write(out_dir: Path = APP_DIR) -> list[str]:
    written = []
    for rel, text in render_all().items():
        p = out_dir / rel
        if not p.exists() or p.read_text() != text:
            p.write_text(text)
            written.append(rel)
    return written


def check(out_dir: Path = APP_DIR) -> list[str]:
    return [rel for rel, text in render_all().items()
            if not (out_dir / rel).exists() or (out_dir / rel).read_text() != text]
