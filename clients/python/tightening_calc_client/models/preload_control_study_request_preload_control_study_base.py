from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.preload_control_study_request_preload_control_study_base_clamped_material_type_0 import (
    PreloadControlStudyRequestPreloadControlStudyBaseClampedMaterialType0,
)
from ..models.preload_control_study_request_preload_control_study_base_head_standard_type_0 import (
    PreloadControlStudyRequestPreloadControlStudyBaseHeadStandardType0,
)
from ..models.preload_control_study_request_preload_control_study_base_hole_series_type_0 import (
    PreloadControlStudyRequestPreloadControlStudyBaseHoleSeriesType0,
)
from ..models.preload_control_study_request_preload_control_study_base_internal_thread_material_type_0 import (
    PreloadControlStudyRequestPreloadControlStudyBaseInternalThreadMaterialType0,
)
from ..models.preload_control_study_request_preload_control_study_base_load_type_type_0 import (
    PreloadControlStudyRequestPreloadControlStudyBaseLoadTypeType0,
)
from ..models.preload_control_study_request_preload_control_study_base_method_type_0 import (
    PreloadControlStudyRequestPreloadControlStudyBaseMethodType0,
)
from ..models.preload_control_study_request_preload_control_study_base_nut_property_class_type_0 import (
    PreloadControlStudyRequestPreloadControlStudyBaseNutPropertyClassType0,
)
from ..models.preload_control_study_request_preload_control_study_base_nut_type_0 import (
    PreloadControlStudyRequestPreloadControlStudyBaseNutType0,
)
from ..models.preload_control_study_request_preload_control_study_base_preload_convention_type_0 import (
    PreloadControlStudyRequestPreloadControlStudyBasePreloadConventionType0,
)
from ..models.preload_control_study_request_preload_control_study_base_property_class_type_0 import (
    PreloadControlStudyRequestPreloadControlStudyBasePropertyClassType0,
)
from ..models.preload_control_study_request_preload_control_study_base_torque_formula_type_0 import (
    PreloadControlStudyRequestPreloadControlStudyBaseTorqueFormulaType0,
)
from ..models.preload_control_study_request_preload_control_study_base_washer_type_0 import (
    PreloadControlStudyRequestPreloadControlStudyBaseWasherType0,
)
from ..types import UNSET, Unset

T = TypeVar("T", bound="PreloadControlStudyRequestPreloadControlStudyBase")


@_attrs_define
class PreloadControlStudyRequestPreloadControlStudyBase:
    """inputs held fixed (defaults fill the rest)

    Attributes:
        thread (str | Unset): Designation instead of thread_diameter: 'M12', 'M12x1.25', 'M10 ISO 4762 12.9', '1/2-13
            UNC', '1/2-13 UNC Grade 5' (ISO M1.6…M64 coarse and fine, UNC/UNF 1/4…1-1/2; GET /api/v1/fasteners lists them).
            A head standard or grade in it sets head_standard and grade
        grade (str | Unset): Bolt grade, overriding property_class: ISO 898-1 (8.8…12.9), ISO 3506-1 (A2-70, A4-70,
            A4-80), SAE J429 ('SAE 5', 'Grade 8'), ASTM A193 'B7'
        thread_diameter (float | None | str | Unset): Nominal thread diameter d, when no thread designation is given
            (ISO 261 M3…M39 have tabulated data; other sizes need thread_pitch, bearing_outer_diameter, hole_diameter and
            yield_strength)
        thread_pitch (float | None | str | Unset): Thread pitch P; ISO 261 coarse pitch when absent
        property_class (None | PreloadControlStudyRequestPreloadControlStudyBasePropertyClassType0 | Unset): ISO 898-1
            property class: minimum yield and tensile strength (8.8: 640/800 MPa up to M16, 660/830 MPa above) Default:
            PreloadControlStudyRequestPreloadControlStudyBasePropertyClassType0.VALUE_5.
        yield_strength (float | None | str | Unset): Minimum yield strength R_p0.2 (σ_T in [004]); overrides the
            property class
        thread_friction (float | None | str | Unset): Thread friction coefficient μ_G (f_p in [004]) Default: 0.12.
        bearing_friction (float | None | str | Unset): Bearing-face friction coefficient μ_K (f_T in [004]) Default:
            0.12.
        bearing_outer_diameter (float | None | str | Unset): Outer diameter D_f of the bearing face; ISO 4017 hexagon
            head d_w,min when absent
        hole_diameter (float | None | str | Unset): Clearance-hole diameter d_h (inner diameter of the bearing face);
            ISO 273 of hole_series when absent
        hole_series (None | PreloadControlStudyRequestPreloadControlStudyBaseHoleSeriesType0 | Unset): ISO 273
            clearance-hole series used when hole_diameter is absent Default:
            PreloadControlStudyRequestPreloadControlStudyBaseHoleSeriesType0.MEDIUM.
        utilization (float | None | str | Unset): ν: share of the yield strength the equivalent stress may use at
            assembly (VDI 2230: 0.9; [004, eq. 3]: ξ/n_T, 0.71…0.83) Default: 0.9.
        preload_convention (None | PreloadControlStudyRequestPreloadControlStudyBasePreloadConventionType0 | Unset):
            'vdi2230': β of VDI 2230 step R7 (plastic torsion, factor 3/2); 'elastic': β of [004, eq. 5] with τ/σ =
            2(d2/d0)·tan(ψ+ρ') Default: PreloadControlStudyRequestPreloadControlStudyBasePreloadConventionType0.VDI2230.
        torque_formula (None | PreloadControlStudyRequestPreloadControlStudyBaseTorqueFormulaType0 | Unset): 'vdi2230':
            M_A = F(0.16P + 0.58 d2 μ_G + μ_K D_Km/2); 'exact': [004, eq. 10–13] with the annular friction radius; 'approx':
            [004, eq. 15/19] with d2 ≈ d Default:
            PreloadControlStudyRequestPreloadControlStudyBaseTorqueFormulaType0.VDI2230.
        preload (float | None | str | Unset): Nominal preload (middle of the method's band); when absent the band's top
            is the permissible preload (yield control: the preload at yield)
        head_standard (None | PreloadControlStudyRequestPreloadControlStudyBaseHeadStandardType0 | Unset): Head standard
            (bearing diameter d_w, drive): hexagon ISO 4017/4014 when absent (ASME B18.2.1 hex for inch threads)
        washer (None | PreloadControlStudyRequestPreloadControlStudyBaseWasherType0 | Unset): Plain washer under the
            head (spreads the pressure on the clamped part)
        nut (None | PreloadControlStudyRequestPreloadControlStudyBaseNutType0 | Unset): Hexagon nut (a through-bolted
            joint: surface pressure under the nut); absent: tapped
        clamped_material (None | PreloadControlStudyRequestPreloadControlStudyBaseClampedMaterialType0 | Unset):
            Material under the head and nut: its limiting surface pressure p_G (VDI 2230-1 Table A9; plastics: compressive
            yield)
        limiting_surface_pressure (float | None | str | Unset): Limiting surface pressure p_G of the clamped part;
            overrides clamped_material
        internal_thread_material (None | PreloadControlStudyRequestPreloadControlStudyBaseInternalThreadMaterialType0 |
            Unset): Material of the tapped hole: its shear strength τ_BM for the stripping check
        internal_thread_shear_strength (float | None | str | Unset): Shear strength τ_BM of the internal thread;
            overrides internal_thread_material
        engagement_length (float | None | str | Unset): Length of thread engagement in the tapped hole as built, entry
            chamfers included (VDI 2230-1 R11: m_ges = m_eff + 2P)
        working_bolt_force (float | None | str | Unset): Largest bolt force in service F_S,max (surface pressure in
            service, VDI 2230-1 R10)
        nut_property_class (None | PreloadControlStudyRequestPreloadControlStudyBaseNutPropertyClassType0 | Unset):
            Property class of the nut (ISO 898-2; 04/05: thin nuts): its proof load caps F_M,zul; absent: the lowest class
            the nut standard is made in that pairs with the bolt
        required_clamp_force (float | str | Unset): Clamp force the joint needs in service (tightness, no separation)
        load_type (None | PreloadControlStudyRequestPreloadControlStudyBaseLoadTypeType0 | Unset): 'steady' (υ =
            1.25…2.0) or 'varying' (υ = 2.5…4.0) load [004, eq. 2] Default:
            PreloadControlStudyRequestPreloadControlStudyBaseLoadTypeType0.STEADY.
        preload_factor (float | None | str | Unset): υ of [004, eq. 2]: minimum preload = υ × clamp force; the lower end
            of the load type's range when absent
        method (None | PreloadControlStudyRequestPreloadControlStudyBaseMethodType0 | Unset): Control method (GET
            /api/v1/preload/methods lists them with their scatter) Default:
            PreloadControlStudyRequestPreloadControlStudyBaseMethodType0.TORQUE_WRENCH.
        snug_fraction (float | None | str | Unset): torque_then_angle: share of the final torque (and preload) at the
            snug point, where the angle count starts; 0.1 as ISO 5393 starts its angles, when absent (better: from the
            joint's torque–angle diagram, [004]) Default: 0.1.
        clamped_length (float | None | str | Unset): Clamped (grip) length l_k: needed for angle, elongation and
            displacement targets
        shank_length (float | None | str | Unset): Length of plain shank inside the grip; the rest of the grip is free
            thread (d3) Default: 0.0.
        shank_diameter (float | None | str | Unset): Plain shank diameter; d when absent
        reduced_length (float | None | str | Unset): Length of a reduced (waisted) shank section inside the grip
            Default: 0.0.
        reduced_diameter (float | None | str | Unset): Diameter of the reduced shank section (needed when reduced_length
            > 0)
        nut_height (float | None | str | Unset): Nut height m; [004] adds m/3 at the minor diameter to the stretched
            length; 0.8 d when absent
        youngs_modulus (float | None | str | Unset): Young's modulus of the bolt E_b Default: 210000000000.0.
        clamped_compliance (float | None | str | Unset): Compliance of the clamped parts λ_p ([004, eq. 8]); when
            absent, bolts get VDI 2230 R3's deformation cone through clamped_length of one material (wide plates, through-
            bolted), sucker rods 0 (rigid, [004, eq. 9]); 0 for a rigid joint
        clamped_youngs_modulus (float | None | str | Unset): Young's modulus of the clamped parts for the cone model;
            youngs_modulus when absent
        coupling_outer_diameter (float | None | str | Unset): Sucker-rod coupling outside diameter: turns the make-up
            angle into the circumferential displacement of the marks
        thread_friction_min (float | None | str | Unset): Friction scatter: lowest μ_G (with thread_friction_max, gives
            the preload histogram at a fixed torque)
        thread_friction_max (float | None | str | Unset): Friction scatter: highest μ_G
        bearing_friction_min (float | None | str | Unset): Friction scatter: lowest μ_K (bearing_friction when absent)
        bearing_friction_max (float | None | str | Unset): Friction scatter: highest μ_K
        scatter_torque (float | None | str | Unset): Fixed wrench torque for the friction-scatter histogram; the target
            torque when absent
        histogram_bins (int | None | str | Unset): Number of preload bins Default: 10.
        sample_size (int | None | str | Unset): Bolts the histogram counts are scaled to (38 in [004, fig. 5]) Default:
            38.
    """

    thread: str | Unset = UNSET
    grade: str | Unset = UNSET
    thread_diameter: float | None | str | Unset = UNSET
    thread_pitch: float | None | str | Unset = UNSET
    property_class: None | PreloadControlStudyRequestPreloadControlStudyBasePropertyClassType0 | Unset = (
        PreloadControlStudyRequestPreloadControlStudyBasePropertyClassType0.VALUE_5
    )
    yield_strength: float | None | str | Unset = UNSET
    thread_friction: float | None | str | Unset = 0.12
    bearing_friction: float | None | str | Unset = 0.12
    bearing_outer_diameter: float | None | str | Unset = UNSET
    hole_diameter: float | None | str | Unset = UNSET
    hole_series: None | PreloadControlStudyRequestPreloadControlStudyBaseHoleSeriesType0 | Unset = (
        PreloadControlStudyRequestPreloadControlStudyBaseHoleSeriesType0.MEDIUM
    )
    utilization: float | None | str | Unset = 0.9
    preload_convention: None | PreloadControlStudyRequestPreloadControlStudyBasePreloadConventionType0 | Unset = (
        PreloadControlStudyRequestPreloadControlStudyBasePreloadConventionType0.VDI2230
    )
    torque_formula: None | PreloadControlStudyRequestPreloadControlStudyBaseTorqueFormulaType0 | Unset = (
        PreloadControlStudyRequestPreloadControlStudyBaseTorqueFormulaType0.VDI2230
    )
    preload: float | None | str | Unset = UNSET
    head_standard: None | PreloadControlStudyRequestPreloadControlStudyBaseHeadStandardType0 | Unset = UNSET
    washer: None | PreloadControlStudyRequestPreloadControlStudyBaseWasherType0 | Unset = UNSET
    nut: None | PreloadControlStudyRequestPreloadControlStudyBaseNutType0 | Unset = UNSET
    clamped_material: None | PreloadControlStudyRequestPreloadControlStudyBaseClampedMaterialType0 | Unset = UNSET
    limiting_surface_pressure: float | None | str | Unset = UNSET
    internal_thread_material: (
        None | PreloadControlStudyRequestPreloadControlStudyBaseInternalThreadMaterialType0 | Unset
    ) = UNSET
    internal_thread_shear_strength: float | None | str | Unset = UNSET
    engagement_length: float | None | str | Unset = UNSET
    working_bolt_force: float | None | str | Unset = UNSET
    nut_property_class: None | PreloadControlStudyRequestPreloadControlStudyBaseNutPropertyClassType0 | Unset = UNSET
    required_clamp_force: float | str | Unset = UNSET
    load_type: None | PreloadControlStudyRequestPreloadControlStudyBaseLoadTypeType0 | Unset = (
        PreloadControlStudyRequestPreloadControlStudyBaseLoadTypeType0.STEADY
    )
    preload_factor: float | None | str | Unset = UNSET
    method: None | PreloadControlStudyRequestPreloadControlStudyBaseMethodType0 | Unset = (
        PreloadControlStudyRequestPreloadControlStudyBaseMethodType0.TORQUE_WRENCH
    )
    snug_fraction: float | None | str | Unset = 0.1
    clamped_length: float | None | str | Unset = UNSET
    shank_length: float | None | str | Unset = 0.0
    shank_diameter: float | None | str | Unset = UNSET
    reduced_length: float | None | str | Unset = 0.0
    reduced_diameter: float | None | str | Unset = UNSET
    nut_height: float | None | str | Unset = UNSET
    youngs_modulus: float | None | str | Unset = 210000000000.0
    clamped_compliance: float | None | str | Unset = UNSET
    clamped_youngs_modulus: float | None | str | Unset = UNSET
    coupling_outer_diameter: float | None | str | Unset = UNSET
    thread_friction_min: float | None | str | Unset = UNSET
    thread_friction_max: float | None | str | Unset = UNSET
    bearing_friction_min: float | None | str | Unset = UNSET
    bearing_friction_max: float | None | str | Unset = UNSET
    scatter_torque: float | None | str | Unset = UNSET
    histogram_bins: int | None | str | Unset = 10
    sample_size: int | None | str | Unset = 38

    def to_dict(self) -> dict[str, Any]:
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
        elif isinstance(self.property_class, PreloadControlStudyRequestPreloadControlStudyBasePropertyClassType0):
            property_class = self.property_class.value
        else:
            property_class = self.property_class

        yield_strength: float | None | str | Unset
        if isinstance(self.yield_strength, Unset):
            yield_strength = UNSET
        else:
            yield_strength = self.yield_strength

        thread_friction: float | None | str | Unset
        if isinstance(self.thread_friction, Unset):
            thread_friction = UNSET
        else:
            thread_friction = self.thread_friction

        bearing_friction: float | None | str | Unset
        if isinstance(self.bearing_friction, Unset):
            bearing_friction = UNSET
        else:
            bearing_friction = self.bearing_friction

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
        elif isinstance(self.hole_series, PreloadControlStudyRequestPreloadControlStudyBaseHoleSeriesType0):
            hole_series = self.hole_series.value
        else:
            hole_series = self.hole_series

        utilization: float | None | str | Unset
        if isinstance(self.utilization, Unset):
            utilization = UNSET
        else:
            utilization = self.utilization

        preload_convention: None | str | Unset
        if isinstance(self.preload_convention, Unset):
            preload_convention = UNSET
        elif isinstance(
            self.preload_convention, PreloadControlStudyRequestPreloadControlStudyBasePreloadConventionType0
        ):
            preload_convention = self.preload_convention.value
        else:
            preload_convention = self.preload_convention

        torque_formula: None | str | Unset
        if isinstance(self.torque_formula, Unset):
            torque_formula = UNSET
        elif isinstance(self.torque_formula, PreloadControlStudyRequestPreloadControlStudyBaseTorqueFormulaType0):
            torque_formula = self.torque_formula.value
        else:
            torque_formula = self.torque_formula

        preload: float | None | str | Unset
        if isinstance(self.preload, Unset):
            preload = UNSET
        else:
            preload = self.preload

        head_standard: None | str | Unset
        if isinstance(self.head_standard, Unset):
            head_standard = UNSET
        elif isinstance(self.head_standard, PreloadControlStudyRequestPreloadControlStudyBaseHeadStandardType0):
            head_standard = self.head_standard.value
        else:
            head_standard = self.head_standard

        washer: None | str | Unset
        if isinstance(self.washer, Unset):
            washer = UNSET
        elif isinstance(self.washer, PreloadControlStudyRequestPreloadControlStudyBaseWasherType0):
            washer = self.washer.value
        else:
            washer = self.washer

        nut: None | str | Unset
        if isinstance(self.nut, Unset):
            nut = UNSET
        elif isinstance(self.nut, PreloadControlStudyRequestPreloadControlStudyBaseNutType0):
            nut = self.nut.value
        else:
            nut = self.nut

        clamped_material: None | str | Unset
        if isinstance(self.clamped_material, Unset):
            clamped_material = UNSET
        elif isinstance(self.clamped_material, PreloadControlStudyRequestPreloadControlStudyBaseClampedMaterialType0):
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
        elif isinstance(
            self.internal_thread_material, PreloadControlStudyRequestPreloadControlStudyBaseInternalThreadMaterialType0
        ):
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

        working_bolt_force: float | None | str | Unset
        if isinstance(self.working_bolt_force, Unset):
            working_bolt_force = UNSET
        else:
            working_bolt_force = self.working_bolt_force

        nut_property_class: None | str | Unset
        if isinstance(self.nut_property_class, Unset):
            nut_property_class = UNSET
        elif isinstance(
            self.nut_property_class, PreloadControlStudyRequestPreloadControlStudyBaseNutPropertyClassType0
        ):
            nut_property_class = self.nut_property_class.value
        else:
            nut_property_class = self.nut_property_class

        required_clamp_force: float | str | Unset
        if isinstance(self.required_clamp_force, Unset):
            required_clamp_force = UNSET
        else:
            required_clamp_force = self.required_clamp_force

        load_type: None | str | Unset
        if isinstance(self.load_type, Unset):
            load_type = UNSET
        elif isinstance(self.load_type, PreloadControlStudyRequestPreloadControlStudyBaseLoadTypeType0):
            load_type = self.load_type.value
        else:
            load_type = self.load_type

        preload_factor: float | None | str | Unset
        if isinstance(self.preload_factor, Unset):
            preload_factor = UNSET
        else:
            preload_factor = self.preload_factor

        method: None | str | Unset
        if isinstance(self.method, Unset):
            method = UNSET
        elif isinstance(self.method, PreloadControlStudyRequestPreloadControlStudyBaseMethodType0):
            method = self.method.value
        else:
            method = self.method

        snug_fraction: float | None | str | Unset
        if isinstance(self.snug_fraction, Unset):
            snug_fraction = UNSET
        else:
            snug_fraction = self.snug_fraction

        clamped_length: float | None | str | Unset
        if isinstance(self.clamped_length, Unset):
            clamped_length = UNSET
        else:
            clamped_length = self.clamped_length

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

        nut_height: float | None | str | Unset
        if isinstance(self.nut_height, Unset):
            nut_height = UNSET
        else:
            nut_height = self.nut_height

        youngs_modulus: float | None | str | Unset
        if isinstance(self.youngs_modulus, Unset):
            youngs_modulus = UNSET
        else:
            youngs_modulus = self.youngs_modulus

        clamped_compliance: float | None | str | Unset
        if isinstance(self.clamped_compliance, Unset):
            clamped_compliance = UNSET
        else:
            clamped_compliance = self.clamped_compliance

        clamped_youngs_modulus: float | None | str | Unset
        if isinstance(self.clamped_youngs_modulus, Unset):
            clamped_youngs_modulus = UNSET
        else:
            clamped_youngs_modulus = self.clamped_youngs_modulus

        coupling_outer_diameter: float | None | str | Unset
        if isinstance(self.coupling_outer_diameter, Unset):
            coupling_outer_diameter = UNSET
        else:
            coupling_outer_diameter = self.coupling_outer_diameter

        thread_friction_min: float | None | str | Unset
        if isinstance(self.thread_friction_min, Unset):
            thread_friction_min = UNSET
        else:
            thread_friction_min = self.thread_friction_min

        thread_friction_max: float | None | str | Unset
        if isinstance(self.thread_friction_max, Unset):
            thread_friction_max = UNSET
        else:
            thread_friction_max = self.thread_friction_max

        bearing_friction_min: float | None | str | Unset
        if isinstance(self.bearing_friction_min, Unset):
            bearing_friction_min = UNSET
        else:
            bearing_friction_min = self.bearing_friction_min

        bearing_friction_max: float | None | str | Unset
        if isinstance(self.bearing_friction_max, Unset):
            bearing_friction_max = UNSET
        else:
            bearing_friction_max = self.bearing_friction_max

        scatter_torque: float | None | str | Unset
        if isinstance(self.scatter_torque, Unset):
            scatter_torque = UNSET
        else:
            scatter_torque = self.scatter_torque

        histogram_bins: int | None | str | Unset
        if isinstance(self.histogram_bins, Unset):
            histogram_bins = UNSET
        else:
            histogram_bins = self.histogram_bins

        sample_size: int | None | str | Unset
        if isinstance(self.sample_size, Unset):
            sample_size = UNSET
        else:
            sample_size = self.sample_size

        field_dict: dict[str, Any] = {}

        field_dict.update({})
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
        if thread_friction is not UNSET:
            field_dict["thread_friction"] = thread_friction
        if bearing_friction is not UNSET:
            field_dict["bearing_friction"] = bearing_friction
        if bearing_outer_diameter is not UNSET:
            field_dict["bearing_outer_diameter"] = bearing_outer_diameter
        if hole_diameter is not UNSET:
            field_dict["hole_diameter"] = hole_diameter
        if hole_series is not UNSET:
            field_dict["hole_series"] = hole_series
        if utilization is not UNSET:
            field_dict["utilization"] = utilization
        if preload_convention is not UNSET:
            field_dict["preload_convention"] = preload_convention
        if torque_formula is not UNSET:
            field_dict["torque_formula"] = torque_formula
        if preload is not UNSET:
            field_dict["preload"] = preload
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
        if working_bolt_force is not UNSET:
            field_dict["working_bolt_force"] = working_bolt_force
        if nut_property_class is not UNSET:
            field_dict["nut_property_class"] = nut_property_class
        if required_clamp_force is not UNSET:
            field_dict["required_clamp_force"] = required_clamp_force
        if load_type is not UNSET:
            field_dict["load_type"] = load_type
        if preload_factor is not UNSET:
            field_dict["preload_factor"] = preload_factor
        if method is not UNSET:
            field_dict["method"] = method
        if snug_fraction is not UNSET:
            field_dict["snug_fraction"] = snug_fraction
        if clamped_length is not UNSET:
            field_dict["clamped_length"] = clamped_length
        if shank_length is not UNSET:
            field_dict["shank_length"] = shank_length
        if shank_diameter is not UNSET:
            field_dict["shank_diameter"] = shank_diameter
        if reduced_length is not UNSET:
            field_dict["reduced_length"] = reduced_length
        if reduced_diameter is not UNSET:
            field_dict["reduced_diameter"] = reduced_diameter
        if nut_height is not UNSET:
            field_dict["nut_height"] = nut_height
        if youngs_modulus is not UNSET:
            field_dict["youngs_modulus"] = youngs_modulus
        if clamped_compliance is not UNSET:
            field_dict["clamped_compliance"] = clamped_compliance
        if clamped_youngs_modulus is not UNSET:
            field_dict["clamped_youngs_modulus"] = clamped_youngs_modulus
        if coupling_outer_diameter is not UNSET:
            field_dict["coupling_outer_diameter"] = coupling_outer_diameter
        if thread_friction_min is not UNSET:
            field_dict["thread_friction_min"] = thread_friction_min
        if thread_friction_max is not UNSET:
            field_dict["thread_friction_max"] = thread_friction_max
        if bearing_friction_min is not UNSET:
            field_dict["bearing_friction_min"] = bearing_friction_min
        if bearing_friction_max is not UNSET:
            field_dict["bearing_friction_max"] = bearing_friction_max
        if scatter_torque is not UNSET:
            field_dict["scatter_torque"] = scatter_torque
        if histogram_bins is not UNSET:
            field_dict["histogram_bins"] = histogram_bins
        if sample_size is not UNSET:
            field_dict["sample_size"] = sample_size

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
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

        def _parse_property_class(
            data: object,
        ) -> None | PreloadControlStudyRequestPreloadControlStudyBasePropertyClassType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                property_class_type_0 = PreloadControlStudyRequestPreloadControlStudyBasePropertyClassType0(data)

                return property_class_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadControlStudyRequestPreloadControlStudyBasePropertyClassType0 | Unset, data)

        property_class = _parse_property_class(d.pop("property_class", UNSET))

        def _parse_yield_strength(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        yield_strength = _parse_yield_strength(d.pop("yield_strength", UNSET))

        def _parse_thread_friction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        thread_friction = _parse_thread_friction(d.pop("thread_friction", UNSET))

        def _parse_bearing_friction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bearing_friction = _parse_bearing_friction(d.pop("bearing_friction", UNSET))

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

        def _parse_hole_series(
            data: object,
        ) -> None | PreloadControlStudyRequestPreloadControlStudyBaseHoleSeriesType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                hole_series_type_0 = PreloadControlStudyRequestPreloadControlStudyBaseHoleSeriesType0(data)

                return hole_series_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadControlStudyRequestPreloadControlStudyBaseHoleSeriesType0 | Unset, data)

        hole_series = _parse_hole_series(d.pop("hole_series", UNSET))

        def _parse_utilization(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        utilization = _parse_utilization(d.pop("utilization", UNSET))

        def _parse_preload_convention(
            data: object,
        ) -> None | PreloadControlStudyRequestPreloadControlStudyBasePreloadConventionType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                preload_convention_type_0 = PreloadControlStudyRequestPreloadControlStudyBasePreloadConventionType0(
                    data
                )

                return preload_convention_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadControlStudyRequestPreloadControlStudyBasePreloadConventionType0 | Unset, data)

        preload_convention = _parse_preload_convention(d.pop("preload_convention", UNSET))

        def _parse_torque_formula(
            data: object,
        ) -> None | PreloadControlStudyRequestPreloadControlStudyBaseTorqueFormulaType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                torque_formula_type_0 = PreloadControlStudyRequestPreloadControlStudyBaseTorqueFormulaType0(data)

                return torque_formula_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadControlStudyRequestPreloadControlStudyBaseTorqueFormulaType0 | Unset, data)

        torque_formula = _parse_torque_formula(d.pop("torque_formula", UNSET))

        def _parse_preload(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        preload = _parse_preload(d.pop("preload", UNSET))

        def _parse_head_standard(
            data: object,
        ) -> None | PreloadControlStudyRequestPreloadControlStudyBaseHeadStandardType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                head_standard_type_0 = PreloadControlStudyRequestPreloadControlStudyBaseHeadStandardType0(data)

                return head_standard_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadControlStudyRequestPreloadControlStudyBaseHeadStandardType0 | Unset, data)

        head_standard = _parse_head_standard(d.pop("head_standard", UNSET))

        def _parse_washer(data: object) -> None | PreloadControlStudyRequestPreloadControlStudyBaseWasherType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                washer_type_0 = PreloadControlStudyRequestPreloadControlStudyBaseWasherType0(data)

                return washer_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadControlStudyRequestPreloadControlStudyBaseWasherType0 | Unset, data)

        washer = _parse_washer(d.pop("washer", UNSET))

        def _parse_nut(data: object) -> None | PreloadControlStudyRequestPreloadControlStudyBaseNutType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                nut_type_0 = PreloadControlStudyRequestPreloadControlStudyBaseNutType0(data)

                return nut_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadControlStudyRequestPreloadControlStudyBaseNutType0 | Unset, data)

        nut = _parse_nut(d.pop("nut", UNSET))

        def _parse_clamped_material(
            data: object,
        ) -> None | PreloadControlStudyRequestPreloadControlStudyBaseClampedMaterialType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                clamped_material_type_0 = PreloadControlStudyRequestPreloadControlStudyBaseClampedMaterialType0(data)

                return clamped_material_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadControlStudyRequestPreloadControlStudyBaseClampedMaterialType0 | Unset, data)

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
        ) -> None | PreloadControlStudyRequestPreloadControlStudyBaseInternalThreadMaterialType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                internal_thread_material_type_0 = (
                    PreloadControlStudyRequestPreloadControlStudyBaseInternalThreadMaterialType0(data)
                )

                return internal_thread_material_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(
                None | PreloadControlStudyRequestPreloadControlStudyBaseInternalThreadMaterialType0 | Unset, data
            )

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

        def _parse_working_bolt_force(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        working_bolt_force = _parse_working_bolt_force(d.pop("working_bolt_force", UNSET))

        def _parse_nut_property_class(
            data: object,
        ) -> None | PreloadControlStudyRequestPreloadControlStudyBaseNutPropertyClassType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                nut_property_class_type_0 = PreloadControlStudyRequestPreloadControlStudyBaseNutPropertyClassType0(data)

                return nut_property_class_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadControlStudyRequestPreloadControlStudyBaseNutPropertyClassType0 | Unset, data)

        nut_property_class = _parse_nut_property_class(d.pop("nut_property_class", UNSET))

        def _parse_required_clamp_force(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        required_clamp_force = _parse_required_clamp_force(d.pop("required_clamp_force", UNSET))

        def _parse_load_type(
            data: object,
        ) -> None | PreloadControlStudyRequestPreloadControlStudyBaseLoadTypeType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                load_type_type_0 = PreloadControlStudyRequestPreloadControlStudyBaseLoadTypeType0(data)

                return load_type_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadControlStudyRequestPreloadControlStudyBaseLoadTypeType0 | Unset, data)

        load_type = _parse_load_type(d.pop("load_type", UNSET))

        def _parse_preload_factor(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        preload_factor = _parse_preload_factor(d.pop("preload_factor", UNSET))

        def _parse_method(data: object) -> None | PreloadControlStudyRequestPreloadControlStudyBaseMethodType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                method_type_0 = PreloadControlStudyRequestPreloadControlStudyBaseMethodType0(data)

                return method_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadControlStudyRequestPreloadControlStudyBaseMethodType0 | Unset, data)

        method = _parse_method(d.pop("method", UNSET))

        def _parse_snug_fraction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        snug_fraction = _parse_snug_fraction(d.pop("snug_fraction", UNSET))

        def _parse_clamped_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        clamped_length = _parse_clamped_length(d.pop("clamped_length", UNSET))

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

        def _parse_nut_height(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        nut_height = _parse_nut_height(d.pop("nut_height", UNSET))

        def _parse_youngs_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        youngs_modulus = _parse_youngs_modulus(d.pop("youngs_modulus", UNSET))

        def _parse_clamped_compliance(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        clamped_compliance = _parse_clamped_compliance(d.pop("clamped_compliance", UNSET))

        def _parse_clamped_youngs_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        clamped_youngs_modulus = _parse_clamped_youngs_modulus(d.pop("clamped_youngs_modulus", UNSET))

        def _parse_coupling_outer_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        coupling_outer_diameter = _parse_coupling_outer_diameter(d.pop("coupling_outer_diameter", UNSET))

        def _parse_thread_friction_min(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        thread_friction_min = _parse_thread_friction_min(d.pop("thread_friction_min", UNSET))

        def _parse_thread_friction_max(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        thread_friction_max = _parse_thread_friction_max(d.pop("thread_friction_max", UNSET))

        def _parse_bearing_friction_min(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bearing_friction_min = _parse_bearing_friction_min(d.pop("bearing_friction_min", UNSET))

        def _parse_bearing_friction_max(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bearing_friction_max = _parse_bearing_friction_max(d.pop("bearing_friction_max", UNSET))

        def _parse_scatter_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        scatter_torque = _parse_scatter_torque(d.pop("scatter_torque", UNSET))

        def _parse_histogram_bins(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        histogram_bins = _parse_histogram_bins(d.pop("histogram_bins", UNSET))

        def _parse_sample_size(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        sample_size = _parse_sample_size(d.pop("sample_size", UNSET))

        preload_control_study_request_preload_control_study_base = cls(
            thread=thread,
            grade=grade,
            thread_diameter=thread_diameter,
            thread_pitch=thread_pitch,
            property_class=property_class,
            yield_strength=yield_strength,
            thread_friction=thread_friction,
            bearing_friction=bearing_friction,
            bearing_outer_diameter=bearing_outer_diameter,
            hole_diameter=hole_diameter,
            hole_series=hole_series,
            utilization=utilization,
            preload_convention=preload_convention,
            torque_formula=torque_formula,
            preload=preload,
            head_standard=head_standard,
            washer=washer,
            nut=nut,
            clamped_material=clamped_material,
            limiting_surface_pressure=limiting_surface_pressure,
            internal_thread_material=internal_thread_material,
            internal_thread_shear_strength=internal_thread_shear_strength,
            engagement_length=engagement_length,
            working_bolt_force=working_bolt_force,
            nut_property_class=nut_property_class,
            required_clamp_force=required_clamp_force,
            load_type=load_type,
            preload_factor=preload_factor,
            method=method,
            snug_fraction=snug_fraction,
            clamped_length=clamped_length,
            shank_length=shank_length,
            shank_diameter=shank_diameter,
            reduced_length=reduced_length,
            reduced_diameter=reduced_diameter,
            nut_height=nut_height,
            youngs_modulus=youngs_modulus,
            clamped_compliance=clamped_compliance,
            clamped_youngs_modulus=clamped_youngs_modulus,
            coupling_outer_diameter=coupling_outer_diameter,
            thread_friction_min=thread_friction_min,
            thread_friction_max=thread_friction_max,
            bearing_friction_min=bearing_friction_min,
            bearing_friction_max=bearing_friction_max,
            scatter_torque=scatter_torque,
            histogram_bins=histogram_bins,
            sample_size=sample_size,
        )

        return preload_control_study_request_preload_control_study_base
