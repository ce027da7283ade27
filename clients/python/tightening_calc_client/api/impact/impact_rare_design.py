from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.impact_rare_design_request import ImpactRareDesignRequest
from ...models.impact_rare_design_response import ImpactRareDesignResponse
from ...types import Response


def _get_kwargs(
    *,
    body: ImpactRareDesignRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/impact/rare_design",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | ImpactRareDesignResponse | None:
    if response.status_code == 200:
        response_200 = ImpactRareDesignResponse.from_dict(response.json())

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
) -> Response[ErrorResponse | ImpactRareDesignResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ImpactRareDesignRequest,
) -> Response[ErrorResponse | ImpactRareDesignResponse]:
    """Rare-impact wrench: the nearest design that passes

     For a striker design that fails a check of impact.rare (edge blow, c3 > c1, λ1 < λ3, reach, return,
    re-lock): the smallest change of the springs' rates and preloads (and the striker's mass) that
    passes every check, or the statement that none does in the ranges, naming the binding checks.

    Source: [002] through impact.rare's closed form (its checks and design rules); the search is this
    product's

    Args:
        body (ImpactRareDesignRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | ImpactRareDesignResponse]
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
    body: ImpactRareDesignRequest,
) -> ErrorResponse | ImpactRareDesignResponse | None:
    """Rare-impact wrench: the nearest design that passes

     For a striker design that fails a check of impact.rare (edge blow, c3 > c1, λ1 < λ3, reach, return,
    re-lock): the smallest change of the springs' rates and preloads (and the striker's mass) that
    passes every check, or the statement that none does in the ranges, naming the binding checks.

    Source: [002] through impact.rare's closed form (its checks and design rules); the search is this
    product's

    Args:
        body (ImpactRareDesignRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | ImpactRareDesignResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ImpactRareDesignRequest,
) -> Response[ErrorResponse | ImpactRareDesignResponse]:
    """Rare-impact wrench: the nearest design that passes

     For a striker design that fails a check of impact.rare (edge blow, c3 > c1, λ1 < λ3, reach, return,
    re-lock): the smallest change of the springs' rates and preloads (and the striker's mass) that
    passes every check, or the statement that none does in the ranges, naming the binding checks.

    Source: [002] through impact.rare's closed form (its checks and design rules); the search is this
    product's

    Args:
        body (ImpactRareDesignRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | ImpactRareDesignResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: ImpactRareDesignRequest,
) -> ErrorResponse | ImpactRareDesignResponse | None:
    """Rare-impact wrench: the nearest design that passes

     For a striker design that fails a check of impact.rare (edge blow, c3 > c1, λ1 < λ3, reach, return,
    re-lock): the smallest change of the springs' rates and preloads (and the striker's mass) that
    passes every check, or the statement that none does in the ranges, naming the binding checks.

    Source: [002] through impact.rare's closed form (its checks and design rules); the search is this
    product's

    Args:
        body (ImpactRareDesignRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | ImpactRareDesignResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
