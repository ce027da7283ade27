"""Settings from the environment, each with an embedded default (nothing to configure).

The bounds on work (``BUDGET_S``, ``MAX_STEPS``, ``MAX_SERIES_POINTS``,
``MAX_BODY_BYTES``, the lanes' ``ENGINE_THREADS``, ``ENGINE_QUEUE``, ``HEAVY_SLOTS``,
``HEAVY_QUEUE``, ``HEAVY_PER_CLIENT``, ``ADMISSION_WAIT_S``, ``INLINE_BUDGET_S``, and the
connection bounds ``MAX_CONNECTIONS``, ``MAX_CONNECTIONS_PER_CLIENT``, ``MAX_HEAD_BYTES``,
``HEADER_TIMEOUT_S``, ``BODY_TIMEOUT_S``) are read once
when the app is built; a value that is not a positive number stops the service at
start-up with a message naming the variable, rather than at the first request. Counts
sized to the machine (the heavy lane, the Dask workers) follow the CPUs the process may
really use (:func:`usable_cpus`: affinity and cgroup quota), not the host's count.
"""

from __future__ import annotations

import hashlib
import math
import os
import re
from dataclasses import dataclass, field
from pathlib import Path

from engine.core.runner import DEFAULT_BUDGET_S, DEFAULT_MAX_STEPS
from engine.studies.execute import TLSFiles


def _origins() -> tuple[str, ...]:
    raw = os.environ.get("CORS_ORIGINS", "")
    return tuple(o.strip() for o in raw.split(",") if o.strip())


def _proxies() -> tuple[str, ...]:
    raw = os.environ.get("TRUSTED_PROXIES", "")
    return tuple(p.strip() for p in raw.split(",") if p.strip())


#: A key's name: its identity in quotas, the heavy lane's share and the logs.
_KEY_NAME = re.compile(r"[A-Za-z0-9._-]{1,64}")
#: The shortest secret a key may have [characters].
MIN_KEY_CHARS = 16


@dataclass(frozen=True)
class ApiKey:
    """A client's API key: its name, the secret's SHA-256 (the secret itself is not kept),
    and its study quotas; None takes the server's (``STUDY_PER_CLIENT``,
    ``STUDY_MAX_POINTS``)."""

    name: str
    digest: bytes = field(repr=False)
    #: Unfinished studies the key may have at once.
    studies: int | None = None
    #: Points one study of the key may have.
    points: int | None = None

    @classmethod
    def of(
        cls, name: str, secret: str, studies: int | None = None, points: int | None = None
    ) -> ApiKey:
        """The key of ``name`` with the secret ``secret``."""
        return cls(name, hashlib.sha256(secret.encode()).digest(), studies, points)


def read_api_keys(path: Path) -> tuple[ApiKey, ...]:
    r"""The keys of ``API_KEYS_FILE``: one a line, ``name secret [studies=N] [points=N]``,
    blank lines and ``#`` comments ignored. A malformed line stops the service at start-up,
    naming the file and the line (never the secret).

    >>> import tempfile
    >>> with tempfile.NamedTemporaryFile("w", suffix=".keys", delete=False) as f:
    ...     _ = f.write("# shop floor\nline-3  k3-2f9a8e1c7b6d5a4f  studies=1 points=50000\n")
    >>> key = read_api_keys(Path(f.name))[0]
    >>> key.name, key.studies, key.points, len(key.digest)
    ('line-3', 1, 50000, 32)
    """
    try:
        text = path.read_text()
    except OSError as exc:
        raise ValueError(f"API_KEYS_FILE {str(path)!r} cannot be read: {exc.strerror}") from None
    keys: list[ApiKey] = []
    for number, line in enumerate(text.splitlines(), start=1):
        words = line.split("#", 1)[0].split()
        if not words:
            continue
        where = f"API_KEYS_FILE {str(path)!r} line {number}"
        if len(words) < 2 or not _KEY_NAME.fullmatch(words[0]):
            raise ValueError(
                f"{where}: write 'name secret [studies=N] [points=N]', the name of letters, "
                "digits and ._- (at most 64)"
            )
        name, secret, quotas = words[0], words[1], dict.fromkeys(("studies", "points"))
        if len(secret) < MIN_KEY_CHARS:
            raise ValueError(f"{where}: the secret of {name!r} is shorter than {MIN_KEY_CHARS}")
        for word in words[2:]:
            quota, _, value = word.partition("=")
            if quota not in quotas or not value.isdigit() or int(value) < 1:
                raise ValueError(
                    f"{where}: {word[:40]!r} is not studies=N or points=N with N an integer >= 1"
                )
            quotas[quota] = int(value)
        keys.append(ApiKey.of(name, secret, quotas["studies"], quotas["points"]))
    names = [k.name for k in keys]
    digests = [k.digest for k in keys]
    if len(set(names)) < len(names) or len(set(digests)) < len(digests):
        raise ValueError(f"API_KEYS_FILE {str(path)!r}: each name and each secret may appear once")
    return tuple(keys)


def _api_keys() -> tuple[ApiKey, ...]:
    path = os.environ.get("API_KEYS_FILE", "")
    return read_api_keys(Path(path)) if path else ()


def _quota(text: str, period_text: str | None = None) -> float | None:
    """CPUs a cgroup quota allows: cgroup v2 ``cpu.max`` holds ``"<quota> <period>"`` or
    ``"max <period>"``; v1 gives the quota and period in two files, ``-1`` for none."""
    parts = text.split()
    if period_text is not None:
        parts = [parts[0] if parts else "", period_text.strip()]
    try:
        quota, period = parts[0], float(parts[1])
        return None if quota in ("max", "-1") or period <= 0 else float(quota) / period
    except (IndexError, ValueError):
        return None


def _read(path: Path) -> str | None:
    try:
        return path.read_text()
    except OSError:
        return None


def _groups(self_cgroup: Path | None) -> dict[str, str]:
    """This process's cgroup paths from ``/proc/self/cgroup``: v2's under ``""``, v1's under
    each controller's name."""
    groups = {"": "/"}
    for line in (_read(self_cgroup or Path("/proc/self/cgroup")) or "").splitlines():
        number, _, rest = line.partition(":")
        controllers, _, path = rest.partition(":")
        if number == "0" and controllers == "":
            groups[""] = path
        else:
            for name in controllers.split(","):
                groups[name] = path
    return groups


def _limits(
    root: Path, self_cgroup: Path | None, controller: str, v1_dirs: tuple[str, ...]
) -> list[tuple[Path, bool]]:
    """The folders to read a limit from, the process's group first and then each parent up
    to ``root``: v2's (``True``) and, under ``root/<v1 dir>``, v1's (``False``)."""
    groups = _groups(self_cgroup)
    places = [(root, groups[""], True)]
    places += [(root / d, groups.get(controller, "/"), False) for d in v1_dirs]
    found = []
    for base, group, v2 in places:
        parts = [p for p in group.split("/") if p and p != ".."]
        for depth in range(len(parts), -1, -1):  # the group itself, then each parent
            found.append((base.joinpath(*parts[:depth]), v2))
    return found


def cgroup_cpus(
    root: Path = Path("/sys/fs/cgroup"), self_cgroup: Path | None = None
) -> float | None:
    """The CPU quota of this process's cgroup (and its parents), in CPUs; None when unlimited.

    cgroup v2: ``cpu.max`` in the process's group (from ``/proc/self/cgroup``, ``0::/path``)
    and each parent up to ``root``; v1: ``cpu.cfs_quota_us / cpu.cfs_period_us`` under
    ``root/cpu`` (or ``root/cpu,cpuacct``). The smallest quota found holds.
    """
    found: list[float] = []
    for here, v2 in _limits(root, self_cgroup, "cpu", ("cpu", "cpu,cpuacct")):
        text = _read(here / ("cpu.max" if v2 else "cpu.cfs_quota_us"))
        if text is None:
            continue
        cpus = _quota(text) if v2 else _quota(text, _read(here / "cpu.cfs_period_us") or "")
        if cpus is not None:
            found.append(cpus)
    return min(found) if found else None


def cgroup_memory(
    root: Path = Path("/sys/fs/cgroup"), self_cgroup: Path | None = None
) -> int | None:
    """The memory limit of this process's cgroup (and its parents) in bytes; None when
    unlimited: v2 ``memory.max`` (``max`` for none), v1 ``memory/memory.limit_in_bytes``
    (a number near 2^63 for none). The smallest limit found holds."""
    found: list[int] = []
    for here, v2 in _limits(root, self_cgroup, "memory", ("memory",)):
        text = (_read(here / ("memory.max" if v2 else "memory.limit_in_bytes")) or "").strip()
        if text.isdigit() and 0 < int(text) < 2**62:
            found.append(int(text))
    return min(found) if found else None


def usable_memory(root: Path = Path("/sys/fs/cgroup"), self_cgroup: Path | None = None) -> int:
    """The memory this process may really use [bytes]: the machine's, capped by its cgroup's
    limit (a container limited to 4 GB on a 24 GB host answers 4 GB)."""
    try:
        physical = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (ValueError, OSError, AttributeError):
        physical = 0
    limit = cgroup_memory(root, self_cgroup)
    candidates = [m for m in (physical, limit) if m]
    return min(candidates) if candidates else 2**30


def usable_cpus(root: Path = Path("/sys/fs/cgroup"), self_cgroup: Path | None = None) -> int:
    """The CPUs this process may really use: those it may run on (its affinity, not the
    host's count), capped by its cgroup's CPU quota rounded up; at least 1.

    A container limited to 2 CPUs on a 64-CPU host answers 2, so the service starts two
    Dask workers and two heavy slots, not 64.
    """
    cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    quota = cgroup_cpus(root, self_cgroup)
    if quota is not None:
        cpus = min(cpus or 1, math.ceil(quota - 1e-9))
    return max(1, cpus or 1)


def _int(name: str, default: int) -> int:
    raw = os.environ.get(name, str(default))
    try:
        return int(raw)
    except ValueError:
        raise ValueError(f"{name} must be an integer, not {raw!r}") from None


def _float(name: str, default: float) -> float:
    raw = os.environ.get(name, str(default))
    try:
        return float(raw)
    except ValueError:
        raise ValueError(f"{name} must be a number, not {raw!r}") from None


@dataclass(frozen=True)
class Settings:
    host: str = field(default_factory=lambda: os.environ.get("HOST", "127.0.0.1"))
    port: int = field(default_factory=lambda: _int("PORT", 8000))
    cors_origins: tuple[str, ...] = field(default_factory=_origins)
    max_body_bytes: int = field(default_factory=lambda: _int("MAX_BODY_BYTES", 256 * 1024))
    log_level: str = field(default_factory=lambda: os.environ.get("LOG_LEVEL", "info"))
    #: Wall-clock budget of one model evaluation or sweep, queueing included [s].
    budget_s: float = field(default_factory=lambda: _float("BUDGET_S", DEFAULT_BUDGET_S))
    #: Step budget handed to every model (ODE steps, iterations) as ``ctx.max_steps``.
    max_steps: int = field(default_factory=lambda: _int("MAX_STEPS", DEFAULT_MAX_STEPS))
    #: Longest time series one response may carry [points per series].
    max_series_points: int = field(default_factory=lambda: _int("MAX_SERIES_POINTS", 10_000))
    #: Threads of the quick lane (closed forms, cheap single points), per server process.
    engine_threads: int = field(default_factory=lambda: _int("ENGINE_THREADS", 4))
    #: Quick computations that may wait for a thread; beyond that a request gets 503.
    engine_queue: int = field(default_factory=lambda: _int("ENGINE_QUEUE", 64))
    #: Slots of the heavy lane (simulations, looping sweeps): one per core by default.
    heavy_slots: int = field(default_factory=lambda: _int("HEAVY_SLOTS", usable_cpus()))
    #: Heavy computations that may wait for a slot.
    heavy_queue: int = field(default_factory=lambda: _int("HEAVY_QUEUE", 16))
    #: Heavy slots one client (address) may hold at once: its fair share.
    heavy_per_client: int = field(
        default_factory=lambda: _int("HEAVY_PER_CLIENT", max(1, usable_cpus() // 2))
    )
    #: Time box of a cheap computation run inline on the event loop, without the thread
    #: hop (service.workers.Inline); a (model, rung) measured slower (in processor time)
    #: moves to the quick lane. 0: every computation in a lane [s].
    inline_budget_s: float = field(default_factory=lambda: _float("INLINE_BUDGET_S", 0.002))
    #: How long a request may wait for a slot before it gets 503 with Retry-After [s].
    admission_wait_s: float = field(default_factory=lambda: _float("ADMISSION_WAIT_S", 0.5))
    #: Concurrent connections per process (uvicorn's limit; over it: 503).
    max_connections: int = field(default_factory=lambda: _int("MAX_CONNECTIONS", 1000))
    #: Connections one client address may hold at once (over it: 503) [connections].
    max_connections_per_client: int = field(
        default_factory=lambda: _int("MAX_CONNECTIONS_PER_CLIENT", 100)
    )
    #: Connections that may wait for their request at once (no byte yet, or a head or body
    #: part-sent); beyond it the one that has been sending longest is shed. 0: half of
    #: MAX_CONNECTIONS, so trickling sockets from many addresses leave room for others.
    max_waiting_connections: int = field(default_factory=lambda: _int("MAX_WAITING_CONNECTIONS", 0))
    #: Addresses or networks ("10.0.0.0/8") of reverse proxies whose X-Forwarded-For and
    #: X-Forwarded-Proto are believed: the client's identity (per-client quotas, lanes and
    #: the connection cap) is then the forwarded address. Empty: no one's (a client could
    #: otherwise pose as many), loopback included.
    trusted_proxies: tuple[str, ...] = field(default_factory=_proxies)
    #: The API keys (``API_KEYS_FILE``, :func:`read_api_keys`): with any, every /api/v1
    #: request must carry one (``Authorization: Bearer <key>`` or ``X-API-Key``; 401
    #: otherwise), and the key's name is the client's identity. None: the API is open,
    #: as a single user's embedded service needs.
    api_keys: tuple[ApiKey, ...] = field(default_factory=_api_keys)
    #: Largest request head (request line and headers); over it: 431 [bytes].
    max_head_bytes: int = field(default_factory=lambda: _int("MAX_HEAD_BYTES", 16 * 1024))
    #: A request's headers must arrive within this many seconds of its first byte [s].
    header_timeout_s: float = field(default_factory=lambda: _float("HEADER_TIMEOUT_S", 10.0))
    #: On SIGTERM, how long open requests may take to finish before the process exits [s].
    shutdown_timeout_s: int = field(default_factory=lambda: _int("SHUTDOWN_TIMEOUT_S", 3))
    #: The whole request body must arrive within this many seconds of its head [s].
    body_timeout_s: float = field(default_factory=lambda: _float("BODY_TIMEOUT_S", 10.0))
    #: How long past its budget a computation that ignores its deadline is waited for [s].
    budget_grace_s: float = field(default_factory=lambda: _float("BUDGET_GRACE_S", 1.0))
    #: Run every model's first example once per rung at start-up, in the background, so
    #: the first user request does not pay one-off costs (numba's cache load, ~1.5 s).
    warm_up: bool = field(
        default_factory=lambda: os.environ.get("WARM_UP", "1").lower() not in ("0", "false")
    )
    #: The built manual served at /manual/ (a folder holding index.html); empty: ``site/``
    #: beside the package in a checkout, where ``make run`` builds it.
    manual_dir: str = field(default_factory=lambda: os.environ.get("MANUAL_DIR", ""))
    #: One JSON line per request on the ``service.access`` logger.
    access_log: bool = field(
        default_factory=lambda: os.environ.get("ACCESS_LOG", "1").lower() not in ("0", "false")
    )

    def __post_init__(self) -> None:
        positive = {
            "MAX_BODY_BYTES": self.max_body_bytes,
            "BUDGET_S": self.budget_s,
            "MAX_STEPS": self.max_steps,
            "MAX_SERIES_POINTS": self.max_series_points,
            "ENGINE_THREADS": self.engine_threads,
            "HEAVY_SLOTS": self.heavy_slots,
            "HEAVY_PER_CLIENT": self.heavy_per_client,
            "ADMISSION_WAIT_S": self.admission_wait_s,
            "MAX_CONNECTIONS": self.max_connections,
            "MAX_CONNECTIONS_PER_CLIENT": self.max_connections_per_client,
            "MAX_HEAD_BYTES": self.max_head_bytes,
            "HEADER_TIMEOUT_S": self.header_timeout_s,
            "BODY_TIMEOUT_S": self.body_timeout_s,
        }
        for name, value in positive.items():
            if not value > 0:
                raise ValueError(f"{name} must be positive, not {value!r}")
        if not self.max_waiting_connections >= 0:
            raise ValueError(
                "MAX_WAITING_CONNECTIONS must be an integer >= 0 (0: half of MAX_CONNECTIONS), "
                f"not {self.max_waiting_connections!r}"
            )
        if self.engine_queue < 0 or self.heavy_queue < 0 or self.budget_grace_s < 0:
            raise ValueError("ENGINE_QUEUE, HEAVY_QUEUE and BUDGET_GRACE_S must not be negative")
        if not self.inline_budget_s >= 0:
            raise ValueError(f"INLINE_BUDGET_S must not be negative, not {self.inline_budget_s!r}")


def dask_tls(scheduler: str | None) -> TLSFiles | None:
    """The certificates for the scheduler ``DASK_SCHEDULER`` names, from
    ``DASK_TLS_CA_FILE`` (the authority that signed the cluster's certificates),
    ``DASK_TLS_CERT`` (this client's certificate) and ``DASK_TLS_KEY`` (its key, when not in
    the certificate's file); None when none is set (Dask's own ``distributed.comm.tls``
    configuration then applies, plain TCP when it names none).

    Checked when the app is built: a CA without a certificate (or the reverse), a file
    that cannot be read, or certificates for a ``tcp://`` scheduler stop the service with
    a message naming the variable. The local cluster needs none of them: it makes its own
    (:class:`engine.studies.execute.DaskExecutor`).

    >>> dask_tls(None) is None
    True
    """
    names = ("DASK_TLS_CA_FILE", "DASK_TLS_CERT", "DASK_TLS_KEY")
    ca, cert, key = (os.environ.get(n) or None for n in names)
    if not (ca or cert or key):
        return None
    if not (ca and cert):
        raise ValueError(
            "DASK_TLS_CA_FILE and DASK_TLS_CERT must be set together (DASK_TLS_KEY too when "
            "the key is not in the certificate's file)"
        )
    for name, path in zip(names, (ca, cert, key), strict=True):
        if path is not None and not os.access(path, os.R_OK):
            raise ValueError(f"{name} must name a readable PEM file, not {path!r}")
    if not scheduler:
        raise ValueError(
            "DASK_TLS_CA_FILE and DASK_TLS_CERT are for a scheduler of your own: set "
            "DASK_SCHEDULER=tls://host:port too (the local cluster makes its own certificates)"
        )
    if not scheduler.startswith("tls://"):
        raise ValueError(
            f"DASK_SCHEDULER must be a tls:// address when DASK_TLS_CA_FILE is set, not "
            f"{scheduler!r}"
        )
    return TLSFiles(ca, cert, key)
