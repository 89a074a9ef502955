"""The kinefuse MAVLink dialect: id allocation, generated output freshness, C <-> Python frames."""
from __future__ import annotations

import os
import shutil
import struct
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from kinefuse.host.link import regen
from kinefuse.host.link.codec import Encoder
from kinefuse.host.link.decoder import decode_bytes
from kinefuse.host.link.dialect import dialect_hash, module
from kinefuse.host.link.spec import kinefuse_dialect

XML = regen.XML
GENERATED = regen.C_OUT
BLOCK = range(52500, 52550)


def _own_ids():
    root = ET.parse(XML).getroot()
    msgs = {int(m.get("id")): m.get("name") for m in root.iter("message")}
    cmds = {int(e.get("value")): e.get("name")
            for en in root.iter("enum") if en.get("name") == "MAV_CMD" for e in en.iter("entry")}
    return msgs, cmds


def _all_xml_ids():
    """Message and MAV_CMD ids of every dialect pymavlink's all.xml includes (parsed from XML)."""
    import pymavlink
    base = Path(pymavlink.__file__).parent / "dialects" / "v20"
    seen, todo = set(), ["all.xml"]
    msgs, cmds = {}, {}
    while todo:
        name = todo.pop()
        if name in seen or not (base / name).exists():
            continue
        seen.add(name)
        root = ET.parse(base / name).getroot()
        todo += [inc.text.strip() for inc in root.iter("include")]
        for m in root.iter("message"):
            msgs[int(m.get("id"))] = (m.get("name"), name)
        for en in root.iter("enum"):
            if en.get("name") == "MAV_CMD":
                for e in en.iter("entry"):
                    cmds[int(e.get("value"))] = (e.get("name"), name)
    assert "icarous.xml" in seen and "common.xml" in seen  # the walk really covered all.xml
    return msgs, cmds


def test_ids_are_in_our_block_and_free_in_all_xml():
    own_msgs, own_cmds = _own_ids()
    all_msgs, all_cmds = _all_xml_ids()
    assert set(own_msgs) == {52500, 52501, 52502, 52503, 52504}
    assert own_msgs and own_cmds
    for mid, name in own_msgs.items():
        assert mid in BLOCK, name
        assert mid not in all_msgs, f"{name} collides with {all_msgs.get(mid)}"
    for cid, name in own_cmds.items():
        assert cid in BLOCK, name
        assert cid not in all_cmds, f"{name} collides with {all_cmds.get(cid)}"
    # the range named free by all.xml is really unused by upstream dialects
    assert not any(52100 <= i < 60000 for i in all_msgs)


def test_included_xml_are_pymavlink_copies():
    import pymavlink
    base = Path(pymavlink.__file__).parent / "dialects" / "v20"
    for name in ("common.xml", "standard.xml", "minimal.xml"):
        assert (XML.parent / name).read_bytes() == (base / name).read_bytes(), name


def test_generated_output_is_up_to_date():
    assert regen.check() == []


def test_dialect_hash_matches_c_header():
    text = (GENERATED / "kf_dialect.h").read_text()
    value = int(text.split("#define KF_DIALECT_HASH 0x")[1].split("UL")[0], 16)
    assert value == dialect_hash(module())
    assert f'"kinefuse dialect {value:08X}"' in (GENERATED / "kinefuse" / "version.h").read_text()


def test_generated_module_knows_our_messages():
    d = kinefuse_dialect()
    for name, size in [("KF_RAW_SAMPLE", 35), ("KF_ORIENTATION", 61), ("KF_JOINT_ANGLE", 29),
                       ("KF_EFFORTS", 111), ("KF_UNIT_STATUS", 95)]:   # 83 + 12 bytes of extensions
        assert d[name].length == size, name
    m = module()
    assert m.MAV_CMD_KF_STREAM == 52500 and m.MAV_CMD_KF_HEADING_TARE == 52501
    assert d["KF_RAW_SAMPLE"].units["gyro_x"] == "mrad/s"


# ------------------------------------------------------------------------------------ C side
gcc = shutil.which("gcc")
needs_gcc = pytest.mark.skipif(gcc is None, reason="gcc not installed")

C_PROGRAM = r"""
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <inttypes.h>
#include "kinefuse/mavlink.h"
#include "kf_dialect.h"

/* pack: argv = p sysid compid time_boot_us sample_counter acc_x .. temperature unit_id flags
                 gyro_shift
   pack_orientation: argv = o sysid compid time_boot_us counter qw qx qy qz rejected status
                             frame filter unit cov0..cov5   (floats in hex bit patterns)
   parse: bytes on stdin, one line per decoded KF_RAW_SAMPLE / KF_ORIENTATION */
static uint32_t u32(const char *s) { return (uint32_t)strtoul(s, NULL, 0); }
static float f32(const char *s) { uint32_t b = u32(s); float f; memcpy(&f, &b, 4); return f; }
static uint32_t bits(float f) { uint32_t b; memcpy(&b, &f, 4); return b; }

int main(int argc, char **argv)
{
    mavlink_message_t msg;
    uint8_t buf[MAVLINK_MAX_PACKET_LEN];
    if (argc > 1 && argv[1][0] == 'p' && argc == 19) {
        mavlink_msg_kf_raw_sample_pack((uint8_t)u32(argv[2]), (uint8_t)u32(argv[3]), &msg,
            strtoull(argv[4], NULL, 0), u32(argv[5]),
            (int16_t)atoi(argv[6]), (int16_t)atoi(argv[7]), (int16_t)atoi(argv[8]),
            (int16_t)atoi(argv[9]), (int16_t)atoi(argv[10]), (int16_t)atoi(argv[11]),
            (int16_t)atoi(argv[12]), (int16_t)atoi(argv[13]), (int16_t)atoi(argv[14]),
            (int16_t)atoi(argv[15]), (uint8_t)u32(argv[16]), (uint8_t)u32(argv[17]),
            (uint8_t)u32(argv[18]));
    } else if (argc > 1 && argv[1][0] == 'o' && argc == 21) {
        float cov[6];
        int k;
        for (k = 0; k < 6; k++) cov[k] = f32(argv[15 + k]);
        mavlink_msg_kf_orientation_pack((uint8_t)u32(argv[2]), (uint8_t)u32(argv[3]), &msg,
            strtoull(argv[4], NULL, 0), u32(argv[5]), f32(argv[6]), f32(argv[7]), f32(argv[8]),
            f32(argv[9]), u32(argv[10]), (uint16_t)u32(argv[11]), (uint8_t)u32(argv[12]),
            (uint8_t)u32(argv[13]), (uint8_t)u32(argv[14]), cov);
    } else if (argc > 1 && argv[1][0] == 'r') {
        mavlink_status_t st;
        int c;
        memset(&st, 0, sizeof st);
        while ((c = getchar()) != EOF) {
            if (mavlink_parse_char(MAVLINK_COMM_0, (uint8_t)c, &msg, &st)) {
                if (msg.msgid == MAVLINK_MSG_ID_KF_RAW_SAMPLE) {
                    mavlink_kf_raw_sample_t s;
                    mavlink_msg_kf_raw_sample_decode(&msg, &s);
                    printf("R %u %u %u %" PRIu64 " %" PRIu32 " %d %d %d %d %d %d %d %d %d %d %u %u %u\n",
                           msg.sysid, msg.compid, msg.seq, s.time_boot_us, s.sample_counter,
                           s.acc_x, s.acc_y, s.acc_z, s.gyro_x, s.gyro_y, s.gyro_z,
                           s.mag_x, s.mag_y, s.mag_z, s.temperature, s.unit_id, s.flags, s.gyro_shift);
                } else if (msg.msgid == MAVLINK_MSG_ID_KF_ORIENTATION) {
                    mavlink_kf_orientation_t o;
                    mavlink_msg_kf_orientation_decode(&msg, &o);
                    printf("O %" PRIu64 " %" PRIu32 " %08" PRIx32 " %08" PRIx32 " %08" PRIx32 " %08" PRIx32
                           " %" PRIu32 " %u %u %u %u %08" PRIx32 " %08" PRIx32 " %08" PRIx32 " %08" PRIx32
                           " %08" PRIx32 " %08" PRIx32 "\n",
                           o.time_boot_us, o.sample_counter, bits(o.q_w), bits(o.q_x), bits(o.q_y),
                           bits(o.q_z), o.rejected_samples, o.status, o.earth_frame, o.filter_id,
                           o.unit_id, bits(o.cov[0]), bits(o.cov[1]), bits(o.cov[2]), bits(o.cov[3]),
                           bits(o.cov[4]), bits(o.cov[5]));
                }
            }
        }
        printf("E %u %u\n", st.packet_rx_drop_count, KF_DIALECT_HASH == 0 ? 1u : 0u);
        return 0;
    } else {
        fprintf(stderr, "bad arguments\n");
        return 2;
    }
    fwrite(buf, 1, mavlink_msg_to_send_buffer(buf, &msg), stdout);
    return 0;
}
"""

C_TESTSUITE = r"""
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define MAVLINK_USE_CONVENIENCE_FUNCTIONS
#define MAVLINK_COMM_NUM_BUFFERS 2
#include "mavlink_types.h"
static mavlink_system_t mavlink_system = {42, 11, 0, 0, 0, 0};
static unsigned failures, received, drops;
#define MAVLINK_ASSERT(x) do { if (!(x)) { failures++; fprintf(stderr, "assert %s:%d\n", __FILE__, __LINE__); } } while (0)
static void comm_send_ch(mavlink_channel_t chan, uint8_t c);
static mavlink_message_t last_msg;
#include "kinefuse/mavlink.h"
#include "kinefuse/testsuite.h"
static void comm_send_ch(mavlink_channel_t chan, uint8_t c)
{
    mavlink_status_t status;
    if (mavlink_parse_char(chan, c, &last_msg, &status)) received++;
    drops = status.packet_rx_drop_count;
}
int main(void)
{
    (void)mavlink_system;
    mavlink_test_all(11, 10, &last_msg);
    printf("%u %u %u\n", received, failures, drops);
    return failures != 0;
}
"""

CFLAGS = ["-std=c99", "-O1", "-Wall", "-Wno-address-of-packed-member", "-Werror"]


@pytest.fixture(scope="module")
def c_prog(tmp_path_factory):
    if gcc is None:
        pytest.skip("gcc not installed")
    d = tmp_path_factory.mktemp("c")
    (d / "prog.c").write_text(C_PROGRAM)
    subprocess.run([gcc, *CFLAGS, "-I", str(GENERATED), "-o", str(d / "prog"), str(d / "prog.c")],
                   check=True, capture_output=True)
    return d / "prog"


HEADER_USER = ('#include "kinefuse/mavlink.h"\n#include "kf_dialect.h"\n'
               "int kf_unused(void) { return (int)(KF_DIALECT_HASH & 1u) + MAVLINK_MSG_ID_KF_EFFORTS_LEN; }\n")


@needs_gcc
def test_headers_compile_c99(tmp_path):
    """mavgen's C is C99 but not -pedantic clean (anonymous unions, enum values > INT_MAX) and
    passes packed array members by pointer: firmware includes it with -isystem (warnings of our
    own code stay on) or with -Wno-address-of-packed-member."""
    src = tmp_path / "h.c"
    src.write_text(HEADER_USER)
    subprocess.run([gcc, *CFLAGS, "-fsyntax-only", "-I", str(GENERATED), str(src)], check=True, capture_output=True)
    subprocess.run([gcc, "-std=c99", "-Wall", "-Wextra", "-pedantic", "-Werror", "-fsyntax-only",
                    "-isystem", str(GENERATED), str(src)], check=True, capture_output=True)


@pytest.mark.skipif(shutil.which("arm-none-eabi-gcc") is None, reason="arm-none-eabi-gcc not installed")
def test_headers_compile_for_cortex_m4(tmp_path):
    src = tmp_path / "h.c"
    src.write_text(HEADER_USER)
    subprocess.run(["arm-none-eabi-gcc", "-std=c99", "-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard",
                    "-mfpu=fpv4-sp-d16", "-Wall", "-Wextra", "-pedantic", "-Werror", "-fsyntax-only",
                    "-isystem", str(GENERATED), str(src)], check=True, capture_output=True)


@needs_gcc
def test_generated_c_testsuite_round_trips(tmp_path):
    (tmp_path / "t.c").write_text(C_TESTSUITE)
    r = subprocess.run([gcc, "-std=c99", "-O0", "-Wall", "-Wno-unused-function", "-Wno-address-of-packed-member",
                        "-I", str(GENERATED), "-o", str(tmp_path / "t"), str(tmp_path / "t.c")],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr[-2000:]
    out = subprocess.run([str(tmp_path / "t")], capture_output=True, text=True, timeout=60)
    received, failures, drops = map(int, out.stdout.split())
    assert out.returncode == 0 and failures == 0 and drops == 0
    assert received >= 4 * 5  # at least our five messages, four frames each through the parser


def _raw_values(rng):
    i16 = lambda: int(rng.integers(-32768, 32768))  # noqa: E731
    return dict(time_boot_us=int(rng.integers(0, 2**63)), sample_counter=int(rng.integers(0, 2**32)),
                acc_x=i16(), acc_y=i16(), acc_z=i16(), gyro_x=i16(), gyro_y=i16(), gyro_z=i16(),
                mag_x=i16(), mag_y=i16(), mag_z=i16(), temperature=i16(),
                unit_id=int(rng.integers(0, 256)), flags=int(rng.integers(0, 256)),
                gyro_shift=int(rng.integers(0, 4)))   # the extension field


@needs_gcc
def test_c_packs_python_decodes(c_prog):
    rng = np.random.default_rng(11)
    fields = list(kinefuse_dialect()["KF_RAW_SAMPLE"].fields)
    for case in range(25):
        v = _raw_values(rng)
        if case % 5 == 0:  # zero tail: the C side truncates, Python must pad
            v.update(mag_z=0, temperature=0, unit_id=0, flags=0, gyro_shift=0)
        sysid, compid = int(rng.integers(1, 255)), 200
        frame = subprocess.run([str(c_prog), "p", str(sysid), str(compid)] + [str(v[k]) for k in fields],
                               capture_output=True, check=True).stdout
        frames, counters = decode_bytes(frame)
        assert counters.frames_ok == 1 and counters.bytes_skipped == 0
        f = frames[0]
        assert (f.msgid, f.sysid, f.compid) == (52500, sysid, compid)
        assert f.msg._asdict() == v
        # and pymavlink agrees on the same bytes
        m = module().MAVLink(None)
        pm = m.parse_buffer(frame)[0]
        assert {k: getattr(pm, k) for k in fields} == v


@needs_gcc
def test_python_packs_c_decodes(c_prog):
    rng = np.random.default_rng(12)
    enc = Encoder(sysid=9, compid=200)
    expected, stream = [], b""
    for case in range(30):
        v = _raw_values(rng)
        if case % 4 == 0:
            v.update(temperature=0, unit_id=0, flags=0, gyro_shift=0)
        stream += enc.encode("KF_RAW_SAMPLE", **v)
        expected.append(f"R 9 200 {case} {v['time_boot_us']} {v['sample_counter']} "
                        + " ".join(str(v[k]) for k in ["acc_x", "acc_y", "acc_z", "gyro_x", "gyro_y", "gyro_z",
                                                       "mag_x", "mag_y", "mag_z", "temperature", "unit_id", "flags",
                                                       "gyro_shift"]))
    out = subprocess.run([str(c_prog), "r"], input=stream, capture_output=True, check=True).stdout.decode()
    lines = out.splitlines()
    assert lines[:-1] == expected
    assert lines[-1] == "E 0 0"


def _f32_hex(x: float) -> str:
    return f"0x{struct.unpack('<I', struct.pack('<f', x))[0]:08x}"


@needs_gcc
def test_orientation_with_extension_both_ways(c_prog):
    rng = np.random.default_rng(13)
    enc = Encoder(sysid=4, compid=200)
    for case in range(10):
        q = rng.normal(size=4).astype(np.float32)
        cov = rng.normal(size=6).astype(np.float32) if case % 2 else np.zeros(6, np.float32)
        ints = [int(rng.integers(0, 2**40)), int(rng.integers(0, 2**32)), int(rng.integers(0, 2**32)),
                int(rng.integers(0, 2**16)), 1, 5, 4]
        args = ["o", "4", "200", str(ints[0]), str(ints[1])] + [_f32_hex(float(x)) for x in q] \
            + [str(x) for x in ints[2:]] + [_f32_hex(float(x)) for x in cov]
        frame = subprocess.run([str(c_prog), *args], capture_output=True, check=True).stdout
        (f,), counters = decode_bytes(frame)
        m = f.msg
        assert np.array([m.q_w, m.q_x, m.q_y, m.q_z], np.float32).tobytes() == q.tobytes()
        assert np.array(m.cov, np.float32).tobytes() == cov.tobytes()
        assert (m.time_boot_us, m.sample_counter, m.rejected_samples, m.status, m.earth_frame,
                m.filter_id, m.unit_id) == tuple(ints)
        # Python -> C: the same record re-encoded by our encoder is parsed identically by C
        enc.seq = 0
        back = subprocess.run([str(c_prog), "r"], input=enc.encode_record(m), capture_output=True,
                              check=True).stdout.decode().splitlines()[0]
        assert back.split()[3:7] == [f"{x:08x}" for x in np.frombuffer(q.tobytes(), "<u4")]
        assert back.split()[12:] == [f"{x:08x}" for x in np.frombuffer(cov.tobytes(), "<u4")]
        if case % 2 == 0:
            assert len(frame) < 12 + 61  # all-zero covariance costs no bytes on the wire


def test_signed_frames_encoded_back_to_back_have_increasing_timestamps():
    """Two frames within one 10 us tick must not share a signing timestamp (replay check)."""
    from kinefuse.host.link.codec import Encoder
    enc = Encoder(key=b"k" * 32)
    stamps = []
    for _ in range(200):
        f = enc.encode("HEARTBEAT")
        stamps.append(int.from_bytes(f[-12:-6], "little"))
    assert all(b > a for a, b in zip(stamps, stamps[1:]))
