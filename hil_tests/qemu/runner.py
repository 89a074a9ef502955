"""Run Cortex-M ELF files under ``qemu-system-arm`` (MPS2 boards).

Channels between the host and the emulated program:

* **semihosting** (always enabled): the program's ``:tt`` handle (``printf`` with newlib's
  rdimon, ``kf_sh_write``) is QEMU's stdout, reads from ``:tt`` come from QEMU's stdin, host
  files open relative to the working directory, ``kf_sh_write0`` goes to a separate console
  capture, and ``kf_sh_exit(status)`` ends QEMU with that exit status.
* **UART0** (CMSDK APB UART, ``kf_hal_uart_*``): in :func:`run_elf` over a loopback TCP
  connection that this module accepts; in :class:`QemuSession` as a socket, as a TCP server
  port a host tool connects to (``tcp:127.0.0.1:PORT``, e.g. pymavlink), or as a pty.

Only loopback addresses are used.
"""
from __future__ import annotations

import os
import re
import shutil
import socket
import subprocess
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Sequence

from kinefuse.firmware.targets import Target, get_target
from kinefuse.host.errors import KinefuseError

QEMU = "qemu-system-arm"


class QemuError(KinefuseError):
    """QEMU is missing, failed to start, timed out or the program failed."""


def qemu_missing() -> str | None:
    """None when qemu-system-arm is installed, else a one-line reason (for test skips)."""
    if shutil.which(QEMU) is None:
        return f"{QEMU} not installed (apt-get install qemu-system-arm)"
    return None


@dataclass
class RunResult:
    """What an emulated program produced.

    ``exit_code`` is the status passed to semihosting exit (``main``'s return value), None if
    QEMU was killed at the timeout.  ``stdout``: semihosting ``:tt`` output; ``console``:
    ``kf_sh_write0`` output; ``uart``: bytes sent on UART0 (when captured); ``stderr``: QEMU's
    own messages and semihosting ``:tt`` opened for append.
    """

    exit_code: int | None
    stdout: bytes
    stderr: bytes
    console: bytes
    uart: bytes
    wall_s: float
    timed_out: bool
    command: list[str] = field(default_factory=list)

    def check(self, what: str = "program") -> "RunResult":
        """Raise :class:`QemuError` unless the program exited with status 0."""
        if self.timed_out:
            raise QemuError(f"{what} timed out after {self.wall_s:.1f} s under QEMU")
        if self.exit_code != 0:
            detail = (self.console + self.stderr).decode(errors="replace").strip().splitlines()
            tail = f": {detail[-1]}" if detail else ""
            raise QemuError(f"{what} exited with status {self.exit_code} under QEMU{tail}")
        return self


def _need_elf(elf: str | os.PathLike) -> None:
    """One-line QemuError for a missing image (QEMU's own 'Could not load kernel' comes as an
    exit status, after a start-up, and reads like an emulator fault)."""
    if not Path(elf).is_file():
        raise QemuError(f"firmware image {elf} does not exist: build it first "
                        "(e.g. python -m kinefuse.firmware.build)")


def qemu_command(elf: str | os.PathLike, target: str | Target, *,
                 serial: str = "null",
                 semihosting_args: Sequence[str] = (),
                 console_path: str | os.PathLike | None = None,
                 plugin: str | None = None,
                 extra_args: Sequence[str] = ()) -> list[str]:
    """The qemu-system-arm command line for ``elf`` on ``target``'s MPS2 machine.

    ``serial`` is QEMU's -serial backend for UART0 (``null``, ``pty``, ``tcp:...``).
    ``semihosting_args`` become the program's semihosting command line (argv[0] first).
    ``plugin`` is a ``-plugin`` specification (``path.so,arg=...``).
    """
    tgt = get_target(target)
    sh = "enable=on,target=native"
    cmd = [QEMU, "-M", tgt.machine, "-display", "none", "-monitor", "none", "-serial", serial]
    if console_path is not None:
        cmd += ["-chardev", f"file,id=kfcon,path={_qemu_escape(str(console_path))}"]
        sh += ",chardev=kfcon"
    for a in semihosting_args:
        sh += f",arg={_qemu_escape(a)}"
    cmd += ["-semihosting-config", sh]
    if plugin:
        cmd += ["-plugin", plugin]
    cmd += list(extra_args) + ["-kernel", str(elf)]
    return cmd


def run_elf(elf: str | os.PathLike, target: str | Target, *,
            stdin: bytes = b"",
            uart_input: bytes | None = None,
            capture_uart: bool = False,
            timeout: float = 30.0,
            cwd: str | os.PathLike | None = None,
            args: Sequence[str] = (),
            plugin: str | None = None,
            extra_args: Sequence[str] = ()) -> RunResult:
    """Run ``elf`` to completion (semihosting exit) or until ``timeout`` seconds.

    Args:
        stdin: bytes the program reads from semihosting ``:tt``.
        uart_input: bytes fed to UART0 (implies ``capture_uart``); they are written as fast as
            the emulated UART takes them.
        capture_uart: collect what the program sends on UART0 into ``RunResult.uart``.
        cwd: working directory for semihosting file access (default: a temporary one).
        args: semihosting command line after argv[0].
        plugin: ``-plugin`` specification (see :mod:`kinefuse.hil_tests.qemu.insn`).

    Never raises for a failing program: inspect the result or call ``.check()``.
    """
    reason = qemu_missing()
    if reason:
        raise QemuError(reason)
    _need_elf(elf)
    tmp = tempfile.TemporaryDirectory(prefix="kf-qemu-")
    try:
        console_path = Path(tmp.name) / "console.txt"
        listener = None
        serial = "null"
        if uart_input is not None or capture_uart:
            listener = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
            listener.bind(("127.0.0.1", 0))
            listener.listen(1)
            serial = f"tcp:127.0.0.1:{listener.getsockname()[1]}"
        cmd = qemu_command(elf, target, serial=serial, console_path=console_path,
                           semihosting_args=[Path(elf).name, *args], plugin=plugin,
                           extra_args=extra_args)
        t0 = time.perf_counter()
        proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, cwd=str(cwd or tmp.name))
        uart_pump = None
        if listener is not None:
            uart_pump = _UartPump(listener, uart_input or b"", timeout)
            uart_pump.start()
        timed_out = False
        try:
            out, err = proc.communicate(stdin, timeout=timeout)
        except subprocess.TimeoutExpired:
            timed_out = True
            proc.kill()
            out, err = proc.communicate()
        wall = time.perf_counter() - t0
        uart = b""
        if uart_pump is not None:
            uart_pump.join(5.0)
            uart = bytes(uart_pump.received)
            listener.close()
        console = console_path.read_bytes() if console_path.exists() else b""
        return RunResult(None if timed_out else proc.returncode, out, err, console, uart, wall,
                         timed_out, cmd)
    finally:
        tmp.cleanup()


class _UartPump(threading.Thread):
    """Accepts QEMU's UART connection, sends the input and collects output until EOF."""

    def __init__(self, listener: socket.socket, data: bytes, timeout: float):
        super().__init__(daemon=True)
        self.listener, self.data, self.timeout = listener, data, timeout
        self.received = bytearray()

    def run(self) -> None:
        self.listener.settimeout(self.timeout)
        try:
            conn, _ = self.listener.accept()
        except OSError:
            return
        with conn:
            if self.data:
                threading.Thread(target=self._send, args=(conn,), daemon=True).start()
            conn.settimeout(self.timeout)
            while True:
                try:
                    chunk = conn.recv(65536)
                except OSError:
                    return
                if not chunk:
                    return
                self.received += chunk

    def _send(self, conn: socket.socket) -> None:
        try:
            conn.sendall(self.data)
        except OSError:
            pass


class QemuSession:
    """A long-running emulated board whose UART0 a host program talks to.

    ``uart`` selects how UART0 is exposed:

    * ``"socket"``: this object holds the connection; use :meth:`write`, :meth:`read`,
      :meth:`read_until` (tests).
    * ``"tcp"``: QEMU listens on ``127.0.0.1:<port>``; ``uart_url`` is ``tcp:127.0.0.1:<port>``
      (pymavlink's ``mavutil.mavlink_connection(uart_url)`` or any TCP client).  QEMU holds the
      guest until the first client connects, so no early byte is lost.
    * ``"pty"``: ``uart_device`` is a ``/dev/pts/N`` path for pyserial and other serial tools.

      QEMU drops pty output while no program has the device open, so pass ``paused=True``,
      open ``uart_device``, then call :meth:`resume` if the firmware talks first.

    ``paused=True`` starts the CPU halted (QEMU ``-S``) until :meth:`resume`.
    Use as a context manager; leaving it stops QEMU.  ``stdout``/``console`` hold semihosting
    output after :meth:`stop` or :meth:`wait`.
    """

    def __init__(self, elf: str | os.PathLike, target: str | Target, *, uart: str = "socket",
                 args: Sequence[str] = (), extra_args: Sequence[str] = (),
                 start_timeout: float = 10.0, paused: bool = False):
        if uart not in ("socket", "tcp", "pty"):
            raise KinefuseError(f"uart must be 'socket', 'tcp' or 'pty', not {uart!r}")
        self.elf, self.target, self.mode = Path(elf), get_target(target), uart
        self.args, self.extra_args, self.start_timeout = list(args), list(extra_args), start_timeout
        self.paused = paused
        self.uart_url: str | None = None
        self.uart_device: str | None = None
        self.proc: subprocess.Popen | None = None
        self.exit_code: int | None = None
        self._sock: socket.socket | None = None
        self._tmp: tempfile.TemporaryDirectory | None = None
        self._out, self._err = bytearray(), bytearray()
        self._rx = bytearray()
        self._threads: list[threading.Thread] = []

    # -- life cycle ---------------------------------------------------------------------------
    def start(self) -> "QemuSession":
        reason = qemu_missing()
        if reason:
            raise QemuError(reason)
        _need_elf(self.elf)
        self._tmp = tempfile.TemporaryDirectory(prefix="kf-qemu-")
        listener = None
        if self.mode == "socket":
            listener = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
            listener.bind(("127.0.0.1", 0))
            listener.listen(1)
            serial = f"tcp:127.0.0.1:{listener.getsockname()[1]}"
        elif self.mode == "tcp":
            port = _free_port()
            serial = f"tcp:127.0.0.1:{port},server=on,wait=on"
            self.uart_url = f"tcp:127.0.0.1:{port}"
        else:
            serial = "pty"
        extra = list(self.extra_args)
        if self.paused:
            self._qmp_path = Path(self._tmp.name) / "qmp.sock"
            extra += ["-S", "-qmp", f"unix:{_qemu_escape(str(self._qmp_path))},server=on,wait=off"]
        cmd = qemu_command(self.elf, self.target, serial=serial,
                           console_path=Path(self._tmp.name) / "console.txt",
                           semihosting_args=[self.elf.name, *self.args], extra_args=extra)
        self.command = cmd
        self.proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE, cwd=self._tmp.name)
        self._threads = [threading.Thread(target=_drain, args=(self.proc.stdout, self._out), daemon=True),
                         threading.Thread(target=_drain, args=(self.proc.stderr, self._err), daemon=True)]
        for t in self._threads:
            t.start()
        deadline = time.monotonic() + self.start_timeout
        if listener is not None:
            listener.settimeout(self.start_timeout)
            try:
                self._sock, _ = listener.accept()
            except OSError:
                self.stop()
                raise QemuError(f"QEMU did not connect its UART within {self.start_timeout} s") from None
            finally:
                listener.close()
        elif self.mode == "pty":
            while time.monotonic() < deadline:
                m = re.search(rb"char device redirected to (\S+) \(label serial0\)",
                              bytes(self._out) + bytes(self._err))
                if m:
                    self.uart_device = m.group(1).decode()
                    break
                if self.proc.poll() is not None:
                    break
                time.sleep(0.01)
            if self.uart_device is None:
                self.stop()
                raise QemuError("QEMU did not report its pty: " + bytes(self._err).decode(errors="replace").strip()[:200])
        else:
            while b"QEMU waiting for connection" not in self._err:
                if self.proc.poll() is not None:
                    for t in self._threads:
                        t.join(1.0)
                    err = bytes(self._err).decode(errors="replace").strip()
                    self.stop()
                    raise QemuError("QEMU exited at start: " + (err.splitlines() or ["no message"])[-1][:200])
                if time.monotonic() >= deadline:
                    self.stop()
                    raise QemuError(f"QEMU did not open its UART port within {self.start_timeout} s")
                time.sleep(0.01)
        return self

    def resume(self, timeout: float = 10.0) -> None:
        """Start the CPU of a session created with ``paused=True`` (QMP ``cont``)."""
        if not self.paused:
            return
        deadline = time.monotonic() + timeout
        while True:
            try:
                qmp = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
                qmp.connect(str(self._qmp_path))
                break
            except OSError:
                qmp.close()
                if time.monotonic() > deadline:
                    raise QemuError("QEMU's QMP socket did not open") from None
                time.sleep(0.01)
        with qmp:
            qmp.settimeout(timeout)
            reader = qmp.makefile("rb")
            reader.readline()                                   # greeting
            for command in (b'{"execute": "qmp_capabilities"}\n', b'{"execute": "cont"}\n'):
                qmp.sendall(command)
                while b'"return"' not in (line := reader.readline()):
                    if not line:
                        raise QemuError("QMP connection closed before 'cont' was acknowledged")
        self.paused = False

    def __enter__(self) -> "QemuSession":
        return self.start()

    def __exit__(self, *exc) -> None:
        self.stop()

    def wait(self, timeout: float) -> int | None:
        """Wait for the program to exit; returns its status or None on timeout."""
        assert self.proc is not None
        try:
            self.exit_code = self.proc.wait(timeout)
        except subprocess.TimeoutExpired:
            return None
        for t in self._threads:
            t.join(1.0)
        return self.exit_code

    def stop(self) -> None:
        """Stop QEMU (kill if still running) and release the UART."""
        if self._sock is not None:
            self._sock.close()
            self._sock = None
        if self.proc is not None and self.proc.poll() is None:
            self.proc.kill()
        if self.proc is not None:
            self.exit_code = self.proc.wait()
            for t in self._threads:
                t.join(1.0)
            console = Path(self._tmp.name) / "console.txt" if self._tmp else None
            self._console = console.read_bytes() if console and console.exists() else b""
        if self._tmp is not None:
            self._tmp.cleanup()
            self._tmp = None

    # -- output ------------------------------------------------------------------------------
    @property
    def stdout(self) -> bytes:
        return bytes(self._out)

    @property
    def stderr(self) -> bytes:
        return bytes(self._err)

    @property
    def console(self) -> bytes:
        if self._tmp is not None:
            p = Path(self._tmp.name) / "console.txt"
            return p.read_bytes() if p.exists() else b""
        return getattr(self, "_console", b"")

    # -- UART (socket mode) --------------------------------------------------------------------
    def _need_socket(self) -> socket.socket:
        if self._sock is None:
            raise KinefuseError("UART read/write needs a running session with uart='socket'")
        return self._sock

    def write(self, data: bytes) -> None:
        """Send bytes to the program's UART0."""
        self._need_socket().sendall(data)

    def read(self, n: int, timeout: float = 5.0) -> bytes:
        """Read exactly ``n`` UART bytes (fewer only at timeout or end of connection)."""
        sock = self._need_socket()
        deadline = time.monotonic() + timeout
        while len(self._rx) < n:
            left = deadline - time.monotonic()
            if left <= 0:
                break
            sock.settimeout(left)
            try:
                chunk = sock.recv(65536)
            except socket.timeout:
                break
            if not chunk:
                break
            self._rx += chunk
        out, self._rx = bytes(self._rx[:n]), self._rx[n:]
        return out

    def read_until(self, marker: bytes, timeout: float = 5.0) -> bytes:
        """Read UART bytes up to and including ``marker`` (or what arrived by the timeout)."""
        sock = self._need_socket()
        deadline = time.monotonic() + timeout
        while marker not in self._rx:
            left = deadline - time.monotonic()
            if left <= 0:
                break
            sock.settimeout(left)
            try:
                chunk = sock.recv(65536)
            except socket.timeout:
                break
            if not chunk:
                break
            self._rx += chunk
        i = self._rx.find(marker)
        end = len(self._rx) if i < 0 else i + len(marker)
        out, self._rx = bytes(self._rx[:end]), self._rx[end:]
        return out


def _drain(stream, sink: bytearray) -> None:
    for chunk in iter(lambda: stream.read1(65536), b""):
        sink += chunk


def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _qemu_escape(value: str) -> str:
    """QEMU option values escape a comma by doubling it."""
    return value.replace(",", ",,")
