from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.joint_clamp_capability_request import JointClampCapabilityRequest
from ...models.joint_clamp_capability_response import JointClampCapabilityResponse
from ...types import Response


def _get_kwargs(
    *,
    body: JointClampCapabilityRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/joint/clamp_capability",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | JointClampCapabilityResponse | None:
    if response.status_code == 200:
        response_200 = JointClampCapabilityResponse.from_dict(response.json())

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
) -> Response[ErrorResponse | JointClampCapabilityResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: JointClampCapabilityRequest,
) -> Response[ErrorResponse | JointClampCapabilityResponse]:
    """Clamp-force capability: ppm below F_M,min and above F_M,zul of a tool on a joint

     A joint (as joint.vdi2230), the tool's torque law (σ, or Cm/Cmk at a tolerance, or measured torques)
    and the friction laws of the lot (uniform, normal, truncated, lognormal, triangular; correlated):
    the distribution of the assembly preload and of the bolt's utilisation, the share of bolts below
    F_M,min and above F_M,zul in ppm with their error, Cpk on clamp force and the α_A the process has.

    Source: VDI 2230-1 R7 and R13 (the joint's preload at a torque and its permissible preload), VDI/VDE
    2645-2 (Cm, Cmk of the tool), VDI/VDE 2862 as a public secondary source states its categories'
    minimum [CSP2862]; the copula's rank correlation after [Kruskal1958]

    Args:
        body (JointClampCapabilityRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | JointClampCapabilityResponse]
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
    body: JointClampCapabilityRequest,
) -> ErrorResponse | JointClampCapabilityResponse | None:
    """Clamp-force capability: ppm below F_M,min and above F_M,zul of a tool on a joint

     A joint (as joint.vdi2230), the tool's torque law (σ, or Cm/Cmk at a tolerance, or measured torques)
    and the friction laws of the lot (uniform, normal, truncated, lognormal, triangular; correlated):
    the distribution of the assembly preload and of the bolt's utilisation, the share of bolts below
    F_M,min and above F_M,zul in ppm with their error, Cpk on clamp force and the α_A the process has.

    Source: VDI 2230-1 R7 and R13 (the joint's preload at a torque and its permissible preload), VDI/VDE
    2645-2 (Cm, Cmk of the tool), VDI/VDE 2862 as a public secondary source states its categories'
    minimum [CSP2862]; the copula's rank correlation after [Kruskal1958]

    Args:
        body (JointClampCapabilityRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | JointClampCapabilityResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: JointClampCapabilityRequest,
) -> Response[ErrorResponse | JointClampCapabilityResponse]:
    """Clamp-force capability: ppm below F_M,min and above F_M,zul of a tool on a joint

     A joint (as joint.vdi2230), the tool's torque law (σ, or Cm/Cmk at a tolerance, or measured torques)
    and the friction laws of the lot (uniform, normal, truncated, lognormal, triangular; correlated):
    the distribution of the assembly preload and of the bolt's utilisation, the share of bolts below
    F_M,min and above F_M,zul in ppm with their error, Cpk on clamp force and the α_A the process has.

    Source: VDI 2230-1 R7 and R13 (the joint's preload at a torque and its permissible preload), VDI/VDE
    2645-2 (Cm, Cmk of the tool), VDI/VDE 2862 as a public secondary source states its categories'
    minimum [CSP2862]; the copula's rank correlation after [Kruskal1958]

    Args:
        body (JointClampCapabilityRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | JointClampCapabilityResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: JointClampCapabilityRequest,
) -> ErrorResponse | JointClampCapabilityResponse | None:
    """Clamp-force capability: ppm below F_M,min and above F_M,zul of a tool on a joint

     A joint (as joint.vdi2230), the tool's torque law (σ, or Cm/Cmk at a tolerance, or measured torques)
    and the friction laws of the lot (uniform, normal, truncated, lognormal, triangular; correlated):
    the distribution of the assembly preload and of the bolt's utilisation, the share of bolts below
    F_M,min and above F_M,zul in ppm with their error, Cpk on clamp force and the α_A the process has.

    Source: VDI 2230-1 R7 and R13 (the joint's preload at a torque and its permissible preload), VDI/VDE
    2645-2 (Cm, Cmk of the tool), VDI/VDE 2862 as a public secondary source states its categories'
    minimum [CSP2862]; the copula's rank correlation after [Kruskal1958]

    Args:
        body (JointClampCapabilityRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | JointClampCapabilityResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
