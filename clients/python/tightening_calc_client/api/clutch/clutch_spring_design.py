from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.clutch_spring_design_request import ClutchSpringDesignRequest
from ...models.clutch_spring_design_response import ClutchSpringDesignResponse
from ...models.error_response import ErrorResponse
from ...types import Response


def _get_kwargs(
    *,
    body: ClutchSpringDesignRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/clutch/spring_design",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ClutchSpringDesignResponse | ErrorResponse | None:
    if response.status_code == 200:
        response_200 = ClutchSpringDesignResponse.from_dict(response.json())

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
) -> Response[ClutchSpringDesignResponse | ErrorResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ClutchSpringDesignRequest,
) -> Response[ClutchSpringDesignResponse | ErrorResponse]:
    """Ball safety clutch: the spring for a setting (EN 13906-1, DIN EN 16983)

     The helical compression spring a ball clutch's setting needs: wire, mean diameter, coils and free
    length from the clutch's spring force and stroke and the space, checked to EN 13906-1 (stress at the
    setting and at full stroke, solid length with the minimum gap sum, buckling, spring index); where
    none fits, the binding limit and the nearest spring that passes every other check. Or a stack of DIN
    2093 standard disc springs (n in parallel, i in series) to DIN EN 16983: deflection per disc within
    0.75 h0, σ_OM within R_e, the stack within the pocket.

    Source: [001, eq. 1–3] for the force; EN 13906-1 for the spring; EN 10270-1 wire sizes; DIN EN 16983
    and DIN 2093's standard discs for a disc pack

    Args:
        body (ClutchSpringDesignRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ClutchSpringDesignResponse | ErrorResponse]
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
    body: ClutchSpringDesignRequest,
) -> ClutchSpringDesignResponse | ErrorResponse | None:
    """Ball safety clutch: the spring for a setting (EN 13906-1, DIN EN 16983)

     The helical compression spring a ball clutch's setting needs: wire, mean diameter, coils and free
    length from the clutch's spring force and stroke and the space, checked to EN 13906-1 (stress at the
    setting and at full stroke, solid length with the minimum gap sum, buckling, spring index); where
    none fits, the binding limit and the nearest spring that passes every other check. Or a stack of DIN
    2093 standard disc springs (n in parallel, i in series) to DIN EN 16983: deflection per disc within
    0.75 h0, σ_OM within R_e, the stack within the pocket.

    Source: [001, eq. 1–3] for the force; EN 13906-1 for the spring; EN 10270-1 wire sizes; DIN EN 16983
    and DIN 2093's standard discs for a disc pack

    Args:
        body (ClutchSpringDesignRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ClutchSpringDesignResponse | ErrorResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ClutchSpringDesignRequest,
) -> Response[ClutchSpringDesignResponse | ErrorResponse]:
    """Ball safety clutch: the spring for a setting (EN 13906-1, DIN EN 16983)

     The helical compression spring a ball clutch's setting needs: wire, mean diameter, coils and free
    length from the clutch's spring force and stroke and the space, checked to EN 13906-1 (stress at the
    setting and at full stroke, solid length with the minimum gap sum, buckling, spring index); where
    none fits, the binding limit and the nearest spring that passes every other check. Or a stack of DIN
    2093 standard disc springs (n in parallel, i in series) to DIN EN 16983: deflection per disc within
    0.75 h0, σ_OM within R_e, the stack within the pocket.

    Source: [001, eq. 1–3] for the force; EN 13906-1 for the spring; EN 10270-1 wire sizes; DIN EN 16983
    and DIN 2093's standard discs for a disc pack

    Args:
        body (ClutchSpringDesignRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ClutchSpringDesignResponse | ErrorResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: ClutchSpringDesignRequest,
) -> ClutchSpringDesignResponse | ErrorResponse | None:
    """Ball safety clutch: the spring for a setting (EN 13906-1, DIN EN 16983)

     The helical compression spring a ball clutch's setting needs: wire, mean diameter, coils and free
    length from the clutch's spring force and stroke and the space, checked to EN 13906-1 (stress at the
    setting and at full stroke, solid length with the minimum gap sum, buckling, spring index); where
    none fits, the binding limit and the nearest spring that passes every other check. Or a stack of DIN
    2093 standard disc springs (n in parallel, i in series) to DIN EN 16983: deflection per disc within
    0.75 h0, σ_OM within R_e, the stack within the pocket.

    Source: [001, eq. 1–3] for the force; EN 13906-1 for the spring; EN 10270-1 wire sizes; DIN EN 16983
    and DIN 2093's standard discs for a disc pack

    Args:
        body (ClutchSpringDesignRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ClutchSpringDesignResponse | ErrorResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
