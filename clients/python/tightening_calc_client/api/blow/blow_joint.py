from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.blow_joint_request import BlowJointRequest
from ...models.blow_joint_response import BlowJointResponse
from ...models.error_response import ErrorResponse
from ...types import Response


def _get_kwargs(
    *,
    body: BlowJointRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/api/v1/blow/joint",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> BlowJointResponse | ErrorResponse | None:
    if response.status_code == 200:
        response_200 = BlowJointResponse.from_dict(response.json())

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
) -> Response[BlowJointResponse | ErrorResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: BlowJointRequest,
) -> Response[BlowJointResponse | ErrorResponse]:
    """Blow into a joint: torque and preload per blow, blows to target

     What a tool delivers into a joint: peak torque and nut rotation per blow, joint torque and preload
    after each blow, blows to reach a target, energy into the joint, and the preload window a clutch-
    limited tool gives.

    Source: Tools: [000] (nut-runner drive energy and stiffness), [002] (rare-impact release speed and
    energy, from impact.rare's closed form), [001] (ball clutch slipping torque); joint: ISO 5393 test
    joints, the tightening relation VDI 2230-1 R13 and the angle relation [004, eq. 8]; the blow: two-
    mass torsional impact with stick-slip of the nut (textbook mechanics).

    Args:
        body (BlowJointRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[BlowJointResponse | ErrorResponse]
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
    body: BlowJointRequest,
) -> BlowJointResponse | ErrorResponse | None:
    """Blow into a joint: torque and preload per blow, blows to target

     What a tool delivers into a joint: peak torque and nut rotation per blow, joint torque and preload
    after each blow, blows to reach a target, energy into the joint, and the preload window a clutch-
    limited tool gives.

    Source: Tools: [000] (nut-runner drive energy and stiffness), [002] (rare-impact release speed and
    energy, from impact.rare's closed form), [001] (ball clutch slipping torque); joint: ISO 5393 test
    joints, the tightening relation VDI 2230-1 R13 and the angle relation [004, eq. 8]; the blow: two-
    mass torsional impact with stick-slip of the nut (textbook mechanics).

    Args:
        body (BlowJointRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        BlowJointResponse | ErrorResponse
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: BlowJointRequest,
) -> Response[BlowJointResponse | ErrorResponse]:
    """Blow into a joint: torque and preload per blow, blows to target

     What a tool delivers into a joint: peak torque and nut rotation per blow, joint torque and preload
    after each blow, blows to reach a target, energy into the joint, and the preload window a clutch-
    limited tool gives.

    Source: Tools: [000] (nut-runner drive energy and stiffness), [002] (rare-impact release speed and
    energy, from impact.rare's closed form), [001] (ball clutch slipping torque); joint: ISO 5393 test
    joints, the tightening relation VDI 2230-1 R13 and the angle relation [004, eq. 8]; the blow: two-
    mass torsional impact with stick-slip of the nut (textbook mechanics).

    Args:
        body (BlowJointRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[BlowJointResponse | ErrorResponse]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: BlowJointRequest,
) -> BlowJointResponse | ErrorResponse | None:
    """Blow into a joint: torque and preload per blow, blows to target

     What a tool delivers into a joint: peak torque and nut rotation per blow, joint torque and preload
    after each blow, blows to reach a target, energy into the joint, and the preload window a clutch-
    limited tool gives.

    Source: Tools: [000] (nut-runner drive energy and stiffness), [002] (rare-impact release speed and
    energy, from impact.rare's closed form), [001] (ball clutch slipping torque); joint: ISO 5393 test
    joints, the tightening relation VDI 2230-1 R13 and the angle relation [004, eq. 8]; the blow: two-
    mass torsional impact with stick-slip of the nut (textbook mechanics).

    Args:
        body (BlowJointRequest):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        BlowJointResponse | ErrorResponse
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
