from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.trace_batch_request import TraceBatchRequest
from ...models.trace_batch_response import TraceBatchResponse
from ...types import Response


def _get_kwargs(
    *,
    body: TraceBatchRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/trace/batch",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | TraceBatchResponse | None:
    if response.status_code == 200:
        response_200 = TraceBatchResponse.from_dict(response.json())

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
) -> Response[ErrorResponse | TraceBatchResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: TraceBatchRequest,
) -> Response[ErrorResponse | TraceBatchResponse]:
    """Many tightening traces of one joint: friction and preload spread, outliers, C_p

     Many torque–angle traces of one joint, each read as trace.analysis reads it: the distribution of the
    total friction and of the preload they imply, the traces whose friction lies apart from the others',
    and the capability C_p, C_pk of the preload against the joint's window F_M,min…F_M,zul.

    Source: [004, eq. 8] differentiated and VDI 2230-1 R13 (the elastic torque rate from the joint's
    compliance and torque coefficient); gradient-drop yield detection as controllers do it [Desoutter-
    CVIR] [AtlasCopco-PF], the YIELD tag of OPC 40450; the joint of VDI 2230-1 R0–R13 (joint.vdi2230);
    modified z-score (Iglewicz and Hoaglin); C_p, C_pk as [ECSS-E-HB-32-23A] prints them

    Args:
        body (TraceBatchRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | TraceBatchResponse]
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
    body: TraceBatchRequest,
) -> ErrorResponse | TraceBatchResponse | None:
    """Many tightening traces of one joint: friction and preload spread, outliers, C_p

     Many torque–angle traces of one joint, each read as trace.analysis reads it: the distribution of the
    total friction and of the preload they imply, the traces whose friction lies apart from the others',
    and the capability C_p, C_pk of the preload against the joint's window F_M,min…F_M,zul.

    Source: [004, eq. 8] differentiated and VDI 2230-1 R13 (the elastic torque rate from the joint's
    compliance and torque coefficient); gradient-drop yield detection as controllers do it [Desoutter-
    CVIR] [AtlasCopco-PF], the YIELD tag of OPC 40450; the joint of VDI 2230-1 R0–R13 (joint.vdi2230);
    modified z-score (Iglewicz and Hoaglin); C_p, C_pk as [ECSS-E-HB-32-23A] prints them

    Args:
        body (TraceBatchRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | TraceBatchResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: TraceBatchRequest,
) -> Response[ErrorResponse | TraceBatchResponse]:
    """Many tightening traces of one joint: friction and preload spread, outliers, C_p

     Many torque–angle traces of one joint, each read as trace.analysis reads it: the distribution of the
    total friction and of the preload they imply, the traces whose friction lies apart from the others',
    and the capability C_p, C_pk of the preload against the joint's window F_M,min…F_M,zul.

    Source: [004, eq. 8] differentiated and VDI 2230-1 R13 (the elastic torque rate from the joint's
    compliance and torque coefficient); gradient-drop yield detection as controllers do it [Desoutter-
    CVIR] [AtlasCopco-PF], the YIELD tag of OPC 40450; the joint of VDI 2230-1 R0–R13 (joint.vdi2230);
    modified z-score (Iglewicz and Hoaglin); C_p, C_pk as [ECSS-E-HB-32-23A] prints them

    Args:
        body (TraceBatchRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | TraceBatchResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: TraceBatchRequest,
) -> ErrorResponse | TraceBatchResponse | None:
    """Many tightening traces of one joint: friction and preload spread, outliers, C_p

     Many torque–angle traces of one joint, each read as trace.analysis reads it: the distribution of the
    total friction and of the preload they imply, the traces whose friction lies apart from the others',
    and the capability C_p, C_pk of the preload against the joint's window F_M,min…F_M,zul.

    Source: [004, eq. 8] differentiated and VDI 2230-1 R13 (the elastic torque rate from the joint's
    compliance and torque coefficient); gradient-drop yield detection as controllers do it [Desoutter-
    CVIR] [AtlasCopco-PF], the YIELD tag of OPC 40450; the joint of VDI 2230-1 R0–R13 (joint.vdi2230);
    modified z-score (Iglewicz and Hoaglin); C_p, C_pk as [ECSS-E-HB-32-23A] prints them

    Args:
        body (TraceBatchRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | TraceBatchResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
