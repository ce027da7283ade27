"""A study counts refused designs by reason: the figures of each design are not part of the row."""

from __future__ import annotations

import engine
from engine.core.errors import BudgetExceeded, InputOutOfRange
from engine.studies.execute import run_study
from engine.studies.plan import Study, Variable, refusal_key


def test_stiff_strikers_refused_by_the_step_budget_share_one_row() -> None:
    """Springs 10⁴ times the reference's, parts 100 times lighter: each design would take
    its own number of RK4 steps (2e8 to 1e9), each is refused up front, all in one row
    (each had a row of its own)."""
    spec = engine.get_model("impact.rare")
    ex = dict(spec.examples[0])
    varied = ("power_spring_rate", "roller_mass")
    study = Study(
        variables=(
            Variable("power_spring_rate", "uniform", low=1e8, high=1e9),
            Variable(
                "roller_mass", "uniform", low=ex["roller_mass"] / 100, high=ex["roller_mass"] / 50
            ),
        ),
        base={k: v for k, v in ex.items() if k not in varied},
        samples=40,
        seed=1,
        fidelity="simulation",
    )
    # no chunk budget: each design has the step budget of a request without a deadline (10⁶
    # steps), not the steps the chunk's time leaves at this process's measured cost a step
    # (some designs would then run for a minute)
    refusals = run_study(spec, study, chunk_budget_s=None).merged.refusals
    (key,) = refusals
    assert refusals[key] == 40, refusals
    assert key == "BudgetExceeded: the cycle simulation would take about … RK4 steps (budget …)"


def test_a_reason_keeps_its_names_and_standards() -> None:
    key = refusal_key(
        InputOutOfRange("thread M12 of class 10.9 (ISO 898-1, VDI 2230 R7) at 1.5e3 N: 4 more")
    )
    assert key == "InputOutOfRange: thread M12 of class … (ISO 898-1, VDI 2230 R7) at … N"
    assert refusal_key(BudgetExceeded("no colon, 12 steps")) == "BudgetExceeded: no colon, … steps"


def test_a_reason_is_cut_after_its_numbers_are_written() -> None:
    """Cut at 120 characters before the numbers were written, one reason made a row per
    length of its figures ("… report this design", "… report this d")."""
    from engine.core.errors import SolverFailed

    def key(t: str) -> str:
        return refusal_key(
            SolverFailed(
                f"the half-coupling did not reach h1 by t = {t} s although the quasi-static "
                f"release is at {t} s; report this design"
            )
        )

    assert key("0.1") == key("1.234567e-05")
    assert key("0.1").endswith("; report this design")
