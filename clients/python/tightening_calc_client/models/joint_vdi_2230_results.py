from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="JointVdi2230Results")


@_attrs_define
class JointVdi2230Results:
    """
    Attributes:
        tightening_factor (float | None | Unset): R1: α_A = F_M,max/F_M,min (method, given, or torque box)
            [dimensionless]
        required_clamp_force (float | None | Unset): R2: F_K,erf = max(F_KQ, F_KP + F_KA) [N]
        opening_clamp_force (float | None | Unset): R2: F_KA = F_A (a − s_sym) u/(I_BT/A_D + s_sym u), not below 0 (0
            concentric) [N]
        transverse_clamp_force (float | None | Unset): R2: F_KQ = F_Q/(q_F μ_T,min) + M_Y/(q_M r_a μ_T,min) [N]
        bolt_compliance (float | None | Unset): R3: δ_S, head + shank + free thread + engaged thread + nut [m/N]
        bolt_compliance_head (float | None | Unset): R3: δ_SK = l_SK/(E_S A_N), l_SK = 0.5 d / 0.4 d [m/N]
        bolt_compliance_shank (float | None | Unset): R3: Σ l_i/(E_S A_i) of the plain and reduced shank [m/N]
        bolt_compliance_free_thread (float | None | Unset): R3: δ_Gew = l_Gew/(E_S A_d3) [m/N]
        bolt_compliance_engaged (float | None | Unset): R3: δ_GM = 0.5 d/(E_S A_d3) + l_M/(E_M A_N), l_M = 0.4 d (nut) /
            0.33 d (tapped) [m/N]
        clamped_compliance (float | None | Unset): R3: δ_P, deformation cone and sleeve, plate by plate [m/N]
        eccentric_clamped_compliance (float | None | Unset): R3 §5.3.2: δ*_P = δ_P + s_sym² β_P (δ_P for a concentric
            joint) [m/N]
        substitute_bending_inertia (float | None | Unset): R3 §5.3.2: I_Bers of cone (Steiner-shifted by s_sym) and
            sleeve b c_T³/12 in series (null without the interface) [m^4]
        clamped_bending_compliance (float | None | Unset): R3 §5.3.2: β_P = Σ h_i/E_i / I_Bers (null without the
            interface) [1/(N*m)]
        bolt_bending_compliance (float | None | Unset): R9 §5.1.1.2: β_S = Σ l_i/(E I_i) over the bolt's sections (null
            without the interface) [1/(N*m)]
        cone_tangent (float | None | Unset): R3: tan φ of the deformation cone (VDI fit) [dimensionless]
        cone_limit_diameter (float | None | Unset): R3: D_A,Gr = d_W + w l_K tan φ [m]
        outer_diameter_used (float | None | Unset): R3: D_A used [m]
        grip (float | None | Unset): R3: clamp length l_K = Σ h_i [m]
        load_factor_k (float | None | Unset): R3: Φ_K = δ_P/(δ_S + δ_P) (load under head and nut) [dimensionless]
        load_factor (float | None | Unset): R3: Φ_n = n Φ_K; eccentric: Φ*_en = n δ**_P/(δ_S + δ*_P), δ**_P = δ_P + a
            s_sym β_P [dimensionless]
        additional_bolt_load (float | None | Unset): R3/R8: F_SA = Φ_n F_A,max [N]
        clamp_load_reduction (float | None | Unset): R3: F_PA = (1 − Φ_n) F_A,max [N]
        embedding_settlement (float | None | Unset): R4: f_Z from the VDI table [m]
        embedding_loss (float | None | Unset): R4: F_Z = f_Z/(δ_S + δ_P) [N]
        thermal_loss (float | None | Unset): R4: ΔF_th (positive: preload lost) at F_V,min [N]
        required_preload_min (float | None | Unset): R5: F_M,min = F_K,erf + (1 − Φ_n) F_A + F_Z + ΔF_th [N]
        required_preload_max (float | None | Unset): R6: F_M,max = α_A F_M,min [N]
        smallest_diameter (float | None | Unset): R7: d_0 of the smallest section [m]
        smallest_area (float | None | Unset): R7: A_0 = π d_0²/4 [m^2]
        permissible_preload (float | None | Unset): R7: F_M,zul = ν R_p0.2 A_0/β at the smallest section, μ_G,min [N]
        yield_preload (float | None | Unset): R7: preload at σ_red = R_p0.2 (ν = 1) [N]
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
        additional_bolt_stress (float | None | Unset): R9: σ_SAb = Φ_b F_A,max/A_S, Φ_b = Φ*_en + (a − s_sym
            Φ*_en)(β_P/β_S)(A_S/W_S) with the bending (σ_SA = Φ_n F_A/A_S concentric) [Pa]
        endurance_limit (float | None | Unset): R9: σ_ASV or σ_ASG [Pa]
        fatigue_safety (float | None | Unset): R9: S_D = σ_AS/σ_a (null for static load) [dimensionless]
        slip_safety (float | None | Unset): R12: S_G = F_KR,min q_F μ_T/(F_Q + M_Y q_F/(q_M r_a)) (null without F_Q and
            M_Y; 0 where it opens) [dimensionless]
        fitted_shear_stress (float | None | Unset): R12 fitted bolt: τ_Q = F_Q/(q_F π d_τ²/4) (null without
            fitted_diameter) [Pa]
        fitted_shear_safety (float | None | Unset): R12 fitted bolt: S_A = 0.6 R_m/τ_Q, VDI asks ≥ 1.1 (null without
            fitted_diameter, R_m or F_Q) [dimensionless]
        fitted_bearing_pressure (float | None | Unset): R12 fitted bolt: p_Q = F_Q/(d_τ h_min) on the thinnest plate
            (null without fitted_diameter) [Pa]
        preload_stress_ratio (float | None | Unset): [004, eq. 6]: σ0/σ_T at the nominal preload, on A_0 [dimensionless]
        bolt_elongation (float | None | Unset): [004, eq. 7]: F_M,nom δ_S [m]
        target_angle (float | None | Unset): [004, eq. 8]: nut angle from snug to F_M,nom with δ_S + δ_P (R3) [rad]
        rigid_joint_angle (float | None | Unset): [004, eq. 9]: the same with rigid plates (what a rigid default gives)
            [rad]
        nut_stripping_force (float | None | Unset): R11 for a nut that does not pair with the bolt (thin, weaker class):
            F_SM = C1 C3 τ_BM A_SGM over m − 2P, τ_BM = 0.6 S_p (null where the nut pairs or is absent) [N]
        yield_strength_at_temperature (float | None | Unset): R8 at service_temperature: R_p0.2(T) = R_p0.2 ×
            R_p0.2,T/R_p0.2,20°C of the class (ISO 898-1 Annex A), the yield strength of S_F in service (R7, tightened cold,
            keeps R_p0.2 at room temperature; null at room temperature) [Pa]
        bolt_modulus_ratio_at_temperature (float | None | Unset): R4 at service_temperature: E_S,T/E_S,RT of the bolt
            (steel table), in ΔF_Vth (null at room temperature) [dimensionless]
        plate_modulus_ratio_at_temperature (float | None | Unset): R4 at service_temperature: E_P,T/E_P,RT of the
            plates, δ_P/Σ(δ_i E_i,RT/E_i,T), in ΔF_Vth (null at room temperature) [dimensionless]
    """

    tightening_factor: float | None | Unset = UNSET
    required_clamp_force: float | None | Unset = UNSET
    opening_clamp_force: float | None | Unset = UNSET
    transverse_clamp_force: float | None | Unset = UNSET
    bolt_compliance: float | None | Unset = UNSET
    bolt_compliance_head: float | None | Unset = UNSET
    bolt_compliance_shank: float | None | Unset = UNSET
    bolt_compliance_free_thread: float | None | Unset = UNSET
    bolt_compliance_engaged: float | None | Unset = UNSET
    clamped_compliance: float | None | Unset = UNSET
    eccentric_clamped_compliance: float | None | Unset = UNSET
    substitute_bending_inertia: float | None | Unset = UNSET
    clamped_bending_compliance: float | None | Unset = UNSET
    bolt_bending_compliance: float | None | Unset = UNSET
    cone_tangent: float | None | Unset = UNSET
    cone_limit_diameter: float | None | Unset = UNSET
    outer_diameter_used: float | None | Unset = UNSET
    grip: float | None | Unset = UNSET
    load_factor_k: float | None | Unset = UNSET
    load_factor: float | None | Unset = UNSET
    additional_bolt_load: float | None | Unset = UNSET
    clamp_load_reduction: float | None | Unset = UNSET
    embedding_settlement: float | None | Unset = UNSET
    embedding_loss: float | None | Unset = UNSET
    thermal_loss: float | None | Unset = UNSET
    required_preload_min: float | None | Unset = UNSET
    required_preload_max: float | None | Unset = UNSET
    smallest_diameter: float | None | Unset = UNSET
    smallest_area: float | None | Unset = UNSET
    permissible_preload: float | None | Unset = UNSET
    yield_preload: float | None | Unset = UNSET
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
    additional_bolt_stress: float | None | Unset = UNSET
    endurance_limit: float | None | Unset = UNSET
    fatigue_safety: float | None | Unset = UNSET
    slip_safety: float | None | Unset = UNSET
    fitted_shear_stress: float | None | Unset = UNSET
    fitted_shear_safety: float | None | Unset = UNSET
    fitted_bearing_pressure: float | None | Unset = UNSET
    preload_stress_ratio: float | None | Unset = UNSET
    bolt_elongation: float | None | Unset = UNSET
    target_angle: float | None | Unset = UNSET
    rigid_joint_angle: float | None | Unset = UNSET
    nut_stripping_force: float | None | Unset = UNSET
    yield_strength_at_temperature: float | None | Unset = UNSET
    bolt_modulus_ratio_at_temperature: float | None | Unset = UNSET
    plate_modulus_ratio_at_temperature: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        tightening_factor: float | None | Unset
        if isinstance(self.tightening_factor, Unset):
            tightening_factor = UNSET
        else:
            tightening_factor = self.tightening_factor

        required_clamp_force: float | None | Unset
        if isinstance(self.required_clamp_force, Unset):
            required_clamp_force = UNSET
        else:
            required_clamp_force = self.required_clamp_force

        opening_clamp_force: float | None | Unset
        if isinstance(self.opening_clamp_force, Unset):
            opening_clamp_force = UNSET
        else:
            opening_clamp_force = self.opening_clamp_force

        transverse_clamp_force: float | None | Unset
        if isinstance(self.transverse_clamp_force, Unset):
            transverse_clamp_force = UNSET
        else:
            transverse_clamp_force = self.transverse_clamp_force

        bolt_compliance: float | None | Unset
        if isinstance(self.bolt_compliance, Unset):
            bolt_compliance = UNSET
        else:
            bolt_compliance = self.bolt_compliance

        bolt_compliance_head: float | None | Unset
        if isinstance(self.bolt_compliance_head, Unset):
            bolt_compliance_head = UNSET
        else:
            bolt_compliance_head = self.bolt_compliance_head

        bolt_compliance_shank: float | None | Unset
        if isinstance(self.bolt_compliance_shank, Unset):
            bolt_compliance_shank = UNSET
        else:
            bolt_compliance_shank = self.bolt_compliance_shank

        bolt_compliance_free_thread: float | None | Unset
        if isinstance(self.bolt_compliance_free_thread, Unset):
            bolt_compliance_free_thread = UNSET
        else:
            bolt_compliance_free_thread = self.bolt_compliance_free_thread

        bolt_compliance_engaged: float | None | Unset
        if isinstance(self.bolt_compliance_engaged, Unset):
            bolt_compliance_engaged = UNSET
        else:
            bolt_compliance_engaged = self.bolt_compliance_engaged

        clamped_compliance: float | None | Unset
        if isinstance(self.clamped_compliance, Unset):
            clamped_compliance = UNSET
        else:
            clamped_compliance = self.clamped_compliance

        eccentric_clamped_compliance: float | None | Unset
        if isinstance(self.eccentric_clamped_compliance, Unset):
            eccentric_clamped_compliance = UNSET
        else:
            eccentric_clamped_compliance = self.eccentric_clamped_compliance

        substitute_bending_inertia: float | None | Unset
        if isinstance(self.substitute_bending_inertia, Unset):
            substitute_bending_inertia = UNSET
        else:
            substitute_bending_inertia = self.substitute_bending_inertia

        clamped_bending_compliance: float | None | Unset
        if isinstance(self.clamped_bending_compliance, Unset):
            clamped_bending_compliance = UNSET
        else:
            clamped_bending_compliance = self.clamped_bending_compliance

        bolt_bending_compliance: float | None | Unset
        if isinstance(self.bolt_bending_compliance, Unset):
            bolt_bending_compliance = UNSET
        else:
            bolt_bending_compliance = self.bolt_bending_compliance

        cone_tangent: float | None | Unset
        if isinstance(self.cone_tangent, Unset):
            cone_tangent = UNSET
        else:
            cone_tangent = self.cone_tangent

        cone_limit_diameter: float | None | Unset
        if isinstance(self.cone_limit_diameter, Unset):
            cone_limit_diameter = UNSET
        else:
            cone_limit_diameter = self.cone_limit_diameter

        outer_diameter_used: float | None | Unset
        if isinstance(self.outer_diameter_used, Unset):
            outer_diameter_used = UNSET
        else:
            outer_diameter_used = self.outer_diameter_used

        grip: float | None | Unset
        if isinstance(self.grip, Unset):
            grip = UNSET
        else:
            grip = self.grip

        load_factor_k: float | None | Unset
        if isinstance(self.load_factor_k, Unset):
            load_factor_k = UNSET
        else:
            load_factor_k = self.load_factor_k

        load_factor: float | None | Unset
        if isinstance(self.load_factor, Unset):
            load_factor = UNSET
        else:
            load_factor = self.load_factor

        additional_bolt_load: float | None | Unset
        if isinstance(self.additional_bolt_load, Unset):
            additional_bolt_load = UNSET
        else:
            additional_bolt_load = self.additional_bolt_load

        clamp_load_reduction: float | None | Unset
        if isinstance(self.clamp_load_reduction, Unset):
            clamp_load_reduction = UNSET
        else:
            clamp_load_reduction = self.clamp_load_reduction

        embedding_settlement: float | None | Unset
        if isinstance(self.embedding_settlement, Unset):
            embedding_settlement = UNSET
        else:
            embedding_settlement = self.embedding_settlement

        embedding_loss: float | None | Unset
        if isinstance(self.embedding_loss, Unset):
            embedding_loss = UNSET
        else:
            embedding_loss = self.embedding_loss

        thermal_loss: float | None | Unset
        if isinstance(self.thermal_loss, Unset):
            thermal_loss = UNSET
        else:
            thermal_loss = self.thermal_loss

        required_preload_min: float | None | Unset
        if isinstance(self.required_preload_min, Unset):
            required_preload_min = UNSET
        else:
            required_preload_min = self.required_preload_min

        required_preload_max: float | None | Unset
        if isinstance(self.required_preload_max, Unset):
            required_preload_max = UNSET
        else:
            required_preload_max = self.required_preload_max

        smallest_diameter: float | None | Unset
        if isinstance(self.smallest_diameter, Unset):
            smallest_diameter = UNSET
        else:
            smallest_diameter = self.smallest_diameter

        smallest_area: float | None | Unset
        if isinstance(self.smallest_area, Unset):
            smallest_area = UNSET
        else:
            smallest_area = self.smallest_area

        permissible_preload: float | None | Unset
        if isinstance(self.permissible_preload, Unset):
            permissible_preload = UNSET
        else:
            permissible_preload = self.permissible_preload

        yield_preload: float | None | Unset
        if isinstance(self.yield_preload, Unset):
            yield_preload = UNSET
        else:
            yield_preload = self.yield_preload

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

        additional_bolt_stress: float | None | Unset
        if isinstance(self.additional_bolt_stress, Unset):
            additional_bolt_stress = UNSET
        else:
            additional_bolt_stress = self.additional_bolt_stress

        endurance_limit: float | None | Unset
        if isinstance(self.endurance_limit, Unset):
            endurance_limit = UNSET
        else:
            endurance_limit = self.endurance_limit

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

        fitted_shear_stress: float | None | Unset
        if isinstance(self.fitted_shear_stress, Unset):
            fitted_shear_stress = UNSET
        else:
            fitted_shear_stress = self.fitted_shear_stress

        fitted_shear_safety: float | None | Unset
        if isinstance(self.fitted_shear_safety, Unset):
            fitted_shear_safety = UNSET
        else:
            fitted_shear_safety = self.fitted_shear_safety

        fitted_bearing_pressure: float | None | Unset
        if isinstance(self.fitted_bearing_pressure, Unset):
            fitted_bearing_pressure = UNSET
        else:
            fitted_bearing_pressure = self.fitted_bearing_pressure

        preload_stress_ratio: float | None | Unset
        if isinstance(self.preload_stress_ratio, Unset):
            preload_stress_ratio = UNSET
        else:
            preload_stress_ratio = self.preload_stress_ratio

        bolt_elongation: float | None | Unset
        if isinstance(self.bolt_elongation, Unset):
            bolt_elongation = UNSET
        else:
            bolt_elongation = self.bolt_elongation

        target_angle: float | None | Unset
        if isinstance(self.target_angle, Unset):
            target_angle = UNSET
        else:
            target_angle = self.target_angle

        rigid_joint_angle: float | None | Unset
        if isinstance(self.rigid_joint_angle, Unset):
            rigid_joint_angle = UNSET
        else:
            rigid_joint_angle = self.rigid_joint_angle

        nut_stripping_force: float | None | Unset
        if isinstance(self.nut_stripping_force, Unset):
            nut_stripping_force = UNSET
        else:
            nut_stripping_force = self.nut_stripping_force

        yield_strength_at_temperature: float | None | Unset
        if isinstance(self.yield_strength_at_temperature, Unset):
            yield_strength_at_temperature = UNSET
        else:
            yield_strength_at_temperature = self.yield_strength_at_temperature

        bolt_modulus_ratio_at_temperature: float | None | Unset
        if isinstance(self.bolt_modulus_ratio_at_temperature, Unset):
            bolt_modulus_ratio_at_temperature = UNSET
        else:
            bolt_modulus_ratio_at_temperature = self.bolt_modulus_ratio_at_temperature

        plate_modulus_ratio_at_temperature: float | None | Unset
        if isinstance(self.plate_modulus_ratio_at_temperature, Unset):
            plate_modulus_ratio_at_temperature = UNSET
        else:
            plate_modulus_ratio_at_temperature = self.plate_modulus_ratio_at_temperature

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if tightening_factor is not UNSET:
            field_dict["tightening_factor"] = tightening_factor
        if required_clamp_force is not UNSET:
            field_dict["required_clamp_force"] = required_clamp_force
        if opening_clamp_force is not UNSET:
            field_dict["opening_clamp_force"] = opening_clamp_force
        if transverse_clamp_force is not UNSET:
            field_dict["transverse_clamp_force"] = transverse_clamp_force
        if bolt_compliance is not UNSET:
            field_dict["bolt_compliance"] = bolt_compliance
        if bolt_compliance_head is not UNSET:
            field_dict["bolt_compliance_head"] = bolt_compliance_head
        if bolt_compliance_shank is not UNSET:
            field_dict["bolt_compliance_shank"] = bolt_compliance_shank
        if bolt_compliance_free_thread is not UNSET:
            field_dict["bolt_compliance_free_thread"] = bolt_compliance_free_thread
        if bolt_compliance_engaged is not UNSET:
            field_dict["bolt_compliance_engaged"] = bolt_compliance_engaged
        if clamped_compliance is not UNSET:
            field_dict["clamped_compliance"] = clamped_compliance
        if eccentric_clamped_compliance is not UNSET:
            field_dict["eccentric_clamped_compliance"] = eccentric_clamped_compliance
        if substitute_bending_inertia is not UNSET:
            field_dict["substitute_bending_inertia"] = substitute_bending_inertia
        if clamped_bending_compliance is not UNSET:
            field_dict["clamped_bending_compliance"] = clamped_bending_compliance
        if bolt_bending_compliance is not UNSET:
            field_dict["bolt_bending_compliance"] = bolt_bending_compliance
        if cone_tangent is not UNSET:
            field_dict["cone_tangent"] = cone_tangent
        if cone_limit_diameter is not UNSET:
            field_dict["cone_limit_diameter"] = cone_limit_diameter
        if outer_diameter_used is not UNSET:
            field_dict["outer_diameter_used"] = outer_diameter_used
        if grip is not UNSET:
            field_dict["grip"] = grip
        if load_factor_k is not UNSET:
            field_dict["load_factor_k"] = load_factor_k
        if load_factor is not UNSET:
            field_dict["load_factor"] = load_factor
        if additional_bolt_load is not UNSET:
            field_dict["additional_bolt_load"] = additional_bolt_load
        if clamp_load_reduction is not UNSET:
            field_dict["clamp_load_reduction"] = clamp_load_reduction
        if embedding_settlement is not UNSET:
            field_dict["embedding_settlement"] = embedding_settlement
        if embedding_loss is not UNSET:
            field_dict["embedding_loss"] = embedding_loss
        if thermal_loss is not UNSET:
            field_dict["thermal_loss"] = thermal_loss
        if required_preload_min is not UNSET:
            field_dict["required_preload_min"] = required_preload_min
        if required_preload_max is not UNSET:
            field_dict["required_preload_max"] = required_preload_max
        if smallest_diameter is not UNSET:
            field_dict["smallest_diameter"] = smallest_diameter
        if smallest_area is not UNSET:
            field_dict["smallest_area"] = smallest_area
        if permissible_preload is not UNSET:
            field_dict["permissible_preload"] = permissible_preload
        if yield_preload is not UNSET:
            field_dict["yield_preload"] = yield_preload
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
        if additional_bolt_stress is not UNSET:
            field_dict["additional_bolt_stress"] = additional_bolt_stress
        if endurance_limit is not UNSET:
            field_dict["endurance_limit"] = endurance_limit
        if fatigue_safety is not UNSET:
            field_dict["fatigue_safety"] = fatigue_safety
        if slip_safety is not UNSET:
            field_dict["slip_safety"] = slip_safety
        if fitted_shear_stress is not UNSET:
            field_dict["fitted_shear_stress"] = fitted_shear_stress
        if fitted_shear_safety is not UNSET:
            field_dict["fitted_shear_safety"] = fitted_shear_safety
        if fitted_bearing_pressure is not UNSET:
            field_dict["fitted_bearing_pressure"] = fitted_bearing_pressure
        if preload_stress_ratio is not UNSET:
            field_dict["preload_stress_ratio"] = preload_stress_ratio
        if bolt_elongation is not UNSET:
            field_dict["bolt_elongation"] = bolt_elongation
        if target_angle is not UNSET:
            field_dict["target_angle"] = target_angle
        if rigid_joint_angle is not UNSET:
            field_dict["rigid_joint_angle"] = rigid_joint_angle
        if nut_stripping_force is not UNSET:
            field_dict["nut_stripping_force"] = nut_stripping_force
        if yield_strength_at_temperature is not UNSET:
            field_dict["yield_strength_at_temperature"] = yield_strength_at_temperature
        if bolt_modulus_ratio_at_temperature is not UNSET:
            field_dict["bolt_modulus_ratio_at_temperature"] = bolt_modulus_ratio_at_temperature
        if plate_modulus_ratio_at_temperature is not UNSET:
            field_dict["plate_modulus_ratio_at_temperature"] = plate_modulus_ratio_at_temperature

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_tightening_factor(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tightening_factor = _parse_tightening_factor(d.pop("tightening_factor", UNSET))

        def _parse_required_clamp_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_clamp_force = _parse_required_clamp_force(d.pop("required_clamp_force", UNSET))

        def _parse_opening_clamp_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        opening_clamp_force = _parse_opening_clamp_force(d.pop("opening_clamp_force", UNSET))

        def _parse_transverse_clamp_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        transverse_clamp_force = _parse_transverse_clamp_force(d.pop("transverse_clamp_force", UNSET))

        def _parse_bolt_compliance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_compliance = _parse_bolt_compliance(d.pop("bolt_compliance", UNSET))

        def _parse_bolt_compliance_head(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_compliance_head = _parse_bolt_compliance_head(d.pop("bolt_compliance_head", UNSET))

        def _parse_bolt_compliance_shank(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_compliance_shank = _parse_bolt_compliance_shank(d.pop("bolt_compliance_shank", UNSET))

        def _parse_bolt_compliance_free_thread(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_compliance_free_thread = _parse_bolt_compliance_free_thread(d.pop("bolt_compliance_free_thread", UNSET))

        def _parse_bolt_compliance_engaged(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_compliance_engaged = _parse_bolt_compliance_engaged(d.pop("bolt_compliance_engaged", UNSET))

        def _parse_clamped_compliance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        clamped_compliance = _parse_clamped_compliance(d.pop("clamped_compliance", UNSET))

        def _parse_eccentric_clamped_compliance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        eccentric_clamped_compliance = _parse_eccentric_clamped_compliance(d.pop("eccentric_clamped_compliance", UNSET))

        def _parse_substitute_bending_inertia(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        substitute_bending_inertia = _parse_substitute_bending_inertia(d.pop("substitute_bending_inertia", UNSET))

        def _parse_clamped_bending_compliance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        clamped_bending_compliance = _parse_clamped_bending_compliance(d.pop("clamped_bending_compliance", UNSET))

        def _parse_bolt_bending_compliance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_bending_compliance = _parse_bolt_bending_compliance(d.pop("bolt_bending_compliance", UNSET))

        def _parse_cone_tangent(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        cone_tangent = _parse_cone_tangent(d.pop("cone_tangent", UNSET))

        def _parse_cone_limit_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        cone_limit_diameter = _parse_cone_limit_diameter(d.pop("cone_limit_diameter", UNSET))

        def _parse_outer_diameter_used(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        outer_diameter_used = _parse_outer_diameter_used(d.pop("outer_diameter_used", UNSET))

        def _parse_grip(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        grip = _parse_grip(d.pop("grip", UNSET))

        def _parse_load_factor_k(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        load_factor_k = _parse_load_factor_k(d.pop("load_factor_k", UNSET))

        def _parse_load_factor(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        load_factor = _parse_load_factor(d.pop("load_factor", UNSET))

        def _parse_additional_bolt_load(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        additional_bolt_load = _parse_additional_bolt_load(d.pop("additional_bolt_load", UNSET))

        def _parse_clamp_load_reduction(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        clamp_load_reduction = _parse_clamp_load_reduction(d.pop("clamp_load_reduction", UNSET))

        def _parse_embedding_settlement(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        embedding_settlement = _parse_embedding_settlement(d.pop("embedding_settlement", UNSET))

        def _parse_embedding_loss(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        embedding_loss = _parse_embedding_loss(d.pop("embedding_loss", UNSET))

        def _parse_thermal_loss(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        thermal_loss = _parse_thermal_loss(d.pop("thermal_loss", UNSET))

        def _parse_required_preload_min(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_preload_min = _parse_required_preload_min(d.pop("required_preload_min", UNSET))

        def _parse_required_preload_max(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        required_preload_max = _parse_required_preload_max(d.pop("required_preload_max", UNSET))

        def _parse_smallest_diameter(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        smallest_diameter = _parse_smallest_diameter(d.pop("smallest_diameter", UNSET))

        def _parse_smallest_area(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        smallest_area = _parse_smallest_area(d.pop("smallest_area", UNSET))

        def _parse_permissible_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        permissible_preload = _parse_permissible_preload(d.pop("permissible_preload", UNSET))

        def _parse_yield_preload(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        yield_preload = _parse_yield_preload(d.pop("yield_preload", UNSET))

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

        def _parse_additional_bolt_stress(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        additional_bolt_stress = _parse_additional_bolt_stress(d.pop("additional_bolt_stress", UNSET))

        def _parse_endurance_limit(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        endurance_limit = _parse_endurance_limit(d.pop("endurance_limit", UNSET))

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

        def _parse_fitted_shear_stress(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        fitted_shear_stress = _parse_fitted_shear_stress(d.pop("fitted_shear_stress", UNSET))

        def _parse_fitted_shear_safety(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        fitted_shear_safety = _parse_fitted_shear_safety(d.pop("fitted_shear_safety", UNSET))

        def _parse_fitted_bearing_pressure(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        fitted_bearing_pressure = _parse_fitted_bearing_pressure(d.pop("fitted_bearing_pressure", UNSET))

        def _parse_preload_stress_ratio(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        preload_stress_ratio = _parse_preload_stress_ratio(d.pop("preload_stress_ratio", UNSET))

        def _parse_bolt_elongation(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_elongation = _parse_bolt_elongation(d.pop("bolt_elongation", UNSET))

        def _parse_target_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        target_angle = _parse_target_angle(d.pop("target_angle", UNSET))

        def _parse_rigid_joint_angle(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        rigid_joint_angle = _parse_rigid_joint_angle(d.pop("rigid_joint_angle", UNSET))

        def _parse_nut_stripping_force(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        nut_stripping_force = _parse_nut_stripping_force(d.pop("nut_stripping_force", UNSET))

        def _parse_yield_strength_at_temperature(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        yield_strength_at_temperature = _parse_yield_strength_at_temperature(
            d.pop("yield_strength_at_temperature", UNSET)
        )

        def _parse_bolt_modulus_ratio_at_temperature(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        bolt_modulus_ratio_at_temperature = _parse_bolt_modulus_ratio_at_temperature(
            d.pop("bolt_modulus_ratio_at_temperature", UNSET)
        )

        def _parse_plate_modulus_ratio_at_temperature(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        plate_modulus_ratio_at_temperature = _parse_plate_modulus_ratio_at_temperature(
            d.pop("plate_modulus_ratio_at_temperature", UNSET)
        )

        joint_vdi_2230_results = cls(
            tightening_factor=tightening_factor,
            required_clamp_force=required_clamp_force,
            opening_clamp_force=opening_clamp_force,
            transverse_clamp_force=transverse_clamp_force,
            bolt_compliance=bolt_compliance,
            bolt_compliance_head=bolt_compliance_head,
            bolt_compliance_shank=bolt_compliance_shank,
            bolt_compliance_free_thread=bolt_compliance_free_thread,
            bolt_compliance_engaged=bolt_compliance_engaged,
            clamped_compliance=clamped_compliance,
            eccentric_clamped_compliance=eccentric_clamped_compliance,
            substitute_bending_inertia=substitute_bending_inertia,
            clamped_bending_compliance=clamped_bending_compliance,
            bolt_bending_compliance=bolt_bending_compliance,
            cone_tangent=cone_tangent,
            cone_limit_diameter=cone_limit_diameter,
            outer_diameter_used=outer_diameter_used,
            grip=grip,
            load_factor_k=load_factor_k,
            load_factor=load_factor,
            additional_bolt_load=additional_bolt_load,
            clamp_load_reduction=clamp_load_reduction,
            embedding_settlement=embedding_settlement,
            embedding_loss=embedding_loss,
            thermal_loss=thermal_loss,
            required_preload_min=required_preload_min,
            required_preload_max=required_preload_max,
            smallest_diameter=smallest_diameter,
            smallest_area=smallest_area,
            permissible_preload=permissible_preload,
            yield_preload=yield_preload,
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
            additional_bolt_stress=additional_bolt_stress,
            endurance_limit=endurance_limit,
            fatigue_safety=fatigue_safety,
            slip_safety=slip_safety,
            fitted_shear_stress=fitted_shear_stress,
            fitted_shear_safety=fitted_shear_safety,
            fitted_bearing_pressure=fitted_bearing_pressure,
            preload_stress_ratio=preload_stress_ratio,
            bolt_elongation=bolt_elongation,
            target_angle=target_angle,
            rigid_joint_angle=rigid_joint_angle,
            nut_stripping_force=nut_stripping_force,
            yield_strength_at_temperature=yield_strength_at_temperature,
            bolt_modulus_ratio_at_temperature=bolt_modulus_ratio_at_temperature,
            plate_modulus_ratio_at_temperature=plate_modulus_ratio_at_temperature,
        )

        joint_vdi_2230_results.additional_properties = d
        return joint_vdi_2230_results

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
