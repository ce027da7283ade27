from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.preload_ultrasonic_request import PreloadUltrasonicRequest
from ...models.preload_ultrasonic_response import PreloadUltrasonicResponse
from ...types import Response


def _get_kwargs(
    *,
    body: PreloadUltrasonicRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/preload/ultrasonic",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | PreloadUltrasonicResponse | None:
    if response.status_code == 200:
        response_200 = PreloadUltrasonicResponse.from_dict(response.json())

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
) -> Response[ErrorResponse | PreloadUltrasonicResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadUltrasonicRequest,
) -> Response[ErrorResponse | PreloadUltrasonicResponse]:
    """Ultrasonic elongation ↔ preload (pulse-echo time of flight)

     From a preload, the bolt's elongation and the change in the echo's time of flight an ultrasonic
    instrument should read; or from a measured time-of-flight change, the elongation and preload. The
    stress factor, the temperature correction and the bolt's compliance (VDI 2230-1 R3, as the joint
    model computes it) enter as ASTM E1685 practice states them.

    Source: ASTM E1685 practice; the instrument makers' relations [BoltMike] and [Dakota]; the bolt's
    compliance δ_S of VDI 2230-1 R3 from joint.vdi2230; F = Δl/δ_S [004, eq. 7]

    Args:
        body (PreloadUltrasonicRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | PreloadUltrasonicResponse]
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
    body: PreloadUltrasonicRequest,
) -> ErrorResponse | PreloadUltrasonicResponse | None:
    """Ultrasonic elongation ↔ preload (pulse-echo time of flight)

     From a preload, the bolt's elongation and the change in the echo's time of flight an ultrasonic
    instrument should read; or from a measured time-of-flight change, the elongation and preload. The
    stress factor, the temperature correction and the bolt's compliance (VDI 2230-1 R3, as the joint
    model computes it) enter as ASTM E1685 practice states them.

    Source: ASTM E1685 practice; the instrument makers' relations [BoltMike] and [Dakota]; the bolt's
    compliance δ_S of VDI 2230-1 R3 from joint.vdi2230; F = Δl/δ_S [004, eq. 7]

    Args:
        body (PreloadUltrasonicRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | PreloadUltrasonicResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadUltrasonicRequest,
) -> Response[ErrorResponse | PreloadUltrasonicResponse]:
    """Ultrasonic elongation ↔ preload (pulse-echo time of flight)

     From a preload, the bolt's elongation and the change in the echo's time of flight an ultrasonic
    instrument should read; or from a measured time-of-flight change, the elongation and preload. The
    stress factor, the temperature correction and the bolt's compliance (VDI 2230-1 R3, as the joint
    model computes it) enter as ASTM E1685 practice states them.

    Source: ASTM E1685 practice; the instrument makers' relations [BoltMike] and [Dakota]; the bolt's
    compliance δ_S of VDI 2230-1 R3 from joint.vdi2230; F = Δl/δ_S [004, eq. 7]

    Args:
        body (PreloadUltrasonicRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | PreloadUltrasonicResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadUltrasonicRequest,
) -> ErrorResponse | PreloadUltrasonicResponse | None:
    """Ultrasonic elongation ↔ preload (pulse-echo time of flight)

     From a preload, the bolt's elongation and the change in the echo's time of flight an ultrasonic
    instrument should read; or from a measured time-of-flight change, the elongation and preload. The
    stress factor, the temperature correction and the bolt's compliance (VDI 2230-1 R3, as the joint
    model computes it) enter as ASTM E1685 practice states them.

    Source: ASTM E1685 practice; the instrument makers' relations [BoltMike] and [Dakota]; the bolt's
    compliance δ_S of VDI 2230-1 R3 from joint.vdi2230; F = Δl/δ_S [004, eq. 7]

    Args:
        body (PreloadUltrasonicRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | PreloadUltrasonicResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
