from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="ClutchSpringDesignResults")


@_attrs_define
class ClutchSpringDesignResults:
    """
    Attributes:
        wire_diameter (float | None | Unset): d, a preferred EN 10270-1 size [m]
        mean_diameter (float | None | Unset): D, mean coil diameter [m]
        active_coils (float | None | Unset): n, active coils (half coils) [dimensionless]
        total_coils (float | None | Unset): n_t = n + 2, closed and ground ends [dimensionless]
        free_length (float | None | Unset): L0 = L1 + s1 (a disc pack: i (h0 + n t)) [m]
        rate (float | None | Unset): R = G d⁴/(8 D³ n) [N/m]
        set_force (float | None | Unset): F1, spring force at the setting [001, eq. 1–3] [N]
        stroke (float | None | Unset): s_h = h + (d_b/2)(1 − sin α): the balls' whole lift [m]
        set_length (float | None | Unset): L1, length at the setting (the pocket; a disc pack: the stack, a shim fills
            the rest) [m]
        set_deflection (float | None | Unset): s1 = F1/R, the nut setting [m]
        stroke_force (float | None | Unset): F2 = F1 + R s_h, force at full stroke [N]
        stroke_length (float | None | Unset): L2 = L1 − s_h, length at full stroke [m]
        solid_length (float | None | Unset): L_c = n_t d (a disc pack: i n t, pressed flat) [m]
        gap_sum (float | None | Unset): S_a, minimum sum of gaps at full stroke (EN 13906-1) [m]
        permissible_stress (float | None | Unset): τ_zul = 0.5 R_m(d) [Pa]
        shear_stress_set (float | None | Unset): τ_k1 = k 8 F1 D/(π d³), Bergsträsser's k [Pa]
        shear_stress_stroke (float | None | Unset): τ_k2 at F2 [Pa]
        buckling_deflection (float | None | Unset): s_K; null: it cannot buckle [m]
        mass (float | None | Unset): m = ρ (π d²/4) π D n_t [kg]
        stress_utilisation_set (float | None | Unset): τ_k1/τ_zul [dimensionless]
        stress_utilisation_stroke (float | None | Unset): τ_k2/τ_zul [dimensionless]
        disc_designation (None | str | Unset): the standard disc of the pack (DIN 2093) [dimensionless]
        disc_outer_diameter (float | None | Unset): De of the discs [m]
        disc_inner_diameter (float | None | Unset): Di of the discs [m]
        disc_thickness (float | None | Unset): t of one disc [m]
        disc_cone_height (float | None | Unset): h0, free cone height of one disc [m]
        discs_parallel (int | None | Unset): n, discs nested in parallel in each pack [dimensionless]
        discs_series (int | None | Unset): i, packs in series (alternately facing) [dimensionless]
        disc_count (int | None | Unset): n i, discs in the stack [dimensionless]
        disc_set_deflection (float | None | Unset): s1 per disc at the setting: n F(s1) = F1 (DIN EN 16983) [m]
        disc_stroke_deflection (float | None | Unset): s2 = s1 + s_h/i per disc at full stroke, ≤ 0.75 h0 [m]
        disc_stress_om (float | None | Unset): |σ_OM| at full stroke (DIN EN 16983) [Pa]
        disc_stress_utilisation (float | None | Unset): |σ_OM|/R_e at full stroke [dimensionless]
        shim_length (float | None | Unset): the pocket's length less the stack's at the setting [m]
        margin_spring_index (float | None | Unset): margin of the spring index check: ≥ 0 passes [dimensionless]
        margin_outer_diameter (float | None | Unset): margin of the outer diameter check: ≥ 0 passes [dimensionless]
        margin_inner_diameter (float | None | Unset): margin of the inner diameter check: ≥ 0 passes [dimensionless]
        margin_stress_at_set (float | None | Unset): margin of the stress at set check: ≥ 0 passes [dimensionless]
        margin_stress_at_stroke (float | None | Unset): margin of the stress at stroke check: ≥ 0 passes [dimensionless]
        margin_coil_gaps (float | None | Unset): margin of the coil gaps check: ≥ 0 passes [dimensionless]
        margin_buckling (float | None | Unset): margin of the buckling check: ≥ 0 passes [dimensionless]
        margin_disc_preload (float | None | Unset): margin of the disc preload check: ≥ 0 passes [dimensionless]
        margin_disc_deflection (float | None | Unset): margin of the disc deflection check: ≥ 0 passes [dimensionless]
        margin_disc_stress_om (float | None | Unset): margin of the disc stress om check: ≥ 0 passes [dimensionless]
        margin_stack_length (float | None | Unset): margin of the stack length check: ≥ 0 passes [dimensionless]
        binding_limit (None | str | Unset): the check with the least margin (or the one failed) [dimensionless]
        candidates_checked (int | None | Unset): springs (d, D) evaluated [dimensionless]
        candidates_passing (int | None | Unset): springs that pass every check [dimensionless]
    """

    wire_diameter: float | None | Unset = UNSET
    mean_diameter: float | None | Unset = UNSET
    active_coils: float | None | Unset = UNSET
    total_coils: float | None | Unset = UNSET
    free_length: float | None | Unset = UNSET
    rate: float | None | Unset = UNSET
    set_force: float | None | Unset = UNSET
    stroke: float | None | Unset = UNSET
    set_length: float | None | Unset = UNSET
    set_deflection: float | None | Unset = UNSET
    stroke_force: float | None | Unset = UNSET
    stroke_length: float | None | Unset = UNSET
    solid_length: float | None | Unset = UNSET
    gap_sum: float | None | Unset = UNSET
    permissible_stress: float | None | Unset = UNSET
    shear_stress_set: float | None | Unset = UNSET
    shear_stress_stroke: float | None | Unset = UNSET
    buckling_deflection: float | None | Unset = UNSET
    mass: float | None | Unset = UNSET
    stress_utilisation_set: float | None | Unset = UNSET
    stress_utilisation_stroke: float | None | Unset = UNSET
    disc_designation: None | str | Unset = UNSET
    disc_outer_diameter: float | None | Unset = UNSET
    disc_inner_diameter: float | None | Unset = UNSET
    disc_thickness: float | None | Unset = UNSET
    disc_cone_height: float | None | Unset = UNSET
    discs_parallel: int | None | Unset = UNSET
    discs_series: int | None | Unset = UNSET
    disc_count: int | None | Unset = UNSET
    disc_set_deflection: float | None | Unset = UNSET
    disc_stroke_deflection: float | None | Unset = UNSET
    disc_stress_om: float | None | Unset = UNSET
    disc_stress_utilisation: float | None | Unset = UNSET
    shim_length: float | None | Unset = UNSET
    margin_spring_index: float | None | Unset = UNSET
    margin_outer_diameter: float | None | Unset = UNSET
    margin_inner_diameter: float | None | Unset = UNSET
    margin_stress_at_set: float | None | Unset = UNSET
    margin_stress_at_stroke: float | None | Unset = UNSET
    margin_coil_gaps: float | None | Unset = UNSET
    margin_buckling: float | None | Unset = UNSET
    margin_disc_preload: float | None | Unset = UNSET
    margin_disc_deflection: float | None | Unset = UNSET
    margin_disc_stress_om: float | None | Unset = UNSET
    margin_stack_length: float | None | Unset = UNSET
    binding_limit: None | str | Unset = UNSET
    candidates_checked: int | None | Unset = UNSET
    candidates_passing: int | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        wire_diameter: float | None | Unset
        if isinstance(self.wire_diameter, Unset):
            wire_diameter = UNSET
        else:
            wire_diameter = self.wire_diameter

        mean_diameter: float | None | Unset
        if isinstance(self.mean_diameter, Unset):
            mean_diameter = UNSET
        else:
            mean_diameter = self.mean_diameter

        active_coils: float | None | Unset
        if isinstance(self.active_coils, Unset):
            active_coils = UNSET
        else:
            active_coils = self.active_coils

        total_coils: float | None | Unset
        if isinstance(self.total_coils, Unset):
            total_coils = UNSET
        else:
            total_coils = self.total_coils

        free_length: float | None | Unset
        if isinstance(self.free_length, Unset):
            free_length = UNSET
        else:
            free_length = self.free_length

        rate: float | None | Unset
        if isinstance(self.rate, Unset):
            rate = UNSET
        else:
            rate = self.rate

        set_force: float | None | Unset
        if isinstance(self.set_force, Unset):
            set_force = UNSET
        else:
            set_force = self.set_force

        stroke: float | None | Unset
        if isinstance(self.stroke, Unset):
            stroke = UNSET
        else:
            stroke = self.stroke

        set_length: float | None | Unset
        if isinstance(self.set_length, Unset):
            set_length = UNSET
        else:
            set_length = self.set_length

        set_deflection: float | None | Unset
        if isinstance(self.set_deflection, Unset):
            set_deflection = UNSET
        else:
            set_deflection = self.set_deflection

        stroke_force: float | None | Unset
        if isinstance(self.stroke_force, Unset):
            stroke_force = UNSET
        else:
            stroke_force = self.stroke_force

        stroke_length: float | None | Unset
        if isinstance(self.stroke_length, Unset):
            stroke_length = UNSET
        else:
            stroke_length = self.stroke_length

        solid_length: float | None | Unset
        if isinstance(self.solid_length, Unset):
            solid_length = UNSET
        else:
            solid_length = self.solid_length

        gap_sum: float | None | Unset
        if isinstance(self.gap_sum, Unset):
            gap_sum = UNSET
        else:
            gap_sum = self.gap_sum

        permissible_stress: float | None | Unset
        if isinstance(self.permissible_stress, Unset):
            permissible_stress = UNSET
        else:
            permissible_stress = self.permissible_stress

        shear_stress_set: float | None | Unset
        if isinstance(self.shear_stress_set, Unset):
            shear_stress_set = UNSET
        else:
            shear_stress_set = self.shear_stress_set

        shear_stress_stroke: float | None | Unset
        if isinstance(self.shear_stress_stroke, Unset):
            shear_stress_stroke = UNSET
        else:
            shear_stress_stroke = self.shear_stress_stroke

        buckling_deflection: float | None | Unset
        if isinstance(self.buckling_deflection, Unset):
            buckling_deflection = UNSET
        else:
            buckling_deflection = self.buckling_deflection

        mass: float | None | Unset
        if isinstance(self.mass, Unset):
            mass = UNSET
        else:
            mass = self.mass

        stress_utilisation_set: float | None | Unset
        if isinstance(self.stress_utilisation_set, Unset):
            stress_utilisation_set = UNSET
        else:
            stress_utilisation_set = self.stress_utilisation_set

        stress_utilisation_stroke: float | None | Unset
        if isinstance(self.stress_utilisation_stroke, Unset):
            stress_utilisation_stroke = UNSET
        else:
            stress_utilisation_stroke = self.stress_utilisation_stroke

        disc_designation: None | str | Unset
        if isinstance(self.disc_designation, Unset):
            disc_designation = UNSET
        else:
            disc_designation = self.disc_designation

        disc_outer_diameter: float | None | Unset
        if isinstance(self.disc_outer_diameter, Unset):
            disc_outer_diameter = UNSET
        else:
            disc_outer_diameter = self.disc_outer_diameter

        disc_inner_diameter: float | None | Unset
        if isinstance(self.disc_inner_diameter, Unset):
            disc_inner_diameter = UNSET
        else:
            disc_inner_diameter = self.disc_inner_diameter

        disc_thickness: float | None | Unset
        if isinstance(self.disc_thickness, Unset):
            disc_thickness = UNSET
        else:
            disc_thickness = self.disc_thickness

        disc_cone_height: float | None | Unset
        if isinstance(self.disc_cone_height, Unset):
            disc_cone_height = UNSET
        else:
            disc_cone_height = self.disc_cone_height

        discs_parallel: int | None | Unset
        if isinstance(self.discs_parallel, Unset):
            discs_parallel = UNSET
        else:
            discs_parallel = self.discs_parallel

        discs_series: int | None | Unset
        if isinstance(self.discs_series, Unset):
            discs_series = UNSET
        else:
            discs_series = self.discs_series

        disc_count: int | None | Unset
        if isinstance(self.disc_count, Unset):
            disc_count = UNSET
        else:
            disc_count = self.disc_count

        disc_set_deflection: float | None | Unset
        if isinstance(self.disc_set_deflection, Unset):
            disc_set_deflection = UNSET
        else:
            disc_set_deflection = self.disc_set_deflection

        disc_stroke_deflection: float | None | Unset
        if isinstance(self.disc_stroke_deflection, Unset):
            disc_stroke_deflection = UNSET
        else:
            disc_stroke_deflection = self.disc_stroke_deflection

        disc_stress_om: float | None | Unset
        if isinstance(self.disc_stress_om, Unset):
            disc_stress_om = UNSET
        else:
            disc_stress_om = self.disc_stress_om

        disc_stress_utilisation: float | None | Unset
        if isinstance(self.disc_stress_utilisation, Unset):
            disc_stress_utilisation = UNSET
        else:
            disc_stress_utilisation = self.disc_stress_utilisation

        shim_length: float | None | Unset
        if isinstance(self.shim_length, Unset):
            shim_length = UNSET
        else:
            shim_length = self.shim_length

        margin_spring_index: float | None | Unset
        if isinstance(self.margin_spring_index, Unset):
            margin_spring_index = UNSET
        else:
            margin_spring_index = self.margin_spring_index

        margin_outer_diameter: float | None | Unset
        if isinstance(self.margin_outer_diameter, Unset):
            margin_outer_diameter = UNSET
        else:
            margin_outer_diameter = self.margin_outer_diameter

        margin_inner_diameter: float | None | Unset
        if isinstance(self.margin_inner_diameter, Unset):
            margin_inner_diameter = UNSET
        else:
            margin_inner_diameter = self.margin_inner_diameter

        margin_stress_at_set: float | None | Unset
        if isinstance(self.margin_stress_at_set, Unset):
            margin_stress_at_set = UNSET
        else:
            margin_stress_at_set = self.margin_stress_at_set

        margin_stress_at_stroke: float | None | Unset
        if isinstance(self.margin_stress_at_stroke, Unset):
            margin_stress_at_stroke = UNSET
        else:
            margin_stress_at_stroke = self.margin_stress_at_stroke

        margin_coil_gaps: float | None | Unset
        if isinstance(self.margin_coil_gaps, Unset):
            margin_coil_gaps = UNSET
        else:
            margin_coil_gaps = self.margin_coil_gaps

        margin_buckling: float | None | Unset
        if isinstance(self.margin_buckling, Unset):
            margin_buckling = UNSET
        else:
            margin_buckling = self.margin_buckling

        margin_disc_preload: float | None | Unset
        if isinstance(self.margin_disc_preload, Unset):
            margin_disc_preload = UNSET
        else:
            margin_disc_preload = self.margin_disc_preload

        margin_disc_deflection: float | None | Unset
        if isinstance(self.margin_disc_deflection, Unset):
            margin_disc_deflection = UNSET
        else:
            margin_disc_deflection = self.margin_disc_deflection

        margin_disc_stress_om: float | None | Unset
        if isinstance(self.margin_disc_stress_om, Unset):
            margin_disc_stress_om = UNSET
        else:
            margin_disc_stress_om = self.margin_disc_stress_om

        margin_stack_length: float | None | Unset
        if isinstance(self.margin_stack_length, Unset):
            margin_stack_length = UNSET
        else:
            margin_stack_length = self.margin_stack_length

        binding_limit: None | str | Unset
        if isinstance(self.binding_limit, Unset):
            binding_limit = UNSET
        else:
            binding_limit = self.binding_limit

        candidates_checked: int | None | Unset
        if isinstance(self.candidates_checked, Unset):
            candidates_checked = UNSET
        else:
            candidates_checked = self.candidates_checked

        candidates_passing: int | None | Unset
        if isinstance(self.candidates_passing, Unset):
            candidates_passing = UNSET
        else:
            candidates_passing = self.candidates_passing

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if wire_diameter is not UNSET:
            field_dict["wire_diameter"] = wire_diameter
        if mean_diameter is not UNSET:
            field_dict["mean_diameter"] = mean_diameter
        if active_coils is not UNSET:
            field_dict["active_coils"] = active_coils
        if total_coils is not UNSET:
            field_dict["total_coils"] = total_coils
        if free_length is not UNSET:
            field_dict["free_length"] = free_length
        if rate is not UNSET:
            field_dict["rate"] = rate
        if set_force is not UNSET:
            field_dict["set_force"] = set_force
        if stroke is not UNSET:
            field_dict["stroke"] = stroke
        if set_length is not UNSET:
            field_dict["set_length"] = set_length
        if set_deflection is not UNSET:
            field_dict["set_deflection"] = set_deflection
        if stroke_force is not UNSET:
            field_dict["stroke_force"] = stroke_force
        if stroke_length is not UNSET:
            field_dict["stroke_length"] = stroke_length
        if solid_length is not UNSET:
            field_dict["solid_length"] = solid_length
        if gap_sum is not UNSET:
            field_dict["gap_sum"] = gap_sum
        if permissible_stress is not UNSET:
            field_dict["permissible_stress"] = permissible_stress
        if shear_stress_set is not UNSET:
            field_dict["shear_stress_set"] = shear_stress_set
        if shear_stress_stroke is not UNSET:
            field_dict["shear_stress_stroke"] = shear_stress_stroke
        if buckling_deflection is not UNSET:
            field_dict["buckling_deflection"] = buckling_deflection
        if mass is not UNSET:
            field_dict["mass"] = mass
        if stress_utilisation_set is not UNSET:
            field_dict["stress_utilisation_set"] = stress_utilisation_set
        if stress_utilisation_stroke is not UNSET:
            field_dict["stress_utilisation_stroke"] = stress_utilisation_stroke
        if disc_designation is not UNSET:
            field_dict["disc_designation"] = disc_designation
        if disc_outer_diameter is not UNSET:
            field_dict["disc_outer_diameter"] = disc_outer_diameter
        if disc_inner_diameter is not UNSET:
            field_dict["disc_inner_diameter"] = disc_inner_diameter
        if disc_thickness is not UNSET:
            field_dict["disc_thickness"] = disc_thickness
        if disc_cone_height is not UNSET:
            field_dict["disc_cone_height"] = disc_cone_height
        if discs_parallel is not UNSET:
            field_dict["discs_parallel"] = discs_parallel
        if discs_series is not UNSET:
            field_dict["discs_series"] = discs_series
        if disc_count is not UNSET:
            field_dict["disc_count"] = disc_count
        if disc_set_deflection is not UNSET:
            field_dict["disc_set_deflection"] = disc_set_deflection
        if disc_stroke_deflection is not UNSET:
            field_dict["disc_stroke_deflection"] = disc_stroke_deflection
        if disc_stress_om is not UNSET:
            field_dict["disc_stress_om"] = disc_stress_om
        if disc_stress_utilisation is not UNSET:
            field_dict["disc_stress_utilisation"] = disc_stress_utilisation
        if shim_length is not UNSET:
            field_dict["shim_length"] = shim_length
        if margin_spring_index is not UNSET:
            field_dict["margin_spring_index"] = margin_spring_index
        if margin_outer_diameter is not UNSET:
            field_dict["margin_outer_diameter"] = margin_outer_diameter
        if margin_inner_diameter is not UNSET:
            field_dict["margin_inner_diameter"] = margin_inner_diameter
        if margin_stress_at_set is not UNSET:
            field_dict["margin_stress_at_set"] = margin_stress_at_set
        if margin_stress_at_stroke is not UNSET:
            field_dict["margin_stress_at_stroke"] = margin_stress_at_stroke
        if margin_coil_gaps is not UNSET:
            field_dict["margin_coil_gaps"] = margin_coil_gaps
        if margin_buckling is not UNSET:
            field_dict["margin_buckling"] = margin_buckling
        if margin_disc_preload is not UNSET:
            field_dict["margin_disc_preload"] = margin_disc_preload
        if margin_disc_deflection is not UNSET:
            field_dict["margin_disc_deflection"] = margin_disc_deflection
        if margin_disc_stress_om is not UNSET:
            field_dict["margin_disc_stress_om"] = margin_disc_stress_om
        if margin_stack_length is not UNSET:
            field_dict["margin_stack_length"] = margin_stack_length
        if binding_limit is not UNSET:
            field_dict["binding_limit"] = binding_limit
        if candidates_checked is not UNSET:
            field_dict["candidates_checked"] = candidates_checked
        if candidates_passing is not UNSET:
            field_dict["candidates_passing"] = candidates_passing

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_wire_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        wire_diameter = _parse_wire_diameter(d.pop("wire_diameter", UNSET))

        def _parse_mean_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mean_diameter = _parse_mean_diameter(d.pop("mean_diameter", UNSET))

        def _parse_active_coils(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        active_coils = _parse_active_coils(d.pop("active_coils", UNSET))

        def _parse_total_coils(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        total_coils = _parse_total_coils(d.pop("total_coils", UNSET))

        def _parse_free_length(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        free_length = _parse_free_length(d.pop("free_length", UNSET))

        def _parse_rate(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        rate = _parse_rate(d.pop("rate", UNSET))

        def _parse_set_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        set_force = _parse_set_force(d.pop("set_force", UNSET))

        def _parse_stroke(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        stroke = _parse_stroke(d.pop("stroke", UNSET))

        def _parse_set_length(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        set_length = _parse_set_length(d.pop("set_length", UNSET))

        def _parse_set_deflection(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        set_deflection = _parse_set_deflection(d.pop("set_deflection", UNSET))

        def _parse_stroke_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        stroke_force = _parse_stroke_force(d.pop("stroke_force", UNSET))

        def _parse_stroke_length(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        stroke_length = _parse_stroke_length(d.pop("stroke_length", UNSET))

        def _parse_solid_length(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        solid_length = _parse_solid_length(d.pop("solid_length", UNSET))

        def _parse_gap_sum(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        gap_sum = _parse_gap_sum(d.pop("gap_sum", UNSET))

        def _parse_permissible_stress(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        permissible_stress = _parse_permissible_stress(d.pop("permissible_stress", UNSET))

        def _parse_shear_stress_set(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        shear_stress_set = _parse_shear_stress_set(d.pop("shear_stress_set", UNSET))

        def _parse_shear_stress_stroke(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        shear_stress_stroke = _parse_shear_stress_stroke(d.pop("shear_stress_stroke", UNSET))

        def _parse_buckling_deflection(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        buckling_deflection = _parse_buckling_deflection(d.pop("buckling_deflection", UNSET))

        def _parse_mass(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        mass = _parse_mass(d.pop("mass", UNSET))

        def _parse_stress_utilisation_set(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        stress_utilisation_set = _parse_stress_utilisation_set(d.pop("stress_utilisation_set", UNSET))

        def _parse_stress_utilisation_stroke(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        stress_utilisation_stroke = _parse_stress_utilisation_stroke(d.pop("stress_utilisation_stroke", UNSET))

        def _parse_disc_designation(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        disc_designation = _parse_disc_designation(d.pop("disc_designation", UNSET))

        def _parse_disc_outer_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        disc_outer_diameter = _parse_disc_outer_diameter(d.pop("disc_outer_diameter", UNSET))

        def _parse_disc_inner_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        disc_inner_diameter = _parse_disc_inner_diameter(d.pop("disc_inner_diameter", UNSET))

        def _parse_disc_thickness(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        disc_thickness = _parse_disc_thickness(d.pop("disc_thickness", UNSET))

        def _parse_disc_cone_height(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        disc_cone_height = _parse_disc_cone_height(d.pop("disc_cone_height", UNSET))

        def _parse_discs_parallel(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        discs_parallel = _parse_discs_parallel(d.pop("discs_parallel", UNSET))

        def _parse_discs_series(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        discs_series = _parse_discs_series(d.pop("discs_series", UNSET))

        def _parse_disc_count(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        disc_count = _parse_disc_count(d.pop("disc_count", UNSET))

        def _parse_disc_set_deflection(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        disc_set_deflection = _parse_disc_set_deflection(d.pop("disc_set_deflection", UNSET))

        def _parse_disc_stroke_deflection(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        disc_stroke_deflection = _parse_disc_stroke_deflection(d.pop("disc_stroke_deflection", UNSET))

        def _parse_disc_stress_om(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        disc_stress_om = _parse_disc_stress_om(d.pop("disc_stress_om", UNSET))

        def _parse_disc_stress_utilisation(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        disc_stress_utilisation = _parse_disc_stress_utilisation(d.pop("disc_stress_utilisation", UNSET))

        def _parse_shim_length(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        shim_length = _parse_shim_length(d.pop("shim_length", UNSET))

        def _parse_margin_spring_index(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        margin_spring_index = _parse_margin_spring_index(d.pop("margin_spring_index", UNSET))

        def _parse_margin_outer_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        margin_outer_diameter = _parse_margin_outer_diameter(d.pop("margin_outer_diameter", UNSET))

        def _parse_margin_inner_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        margin_inner_diameter = _parse_margin_inner_diameter(d.pop("margin_inner_diameter", UNSET))

        def _parse_margin_stress_at_set(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        margin_stress_at_set = _parse_margin_stress_at_set(d.pop("margin_stress_at_set", UNSET))

        def _parse_margin_stress_at_stroke(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        margin_stress_at_stroke = _parse_margin_stress_at_stroke(d.pop("margin_stress_at_stroke", UNSET))

        def _parse_margin_coil_gaps(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        margin_coil_gaps = _parse_margin_coil_gaps(d.pop("margin_coil_gaps", UNSET))

        def _parse_margin_buckling(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        margin_buckling = _parse_margin_buckling(d.pop("margin_buckling", UNSET))

        def _parse_margin_disc_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        margin_disc_preload = _parse_margin_disc_preload(d.pop("margin_disc_preload", UNSET))

        def _parse_margin_disc_deflection(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        margin_disc_deflection = _parse_margin_disc_deflection(d.pop("margin_disc_deflection", UNSET))

        def _parse_margin_disc_stress_om(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        margin_disc_stress_om = _parse_margin_disc_stress_om(d.pop("margin_disc_stress_om", UNSET))

        def _parse_margin_stack_length(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        margin_stack_length = _parse_margin_stack_length(d.pop("margin_stack_length", UNSET))

        def _parse_binding_limit(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        binding_limit = _parse_binding_limit(d.pop("binding_limit", UNSET))

        def _parse_candidates_checked(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        candidates_checked = _parse_candidates_checked(d.pop("candidates_checked", UNSET))

        def _parse_candidates_passing(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        candidates_passing = _parse_candidates_passing(d.pop("candidates_passing", UNSET))

        clutch_spring_design_results = cls(
            wire_diameter=wire_diameter,
            mean_diameter=mean_diameter,
            active_coils=active_coils,
            total_coils=total_coils,
            free_length=free_length,
            rate=rate,
            set_force=set_force,
            stroke=stroke,
            set_length=set_length,
            set_deflection=set_deflection,
            stroke_force=stroke_force,
            stroke_length=stroke_length,
            solid_length=solid_length,
            gap_sum=gap_sum,
            permissible_stress=permissible_stress,
            shear_stress_set=shear_stress_set,
            shear_stress_stroke=shear_stress_stroke,
            buckling_deflection=buckling_deflection,
            mass=mass,
            stress_utilisation_set=stress_utilisation_set,
            stress_utilisation_stroke=stress_utilisation_stroke,
            disc_designation=disc_designation,
            disc_outer_diameter=disc_outer_diameter,
            disc_inner_diameter=disc_inner_diameter,
            disc_thickness=disc_thickness,
            disc_cone_height=disc_cone_height,
            discs_parallel=discs_parallel,
            discs_series=discs_series,
            disc_count=disc_count,
            disc_set_deflection=disc_set_deflection,
            disc_stroke_deflection=disc_stroke_deflection,
            disc_stress_om=disc_stress_om,
            disc_stress_utilisation=disc_stress_utilisation,
            shim_length=shim_length,
            margin_spring_index=margin_spring_index,
            margin_outer_diameter=margin_outer_diameter,
            margin_inner_diameter=margin_inner_diameter,
            margin_stress_at_set=margin_stress_at_set,
            margin_stress_at_stroke=margin_stress_at_stroke,
            margin_coil_gaps=margin_coil_gaps,
            margin_buckling=margin_buckling,
            margin_disc_preload=margin_disc_preload,
            margin_disc_deflection=margin_disc_deflection,
            margin_disc_stress_om=margin_disc_stress_om,
            margin_stack_length=margin_stack_length,
            binding_limit=binding_limit,
            candidates_checked=candidates_checked,
            candidates_passing=candidates_passing,
        )

        clutch_spring_design_results.additional_properties = d
        return clutch_spring_design_results

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
