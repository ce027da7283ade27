"""A design, a sweep and a study through the generated Python client (clients/python).

    pip install ./clients/python          # or: PYTHONPATH=clients/python
    python examples/client_example.py http://127.0.0.1:8000

Prints the three answers' key figures as one JSON line (tests/service/test_python_client.py
runs it against a service it starts and checks them).
"""

from __future__ import annotations

import json
import sys
import time
from typing import Any

from tightening_calc_client import Client
from tightening_calc_client.api.preload import preload_tightening, preload_tightening_sweep
from tightening_calc_client.api.studies import get_job, preload_tightening_study
from tightening_calc_client.models import (
    ErrorResponse,
    PreloadTighteningRequest,
    PreloadTighteningRequestPropertyClassType0,
    PreloadTighteningStudyRequest,
    PreloadTighteningSweepRequest,
)

BOLT = {"thread_diameter": "12 mm", "property_class": "8.8"}


def main(url: str) -> dict[str, Any]:
    with Client(base_url=url, raise_on_unexpected_status=True) as client:
        # one design: typed request, typed answer
        design = preload_tightening.sync(
            client=client,
            body=PreloadTighteningRequest(
                thread_diameter="12 mm",
                property_class=PreloadTighteningRequestPropertyClassType0("8.8"),
                thread_friction=0.12,
            ),
        )
        assert design is not None and not isinstance(design, ErrorResponse), design
        torque = design.results.tightening_torque

        # a sweep of the thread friction (a request built from plain JSON works too)
        sweep = preload_tightening_sweep.sync(
            client=client,
            body=PreloadTighteningSweepRequest.from_dict(
                {
                    "base": BOLT,
                    "vary": "thread_friction",
                    "start": 0.08,
                    "stop": 0.16,
                    "num": 5,
                    "outputs": ["tightening_torque"],
                }
            ),
        )
        assert sweep is not None and not isinstance(sweep, ErrorResponse), sweep
        torques = sweep.results["tightening_torque"]

        # a study: 202 and the job's address, then poll it until it is done
        study = PreloadTighteningStudyRequest.from_dict(
            {
                "base": BOLT,
                "variables": [{"name": "thread_friction", "low": 0.08, "high": 0.16}],
                "samples": 1000,
                "seed": 1,
                "outputs": ["tightening_torque"],
            }
        )
        accepted = preload_tightening_study.sync_detailed(client=client, body=study)
        job_id = accepted.headers["location"].rsplit("/", 1)[-1]
        while True:
            job = get_job.sync(job_id, client=client)
            assert job is not None and not isinstance(job, ErrorResponse), job
            state = job.to_dict()
            if state["state"] not in ("queued", "running"):
                break
            time.sleep(0.2)
        result = state["result"]["outputs"]["tightening_torque"]
    return {
        "design_torque": torque,
        "sweep_friction": sweep.values,
        "sweep_torque": torques,
        "study_state": state["state"],
        "study_mean_torque": result["mean"],
    }


if __name__ == "__main__":
    print(json.dumps(main(sys.argv[1] if len(sys.argv) > 1 else "http://127.0.0.1:8000")))
