from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.tool_capability_request import ToolCapabilityRequest
from ...models.tool_capability_response import ToolCapabilityResponse
from ...types import Response


def _get_kwargs(
    *,
    body: ToolCapabilityRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/tool/capability",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | ToolCapabilityResponse | None:
    if response.status_code == 200:
        response_200 = ToolCapabilityResponse.from_dict(response.json())

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
) -> Response[ErrorResponse | ToolCapabilityResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ToolCapabilityRequest,
) -> Response[ErrorResponse | ToolCapabilityResponse]:
    """Tightening tool capability: Cm, Cmk (Cp, Cpk) from measured torques

     From the torques a tool gave in a test (the values, or their mean and standard deviation) and a
    tolerance: the mean, the standard deviation, Cm and Cmk (a machine test) or Cp and Cpk (a process
    test), the share outside the tolerance they imply, and whether the tool passes at the index and
    sample size required.

    Source: VDI/VDE 2645-2 (machine capability, Cm and Cmk) and VDI/VDE 2645-3 (process capability, Cp
    and Cpk), as public secondary sources print them; worked example [Danikor]; ISO 5393 hard- and soft-
    joint runs pooled into one sample [Danikor-ISO5393]

    Args:
        body (ToolCapabilityRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | ToolCapabilityResponse]
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
    body: ToolCapabilityRequest,
) -> ErrorResponse | ToolCapabilityResponse | None:
    """Tightening tool capability: Cm, Cmk (Cp, Cpk) from measured torques

     From the torques a tool gave in a test (the values, or their mean and standard deviation) and a
    tolerance: the mean, the standard deviation, Cm and Cmk (a machine test) or Cp and Cpk (a process
    test), the share outside the tolerance they imply, and whether the tool passes at the index and
    sample size required.

    Source: VDI/VDE 2645-2 (machine capability, Cm and Cmk) and VDI/VDE 2645-3 (process capability, Cp
    and Cpk), as public secondary sources print them; worked example [Danikor]; ISO 5393 hard- and soft-
    joint runs pooled into one sample [Danikor-ISO5393]

    Args:
        body (ToolCapabilityRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | ToolCapabilityResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ToolCapabilityRequest,
) -> Response[ErrorResponse | ToolCapabilityResponse]:
    """Tightening tool capability: Cm, Cmk (Cp, Cpk) from measured torques

     From the torques a tool gave in a test (the values, or their mean and standard deviation) and a
    tolerance: the mean, the standard deviation, Cm and Cmk (a machine test) or Cp and Cpk (a process
    test), the share outside the tolerance they imply, and whether the tool passes at the index and
    sample size required.

    Source: VDI/VDE 2645-2 (machine capability, Cm and Cmk) and VDI/VDE 2645-3 (process capability, Cp
    and Cpk), as public secondary sources print them; worked example [Danikor]; ISO 5393 hard- and soft-
    joint runs pooled into one sample [Danikor-ISO5393]

    Args:
        body (ToolCapabilityRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | ToolCapabilityResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: ToolCapabilityRequest,
) -> ErrorResponse | ToolCapabilityResponse | None:
    """Tightening tool capability: Cm, Cmk (Cp, Cpk) from measured torques

     From the torques a tool gave in a test (the values, or their mean and standard deviation) and a
    tolerance: the mean, the standard deviation, Cm and Cmk (a machine test) or Cp and Cpk (a process
    test), the share outside the tolerance they imply, and whether the tool passes at the index and
    sample size required.

    Source: VDI/VDE 2645-2 (machine capability, Cm and Cmk) and VDI/VDE 2645-3 (process capability, Cp
    and Cpk), as public secondary sources print them; worked example [Danikor]; ISO 5393 hard- and soft-
    joint runs pooled into one sample [Danikor-ISO5393]

    Args:
        body (ToolCapabilityRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | ToolCapabilityResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
