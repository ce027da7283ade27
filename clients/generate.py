"""Generate the Python client in ``clients/python`` from the service's OpenAPI document.

The document is the app's own (``create_app().openapi()``, every registered model), written
to a temporary file; openapi-python-client (the version pinned in the dev extras, see
:data:`GENERATOR`) turns it into a typed httpx client, offline, and formats it with the
project's ruff. ``tests/service/test_python_client.py`` regenerates it into a temporary
folder and compares: a change to the API that is not regenerated fails there.

    python -m clients.generate            # rewrite clients/python (`make client`)
    python -m clients.generate OUT_DIR    # elsewhere
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: The generator's version, as pinned in pyproject.toml's dev extras.
GENERATOR = "0.29.1"
OUTPUT = ROOT / "clients" / "python"


def openapi_document() -> dict[str, object]:
    """The service's OpenAPI document, as ``GET /openapi.json`` serves it."""
    os.environ.setdefault("WARM_UP", "0")
    from service import create_app

    return create_app().openapi()


def generate(output: Path = OUTPUT) -> Path:
    """Write the client into ``output`` (replaced); answer its folder."""
    from importlib.metadata import version

    found = version("openapi-python-client")
    if found != GENERATOR:
        raise RuntimeError(
            f"openapi-python-client {GENERATOR} generates clients/python, not {found}: "
            "install the dev extras from requirements-dev.lock"
        )
    with tempfile.TemporaryDirectory() as tmp:
        document = Path(tmp) / "openapi.json"
        document.write_text(json.dumps(openapi_document(), indent=1))
        run = subprocess.run(
            [
                sys.executable,
                "-m",
                "openapi_python_client",
                "generate",
                "--path",
                str(document),
                "--config",
                str(ROOT / "clients" / "config.yaml"),
                "--output-path",
                str(output),
                "--overwrite",
                "--fail-on-warning",
            ],
            cwd=tmp,
            # the post-hooks run `ruff`: the one beside this interpreter
            env={
                **os.environ,
                "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}",
            },
            capture_output=True,
            text=True,
        )
        if run.returncode != 0:
            raise RuntimeError(f"openapi-python-client failed:\n{run.stdout}\n{run.stderr}")
    shutil.rmtree(output / ".ruff_cache", ignore_errors=True)  # the post-hooks' cache
    return output


if __name__ == "__main__":
    print(generate(Path(sys.argv[1]) if len(sys.argv) > 1 else OUTPUT))
