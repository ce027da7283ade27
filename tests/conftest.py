"""Fixtures shared by every test group.

Layout: ``tests/engine`` (runner, spec, sources, layout), ``tests/service``
(HTTP contract, limits, hostile input, fuzzing), ``tests/models/<family>``
(one family's functions and model), ``tests/validation`` (published numbers),
``tests/stability`` (extremes and rungs over every model), ``tests/e2e``
(browser, static files, container). Test-only models: :mod:`tests.toys`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest
from hypothesis import settings

from tests.apps import real_client

if TYPE_CHECKING:
    from fastapi.testclient import TestClient

# Hypothesis budgets. `make test` (CI) runs every property test at the budget its file sets;
# `make test-fast` passes --hypothesis-profile=fast, which caps every property test at a few
# examples, the explicit @settings(max_examples=…) in the files included (below).
settings.register_profile("fast", max_examples=8)


#: Property sweeps over whole declared ranges, hostile-value fuzzing, timing under load and
#: the memory of a full-size row group (15 MB of CSV traced by tracemalloc; its sibling
#: test_pieces_have_a_bounded_number_of_rows_and_every_row holds the pieces and every value):
#: `slow` (the full suite, `make test`, runs them; the inner loop does not). Value tests and
#: doctests are never listed here.
SLOW_ITEMS = (
    "tests/service/test_no_500.py::test_every_declared_range_extreme_evaluates_or_is_refused",
    "tests/stability/test_grids.py::test_api_sweeps_over_whole_ranges",
    "tests/stability/test_grids.py::test_api_at_the_extremes",
    "tests/service/test_hostile.py::test_every_numeric_input_of_every_model_survives_hostile",
    "tests/service/test_lanes.py::",
    "tests/service/test_isolation.py::",
    "tests/service/test_shopfloor_csv.py::test_a_row_group_is_not_held_as_text",
)


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Mark :data:`SLOW_ITEMS` slow (before ``-m`` selects), and under the ``fast`` hypothesis
    profile size every property test's budget to the profile.

    A test's own ``@settings(max_examples=…)`` outranks any profile, so the cap is applied
    here, once, to the settings each ``@given`` test reads when it runs.
    """
    for item in items:
        if item.nodeid.startswith(SLOW_ITEMS):
            item.add_marker(pytest.mark.slow)
    if config.getoption("hypothesis_profile", None) != "fast":
        return
    cap = settings.get_profile("fast").max_examples
    for item in items:
        fn = getattr(item, "obj", None)
        own = getattr(fn, "_hypothesis_internal_use_settings", None)
        if own is not None and own.max_examples > cap:
            fn._hypothesis_internal_use_settings = settings(own, max_examples=cap)  # type: ignore[union-attr]


@pytest.fixture(scope="session")
def client() -> TestClient:
    """The real app with every registered model."""
    return real_client()


@pytest.fixture(scope="session")
def api() -> TestClient:
    """The real app, answering a model's crash with a 500 instead of raising it."""
    return real_client(raise_server_exceptions=False)


@pytest.fixture(scope="module")
def toy() -> TestClient:
    """The app over the ``toy.disc`` model alone (modules may override it)."""
    from fastapi.testclient import TestClient

    from service import create_app
    from tests.toys import TOY

    return TestClient(create_app(models=[TOY]), raise_server_exceptions=False)


@pytest.fixture(scope="session", autouse=True)
def _compiled_kernels() -> None:
    """Load (or, on a fresh checkout, compile: several seconds) the numba kernels once,
    before any test times a run; the service does the same at start-up (warm_up)."""
    import numpy as np

    from engine.procedures.striker_cycle import _ensure_compiled

    _ensure_compiled(np.ones(32))
