"""Protocol property: corrupting k bits of a frame is detected (the frame is dropped), never
decoded as something else, and never costs the neighbouring frames.

MAVLink 2's CRC-16/MCRF4XX (polynomial 0x1021) has Hamming distance 4 up to 32 751 bits, so
every 1-, 2- and 3-bit error in a frame is detected with certainty; for k ≥ 4 a corrupted frame
passes with probability ~2⁻¹⁶, so the check there is that no decoded frame differs from a sent
one (with the examples drawn here).  The round trip of every message and the decoder's
no-raise / bounded-memory properties are tested in ``host/tests/test_link_decoder.py``.
"""
from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from kinefuse.host.link.codec import Encoder
from kinefuse.host.link.decoder import StreamDecoder

ENC = Encoder(sysid=3, compid=200)


def _frames(seed: int) -> list[bytes]:
    rng = np.random.default_rng(seed)
    out = []
    for i in range(6):
        kind = i % 3
        if kind == 0:
            out.append(ENC.encode("KF_RAW_SAMPLE", time_boot_us=int(rng.integers(0, 2 ** 40)),
                                  sample_counter=i, acc_x=int(rng.integers(-2000, 2000)),
                                  acc_z=1000, gyro_y=int(rng.integers(-500, 500)), mag_x=300,
                                  unit_id=3, flags=8))
        elif kind == 1:
            q = rng.normal(size=4)
            q /= np.linalg.norm(q)
            out.append(ENC.encode("KF_ORIENTATION", time_boot_us=int(rng.integers(0, 2 ** 40)),
                                  sample_counter=i, q_w=float(q[0]), q_x=float(q[1]),
                                  q_y=float(q[2]), q_z=float(q[3]), earth_frame=1, unit_id=3))
        else:
            out.append(ENC.encode("HEARTBEAT", type=0, autopilot=8, base_mode=0, custom_mode=0,
                                  system_status=4, mavlink_version=3))
    return out


def _decode(stream: bytes) -> list:
    dec = StreamDecoder()
    return [(f.msgid, f.sysid, f.compid, f.seq, f.msg) for f in dec.feed(stream) + dec.flush()]


@settings(max_examples=150, deadline=None, derandomize=True)
@given(seed=st.integers(0, 1000), victim=st.integers(0, 5), k=st.integers(1, 3),
       positions=st.lists(st.integers(0, 10_000), min_size=3, max_size=3, unique=True))
def test_up_to_three_flipped_bits_drop_exactly_that_frame(seed, victim, k, positions):
    frames = _frames(seed)
    clean = _decode(b"".join(frames))
    assert len(clean) == len(frames)
    bad = bytearray(frames[victim])
    nbits = len(bad) * 8
    flips = sorted({p % nbits for p in positions[:k]})
    for p in flips:
        bad[p // 8] ^= 1 << (p % 8)
    stream = b"".join(frames[:victim]) + bytes(bad) + b"".join(frames[victim + 1:])
    got = _decode(stream)
    assert got == clean[:victim] + clean[victim + 1:], f"bits {flips} of frame {victim}"


@settings(max_examples=80, deadline=None, derandomize=True)
@given(seed=st.integers(0, 1000), victim=st.integers(0, 5), k=st.integers(4, 24),
       positions=st.lists(st.integers(0, 10_000), min_size=24, max_size=24))
def test_many_flipped_bits_never_decode_as_another_frame(seed, victim, k, positions):
    frames = _frames(seed)
    clean = _decode(b"".join(frames))
    bad = bytearray(frames[victim])
    for p in positions[:k]:
        p %= len(bad) * 8
        bad[p // 8] ^= 1 << (p % 8)
    got = _decode(b"".join(frames[:victim]) + bytes(bad) + b"".join(frames[victim + 1:]))
    assert all(g in clean for g in got)
    others = clean[:victim] + clean[victim + 1:]
    # the other frames survive unless the corrupted bytes happen to equal the original frame
    assert [g for g in got if g in others] == others or bytes(bad) == frames[victim]
