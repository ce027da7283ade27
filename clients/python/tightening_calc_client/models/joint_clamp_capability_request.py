from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.joint_clamp_capability_request_bearing_friction_law_type_0 import (
    JointClampCapabilityRequestBearingFrictionLawType0,
)
from ..models.joint_clamp_capability_request_category_type_0 import JointClampCapabilityRequestCategoryType0
from ..models.joint_clamp_capability_request_clamped_material_type_0 import (
    JointClampCapabilityRequestClampedMaterialType0,
)
from ..models.joint_clamp_capability_request_fidelity_type_0 import JointClampCapabilityRequestFidelityType0
from ..models.joint_clamp_capability_request_head_standard_type_0 import JointClampCapabilityRequestHeadStandardType0
from ..models.joint_clamp_capability_request_head_type_0 import JointClampCapabilityRequestHeadType0
from ..models.joint_clamp_capability_request_hole_series_type_0 import JointClampCapabilityRequestHoleSeriesType0
from ..models.joint_clamp_capability_request_internal_thread_material_type_0 import (
    JointClampCapabilityRequestInternalThreadMaterialType0,
)
from ..models.joint_clamp_capability_request_joint_type_type_0 import JointClampCapabilityRequestJointTypeType0
from ..models.joint_clamp_capability_request_nut_property_class_type_0 import (
    JointClampCapabilityRequestNutPropertyClassType0,
)
from ..models.joint_clamp_capability_request_nut_type_0 import JointClampCapabilityRequestNutType0
from ..models.joint_clamp_capability_request_outputs_type_0_item import JointClampCapabilityRequestOutputsType0Item
from ..models.joint_clamp_capability_request_property_class_type_0 import JointClampCapabilityRequestPropertyClassType0
from ..models.joint_clamp_capability_request_rolling_type_0 import JointClampCapabilityRequestRollingType0
from ..models.joint_clamp_capability_request_surface_roughness_type_0 import (
    JointClampCapabilityRequestSurfaceRoughnessType0,
)
from ..models.joint_clamp_capability_request_thread_friction_law_type_0 import (
    JointClampCapabilityRequestThreadFrictionLawType0,
)
from ..models.joint_clamp_capability_request_washer_type_0 import JointClampCapabilityRequestWasherType0
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.joint_clamp_capability_request_torque_samples_type_1 import (
        JointClampCapabilityRequestTorqueSamplesType1,
    )


T = TypeVar("T", bound="JointClampCapabilityRequest")


@_attrs_define
class JointClampCapabilityRequest:
    """
    Attributes:
        plate1_thickness (float | str): Thickness h_1 of clamped plate 1 (from the head side)
        thread (str | Unset): Designation instead of thread_diameter: 'M12', 'M12x1.25', 'M10 ISO 4762 12.9', '1/2-13
            UNC', '1/2-13 UNC Grade 5' (ISO M1.6…M64 coarse and fine, UNC/UNF 1/4…1-1/2; GET /api/v1/fasteners lists them).
            A head standard or grade in it sets head_standard and grade
        grade (str | Unset): Bolt grade, overriding property_class: ISO 898-1 (8.8…12.9), ISO 3506-1 (A2-70, A4-70,
            A4-80), SAE J429 ('SAE 5', 'Grade 8'), ASTM A193 'B7'
        thread_diameter (float | None | str | Unset): Nominal thread diameter d, when no thread designation is given
            (ISO 261 M3…M39 have tabulated data; other sizes need thread_pitch, bearing_outer_diameter, hole_diameter and
            yield_strength)
        thread_pitch (float | None | str | Unset): Thread pitch P; ISO 261 coarse pitch when absent
        property_class (JointClampCapabilityRequestPropertyClassType0 | None | Unset): ISO 898-1 property class: minimum
            yield and tensile strength (8.8: 640/800 MPa up to M16, 660/830 MPa above) Default:
            JointClampCapabilityRequestPropertyClassType0.VALUE_5.
        yield_strength (float | None | str | Unset): Minimum yield strength R_p0.2 (σ_T in [004]); overrides the
            property class
        bearing_outer_diameter (float | None | str | Unset): Outer diameter D_f of the bearing face; ISO 4017 hexagon
            head d_w,min when absent
        hole_diameter (float | None | str | Unset): Clearance-hole diameter d_h (inner diameter of the bearing face);
            ISO 273 of hole_series when absent
        hole_series (JointClampCapabilityRequestHoleSeriesType0 | None | Unset): ISO 273 clearance-hole series used when
            hole_diameter is absent Default: JointClampCapabilityRequestHoleSeriesType0.MEDIUM.
        utilization (float | None | str | Unset): ν: share of the yield strength the equivalent stress may use at
            assembly (VDI 2230: 0.9; [004, eq. 3]: ξ/n_T, 0.71…0.83) Default: 0.9.
        head (JointClampCapabilityRequestHeadType0 | None | Unset): Head type: 'hex' (l_SK = 0.5 d) or 'socket' (0.4 d),
            VDI 2230-1 R3 Default: JointClampCapabilityRequestHeadType0.HEX.
        joint_type (JointClampCapabilityRequestJointTypeType0 | None | Unset): 'through': bolt and nut (DSV); 'tapped':
            screwed into the last part (ESV) Default: JointClampCapabilityRequestJointTypeType0.THROUGH.
        shank_length (float | None | str | Unset): Length of plain shank inside the grip; the rest of the grip is free
            thread Default: 0.0.
        shank_diameter (float | None | str | Unset): Plain shank diameter; d when absent
        reduced_length (float | None | str | Unset): Length of a reduced (waisted) shank inside the grip Default: 0.0.
        reduced_diameter (float | None | str | Unset): Diameter d_T of the reduced shank (needed when reduced_length >
            0); the strength limit F_M,zul is taken at the smallest section (VDI 2230-1 R7)
        youngs_modulus (float | None | str | Unset): Young's modulus of the bolt E_S Default: 210000000000.0.
        nut_youngs_modulus (float | None | str | Unset): Young's modulus E_M of the nut or of the part with the tapped
            thread; E_S when absent
        bolt_expansion (float | None | str | Unset): Thermal expansion coefficient α_S of the bolt Default: 1.15e-05.
        plate1_youngs_modulus (float | None | str | Unset): Young's modulus E_1 of plate 1 (steel 210 GPa) Default:
            210000000000.0.
        plate1_expansion (float | None | str | Unset): Thermal expansion coefficient α_1 of plate 1 (steel 11.5e-6 /K;
            type e.g. '23e-6 K^-1') Default: 1.15e-05.
        plate2_thickness (float | None | str | Unset): Thickness h_2 of clamped plate 2 (from the head side); absent or
            0: no such plate
        plate2_youngs_modulus (float | None | str | Unset): Young's modulus E_2 of plate 2; plate 1's when absent
        plate2_expansion (float | None | str | Unset): Thermal expansion coefficient α_2 of plate 2; plate 1's when
            absent
        plate2_outer_diameter (float | None | str | Unset): Outer diameter D_A,2 of plate 2 (VDI 2230-1 R3: its part of
            the cone is capped there, a sleeve below d_W); outer_diameter (plate 1's) when absent
        plate3_thickness (float | None | str | Unset): Thickness h_3 of clamped plate 3 (from the head side); absent or
            0: no such plate
        plate3_youngs_modulus (float | None | str | Unset): Young's modulus E_3 of plate 3; plate 1's when absent
        plate3_expansion (float | None | str | Unset): Thermal expansion coefficient α_3 of plate 3; plate 1's when
            absent
        plate3_outer_diameter (float | None | str | Unset): Outer diameter D_A,3 of plate 3 (VDI 2230-1 R3: its part of
            the cone is capped there, a sleeve below d_W); outer_diameter (plate 1's) when absent
        outer_diameter (float | None | str | Unset): Outer diameter D_A of the clamped parts (equivalent); absent:
            plates wide enough for the full deformation cone. Must be ≥ the bearing diameter d_W
        load_introduction (float | None | str | Unset): Load-introduction factor n (VDI 2230-1 R3): 1 under the head and
            nut, 0.5 typical, lower when the load enters near the interface Default: 0.5.
        bolt_offset (float | None | str | Unset): Eccentric clamping (VDI 2230-1 §5.3.2): distance s_sym of the bolt
            axis from the axis O–O of the clamped body, positive towards the working load's line; 0: concentric Default:
            0.0.
        load_lever (float | None | str | Unset): Eccentric loading: distance a of the working load's line from the axis
            O–O; 0: the load acts on the body's axis Default: 0.0.
        opening_edge (float | None | str | Unset): Distance u from O–O of the interface edge that opens first (on the
            load's side); 0: no opening requirement F_KA Default: 0.0.
        interface_length (float | None | str | Unset): Length c_T of the interface in the bending plane (needed with
            s_sym, a or u ≠ 0)
        interface_width (float | None | str | Unset): Width b of the interface across the bending plane (needed with
            c_T)
        working_load (float | None | str | Unset): Axial working load F_A,max per bolt (0: preload only) Default: 0.0.
        working_load_min (float | None | str | Unset): Lower axial working load F_A,min of an alternating load; static
            (= F_A,max) when absent
        transverse_load (float | None | str | Unset): Transverse load F_Q,max per bolt carried by interface friction
            Default: 0.0.
        slip_interfaces (int | None | str | Unset): Number q_F of interfaces that carry the transverse load Default: 1.
        fitted_diameter (float | None | str | Unset): Fitted bolt: diameter d_τ of the fitted shank that carries F_Q in
            shear and bearing (VDI 2230-1 R12); absent: the interfaces carry F_Q by friction alone
        torsional_moment (float | None | str | Unset): Torsional moment M_Y,max about the bolt axis carried by interface
            friction (VDI 2230-1 R2/R12); needs friction_radius Default: 0.0.
        torque_interfaces (int | None | str | Unset): Number q_M of interfaces that carry the torsional moment Default:
            1.
        friction_radius (float | None | str | Unset): Friction radius r_a of the interface for the torsional moment
            (needed with M_Y > 0)
        interface_friction (float | None | str | Unset): Smallest interface friction coefficient μ_T,min (VDI 2230-1
            Table A6: 0.1…0.2 dry steel) Default: 0.15.
        sealing_clamp_force (float | None | str | Unset): Clamp force F_KP that must remain for sealing or other reasons
            (added to the friction requirement's maximum, VDI 2230-1 R2) Default: 0.0.
        surface_roughness (JointClampCapabilityRequestSurfaceRoughnessType0 | None | Unset): Mean roughness depth class
            of the bearing faces and interfaces (embedding, VDI R4) Default:
            JointClampCapabilityRequestSurfaceRoughnessType0.RZ10_40.
        temperature_change (float | None | str | Unset): Service temperature minus assembly temperature of the bolt ΔT_S
            Default: 0.0.
        plate_temperature_change (float | None | str | Unset): Temperature change of the plates ΔT_P; ΔT_S when absent
        bolt_modulus_ratio (float | None | str | Unset): E of the bolt at service temperature / at room temperature
            Default: 1.0.
        plate_modulus_ratio (float | None | str | Unset): E of the plates at service temperature / at room temperature
            Default: 1.0.
        service_temperature (float | None | str | Unset): Absolute temperature of bolt and plates in service (e.g. '150
            degC'); absent: room temperature; −40…300 °C (below 20 °C the 20 °C values, conservative). At it R_p0.2 of the
            bolt's class (ISO 898-1 Annex A: 5.6, 8.8, 10.9, 12.9) sets R8 (R7 stays at room temperature: the bolt is
            tightened cold), and E of bolt and plates (tables by material) set the thermal preload loss in place of
            bolt_modulus_ratio and plate_modulus_ratio
        prevailing_torque (float | None | str | Unset): Prevailing (locking) torque M_ü that produces no preload
            Default: 0.0.
        rolling (JointClampCapabilityRequestRollingType0 | None | Unset): Thread rolled before or after heat treatment
            (endurance limit, VDI 2230-1 R9) Default: JointClampCapabilityRequestRollingType0.BEFORE_HEAT_TREATMENT.
        head_standard (JointClampCapabilityRequestHeadStandardType0 | None | Unset): Head standard (bearing diameter
            d_w, drive): hexagon ISO 4017/4014 when absent (ASME B18.2.1 hex for inch threads)
        washer (JointClampCapabilityRequestWasherType0 | None | Unset): Plain washer under the head (spreads the
            pressure on the clamped part)
        nut (JointClampCapabilityRequestNutType0 | None | Unset): Hexagon nut (a through-bolted joint: surface pressure
            under the nut); absent: tapped
        clamped_material (JointClampCapabilityRequestClampedMaterialType0 | None | Unset): Material under the head and
            nut: its limiting surface pressure p_G (VDI 2230-1 Table A9; plastics: compressive yield)
        limiting_surface_pressure (float | None | str | Unset): Limiting surface pressure p_G of the clamped part;
            overrides clamped_material
        internal_thread_material (JointClampCapabilityRequestInternalThreadMaterialType0 | None | Unset): Material of
            the tapped hole: its shear strength τ_BM for the stripping check
        internal_thread_shear_strength (float | None | str | Unset): Shear strength τ_BM of the internal thread;
            overrides internal_thread_material
        engagement_length (float | None | str | Unset): Length of thread engagement in the tapped hole as built, entry
            chamfers included (VDI 2230-1 R11: m_ges = m_eff + 2P)
        nut_property_class (JointClampCapabilityRequestNutPropertyClassType0 | None | Unset): Property class of the nut
            (ISO 898-2; 04/05: thin nuts): its proof load caps F_M,zul; absent: the lowest class the nut standard is made in
            that pairs with the bolt
        nominal_torque (float | None | str | Unset): Torque the tool is set to (the middle of its tolerance) Default:
            80.0.
        mean_torque (float | None | str | Unset): Mean torque the tool gives, when it is not the nominal (with
            torque_sd)
        torque_sd (float | None | str | Unset): Standard deviation of the tool's torque (0: a perfect tool)
        capability_index (float | None | str | Unset): The tool's Cm at relative_tolerance (instead of torque_sd): σ = 2
            t M_A/(6 Cm)
        critical_capability_index (float | None | str | Unset): The tool's Cmk (≤ Cm); its mean then lies 3σ(Cm − Cmk)
            above the nominal (the side that loads the bolt more); Cm when absent
        relative_tolerance (float | None | str | Unset): Torque tolerance ± of the tool's Cm/Cmk and of the category
            check (0.1 is ±10 %) Default: 0.1.
        torque_samples (JointClampCapabilityRequestTorqueSamplesType1 | list[float] | None | Unset): Measured torques of
            the tool (instead of torque_sd or Cm): their mean and s
        thread_friction_law (JointClampCapabilityRequestThreadFrictionLawType0 | None | Unset): Law of the thread
            friction μ_G over the bolts of the lot Default: JointClampCapabilityRequestThreadFrictionLawType0.UNIFORM.
        thread_friction_low (float | None | str | Unset): μ_G: lower end (uniform, triangular) or truncation (truncated
            normal) Default: 0.08.
        thread_friction_high (float | None | str | Unset): μ_G: upper end (uniform, triangular) or truncation (truncated
            normal) Default: 0.16.
        thread_friction_mean (float | None | str | Unset): μ_G: mean (normal, truncated normal, lognormal, fixed)
        thread_friction_sd (float | None | str | Unset): μ_G: standard deviation (normal, truncated normal, lognormal)
        thread_friction_mode (float | None | str | Unset): μ_G: most likely value (triangular)
        bearing_friction_law (JointClampCapabilityRequestBearingFrictionLawType0 | None | Unset): Law of the bearing-
            face friction μ_K over the bolts of the lot Default: JointClampCapabilityRequestBearingFrictionLawType0.UNIFORM.
        bearing_friction_low (float | None | str | Unset): μ_K: lower end (uniform, triangular) or truncation (truncated
            normal) Default: 0.08.
        bearing_friction_high (float | None | str | Unset): μ_K: upper end (uniform, triangular) or truncation
            (truncated normal) Default: 0.16.
        bearing_friction_mean (float | None | str | Unset): μ_K: mean (normal, truncated normal, lognormal, fixed)
        bearing_friction_sd (float | None | str | Unset): μ_K: standard deviation (normal, truncated normal, lognormal)
        bearing_friction_mode (float | None | str | Unset): μ_K: most likely value (triangular)
        friction_correlation (float | None | str | Unset): Rank (Spearman) correlation of μ_G and μ_K over the lot,
            through a Gaussian copula Default: 0.0.
        allowed_ppm (float | None | str | Unset): Share of bolts you accept below F_M,min or above F_M,zul, in ppm (your
            limit; no standard sets one) Default: 1.0.
        category (JointClampCapabilityRequestCategoryType0 | None | Unset): VDI/VDE 2862 category of the joint, for the
            tool's minimum Cmk as [CSP2862] states it Default: JointClampCapabilityRequestCategoryType0.NONE.
        fidelity (JointClampCapabilityRequestFidelityType0 | None | Unset): 'auto' picks the cheapest rung whose error
            estimate meets `tolerance`; or name a rung. Absent: 'auto', or 'auto' when a tolerance is given
        tolerance (float | None | Unset): relative tolerance for 'auto' (0.01)
        outputs (list[JointClampCapabilityRequestOutputsType0Item] | None | Unset): compute only these outputs and
            series (every scalar output when absent)
        series (bool | Unset): true: compute and send every series too (absent/false: only the series named in
            `outputs`) Default: False.
    """

    plate1_thickness: float | str
    thread: str | Unset = UNSET
    grade: str | Unset = UNSET
    thread_diameter: float | None | str | Unset = UNSET
    thread_pitch: float | None | str | Unset = UNSET
    property_class: JointClampCapabilityRequestPropertyClassType0 | None | Unset = (
        JointClampCapabilityRequestPropertyClassType0.VALUE_5
    )
    yield_strength: float | None | str | Unset = UNSET
    bearing_outer_diameter: float | None | str | Unset = UNSET
    hole_diameter: float | None | str | Unset = UNSET
    hole_series: JointClampCapabilityRequestHoleSeriesType0 | None | Unset = (
        JointClampCapabilityRequestHoleSeriesType0.MEDIUM
    )
    utilization: float | None | str | Unset = 0.9
    head: JointClampCapabilityRequestHeadType0 | None | Unset = JointClampCapabilityRequestHeadType0.HEX
    joint_type: JointClampCapabilityRequestJointTypeType0 | None | Unset = (
        JointClampCapabilityRequestJointTypeType0.THROUGH
    )
    shank_length: float | None | str | Unset = 0.0
    shank_diameter: float | None | str | Unset = UNSET
    reduced_length: float | None | str | Unset = 0.0
    reduced_diameter: float | None | str | Unset = UNSET
    youngs_modulus: float | None | str | Unset = 210000000000.0
    nut_youngs_modulus: float | None | str | Unset = UNSET
    bolt_expansion: float | None | str | Unset = 1.15e-05
    plate1_youngs_modulus: float | None | str | Unset = 210000000000.0
    plate1_expansion: float | None | str | Unset = 1.15e-05
    plate2_thickness: float | None | str | Unset = UNSET
    plate2_youngs_modulus: float | None | str | Unset = UNSET
    plate2_expansion: float | None | str | Unset = UNSET
    plate2_outer_diameter: float | None | str | Unset = UNSET
    plate3_thickness: float | None | str | Unset = UNSET
    plate3_youngs_modulus: float | None | str | Unset = UNSET
    plate3_expansion: float | None | str | Unset = UNSET
    plate3_outer_diameter: float | None | str | Unset = UNSET
    outer_diameter: float | None | str | Unset = UNSET
    load_introduction: float | None | str | Unset = 0.5
    bolt_offset: float | None | str | Unset = 0.0
    load_lever: float | None | str | Unset = 0.0
    opening_edge: float | None | str | Unset = 0.0
    interface_length: float | None | str | Unset = UNSET
    interface_width: float | None | str | Unset = UNSET
    working_load: float | None | str | Unset = 0.0
    working_load_min: float | None | str | Unset = UNSET
    transverse_load: float | None | str | Unset = 0.0
    slip_interfaces: int | None | str | Unset = 1
    fitted_diameter: float | None | str | Unset = UNSET
    torsional_moment: float | None | str | Unset = 0.0
    torque_interfaces: int | None | str | Unset = 1
    friction_radius: float | None | str | Unset = UNSET
    interface_friction: float | None | str | Unset = 0.15
    sealing_clamp_force: float | None | str | Unset = 0.0
    surface_roughness: JointClampCapabilityRequestSurfaceRoughnessType0 | None | Unset = (
        JointClampCapabilityRequestSurfaceRoughnessType0.RZ10_40
    )
    temperature_change: float | None | str | Unset = 0.0
    plate_temperature_change: float | None | str | Unset = UNSET
    bolt_modulus_ratio: float | None | str | Unset = 1.0
    plate_modulus_ratio: float | None | str | Unset = 1.0
    service_temperature: float | None | str | Unset = UNSET
    prevailing_torque: float | None | str | Unset = 0.0
    rolling: JointClampCapabilityRequestRollingType0 | None | Unset = (
        JointClampCapabilityRequestRollingType0.BEFORE_HEAT_TREATMENT
    )
    head_standard: JointClampCapabilityRequestHeadStandardType0 | None | Unset = UNSET
    washer: JointClampCapabilityRequestWasherType0 | None | Unset = UNSET
    nut: JointClampCapabilityRequestNutType0 | None | Unset = UNSET
    clamped_material: JointClampCapabilityRequestClampedMaterialType0 | None | Unset = UNSET
    limiting_surface_pressure: float | None | str | Unset = UNSET
    internal_thread_material: JointClampCapabilityRequestInternalThreadMaterialType0 | None | Unset = UNSET
    internal_thread_shear_strength: float | None | str | Unset = UNSET
    engagement_length: float | None | str | Unset = UNSET
    nut_property_class: JointClampCapabilityRequestNutPropertyClassType0 | None | Unset = UNSET
    nominal_torque: float | None | str | Unset = 80.0
    mean_torque: float | None | str | Unset = UNSET
    torque_sd: float | None | str | Unset = UNSET
    capability_index: float | None | str | Unset = UNSET
    critical_capability_index: float | None | str | Unset = UNSET
    relative_tolerance: float | None | str | Unset = 0.1
    torque_samples: JointClampCapabilityRequestTorqueSamplesType1 | list[float] | None | Unset = UNSET
    thread_friction_law: JointClampCapabilityRequestThreadFrictionLawType0 | None | Unset = (
        JointClampCapabilityRequestThreadFrictionLawType0.UNIFORM
    )
    thread_friction_low: float | None | str | Unset = 0.08
    thread_friction_high: float | None | str | Unset = 0.16
    thread_friction_mean: float | None | str | Unset = UNSET
    thread_friction_sd: float | None | str | Unset = UNSET
    thread_friction_mode: float | None | str | Unset = UNSET
    bearing_friction_law: JointClampCapabilityRequestBearingFrictionLawType0 | None | Unset = (
        JointClampCapabilityRequestBearingFrictionLawType0.UNIFORM
    )
    bearing_friction_low: float | None | str | Unset = 0.08
    bearing_friction_high: float | None | str | Unset = 0.16
    bearing_friction_mean: float | None | str | Unset = UNSET
    bearing_friction_sd: float | None | str | Unset = UNSET
    bearing_friction_mode: float | None | str | Unset = UNSET
    friction_correlation: float | None | str | Unset = 0.0
    allowed_ppm: float | None | str | Unset = 1.0
    category: JointClampCapabilityRequestCategoryType0 | None | Unset = JointClampCapabilityRequestCategoryType0.NONE
    fidelity: JointClampCapabilityRequestFidelityType0 | None | Unset = UNSET
    tolerance: float | None | Unset = UNSET
    outputs: list[JointClampCapabilityRequestOutputsType0Item] | None | Unset = UNSET
    series: bool | Unset = False

    def to_dict(self) -> dict[str, Any]:
        from ..models.joint_clamp_capability_request_torque_samples_type_1 import (
            JointClampCapabilityRequestTorqueSamplesType1,  # noqa: PLC0415
        )

        plate1_thickness: float | str
        plate1_thickness = self.plate1_thickness

        thread = self.thread

        grade = self.grade

        thread_diameter: float | None | str | Unset
        if isinstance(self.thread_diameter, Unset):
            thread_diameter = UNSET
        else:
            thread_diameter = self.thread_diameter

        thread_pitch: float | None | str | Unset
        if isinstance(self.thread_pitch, Unset):
            thread_pitch = UNSET
        else:
            thread_pitch = self.thread_pitch

        property_class: None | str | Unset
        if isinstance(self.property_class, Unset):
            property_class = UNSET
        elif isinstance(self.property_class, JointClampCapabilityRequestPropertyClassType0):
            property_class = self.property_class.value
        else:
            property_class = self.property_class

        yield_strength: float | None | str | Unset
        if isinstance(self.yield_strength, Unset):
            yield_strength = UNSET
        else:
            yield_strength = self.yield_strength

        bearing_outer_diameter: float | None | str | Unset
        if isinstance(self.bearing_outer_diameter, Unset):
            bearing_outer_diameter = UNSET
        else:
            bearing_outer_diameter = self.bearing_outer_diameter

        hole_diameter: float | None | str | Unset
        if isinstance(self.hole_diameter, Unset):
            hole_diameter = UNSET
        else:
            hole_diameter = self.hole_diameter

        hole_series: None | str | Unset
        if isinstance(self.hole_series, Unset):
            hole_series = UNSET
        elif isinstance(self.hole_series, JointClampCapabilityRequestHoleSeriesType0):
            hole_series = self.hole_series.value
        else:
            hole_series = self.hole_series

        utilization: float | None | str | Unset
        if isinstance(self.utilization, Unset):
            utilization = UNSET
        else:
            utilization = self.utilization

        head: None | str | Unset
        if isinstance(self.head, Unset):
            head = UNSET
        elif isinstance(self.head, JointClampCapabilityRequestHeadType0):
            head = self.head.value
        else:
            head = self.head

        joint_type: None | str | Unset
        if isinstance(self.joint_type, Unset):
            joint_type = UNSET
        elif isinstance(self.joint_type, JointClampCapabilityRequestJointTypeType0):
            joint_type = self.joint_type.value
        else:
            joint_type = self.joint_type

        shank_length: float | None | str | Unset
        if isinstance(self.shank_length, Unset):
            shank_length = UNSET
        else:
            shank_length = self.shank_length

        shank_diameter: float | None | str | Unset
        if isinstance(self.shank_diameter, Unset):
            shank_diameter = UNSET
        else:
            shank_diameter = self.shank_diameter

        reduced_length: float | None | str | Unset
        if isinstance(self.reduced_length, Unset):
            reduced_length = UNSET
        else:
            reduced_length = self.reduced_length

        reduced_diameter: float | None | str | Unset
        if isinstance(self.reduced_diameter, Unset):
            reduced_diameter = UNSET
        else:
            reduced_diameter = self.reduced_diameter

        youngs_modulus: float | None | str | Unset
        if isinstance(self.youngs_modulus, Unset):
            youngs_modulus = UNSET
        else:
            youngs_modulus = self.youngs_modulus

        nut_youngs_modulus: float | None | str | Unset
        if isinstance(self.nut_youngs_modulus, Unset):
            nut_youngs_modulus = UNSET
        else:
            nut_youngs_modulus = self.nut_youngs_modulus

        bolt_expansion: float | None | str | Unset
        if isinstance(self.bolt_expansion, Unset):
            bolt_expansion = UNSET
        else:
            bolt_expansion = self.bolt_expansion

        plate1_youngs_modulus: float | None | str | Unset
        if isinstance(self.plate1_youngs_modulus, Unset):
            plate1_youngs_modulus = UNSET
        else:
            plate1_youngs_modulus = self.plate1_youngs_modulus

        plate1_expansion: float | None | str | Unset
        if isinstance(self.plate1_expansion, Unset):
            plate1_expansion = UNSET
        else:
            plate1_expansion = self.plate1_expansion

        plate2_thickness: float | None | str | Unset
        if isinstance(self.plate2_thickness, Unset):
            plate2_thickness = UNSET
        else:
            plate2_thickness = self.plate2_thickness

        plate2_youngs_modulus: float | None | str | Unset
        if isinstance(self.plate2_youngs_modulus, Unset):
            plate2_youngs_modulus = UNSET
        else:
            plate2_youngs_modulus = self.plate2_youngs_modulus

        plate2_expansion: float | None | str | Unset
        if isinstance(self.plate2_expansion, Unset):
            plate2_expansion = UNSET
        else:
            plate2_expansion = self.plate2_expansion

        plate2_outer_diameter: float | None | str | Unset
        if isinstance(self.plate2_outer_diameter, Unset):
            plate2_outer_diameter = UNSET
        else:
            plate2_outer_diameter = self.plate2_outer_diameter

        plate3_thickness: float | None | str | Unset
        if isinstance(self.plate3_thickness, Unset):
            plate3_thickness = UNSET
        else:
            plate3_thickness = self.plate3_thickness

        plate3_youngs_modulus: float | None | str | Unset
        if isinstance(self.plate3_youngs_modulus, Unset):
            plate3_youngs_modulus = UNSET
        else:
            plate3_youngs_modulus = self.plate3_youngs_modulus

        plate3_expansion: float | None | str | Unset
        if isinstance(self.plate3_expansion, Unset):
            plate3_expansion = UNSET
        else:
            plate3_expansion = self.plate3_expansion

        plate3_outer_diameter: float | None | str | Unset
        if isinstance(self.plate3_outer_diameter, Unset):
            plate3_outer_diameter = UNSET
        else:
            plate3_outer_diameter = self.plate3_outer_diameter

        outer_diameter: float | None | str | Unset
        if isinstance(self.outer_diameter, Unset):
            outer_diameter = UNSET
        else:
            outer_diameter = self.outer_diameter

        load_introduction: float | None | str | Unset
        if isinstance(self.load_introduction, Unset):
            load_introduction = UNSET
        else:
            load_introduction = self.load_introduction

        bolt_offset: float | None | str | Unset
        if isinstance(self.bolt_offset, Unset):
            bolt_offset = UNSET
        else:
            bolt_offset = self.bolt_offset

        load_lever: float | None | str | Unset
        if isinstance(self.load_lever, Unset):
            load_lever = UNSET
        else:
            load_lever = self.load_lever

        opening_edge: float | None | str | Unset
        if isinstance(self.opening_edge, Unset):
            opening_edge = UNSET
        else:
            opening_edge = self.opening_edge

        interface_length: float | None | str | Unset
        if isinstance(self.interface_length, Unset):
            interface_length = UNSET
        else:
            interface_length = self.interface_length

        interface_width: float | None | str | Unset
        if isinstance(self.interface_width, Unset):
            interface_width = UNSET
        else:
            interface_width = self.interface_width

        working_load: float | None | str | Unset
        if isinstance(self.working_load, Unset):
            working_load = UNSET
        else:
            working_load = self.working_load

        working_load_min: float | None | str | Unset
        if isinstance(self.working_load_min, Unset):
            working_load_min = UNSET
        else:
            working_load_min = self.working_load_min

        transverse_load: float | None | str | Unset
        if isinstance(self.transverse_load, Unset):
            transverse_load = UNSET
        else:
            transverse_load = self.transverse_load

        slip_interfaces: int | None | str | Unset
        if isinstance(self.slip_interfaces, Unset):
            slip_interfaces = UNSET
        else:
            slip_interfaces = self.slip_interfaces

        fitted_diameter: float | None | str | Unset
        if isinstance(self.fitted_diameter, Unset):
            fitted_diameter = UNSET
        else:
            fitted_diameter = self.fitted_diameter

        torsional_moment: float | None | str | Unset
        if isinstance(self.torsional_moment, Unset):
            torsional_moment = UNSET
        else:
            torsional_moment = self.torsional_moment

        torque_interfaces: int | None | str | Unset
        if isinstance(self.torque_interfaces, Unset):
            torque_interfaces = UNSET
        else:
            torque_interfaces = self.torque_interfaces

        friction_radius: float | None | str | Unset
        if isinstance(self.friction_radius, Unset):
            friction_radius = UNSET
        else:
            friction_radius = self.friction_radius

        interface_friction: float | None | str | Unset
        if isinstance(self.interface_friction, Unset):
            interface_friction = UNSET
        else:
            interface_friction = self.interface_friction

        sealing_clamp_force: float | None | str | Unset
        if isinstance(self.sealing_clamp_force, Unset):
            sealing_clamp_force = UNSET
        else:
            sealing_clamp_force = self.sealing_clamp_force

        surface_roughness: None | str | Unset
        if isinstance(self.surface_roughness, Unset):
            surface_roughness = UNSET
        elif isinstance(self.surface_roughness, JointClampCapabilityRequestSurfaceRoughnessType0):
            surface_roughness = self.surface_roughness.value
        else:
            surface_roughness = self.surface_roughness

        temperature_change: float | None | str | Unset
        if isinstance(self.temperature_change, Unset):
            temperature_change = UNSET
        else:
            temperature_change = self.temperature_change

        plate_temperature_change: float | None | str | Unset
        if isinstance(self.plate_temperature_change, Unset):
            plate_temperature_change = UNSET
        else:
            plate_temperature_change = self.plate_temperature_change

        bolt_modulus_ratio: float | None | str | Unset
        if isinstance(self.bolt_modulus_ratio, Unset):
            bolt_modulus_ratio = UNSET
        else:
            bolt_modulus_ratio = self.bolt_modulus_ratio

        plate_modulus_ratio: float | None | str | Unset
        if isinstance(self.plate_modulus_ratio, Unset):
            plate_modulus_ratio = UNSET
        else:
            plate_modulus_ratio = self.plate_modulus_ratio

        service_temperature: float | None | str | Unset
        if isinstance(self.service_temperature, Unset):
            service_temperature = UNSET
        else:
            service_temperature = self.service_temperature

        prevailing_torque: float | None | str | Unset
        if isinstance(self.prevailing_torque, Unset):
            prevailing_torque = UNSET
        else:
            prevailing_torque = self.prevailing_torque

        rolling: None | str | Unset
        if isinstance(self.rolling, Unset):
            rolling = UNSET
        elif isinstance(self.rolling, JointClampCapabilityRequestRollingType0):
            rolling = self.rolling.value
        else:
            rolling = self.rolling

        head_standard: None | str | Unset
        if isinstance(self.head_standard, Unset):
            head_standard = UNSET
        elif isinstance(self.head_standard, JointClampCapabilityRequestHeadStandardType0):
            head_standard = self.head_standard.value
        else:
            head_standard = self.head_standard

        washer: None | str | Unset
        if isinstance(self.washer, Unset):
            washer = UNSET
        elif isinstance(self.washer, JointClampCapabilityRequestWasherType0):
            washer = self.washer.value
        else:
            washer = self.washer

        nut: None | str | Unset
        if isinstance(self.nut, Unset):
            nut = UNSET
        elif isinstance(self.nut, JointClampCapabilityRequestNutType0):
            nut = self.nut.value
        else:
            nut = self.nut

        clamped_material: None | str | Unset
        if isinstance(self.clamped_material, Unset):
            clamped_material = UNSET
        elif isinstance(self.clamped_material, JointClampCapabilityRequestClampedMaterialType0):
            clamped_material = self.clamped_material.value
        else:
            clamped_material = self.clamped_material

        limiting_surface_pressure: float | None | str | Unset
        if isinstance(self.limiting_surface_pressure, Unset):
            limiting_surface_pressure = UNSET
        else:
            limiting_surface_pressure = self.limiting_surface_pressure

        internal_thread_material: None | str | Unset
        if isinstance(self.internal_thread_material, Unset):
            internal_thread_material = UNSET
        elif isinstance(self.internal_thread_material, JointClampCapabilityRequestInternalThreadMaterialType0):
            internal_thread_material = self.internal_thread_material.value
        else:
            internal_thread_material = self.internal_thread_material

        internal_thread_shear_strength: float | None | str | Unset
        if isinstance(self.internal_thread_shear_strength, Unset):
            internal_thread_shear_strength = UNSET
        else:
            internal_thread_shear_strength = self.internal_thread_shear_strength

        engagement_length: float | None | str | Unset
        if isinstance(self.engagement_length, Unset):
            engagement_length = UNSET
        else:
            engagement_length = self.engagement_length

        nut_property_class: None | str | Unset
        if isinstance(self.nut_property_class, Unset):
            nut_property_class = UNSET
        elif isinstance(self.nut_property_class, JointClampCapabilityRequestNutPropertyClassType0):
            nut_property_class = self.nut_property_class.value
        else:
            nut_property_class = self.nut_property_class

        nominal_torque: float | None | str | Unset
        if isinstance(self.nominal_torque, Unset):
            nominal_torque = UNSET
        else:
            nominal_torque = self.nominal_torque

        mean_torque: float | None | str | Unset
        if isinstance(self.mean_torque, Unset):
            mean_torque = UNSET
        else:
            mean_torque = self.mean_torque

        torque_sd: float | None | str | Unset
        if isinstance(self.torque_sd, Unset):
            torque_sd = UNSET
        else:
            torque_sd = self.torque_sd

        capability_index: float | None | str | Unset
        if isinstance(self.capability_index, Unset):
            capability_index = UNSET
        else:
            capability_index = self.capability_index

        critical_capability_index: float | None | str | Unset
        if isinstance(self.critical_capability_index, Unset):
            critical_capability_index = UNSET
        else:
            critical_capability_index = self.critical_capability_index

        relative_tolerance: float | None | str | Unset
        if isinstance(self.relative_tolerance, Unset):
            relative_tolerance = UNSET
        else:
            relative_tolerance = self.relative_tolerance

        torque_samples: dict[str, Any] | list[float] | None | Unset
        if isinstance(self.torque_samples, Unset):
            torque_samples = UNSET
        elif isinstance(self.torque_samples, list):
            torque_samples = self.torque_samples

        elif isinstance(self.torque_samples, JointClampCapabilityRequestTorqueSamplesType1):
            torque_samples = self.torque_samples.to_dict()
        else:
            torque_samples = self.torque_samples

        thread_friction_law: None | str | Unset
        if isinstance(self.thread_friction_law, Unset):
            thread_friction_law = UNSET
        elif isinstance(self.thread_friction_law, JointClampCapabilityRequestThreadFrictionLawType0):
            thread_friction_law = self.thread_friction_law.value
        else:
            thread_friction_law = self.thread_friction_law

        thread_friction_low: float | None | str | Unset
        if isinstance(self.thread_friction_low, Unset):
            thread_friction_low = UNSET
        else:
            thread_friction_low = self.thread_friction_low

        thread_friction_high: float | None | str | Unset
        if isinstance(self.thread_friction_high, Unset):
            thread_friction_high = UNSET
        else:
            thread_friction_high = self.thread_friction_high

        thread_friction_mean: float | None | str | Unset
        if isinstance(self.thread_friction_mean, Unset):
            thread_friction_mean = UNSET
        else:
            thread_friction_mean = self.thread_friction_mean

        thread_friction_sd: float | None | str | Unset
        if isinstance(self.thread_friction_sd, Unset):
            thread_friction_sd = UNSET
        else:
            thread_friction_sd = self.thread_friction_sd

        thread_friction_mode: float | None | str | Unset
        if isinstance(self.thread_friction_mode, Unset):
            thread_friction_mode = UNSET
        else:
            thread_friction_mode = self.thread_friction_mode

        bearing_friction_law: None | str | Unset
        if isinstance(self.bearing_friction_law, Unset):
            bearing_friction_law = UNSET
        elif isinstance(self.bearing_friction_law, JointClampCapabilityRequestBearingFrictionLawType0):
            bearing_friction_law = self.bearing_friction_law.value
        else:
            bearing_friction_law = self.bearing_friction_law

        bearing_friction_low: float | None | str | Unset
        if isinstance(self.bearing_friction_low, Unset):
            bearing_friction_low = UNSET
        else:
            bearing_friction_low = self.bearing_friction_low

        bearing_friction_high: float | None | str | Unset
        if isinstance(self.bearing_friction_high, Unset):
            bearing_friction_high = UNSET
        else:
            bearing_friction_high = self.bearing_friction_high

        bearing_friction_mean: float | None | str | Unset
        if isinstance(self.bearing_friction_mean, Unset):
            bearing_friction_mean = UNSET
        else:
            bearing_friction_mean = self.bearing_friction_mean

        bearing_friction_sd: float | None | str | Unset
        if isinstance(self.bearing_friction_sd, Unset):
            bearing_friction_sd = UNSET
        else:
            bearing_friction_sd = self.bearing_friction_sd

        bearing_friction_mode: float | None | str | Unset
        if isinstance(self.bearing_friction_mode, Unset):
            bearing_friction_mode = UNSET
        else:
            bearing_friction_mode = self.bearing_friction_mode

        friction_correlation: float | None | str | Unset
        if isinstance(self.friction_correlation, Unset):
            friction_correlation = UNSET
        else:
            friction_correlation = self.friction_correlation

        allowed_ppm: float | None | str | Unset
        if isinstance(self.allowed_ppm, Unset):
            allowed_ppm = UNSET
        else:
            allowed_ppm = self.allowed_ppm

        category: None | str | Unset
        if isinstance(self.category, Unset):
            category = UNSET
        elif isinstance(self.category, JointClampCapabilityRequestCategoryType0):
            category = self.category.value
        else:
            category = self.category

        fidelity: None | str | Unset
        if isinstance(self.fidelity, Unset):
            fidelity = UNSET
        elif isinstance(self.fidelity, JointClampCapabilityRequestFidelityType0):
            fidelity = self.fidelity.value
        else:
            fidelity = self.fidelity

        tolerance: float | None | Unset
        if isinstance(self.tolerance, Unset):
            tolerance = UNSET
        else:
            tolerance = self.tolerance

        outputs: list[str] | None | Unset
        if isinstance(self.outputs, Unset):
            outputs = UNSET
        elif isinstance(self.outputs, list):
            outputs = []
            for outputs_type_0_item_data in self.outputs:
                outputs_type_0_item = outputs_type_0_item_data.value
                outputs.append(outputs_type_0_item)

        else:
            outputs = self.outputs

        series = self.series

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "plate1_thickness": plate1_thickness,
            }
        )
        if thread is not UNSET:
            field_dict["thread"] = thread
        if grade is not UNSET:
            field_dict["grade"] = grade
        if thread_diameter is not UNSET:
            field_dict["thread_diameter"] = thread_diameter
        if thread_pitch is not UNSET:
            field_dict["thread_pitch"] = thread_pitch
        if property_class is not UNSET:
            field_dict["property_class"] = property_class
        if yield_strength is not UNSET:
            field_dict["yield_strength"] = yield_strength
        if bearing_outer_diameter is not UNSET:
            field_dict["bearing_outer_diameter"] = bearing_outer_diameter
        if hole_diameter is not UNSET:
            field_dict["hole_diameter"] = hole_diameter
        if hole_series is not UNSET:
            field_dict["hole_series"] = hole_series
        if utilization is not UNSET:
            field_dict["utilization"] = utilization
        if head is not UNSET:
            field_dict["head"] = head
        if joint_type is not UNSET:
            field_dict["joint_type"] = joint_type
        if shank_length is not UNSET:
            field_dict["shank_length"] = shank_length
        if shank_diameter is not UNSET:
            field_dict["shank_diameter"] = shank_diameter
        if reduced_length is not UNSET:
            field_dict["reduced_length"] = reduced_length
        if reduced_diameter is not UNSET:
            field_dict["reduced_diameter"] = reduced_diameter
        if youngs_modulus is not UNSET:
            field_dict["youngs_modulus"] = youngs_modulus
        if nut_youngs_modulus is not UNSET:
            field_dict["nut_youngs_modulus"] = nut_youngs_modulus
        if bolt_expansion is not UNSET:
            field_dict["bolt_expansion"] = bolt_expansion
        if plate1_youngs_modulus is not UNSET:
            field_dict["plate1_youngs_modulus"] = plate1_youngs_modulus
        if plate1_expansion is not UNSET:
            field_dict["plate1_expansion"] = plate1_expansion
        if plate2_thickness is not UNSET:
            field_dict["plate2_thickness"] = plate2_thickness
        if plate2_youngs_modulus is not UNSET:
            field_dict["plate2_youngs_modulus"] = plate2_youngs_modulus
        if plate2_expansion is not UNSET:
            field_dict["plate2_expansion"] = plate2_expansion
        if plate2_outer_diameter is not UNSET:
            field_dict["plate2_outer_diameter"] = plate2_outer_diameter
        if plate3_thickness is not UNSET:
            field_dict["plate3_thickness"] = plate3_thickness
        if plate3_youngs_modulus is not UNSET:
            field_dict["plate3_youngs_modulus"] = plate3_youngs_modulus
        if plate3_expansion is not UNSET:
            field_dict["plate3_expansion"] = plate3_expansion
        if plate3_outer_diameter is not UNSET:
            field_dict["plate3_outer_diameter"] = plate3_outer_diameter
        if outer_diameter is not UNSET:
            field_dict["outer_diameter"] = outer_diameter
        if load_introduction is not UNSET:
            field_dict["load_introduction"] = load_introduction
        if bolt_offset is not UNSET:
            field_dict["bolt_offset"] = bolt_offset
        if load_lever is not UNSET:
            field_dict["load_lever"] = load_lever
        if opening_edge is not UNSET:
            field_dict["opening_edge"] = opening_edge
        if interface_length is not UNSET:
            field_dict["interface_length"] = interface_length
        if interface_width is not UNSET:
            field_dict["interface_width"] = interface_width
        if working_load is not UNSET:
            field_dict["working_load"] = working_load
        if working_load_min is not UNSET:
            field_dict["working_load_min"] = working_load_min
        if transverse_load is not UNSET:
            field_dict["transverse_load"] = transverse_load
        if slip_interfaces is not UNSET:
            field_dict["slip_interfaces"] = slip_interfaces
        if fitted_diameter is not UNSET:
            field_dict["fitted_diameter"] = fitted_diameter
        if torsional_moment is not UNSET:
            field_dict["torsional_moment"] = torsional_moment
        if torque_interfaces is not UNSET:
            field_dict["torque_interfaces"] = torque_interfaces
        if friction_radius is not UNSET:
            field_dict["friction_radius"] = friction_radius
        if interface_friction is not UNSET:
            field_dict["interface_friction"] = interface_friction
        if sealing_clamp_force is not UNSET:
            field_dict["sealing_clamp_force"] = sealing_clamp_force
        if surface_roughness is not UNSET:
            field_dict["surface_roughness"] = surface_roughness
        if temperature_change is not UNSET:
            field_dict["temperature_change"] = temperature_change
        if plate_temperature_change is not UNSET:
            field_dict["plate_temperature_change"] = plate_temperature_change
        if bolt_modulus_ratio is not UNSET:
            field_dict["bolt_modulus_ratio"] = bolt_modulus_ratio
        if plate_modulus_ratio is not UNSET:
            field_dict["plate_modulus_ratio"] = plate_modulus_ratio
        if service_temperature is not UNSET:
            field_dict["service_temperature"] = service_temperature
        if prevailing_torque is not UNSET:
            field_dict["prevailing_torque"] = prevailing_torque
        if rolling is not UNSET:
            field_dict["rolling"] = rolling
        if head_standard is not UNSET:
            field_dict["head_standard"] = head_standard
        if washer is not UNSET:
            field_dict["washer"] = washer
        if nut is not UNSET:
            field_dict["nut"] = nut
        if clamped_material is not UNSET:
            field_dict["clamped_material"] = clamped_material
        if limiting_surface_pressure is not UNSET:
            field_dict["limiting_surface_pressure"] = limiting_surface_pressure
        if internal_thread_material is not UNSET:
            field_dict["internal_thread_material"] = internal_thread_material
        if internal_thread_shear_strength is not UNSET:
            field_dict["internal_thread_shear_strength"] = internal_thread_shear_strength
        if engagement_length is not UNSET:
            field_dict["engagement_length"] = engagement_length
        if nut_property_class is not UNSET:
            field_dict["nut_property_class"] = nut_property_class
        if nominal_torque is not UNSET:
            field_dict["nominal_torque"] = nominal_torque
        if mean_torque is not UNSET:
            field_dict["mean_torque"] = mean_torque
        if torque_sd is not UNSET:
            field_dict["torque_sd"] = torque_sd
        if capability_index is not UNSET:
            field_dict["capability_index"] = capability_index
        if critical_capability_index is not UNSET:
            field_dict["critical_capability_index"] = critical_capability_index
        if relative_tolerance is not UNSET:
            field_dict["relative_tolerance"] = relative_tolerance
        if torque_samples is not UNSET:
            field_dict["torque_samples"] = torque_samples
        if thread_friction_law is not UNSET:
            field_dict["thread_friction_law"] = thread_friction_law
        if thread_friction_low is not UNSET:
            field_dict["thread_friction_low"] = thread_friction_low
        if thread_friction_high is not UNSET:
            field_dict["thread_friction_high"] = thread_friction_high
        if thread_friction_mean is not UNSET:
            field_dict["thread_friction_mean"] = thread_friction_mean
        if thread_friction_sd is not UNSET:
            field_dict["thread_friction_sd"] = thread_friction_sd
        if thread_friction_mode is not UNSET:
            field_dict["thread_friction_mode"] = thread_friction_mode
        if bearing_friction_law is not UNSET:
            field_dict["bearing_friction_law"] = bearing_friction_law
        if bearing_friction_low is not UNSET:
            field_dict["bearing_friction_low"] = bearing_friction_low
        if bearing_friction_high is not UNSET:
            field_dict["bearing_friction_high"] = bearing_friction_high
        if bearing_friction_mean is not UNSET:
            field_dict["bearing_friction_mean"] = bearing_friction_mean
        if bearing_friction_sd is not UNSET:
            field_dict["bearing_friction_sd"] = bearing_friction_sd
        if bearing_friction_mode is not UNSET:
            field_dict["bearing_friction_mode"] = bearing_friction_mode
        if friction_correlation is not UNSET:
            field_dict["friction_correlation"] = friction_correlation
        if allowed_ppm is not UNSET:
            field_dict["allowed_ppm"] = allowed_ppm
        if category is not UNSET:
            field_dict["category"] = category
        if fidelity is not UNSET:
            field_dict["fidelity"] = fidelity
        if tolerance is not UNSET:
            field_dict["tolerance"] = tolerance
        if outputs is not UNSET:
            field_dict["outputs"] = outputs
        if series is not UNSET:
            field_dict["series"] = series

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_clamp_capability_request_torque_samples_type_1 import (
            JointClampCapabilityRequestTorqueSamplesType1,  # noqa: PLC0415
        )

        d = dict(src_dict)

        def _parse_plate1_thickness(data: object) -> float | str:
            return cast(float | str, data)

        plate1_thickness = _parse_plate1_thickness(d.pop("plate1_thickness"))

        thread = d.pop("thread", UNSET)

        grade = d.pop("grade", UNSET)

        def _parse_thread_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        thread_diameter = _parse_thread_diameter(d.pop("thread_diameter", UNSET))

        def _parse_thread_pitch(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        thread_pitch = _parse_thread_pitch(d.pop("thread_pitch", UNSET))

        def _parse_property_class(data: object) -> JointClampCapabilityRequestPropertyClassType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                property_class_type_0 = JointClampCapabilityRequestPropertyClassType0(data)

                return property_class_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestPropertyClassType0 | None | Unset, data)

        property_class = _parse_property_class(d.pop("property_class", UNSET))

        def _parse_yield_strength(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        yield_strength = _parse_yield_strength(d.pop("yield_strength", UNSET))

        def _parse_bearing_outer_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bearing_outer_diameter = _parse_bearing_outer_diameter(d.pop("bearing_outer_diameter", UNSET))

        def _parse_hole_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        hole_diameter = _parse_hole_diameter(d.pop("hole_diameter", UNSET))

        def _parse_hole_series(data: object) -> JointClampCapabilityRequestHoleSeriesType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                hole_series_type_0 = JointClampCapabilityRequestHoleSeriesType0(data)

                return hole_series_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestHoleSeriesType0 | None | Unset, data)

        hole_series = _parse_hole_series(d.pop("hole_series", UNSET))

        def _parse_utilization(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        utilization = _parse_utilization(d.pop("utilization", UNSET))

        def _parse_head(data: object) -> JointClampCapabilityRequestHeadType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                head_type_0 = JointClampCapabilityRequestHeadType0(data)

                return head_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestHeadType0 | None | Unset, data)

        head = _parse_head(d.pop("head", UNSET))

        def _parse_joint_type(data: object) -> JointClampCapabilityRequestJointTypeType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                joint_type_type_0 = JointClampCapabilityRequestJointTypeType0(data)

                return joint_type_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestJointTypeType0 | None | Unset, data)

        joint_type = _parse_joint_type(d.pop("joint_type", UNSET))

        def _parse_shank_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        shank_length = _parse_shank_length(d.pop("shank_length", UNSET))

        def _parse_shank_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        shank_diameter = _parse_shank_diameter(d.pop("shank_diameter", UNSET))

        def _parse_reduced_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        reduced_length = _parse_reduced_length(d.pop("reduced_length", UNSET))

        def _parse_reduced_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        reduced_diameter = _parse_reduced_diameter(d.pop("reduced_diameter", UNSET))

        def _parse_youngs_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        youngs_modulus = _parse_youngs_modulus(d.pop("youngs_modulus", UNSET))

        def _parse_nut_youngs_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        nut_youngs_modulus = _parse_nut_youngs_modulus(d.pop("nut_youngs_modulus", UNSET))

        def _parse_bolt_expansion(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bolt_expansion = _parse_bolt_expansion(d.pop("bolt_expansion", UNSET))

        def _parse_plate1_youngs_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate1_youngs_modulus = _parse_plate1_youngs_modulus(d.pop("plate1_youngs_modulus", UNSET))

        def _parse_plate1_expansion(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate1_expansion = _parse_plate1_expansion(d.pop("plate1_expansion", UNSET))

        def _parse_plate2_thickness(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate2_thickness = _parse_plate2_thickness(d.pop("plate2_thickness", UNSET))

        def _parse_plate2_youngs_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate2_youngs_modulus = _parse_plate2_youngs_modulus(d.pop("plate2_youngs_modulus", UNSET))

        def _parse_plate2_expansion(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate2_expansion = _parse_plate2_expansion(d.pop("plate2_expansion", UNSET))

        def _parse_plate2_outer_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate2_outer_diameter = _parse_plate2_outer_diameter(d.pop("plate2_outer_diameter", UNSET))

        def _parse_plate3_thickness(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate3_thickness = _parse_plate3_thickness(d.pop("plate3_thickness", UNSET))

        def _parse_plate3_youngs_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate3_youngs_modulus = _parse_plate3_youngs_modulus(d.pop("plate3_youngs_modulus", UNSET))

        def _parse_plate3_expansion(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate3_expansion = _parse_plate3_expansion(d.pop("plate3_expansion", UNSET))

        def _parse_plate3_outer_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate3_outer_diameter = _parse_plate3_outer_diameter(d.pop("plate3_outer_diameter", UNSET))

        def _parse_outer_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        outer_diameter = _parse_outer_diameter(d.pop("outer_diameter", UNSET))

        def _parse_load_introduction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        load_introduction = _parse_load_introduction(d.pop("load_introduction", UNSET))

        def _parse_bolt_offset(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bolt_offset = _parse_bolt_offset(d.pop("bolt_offset", UNSET))

        def _parse_load_lever(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        load_lever = _parse_load_lever(d.pop("load_lever", UNSET))

        def _parse_opening_edge(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        opening_edge = _parse_opening_edge(d.pop("opening_edge", UNSET))

        def _parse_interface_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        interface_length = _parse_interface_length(d.pop("interface_length", UNSET))

        def _parse_interface_width(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        interface_width = _parse_interface_width(d.pop("interface_width", UNSET))

        def _parse_working_load(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        working_load = _parse_working_load(d.pop("working_load", UNSET))

        def _parse_working_load_min(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        working_load_min = _parse_working_load_min(d.pop("working_load_min", UNSET))

        def _parse_transverse_load(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        transverse_load = _parse_transverse_load(d.pop("transverse_load", UNSET))

        def _parse_slip_interfaces(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        slip_interfaces = _parse_slip_interfaces(d.pop("slip_interfaces", UNSET))

        def _parse_fitted_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        fitted_diameter = _parse_fitted_diameter(d.pop("fitted_diameter", UNSET))

        def _parse_torsional_moment(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        torsional_moment = _parse_torsional_moment(d.pop("torsional_moment", UNSET))

        def _parse_torque_interfaces(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        torque_interfaces = _parse_torque_interfaces(d.pop("torque_interfaces", UNSET))

        def _parse_friction_radius(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        friction_radius = _parse_friction_radius(d.pop("friction_radius", UNSET))

        def _parse_interface_friction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        interface_friction = _parse_interface_friction(d.pop("interface_friction", UNSET))

        def _parse_sealing_clamp_force(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        sealing_clamp_force = _parse_sealing_clamp_force(d.pop("sealing_clamp_force", UNSET))

        def _parse_surface_roughness(data: object) -> JointClampCapabilityRequestSurfaceRoughnessType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                surface_roughness_type_0 = JointClampCapabilityRequestSurfaceRoughnessType0(data)

                return surface_roughness_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestSurfaceRoughnessType0 | None | Unset, data)

        surface_roughness = _parse_surface_roughness(d.pop("surface_roughness", UNSET))

        def _parse_temperature_change(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        temperature_change = _parse_temperature_change(d.pop("temperature_change", UNSET))

        def _parse_plate_temperature_change(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate_temperature_change = _parse_plate_temperature_change(d.pop("plate_temperature_change", UNSET))

        def _parse_bolt_modulus_ratio(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bolt_modulus_ratio = _parse_bolt_modulus_ratio(d.pop("bolt_modulus_ratio", UNSET))

        def _parse_plate_modulus_ratio(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate_modulus_ratio = _parse_plate_modulus_ratio(d.pop("plate_modulus_ratio", UNSET))

        def _parse_service_temperature(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        service_temperature = _parse_service_temperature(d.pop("service_temperature", UNSET))

        def _parse_prevailing_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        prevailing_torque = _parse_prevailing_torque(d.pop("prevailing_torque", UNSET))

        def _parse_rolling(data: object) -> JointClampCapabilityRequestRollingType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                rolling_type_0 = JointClampCapabilityRequestRollingType0(data)

                return rolling_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestRollingType0 | None | Unset, data)

        rolling = _parse_rolling(d.pop("rolling", UNSET))

        def _parse_head_standard(data: object) -> JointClampCapabilityRequestHeadStandardType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                head_standard_type_0 = JointClampCapabilityRequestHeadStandardType0(data)

                return head_standard_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestHeadStandardType0 | None | Unset, data)

        head_standard = _parse_head_standard(d.pop("head_standard", UNSET))

        def _parse_washer(data: object) -> JointClampCapabilityRequestWasherType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                washer_type_0 = JointClampCapabilityRequestWasherType0(data)

                return washer_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestWasherType0 | None | Unset, data)

        washer = _parse_washer(d.pop("washer", UNSET))

        def _parse_nut(data: object) -> JointClampCapabilityRequestNutType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                nut_type_0 = JointClampCapabilityRequestNutType0(data)

                return nut_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestNutType0 | None | Unset, data)

        nut = _parse_nut(d.pop("nut", UNSET))

        def _parse_clamped_material(data: object) -> JointClampCapabilityRequestClampedMaterialType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                clamped_material_type_0 = JointClampCapabilityRequestClampedMaterialType0(data)

                return clamped_material_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestClampedMaterialType0 | None | Unset, data)

        clamped_material = _parse_clamped_material(d.pop("clamped_material", UNSET))

        def _parse_limiting_surface_pressure(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        limiting_surface_pressure = _parse_limiting_surface_pressure(d.pop("limiting_surface_pressure", UNSET))

        def _parse_internal_thread_material(
            data: object,
        ) -> JointClampCapabilityRequestInternalThreadMaterialType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                internal_thread_material_type_0 = JointClampCapabilityRequestInternalThreadMaterialType0(data)

                return internal_thread_material_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestInternalThreadMaterialType0 | None | Unset, data)

        internal_thread_material = _parse_internal_thread_material(d.pop("internal_thread_material", UNSET))

        def _parse_internal_thread_shear_strength(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        internal_thread_shear_strength = _parse_internal_thread_shear_strength(
            d.pop("internal_thread_shear_strength", UNSET)
        )

        def _parse_engagement_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        engagement_length = _parse_engagement_length(d.pop("engagement_length", UNSET))

        def _parse_nut_property_class(data: object) -> JointClampCapabilityRequestNutPropertyClassType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                nut_property_class_type_0 = JointClampCapabilityRequestNutPropertyClassType0(data)

                return nut_property_class_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestNutPropertyClassType0 | None | Unset, data)

        nut_property_class = _parse_nut_property_class(d.pop("nut_property_class", UNSET))

        def _parse_nominal_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        nominal_torque = _parse_nominal_torque(d.pop("nominal_torque", UNSET))

        def _parse_mean_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        mean_torque = _parse_mean_torque(d.pop("mean_torque", UNSET))

        def _parse_torque_sd(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        torque_sd = _parse_torque_sd(d.pop("torque_sd", UNSET))

        def _parse_capability_index(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        capability_index = _parse_capability_index(d.pop("capability_index", UNSET))

        def _parse_critical_capability_index(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        critical_capability_index = _parse_critical_capability_index(d.pop("critical_capability_index", UNSET))

        def _parse_relative_tolerance(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        relative_tolerance = _parse_relative_tolerance(d.pop("relative_tolerance", UNSET))

        def _parse_torque_samples(
            data: object,
        ) -> JointClampCapabilityRequestTorqueSamplesType1 | list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                torque_samples_type_0 = cast(list[float], data)

                return torque_samples_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                torque_samples_type_1 = JointClampCapabilityRequestTorqueSamplesType1.from_dict(data)

                return torque_samples_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestTorqueSamplesType1 | list[float] | None | Unset, data)

        torque_samples = _parse_torque_samples(d.pop("torque_samples", UNSET))

        def _parse_thread_friction_law(
            data: object,
        ) -> JointClampCapabilityRequestThreadFrictionLawType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                thread_friction_law_type_0 = JointClampCapabilityRequestThreadFrictionLawType0(data)

                return thread_friction_law_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestThreadFrictionLawType0 | None | Unset, data)

        thread_friction_law = _parse_thread_friction_law(d.pop("thread_friction_law", UNSET))

        def _parse_thread_friction_low(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        thread_friction_low = _parse_thread_friction_low(d.pop("thread_friction_low", UNSET))

        def _parse_thread_friction_high(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        thread_friction_high = _parse_thread_friction_high(d.pop("thread_friction_high", UNSET))

        def _parse_thread_friction_mean(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        thread_friction_mean = _parse_thread_friction_mean(d.pop("thread_friction_mean", UNSET))

        def _parse_thread_friction_sd(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        thread_friction_sd = _parse_thread_friction_sd(d.pop("thread_friction_sd", UNSET))

        def _parse_thread_friction_mode(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        thread_friction_mode = _parse_thread_friction_mode(d.pop("thread_friction_mode", UNSET))

        def _parse_bearing_friction_law(
            data: object,
        ) -> JointClampCapabilityRequestBearingFrictionLawType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                bearing_friction_law_type_0 = JointClampCapabilityRequestBearingFrictionLawType0(data)

                return bearing_friction_law_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestBearingFrictionLawType0 | None | Unset, data)

        bearing_friction_law = _parse_bearing_friction_law(d.pop("bearing_friction_law", UNSET))

        def _parse_bearing_friction_low(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bearing_friction_low = _parse_bearing_friction_low(d.pop("bearing_friction_low", UNSET))

        def _parse_bearing_friction_high(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bearing_friction_high = _parse_bearing_friction_high(d.pop("bearing_friction_high", UNSET))

        def _parse_bearing_friction_mean(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bearing_friction_mean = _parse_bearing_friction_mean(d.pop("bearing_friction_mean", UNSET))

        def _parse_bearing_friction_sd(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bearing_friction_sd = _parse_bearing_friction_sd(d.pop("bearing_friction_sd", UNSET))

        def _parse_bearing_friction_mode(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bearing_friction_mode = _parse_bearing_friction_mode(d.pop("bearing_friction_mode", UNSET))

        def _parse_friction_correlation(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        friction_correlation = _parse_friction_correlation(d.pop("friction_correlation", UNSET))

        def _parse_allowed_ppm(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        allowed_ppm = _parse_allowed_ppm(d.pop("allowed_ppm", UNSET))

        def _parse_category(data: object) -> JointClampCapabilityRequestCategoryType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                category_type_0 = JointClampCapabilityRequestCategoryType0(data)

                return category_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestCategoryType0 | None | Unset, data)

        category = _parse_category(d.pop("category", UNSET))

        def _parse_fidelity(data: object) -> JointClampCapabilityRequestFidelityType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                fidelity_type_0 = JointClampCapabilityRequestFidelityType0(data)

                return fidelity_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointClampCapabilityRequestFidelityType0 | None | Unset, data)

        fidelity = _parse_fidelity(d.pop("fidelity", UNSET))

        def _parse_tolerance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tolerance = _parse_tolerance(d.pop("tolerance", UNSET))

        def _parse_outputs(data: object) -> list[JointClampCapabilityRequestOutputsType0Item] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                outputs_type_0 = []
                _outputs_type_0 = data
                for outputs_type_0_item_data in _outputs_type_0:
                    outputs_type_0_item = JointClampCapabilityRequestOutputsType0Item(outputs_type_0_item_data)

                    outputs_type_0.append(outputs_type_0_item)

                return outputs_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[JointClampCapabilityRequestOutputsType0Item] | None | Unset, data)

        outputs = _parse_outputs(d.pop("outputs", UNSET))

        series = d.pop("series", UNSET)

        joint_clamp_capability_request = cls(
            plate1_thickness=plate1_thickness,
            thread=thread,
            grade=grade,
            thread_diameter=thread_diameter,
            thread_pitch=thread_pitch,
            property_class=property_class,
            yield_strength=yield_strength,
            bearing_outer_diameter=bearing_outer_diameter,
            hole_diameter=hole_diameter,
            hole_series=hole_series,
            utilization=utilization,
            head=head,
            joint_type=joint_type,
            shank_length=shank_length,
            shank_diameter=shank_diameter,
            reduced_length=reduced_length,
            reduced_diameter=reduced_diameter,
            youngs_modulus=youngs_modulus,
            nut_youngs_modulus=nut_youngs_modulus,
            bolt_expansion=bolt_expansion,
            plate1_youngs_modulus=plate1_youngs_modulus,
            plate1_expansion=plate1_expansion,
            plate2_thickness=plate2_thickness,
            plate2_youngs_modulus=plate2_youngs_modulus,
            plate2_expansion=plate2_expansion,
            plate2_outer_diameter=plate2_outer_diameter,
            plate3_thickness=plate3_thickness,
            plate3_youngs_modulus=plate3_youngs_modulus,
            plate3_expansion=plate3_expansion,
            plate3_outer_diameter=plate3_outer_diameter,
            outer_diameter=outer_diameter,
            load_introduction=load_introduction,
            bolt_offset=bolt_offset,
            load_lever=load_lever,
            opening_edge=opening_edge,
            interface_length=interface_length,
            interface_width=interface_width,
            working_load=working_load,
            working_load_min=working_load_min,
            transverse_load=transverse_load,
            slip_interfaces=slip_interfaces,
            fitted_diameter=fitted_diameter,
            torsional_moment=torsional_moment,
            torque_interfaces=torque_interfaces,
            friction_radius=friction_radius,
            interface_friction=interface_friction,
            sealing_clamp_force=sealing_clamp_force,
            surface_roughness=surface_roughness,
            temperature_change=temperature_change,
            plate_temperature_change=plate_temperature_change,
            bolt_modulus_ratio=bolt_modulus_ratio,
            plate_modulus_ratio=plate_modulus_ratio,
            service_temperature=service_temperature,
            prevailing_torque=prevailing_torque,
            rolling=rolling,
            head_standard=head_standard,
            washer=washer,
            nut=nut,
            clamped_material=clamped_material,
            limiting_surface_pressure=limiting_surface_pressure,
            internal_thread_material=internal_thread_material,
            internal_thread_shear_strength=internal_thread_shear_strength,
            engagement_length=engagement_length,
            nut_property_class=nut_property_class,
            nominal_torque=nominal_torque,
            mean_torque=mean_torque,
            torque_sd=torque_sd,
            capability_index=capability_index,
            critical_capability_index=critical_capability_index,
            relative_tolerance=relative_tolerance,
            torque_samples=torque_samples,
            thread_friction_law=thread_friction_law,
            thread_friction_low=thread_friction_low,
            thread_friction_high=thread_friction_high,
            thread_friction_mean=thread_friction_mean,
            thread_friction_sd=thread_friction_sd,
            thread_friction_mode=thread_friction_mode,
            bearing_friction_law=bearing_friction_law,
            bearing_friction_low=bearing_friction_low,
            bearing_friction_high=bearing_friction_high,
            bearing_friction_mean=bearing_friction_mean,
            bearing_friction_sd=bearing_friction_sd,
            bearing_friction_mode=bearing_friction_mode,
            friction_correlation=friction_correlation,
            allowed_ppm=allowed_ppm,
            category=category,
            fidelity=fidelity,
            tolerance=tolerance,
            outputs=outputs,
            series=series,
        )

        return joint_clamp_capability_request
