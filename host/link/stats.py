"""Link statistics of a recording: per stream and unit, rates, loss, errors, clock fit, latency.

- rate achieved: frames received per second of the unit's clock, vs the rate requested (from
  KF_UNIT_STATUS, else the recording header); a requested rate of 0 in the status is the stream
  turned off (``record --start`` stops it at the end), not a rate: the requested rate is the
  last nonzero one and the achieved rate is measured over the stretch in which the stream ran
  at it (from its last change or restart on, up to the stop); changes between nonzero rates
  and restarts (off, then on again) are counted, a stream off at the end is said so;
- samples lost: from the 32-bit ``sample_counter`` (wrap-safe; the usual step between frames
  is taken as the stride, so a decimated stream is not counted as loss); resets (reboots),
  duplicates and frames reordered on the way (up to REORDER_US of device time late: put back
  in their place, not lost) are counted separately;
- clock: host time = offset + slope * device time + delay.  The slope is the Theil-Sen median
  of the slopes between the lowest-delay points of 40 blocks, the offset puts the line on the
  lower envelope (minimum delay), so ``drift_ppm`` (unit clock rate relative to the host's,
  positive = unit fast) is robust to delay spikes; the residual is the delay above the minimum;
- latency: with TIMESYNC replies in the recording, the round trip host -> unit -> host; the
  one-way latency is estimated as half the minimum round trip plus the median delay above the
  minimum (assumes a symmetric minimum path).
"""
from __future__ import annotations

import math

import numpy as np

from kinefuse.host.link.dialect import DIALECT_HASH
from kinefuse.host.link.frames import DecodedFile, DecodedStream
from kinefuse.host.link.spec import kinefuse_dialect

MSG_RAW, MSG_ORI, MSG_STATUS, MSG_TIMESYNC = 52500, 52501, 52504, 111
MSG_STATUSTEXT = 253
SEVERITY_NAMES = {0: "EMERGENCY", 1: "ALERT", 2: "CRITICAL", 3: "ERROR", 4: "WARNING", 5: "NOTICE", 6: "INFO",
                  7: "DEBUG"}
# KF_UNIT_STATUS extension fields (MAVLink 2): an older firmware's shorter frames decode them as 0
STATUS_EXTENSIONS = ("numeric_resets", "hil_invalid", "rejected_samples2")


def severity_name(severity: int) -> str:
    return SEVERITY_NAMES.get(int(severity), f"severity {int(severity)}")


def clean_statustext(text) -> str:
    """A STATUSTEXT's text (str, or NUL-padded bytes) without its padding."""
    if not isinstance(text, str):
        text = bytes(text).decode("utf-8", "replace")
    return text.rstrip("\0").strip()


def statustext_text(severity: int, text) -> str:
    """"ERROR: parameter storage error: ..." of a STATUSTEXT (text as str or NUL-padded bytes)."""
    return f"{severity_name(severity)}: {clean_statustext(text)}"


def statustexts(ds: DecodedStream, start_ns: int | None = None) -> list[dict]:
    """The STATUSTEXTs of a decoded stream, the same (unit, severity, text) once with its count:
    [{"sysid", "severity", "severity_name", "text", "count", "first_s", "last_s"}] in order of
    first appearance; first_s/last_s: host seconds from ``start_ns`` (None without host times)."""
    arr = ds.arrays.get(MSG_STATUSTEXT)
    if arr is None or not arr.size:
        return []
    host = ds.host_ns.get(MSG_STATUSTEXT)
    out: dict = {}
    for k, r in enumerate(arr):
        text = clean_statustext(r["text"])
        key = (int(r["_sysid"]), int(r["severity"]), text)
        t = None if host is None or start_ns is None else (int(host[k]) - start_ns) / 1e9
        e = out.get(key)
        if e is None:
            out[key] = {"sysid": key[0], "severity": key[1], "severity_name": severity_name(key[1]), "text": text,
                        "count": 1, "first_s": t, "last_s": t}
        else:
            e["count"] += 1
            e["last_s"] = t
    return list(out.values())


def statustext_line(e: dict) -> str:
    """One line of a :func:`statustexts` entry."""
    when = "" if e["first_s"] is None else (
        f" at {e['first_s']:.1f} s" if e["count"] == 1 else f", {e['first_s']:.1f} s .. {e['last_s']:.1f} s")
    times = "" if e["count"] == 1 else f" ({e['count']} times{when})"
    return f"unit {e['sysid']} said {e['severity_name']}: {e['text']}" + (times or when)
KF_MESSAGES = (52500, 52501, 52502, 52503, 52504)
REQUESTED_FIELD = {MSG_RAW: "raw_rate_requested", MSG_ORI: "orientation_rate_requested"}


STRIDE_WINDOW = 31   # steps on each side of a step that give its expected step


def _window_gcd(g: np.ndarray, w: int) -> np.ndarray:
    """``r[i] = gcd(g[i:i + w])`` (fewer at the end), in log2(w) vectorised steps."""
    n = g.size
    r = np.concatenate([g, np.zeros(w, g.dtype)])     # gcd(x, 0) = x
    span = 1
    while span * 2 <= w:
        r = np.gcd(r[:-span], r[span:])               # r[i] = gcd over 2 * span steps from i
        span *= 2
    return np.gcd(r[:n], r[w - span:w - span + n])


def _expected_steps(gaps: np.ndarray, w: int = STRIDE_WINDOW) -> np.ndarray:
    """Each step's expected step: the larger of the greatest common divisors of the ``w`` steps
    before it and of the ``w`` steps after it.  A sample counter's steps are multiples of its
    stride however many samples are lost, and one side lies within one stride next to a change
    of stride (the step itself is left out: the firmware restarts its divider on a rate change,
    so the step across the change may be neither stride).  The median of the steps around it
    was the stride only while most steps had no loss: with a third of the samples lost, stats
    counted 428 of 783 lost."""
    gaps = np.asarray(gaps).astype(np.int32)          # forward steps are < 2**31; int32 gcd is faster
    n = gaps.size
    i = np.arange(n)
    f = _window_gcd(gaps, w)                          # f[j] = gcd(gaps[j:j + w])
    # a window cut short by an end of the recording may hold only steps with a loss: not used
    left = np.where(i >= w, f[np.maximum(i - w, 0)], 0)
    right = np.where(i + 1 + w <= n, f[np.minimum(i + 1, n - 1)], 0)
    step = np.maximum(left, right)
    step[step == 0] = np.gcd.reduce(gaps)   # fewer than 2 w + 1 steps: all of them
    return np.maximum(1, step)


def counter_analysis(counter: np.ndarray, stride: int | None = None) -> dict:
    """Loss from a uint32 counter (wrap-safe).  ``stride`` (reported) is the most common step;
    unless given (a live view learns it once and then analyses short pieces) each step is
    compared with its expected step (:func:`_expected_steps`, from the STRIDE_WINDOW steps on
    either side of it), so a stride that changes within the recording (KF_ORIENTATION's after
    a KF_RATE_HZ change: 10 samples at 1 kHz, 5 at 500 Hz for 100 Hz) is not counted as loss,
    nor is heavy loss taken for a longer stride."""
    c = np.asarray(counter, dtype=np.int64)
    if c.size < 2:
        return {"stride": stride, "samples_lost": 0, "loss_fraction": 0.0, "resets": 0,
                "duplicates": 0}
    d = (c[1:] - c[:-1]) & 0xFFFFFFFF
    forward = (d > 0) & (d < 1 << 31)
    gaps = d[forward]
    step = stride
    if stride is None:
        steps, counts = np.unique(gaps, return_counts=True)
        stride = int(steps[np.argmax(counts)]) if steps.size else 1
        if gaps.size:
            step = _expected_steps(gaps)
    lost = int(np.sum(np.maximum(0, np.round(gaps / step).astype(np.int64) - 1)))
    expected = int(c.size + lost)
    return {"stride": stride, "samples_lost": lost, "loss_fraction": lost / expected if expected else 0.0,
            "resets": int(np.sum(d >= 1 << 31)), "duplicates": int(np.sum(d == 0))}


def fit_clock(device_s: np.ndarray, host_s: np.ndarray, blocks: int = 40) -> dict | None:
    """Robust fit host = offset + slope * device on the lower envelope; see module docstring."""
    x = np.asarray(device_s, np.float64)
    y = np.asarray(host_s, np.float64)
    n = x.size
    if n < 10 or x[-1] - x[0] <= 0:
        return None
    k = int(min(blocks, n // 5))
    if k < 2:
        return None
    edges = np.linspace(0, n, k + 1).astype(int)
    idx = np.array([a + int(np.argmin(y[a:b] - x[a:b])) for a, b in zip(edges[:-1], edges[1:])])
    bx, by = x[idx], y[idx]
    i, j = np.triu_indices(k, 1)
    dx = bx[j] - bx[i]
    ok = dx > 0
    if not ok.any():
        return None
    slope = float(np.median((by[j] - by[i])[ok] / dx[ok]))
    if not slope > 0:       # host time not advancing (one read time for everything): no fit
        return None
    resid0 = y - slope * x
    offset = float(resid0.min())
    excess = resid0 - offset
    return {
        "slope": slope,
        "offset_s": offset,                       # host time (s from recording start) at device time 0
        "drift_ppm": (1.0 / slope - 1.0) * 1e6,   # unit clock rate vs host clock; > 0: unit fast
        "delay_above_min_ms": {"median": float(np.median(excess) * 1e3),
                               "p95": float(np.percentile(excess, 95) * 1e3), "max": float(excess.max() * 1e3)},
        "points": int(n),
        "span_s": float(x[-1] - x[0]),
    }


DRIFT_PLAUSIBLE_PPM = 1000.0   # crystals: tens of ppm; RC oscillators: a few thousand at worst
STALE_EXCESS_S = 0.05          # leading frames this much later than the live line: queued before
STALE_WINDOW_S = 2.0           # ... than a frame sent within this much unit time after them
JUMP_S = 0.02                  # a rise of the minimum delay by this much: a latency/offset jump


def leading_stale(device_s: np.ndarray, host_s: np.ndarray) -> int:
    """Number of leading frames that were queued before the recording started (the bytes a pty
    or serial buffer held, delivered in a burst: host time barely moves while device time does).

    A frame is stale when a frame sent at most STALE_WINDOW_S (unit time) after it arrived with
    a delay (host - device time) more than STALE_EXCESS_S smaller: it waited that much longer.
    Over that window clock drift moves the delay by 2 ms at most (1000 ppm), so no fit is
    needed, and a burst of any length is found (one of the window's length waits for the next
    window's frames).  Returns the leading run; 0 when fewer than 10 frames would remain."""
    x = np.asarray(device_s, np.float64)
    y = np.asarray(host_s, np.float64)
    n = x.size
    if n < 20:
        return 0
    step = float(np.median(np.diff(x)))
    if not step > 0:
        return 0
    from scipy.ndimage import minimum_filter1d
    w = int(min(n, max(2, round(STALE_WINDOW_S / step))))
    delay = y - x
    floor = minimum_filter1d(delay, size=w, origin=-(w // 2), mode="nearest")   # over [i, i + w)
    late = delay - floor > STALE_EXCESS_S
    if not late[0]:
        return 0
    k = int(np.argmin(late)) if not late.all() else n
    return k if n - k >= 10 else 0


def fit_clock_checked(device_s, host_s, blocks: int = 40) -> dict | None:
    """:func:`fit_clock` without a leading burst of stale frames, plus plausibility warnings:
    ``excluded_leading`` (frames left out), ``warnings`` (texts; empty when plausible)."""
    x = np.asarray(device_s, np.float64)
    y = np.asarray(host_s, np.float64)
    k = leading_stale(x, y)
    fit = fit_clock(x[k:], y[k:], blocks)
    if fit is None:
        return None
    fit["excluded_leading"] = k
    warn = []
    if k:
        warn.append(f"the first {k} frames ({x[k] - x[0]:.2f} s of unit time) arrived in a burst at the start "
                    f"(queued before the recording, e.g. in a pty or serial buffer): left out of the clock fit")
    if abs(fit["drift_ppm"]) > DRIFT_PLAUSIBLE_PPM:
        warn.append(f"implausible clock fit: drift {fit['drift_ppm']:+,.0f} ppm (unit clocks are within about "
                    f"+-{DRIFT_PLAUSIBLE_PPM:.0f} ppm): offset, drift and latency figures are unreliable "
                    f"(stale or reordered data, a clock step, or a host that stalled)")
    # a jump: the per-block minimum delay above the line rises by more than JUMP_S
    xs, ys = x[k:], y[k:]
    nb = int(min(blocks, xs.size // 5))
    if nb >= 4:
        resid = ys - (fit["offset_s"] + fit["slope"] * xs)
        edges = np.linspace(0, xs.size, nb + 1).astype(int)
        mins = np.array([resid[a:b].min() for a, b in zip(edges[:-1], edges[1:])])
        rise = float(mins.max() - mins.min())
        fit["min_delay_range_ms"] = rise * 1e3
        if rise > JUMP_S:
            warn.append(f"the minimum delay changes by {rise * 1e3:.1f} ms within the recording (a latency or "
                        f"offset jump: unit reboot, clock step, host stall or link change): the fit may be off")
    fit["warnings"] = warn
    return fit


CLOCK_JUMP_S = 1.0             # device time this much ahead of what the sample counter says: a jump


def clock_jumps(t_us, counter) -> np.ndarray:
    """Indices where the device clock jumps forward with the sample counter running on (a clock
    set or stepped, not lost samples: those skip counter values too): the device time step
    exceeds the counter step times the usual time per count by more than CLOCK_JUMP_S.  Like a
    reboot, each starts a clock segment of its own (one fit across it is meaningless)."""
    dt = np.diff(np.asarray(t_us, np.int64))
    dc = np.diff(np.asarray(counter, np.int64)) & 0xFFFFFFFF
    ok = (dt > 0) & (dc > 0) & (dc < 1 << 31)
    if not ok.any():
        return np.zeros(0, np.int64)
    per_count = float(np.median(dt[ok] / dc[ok]))
    return np.flatnonzero(ok & (dt > dc * per_count + CLOCK_JUMP_S * 1e6)) + 1


def unit_clock_segments(ds, sysid: int, start_ns: int) -> list[dict]:
    """The unit's device -> host clock, one fit per device-clock segment (a reboot starts one):
    [{"host_from_ns", "offset_s", "slope", "drift_ppm", "points", "excluded_leading", "warnings"}]
    from its KF_RAW_SAMPLE (else another kinefuse message with ``time_boot_us``) frames;
    host = offset_s + slope * device seconds, in seconds since ``start_ns``.  [] without host times."""
    for mid in (MSG_RAW, MSG_ORI, 52502, 52503, MSG_STATUS):
        arr = ds.arrays.get(mid)
        host_ns = ds.host_ns.get(mid)
        if arr is None or host_ns is None:
            continue
        rows = arr["_sysid"] == sysid
        if rows.sum() < 2:
            continue
        dev = arr["time_boot_us"][rows].astype(np.int64)
        h = host_ns[rows].astype(np.int64)
        counter = arr["sample_counter"][rows] if "sample_counter" in arr.dtype.names else None
        starts, keep = device_segments(dev, counter)     # a repeated frame is no reboot
        cuts = sorted({0, dev.size, *starts, *(int(k) for k in (clock_jumps(dev, counter)
                                                                if counter is not None else ()))})
        out = []
        for a, b in zip(cuts[:-1], cuts[1:]):
            fresh = keep[a:b]                             # repeats (late frames) are not fitted
            x, y = dev[a:b][fresh] / 1e6, (h[a:b][fresh] - start_ns) / 1e9
            fit = fit_clock_checked(x, y) if x.size >= 10 else None
            if fit is None:   # too few points for the robust fit: the offset of the lower envelope
                fit = {"slope": 1.0, "offset_s": float(np.min(y - x)), "drift_ppm": 0.0, "points": int(x.size),
                       "excluded_leading": 0, "warnings": ["too few samples for a drift fit: offset only"]}
            out.append({"host_from_ns": int(h[a]), **{k: fit[k] for k in ("offset_s", "slope", "drift_ppm", "points",
                                                                         "excluded_leading", "warnings")},
                        "reference": kinefuse_dialect().get(mid).name})
        return out
    return []


def host_time_from_fit(segments: list[dict], device_us, host_ns) -> np.ndarray:
    """Device times (us) -> host seconds since the recording start through the unit's clock
    fit; the segment is chosen by the frame's host receive time.  NaN without a fit."""
    t = np.asarray(device_us, np.float64) / 1e6
    out = np.full(t.shape, np.nan)
    if not segments:
        return out
    starts = np.array([sg["host_from_ns"] for sg in segments], np.int64)
    k = np.clip(np.searchsorted(starts, np.asarray(host_ns, np.int64), side="right") - 1, 0, len(segments) - 1)
    off = np.array([sg["offset_s"] for sg in segments])[k]
    slope = np.array([sg["slope"] for sg in segments])[k]
    return off + slope * t


REORDER_US = 50_000    # a frame at most this far (device time) behind the latest of its segment: reordered


def reordered(t_us: int, counter, top_t: int, top_counter) -> bool:
    """A frame (``t_us``, ``counter``) not sent before, arriving after the frame (``top_t``,
    ``top_counter``) -- the latest of its clock segment -- was swapped on the way (UDP, a Wi-Fi
    bridge deliver frame N+1 before N): it is at most REORDER_US of device time behind it and,
    with a sample counter, its counter is behind too (wrap-safe).  A reboot restarts the device
    clock near 0, further behind unless the unit had been up for less than REORDER_US."""
    if not 0 < top_t - t_us <= REORDER_US:
        return False
    return counter is None or 0 < (int(top_counter) - int(counter)) & 0xFFFFFFFF < 1 << 31


def device_segments(t_us, counter=None) -> tuple[list[int], np.ndarray]:
    """(start indices of the device-clock segments, mask of the frames that are not repeats)
    of one unit's frames of one message, in arrival order.

    A step back of the device clock onto a time (with the same sample counter, when there is
    one) already sent in the current segment is a repeat -- a frame the link delivered again --
    not a reboot; a step back onto a time not sent before is a frame swapped on the way when it
    lands within the reorder window behind the segment's latest frame (:func:`reordered`: kept,
    it belongs between its neighbours by device time), else it starts a new segment (a reboot).
    The kfr reader, stats and export use this rule, live the same frame by frame
    (:class:`kinefuse.host.commands.live_cmd.UnitView`); stats and export took every step
    back for a reboot, so a frame replayed late counted a reset, the jump from it back onto the
    stream's latest sample that many samples lost (14 lost for 6), and the rate and clock fit
    were those after the replay; a swapped pair counted a reset and two samples lost."""
    dev = np.asarray(t_us, np.int64)
    cnt = None if counter is None else np.asarray(counter, np.int64)
    n = dev.size
    starts = [0]
    backs = np.flatnonzero(np.diff(dev) < 0) + 1
    if not backs.size:          # times never go back: a repeat is the frame just before again
        keep = np.ones(n, bool)
        same = dev[1:] == dev[:-1]
        keep[1:] = ~(same if cnt is None else same & (cnt[1:] == cnt[:-1]))
        return starts, keep
    # prev[i]: the latest earlier frame with the same (time, counter), -1 if none (one sort,
    # not a scan of the segment per step back: a flaky hour-long link has thousands)
    keys = (np.arange(n), dev) if cnt is None else (np.arange(n), cnt, dev)
    order = np.lexsort(keys)
    same = dev[order][1:] == dev[order][:-1]
    if cnt is not None:
        same &= cnt[order][1:] == cnt[order][:-1]
    prev = np.full(n, -1, np.int64)
    prev[order[1:][same]] = order[:-1][same]
    top = -1                    # the frame with the latest time of the segment so far
    for b in backs:
        # between two steps back the times rise: the latest is one just before a step back
        if top < starts[-1] or dev[b - 1] >= dev[top]:
            top = b - 1
        if prev[b] >= starts[-1] or reordered(dev[b], None if cnt is None else cnt[b], dev[top],
                                              None if cnt is None else cnt[top]):
            continue            # a repeat, or a frame swapped on the way
        starts.append(int(b))   # not sent before in this segment, far behind: a reboot
    seg_start = np.asarray(starts)[np.searchsorted(starts, np.arange(n), side="right") - 1]
    return starts, prev < seg_start


def in_device_order(t_us, keep, start: int, end: int) -> tuple[np.ndarray, int]:
    """(indices of the kept frames of the segment [start, end) sorted by device time -- a frame
    swapped on the way goes back between its neighbours, stable for equal times --, number of
    them that arrived after a frame with a later time: the reordered ones)."""
    idx = np.arange(start, end)[keep[start:end]]
    t = np.asarray(t_us, np.int64)[idx]
    late = int(np.count_nonzero(t[1:] < np.maximum.accumulate(t)[:-1]))
    return idx[np.argsort(t, kind="stable")], late


INTERLEAVE_MIN_RESETS = 5     # this many device-clock restarts, each one later than the last,
INTERLEAVE_BACK_US = 100_000   # landing this far (median) behind the latest time: another clock


def interleaved_clocks(t_us, counter=None) -> dict | None:
    """Two units sending with one system id on one link: their frames interleave into one
    series whose device clock "restarts" (:func:`device_segments`) at every step from the unit
    ahead to the one behind, and each restart lands later on the clock than the one before (the
    clock behind runs on).  A reboot restarts near the boot time instead.  Stats reported 0.15
    Hz with 1999 resets and no warning; the kfr reader returned the two units' samples mixed.
    Returns {"resets", "restarts_later"} when at least INTERLEAVE_MIN_RESETS restarts, 90 % of
    them later than the previous one, together span more than a second and land (median) at
    least INTERLEAVE_BACK_US behind the latest time sent (frames merely swapped on the way land
    a sample behind); else None."""
    starts, _ = device_segments(t_us, counter)
    if len(starts) - 1 < INTERLEAVE_MIN_RESETS:
        return None
    dev = np.asarray(t_us, np.int64)
    idx = np.array(starts[1:])
    first = dev[idx]
    later = float(np.mean(np.diff(first) > 0))
    if later < 0.9 or first.max() - first.min() <= 1_000_000:
        return None
    # frames swapped on the way (UDP, a radio) step back a sample or two: not another clock
    back = np.maximum.accumulate(dev)[idx - 1] - first
    if np.median(back) < INTERLEAVE_BACK_US:
        return None
    return {"resets": len(starts) - 1, "restarts_later": later}


def interleaved_text(sysid, name: str, info: dict,
                     consequence: str = "rate, loss and clock figures of this id are meaningless") -> str:
    return (f"unit {sysid}: the device clock of its {name} frames went back {info['resets']:,} times "
            f"onto a clock that ran on (not a reboot's restart): two units with the same "
            f"system id on this link (give each its own KF_UNIT_ID): their frames are mixed, {consequence}")


def sample_loss(t_us, counter) -> dict:
    """:func:`counter_analysis` of a unit's frames, segment by segment (:func:`device_segments`):
    repeats left out (counted as ``duplicates``), frames swapped on the way put back in device
    order (counted as ``reordered``, neither lost nor a reset), ``resets`` = reboots."""
    starts, keep = device_segments(t_us, counter)
    c = np.asarray(counter, np.int64)
    lost = received = dup = late = 0
    strides: dict = {}
    for s, e in zip(starts, starts[1:] + [c.size]):
        idx, k = in_device_order(t_us, keep, s, e)
        late += k
        part = c[idx]
        ca = counter_analysis(part)
        lost += ca["samples_lost"]
        dup += ca["duplicates"]
        received += part.size
        if ca["stride"] is not None and part.size >= 2:
            strides[ca["stride"]] = strides.get(ca["stride"], 0) + part.size
    expected = received + lost
    return {"stride": max(strides, key=strides.get) if strides else None, "samples_lost": int(lost),
            "loss_fraction": lost / expected if expected else 0.0, "resets": len(starts) - 1,
            "duplicates": int(dup + np.count_nonzero(~keep)), "reordered": late}


def _last_segment(t_us: np.ndarray, counter=None) -> tuple[slice, np.ndarray]:
    """(rows after the last reset of the device clock -- time going back to a time not sent
    before, :func:`device_segments` -- or, with the sample counter, its last forward jump
    (:func:`clock_jumps`); mask of those rows that are not repeats)."""
    starts, keep = device_segments(t_us, counter)
    cuts = starts[1:]
    if counter is not None:
        cuts += [int(j) for j in clock_jumps(t_us, counter)]
    seg = slice(int(max(cuts)) if cuts else 0, None)
    return seg, keep[seg]


def _requested_run(status_rows, field: str) -> dict:
    """The stretch of unit time in which a stream ran at its last requested rate, from a unit's
    KF_UNIT_STATUS rows (``field``: raw_rate_requested, orientation_rate_requested; 0 is the
    stream off, not a rate): {"requested": the last nonzero requested rate (None: no status
    said the stream was on), "from_us": its samples are those after this device time (None:
    from the start), "from_inclusive": at it too, "until_us": ... and before this one (None: to
    the end), "changes": changes between nonzero rates, "restarts": times the stream was on,
    off and on again, "off_at_us": the time of the last status when it says off (else None)}.
    Statuses before the unit's last reboot (its clock went back) are not compared with those
    after.

    The last status of a ``record --start`` often comes after the stop and says 0: that was
    counted as a change of the requested rate, the rate measured from it on (no samples: none)
    and the 0 taken for a missing value (the header's --rate shown as requested)."""
    t = status_rows["time_boot_us"].astype(np.int64)
    # the last device-clock segment without repeats: a status delivered again after the rate
    # change was taken for a reboot, so the change was dated at the next status after it
    last, fresh = _last_segment(t)
    rows = status_rows[last][fresh]
    rows = rows[np.argsort(rows["time_boot_us"].astype(np.int64), kind="stable")]
    r = rows[field].astype(np.float64)
    times = rows["time_boot_us"].astype(np.int64)
    out = {"requested": None, "from_us": None, "from_inclusive": True, "until_us": None, "changes": 0,
           "restarts": 0, "off_at_us": None}
    if not r.size:
        return out
    if r[-1] == 0:
        out["off_at_us"] = int(times[-1])
    starts = np.flatnonzero(np.r_[True, r[1:] != r[:-1]])       # runs of statuses with one value
    vals = r[starts]
    on = np.flatnonzero(vals != 0)
    if not on.size:
        return out
    rates = vals[on]
    out["changes"] = int(np.count_nonzero(rates[1:] != rates[:-1]))
    # an off run with on runs before and after it (neighbouring runs differ, so are nonzero)
    out["restarts"] = int(np.count_nonzero(vals[1:-1] == 0))
    k = int(on[-1])
    out["requested"] = float(vals[k])
    a = int(starts[k])
    if k > 0:
        if vals[k - 1] == 0:
            # off at the status before: every sample after it is at the new rate
            out["from_us"], out["from_inclusive"] = int(times[a - 1]), False
        else:
            # the change happened between the two statuses: from the first one with the new
            # value, the stream surely runs at it
            out["from_us"] = int(times[a])
    if k + 1 < starts.size:         # the run after it says off: the stream stopped before it
        out["until_us"] = int(times[starts[k + 1]])
    return out


def _unit_stats(ds: DecodedStream, sysid: int, start_ns: int, header_stream: dict) -> dict:
    d = kinefuse_dialect()
    out: dict = {"sysid": sysid, "messages": {}}
    status = statuses = None
    if MSG_STATUS in ds.arrays:
        st = ds.arrays[MSG_STATUS]
        st = st[st["_sysid"] == sysid]
        if st.size:
            # the latest status by the unit's clock (not a late repeat of an older one)
            last, fresh = _last_segment(st["time_boot_us"].astype(np.int64))
            status, statuses = st[last][fresh][-1], st
            from kinefuse.host.link.recorder import firmware_version_text   # as decode and record say it
            out["firmware_version"] = firmware_version_text(int(status["firmware_version"]))
            out["dialect_hash"] = f"0x{int(status['dialect_hash']):08X}"
            out["dialect_match"] = int(status["dialect_hash"]) == DIALECT_HASH()
            out["unit_reported"] = {k: int(status[k]) for k in
                                    ("samples", "samples_dropped", "frames_dropped", "rejected_samples",
                                     "crc_errors", "unknown_messages", "param_rejects")}
            # the extension counters: known when the unit speaks this dialect or any of its
            # statuses carried them (an older firmware's 83-byte frames decode them as 0; a newer
            # one's may be as short when they are 0: MAVLink 2 drops trailing zeros)
            for k in STATUS_EXTENSIONS:
                known = out["dialect_match"] or ("_len" in st.dtype.names and
                                                 int(st["_len"].max()) > d.get(MSG_STATUS).dtype.fields[k][1])
                out["unit_reported"][k] = int(status[k]) if known else None
            out["unit_reported"]["battery_voltage_V"] = (None if int(status["battery_voltage"]) == 0xFFFF
                                                         else int(status["battery_voltage"]) / 1000)
    requested_header = header_stream.get("requested_rates_hz", {}) if header_stream else {}
    clock_ref = None
    for mid, arr in sorted(ds.arrays.items()):
        rows = arr["_sysid"] == sysid
        if not rows.any():
            continue
        a = arr[rows]
        spec = d.get(mid)
        m: dict = {"count": int(a.size)}
        run = None
        if statuses is not None and mid in REQUESTED_FIELD:
            run = _requested_run(statuses, REQUESTED_FIELD[mid])
        if "time_boot_us" in a.dtype.names and a.size >= 2:
            counter = a["sample_counter"] if "sample_counter" in a.dtype.names else None
            last, fresh = _last_segment(a["time_boot_us"], counter)
            seg = a[last][fresh]        # repeats are not samples of the rate
            if run is not None:
                ts = seg["time_boot_us"].astype(np.int64)
                # off at the end: the last status says so and no sample (since the unit's last
                # reboot) came after it
                if run["off_at_us"] is not None and not np.any(ts >= run["off_at_us"]):
                    m["stopped_at_end"] = True
                if run["changes"]:
                    m["requested_changes"] = run["changes"]
                if run["restarts"]:
                    m["restarts"] = run["restarts"]
                if run["from_us"] is not None:
                    if run["changes"] or run["restarts"]:
                        m["rate_from_device_s"] = run["from_us"] / 1e6
                    seg = seg[ts >= run["from_us"] if run["from_inclusive"] else ts > run["from_us"]]
                    ts = seg["time_boot_us"].astype(np.int64)
                if run["until_us"] is not None:
                    m["rate_until_device_s"] = run["until_us"] / 1e6
                    seg = seg[ts < run["until_us"]]
            t = seg["time_boot_us"].astype(np.int64)
            span = (t.max() - t.min()) / 1e6 if t.size >= 2 else 0.0   # a swapped frame may be first or last
            if span > 0:
                m["rate_hz"] = (seg.size - 1) / span
                m["device_span_s"] = span
            if "sample_counter" in a.dtype.names:
                m.update(sample_loss(a["time_boot_us"], a["sample_counter"]))
            mixed = interleaved_clocks(a["time_boot_us"], counter)
            if mixed is not None:
                m["interleaved_clocks"] = mixed
                if not any("same system id" in w for w in out.get("warnings", [])):   # once per unit
                    out.setdefault("warnings", []).append(
                        interleaved_text(sysid, spec.name if spec else str(mid), mixed))
        # the last nonzero rate the unit's statuses asked for (0 is the stream off: was taken
        # for a missing value, so the header's --rate showed instead of the rate the unit granted)
        req = None if run is None else run["requested"]
        if req is None and spec is not None:
            req = requested_header.get(spec.name)
        if req:
            m["requested_hz"] = req
            if "rate_hz" in m:
                m["rate_ratio"] = m["rate_hz"] / req
        out["messages"][spec.name if spec else str(mid)] = m
        if clock_ref is None and mid in (MSG_RAW, MSG_ORI, 52502, 52503) and ds.host_ns.get(mid) is not None:
            clock_ref = mid
    if clock_ref is not None:
        arr = ds.arrays[clock_ref]
        rows = arr["_sysid"] == sysid
        t_us = arr["time_boot_us"][rows]
        counter = arr["sample_counter"][rows] if "sample_counter" in arr.dtype.names else None
        seg, fresh = _last_segment(t_us, counter)
        jumps = clock_jumps(t_us, counter) if counter is not None else ()
        if len(jumps):
            by = (int(t_us[jumps[0]]) - int(t_us[jumps[0] - 1])) / 1e6
            out.setdefault("warnings", []).append(
                f"unit {sysid}: its clock jumped forward {len(jumps)} time(s) with the sample counter running on "
                f"(first by {by:,.1f} s): rate and clock fit are those of the last clock segment")
        host = (ds.host_ns[clock_ref][rows][seg][fresh] - start_ns) / 1e9
        fit = fit_clock_checked(t_us[seg][fresh].astype(np.float64) / 1e6, host)
        if fit is not None:
            fit["reference"] = d.get(clock_ref).name
            out["clock"] = fit
            out.setdefault("warnings", []).extend(f"unit {sysid}: {w}" for w in fit["warnings"])
    if MSG_TIMESYNC in ds.arrays and ds.host_ns.get(MSG_TIMESYNC) is not None:
        ts = ds.arrays[MSG_TIMESYNC]
        sel = (ts["_sysid"] == sysid) & (ts["tc1"] != 0)
        rtt = (ds.host_ns[MSG_TIMESYNC][sel] - ts["ts1"][sel]) / 1e6
        rtt = rtt[(rtt > 0) & (rtt < 10_000)]
        if rtt.size:
            lat = {"timesync_rtt_ms": {"min": float(rtt.min()), "median": float(np.median(rtt)),
                                       "p95": float(np.percentile(rtt, 95)), "count": int(rtt.size)}}
            excess = out.get("clock", {}).get("delay_above_min_ms", {}).get("median", 0.0)
            lat["one_way_estimate_ms"] = float(rtt.min() / 2 + excess)
            out["latency"] = lat
    return out


def crc_extra_mismatches(rx: bytes, check: int = 64, accepted=None) -> list[dict]:
    """Messages whose frames fail their CRC with this dialect's CRC_EXTRA but check with one
    other CRC_EXTRA: a unit built with another version of the message.  Its frames were only
    "CRC errors" (all of them dropped, no reason given).  Up to ``check`` failing candidates
    per message id are tried with all 256 CRC_EXTRA values; a mismatch needs at least 3 of
    them (and a quarter) to agree on one (a random candidate matches some value with
    probability 1/256).  ``accepted``: start offsets of the frames decoded (not checked again).
    [{"message", "failed", "crc_extra", "crc_extra_found"}]."""
    from kinefuse.host.link.batch import _crc_ok
    from kinefuse.host.link.crc import TABLE_NP, x25
    extras = np.arange(256)
    d = kinefuse_dialect()
    arr = np.frombuffer(rx, np.uint8)
    n = arr.size
    if n < 12:
        return []
    pos = np.flatnonzero(arr[:n - 11] == 0xFD)
    pos = pos[arr[pos + 2] <= 1]
    if accepted is not None and len(accepted):
        pos = pos[~np.isin(pos, accepted)]
    msgid = (arr[pos + 7].astype(np.int64) | (arr[pos + 8].astype(np.int64) << 8)
             | (arr[pos + 9].astype(np.int64) << 16))
    out = []
    for mid in np.unique(msgid[np.isin(msgid, np.fromiter(d.ids, np.int64))]):
        spec = d.get(int(mid))
        p = pos[msgid == mid]
        plen = arr[p + 1].astype(np.int64)
        stop = p + 12 + plen + np.where(arr[p + 2] == 1, 13, 0)
        sel = (plen >= 1) & (stop <= n)   # longer payloads are decoded (truncated) too
        p, plen = p[sel], plen[sel]
        if not p.size:
            continue
        bad = ~_crc_ok(arr, p, plen, spec.crc_extra)
        if not bad.any():
            continue
        found: dict = {}
        tried = 0
        for q, ln in zip(p[bad][:check], plen[bad][:check]):
            q, ln = int(q), int(ln)
            body, got = rx[q + 1:q + 10 + ln], rx[q + 10 + ln] | (rx[q + 11 + ln] << 8)
            tried += 1
            # the body's CRC once, then the last step (the CRC_EXTRA byte) for all 256 values
            c = x25(body)      # the register (MCRF4XX has no final xor)
            for e in np.flatnonzero(((c >> 8) ^ TABLE_NP[(c ^ extras) & 0xFF]) == got):
                found[int(e)] = found.get(int(e), 0) + 1
        if found:
            e, k = max(found.items(), key=lambda kv: kv[1])
            if k >= 3 and 4 * k >= tried:
                out.append({"message": spec.name, "failed": int(bad.sum()), "crc_extra": spec.crc_extra,
                            "crc_extra_found": e})
    return out


def crc_extra_text(m: dict) -> str:
    return (f"{m['failed']:,} {m['message']} frame(s) fail their CRC with this kinefuse's CRC_EXTRA "
            f"{m['crc_extra']} but check with {m['crc_extra_found']}: the unit was built with another version "
            f"of this message (a dialect mismatch), so they are dropped; update the unit's firmware or kinefuse")


def header_rates_checked(info) -> tuple[dict, str | None]:
    """A stream's header entry with its ``requested_rates_hz`` (the recorder's --rate: message
    name -> Hz) checked: anything but a mapping of names to positive finite numbers (a damaged
    header whose text still reads) is left out, with a warning (it was a traceback)."""
    if not isinstance(info, dict):
        return {}, None
    rates = info.get("requested_rates_hz")
    if rates is None or (isinstance(rates, dict) and all(
            isinstance(k, str) and isinstance(v, (int, float)) and not isinstance(v, bool)
            and math.isfinite(v) and v > 0 for k, v in rates.items())):
        return info, None
    clean = {k: v for k, v in info.items() if k != "requested_rates_hz"}
    shown = repr(rates)
    shown = shown if len(shown) <= 60 else shown[:57] + "..."
    return clean, (f"the header's requested_rates_hz is not a map of message names to rates in Hz "
                   f"({shown}): ignored (a damaged header?)")


def compute(df: DecodedFile) -> dict:
    start = df.start_monotonic_ns
    header = df.header
    result = {"file": str(df.path), "format": header.get("format"), "start_utc": header.get("start_utc"),
              "streams": [], "warnings": []}
    rec = df.recording
    if rec is not None:
        result["file_damage"] = {"chunks": rec.chunks, "damaged_chunks": rec.damaged_chunks,
                                 "recovered_chunks": rec.recovered_chunks,
                                 "skipped_bytes": rec.skipped_bytes, "truncated": rec.truncated}
        if rec.damaged_chunks:
            result["warnings"].append(damage_text(rec))
        if rec.truncated:
            result["warnings"].append("the recording is truncated (ends inside a chunk): read up to the cut")
        for sid, sd in rec.streams.items():
            for m in sd.meta:
                if m.get("type") in ("warning", "error") and m.get("text"):
                    result["warnings"].append(f"recorder {m['type']} (stream {sid}): {m['text']}")
    for sid, ds in sorted(df.streams.items()):
        s = {"id": sid, "connection": ds.info.get("connection"), "bytes": ds.rx_bytes, **ds.counters.as_dict()}
        s.pop("bytes_in", None)
        s["unknown_ids"] = dict(sorted(ds.unknown_ids.items()))
        t_all = [h for h in ds.host_ns.values() if h is not None and h.size]
        if t_all:
            lo = min(int(h.min()) for h in t_all)
            hi = max(int(h.max()) for h in t_all)
            s["host_span_s"] = (hi - lo) / 1e9
        sysids = sorted({int(x) for arr in ds.arrays.values() for x in np.unique(arr["_sysid"])})
        info, bad = header_rates_checked(ds.info)
        if bad:
            result["warnings"].append(f"stream {sid}: {bad}")
        units = [_unit_stats(ds, sysid, start, info) for sysid in sysids]
        s["units"] = [u for u in units if any(k in KF_NAMES for k in u["messages"]) or "firmware_version" in u] \
            or units
        s["other_systems"] = [u["sysid"] for u in units if u not in s["units"]]
        s["statustexts"] = statustexts(ds, start)
        mm = stream_crc_extra_mismatches(df, sid)
        if mm is not None:
            s["crc_extra_mismatch"] = mm
            result["warnings"].extend(f"stream {sid}: {crc_extra_text(m)}" for m in mm)
        for u in s["units"]:
            result["warnings"].extend(f"stream {sid} {w}" for w in u.get("warnings", []))
        result["streams"].append(s)
    return result


def stream_crc_extra_mismatches(df: DecodedFile, sid: int) -> list | None:
    """:func:`crc_extra_mismatches` of one stream of a decoded file; None without CRC errors."""
    ds = df.streams[sid]
    if not ds.counters.crc_errors:
        return None
    accepted = np.concatenate([a["_offset"] for a in ds.arrays.values()] or [np.zeros(0, np.int64)])
    if df.recording is not None:
        sd = df.recording.streams.get(sid)
        return crc_extra_mismatches(sd.rx, accepted=accepted) if sd is not None else None
    try:    # a raw capture or a tlog (one stream): its bytes are not kept, read them again
        return crc_extra_mismatches(df.path.read_bytes(), accepted=accepted)
    except OSError:
        return None


def damage_text(rec) -> str:
    """One line on the damaged chunks of a recording."""
    header = bool(getattr(rec, "header_damaged", False))   # counted in damaged_chunks
    chunks = rec.damaged_chunks - header
    skipped = chunks - rec.recovered_chunks
    parts = []
    if rec.recovered_chunks:
        parts.append(f"{rec.recovered_chunks} recovered (their intact frames kept, checked by the MAVLink CRCs)")
    if skipped:
        parts.append(f"{skipped} skipped ({rec.skipped_bytes:,} bytes lost)")
    text = f"{chunks} damaged chunk(s): " + ", ".join(parts) if chunks else ""
    if header:
        text = ("the file header is damaged (its CRC fails; its text still reads and is used: host times and "
                "stream descriptions may be off)" + (f"; {text}" if text else ""))
    return text


KF_NAMES = ("KF_RAW_SAMPLE", "KF_ORIENTATION", "KF_JOINT_ANGLE", "KF_EFFORTS", "KF_UNIT_STATUS")
