"""The ASGI scope of a plain HTTP/1.1 JSON request, for the tests that drive the app
directly (a client that disconnects mid-body or mid-computation)."""

from __future__ import annotations

from typing import Any


def json_post_scope(path: str, *, host: str, client: tuple[str, int]) -> dict[str, Any]:
    """The scope of a JSON ``POST`` to ``path`` on server ``host`` (port 80) from ``client``.

    >>> scope = json_post_scope("/api/v1/toy", host="t", client=("10.0.0.1", 1))
    >>> scope["raw_path"], scope["server"], dict(scope["headers"])[b"host"]
    (b'/api/v1/toy', ('t', 80), b't')
    """
    return {
        "type": "http",
        "asgi": {"version": "3.0"},
        "http_version": "1.1",
        "method": "POST",
        "scheme": "http",
        "path": path,
        "raw_path": path.encode(),
        "query_string": b"",
        "root_path": "",
        "headers": [(b"content-type", b"application/json"), (b"host", host.encode())],
        "client": client,
        "server": (host, 80),
    }
