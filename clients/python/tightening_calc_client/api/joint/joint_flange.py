from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.joint_flange_request import JointFlangeRequest
from ...models.joint_flange_response import JointFlangeResponse
from ...types import Response


def _get_kwargs(
    *,
    body: JointFlangeRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/joint/flange",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | JointFlangeResponse | None:
    if response.status_code == 200:
        response_200 = JointFlangeResponse.from_dict(response.json())

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
) -> Response[ErrorResponse | JointFlangeResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: JointFlangeRequest,
) -> Response[ErrorResponse | JointFlangeResponse]:
    """Ring flange of z bolts: the most loaded bolt through VDI 2230

     A rigid ring flange of z equal bolts on a bolt circle under an axial force, a bending moment, a
    shear force and a torque: the most loaded bolt's working and transverse loads, then that bolt
    through the single-bolt chain of joint.vdi2230 (preload window, working and alternating stress,
    slipping, opening).

    Source: VDI 2230-1:2015 §3.1 and steps R0–R13 (the most loaded bolt of a rigid flange, the
    simplification of VDI 2230 Part 2); the single-bolt chain as in joint.vdi2230

    Args:
        body (JointFlangeRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | JointFlangeResponse]
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
    body: JointFlangeRequest,
) -> ErrorResponse | JointFlangeResponse | None:
    """Ring flange of z bolts: the most loaded bolt through VDI 2230

     A rigid ring flange of z equal bolts on a bolt circle under an axial force, a bending moment, a
    shear force and a torque: the most loaded bolt's working and transverse loads, then that bolt
    through the single-bolt chain of joint.vdi2230 (preload window, working and alternating stress,
    slipping, opening).

    Source: VDI 2230-1:2015 §3.1 and steps R0–R13 (the most loaded bolt of a rigid flange, the
    simplification of VDI 2230 Part 2); the single-bolt chain as in joint.vdi2230

    Args:
        body (JointFlangeRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | JointFlangeResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: JointFlangeRequest,
) -> Response[ErrorResponse | JointFlangeResponse]:
    """Ring flange of z bolts: the most loaded bolt through VDI 2230

     A rigid ring flange of z equal bolts on a bolt circle under an axial force, a bending moment, a
    shear force and a torque: the most loaded bolt's working and transverse loads, then that bolt
    through the single-bolt chain of joint.vdi2230 (preload window, working and alternating stress,
    slipping, opening).

    Source: VDI 2230-1:2015 §3.1 and steps R0–R13 (the most loaded bolt of a rigid flange, the
    simplification of VDI 2230 Part 2); the single-bolt chain as in joint.vdi2230

    Args:
        body (JointFlangeRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | JointFlangeResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: JointFlangeRequest,
) -> ErrorResponse | JointFlangeResponse | None:
    """Ring flange of z bolts: the most loaded bolt through VDI 2230

     A rigid ring flange of z equal bolts on a bolt circle under an axial force, a bending moment, a
    shear force and a torque: the most loaded bolt's working and transverse loads, then that bolt
    through the single-bolt chain of joint.vdi2230 (preload window, working and alternating stress,
    slipping, opening).

    Source: VDI 2230-1:2015 §3.1 and steps R0–R13 (the most loaded bolt of a rigid flange, the
    simplification of VDI 2230 Part 2); the single-bolt chain as in joint.vdi2230

    Args:
        body (JointFlangeRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | JointFlangeResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
