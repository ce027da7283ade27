from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="JointClampCapabilityResults")


@_attrs_define
class JointClampCapabilityResults:
    """
    Attributes:
        mean_torque (float | None | Unset): Mean of the tool's torque law [N*m]
        torque_sd (float | None | Unset): Standard deviation of the tool's torque law [N*m]
        preload_mean (float | None | Unset): Mean assembly preload F_M [N]
        preload_sd (float | None | Unset): Standard deviation of F_M [N]
        preload_q1e_6 (float | None | Unset): F_M exceeded by a share 0.999999 of the bolts [N]
        preload_q00135 (float | None | Unset): F_M exceeded by a share 0.99865 of the bolts [N]
        preload_median (float | None | Unset): F_M exceeded by a share 0.5 of the bolts [N]
        preload_q99865 (float | None | Unset): F_M exceeded by a share 0.00135 of the bolts [N]
        preload_q1_1e_6 (float | None | Unset): F_M exceeded by a share 1e-06 of the bolts [N]
        utilisation_median (float | None | Unset): Bolt utilisation ν = σ_red,M/R_p0.2 at the quantile 0.5
            [dimensionless]
        utilisation_q99865 (float | None | Unset): Bolt utilisation ν = σ_red,M/R_p0.2 at the quantile 0.99865
            [dimensionless]
        utilisation_q1_1e_6 (float | None | Unset): Bolt utilisation ν = σ_red,M/R_p0.2 at the quantile 0.999999
            [dimensionless]
        required_preload_min (float | None | Unset): F_M,min the joint requires (VDI 2230-1 R5: F_K,erf, the working
            load's share, embedding and thermal losses) [N]
        permissible_preload (float | None | Unset): F_M,zul at the median thread friction (each bolt is judged at its
            own μ_G) [N]
        low_ppm (float | None | Unset): Bolts below F_M,min, in ppm [dimensionless]
        low_ppm_error (float | None | Unset): Estimated relative error of low_ppm: the change from half the panels, a
            typical estimate (exceeded in 7 of 124 random designs against a 16× finer rule; the rung's 10 % held in all)
            [dimensionless]
        high_ppm (float | None | Unset): Bolts above F_M,zul (utilisation above ν), in ppm [dimensionless]
        high_ppm_error (float | None | Unset): Estimated relative error of high_ppm: the change from half the panels, a
            typical estimate (exceeded in 7 of 124 random designs against a 16× finer rule; the rung's 10 % held in all)
            [dimensionless]
        clamp_force_cpk (float | None | Unset): Cpk of the preload between F_M,min and F_M,zul: min(U − mean, mean −
            L)/(3 sd) [dimensionless]
        tightening_factor (float | None | Unset): α_A this process has: F_M at 0.99865 over F_M at 0.00135 (±3σ
            equivalents) [dimensionless]
        friction_copula (float | None | Unset): The Gaussian copula's ρ for the rank correlation given [dimensionless]
        tool_critical_index (float | None | Unset): Cmk of the tool's torque law at relative_tolerance (null for a
            perfect tool) [dimensionless]
        quadrature_panels (int | None | Unset): Gauss-Legendre panels per score axis used [dimensionless]
        category_minimum_met (bool | None | Unset): The tool reaches the category's minimum Cmk as [CSP2862] states it
            (null: none) [dimensionless]
    """

    mean_torque: float | None | Unset = UNSET
    torque_sd: float | None | Unset = UNSET
    preload_mean: float | None | Unset = UNSET
    preload_sd: float | None | Unset = UNSET
    preload_q1e_6: float | None | Unset = UNSET
    preload_q00135: float | None | Unset = UNSET
    preload_median: float | None | Unset = UNSET
    preload_q99865: float | None | Unset = UNSET
    preload_q1_1e_6: float | None | Unset = UNSET
    utilisation_median: float | None | Unset = UNSET
    utilisation_q99865: float | None | Unset = UNSET
    utilisation_q1_1e_6: float | None | Unset = UNSET
    required_preload_min: float | None | Unset = UNSET
    permissible_preload: float | None | Unset = UNSET
    low_ppm: float | None | Unset = UNSET
    low_ppm_error: float | None | Unset = UNSET
    high_ppm: float | None | Unset = UNSET
    high_ppm_error: float | None | Unset = UNSET
    clamp_force_cpk: float | None | Unset = UNSET
    tightening_factor: float | None | Unset = UNSET
    friction_copula: float | None | Unset = UNSET
    tool_critical_index: float | None | Unset = UNSET
    quadrature_panels: int | None | Unset = UNSET
    category_minimum_met: bool | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        mean_torque: float | None | Unset
        if isinstance(self.mean_torque, Unset):
            mean_torque = UNSET
        else:
            mean_torque = self.mean_torque

        torque_sd: float | None | Unset
        if isinstance(self.torque_sd, Unset):
            torque_sd = UNSET
        else:
            torque_sd = self.torque_sd

        preload_mean: float | None | Unset
        if isinstance(self.preload_mean, Unset):
            preload_mean = UNSET
        else:
            preload_mean = self.preload_mean

        preload_sd: float | None | Unset
        if isinstance(self.preload_sd, Unset):
            preload_sd = UNSET
        else:
            preload_sd = self.preload_sd

        preload_q1e_6: float | None | Unset
        if isinstance(self.preload_q1e_6, Unset):
            preload_q1e_6 = UNSET
        else:
            preload_q1e_6 = self.preload_q1e_6

        preload_q00135: float | None | Unset
        if isinstance(self.preload_q00135, Unset):
            preload_q00135 = UNSET
        else:
            preload_q00135 = self.preload_q00135

        preload_median: float | None | Unset
        if isinstance(self.preload_median, Unset):
            preload_median = UNSET
        else:
            preload_median = self.preload_median

        preload_q99865: float | None | Unset
        if isinstance(self.preload_q99865, Unset):
            preload_q99865 = UNSET
        else:
            preload_q99865 = self.preload_q99865

        preload_q1_1e_6: float | None | Unset
        if isinstance(self.preload_q1_1e_6, Unset):
            preload_q1_1e_6 = UNSET
        else:
            preload_q1_1e_6 = self.preload_q1_1e_6

        utilisation_median: float | None | Unset
        if isinstance(self.utilisation_median, Unset):
            utilisation_median = UNSET
        else:
            utilisation_median = self.utilisation_median

        utilisation_q99865: float | None | Unset
        if isinstance(self.utilisation_q99865, Unset):
            utilisation_q99865 = UNSET
        else:
            utilisation_q99865 = self.utilisation_q99865

        utilisation_q1_1e_6: float | None | Unset
        if isinstance(self.utilisation_q1_1e_6, Unset):
            utilisation_q1_1e_6 = UNSET
        else:
            utilisation_q1_1e_6 = self.utilisation_q1_1e_6

        required_preload_min: float | None | Unset
        if isinstance(self.required_preload_min, Unset):
            required_preload_min = UNSET
        else:
            required_preload_min = self.required_preload_min

        permissible_preload: float | None | Unset
        if isinstance(self.permissible_preload, Unset):
            permissible_preload = UNSET
        else:
            permissible_preload = self.permissible_preload

        low_ppm: float | None | Unset
        if isinstance(self.low_ppm, Unset):
            low_ppm = UNSET
        else:
            low_ppm = self.low_ppm

        low_ppm_error: float | None | Unset
        if isinstance(self.low_ppm_error, Unset):
            low_ppm_error = UNSET
        else:
            low_ppm_error = self.low_ppm_error

        high_ppm: float | None | Unset
        if isinstance(self.high_ppm, Unset):
            high_ppm = UNSET
        else:
            high_ppm = self.high_ppm

        high_ppm_error: float | None | Unset
        if isinstance(self.high_ppm_error, Unset):
            high_ppm_error = UNSET
        else:
            high_ppm_error = self.high_ppm_error

        clamp_force_cpk: float | None | Unset
        if isinstance(self.clamp_force_cpk, Unset):
            clamp_force_cpk = UNSET
        else:
            clamp_force_cpk = self.clamp_force_cpk

        tightening_factor: float | None | Unset
        if isinstance(self.tightening_factor, Unset):
            tightening_factor = UNSET
        else:
            tightening_factor = self.tightening_factor

        friction_copula: float | None | Unset
        if isinstance(self.friction_copula, Unset):
            friction_copula = UNSET
        else:
            friction_copula = self.friction_copula

        tool_critical_index: float | None | Unset
        if isinstance(self.tool_critical_index, Unset):
            tool_critical_index = UNSET
        else:
            tool_critical_index = self.tool_critical_index

        quadrature_panels: int | None | Unset
        if isinstance(self.quadrature_panels, Unset):
            quadrature_panels = UNSET
        else:
            quadrature_panels = self.quadrature_panels

        category_minimum_met: bool | None | Unset
        if isinstance(self.category_minimum_met, Unset):
            category_minimum_met = UNSET
        else:
            category_minimum_met = self.category_minimum_met

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if mean_torque is not UNSET:
            field_dict["mean_torque"] = mean_torque
        if torque_sd is not UNSET:
            field_dict["torque_sd"] = torque_sd
        if preload_mean is not UNSET:
            field_dict["preload_mean"] = preload_mean
        if preload_sd is not UNSET:
            field_dict["preload_sd"] = preload_sd
        if preload_q1e_6 is not UNSET:
            field_dict["preload_q1e-6"] = preload_q1e_6
        if preload_q00135 is not UNSET:
            field_dict["preload_q00135"] = preload_q00135
        if preload_median is not UNSET:
            field_dict["preload_median"] = preload_median
        if preload_q99865 is not UNSET:
            field_dict["preload_q99865"] = preload_q99865
        if preload_q1_1e_6 is not UNSET:
            field_dict["preload_q1-1e-6"] = preload_q1_1e_6
        if utilisation_median is not UNSET:
            field_dict["utilisation_median"] = utilisation_median
        if utilisation_q99865 is not UNSET:
            field_dict["utilisation_q99865"] = utilisation_q99865
        if utilisation_q1_1e_6 is not UNSET:
            field_dict["utilisation_q1-1e-6"] = utilisation_q1_1e_6
        if required_preload_min is not UNSET:
            field_dict["required_preload_min"] = required_preload_min
        if permissible_preload is not UNSET:
            field_dict["permissible_preload"] = permissible_preload
        if low_ppm is not UNSET:
            field_dict["low_ppm"] = low_ppm
        if low_ppm_error is not UNSET:
            field_dict["low_ppm_error"] = low_ppm_error
        if high_ppm is not UNSET:
            field_dict["high_ppm"] = high_ppm
        if high_ppm_error is not UNSET:
            field_dict["high_ppm_error"] = high_ppm_error
        if clamp_force_cpk is not UNSET:
            field_dict["clamp_force_cpk"] = clamp_force_cpk
        if tightening_factor is not UNSET:
            field_dict["tightening_factor"] = tightening_factor
        if friction_copula is not UNSET:
            field_dict["friction_copula"] = friction_copula
        if tool_critical_index is not UNSET:
            field_dict["tool_critical_index"] = tool_critical_index
        if quadrature_panels is not UNSET:
            field_dict["quadrature_panels"] = quadrature_panels
        if category_minimum_met is not UNSET:
            field_dict["category_minimum_met"] = category_minimum_met

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_mean_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mean_torque = _parse_mean_torque(d.pop("mean_torque", UNSET))

        def _parse_torque_sd(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_sd = _parse_torque_sd(d.pop("torque_sd", UNSET))

        def _parse_preload_mean(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_mean = _parse_preload_mean(d.pop("preload_mean", UNSET))

        def _parse_preload_sd(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_sd = _parse_preload_sd(d.pop("preload_sd", UNSET))

        def _parse_preload_q1e_6(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_q1e_6 = _parse_preload_q1e_6(d.pop("preload_q1e-6", UNSET))

        def _parse_preload_q00135(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_q00135 = _parse_preload_q00135(d.pop("preload_q00135", UNSET))

        def _parse_preload_median(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_median = _parse_preload_median(d.pop("preload_median", UNSET))

        def _parse_preload_q99865(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_q99865 = _parse_preload_q99865(d.pop("preload_q99865", UNSET))

        def _parse_preload_q1_1e_6(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_q1_1e_6 = _parse_preload_q1_1e_6(d.pop("preload_q1-1e-6", UNSET))

        def _parse_utilisation_median(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        utilisation_median = _parse_utilisation_median(d.pop("utilisation_median", UNSET))

        def _parse_utilisation_q99865(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        utilisation_q99865 = _parse_utilisation_q99865(d.pop("utilisation_q99865", UNSET))

        def _parse_utilisation_q1_1e_6(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        utilisation_q1_1e_6 = _parse_utilisation_q1_1e_6(d.pop("utilisation_q1-1e-6", UNSET))

        def _parse_required_preload_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_preload_min = _parse_required_preload_min(d.pop("required_preload_min", UNSET))

        def _parse_permissible_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        permissible_preload = _parse_permissible_preload(d.pop("permissible_preload", UNSET))

        def _parse_low_ppm(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        low_ppm = _parse_low_ppm(d.pop("low_ppm", UNSET))

        def _parse_low_ppm_error(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        low_ppm_error = _parse_low_ppm_error(d.pop("low_ppm_error", UNSET))

        def _parse_high_ppm(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        high_ppm = _parse_high_ppm(d.pop("high_ppm", UNSET))

        def _parse_high_ppm_error(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        high_ppm_error = _parse_high_ppm_error(d.pop("high_ppm_error", UNSET))

        def _parse_clamp_force_cpk(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        clamp_force_cpk = _parse_clamp_force_cpk(d.pop("clamp_force_cpk", UNSET))

        def _parse_tightening_factor(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tightening_factor = _parse_tightening_factor(d.pop("tightening_factor", UNSET))

        def _parse_friction_copula(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        friction_copula = _parse_friction_copula(d.pop("friction_copula", UNSET))

        def _parse_tool_critical_index(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tool_critical_index = _parse_tool_critical_index(d.pop("tool_critical_index", UNSET))

        def _parse_quadrature_panels(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        quadrature_panels = _parse_quadrature_panels(d.pop("quadrature_panels", UNSET))

        def _parse_category_minimum_met(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        category_minimum_met = _parse_category_minimum_met(d.pop("category_minimum_met", UNSET))

        joint_clamp_capability_results = cls(
            mean_torque=mean_torque,
            torque_sd=torque_sd,
            preload_mean=preload_mean,
            preload_sd=preload_sd,
            preload_q1e_6=preload_q1e_6,
            preload_q00135=preload_q00135,
            preload_median=preload_median,
            preload_q99865=preload_q99865,
            preload_q1_1e_6=preload_q1_1e_6,
            utilisation_median=utilisation_median,
            utilisation_q99865=utilisation_q99865,
            utilisation_q1_1e_6=utilisation_q1_1e_6,
            required_preload_min=required_preload_min,
            permissible_preload=permissible_preload,
            low_ppm=low_ppm,
            low_ppm_error=low_ppm_error,
            high_ppm=high_ppm,
            high_ppm_error=high_ppm_error,
            clamp_force_cpk=clamp_force_cpk,
            tightening_factor=tightening_factor,
            friction_copula=friction_copula,
            tool_critical_index=tool_critical_index,
            quadrature_panels=quadrature_panels,
            category_minimum_met=category_minimum_met,
        )

        joint_clamp_capability_results.additional_properties = d
        return joint_clamp_capability_results

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
