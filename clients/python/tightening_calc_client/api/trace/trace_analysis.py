from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.trace_analysis_request import TraceAnalysisRequest
from ...models.trace_analysis_response import TraceAnalysisResponse
from ...types import Response


def _get_kwargs(
    *,
    body: TraceAnalysisRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/trace/analysis",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | TraceAnalysisResponse | None:
    if response.status_code == 200:
        response_200 = TraceAnalysisResponse.from_dict(response.json())

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
) -> Response[ErrorResponse | TraceAnalysisResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: TraceAnalysisRequest,
) -> Response[ErrorResponse | TraceAnalysisResponse]:
    """Tightening trace read against the joint: snug, rate, yield, friction and preload

     A torque–angle trace as a nut-runner records it, with the joint it tightened: the steps, the snug
    point, the elastic torque rate and the rate the joint predicts, the yield point by gradient drop,
    the total friction the rate implies through the joint's compliance, the preload at the end with
    bounds from the compliance's and the friction split's uncertainty, and verdicts against
    F_M,min…F_M,zul and yield.

    Source: [004, eq. 8] differentiated and VDI 2230-1 R13 (the elastic torque rate from the joint's
    compliance and torque coefficient); gradient-drop yield detection as controllers do it [Desoutter-
    CVIR] [AtlasCopco-PF], the YIELD tag of OPC 40450; the joint of VDI 2230-1 R0–R13 (joint.vdi2230)

    Args:
        body (TraceAnalysisRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | TraceAnalysisResponse]
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
    body: TraceAnalysisRequest,
) -> ErrorResponse | TraceAnalysisResponse | None:
    """Tightening trace read against the joint: snug, rate, yield, friction and preload

     A torque–angle trace as a nut-runner records it, with the joint it tightened: the steps, the snug
    point, the elastic torque rate and the rate the joint predicts, the yield point by gradient drop,
    the total friction the rate implies through the joint's compliance, the preload at the end with
    bounds from the compliance's and the friction split's uncertainty, and verdicts against
    F_M,min…F_M,zul and yield.

    Source: [004, eq. 8] differentiated and VDI 2230-1 R13 (the elastic torque rate from the joint's
    compliance and torque coefficient); gradient-drop yield detection as controllers do it [Desoutter-
    CVIR] [AtlasCopco-PF], the YIELD tag of OPC 40450; the joint of VDI 2230-1 R0–R13 (joint.vdi2230)

    Args:
        body (TraceAnalysisRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | TraceAnalysisResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: TraceAnalysisRequest,
) -> Response[ErrorResponse | TraceAnalysisResponse]:
    """Tightening trace read against the joint: snug, rate, yield, friction and preload

     A torque–angle trace as a nut-runner records it, with the joint it tightened: the steps, the snug
    point, the elastic torque rate and the rate the joint predicts, the yield point by gradient drop,
    the total friction the rate implies through the joint's compliance, the preload at the end with
    bounds from the compliance's and the friction split's uncertainty, and verdicts against
    F_M,min…F_M,zul and yield.

    Source: [004, eq. 8] differentiated and VDI 2230-1 R13 (the elastic torque rate from the joint's
    compliance and torque coefficient); gradient-drop yield detection as controllers do it [Desoutter-
    CVIR] [AtlasCopco-PF], the YIELD tag of OPC 40450; the joint of VDI 2230-1 R0–R13 (joint.vdi2230)

    Args:
        body (TraceAnalysisRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | TraceAnalysisResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: TraceAnalysisRequest,
) -> ErrorResponse | TraceAnalysisResponse | None:
    """Tightening trace read against the joint: snug, rate, yield, friction and preload

     A torque–angle trace as a nut-runner records it, with the joint it tightened: the steps, the snug
    point, the elastic torque rate and the rate the joint predicts, the yield point by gradient drop,
    the total friction the rate implies through the joint's compliance, the preload at the end with
    bounds from the compliance's and the friction split's uncertainty, and verdicts against
    F_M,min…F_M,zul and yield.

    Source: [004, eq. 8] differentiated and VDI 2230-1 R13 (the elastic torque rate from the joint's
    compliance and torque coefficient); gradient-drop yield detection as controllers do it [Desoutter-
    CVIR] [AtlasCopco-PF], the YIELD tag of OPC 40450; the joint of VDI 2230-1 R0–R13 (joint.vdi2230)

    Args:
        body (TraceAnalysisRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | TraceAnalysisResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
