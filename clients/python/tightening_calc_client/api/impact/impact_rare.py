from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.impact_rare_request import ImpactRareRequest
from ...models.impact_rare_response import ImpactRareResponse
from ...types import Response


def _get_kwargs(
    *,
    body: ImpactRareRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/impact/rare",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | ImpactRareResponse | None:
    if response.status_code == 200:
        response_200 = ImpactRareResponse.from_dict(response.json())

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
) -> Response[ErrorResponse | ImpactRareResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ImpactRareRequest,
) -> Response[ErrorResponse | ImpactRareResponse]:
    """Rare-impact wrench: striker engagement

     Release speed, spin-up time and whether the axially moving striker engages the anvil fully (no edge
    blow), returns and re-locks, over one whole impact cycle.

    Source: [002] N. V. Vodolazskaya, V. M. Iskritsky, Dynamics of the percussive mechanism of a rare-
    impact nut wrench with an axially moving striker (DonNTU / DGMA); scan [003]. Stage 1 is derived
    from a Lagrangian of a stated roller geometry (the printed eq. 1 does not balance). The paper gives
    no numeric example: the defaults are a plausible reference design.

    Args:
        body (ImpactRareRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | ImpactRareResponse]
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
    body: ImpactRareRequest,
) -> ErrorResponse | ImpactRareResponse | None:
    """Rare-impact wrench: striker engagement

     Release speed, spin-up time and whether the axially moving striker engages the anvil fully (no edge
    blow), returns and re-locks, over one whole impact cycle.

    Source: [002] N. V. Vodolazskaya, V. M. Iskritsky, Dynamics of the percussive mechanism of a rare-
    impact nut wrench with an axially moving striker (DonNTU / DGMA); scan [003]. Stage 1 is derived
    from a Lagrangian of a stated roller geometry (the printed eq. 1 does not balance). The paper gives
    no numeric example: the defaults are a plausible reference design.

    Args:
        body (ImpactRareRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | ImpactRareResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ImpactRareRequest,
) -> Response[ErrorResponse | ImpactRareResponse]:
    """Rare-impact wrench: striker engagement

     Release speed, spin-up time and whether the axially moving striker engages the anvil fully (no edge
    blow), returns and re-locks, over one whole impact cycle.

    Source: [002] N. V. Vodolazskaya, V. M. Iskritsky, Dynamics of the percussive mechanism of a rare-
    impact nut wrench with an axially moving striker (DonNTU / DGMA); scan [003]. Stage 1 is derived
    from a Lagrangian of a stated roller geometry (the printed eq. 1 does not balance). The paper gives
    no numeric example: the defaults are a plausible reference design.

    Args:
        body (ImpactRareRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | ImpactRareResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: ImpactRareRequest,
) -> ErrorResponse | ImpactRareResponse | None:
    """Rare-impact wrench: striker engagement

     Release speed, spin-up time and whether the axially moving striker engages the anvil fully (no edge
    blow), returns and re-locks, over one whole impact cycle.

    Source: [002] N. V. Vodolazskaya, V. M. Iskritsky, Dynamics of the percussive mechanism of a rare-
    impact nut wrench with an axially moving striker (DonNTU / DGMA); scan [003]. Stage 1 is derived
    from a Lagrangian of a stated roller geometry (the printed eq. 1 does not balance). The paper gives
    no numeric example: the defaults are a plausible reference design.

    Args:
        body (ImpactRareRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | ImpactRareResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
