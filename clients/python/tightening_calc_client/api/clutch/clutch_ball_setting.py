from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.clutch_ball_setting_request import ClutchBallSettingRequest
from ...models.clutch_ball_setting_response import ClutchBallSettingResponse
from ...models.error_response import ErrorResponse
from ...types import Response


def _get_kwargs(
    *,
    body: ClutchBallSettingRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/clutch/ball_setting",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ClutchBallSettingResponse | ErrorResponse | None:
    if response.status_code == 200:
        response_200 = ClutchBallSettingResponse.from_dict(response.json())

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
) -> Response[ClutchBallSettingResponse | ErrorResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ClutchBallSettingRequest,
) -> Response[ClutchBallSettingResponse | ErrorResponse]:
    """Ball safety clutch: setting for a target torque

     The inverse of clutch.ball: the spring force a target slipping torque needs, the spring compression
    (nut setting) that gives it with a given wire, and the wire diameter that gives it at a chosen
    compression.

    Source: [001] Malashchenko V.O., Semenyuk V.F., Lysiak B.R., Parameters of double action ball
    overturn coupling, eq. 1–3; spring checks after Wahl; helical springs to EN 13906-1 with wire to EN
    10270-1 and EN 10270-3; disc springs to DIN EN 16983

    Args:
        body (ClutchBallSettingRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ClutchBallSettingResponse | ErrorResponse]
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
    body: ClutchBallSettingRequest,
) -> ClutchBallSettingResponse | ErrorResponse | None:
    """Ball safety clutch: setting for a target torque

     The inverse of clutch.ball: the spring force a target slipping torque needs, the spring compression
    (nut setting) that gives it with a given wire, and the wire diameter that gives it at a chosen
    compression.

    Source: [001] Malashchenko V.O., Semenyuk V.F., Lysiak B.R., Parameters of double action ball
    overturn coupling, eq. 1–3; spring checks after Wahl; helical springs to EN 13906-1 with wire to EN
    10270-1 and EN 10270-3; disc springs to DIN EN 16983

    Args:
        body (ClutchBallSettingRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ClutchBallSettingResponse | ErrorResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ClutchBallSettingRequest,
) -> Response[ClutchBallSettingResponse | ErrorResponse]:
    """Ball safety clutch: setting for a target torque

     The inverse of clutch.ball: the spring force a target slipping torque needs, the spring compression
    (nut setting) that gives it with a given wire, and the wire diameter that gives it at a chosen
    compression.

    Source: [001] Malashchenko V.O., Semenyuk V.F., Lysiak B.R., Parameters of double action ball
    overturn coupling, eq. 1–3; spring checks after Wahl; helical springs to EN 13906-1 with wire to EN
    10270-1 and EN 10270-3; disc springs to DIN EN 16983

    Args:
        body (ClutchBallSettingRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ClutchBallSettingResponse | ErrorResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: ClutchBallSettingRequest,
) -> ClutchBallSettingResponse | ErrorResponse | None:
    """Ball safety clutch: setting for a target torque

     The inverse of clutch.ball: the spring force a target slipping torque needs, the spring compression
    (nut setting) that gives it with a given wire, and the wire diameter that gives it at a chosen
    compression.

    Source: [001] Malashchenko V.O., Semenyuk V.F., Lysiak B.R., Parameters of double action ball
    overturn coupling, eq. 1–3; spring checks after Wahl; helical springs to EN 13906-1 with wire to EN
    10270-1 and EN 10270-3; disc springs to DIN EN 16983

    Args:
        body (ClutchBallSettingRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ClutchBallSettingResponse | ErrorResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
