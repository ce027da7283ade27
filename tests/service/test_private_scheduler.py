"""The Dask scheduler the service starts is private: mutual TLS with credentials of its own.

Issue 34: any local process could connect to the local cluster's scheduler and run code
in the service's workers (as root there); ``DASK_SCHEDULER=tcp://…`` connected without
TLS either. The local cluster now makes a key and a self-signed certificate in memory
when it starts (``Security.temporary()``) and its scheduler and workers accept only
peers that present them; a scheduler of one's own is reached over TLS with the files
``DASK_TLS_CA_FILE``, ``DASK_TLS_CERT`` and ``DASK_TLS_KEY`` name.
"""

from __future__ import annotations

import socket
import ssl
import time
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

import engine
from engine.studies.execute import TLSFiles
from service import create_app
from service.config import dask_tls
from service.studies import StudySettings


def _pem(tmp_path: Path) -> tuple[str, str]:
    """A CA file and a certificate-and-key file, as Dask's temporary credentials write
    them (the one self-signed certificate is its own authority)."""
    from distributed.security import Security

    sec = Security.temporary()
    ca, both = tmp_path / "ca.pem", tmp_path / "client.pem"
    ca.write_text(sec.tls_ca_file)
    both.write_text(sec.tls_client_cert + sec.tls_client_key)
    return str(ca), str(both)


def test_the_scheduler_certificates_come_from_the_environment(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    ca, cert = _pem(tmp_path)
    assert dask_tls("tls://10.0.0.5:8786") is None  # none set: Dask's own configuration
    monkeypatch.setenv("DASK_TLS_CA_FILE", ca)
    monkeypatch.setenv("DASK_TLS_CERT", cert)
    assert dask_tls("tls://10.0.0.5:8786") == TLSFiles(ca, cert, None)
    security = TLSFiles(ca, cert).security()
    assert security.require_encryption and security.tls_ca_file == ca
    context = security.get_connection_args("client")["ssl_context"]  # the files load
    assert context.verify_mode == ssl.CERT_REQUIRED
    # certificates for a plain-TCP scheduler, or for none: refused at start-up, named
    with pytest.raises(ValueError, match=r"DASK_SCHEDULER must be a tls:// address"):
        dask_tls("tcp://10.0.0.5:8786")
    with pytest.raises(ValueError, match="set DASK_SCHEDULER=tls://"):
        dask_tls(None)
    monkeypatch.setenv("DASK_TLS_KEY", str(tmp_path / "missing.pem"))
    with pytest.raises(ValueError, match="DASK_TLS_KEY must name a readable PEM file"):
        dask_tls("tls://10.0.0.5:8786")
    monkeypatch.delenv("DASK_TLS_KEY")
    monkeypatch.delenv("DASK_TLS_CERT")
    with pytest.raises(ValueError, match="DASK_TLS_CA_FILE and DASK_TLS_CERT must be set"):
        dask_tls("tls://10.0.0.5:8786")
    monkeypatch.setenv("DASK_SCHEDULER", "tcp://10.0.0.5:8786")
    monkeypatch.setenv("DASK_TLS_CERT", cert)
    with pytest.raises(ValueError, match="tls:// address"):  # the app is not built
        create_app(study_settings=StudySettings(store=str(tmp_path / "jobs")))


def _tls_answer(address: str, cert: Path | None) -> bytes:
    """Open a TLS connection to ``address`` as a client that trusts any server (an attacker
    can read the server's certificate) and presents ``cert`` (certificate and key) or
    none; answer the first bytes the server sends (Dask's handshake), b"" when it closed
    the connection, or raise ``ssl.SSLError`` when it refused the handshake."""
    host, port = address.removeprefix("tls://").rsplit(":", 1)
    context = ssl.SSLContext(ssl.PROTOCOL_TLS_CLIENT)
    context.check_hostname = False
    context.verify_mode = ssl.CERT_NONE
    if cert is not None:
        context.load_cert_chain(cert)
    with (
        socket.create_connection((host, int(port)), timeout=10) as raw,
        context.wrap_socket(raw) as tls,
    ):
        return tls.recv(64)


def _refused(address: str, cert: Path | None) -> str:
    try:
        answer = _tls_answer(address, cert)
    except ssl.SSLError as exc:
        return f"{type(exc).__name__}: {exc}"
    assert answer == b"", f"{address} answered {answer!r} to a client without its credentials"
    return "closed"


@pytest.mark.slow
def test_an_outside_client_is_refused_while_the_service_studies_run(tmp_path: Path) -> None:
    from distributed import Client

    spec = engine.get_model("nutrunner.drive")
    example = dict(spec.examples[0])
    body = {
        "base": {k: v for k, v in example.items() if k != "motor_speed"},
        "variables": [
            {
                "name": "motor_speed",
                "low": 0.9 * example["motor_speed"],
                "high": 1.1 * example["motor_speed"],
            }
        ],
        "samples": 100_000,
        "fidelity": "closed_form",
    }
    settings = StudySettings(store=str(tmp_path), inprocess_points=0, inprocess_s=0, dask_workers=1)
    app = create_app(study_settings=settings)
    with TestClient(app) as client:
        first = client.post("/api/v1/nutrunner/drive/study", json=body)
        assert first.status_code == 202, first.text
        executor = app.state.studies.dask()
        deadline = time.monotonic() + 120
        while executor._cluster is None:  # the job thread starts the cluster
            assert time.monotonic() < deadline, "the cluster did not start"
            time.sleep(0.1)
        address = executor._cluster.scheduler_address
        assert address.startswith("tls://127.0.0.1:")
        # without a certificate, or with a self-signed one of one's own (which the
        # cluster's authority did not sign): refused at the handshake
        foreign = tmp_path / "foreign.pem"
        _, own = _pem(tmp_path)
        Path(own).rename(foreign)
        reasons = [_refused(address, None), _refused(address, foreign)]
        # a Dask client over plain TCP, without TLS: never connects
        with pytest.raises((OSError, TimeoutError)):
            Client(address.replace("tls://", "tcp://"), timeout="3s", set_as_default=False)
        second = client.post("/api/v1/nutrunner/drive/study", json=body)
        jobs = [first.json()["job"], second.json()["job"]]
        for job in jobs:
            while (state := client.get(f"/api/v1/jobs/{job}").json())["state"] in (
                "queued",
                "running",
            ):
                assert time.monotonic() < deadline, state
                time.sleep(0.1)
            assert state["state"] == "done", state
            assert state["progress"]["done"] == 100_000
        # the refusals were for want of credentials: with the cluster's own, the same
        # connection gets Dask's handshake, and a Dask client connects
        security = executor._cluster.security
        mine = tmp_path / "cluster.pem"
        mine.write_text(security.tls_client_cert + security.tls_client_key)
        assert len(_tls_answer(address, mine)) > 0
        insider = Client(address, security=security, set_as_default=False)
        try:
            assert len(insider.scheduler_info()["workers"]) == 1
        finally:
            insider.close()
    # the server's alerts: no certificate, and a certificate its authority did not sign
    assert "CERTIFICATE_REQUIRED" in reasons[0] and "UNKNOWN_CA" in reasons[1], reasons
