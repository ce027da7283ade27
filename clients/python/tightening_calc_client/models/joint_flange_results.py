from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="JointFlangeResults")


@_attrs_define
class JointFlangeResults:
    """
    Attributes:
        bolt_working_load (float | None | Unset): F_A of the most loaded bolt: F_ax/z + 4 M_B/(z D_t) [N]
        bolt_working_load_min (float | None | Unset): Its lower load: F_ax,min/z + 4 M_B,min/(z D_t) [N]
        bolt_transverse_load (float | None | Unset): F_Q per bolt: F_Q/z + 2 M_T/(z D_t) [N]
        required_clamp_force (float | None | Unset): R2: F_K,erf = max(F_KQ, F_KP + F_KA) [N]
        load_factor (float | None | Unset): R3: Φ_n = n Φ_K; eccentric: Φ*_en = n δ**_P/(δ_S + δ*_P), δ**_P = δ_P + a
            s_sym β_P [dimensionless]
        permissible_preload (float | None | Unset): R7: F_M,zul = ν R_p0.2 A_0/β at the smallest section, μ_G,min [N]
        assembly_preload_min (float | None | Unset): R1/R13: lowest assembly preload (F_M,zul/α_A or torque box) [N]
        assembly_preload_max (float | None | Unset): R1/R13: highest assembly preload (F_M,zul or torque box) [N]
        tightening_torque (float | None | Unset): R13: M_A for F_M,zul at μ_G,min, μ_K,min plus M_ü (VDI 2230-1 R13: the
            α_A band lies below F_M,zul), or the torque given; not the torque for a nominal preload at mean friction
            (preload.control target_torque) [N*m]
        residual_clamp_force_min (float | None | Unset): R12: F_KR,min = F_M,min − (1 − Φ_n) F_A − F_Z − ΔF_th, 0 where
            the joint opens [N]
        separation_load (float | None | Unset): R5/R12: F_A at which the joint opens from the lowest assembly preload;
            eccentric: the opening limit F_Aab = F_V/(1 − Φ*_en + F_KA/F_A) [N]
        max_working_load (float | None | Unset): R5–R7: largest F_A whose required window fits under F_M,zul [N]
        max_bolt_force (float | None | Unset): R8: F_S,max = F_M,max + Φ_n F_A,max [N]
        working_stress (float | None | Unset): R8: σ_red,B (k_τ = 0.5) [Pa]
        yield_safety (float | None | Unset): R8: S_F = R_p0.2/σ_red,B [dimensionless]
        stress_amplitude (float | None | Unset): R9: σ_a = Φ_n (F_A,max − F_A,min)/(2 A_S); eccentric: σ_ab = (σ_SAbo −
            σ_SAbu)/2 [Pa]
        fatigue_safety (float | None | Unset): R9: S_D = σ_AS/σ_a (null for static load) [dimensionless]
        slip_safety (float | None | Unset): R12: S_G = F_KR,min q_F μ_T/(F_Q + M_Y q_F/(q_M r_a)) (null without F_Q and
            M_Y; 0 where it opens) [dimensionless]
    """

    bolt_working_load: float | None | Unset = UNSET
    bolt_working_load_min: float | None | Unset = UNSET
    bolt_transverse_load: float | None | Unset = UNSET
    required_clamp_force: float | None | Unset = UNSET
    load_factor: float | None | Unset = UNSET
    permissible_preload: float | None | Unset = UNSET
    assembly_preload_min: float | None | Unset = UNSET
    assembly_preload_max: float | None | Unset = UNSET
    tightening_torque: float | None | Unset = UNSET
    residual_clamp_force_min: float | None | Unset = UNSET
    separation_load: float | None | Unset = UNSET
    max_working_load: float | None | Unset = UNSET
    max_bolt_force: float | None | Unset = UNSET
    working_stress: float | None | Unset = UNSET
    yield_safety: float | None | Unset = UNSET
    stress_amplitude: float | None | Unset = UNSET
    fatigue_safety: float | None | Unset = UNSET
    slip_safety: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        bolt_working_load: float | None | Unset
        if isinstance(self.bolt_working_load, Unset):
            bolt_working_load = UNSET
        else:
            bolt_working_load = self.bolt_working_load

        bolt_working_load_min: float | None | Unset
        if isinstance(self.bolt_working_load_min, Unset):
            bolt_working_load_min = UNSET
        else:
            bolt_working_load_min = self.bolt_working_load_min

        bolt_transverse_load: float | None | Unset
        if isinstance(self.bolt_transverse_load, Unset):
            bolt_transverse_load = UNSET
        else:
            bolt_transverse_load = self.bolt_transverse_load

        required_clamp_force: float | None | Unset
        if isinstance(self.required_clamp_force, Unset):
            required_clamp_force = UNSET
        else:
            required_clamp_force = self.required_clamp_force

        load_factor: float | None | Unset
        if isinstance(self.load_factor, Unset):
            load_factor = UNSET
        else:
            load_factor = self.load_factor

        permissible_preload: float | None | Unset
        if isinstance(self.permissible_preload, Unset):
            permissible_preload = UNSET
        else:
            permissible_preload = self.permissible_preload

        assembly_preload_min: float | None | Unset
        if isinstance(self.assembly_preload_min, Unset):
            assembly_preload_min = UNSET
        else:
            assembly_preload_min = self.assembly_preload_min

        assembly_preload_max: float | None | Unset
        if isinstance(self.assembly_preload_max, Unset):
            assembly_preload_max = UNSET
        else:
            assembly_preload_max = self.assembly_preload_max

        tightening_torque: float | None | Unset
        if isinstance(self.tightening_torque, Unset):
            tightening_torque = UNSET
        else:
            tightening_torque = self.tightening_torque

        residual_clamp_force_min: float | None | Unset
        if isinstance(self.residual_clamp_force_min, Unset):
            residual_clamp_force_min = UNSET
        else:
            residual_clamp_force_min = self.residual_clamp_force_min

        separation_load: float | None | Unset
        if isinstance(self.separation_load, Unset):
            separation_load = UNSET
        else:
            separation_load = self.separation_load

        max_working_load: float | None | Unset
        if isinstance(self.max_working_load, Unset):
            max_working_load = UNSET
        else:
            max_working_load = self.max_working_load

        max_bolt_force: float | None | Unset
        if isinstance(self.max_bolt_force, Unset):
            max_bolt_force = UNSET
        else:
            max_bolt_force = self.max_bolt_force

        working_stress: float | None | Unset
        if isinstance(self.working_stress, Unset):
            working_stress = UNSET
        else:
            working_stress = self.working_stress

        yield_safety: float | None | Unset
        if isinstance(self.yield_safety, Unset):
            yield_safety = UNSET
        else:
            yield_safety = self.yield_safety

        stress_amplitude: float | None | Unset
        if isinstance(self.stress_amplitude, Unset):
            stress_amplitude = UNSET
        else:
            stress_amplitude = self.stress_amplitude

        fatigue_safety: float | None | Unset
        if isinstance(self.fatigue_safety, Unset):
            fatigue_safety = UNSET
        else:
            fatigue_safety = self.fatigue_safety

        slip_safety: float | None | Unset
        if isinstance(self.slip_safety, Unset):
            slip_safety = UNSET
        else:
            slip_safety = self.slip_safety

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if bolt_working_load is not UNSET:
            field_dict["bolt_working_load"] = bolt_working_load
        if bolt_working_load_min is not UNSET:
            field_dict["bolt_working_load_min"] = bolt_working_load_min
        if bolt_transverse_load is not UNSET:
            field_dict["bolt_transverse_load"] = bolt_transverse_load
        if required_clamp_force is not UNSET:
            field_dict["required_clamp_force"] = required_clamp_force
        if load_factor is not UNSET:
            field_dict["load_factor"] = load_factor
        if permissible_preload is not UNSET:
            field_dict["permissible_preload"] = permissible_preload
        if assembly_preload_min is not UNSET:
            field_dict["assembly_preload_min"] = assembly_preload_min
        if assembly_preload_max is not UNSET:
            field_dict["assembly_preload_max"] = assembly_preload_max
        if tightening_torque is not UNSET:
            field_dict["tightening_torque"] = tightening_torque
        if residual_clamp_force_min is not UNSET:
            field_dict["residual_clamp_force_min"] = residual_clamp_force_min
        if separation_load is not UNSET:
            field_dict["separation_load"] = separation_load
        if max_working_load is not UNSET:
            field_dict["max_working_load"] = max_working_load
        if max_bolt_force is not UNSET:
            field_dict["max_bolt_force"] = max_bolt_force
        if working_stress is not UNSET:
            field_dict["working_stress"] = working_stress
        if yield_safety is not UNSET:
            field_dict["yield_safety"] = yield_safety
        if stress_amplitude is not UNSET:
            field_dict["stress_amplitude"] = stress_amplitude
        if fatigue_safety is not UNSET:
            field_dict["fatigue_safety"] = fatigue_safety
        if slip_safety is not UNSET:
            field_dict["slip_safety"] = slip_safety

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_bolt_working_load(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_working_load = _parse_bolt_working_load(d.pop("bolt_working_load", UNSET))

        def _parse_bolt_working_load_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_working_load_min = _parse_bolt_working_load_min(d.pop("bolt_working_load_min", UNSET))

        def _parse_bolt_transverse_load(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_transverse_load = _parse_bolt_transverse_load(d.pop("bolt_transverse_load", UNSET))

        def _parse_required_clamp_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_clamp_force = _parse_required_clamp_force(d.pop("required_clamp_force", UNSET))

        def _parse_load_factor(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        load_factor = _parse_load_factor(d.pop("load_factor", UNSET))

        def _parse_permissible_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        permissible_preload = _parse_permissible_preload(d.pop("permissible_preload", UNSET))

        def _parse_assembly_preload_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        assembly_preload_min = _parse_assembly_preload_min(d.pop("assembly_preload_min", UNSET))

        def _parse_assembly_preload_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        assembly_preload_max = _parse_assembly_preload_max(d.pop("assembly_preload_max", UNSET))

        def _parse_tightening_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tightening_torque = _parse_tightening_torque(d.pop("tightening_torque", UNSET))

        def _parse_residual_clamp_force_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        residual_clamp_force_min = _parse_residual_clamp_force_min(d.pop("residual_clamp_force_min", UNSET))

        def _parse_separation_load(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        separation_load = _parse_separation_load(d.pop("separation_load", UNSET))

        def _parse_max_working_load(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        max_working_load = _parse_max_working_load(d.pop("max_working_load", UNSET))

        def _parse_max_bolt_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        max_bolt_force = _parse_max_bolt_force(d.pop("max_bolt_force", UNSET))

        def _parse_working_stress(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        working_stress = _parse_working_stress(d.pop("working_stress", UNSET))

        def _parse_yield_safety(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        yield_safety = _parse_yield_safety(d.pop("yield_safety", UNSET))

        def _parse_stress_amplitude(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        stress_amplitude = _parse_stress_amplitude(d.pop("stress_amplitude", UNSET))

        def _parse_fatigue_safety(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        fatigue_safety = _parse_fatigue_safety(d.pop("fatigue_safety", UNSET))

        def _parse_slip_safety(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        slip_safety = _parse_slip_safety(d.pop("slip_safety", UNSET))

        joint_flange_results = cls(
            bolt_working_load=bolt_working_load,
            bolt_working_load_min=bolt_working_load_min,
            bolt_transverse_load=bolt_transverse_load,
            required_clamp_force=required_clamp_force,
            load_factor=load_factor,
            permissible_preload=permissible_preload,
            assembly_preload_min=assembly_preload_min,
            assembly_preload_max=assembly_preload_max,
            tightening_torque=tightening_torque,
            residual_clamp_force_min=residual_clamp_force_min,
            separation_load=separation_load,
            max_working_load=max_working_load,
            max_bolt_force=max_bolt_force,
            working_stress=working_stress,
            yield_safety=yield_safety,
            stress_amplitude=stress_amplitude,
            fatigue_safety=fatigue_safety,
            slip_safety=slip_safety,
        )

        joint_flange_results.additional_properties = d
        return joint_flange_results

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
