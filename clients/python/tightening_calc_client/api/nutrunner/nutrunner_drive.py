from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.nutrunner_drive_request import NutrunnerDriveRequest
from ...models.nutrunner_drive_response import NutrunnerDriveResponse
from ...types import Response


def _get_kwargs(
    *,
    body: NutrunnerDriveRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/nutrunner/drive",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | NutrunnerDriveResponse | None:
    if response.status_code == 200:
        response_200 = NutrunnerDriveResponse.from_dict(response.json())

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
) -> Response[ErrorResponse | NutrunnerDriveResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: NutrunnerDriveRequest,
) -> Response[ErrorResponse | NutrunnerDriveResponse]:
    """Multi-spindle impact nut-runner drive

     Spin-up time of a wheel-nut runner's motor–belt–flywheel–gear drive and the torque one blow puts on
    a spindle, from the drive's kinetic energy stored as elastic twist of the flywheel shaft and the
    spindle. The source gives no worked example; examples[0] is an illustrative six-nut light-truck
    runner.

    Source: [000] Parameters of the drive of a multi-spindle nut-runner (Ukrainian journal article), eq.
    1–10; reconstructions in docs/sources.md; motor curves by the Kloss formula

    Args:
        body (NutrunnerDriveRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | NutrunnerDriveResponse]
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
    body: NutrunnerDriveRequest,
) -> ErrorResponse | NutrunnerDriveResponse | None:
    """Multi-spindle impact nut-runner drive

     Spin-up time of a wheel-nut runner's motor–belt–flywheel–gear drive and the torque one blow puts on
    a spindle, from the drive's kinetic energy stored as elastic twist of the flywheel shaft and the
    spindle. The source gives no worked example; examples[0] is an illustrative six-nut light-truck
    runner.

    Source: [000] Parameters of the drive of a multi-spindle nut-runner (Ukrainian journal article), eq.
    1–10; reconstructions in docs/sources.md; motor curves by the Kloss formula

    Args:
        body (NutrunnerDriveRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | NutrunnerDriveResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: NutrunnerDriveRequest,
) -> Response[ErrorResponse | NutrunnerDriveResponse]:
    """Multi-spindle impact nut-runner drive

     Spin-up time of a wheel-nut runner's motor–belt–flywheel–gear drive and the torque one blow puts on
    a spindle, from the drive's kinetic energy stored as elastic twist of the flywheel shaft and the
    spindle. The source gives no worked example; examples[0] is an illustrative six-nut light-truck
    runner.

    Source: [000] Parameters of the drive of a multi-spindle nut-runner (Ukrainian journal article), eq.
    1–10; reconstructions in docs/sources.md; motor curves by the Kloss formula

    Args:
        body (NutrunnerDriveRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | NutrunnerDriveResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: NutrunnerDriveRequest,
) -> ErrorResponse | NutrunnerDriveResponse | None:
    """Multi-spindle impact nut-runner drive

     Spin-up time of a wheel-nut runner's motor–belt–flywheel–gear drive and the torque one blow puts on
    a spindle, from the drive's kinetic energy stored as elastic twist of the flywheel shaft and the
    spindle. The source gives no worked example; examples[0] is an illustrative six-nut light-truck
    runner.

    Source: [000] Parameters of the drive of a multi-spindle nut-runner (Ukrainian journal article), eq.
    1–10; reconstructions in docs/sources.md; motor curves by the Kloss formula

    Args:
        body (NutrunnerDriveRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | NutrunnerDriveResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
