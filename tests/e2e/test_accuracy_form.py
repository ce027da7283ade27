"""The form, its methods table and the report say whether an error estimate is a bound or
typical, with the share of random designs that exceed a typical one (issue 29).

Shown on the toy disc with its rough rung declared typical (tests/engine/test_accuracy_label.py).
"""

from __future__ import annotations

import socket
import threading
import time
from collections.abc import Iterator
from typing import Any

import pytest

from service import create_app
from tests.engine.test_accuracy_label import SHARE, TYPICAL

from .test_browser import _example, _open, _submit, browser, page  # noqa: F401  (fixtures)

pytestmark = [pytest.mark.slow, pytest.mark.browser]


@pytest.fixture(scope="module")
def base_url() -> Iterator[str]:
    import uvicorn

    app = create_app(models=[TYPICAL])
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    config = uvicorn.Config(app, log_level="warning", lifespan="off", ws="none")
    server = uvicorn.Server(config)
    thread = threading.Thread(target=server.run, kwargs={"sockets": [sock]}, daemon=True)
    thread.start()
    deadline = time.monotonic() + 20
    while not server.started:
        assert thread.is_alive() and time.monotonic() < deadline, "the server did not start"
        time.sleep(0.02)
    yield f"http://127.0.0.1:{port}"
    server.should_exit = True
    thread.join(timeout=10)
    sock.close()


def test_the_answer_says_bound_or_typical_with_the_share(page: Any, base_url: str) -> None:  # noqa: F811
    _open(page, base_url, f"m={TYPICAL.name}")
    _example(page)
    kinds = page.locator("details.rungs td.estimate-kind").all_text_contents()  # folded
    assert kinds == [f"typical (exceeded in {SHARE})", "bound"]
    page.select_option("#fidelity", "rough")
    assert _submit(page) == "ok"
    assert page.inner_text("#error-estimate") == "±5 %"
    assert page.inner_text("#error-kind") == f"typical (exceeded in {SHARE})"
    page.click("#show-report")
    assert f"±5 % typical (exceeded in {SHARE})" in page.inner_text("#report-body")
    page.click("#close-report")
    page.select_option("#fidelity", "exact")
    assert _submit(page) == "ok"
    assert page.inner_text("#error-kind") == "bound"
