from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.joint_audit_request import JointAuditRequest
from ...models.joint_audit_response import JointAuditResponse
from ...types import Response


def _get_kwargs(
    *,
    body: JointAuditRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/joint/audit",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | JointAuditResponse | None:
    if response.status_code == 200:
        response_200 = JointAuditResponse.from_dict(response.json())

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
) -> Response[ErrorResponse | JointAuditResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: JointAuditRequest,
) -> Response[ErrorResponse | JointAuditResponse]:
    """Audit window: first-motion, breakaway and mark torque of a tightened joint

     For a torque specification and a joint: the torque each audit method should read, as acceptance
    limits: first motion in the tightening direction, breakaway in the loosening direction (the thread's
    pitch helps) and the mark torque, read at once and after embedding, with the static friction's
    excess over the kinetic.

    Source: VDI 2230-1 R4 (embedding) and R13 (tightening and loosening torque), the joint of
    joint.vdi2230; audit methods as public secondary sources describe them [TorqueAudit]; static
    friction excess [FrictionTables]; published restart and untightening torques [Bickford],
    [BoltScience]

    Args:
        body (JointAuditRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | JointAuditResponse]
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
    body: JointAuditRequest,
) -> ErrorResponse | JointAuditResponse | None:
    """Audit window: first-motion, breakaway and mark torque of a tightened joint

     For a torque specification and a joint: the torque each audit method should read, as acceptance
    limits: first motion in the tightening direction, breakaway in the loosening direction (the thread's
    pitch helps) and the mark torque, read at once and after embedding, with the static friction's
    excess over the kinetic.

    Source: VDI 2230-1 R4 (embedding) and R13 (tightening and loosening torque), the joint of
    joint.vdi2230; audit methods as public secondary sources describe them [TorqueAudit]; static
    friction excess [FrictionTables]; published restart and untightening torques [Bickford],
    [BoltScience]

    Args:
        body (JointAuditRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | JointAuditResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: JointAuditRequest,
) -> Response[ErrorResponse | JointAuditResponse]:
    """Audit window: first-motion, breakaway and mark torque of a tightened joint

     For a torque specification and a joint: the torque each audit method should read, as acceptance
    limits: first motion in the tightening direction, breakaway in the loosening direction (the thread's
    pitch helps) and the mark torque, read at once and after embedding, with the static friction's
    excess over the kinetic.

    Source: VDI 2230-1 R4 (embedding) and R13 (tightening and loosening torque), the joint of
    joint.vdi2230; audit methods as public secondary sources describe them [TorqueAudit]; static
    friction excess [FrictionTables]; published restart and untightening torques [Bickford],
    [BoltScience]

    Args:
        body (JointAuditRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | JointAuditResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: JointAuditRequest,
) -> ErrorResponse | JointAuditResponse | None:
    """Audit window: first-motion, breakaway and mark torque of a tightened joint

     For a torque specification and a joint: the torque each audit method should read, as acceptance
    limits: first motion in the tightening direction, breakaway in the loosening direction (the thread's
    pitch helps) and the mark torque, read at once and after embedding, with the static friction's
    excess over the kinetic.

    Source: VDI 2230-1 R4 (embedding) and R13 (tightening and loosening torque), the joint of
    joint.vdi2230; audit methods as public secondary sources describe them [TorqueAudit]; static
    friction excess [FrictionTables]; published restart and untightening torques [Bickford],
    [BoltScience]

    Args:
        body (JointAuditRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | JointAuditResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
