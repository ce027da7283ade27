from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.friction_iso_16047_request import FrictionIso16047Request
from ...models.friction_iso_16047_response import FrictionIso16047Response
from ...types import Response


def _get_kwargs(
    *,
    body: FrictionIso16047Request,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/friction/iso16047",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | FrictionIso16047Response | None:
    if response.status_code == 200:
        response_200 = FrictionIso16047Response.from_dict(response.json())

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
) -> Response[ErrorResponse | FrictionIso16047Response]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: FrictionIso16047Request,
) -> Response[ErrorResponse | FrictionIso16047Response]:
    """Friction from a torque/clamp-force test series (ISO 16047)

     From the tightening torque, thread torque and clamp force of each test in a series and the thread (a
    designation, or d, P and the bearing diameters): the torque coefficient K and the thread, bearing
    and total friction coefficients of each test, with their mean, standard deviation, minimum and
    maximum.

    Source: ISO 16047 (torque/clamp force testing), its relations in the form of VDI 2230-1 R13; thread
    and head geometry: ISO 68-1, ISO 261, ISO 273, ISO 4017

    Args:
        body (FrictionIso16047Request):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | FrictionIso16047Response]
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
    body: FrictionIso16047Request,
) -> ErrorResponse | FrictionIso16047Response | None:
    """Friction from a torque/clamp-force test series (ISO 16047)

     From the tightening torque, thread torque and clamp force of each test in a series and the thread (a
    designation, or d, P and the bearing diameters): the torque coefficient K and the thread, bearing
    and total friction coefficients of each test, with their mean, standard deviation, minimum and
    maximum.

    Source: ISO 16047 (torque/clamp force testing), its relations in the form of VDI 2230-1 R13; thread
    and head geometry: ISO 68-1, ISO 261, ISO 273, ISO 4017

    Args:
        body (FrictionIso16047Request):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | FrictionIso16047Response
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: FrictionIso16047Request,
) -> Response[ErrorResponse | FrictionIso16047Response]:
    """Friction from a torque/clamp-force test series (ISO 16047)

     From the tightening torque, thread torque and clamp force of each test in a series and the thread (a
    designation, or d, P and the bearing diameters): the torque coefficient K and the thread, bearing
    and total friction coefficients of each test, with their mean, standard deviation, minimum and
    maximum.

    Source: ISO 16047 (torque/clamp force testing), its relations in the form of VDI 2230-1 R13; thread
    and head geometry: ISO 68-1, ISO 261, ISO 273, ISO 4017

    Args:
        body (FrictionIso16047Request):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | FrictionIso16047Response]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: FrictionIso16047Request,
) -> ErrorResponse | FrictionIso16047Response | None:
    """Friction from a torque/clamp-force test series (ISO 16047)

     From the tightening torque, thread torque and clamp force of each test in a series and the thread (a
    designation, or d, P and the bearing diameters): the torque coefficient K and the thread, bearing
    and total friction coefficients of each test, with their mean, standard deviation, minimum and
    maximum.

    Source: ISO 16047 (torque/clamp force testing), its relations in the form of VDI 2230-1 R13; thread
    and head geometry: ISO 68-1, ISO 261, ISO 273, ISO 4017

    Args:
        body (FrictionIso16047Request):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | FrictionIso16047Response
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
