"""Byte connections to units: serial, pty, TCP, UDP, files; a reader thread with real timeouts.

Connection strings::

    /dev/ttyUSB0  COM3  serial:/dev/ttyACM0[:BAUD]   serial port (pyserial), --baud or BAUD
    pty:/dev/pts/7                                   an existing tty opened raw, input NOT flushed
    tcp:127.0.0.1:5760                               TCP client
    tcpin:127.0.0.1:5760                             TCP server: waits for the unit (e.g. QEMU
                                                     -serial tcp:127.0.0.1:5760) to connect
    udp:127.0.0.1:14550 / udpin:...                  UDP, listen (replies go to the last sender)
    udpout:127.0.0.1:14550                           UDP, send to
    file:capture.bin                                 raw bytes from a file (replay)
    fake:rate=500,unit=2                             a simulated unit in this process (demos)

Why not just pyserial: ``Serial.open()`` and ``socket://`` discard input already waiting, and
``read(n)`` raises on a disconnect and drops what it had gathered.  On POSIX we therefore read
the file descriptor ourselves (``select`` + ``os.read``: returns whatever is available, no busy
wait, a real timeout), open ptys without flushing, and let a pty pair we create keep its slave
end open so a simulated unit can start writing before or after we read.
"""
from __future__ import annotations

import errno
import os
import queue
import select
import socket
import sys
import threading
import time
from dataclasses import dataclass
from pathlib import Path

from kinefuse.host.errors import KinefuseError

DEFAULT_BAUD = 921600
READ_SIZE = 1 << 16
POSIX = os.name == "posix"


class ConnectionClosed(EOFError):
    """The other end went away (pty closed, cable pulled, socket closed, end of file)."""


class Connection:
    """A byte pipe.  ``read(timeout)`` returns what is available (b"" on timeout)."""

    url = ""

    def read(self, timeout: float) -> bytes:
        raise NotImplementedError

    def write(self, data: bytes) -> None:
        raise NotImplementedError

    def close(self) -> None:
        pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def describe(self) -> dict:
        return {"connection": self.url}


# --------------------------------------------------------------------------- POSIX descriptors
class FdConnection(Connection):
    """A POSIX file descriptor (tty, pty master/slave) in non-blocking mode."""

    def __init__(self, fd: int, url: str, owns_fd: bool = True, extra_fds: tuple = ()):
        self.fd, self.url, self._owns = fd, url, owns_fd
        self._extra = list(extra_fds)
        os.set_blocking(fd, False)
        self._closed = False

    def read(self, timeout: float) -> bytes:
        if self._closed:
            raise ConnectionClosed(self.url)
        try:
            r, _, _ = select.select([self.fd], [], [], max(0.0, timeout))
        except (OSError, ValueError):
            raise ConnectionClosed(self.url) from None
        if not r:
            return b""
        try:
            data = os.read(self.fd, READ_SIZE)
        except BlockingIOError:
            return b""
        except OSError as exc:
            if exc.errno == errno.EIO:  # pty: the other side closed
                raise ConnectionClosed(self.url) from None
            raise
        if not data:
            raise ConnectionClosed(self.url)
        return data

    def write(self, data: bytes) -> None:
        view = memoryview(data)
        deadline = time.monotonic() + 5.0
        while view:
            try:
                n = os.write(self.fd, view)
                view = view[n:]
            except BlockingIOError:
                if time.monotonic() > deadline:
                    raise TimeoutError(f"{self.url}: write timed out (is the unit reading?)") from None
                select.select([], [self.fd], [], 0.05)

    def close(self) -> None:
        if self._closed:
            return
        self._closed = True
        for fd in ([self.fd] if self._owns else []) + self._extra:
            try:
                os.close(fd)
            except OSError:
                pass


def _raw_tty(fd: int) -> None:
    import termios
    import tty
    tty.setraw(fd, termios.TCSANOW)


def open_tty_raw(path: str) -> FdConnection:
    """Open an existing tty/pty raw, without discarding input already waiting."""
    try:
        fd = os.open(path, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
    except OSError as exc:
        raise KinefuseError(f"cannot open {path}: {exc.strerror}") from None
    try:
        _raw_tty(fd)
    except Exception:
        os.close(fd)
        raise KinefuseError(f"{path} is not a terminal device") from None
    return FdConnection(fd, f"pty:{path}")


@dataclass
class PtyPair:
    """A pseudo-terminal pair: the host reads ``host``; the unit (simulator, QEMU) opens ``device_path``."""
    host: FdConnection
    device_path: str


def create_pty_pair() -> PtyPair:
    """Host side open first, so nothing the unit writes is lost; both ends raw (no echo, no CR/LF)."""
    if not POSIX:
        raise KinefuseError("pty connections need a POSIX system")
    master, slave = os.openpty()
    _raw_tty(master)
    _raw_tty(slave)
    path = os.ttyname(slave)
    # keep our slave descriptor open: the master then never sees EIO while the unit (re)opens it
    return PtyPair(FdConnection(master, f"pty-master:{path}", extra_fds=(slave,)), path)


# ------------------------------------------------------------------------------------ serial
class SerialConnection(Connection):
    def __init__(self, port: str, baud: int):
        import serial
        self.url = f"serial:{port}:{baud}"
        self.port, self.baud = port, baud
        try:
            kw = {"exclusive": True} if POSIX else {}
            self.ser = serial.Serial(port=port, baudrate=baud, timeout=0, write_timeout=5, **kw)
        except ValueError as exc:
            raise KinefuseError(f"bad serial settings for {port}: {exc}") from None
        except serial.SerialException as exc:
            msg = str(exc)
            raise KinefuseError(f"cannot open serial port {port}: {msg.split(': ', 1)[-1] if msg else 'unknown error'}") from None
        self._fd = FdConnection(self.ser.fileno(), self.url, owns_fd=False) if POSIX else None

    def read(self, timeout: float) -> bytes:
        if self._fd is not None:
            return self._fd.read(timeout)
        import serial
        try:  # Windows: pyserial waits on an event with the timeout (no fileno there)
            self.ser.timeout = timeout
            data = self.ser.read(1)
            if data and self.ser.in_waiting:
                data += self.ser.read(self.ser.in_waiting)
            return data
        except serial.SerialException as exc:
            raise ConnectionClosed(f"{self.url}: {exc}") from None

    def write(self, data: bytes) -> None:
        if self._fd is not None:
            self._fd.write(data)
        else:
            self.ser.write(data)

    def close(self) -> None:
        try:
            self.ser.close()
        except Exception:
            pass

    def describe(self) -> dict:
        out = {"connection": self.url, "baud": self.baud}
        latency = ftdi_latency_timer_ms(self.port)
        if latency is not None:
            out["latency_timer_ms"] = latency
        return out


def ftdi_latency_timer_ms(port: str) -> int | None:
    """FTDI USB-serial latency timer (Linux sysfs); 16 ms by default, 1 ms is better for streaming."""
    name = Path(os.path.realpath(port)).name
    p = Path("/sys/bus/usb-serial/devices") / name / "latency_timer"
    try:
        return int(p.read_text().strip())
    except (OSError, ValueError):
        return None


def list_ports() -> list[dict]:
    """Serial ports with USB VID:PID, serial number, description (pyserial's comports)."""
    from serial.tools import list_ports as lp
    out = []
    for p in sorted(lp.comports(), key=lambda p: p.device):
        out.append({
            "device": p.device,
            "vid_pid": f"{p.vid:04X}:{p.pid:04X}" if p.vid is not None and p.pid is not None else None,
            "serial_number": p.serial_number,
            "manufacturer": p.manufacturer,
            "product": p.product,
            "description": p.description if p.description and p.description != "n/a" else None,
            "location": p.location,
            "latency_timer_ms": ftdi_latency_timer_ms(p.device),
        })
    return out


# ----------------------------------------------------------------------------------- sockets
class TcpConnection(Connection):
    def __init__(self, host: str, port: int, listen: bool = False, connect_timeout: float = 5.0):
        self.url = f"{'tcpin' if listen else 'tcp'}:{host}:{port}"
        self._server = None
        self._sock = None
        self._pending = b""
        try:
            if listen:
                self._server = socket.create_server((host, port))
                self._server.settimeout(0)
            else:
                self._sock = socket.create_connection((host, port), timeout=connect_timeout)
                self._sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        except OSError as exc:
            raise KinefuseError(f"cannot {'listen on' if listen else 'connect to'} {host}:{port}: "
                                f"{exc.strerror or exc}") from None

    @property
    def address(self) -> tuple:
        return (self._server or self._sock).getsockname()

    def _accept(self, timeout: float) -> bool:
        r, _, _ = select.select([self._server], [], [], max(0.0, timeout))
        if not r:
            return False
        self._sock, _ = self._server.accept()
        self._sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        if self._pending:
            self._sock.sendall(self._pending)
            self._pending = b""
        return True

    def read(self, timeout: float) -> bytes:
        if self._sock is None:
            if self._server is None:
                raise ConnectionClosed(self.url)
            t0 = time.monotonic()
            if not self._accept(timeout):
                return b""
            timeout = max(0.0, timeout - (time.monotonic() - t0))
        r, _, _ = select.select([self._sock], [], [], max(0.0, timeout))
        if not r:
            return b""
        try:
            data = self._sock.recv(READ_SIZE)
        except (ConnectionResetError, OSError):
            data = b""
        if not data:
            raise ConnectionClosed(self.url)
        return data

    def write(self, data: bytes) -> None:
        if self._sock is None:
            self._pending += bytes(data)  # sent when the unit connects
        else:
            self._sock.sendall(data)

    def close(self) -> None:
        for s in (self._sock, self._server):
            if s is not None:
                try:
                    s.close()
                except OSError:
                    pass
        self._sock = self._server = None


class SocketConnection(Connection):
    """A connected stream socket (socket pairs, accepted connections)."""

    def __init__(self, sock: socket.socket, url: str):
        self._sock, self.url = sock, url
        sock.setblocking(False)

    def read(self, timeout: float) -> bytes:
        try:
            r, _, _ = select.select([self._sock], [], [], max(0.0, timeout))
        except (OSError, ValueError):
            raise ConnectionClosed(self.url) from None
        if not r:
            return b""
        try:
            data = self._sock.recv(READ_SIZE)
        except BlockingIOError:
            return b""
        except OSError:
            data = b""
        if not data:
            raise ConnectionClosed(self.url)
        return data

    def write(self, data: bytes) -> None:
        view = memoryview(data)
        deadline = time.monotonic() + 5.0
        while view:
            try:
                view = view[self._sock.send(view):]
            except BlockingIOError:
                if time.monotonic() > deadline:
                    raise TimeoutError(f"{self.url}: write timed out") from None
                select.select([], [self._sock], [], 0.05)

    def close(self) -> None:
        try:
            self._sock.close()
        except OSError:
            pass


class UdpConnection(Connection):
    def __init__(self, host: str, port: int, listen: bool):
        self.url = f"{'udpin' if listen else 'udpout'}:{host}:{port}"
        self._sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self._peer = None if listen else (host, port)
        try:
            self._sock.bind((host, port) if listen else ("0.0.0.0", 0))
        except OSError as exc:
            raise KinefuseError(f"cannot bind UDP {host}:{port}: {exc.strerror or exc}") from None

    @property
    def address(self) -> tuple:
        return self._sock.getsockname()

    def read(self, timeout: float) -> bytes:
        r, _, _ = select.select([self._sock], [], [], max(0.0, timeout))
        if not r:
            return b""
        data, peer = self._sock.recvfrom(READ_SIZE)
        if self._peer is None or self.url.startswith("udpin"):
            self._peer = peer
        return data

    def write(self, data: bytes) -> None:
        if self._peer is not None:
            self._sock.sendto(data, self._peer)

    def close(self) -> None:
        self._sock.close()


# -------------------------------------------------------------------------------------- files
class FileConnection(Connection):
    """Raw bytes of a capture file, ``chunk`` bytes per read; then ConnectionClosed."""

    def __init__(self, path: str, chunk: int = 4096):
        self.url = f"file:{path}"
        try:
            self._f = open(path, "rb")
        except OSError as exc:
            raise KinefuseError(f"cannot open {path}: {exc.strerror or exc}") from None
        self._chunk = chunk

    def read(self, timeout: float) -> bytes:
        data = self._f.read(self._chunk)
        if not data:
            raise ConnectionClosed(self.url)
        return data

    def write(self, data: bytes) -> None:
        pass  # a file cannot answer

    def close(self) -> None:
        self._f.close()


# ---------------------------------------------------------------------------------- factory
def _host_port(rest: str, url: str, listen: bool = False) -> tuple[str, int]:
    host, sep, port = rest.rpartition(":")
    if not sep or not port.isdigit() or not (0 if listen else 1) <= int(port) < 65536:  # 0: any free port
        raise KinefuseError(f"bad connection string {url!r}: expected HOST:PORT")
    return host or "127.0.0.1", int(port)


def parse_baud(value) -> int:
    try:
        baud = int(value)
    except (TypeError, ValueError):
        raise KinefuseError(f"bad baud rate {value!r}: expected a positive integer such as 921600") from None
    if not 50 <= baud <= 20_000_000:
        raise KinefuseError(f"bad baud rate {baud}: expected 50 .. 20000000 (e.g. 115200, 921600)")
    return baud


def open_connection(url: str, baud: int = DEFAULT_BAUD) -> Connection:
    """Open a connection string (see module docstring); raises KinefuseError with one line."""
    if not url:
        raise KinefuseError("empty connection string")
    scheme, sep, rest = url.partition(":")
    scheme = scheme.lower() if sep else ""
    if scheme in ("tcp", "tcpin"):
        host, port = _host_port(rest, url, listen=scheme == "tcpin")
        return TcpConnection(host, port, listen=scheme == "tcpin")
    if scheme in ("udp", "udpin", "udpout"):
        host, port = _host_port(rest, url, listen=scheme != "udpout")
        return UdpConnection(host, port, listen=scheme != "udpout")
    if scheme == "file":
        return FileConnection(rest)
    if scheme == "fake":
        from kinefuse.host.link.fakeunit import FakeConnection
        return FakeConnection(rest)
    if scheme == "pty":
        return open_tty_raw(rest)
    if scheme == "serial":
        path, sep2, b = rest.rpartition(":")
        if sep2 and b.isdigit() and path:
            return SerialConnection(path, parse_baud(b))
        return SerialConnection(rest, parse_baud(baud))
    # a bare name: COM3, /dev/ttyUSB0, /dev/pts/4, or a capture file
    if sys.platform.startswith("win") or not os.path.exists(url):
        return SerialConnection(url, parse_baud(baud))
    if os.path.isfile(url):
        return FileConnection(url)
    if url.startswith("/dev/pts/"):
        return open_tty_raw(url)
    return SerialConnection(url, parse_baud(baud))


# ------------------------------------------------------------------------------ reader thread
EOF_MARK = object()


class Reader:
    """Drains a connection on a thread; ``get(timeout)`` returns [(host_t_ns, bytes), ...].

    The thread blocks in ``select`` (no busy wait).  When the connection ends, ``closed`` is
    set and ``error`` tells why (None for a clean end of file).
    """

    def __init__(self, conn: Connection, poll: float = 0.1):
        self.conn = conn
        self._q: queue.Queue = queue.Queue()
        self._stop = threading.Event()
        self._poll = poll
        self.closed = threading.Event()
        self.error: str | None = None
        self.bytes = 0
        # set once the first read returned: what was waiting at the open (a pty keeps it) is queued
        self.first_read = threading.Event()
        self._thread = threading.Thread(target=self._run, name=f"kf-reader {conn.url}", daemon=True)
        self._thread.start()

    def _run(self) -> None:
        try:
            while not self._stop.is_set():
                data = self.conn.read(self._poll)
                if data:
                    self.bytes += len(data)
                    self._q.put((time.monotonic_ns(), data))
                self.first_read.set()
        except ConnectionClosed:
            pass
        except Exception as exc:  # noqa: BLE001 - reported to the consumer, not lost
            self.error = f"{type(exc).__name__}: {exc}"
        finally:
            self.closed.set()
            self._q.put(EOF_MARK)
            self.first_read.set()

    def get(self, timeout: float) -> list:
        """Everything queued, waiting up to ``timeout`` s for the first item; [] on timeout."""
        out = []
        try:
            item = self._q.get(timeout=max(0.0, timeout))
        except queue.Empty:
            return out
        while True:
            if item is EOF_MARK:
                self._q.put(EOF_MARK)  # keep signalling the end
                break
            out.append(item)
            try:
                item = self._q.get_nowait()
            except queue.Empty:
                break
        return out

    @property
    def finished(self) -> bool:
        """Closed and fully drained."""
        return self.closed.is_set() and self._q.qsize() <= 1

    def stop(self, join: float = 1.0) -> None:
        self._stop.set()
        self._thread.join(join)
