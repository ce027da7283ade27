from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.joint_vdi_2230_request import JointVdi2230Request
from ...models.joint_vdi_2230_response import JointVdi2230Response
from ...types import Response


def _get_kwargs(
    *,
    body: JointVdi2230Request,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/joint/vdi2230",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | JointVdi2230Response | None:
    if response.status_code == 200:
        response_200 = JointVdi2230Response.from_dict(response.json())

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
) -> Response[ErrorResponse | JointVdi2230Response]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: JointVdi2230Request,
) -> Response[ErrorResponse | JointVdi2230Response]:
    """Bolted joint: stiffness, service loads, losses and the preload window (VDI 2230)

     A single bolted joint through VDI 2230 Part 1: bolt and clamped-part compliance (cone and sleeve,
    several plates), load factor, working and transverse loads, embedding and thermal losses, the
    required preload window against the permissible preload at the smallest section, the preload range a
    torque specification gives over the friction box, working and alternating stress, slipping, and the
    joint diagram.

    Source: VDI 2230-1:2015 steps R0–R13 (text paywalled: relations as reproduced in ECSS-E-HB-32-23A
    §6–7 and the open implementation misams/BAT); [004] eq. 2–8 for the review's preload rules; ISO
    68-1, 261, 273, 898-1, 4017; nut proof loads of ISO 898-2:1992 (EN 20898-2)

    Args:
        body (JointVdi2230Request):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | JointVdi2230Response]
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
    body: JointVdi2230Request,
) -> ErrorResponse | JointVdi2230Response | None:
    """Bolted joint: stiffness, service loads, losses and the preload window (VDI 2230)

     A single bolted joint through VDI 2230 Part 1: bolt and clamped-part compliance (cone and sleeve,
    several plates), load factor, working and transverse loads, embedding and thermal losses, the
    required preload window against the permissible preload at the smallest section, the preload range a
    torque specification gives over the friction box, working and alternating stress, slipping, and the
    joint diagram.

    Source: VDI 2230-1:2015 steps R0–R13 (text paywalled: relations as reproduced in ECSS-E-HB-32-23A
    §6–7 and the open implementation misams/BAT); [004] eq. 2–8 for the review's preload rules; ISO
    68-1, 261, 273, 898-1, 4017; nut proof loads of ISO 898-2:1992 (EN 20898-2)

    Args:
        body (JointVdi2230Request):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | JointVdi2230Response
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: JointVdi2230Request,
) -> Response[ErrorResponse | JointVdi2230Response]:
    """Bolted joint: stiffness, service loads, losses and the preload window (VDI 2230)

     A single bolted joint through VDI 2230 Part 1: bolt and clamped-part compliance (cone and sleeve,
    several plates), load factor, working and transverse loads, embedding and thermal losses, the
    required preload window against the permissible preload at the smallest section, the preload range a
    torque specification gives over the friction box, working and alternating stress, slipping, and the
    joint diagram.

    Source: VDI 2230-1:2015 steps R0–R13 (text paywalled: relations as reproduced in ECSS-E-HB-32-23A
    §6–7 and the open implementation misams/BAT); [004] eq. 2–8 for the review's preload rules; ISO
    68-1, 261, 273, 898-1, 4017; nut proof loads of ISO 898-2:1992 (EN 20898-2)

    Args:
        body (JointVdi2230Request):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | JointVdi2230Response]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: JointVdi2230Request,
) -> ErrorResponse | JointVdi2230Response | None:
    """Bolted joint: stiffness, service loads, losses and the preload window (VDI 2230)

     A single bolted joint through VDI 2230 Part 1: bolt and clamped-part compliance (cone and sleeve,
    several plates), load factor, working and transverse loads, embedding and thermal losses, the
    required preload window against the permissible preload at the smallest section, the preload range a
    torque specification gives over the friction box, working and alternating stress, slipping, and the
    joint diagram.

    Source: VDI 2230-1:2015 steps R0–R13 (text paywalled: relations as reproduced in ECSS-E-HB-32-23A
    §6–7 and the open implementation misams/BAT); [004] eq. 2–8 for the review's preload rules; ISO
    68-1, 261, 273, 898-1, 4017; nut proof loads of ISO 898-2:1992 (EN 20898-2)

    Args:
        body (JointVdi2230Request):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | JointVdi2230Response
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
