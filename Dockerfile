# Slim runtime image: pinned dependencies, no dev tools, non-root, health-checked.
#
# Build with scripts/image, which first fills wheelhouse/ with the wheels of
# requirements.lock and of the project (pip on the host, so the host's index and
# certificates apply); the image then installs offline from it (--no-index).
#
# BASE_IMAGE must provide python3.11 with venv. Default: the official slim image. CI, where no
# image registry is reachable, builds a base from Debian packages (.ci/base-image:
# debootstrap bookworm + python3.11 + python3-venv, `docker import`) and passes it:
#   BASE_IMAGE=calc-base:bookworm-py311 scripts/image calc:ci
ARG BASE_IMAGE=python:3.11-slim-bookworm
FROM ${BASE_IMAGE}

ENV PYTHONDONTWRITEBYTECODE=1 \
    PYTHONUNBUFFERED=1 \
    PIP_NO_CACHE_DIR=1 \
    PIP_DISABLE_PIP_VERSION_CHECK=1 \
    PATH=/opt/venv/bin:$PATH

WORKDIR /app
# dependencies first, pinned by the lock file: this layer is reused while only the code changes
COPY requirements.lock ./
COPY wheelhouse/deps ./wheels
RUN python3 -m venv /opt/venv \
    && /opt/venv/bin/python -m pip install --quiet --no-index --find-links ./wheels \
        -r requirements.lock
COPY wheelhouse/app ./app
RUN /opt/venv/bin/python -m pip install --quiet --no-index --no-deps ./app/*.whl \
    && rm -rf /app \
    && useradd --create-home --uid 10001 app
# the manual, built by scripts/image from the same checkout as the wheel, at /manual/
COPY wheelhouse/manual /opt/manual
ENV MANUAL_DIR=/opt/manual
USER app
WORKDIR /home/app

EXPOSE 8000
# liveness only: /readyz says whether the engine can take work right now
HEALTHCHECK --interval=5s --timeout=3s --start-period=20s --retries=3 \
    CMD ["python", "-c", "import sys, urllib.request; sys.exit(urllib.request.urlopen('http://127.0.0.1:8000/healthz', timeout=2).status != 200)"]
# SIGTERM: uvicorn stops accepting, open requests get SHUTDOWN_TIMEOUT_S (3 s), running
# computations are cancelled; `docker stop` waits 10 s by default.
STOPSIGNAL SIGTERM
CMD ["python", "-m", "service", "--host", "0.0.0.0", "--port", "8000"]
