from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.preload_tightening_request import PreloadTighteningRequest
from ...models.preload_tightening_response import PreloadTighteningResponse
from ...types import Response


def _get_kwargs(
    *,
    body: PreloadTighteningRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/preload/tightening",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | PreloadTighteningResponse | None:
    if response.status_code == 200:
        response_200 = PreloadTighteningResponse.from_dict(response.json())

        return response_200

    if response.status_code == 400:
        response_400 = ErrorResponse.from_dict(response.json())

        return response_400

    if response.status_code == 413:
        response_413 = ErrorResponse.from_dict(response.json())

        return response_413

    if response.status_code == 415:
        response_415 = ErrorResponse.from_dict(response.json())

        return response_415

    if response.status_code == 422:
        response_422 = ErrorResponse.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorResponse.from_dict(response.json())

        return response_503

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[ErrorResponse | PreloadTighteningResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadTighteningRequest,
) -> Response[ErrorResponse | PreloadTighteningResponse]:
    """Bolt preload and tightening torque

     The largest assembly preload a metric bolt takes at a share ν of its yield strength, and the torque
    that gives it: thread, bearing and frictionless parts, by the VDI 2230 formula, the review's exact
    relations or its approximation, with the review's rules of thumb beside them.

    Source: [004] review of preload selection and tightening control, eq. 2–19, fig. 1–9; VDI
    2230-1:2015 steps R7 and R13, Table A8; ISO 68-1, ISO 261, ISO 273, ISO 898-1, ISO 4017; ISO 261,
    ISO 262, ISO 3506-1, SAE J429, ASTM A193, ASME B1.1, ASME B18.2.1, ISO 4762, EN 1665, ISO 10642, ISO
    2936, VDI 2230-1 R10 and R11 (Alexander)

    Args:
        body (PreloadTighteningRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | PreloadTighteningResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadTighteningRequest,
) -> ErrorResponse | PreloadTighteningResponse | None:
    """Bolt preload and tightening torque

     The largest assembly preload a metric bolt takes at a share ν of its yield strength, and the torque
    that gives it: thread, bearing and frictionless parts, by the VDI 2230 formula, the review's exact
    relations or its approximation, with the review's rules of thumb beside them.

    Source: [004] review of preload selection and tightening control, eq. 2–19, fig. 1–9; VDI
    2230-1:2015 steps R7 and R13, Table A8; ISO 68-1, ISO 261, ISO 273, ISO 898-1, ISO 4017; ISO 261,
    ISO 262, ISO 3506-1, SAE J429, ASTM A193, ASME B1.1, ASME B18.2.1, ISO 4762, EN 1665, ISO 10642, ISO
    2936, VDI 2230-1 R10 and R11 (Alexander)

    Args:
        body (PreloadTighteningRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | PreloadTighteningResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadTighteningRequest,
) -> Response[ErrorResponse | PreloadTighteningResponse]:
    """Bolt preload and tightening torque

     The largest assembly preload a metric bolt takes at a share ν of its yield strength, and the torque
    that gives it: thread, bearing and frictionless parts, by the VDI 2230 formula, the review's exact
    relations or its approximation, with the review's rules of thumb beside them.

    Source: [004] review of preload selection and tightening control, eq. 2–19, fig. 1–9; VDI
    2230-1:2015 steps R7 and R13, Table A8; ISO 68-1, ISO 261, ISO 273, ISO 898-1, ISO 4017; ISO 261,
    ISO 262, ISO 3506-1, SAE J429, ASTM A193, ASME B1.1, ASME B18.2.1, ISO 4762, EN 1665, ISO 10642, ISO
    2936, VDI 2230-1 R10 and R11 (Alexander)

    Args:
        body (PreloadTighteningRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | PreloadTighteningResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadTighteningRequest,
) -> ErrorResponse | PreloadTighteningResponse | None:
    """Bolt preload and tightening torque

     The largest assembly preload a metric bolt takes at a share ν of its yield strength, and the torque
    that gives it: thread, bearing and frictionless parts, by the VDI 2230 formula, the review's exact
    relations or its approximation, with the review's rules of thumb beside them.

    Source: [004] review of preload selection and tightening control, eq. 2–19, fig. 1–9; VDI
    2230-1:2015 steps R7 and R13, Table A8; ISO 68-1, ISO 261, ISO 273, ISO 898-1, ISO 4017; ISO 261,
    ISO 262, ISO 3506-1, SAE J429, ASTM A193, ASME B1.1, ASME B18.2.1, ISO 4762, EN 1665, ISO 10642, ISO
    2936, VDI 2230-1 R10 and R11 (Alexander)

    Args:
        body (PreloadTighteningRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | PreloadTighteningResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
