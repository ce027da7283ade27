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
# pint's parsed unit definitions are cached beside the package's bytecode
# (service.units.PINT_CACHE), written here by the install's owner: the runtime user cannot
# write there and would parse them afresh at every start (0.13 s more CPU, measured).
RUN /opt/venv/bin/python -m pip install --quiet --no-index --no-deps ./app/*.whl \
    && rm -rf /app \
    && /opt/venv/bin/python -c "import service.units; service.units.registry()" \
    && useradd --create-home --uid 10001 app
# the manual, built by scripts/image from the same checkout as the wheel, at /manual/
COPY wheelhouse/manual /opt/manual
# The numba-compiled kernels (the striker's cycle, the blow), compiled here once into a
# cache the runtime user owns: numba keys its cache on each source file's path and mtime,
# and these are the installed files the service runs, unchanged from this layer on. The
# second run checks that a fresh process loads every kernel from the cache (none compiled).
# A host whose CPU differs from the build machine's misses the cache: the service then
# compiles once at start (several seconds), writes the cache, and /readyz waits for it.
ENV MANUAL_DIR=/opt/manual \
    NUMBA_CACHE_DIR=/opt/numba-cache
RUN mkdir -p /opt/numba-cache && chown app /opt/numba-cache
USER app
RUN python -c "import engine, service.main as m; m.warm_up(engine.MODELS)" \
    && python -c "import engine, service.main as m; m.warm_up(engine.MODELS); \
k = m.kernel_cache(); bad = sorted(n for n, s in k.items() if s['compiled']); \
assert k and not bad, f'kernels compiled, not loaded from the cache: {bad or k}'"
WORKDIR /home/app

EXPOSE 8000
# Ready, not merely alive: healthy once /readyz says the warm-up has loaded the compiled
# kernels ("warming" until then: the first request then pays no compile or load). A
# "busy" answer (a lane full for the moment) still counts as healthy: the process is fine,
# and an orchestrator must not replace it for being under load.
HEALTHCHECK --interval=5s --timeout=3s --start-period=60s --retries=3 \
    CMD ["python", "-c", "import json, sys, urllib.request as u; o = u.OpenerDirector(); o.add_handler(u.HTTPHandler()); sys.exit(json.load(o.open('http://127.0.0.1:8000/readyz', timeout=2)).get('status') not in ('ready', 'busy'))"]
# SIGTERM: uvicorn stops accepting, open requests get SHUTDOWN_TIMEOUT_S (3 s), running
# computations are cancelled; `docker stop` waits 10 s by default.
STOPSIGNAL SIGTERM
CMD ["python", "-m", "service", "--host", "0.0.0.0", "--port", "8000"]
