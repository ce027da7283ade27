from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="ClutchBallResults")


@_attrs_define
class ClutchBallResults:
    """
    Attributes:
        spring_force (float | None | Unset): spring force at the setting Δ: G d0⁴ Δ / (8 D³ i_p) [001, eq. 2], or the
            disc stack's (DIN EN 16983) [N]
        torque_limit (float | None | Unset): slipping torque: common D0 F/(2 tan(α−ρ)); per_ball K_r i D0 F/(2 tan(α−ρ))
            [001, eq. 3] [N*m]
        ball_tangential_force (float | None | Unset): F_t = 2T/(K_r D0 i) on the most-loaded ball, at the limit or at
            `torque` [001, eq. 1] [N]
        ball_axial_force (float | None | Unset): F_a = F_t tan(α − atan f) [001, eq. 1 with friction]; with α′ the push
            of flank_construction (max or sum of the two flanks') [N]
        ball_normal_force (float | None | Unset): F_N = F_t/(cos α + f sin α), normal to the flank [001, eq. 1 with
            friction] [N]
        spring_index (float | None | Unset): C = D/d0 [dimensionless]
        wahl_factor (float | None | Unset): K_w = (4C−1)/(4C−4) + 0.615/C [dimensionless]
        spring_shear_stress (float | None | Unset): τ = 8 F D k/(π d0³) at the spring force, k Wahl's K_w or
            Bergsträsser's (w + 0.5)/(w − 0.75) as stress_correction chooses (EN 13906-1) [Pa]
        spring_rate (float | None | Unset): c = G d0⁴/(8 D³ i_p) [001, eq. 2] [N/m]
        peak_torque (float | None | Unset): largest torque over the lift from seated to riding on the face: the clutch
            disengages above it (= torque_limit at zero lift) [N*m]
        lift_at_peak (float | None | Unset): lift at the peak torque [m]
        torque_at_rim (float | None | Unset): torque when the balls reach the rim (end of the flank); below peak_torque
            when the spring force falls (disc springs past their maximum) [N*m]
        residual_torque (float | None | Unset): torque while the balls ride on the face, n μ_f F D0/2; null without
            face_friction [N*m]
        total_lift (float | None | Unset): lift from seated to riding on the face, h + (d/2)(1 − sin α) [m]
        spring_force_at_peak (float | None | Unset): spring force at the peak torque [N]
        spring_stress_at_peak (float | None | Unset): spring stress at the peak torque: corrected wire shear τ_k
            (helical) or |σ_OM| (disc) [Pa]
        spring_force_max (float | None | Unset): largest spring force over the lift [N]
        spring_stress_max (float | None | Unset): largest spring stress over the lift (every slip cycles the spring to
            it) [Pa]
        permissible_stress (float | None | Unset): permissible spring stress: allowable_shear_stress, 0.5 R_m(d) of the
            wire material (EN 13906-1), or the disc's yield strength for σ_OM [Pa]
        tensile_strength (float | None | Unset): R_m(d) of the helical wire material [Pa]
        self_locking_margin (float | None | Unset): α − atan f (the smaller over the two flanks); the limit explodes as
            it → 0 [rad]
        friction_sensitivity (float | None | Unset): dT/df, change of the torque limit per unit flank friction [N*m]
        solid_length (float | None | Unset): L_c of the helical spring (EN 13906-1) [m]
        buckling_deflection (float | None | Unset): s_K, deflection at which the free helical spring buckles (EN
            13906-1); null: it cannot buckle [m]
        natural_frequency (float | None | Unset): first surge frequency of the helical spring (EN 13906-1) [Hz]
        disc_force_flat (float | None | Unset): force of the disc stack pressed flat (DIN EN 16983 closed form) [N]
        flank_lift (float | None | Unset): h, lift at which the balls reach the rim (ball_lift, or Δ as in the paper)
            [m]
    """

    spring_force: float | None | Unset = UNSET
    torque_limit: float | None | Unset = UNSET
    ball_tangential_force: float | None | Unset = UNSET
    ball_axial_force: float | None | Unset = UNSET
    ball_normal_force: float | None | Unset = UNSET
    spring_index: float | None | Unset = UNSET
    wahl_factor: float | None | Unset = UNSET
    spring_shear_stress: float | None | Unset = UNSET
    spring_rate: float | None | Unset = UNSET
    peak_torque: float | None | Unset = UNSET
    lift_at_peak: float | None | Unset = UNSET
    torque_at_rim: float | None | Unset = UNSET
    residual_torque: float | None | Unset = UNSET
    total_lift: float | None | Unset = UNSET
    spring_force_at_peak: float | None | Unset = UNSET
    spring_stress_at_peak: float | None | Unset = UNSET
    spring_force_max: float | None | Unset = UNSET
    spring_stress_max: float | None | Unset = UNSET
    permissible_stress: float | None | Unset = UNSET
    tensile_strength: float | None | Unset = UNSET
    self_locking_margin: float | None | Unset = UNSET
    friction_sensitivity: float | None | Unset = UNSET
    solid_length: float | None | Unset = UNSET
    buckling_deflection: float | None | Unset = UNSET
    natural_frequency: float | None | Unset = UNSET
    disc_force_flat: float | None | Unset = UNSET
    flank_lift: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        spring_force: float | None | Unset
        if isinstance(self.spring_force, Unset):
            spring_force = UNSET
        else:
            spring_force = self.spring_force

        torque_limit: float | None | Unset
        if isinstance(self.torque_limit, Unset):
            torque_limit = UNSET
        else:
            torque_limit = self.torque_limit

        ball_tangential_force: float | None | Unset
        if isinstance(self.ball_tangential_force, Unset):
            ball_tangential_force = UNSET
        else:
            ball_tangential_force = self.ball_tangential_force

        ball_axial_force: float | None | Unset
        if isinstance(self.ball_axial_force, Unset):
            ball_axial_force = UNSET
        else:
            ball_axial_force = self.ball_axial_force

        ball_normal_force: float | None | Unset
        if isinstance(self.ball_normal_force, Unset):
            ball_normal_force = UNSET
        else:
            ball_normal_force = self.ball_normal_force

        spring_index: float | None | Unset
        if isinstance(self.spring_index, Unset):
            spring_index = UNSET
        else:
            spring_index = self.spring_index

        wahl_factor: float | None | Unset
        if isinstance(self.wahl_factor, Unset):
            wahl_factor = UNSET
        else:
            wahl_factor = self.wahl_factor

        spring_shear_stress: float | None | Unset
        if isinstance(self.spring_shear_stress, Unset):
            spring_shear_stress = UNSET
        else:
            spring_shear_stress = self.spring_shear_stress

        spring_rate: float | None | Unset
        if isinstance(self.spring_rate, Unset):
            spring_rate = UNSET
        else:
            spring_rate = self.spring_rate

        peak_torque: float | None | Unset
        if isinstance(self.peak_torque, Unset):
            peak_torque = UNSET
        else:
            peak_torque = self.peak_torque

        lift_at_peak: float | None | Unset
        if isinstance(self.lift_at_peak, Unset):
            lift_at_peak = UNSET
        else:
            lift_at_peak = self.lift_at_peak

        torque_at_rim: float | None | Unset
        if isinstance(self.torque_at_rim, Unset):
            torque_at_rim = UNSET
        else:
            torque_at_rim = self.torque_at_rim

        residual_torque: float | None | Unset
        if isinstance(self.residual_torque, Unset):
            residual_torque = UNSET
        else:
            residual_torque = self.residual_torque

        total_lift: float | None | Unset
        if isinstance(self.total_lift, Unset):
            total_lift = UNSET
        else:
            total_lift = self.total_lift

        spring_force_at_peak: float | None | Unset
        if isinstance(self.spring_force_at_peak, Unset):
            spring_force_at_peak = UNSET
        else:
            spring_force_at_peak = self.spring_force_at_peak

        spring_stress_at_peak: float | None | Unset
        if isinstance(self.spring_stress_at_peak, Unset):
            spring_stress_at_peak = UNSET
        else:
            spring_stress_at_peak = self.spring_stress_at_peak

        spring_force_max: float | None | Unset
        if isinstance(self.spring_force_max, Unset):
            spring_force_max = UNSET
        else:
            spring_force_max = self.spring_force_max

        spring_stress_max: float | None | Unset
        if isinstance(self.spring_stress_max, Unset):
            spring_stress_max = UNSET
        else:
            spring_stress_max = self.spring_stress_max

        permissible_stress: float | None | Unset
        if isinstance(self.permissible_stress, Unset):
            permissible_stress = UNSET
        else:
            permissible_stress = self.permissible_stress

        tensile_strength: float | None | Unset
        if isinstance(self.tensile_strength, Unset):
            tensile_strength = UNSET
        else:
            tensile_strength = self.tensile_strength

        self_locking_margin: float | None | Unset
        if isinstance(self.self_locking_margin, Unset):
            self_locking_margin = UNSET
        else:
            self_locking_margin = self.self_locking_margin

        friction_sensitivity: float | None | Unset
        if isinstance(self.friction_sensitivity, Unset):
            friction_sensitivity = UNSET
        else:
            friction_sensitivity = self.friction_sensitivity

        solid_length: float | None | Unset
        if isinstance(self.solid_length, Unset):
            solid_length = UNSET
        else:
            solid_length = self.solid_length

        buckling_deflection: float | None | Unset
        if isinstance(self.buckling_deflection, Unset):
            buckling_deflection = UNSET
        else:
            buckling_deflection = self.buckling_deflection

        natural_frequency: float | None | Unset
        if isinstance(self.natural_frequency, Unset):
            natural_frequency = UNSET
        else:
            natural_frequency = self.natural_frequency

        disc_force_flat: float | None | Unset
        if isinstance(self.disc_force_flat, Unset):
            disc_force_flat = UNSET
        else:
            disc_force_flat = self.disc_force_flat

        flank_lift: float | None | Unset
        if isinstance(self.flank_lift, Unset):
            flank_lift = UNSET
        else:
            flank_lift = self.flank_lift

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if spring_force is not UNSET:
            field_dict["spring_force"] = spring_force
        if torque_limit is not UNSET:
            field_dict["torque_limit"] = torque_limit
        if ball_tangential_force is not UNSET:
            field_dict["ball_tangential_force"] = ball_tangential_force
        if ball_axial_force is not UNSET:
            field_dict["ball_axial_force"] = ball_axial_force
        if ball_normal_force is not UNSET:
            field_dict["ball_normal_force"] = ball_normal_force
        if spring_index is not UNSET:
            field_dict["spring_index"] = spring_index
        if wahl_factor is not UNSET:
            field_dict["wahl_factor"] = wahl_factor
        if spring_shear_stress is not UNSET:
            field_dict["spring_shear_stress"] = spring_shear_stress
        if spring_rate is not UNSET:
            field_dict["spring_rate"] = spring_rate
        if peak_torque is not UNSET:
            field_dict["peak_torque"] = peak_torque
        if lift_at_peak is not UNSET:
            field_dict["lift_at_peak"] = lift_at_peak
        if torque_at_rim is not UNSET:
            field_dict["torque_at_rim"] = torque_at_rim
        if residual_torque is not UNSET:
            field_dict["residual_torque"] = residual_torque
        if total_lift is not UNSET:
            field_dict["total_lift"] = total_lift
        if spring_force_at_peak is not UNSET:
            field_dict["spring_force_at_peak"] = spring_force_at_peak
        if spring_stress_at_peak is not UNSET:
            field_dict["spring_stress_at_peak"] = spring_stress_at_peak
        if spring_force_max is not UNSET:
            field_dict["spring_force_max"] = spring_force_max
        if spring_stress_max is not UNSET:
            field_dict["spring_stress_max"] = spring_stress_max
        if permissible_stress is not UNSET:
            field_dict["permissible_stress"] = permissible_stress
        if tensile_strength is not UNSET:
            field_dict["tensile_strength"] = tensile_strength
        if self_locking_margin is not UNSET:
            field_dict["self_locking_margin"] = self_locking_margin
        if friction_sensitivity is not UNSET:
            field_dict["friction_sensitivity"] = friction_sensitivity
        if solid_length is not UNSET:
            field_dict["solid_length"] = solid_length
        if buckling_deflection is not UNSET:
            field_dict["buckling_deflection"] = buckling_deflection
        if natural_frequency is not UNSET:
            field_dict["natural_frequency"] = natural_frequency
        if disc_force_flat is not UNSET:
            field_dict["disc_force_flat"] = disc_force_flat
        if flank_lift is not UNSET:
            field_dict["flank_lift"] = flank_lift

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_spring_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spring_force = _parse_spring_force(d.pop("spring_force", UNSET))

        def _parse_torque_limit(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_limit = _parse_torque_limit(d.pop("torque_limit", UNSET))

        def _parse_ball_tangential_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        ball_tangential_force = _parse_ball_tangential_force(d.pop("ball_tangential_force", UNSET))

        def _parse_ball_axial_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        ball_axial_force = _parse_ball_axial_force(d.pop("ball_axial_force", UNSET))

        def _parse_ball_normal_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        ball_normal_force = _parse_ball_normal_force(d.pop("ball_normal_force", UNSET))

        def _parse_spring_index(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spring_index = _parse_spring_index(d.pop("spring_index", UNSET))

        def _parse_wahl_factor(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        wahl_factor = _parse_wahl_factor(d.pop("wahl_factor", UNSET))

        def _parse_spring_shear_stress(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spring_shear_stress = _parse_spring_shear_stress(d.pop("spring_shear_stress", UNSET))

        def _parse_spring_rate(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spring_rate = _parse_spring_rate(d.pop("spring_rate", UNSET))

        def _parse_peak_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        peak_torque = _parse_peak_torque(d.pop("peak_torque", UNSET))

        def _parse_lift_at_peak(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        lift_at_peak = _parse_lift_at_peak(d.pop("lift_at_peak", UNSET))

        def _parse_torque_at_rim(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        torque_at_rim = _parse_torque_at_rim(d.pop("torque_at_rim", UNSET))

        def _parse_residual_torque(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        residual_torque = _parse_residual_torque(d.pop("residual_torque", UNSET))

        def _parse_total_lift(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        total_lift = _parse_total_lift(d.pop("total_lift", UNSET))

        def _parse_spring_force_at_peak(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spring_force_at_peak = _parse_spring_force_at_peak(d.pop("spring_force_at_peak", UNSET))

        def _parse_spring_stress_at_peak(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spring_stress_at_peak = _parse_spring_stress_at_peak(d.pop("spring_stress_at_peak", UNSET))

        def _parse_spring_force_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spring_force_max = _parse_spring_force_max(d.pop("spring_force_max", UNSET))

        def _parse_spring_stress_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spring_stress_max = _parse_spring_stress_max(d.pop("spring_stress_max", UNSET))

        def _parse_permissible_stress(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        permissible_stress = _parse_permissible_stress(d.pop("permissible_stress", UNSET))

        def _parse_tensile_strength(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tensile_strength = _parse_tensile_strength(d.pop("tensile_strength", UNSET))

        def _parse_self_locking_margin(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        self_locking_margin = _parse_self_locking_margin(d.pop("self_locking_margin", UNSET))

        def _parse_friction_sensitivity(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        friction_sensitivity = _parse_friction_sensitivity(d.pop("friction_sensitivity", UNSET))

        def _parse_solid_length(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        solid_length = _parse_solid_length(d.pop("solid_length", UNSET))

        def _parse_buckling_deflection(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        buckling_deflection = _parse_buckling_deflection(d.pop("buckling_deflection", UNSET))

        def _parse_natural_frequency(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        natural_frequency = _parse_natural_frequency(d.pop("natural_frequency", UNSET))

        def _parse_disc_force_flat(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        disc_force_flat = _parse_disc_force_flat(d.pop("disc_force_flat", UNSET))

        def _parse_flank_lift(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        flank_lift = _parse_flank_lift(d.pop("flank_lift", UNSET))

        clutch_ball_results = cls(
            spring_force=spring_force,
            torque_limit=torque_limit,
            ball_tangential_force=ball_tangential_force,
            ball_axial_force=ball_axial_force,
            ball_normal_force=ball_normal_force,
            spring_index=spring_index,
            wahl_factor=wahl_factor,
            spring_shear_stress=spring_shear_stress,
            spring_rate=spring_rate,
            peak_torque=peak_torque,
            lift_at_peak=lift_at_peak,
            torque_at_rim=torque_at_rim,
            residual_torque=residual_torque,
            total_lift=total_lift,
            spring_force_at_peak=spring_force_at_peak,
            spring_stress_at_peak=spring_stress_at_peak,
            spring_force_max=spring_force_max,
            spring_stress_max=spring_stress_max,
            permissible_stress=permissible_stress,
            tensile_strength=tensile_strength,
            self_locking_margin=self_locking_margin,
            friction_sensitivity=friction_sensitivity,
            solid_length=solid_length,
            buckling_deflection=buckling_deflection,
            natural_frequency=natural_frequency,
            disc_force_flat=disc_force_flat,
            flank_lift=flank_lift,
        )

        clutch_ball_results.additional_properties = d
        return clutch_ball_results

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
