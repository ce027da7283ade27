"""The access line written straight to the stream of ``python -m service``'s handler is the
line the logging machinery writes, byte for byte; any other set-up gets a record."""

from __future__ import annotations

import contextlib
import io
import json
import logging
from collections.abc import Iterator
from typing import Any

import pytest
from fastapi.testclient import TestClient

from service import create_app
from service.__main__ import log_config
from service.config import Settings
from service.middleware import _bare_stream, _log_access
from tests.toys import TOY

RID = "0123456789abcdef0123456789abcdef"


def _served_handler(stream: io.StringIO) -> logging.StreamHandler[io.StringIO]:
    """The access handler as ``python -m service`` configures it (its format read from
    :func:`service.__main__.log_config`), writing to ``stream`` instead of stdout."""
    config = log_config("info")
    handler_config = config["handlers"]["json_access"]
    assert handler_config["class"] == "logging.StreamHandler"
    assert config["loggers"]["service.access"] == {
        "handlers": ["json_access"],
        "level": "INFO",
        "propagate": False,
    }
    handler = logging.StreamHandler(stream)
    handler.setFormatter(
        logging.Formatter(config["formatters"][handler_config["formatter"]]["format"])
    )
    return handler


@contextlib.contextmanager
def served() -> Iterator[tuple[logging.Logger, logging.StreamHandler[io.StringIO]]]:
    """The access logger as served, for the ``with`` block. Set up inside the test, not in
    a fixture: pytest adds its capturing handlers to non-propagating loggers as a test
    starts, which would make a second handler."""
    logger = logging.getLogger("service.access")
    saved = (logger.handlers[:], logger.level, logger.propagate, logger.filters[:])
    handler = _served_handler(io.StringIO())
    logger.handlers[:] = [handler]
    logger.setLevel(logging.INFO)
    logger.propagate = False
    try:
        yield logger, handler
    finally:
        logger.handlers[:], level, logger.propagate, logger.filters[:] = saved
        logger.setLevel(level)


CASES: list[tuple[dict[str, Any], int, float]] = [
    ({"method": "POST", "path": "/api/v1/joint/vdi2230"}, 200, 1.25e-4),
    ({"method": "GET", "path": '/a"b\\c/é/\u2028'}, 404, 12.0),
    ({"method": None, "path": "/\ud800"}, 500, 0.0),
    ({}, 499, 0.5004999),
]


def test_the_written_line_is_the_records_line_byte_for_byte() -> None:
    with served() as (logger, handler):
        _the_same_bytes(logger, handler)


def _the_same_bytes(logger: logging.Logger, handler: logging.StreamHandler[io.StringIO]) -> None:
    assert _bare_stream(logger) is handler  # the set-up python -m service makes: no record
    for scope, status, seconds in CASES:
        _log_access(scope, status, seconds, RID)
    direct = handler.stream.getvalue()
    # the same handler made to take records: a filter that lets everything through
    handler.stream = io.StringIO()
    handler.addFilter(lambda record: True)
    assert _bare_stream(logger) is None
    for scope, status, seconds in CASES:
        _log_access(scope, status, seconds, RID)
    assert direct == handler.stream.getvalue()
    first = direct.splitlines()[0]
    assert direct.endswith("\n") and len(direct.splitlines()) == len(CASES)
    assert json.loads(first) == {
        "method": "POST",
        "path": "/api/v1/joint/vdi2230",
        "status": 200,
        "duration_ms": 0.125,
        "request_id": RID,
    }


def test_a_request_writes_one_line_through_the_served_handler() -> None:
    client = TestClient(create_app(models=[TOY], settings=Settings(warm_up=False)))
    with served() as (_, handler):
        r = client.post(
            "/api/v1/toy/disc", json={"diameter": 0.05}, headers={"x-request-id": "a-1"}
        )
    assert r.status_code == 200
    (line,) = handler.stream.getvalue().splitlines()
    entry = json.loads(line)
    assert (entry["method"], entry["path"], entry["status"]) == ("POST", "/api/v1/toy/disc", 200)
    assert entry["request_id"] == "a-1" and entry["duration_ms"] >= 0


def test_every_other_set_up_gets_a_record(monkeypatch: pytest.MonkeyPatch) -> None:
    with served() as (logger, handler):
        _only_the_served_set_up(logger, handler, monkeypatch)


def _only_the_served_set_up(
    logger: logging.Logger,
    handler: logging.StreamHandler[io.StringIO],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    assert _bare_stream(logger) is handler
    logger.propagate = True  # a parent's handlers (pytest's caplog) see records
    assert _bare_stream(logger) is None
    logger.propagate = False
    logger.addFilter(lambda record: True)
    assert _bare_stream(logger) is None
    logger.filters.clear()
    handler.setFormatter(logging.Formatter("%(asctime)s %(message)s"))
    assert _bare_stream(logger) is None
    handler.setFormatter(logging.Formatter("%(message)s", defaults={"x": 1}))
    assert _bare_stream(logger) is None
    handler.setFormatter(None)  # the default format: the message
    assert _bare_stream(logger) is handler
    handler.setLevel(logging.WARNING)
    assert _bare_stream(logger) is None
    handler.setLevel(logging.NOTSET)
    monkeypatch.setattr(logging, "getLogRecordFactory", lambda: lambda *a: None)
    assert _bare_stream(logger) is None


def test_a_failing_stream_is_reported_as_the_handler_reports_it() -> None:
    """As :meth:`logging.StreamHandler.emit`: the error goes to ``handleError`` with the
    record of the line, and the request goes on."""
    reported: list[logging.LogRecord] = []
    with served() as (logger, handler):
        assert _bare_stream(logger) is handler
        handler.handleError = reported.append  # type: ignore[method-assign,assignment]
        handler.stream.close()
        _log_access({"method": "GET", "path": "/healthz"}, 200, 0.001, RID)
    (record,) = reported
    assert json.loads(record.getMessage())["path"] == "/healthz"
    assert record.name == "service.access" and record.levelno == logging.INFO
