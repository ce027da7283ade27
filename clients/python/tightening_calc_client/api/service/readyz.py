from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...types import Response


def _get_kwargs() -> dict[str, Any]:

    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/readyz",
    }

    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Any | None:
    if response.status_code == 200:
        return None

    if response.status_code == 503:
        return None

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[Any]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
) -> Response[Any]:
    """Readiness: 503 while warming up or while either engine lane cannot admit work

     503 "warming" until the start-up warm-up has run every model's first example once per rung (the
    compiled kernels loaded; at once with WARM_UP=0); then 503 "busy" while a lane has no free slot and
    a full queue. Each lane's running and waiting computations, and the studies: running and queued in
    this process, and unfinished in all. Studies never make the service busy (they run on their own
    threads and workers): they are reported, not gated.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Any]
    """

    kwargs = _get_kwargs()

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
) -> Response[Any]:
    """Readiness: 503 while warming up or while either engine lane cannot admit work

     503 "warming" until the start-up warm-up has run every model's first example once per rung (the
    compiled kernels loaded; at once with WARM_UP=0); then 503 "busy" while a lane has no free slot and
    a full queue. Each lane's running and waiting computations, and the studies: running and queued in
    this process, and unfinished in all. Studies never make the service busy (they run on their own
    threads and workers): they are reported, not gated.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Any]
    """

    kwargs = _get_kwargs()

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)
