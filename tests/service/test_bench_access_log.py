"""The in-process request bench measures with the access log on, as the service writes it."""

from __future__ import annotations

import json
import logging
import os

from service.middleware import _access_line


def test_the_bench_writes_access_lines_and_puts_the_logger_back() -> None:
    from bench.extra_service import access_log_on

    logger = logging.getLogger("service.access")
    before = (logger.handlers[:], logger.level, logger.propagate)
    with access_log_on():
        (handler,) = logger.handlers
        assert isinstance(handler, logging.StreamHandler)
        assert handler.stream.name == os.devnull and not logger.propagate
        assert logger.isEnabledFor(logging.INFO)  # the line is made and written
        assert handler.format(logger.makeRecord("service.access", 20, "f", 1, "L", (), None)) == "L"
    assert (logger.handlers, logger.level, logger.propagate) == before


def test_the_access_line_is_json_dumps_of_its_fields_for_any_path() -> None:
    for path in ("/api/v1/joint/vdi2230", '/a"b\\c', "/é/\u2028/\x00", "/\ud800"):
        for method, status, seconds in (
            ("POST", 200, 1.25e-4),
            ("GET", 404, 12.0),
            (None, 500, 0.0),
        ):
            fields = {
                "method": method,
                "path": path,
                "status": status,
                "duration_ms": round(seconds * 1e3, 3),
                "request_id": "0123abcd._-",
            }
            assert _access_line(method, path, status, seconds, "0123abcd._-") == json.dumps(fields)


def test_the_access_record_is_made_by_the_record_factory_in_force() -> None:
    """A factory that adds a field (a trace id) sees the access lines as every record."""
    from service.middleware import _log_access

    logger = logging.getLogger("service.access")
    seen: list[logging.LogRecord] = []

    class Keep(logging.Handler):
        def emit(self, record: logging.LogRecord) -> None:
            seen.append(record)

    old_factory = logging.getLogRecordFactory()

    def factory(*args: object, **kwargs: object) -> logging.LogRecord:
        record = old_factory(*args, **kwargs)  # type: ignore[arg-type]
        record.trace_id = "t-1"
        return record

    keep, before = Keep(), (logger.level, logger.propagate)
    logger.addHandler(keep)
    logger.setLevel(logging.INFO)
    logging.setLogRecordFactory(factory)
    try:
        _log_access({"method": "GET", "path": "/healthz"}, 200, 0.001, "r-1")
    finally:
        logging.setLogRecordFactory(old_factory)
        logger.removeHandler(keep)
        logger.setLevel(before[0])
    (record,) = seen
    assert getattr(record, "trace_id", None) == "t-1"
    assert json.loads(record.getMessage())["path"] == "/healthz"
