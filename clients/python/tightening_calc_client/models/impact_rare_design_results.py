from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="ImpactRareDesignResults")


@_attrs_define
class ImpactRareDesignResults:
    """
    Attributes:
        new_power_spring_rate (float | None | Unset): c1 of the design found (c_1) [N/m]
        new_power_spring_preload (float | None | Unset): λ1 of the design found (λ_1) [m]
        new_return_spring_rate (float | None | Unset): c3 of the design found (c_3) [N/m]
        new_return_spring_preload (float | None | Unset): λ3 of the design found (λ_3) [m]
        new_auxiliary_spring_rate (float | None | Unset): c2 of the design found (c_2) [N/m]
        new_auxiliary_spring_preload (float | None | Unset): λ2 of the design found (λ_2) [m]
        new_striker_mass (float | None | Unset): m3 of the design found (m_3) [kg]
        change_power_spring_rate (float | None | Unset): relative change of c1: (new − old)/old [dimensionless]
        change_power_spring_preload (float | None | Unset): relative change of λ1: (new − old)/old [dimensionless]
        change_return_spring_rate (float | None | Unset): relative change of c3: (new − old)/old [dimensionless]
        change_return_spring_preload (float | None | Unset): relative change of λ3: (new − old)/old [dimensionless]
        change_auxiliary_spring_rate (float | None | Unset): relative change of c2: (new − old)/old [dimensionless]
        change_auxiliary_spring_preload (float | None | Unset): relative change of λ2: (new − old)/old [dimensionless]
        change_striker_mass (float | None | Unset): relative change of m3: (new − old)/old [dimensionless]
        design_change (float | None | Unset): Δ = √Σ((x − x0)/x0)², the weighted relative change [dimensionless]
        engagement_margin (float | None | Unset): impact.rare's engagement margin of the design found: ≥ 0, no edge blow
            [dimensionless]
        relock_margin (float | None | Unset): impact.rare's static re-lock margin of the design found [N]
        cycle_time (float | None | Unset): impact.rare's cycle time of the design found [s]
        found (bool | None | Unset): a design in the ranges passes every check [dimensionless]
        binding_checks (None | str | Unset): where none passes: the checks the nearest try fails (empty when one passes)
            [dimensionless]
        designs_evaluated (int | None | Unset): designs judged by impact.rare's closed form [dimensionless]
        designs_passing (int | None | Unset): random designs of the search that pass [dimensionless]
    """

    new_power_spring_rate: float | None | Unset = UNSET
    new_power_spring_preload: float | None | Unset = UNSET
    new_return_spring_rate: float | None | Unset = UNSET
    new_return_spring_preload: float | None | Unset = UNSET
    new_auxiliary_spring_rate: float | None | Unset = UNSET
    new_auxiliary_spring_preload: float | None | Unset = UNSET
    new_striker_mass: float | None | Unset = UNSET
    change_power_spring_rate: float | None | Unset = UNSET
    change_power_spring_preload: float | None | Unset = UNSET
    change_return_spring_rate: float | None | Unset = UNSET
    change_return_spring_preload: float | None | Unset = UNSET
    change_auxiliary_spring_rate: float | None | Unset = UNSET
    change_auxiliary_spring_preload: float | None | Unset = UNSET
    change_striker_mass: float | None | Unset = UNSET
    design_change: float | None | Unset = UNSET
    engagement_margin: float | None | Unset = UNSET
    relock_margin: float | None | Unset = UNSET
    cycle_time: float | None | Unset = UNSET
    found: bool | None | Unset = UNSET
    binding_checks: None | str | Unset = UNSET
    designs_evaluated: int | None | Unset = UNSET
    designs_passing: int | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        new_power_spring_rate: float | None | Unset
        if isinstance(self.new_power_spring_rate, Unset):
            new_power_spring_rate = UNSET
        else:
            new_power_spring_rate = self.new_power_spring_rate

        new_power_spring_preload: float | None | Unset
        if isinstance(self.new_power_spring_preload, Unset):
            new_power_spring_preload = UNSET
        else:
            new_power_spring_preload = self.new_power_spring_preload

        new_return_spring_rate: float | None | Unset
        if isinstance(self.new_return_spring_rate, Unset):
            new_return_spring_rate = UNSET
        else:
            new_return_spring_rate = self.new_return_spring_rate

        new_return_spring_preload: float | None | Unset
        if isinstance(self.new_return_spring_preload, Unset):
            new_return_spring_preload = UNSET
        else:
            new_return_spring_preload = self.new_return_spring_preload

        new_auxiliary_spring_rate: float | None | Unset
        if isinstance(self.new_auxiliary_spring_rate, Unset):
            new_auxiliary_spring_rate = UNSET
        else:
            new_auxiliary_spring_rate = self.new_auxiliary_spring_rate

        new_auxiliary_spring_preload: float | None | Unset
        if isinstance(self.new_auxiliary_spring_preload, Unset):
            new_auxiliary_spring_preload = UNSET
        else:
            new_auxiliary_spring_preload = self.new_auxiliary_spring_preload

        new_striker_mass: float | None | Unset
        if isinstance(self.new_striker_mass, Unset):
            new_striker_mass = UNSET
        else:
            new_striker_mass = self.new_striker_mass

        change_power_spring_rate: float | None | Unset
        if isinstance(self.change_power_spring_rate, Unset):
            change_power_spring_rate = UNSET
        else:
            change_power_spring_rate = self.change_power_spring_rate

        change_power_spring_preload: float | None | Unset
        if isinstance(self.change_power_spring_preload, Unset):
            change_power_spring_preload = UNSET
        else:
            change_power_spring_preload = self.change_power_spring_preload

        change_return_spring_rate: float | None | Unset
        if isinstance(self.change_return_spring_rate, Unset):
            change_return_spring_rate = UNSET
        else:
            change_return_spring_rate = self.change_return_spring_rate

        change_return_spring_preload: float | None | Unset
        if isinstance(self.change_return_spring_preload, Unset):
            change_return_spring_preload = UNSET
        else:
            change_return_spring_preload = self.change_return_spring_preload

        change_auxiliary_spring_rate: float | None | Unset
        if isinstance(self.change_auxiliary_spring_rate, Unset):
            change_auxiliary_spring_rate = UNSET
        else:
            change_auxiliary_spring_rate = self.change_auxiliary_spring_rate

        change_auxiliary_spring_preload: float | None | Unset
        if isinstance(self.change_auxiliary_spring_preload, Unset):
            change_auxiliary_spring_preload = UNSET
        else:
            change_auxiliary_spring_preload = self.change_auxiliary_spring_preload

        change_striker_mass: float | None | Unset
        if isinstance(self.change_striker_mass, Unset):
            change_striker_mass = UNSET
        else:
            change_striker_mass = self.change_striker_mass

        design_change: float | None | Unset
        if isinstance(self.design_change, Unset):
            design_change = UNSET
        else:
            design_change = self.design_change

        engagement_margin: float | None | Unset
        if isinstance(self.engagement_margin, Unset):
            engagement_margin = UNSET
        else:
            engagement_margin = self.engagement_margin

        relock_margin: float | None | Unset
        if isinstance(self.relock_margin, Unset):
            relock_margin = UNSET
        else:
            relock_margin = self.relock_margin

        cycle_time: float | None | Unset
        if isinstance(self.cycle_time, Unset):
            cycle_time = UNSET
        else:
            cycle_time = self.cycle_time

        found: bool | None | Unset
        if isinstance(self.found, Unset):
            found = UNSET
        else:
            found = self.found

        binding_checks: None | str | Unset
        if isinstance(self.binding_checks, Unset):
            binding_checks = UNSET
        else:
            binding_checks = self.binding_checks

        designs_evaluated: int | None | Unset
        if isinstance(self.designs_evaluated, Unset):
            designs_evaluated = UNSET
        else:
            designs_evaluated = self.designs_evaluated

        designs_passing: int | None | Unset
        if isinstance(self.designs_passing, Unset):
            designs_passing = UNSET
        else:
            designs_passing = self.designs_passing

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if new_power_spring_rate is not UNSET:
            field_dict["new_power_spring_rate"] = new_power_spring_rate
        if new_power_spring_preload is not UNSET:
            field_dict["new_power_spring_preload"] = new_power_spring_preload
        if new_return_spring_rate is not UNSET:
            field_dict["new_return_spring_rate"] = new_return_spring_rate
        if new_return_spring_preload is not UNSET:
            field_dict["new_return_spring_preload"] = new_return_spring_preload
        if new_auxiliary_spring_rate is not UNSET:
            field_dict["new_auxiliary_spring_rate"] = new_auxiliary_spring_rate
        if new_auxiliary_spring_preload is not UNSET:
            field_dict["new_auxiliary_spring_preload"] = new_auxiliary_spring_preload
        if new_striker_mass is not UNSET:
            field_dict["new_striker_mass"] = new_striker_mass
        if change_power_spring_rate is not UNSET:
            field_dict["change_power_spring_rate"] = change_power_spring_rate
        if change_power_spring_preload is not UNSET:
            field_dict["change_power_spring_preload"] = change_power_spring_preload
        if change_return_spring_rate is not UNSET:
            field_dict["change_return_spring_rate"] = change_return_spring_rate
        if change_return_spring_preload is not UNSET:
            field_dict["change_return_spring_preload"] = change_return_spring_preload
        if change_auxiliary_spring_rate is not UNSET:
            field_dict["change_auxiliary_spring_rate"] = change_auxiliary_spring_rate
        if change_auxiliary_spring_preload is not UNSET:
            field_dict["change_auxiliary_spring_preload"] = change_auxiliary_spring_preload
        if change_striker_mass is not UNSET:
            field_dict["change_striker_mass"] = change_striker_mass
        if design_change is not UNSET:
            field_dict["design_change"] = design_change
        if engagement_margin is not UNSET:
            field_dict["engagement_margin"] = engagement_margin
        if relock_margin is not UNSET:
            field_dict["relock_margin"] = relock_margin
        if cycle_time is not UNSET:
            field_dict["cycle_time"] = cycle_time
        if found is not UNSET:
            field_dict["found"] = found
        if binding_checks is not UNSET:
            field_dict["binding_checks"] = binding_checks
        if designs_evaluated is not UNSET:
            field_dict["designs_evaluated"] = designs_evaluated
        if designs_passing is not UNSET:
            field_dict["designs_passing"] = designs_passing

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_new_power_spring_rate(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        new_power_spring_rate = _parse_new_power_spring_rate(d.pop("new_power_spring_rate", UNSET))

        def _parse_new_power_spring_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        new_power_spring_preload = _parse_new_power_spring_preload(d.pop("new_power_spring_preload", UNSET))

        def _parse_new_return_spring_rate(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        new_return_spring_rate = _parse_new_return_spring_rate(d.pop("new_return_spring_rate", UNSET))

        def _parse_new_return_spring_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        new_return_spring_preload = _parse_new_return_spring_preload(d.pop("new_return_spring_preload", UNSET))

        def _parse_new_auxiliary_spring_rate(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        new_auxiliary_spring_rate = _parse_new_auxiliary_spring_rate(d.pop("new_auxiliary_spring_rate", UNSET))

        def _parse_new_auxiliary_spring_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        new_auxiliary_spring_preload = _parse_new_auxiliary_spring_preload(d.pop("new_auxiliary_spring_preload", UNSET))

        def _parse_new_striker_mass(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        new_striker_mass = _parse_new_striker_mass(d.pop("new_striker_mass", UNSET))

        def _parse_change_power_spring_rate(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        change_power_spring_rate = _parse_change_power_spring_rate(d.pop("change_power_spring_rate", UNSET))

        def _parse_change_power_spring_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        change_power_spring_preload = _parse_change_power_spring_preload(d.pop("change_power_spring_preload", UNSET))

        def _parse_change_return_spring_rate(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        change_return_spring_rate = _parse_change_return_spring_rate(d.pop("change_return_spring_rate", UNSET))

        def _parse_change_return_spring_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        change_return_spring_preload = _parse_change_return_spring_preload(d.pop("change_return_spring_preload", UNSET))

        def _parse_change_auxiliary_spring_rate(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        change_auxiliary_spring_rate = _parse_change_auxiliary_spring_rate(d.pop("change_auxiliary_spring_rate", UNSET))

        def _parse_change_auxiliary_spring_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        change_auxiliary_spring_preload = _parse_change_auxiliary_spring_preload(
            d.pop("change_auxiliary_spring_preload", UNSET)
        )

        def _parse_change_striker_mass(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        change_striker_mass = _parse_change_striker_mass(d.pop("change_striker_mass", UNSET))

        def _parse_design_change(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        design_change = _parse_design_change(d.pop("design_change", UNSET))

        def _parse_engagement_margin(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        engagement_margin = _parse_engagement_margin(d.pop("engagement_margin", UNSET))

        def _parse_relock_margin(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        relock_margin = _parse_relock_margin(d.pop("relock_margin", UNSET))

        def _parse_cycle_time(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        cycle_time = _parse_cycle_time(d.pop("cycle_time", UNSET))

        def _parse_found(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        found = _parse_found(d.pop("found", UNSET))

        def _parse_binding_checks(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        binding_checks = _parse_binding_checks(d.pop("binding_checks", UNSET))

        def _parse_designs_evaluated(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        designs_evaluated = _parse_designs_evaluated(d.pop("designs_evaluated", UNSET))

        def _parse_designs_passing(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        designs_passing = _parse_designs_passing(d.pop("designs_passing", UNSET))

        impact_rare_design_results = cls(
            new_power_spring_rate=new_power_spring_rate,
            new_power_spring_preload=new_power_spring_preload,
            new_return_spring_rate=new_return_spring_rate,
            new_return_spring_preload=new_return_spring_preload,
            new_auxiliary_spring_rate=new_auxiliary_spring_rate,
            new_auxiliary_spring_preload=new_auxiliary_spring_preload,
            new_striker_mass=new_striker_mass,
            change_power_spring_rate=change_power_spring_rate,
            change_power_spring_preload=change_power_spring_preload,
            change_return_spring_rate=change_return_spring_rate,
            change_return_spring_preload=change_return_spring_preload,
            change_auxiliary_spring_rate=change_auxiliary_spring_rate,
            change_auxiliary_spring_preload=change_auxiliary_spring_preload,
            change_striker_mass=change_striker_mass,
            design_change=design_change,
            engagement_margin=engagement_margin,
            relock_margin=relock_margin,
            cycle_time=cycle_time,
            found=found,
            binding_checks=binding_checks,
            designs_evaluated=designs_evaluated,
            designs_passing=designs_passing,
        )

        impact_rare_design_results.additional_properties = d
        return impact_rare_design_results

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> Any:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
