from http import HTTPStatus
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_response import ErrorResponse
from ...models.get_job_response_get_job import GetJobResponseGetJob
from ...models.http_validation_error import HTTPValidationError
from ...types import UNSET, Response, Unset


def _get_kwargs(
    job_id: str,
    *,
    wait: float | Unset = 0.0,
) -> dict[str, Any]:

    params: dict[str, Any] = {}

    params["wait"] = wait

    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}

    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/api/v1/jobs/{job_id}".format(
            job_id=quote(str(job_id), safe=""),
        ),
        "params": params,
    }

    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorResponse | GetJobResponseGetJob | HTTPValidationError | None:
    if response.status_code == 200:
        response_200 = GetJobResponseGetJob.from_dict(response.json())

        return response_200

    if response.status_code == 404:
        response_404 = ErrorResponse.from_dict(response.json())

        return response_404

    if response.status_code == 422:
        response_422 = HTTPValidationError.from_dict(response.json())

        return response_422

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[ErrorResponse | GetJobResponseGetJob | HTTPValidationError]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
    wait: float | Unset = 0.0,
) -> Response[ErrorResponse | GetJobResponseGetJob | HTTPValidationError]:
    """A study's state, progress and, when done, result

     With `wait`, the answer waits up to that many seconds for an unfinished job to end, and comes as
    soon as it has: a client learns of the end at once, without polling.

    Args:
        job_id (str):
        wait (float | Unset): seconds to wait for an unfinished job to end, 0…30 Default: 0.0.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | GetJobResponseGetJob | HTTPValidationError]
    """

    kwargs = _get_kwargs(
        job_id=job_id,
        wait=wait,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
    wait: float | Unset = 0.0,
) -> ErrorResponse | GetJobResponseGetJob | HTTPValidationError | None:
    """A study's state, progress and, when done, result

     With `wait`, the answer waits up to that many seconds for an unfinished job to end, and comes as
    soon as it has: a client learns of the end at once, without polling.

    Args:
        job_id (str):
        wait (float | Unset): seconds to wait for an unfinished job to end, 0…30 Default: 0.0.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | GetJobResponseGetJob | HTTPValidationError
    """

    return sync_detailed(
        job_id=job_id,
        client=client,
        wait=wait,
    ).parsed


async def asyncio_detailed(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
    wait: float | Unset = 0.0,
) -> Response[ErrorResponse | GetJobResponseGetJob | HTTPValidationError]:
    """A study's state, progress and, when done, result

     With `wait`, the answer waits up to that many seconds for an unfinished job to end, and comes as
    soon as it has: a client learns of the end at once, without polling.

    Args:
        job_id (str):
        wait (float | Unset): seconds to wait for an unfinished job to end, 0…30 Default: 0.0.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorResponse | GetJobResponseGetJob | HTTPValidationError]
    """

    kwargs = _get_kwargs(
        job_id=job_id,
        wait=wait,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
    wait: float | Unset = 0.0,
) -> ErrorResponse | GetJobResponseGetJob | HTTPValidationError | None:
    """A study's state, progress and, when done, result

     With `wait`, the answer waits up to that many seconds for an unfinished job to end, and comes as
    soon as it has: a client learns of the end at once, without polling.

    Args:
        job_id (str):
        wait (float | Unset): seconds to wait for an unfinished job to end, 0…30 Default: 0.0.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorResponse | GetJobResponseGetJob | HTTPValidationError
    """

    return (
        await asyncio_detailed(
            job_id=job_id,
            client=client,
            wait=wait,
        )
    ).parsed
