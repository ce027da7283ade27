from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.joint_clamp_capability_study_request import JointClampCapabilityStudyRequest
from ...types import Response


def _get_kwargs(
    *,
    body: JointClampCapabilityStudyRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/joint/clamp_capability/study",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Any | ErrorResponse | None:
    if response.status_code == 202:
        response_202 = response.json()
        return response_202

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


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[Any | ErrorResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: JointClampCapabilityStudyRequest,
) -> Response[Any | ErrorResponse]:
    """Clamp-force capability: ppm below F_M,min and above F_M,zul of a tool on a joint: a design study
    (grid, Monte Carlo, LHS, Sobol')

     Vary up to 12 inputs (a grid: up to 3) by distribution (uniform, normal, triangular, lognormal) with
    method one of grid, monte_carlo, lhs, sobol, points, or list the designs themselves (`points`: JSON
    rows, or `points_csv`); returns 202 with a job to poll at GET /api/v1/jobs/{id}.

    Args:
        body (JointClampCapabilityStudyRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Any | ErrorResponse]
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
    body: JointClampCapabilityStudyRequest,
) -> Any | ErrorResponse | None:
    """Clamp-force capability: ppm below F_M,min and above F_M,zul of a tool on a joint: a design study
    (grid, Monte Carlo, LHS, Sobol')

     Vary up to 12 inputs (a grid: up to 3) by distribution (uniform, normal, triangular, lognormal) with
    method one of grid, monte_carlo, lhs, sobol, points, or list the designs themselves (`points`: JSON
    rows, or `points_csv`); returns 202 with a job to poll at GET /api/v1/jobs/{id}.

    Args:
        body (JointClampCapabilityStudyRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Any | ErrorResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: JointClampCapabilityStudyRequest,
) -> Response[Any | ErrorResponse]:
    """Clamp-force capability: ppm below F_M,min and above F_M,zul of a tool on a joint: a design study
    (grid, Monte Carlo, LHS, Sobol')

     Vary up to 12 inputs (a grid: up to 3) by distribution (uniform, normal, triangular, lognormal) with
    method one of grid, monte_carlo, lhs, sobol, points, or list the designs themselves (`points`: JSON
    rows, or `points_csv`); returns 202 with a job to poll at GET /api/v1/jobs/{id}.

    Args:
        body (JointClampCapabilityStudyRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Any | ErrorResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: JointClampCapabilityStudyRequest,
) -> Any | ErrorResponse | None:
    """Clamp-force capability: ppm below F_M,min and above F_M,zul of a tool on a joint: a design study
    (grid, Monte Carlo, LHS, Sobol')

     Vary up to 12 inputs (a grid: up to 3) by distribution (uniform, normal, triangular, lognormal) with
    method one of grid, monte_carlo, lhs, sobol, points, or list the designs themselves (`points`: JSON
    rows, or `points_csv`); returns 202 with a job to poll at GET /api/v1/jobs/{id}.

    Args:
        body (JointClampCapabilityStudyRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Any | ErrorResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
