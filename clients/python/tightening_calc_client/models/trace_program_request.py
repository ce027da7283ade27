from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.trace_program_request_clamped_material_type_0 import TraceProgramRequestClampedMaterialType0
from ..models.trace_program_request_fidelity_type_0 import TraceProgramRequestFidelityType0
from ..models.trace_program_request_head_standard_type_0 import TraceProgramRequestHeadStandardType0
from ..models.trace_program_request_head_type_0 import TraceProgramRequestHeadType0
from ..models.trace_program_request_hole_series_type_0 import TraceProgramRequestHoleSeriesType0
from ..models.trace_program_request_internal_thread_material_type_0 import (
    TraceProgramRequestInternalThreadMaterialType0,
)
from ..models.trace_program_request_joint_type_type_0 import TraceProgramRequestJointTypeType0
from ..models.trace_program_request_method_type_0 import TraceProgramRequestMethodType0
from ..models.trace_program_request_nut_property_class_type_0 import TraceProgramRequestNutPropertyClassType0
from ..models.trace_program_request_nut_type_0 import TraceProgramRequestNutType0
from ..models.trace_program_request_outputs_type_0_item import TraceProgramRequestOutputsType0Item
from ..models.trace_program_request_property_class_type_0 import TraceProgramRequestPropertyClassType0
from ..models.trace_program_request_rolling_type_0 import TraceProgramRequestRollingType0
from ..models.trace_program_request_strategy_type_0 import TraceProgramRequestStrategyType0
from ..models.trace_program_request_surface_roughness_type_0 import TraceProgramRequestSurfaceRoughnessType0
from ..models.trace_program_request_washer_type_0 import TraceProgramRequestWasherType0
from ..types import UNSET, Unset

T = TypeVar("T", bound="TraceProgramRequest")


@_attrs_define
class TraceProgramRequest:
    """
    Attributes:
        plate1_thickness (float | str): Thickness h_1 of clamped plate 1 (from the head side)
        strategy (None | TraceProgramRequestStrategyType0 | Unset): Tightening strategy: torque then angle to the middle
            of the joint's window, or yield-point control (gradient drop) Default:
            TraceProgramRequestStrategyType0.TORQUE_ANGLE.
        snug_fraction (float | None | str | Unset): torque_then_angle: share of the final torque (and preload) at the
            snug point, where the angle count starts; 0.1 as ISO 5393 starts its angles, when absent (better: from the
            joint's torque–angle diagram, [004]) Default: 0.1.
        yield_gradient_fraction (float | None | str | Unset): Yield point: the gradient has fallen to this share of the
            elastic rate (50 % as controllers default to it) Default: 0.5.
        bolt_compliance_uncertainty (float | None | str | Unset): Relative uncertainty ± of the bolt's compliance δ_S
            Default: 0.05.
        clamped_compliance_uncertainty (float | None | str | Unset): Relative uncertainty ± of the clamped parts'
            compliance δ_P (the cone model's) Default: 0.2.
        thread (str | Unset): Designation instead of thread_diameter: 'M12', 'M12x1.25', 'M10 ISO 4762 12.9', '1/2-13
            UNC', '1/2-13 UNC Grade 5' (ISO M1.6…M64 coarse and fine, UNC/UNF 1/4…1-1/2; GET /api/v1/fasteners lists them).
            A head standard or grade in it sets head_standard and grade
        grade (str | Unset): Bolt grade, overriding property_class: ISO 898-1 (8.8…12.9), ISO 3506-1 (A2-70, A4-70,
            A4-80), SAE J429 ('SAE 5', 'Grade 8'), ASTM A193 'B7'
        thread_diameter (float | None | str | Unset): Nominal thread diameter d, when no thread designation is given
            (ISO 261 M3…M39 have tabulated data; other sizes need thread_pitch, bearing_outer_diameter, hole_diameter and
            yield_strength)
        thread_pitch (float | None | str | Unset): Thread pitch P; ISO 261 coarse pitch when absent
        property_class (None | TraceProgramRequestPropertyClassType0 | Unset): ISO 898-1 property class: minimum yield
            and tensile strength (8.8: 640/800 MPa up to M16, 660/830 MPa above) Default:
            TraceProgramRequestPropertyClassType0.VALUE_5.
        yield_strength (float | None | str | Unset): Minimum yield strength R_p0.2 (σ_T in [004]); overrides the
            property class
        bearing_outer_diameter (float | None | str | Unset): Outer diameter D_f of the bearing face; ISO 4017 hexagon
            head d_w,min when absent
        hole_diameter (float | None | str | Unset): Clearance-hole diameter d_h (inner diameter of the bearing face);
            ISO 273 of hole_series when absent
        hole_series (None | TraceProgramRequestHoleSeriesType0 | Unset): ISO 273 clearance-hole series used when
            hole_diameter is absent Default: TraceProgramRequestHoleSeriesType0.MEDIUM.
        utilization (float | None | str | Unset): ν: share of the yield strength the equivalent stress may use at
            assembly (VDI 2230: 0.9; [004, eq. 3]: ξ/n_T, 0.71…0.83) Default: 0.9.
        head (None | TraceProgramRequestHeadType0 | Unset): Head type: 'hex' (l_SK = 0.5 d) or 'socket' (0.4 d), VDI
            2230-1 R3 Default: TraceProgramRequestHeadType0.HEX.
        joint_type (None | TraceProgramRequestJointTypeType0 | Unset): 'through': bolt and nut (DSV); 'tapped': screwed
            into the last part (ESV) Default: TraceProgramRequestJointTypeType0.THROUGH.
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
        surface_roughness (None | TraceProgramRequestSurfaceRoughnessType0 | Unset): Mean roughness depth class of the
            bearing faces and interfaces (embedding, VDI R4) Default: TraceProgramRequestSurfaceRoughnessType0.RZ10_40.
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
        thread_friction_min (float | None | str | Unset): Smallest thread friction μ_G,min (sets F_M,zul and the highest
            preload) Default: 0.12.
        thread_friction_max (float | None | str | Unset): Largest thread friction μ_G,max (sets the lowest preload at a
            torque); μ_G,min when absent
        bearing_friction_min (float | None | str | Unset): Smallest bearing-face friction μ_K,min Default: 0.12.
        bearing_friction_max (float | None | str | Unset): Largest bearing-face friction μ_K,max; μ_K,min when absent
        method (None | TraceProgramRequestMethodType0 | Unset): Tightening method: its scatter gives α_A (GET
            /api/v1/preload/methods) Default: TraceProgramRequestMethodType0.TORQUE_WRENCH.
        tightening_factor (float | None | str | Unset): α_A = F_M,max/F_M,min (VDI 2230-1 R1, Table A8); the method's
            when absent
        tightening_torque (float | None | str | Unset): Torque specification M_A (including the prevailing torque): when
            given, the assembly preload range comes from it and the friction box
        torque_tolerance (float | None | str | Unset): Relative torque tolerance ± of the tool (0.05 for ±5 %) Default:
            0.0.
        prevailing_torque (float | None | str | Unset): Prevailing (locking) torque M_ü that produces no preload
            Default: 0.0.
        prevailing_torque_min (float | None | str | Unset): Smallest prevailing torque M_ü,min (sets the highest
            preload); prevailing_torque when absent
        controlled (bool | None | Unset): Tightened with a controlled method (false: by feel, [004] warns of over-
            tightening below M10) Default: True.
        bridge_joint (bool | None | Unset): High-strength bridge joint: [004] allows σ0 = 0.8…0.9 σ_T Default: False.
        rolling (None | TraceProgramRequestRollingType0 | Unset): Thread rolled before or after heat treatment
            (endurance limit, VDI 2230-1 R9) Default: TraceProgramRequestRollingType0.BEFORE_HEAT_TREATMENT.
        head_standard (None | TraceProgramRequestHeadStandardType0 | Unset): Head standard (bearing diameter d_w,
            drive): hexagon ISO 4017/4014 when absent (ASME B18.2.1 hex for inch threads)
        washer (None | TraceProgramRequestWasherType0 | Unset): Plain washer under the head (spreads the pressure on the
            clamped part)
        nut (None | TraceProgramRequestNutType0 | Unset): Hexagon nut (a through-bolted joint: surface pressure under
            the nut); absent: tapped
        clamped_material (None | TraceProgramRequestClampedMaterialType0 | Unset): Material under the head and nut: its
            limiting surface pressure p_G (VDI 2230-1 Table A9; plastics: compressive yield)
        limiting_surface_pressure (float | None | str | Unset): Limiting surface pressure p_G of the clamped part;
            overrides clamped_material
        internal_thread_material (None | TraceProgramRequestInternalThreadMaterialType0 | Unset): Material of the tapped
            hole: its shear strength τ_BM for the stripping check
        internal_thread_shear_strength (float | None | str | Unset): Shear strength τ_BM of the internal thread;
            overrides internal_thread_material
        engagement_length (float | None | str | Unset): Length of thread engagement in the tapped hole as built, entry
            chamfers included (VDI 2230-1 R11: m_ges = m_eff + 2P)
        nut_property_class (None | TraceProgramRequestNutPropertyClassType0 | Unset): Property class of the nut (ISO
            898-2; 04/05: thin nuts): its proof load caps F_M,zul; absent: the lowest class the nut standard is made in that
            pairs with the bolt
        fidelity (None | TraceProgramRequestFidelityType0 | Unset): 'auto' picks the cheapest rung whose error estimate
            meets `tolerance`; or name a rung. Absent: 'auto', or 'auto' when a tolerance is given
        tolerance (float | None | Unset): relative tolerance for 'auto' (0.01)
        outputs (list[TraceProgramRequestOutputsType0Item] | None | Unset): compute only these outputs and series (every
            scalar output when absent)
        series (bool | Unset): true: compute and send every series too (absent/false: only the series named in
            `outputs`) Default: False.
    """

    plate1_thickness: float | str
    strategy: None | TraceProgramRequestStrategyType0 | Unset = TraceProgramRequestStrategyType0.TORQUE_ANGLE
    snug_fraction: float | None | str | Unset = 0.1
    yield_gradient_fraction: float | None | str | Unset = 0.5
    bolt_compliance_uncertainty: float | None | str | Unset = 0.05
    clamped_compliance_uncertainty: float | None | str | Unset = 0.2
    thread: str | Unset = UNSET
    grade: str | Unset = UNSET
    thread_diameter: float | None | str | Unset = UNSET
    thread_pitch: float | None | str | Unset = UNSET
    property_class: None | TraceProgramRequestPropertyClassType0 | Unset = TraceProgramRequestPropertyClassType0.VALUE_5
    yield_strength: float | None | str | Unset = UNSET
    bearing_outer_diameter: float | None | str | Unset = UNSET
    hole_diameter: float | None | str | Unset = UNSET
    hole_series: None | TraceProgramRequestHoleSeriesType0 | Unset = TraceProgramRequestHoleSeriesType0.MEDIUM
    utilization: float | None | str | Unset = 0.9
    head: None | TraceProgramRequestHeadType0 | Unset = TraceProgramRequestHeadType0.HEX
    joint_type: None | TraceProgramRequestJointTypeType0 | Unset = TraceProgramRequestJointTypeType0.THROUGH
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
    surface_roughness: None | TraceProgramRequestSurfaceRoughnessType0 | Unset = (
        TraceProgramRequestSurfaceRoughnessType0.RZ10_40
    )
    temperature_change: float | None | str | Unset = 0.0
    plate_temperature_change: float | None | str | Unset = UNSET
    bolt_modulus_ratio: float | None | str | Unset = 1.0
    plate_modulus_ratio: float | None | str | Unset = 1.0
    service_temperature: float | None | str | Unset = UNSET
    thread_friction_min: float | None | str | Unset = 0.12
    thread_friction_max: float | None | str | Unset = UNSET
    bearing_friction_min: float | None | str | Unset = 0.12
    bearing_friction_max: float | None | str | Unset = UNSET
    method: None | TraceProgramRequestMethodType0 | Unset = TraceProgramRequestMethodType0.TORQUE_WRENCH
    tightening_factor: float | None | str | Unset = UNSET
    tightening_torque: float | None | str | Unset = UNSET
    torque_tolerance: float | None | str | Unset = 0.0
    prevailing_torque: float | None | str | Unset = 0.0
    prevailing_torque_min: float | None | str | Unset = UNSET
    controlled: bool | None | Unset = True
    bridge_joint: bool | None | Unset = False
    rolling: None | TraceProgramRequestRollingType0 | Unset = TraceProgramRequestRollingType0.BEFORE_HEAT_TREATMENT
    head_standard: None | TraceProgramRequestHeadStandardType0 | Unset = UNSET
    washer: None | TraceProgramRequestWasherType0 | Unset = UNSET
    nut: None | TraceProgramRequestNutType0 | Unset = UNSET
    clamped_material: None | TraceProgramRequestClampedMaterialType0 | Unset = UNSET
    limiting_surface_pressure: float | None | str | Unset = UNSET
    internal_thread_material: None | TraceProgramRequestInternalThreadMaterialType0 | Unset = UNSET
    internal_thread_shear_strength: float | None | str | Unset = UNSET
    engagement_length: float | None | str | Unset = UNSET
    nut_property_class: None | TraceProgramRequestNutPropertyClassType0 | Unset = UNSET
    fidelity: None | TraceProgramRequestFidelityType0 | Unset = UNSET
    tolerance: float | None | Unset = UNSET
    outputs: list[TraceProgramRequestOutputsType0Item] | None | Unset = UNSET
    series: bool | Unset = False

    def to_dict(self) -> dict[str, Any]:
        plate1_thickness: float | str
        plate1_thickness = self.plate1_thickness

        strategy: None | str | Unset
        if isinstance(self.strategy, Unset):
            strategy = UNSET
        elif isinstance(self.strategy, TraceProgramRequestStrategyType0):
            strategy = self.strategy.value
        else:
            strategy = self.strategy

        snug_fraction: float | None | str | Unset
        if isinstance(self.snug_fraction, Unset):
            snug_fraction = UNSET
        else:
            snug_fraction = self.snug_fraction

        yield_gradient_fraction: float | None | str | Unset
        if isinstance(self.yield_gradient_fraction, Unset):
            yield_gradient_fraction = UNSET
        else:
            yield_gradient_fraction = self.yield_gradient_fraction

        bolt_compliance_uncertainty: float | None | str | Unset
        if isinstance(self.bolt_compliance_uncertainty, Unset):
            bolt_compliance_uncertainty = UNSET
        else:
            bolt_compliance_uncertainty = self.bolt_compliance_uncertainty

        clamped_compliance_uncertainty: float | None | str | Unset
        if isinstance(self.clamped_compliance_uncertainty, Unset):
            clamped_compliance_uncertainty = UNSET
        else:
            clamped_compliance_uncertainty = self.clamped_compliance_uncertainty

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
        elif isinstance(self.property_class, TraceProgramRequestPropertyClassType0):
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
        elif isinstance(self.hole_series, TraceProgramRequestHoleSeriesType0):
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
        elif isinstance(self.head, TraceProgramRequestHeadType0):
            head = self.head.value
        else:
            head = self.head

        joint_type: None | str | Unset
        if isinstance(self.joint_type, Unset):
            joint_type = UNSET
        elif isinstance(self.joint_type, TraceProgramRequestJointTypeType0):
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
        elif isinstance(self.surface_roughness, TraceProgramRequestSurfaceRoughnessType0):
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

        method: None | str | Unset
        if isinstance(self.method, Unset):
            method = UNSET
        elif isinstance(self.method, TraceProgramRequestMethodType0):
            method = self.method.value
        else:
            method = self.method

        tightening_factor: float | None | str | Unset
        if isinstance(self.tightening_factor, Unset):
            tightening_factor = UNSET
        else:
            tightening_factor = self.tightening_factor

        tightening_torque: float | None | str | Unset
        if isinstance(self.tightening_torque, Unset):
            tightening_torque = UNSET
        else:
            tightening_torque = self.tightening_torque

        torque_tolerance: float | None | str | Unset
        if isinstance(self.torque_tolerance, Unset):
            torque_tolerance = UNSET
        else:
            torque_tolerance = self.torque_tolerance

        prevailing_torque: float | None | str | Unset
        if isinstance(self.prevailing_torque, Unset):
            prevailing_torque = UNSET
        else:
            prevailing_torque = self.prevailing_torque

        prevailing_torque_min: float | None | str | Unset
        if isinstance(self.prevailing_torque_min, Unset):
            prevailing_torque_min = UNSET
        else:
            prevailing_torque_min = self.prevailing_torque_min

        controlled: bool | None | Unset
        if isinstance(self.controlled, Unset):
            controlled = UNSET
        else:
            controlled = self.controlled

        bridge_joint: bool | None | Unset
        if isinstance(self.bridge_joint, Unset):
            bridge_joint = UNSET
        else:
            bridge_joint = self.bridge_joint

        rolling: None | str | Unset
        if isinstance(self.rolling, Unset):
            rolling = UNSET
        elif isinstance(self.rolling, TraceProgramRequestRollingType0):
            rolling = self.rolling.value
        else:
            rolling = self.rolling

        head_standard: None | str | Unset
        if isinstance(self.head_standard, Unset):
            head_standard = UNSET
        elif isinstance(self.head_standard, TraceProgramRequestHeadStandardType0):
            head_standard = self.head_standard.value
        else:
            head_standard = self.head_standard

        washer: None | str | Unset
        if isinstance(self.washer, Unset):
            washer = UNSET
        elif isinstance(self.washer, TraceProgramRequestWasherType0):
            washer = self.washer.value
        else:
            washer = self.washer

        nut: None | str | Unset
        if isinstance(self.nut, Unset):
            nut = UNSET
        elif isinstance(self.nut, TraceProgramRequestNutType0):
            nut = self.nut.value
        else:
            nut = self.nut

        clamped_material: None | str | Unset
        if isinstance(self.clamped_material, Unset):
            clamped_material = UNSET
        elif isinstance(self.clamped_material, TraceProgramRequestClampedMaterialType0):
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
        elif isinstance(self.internal_thread_material, TraceProgramRequestInternalThreadMaterialType0):
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
        elif isinstance(self.nut_property_class, TraceProgramRequestNutPropertyClassType0):
            nut_property_class = self.nut_property_class.value
        else:
            nut_property_class = self.nut_property_class

        fidelity: None | str | Unset
        if isinstance(self.fidelity, Unset):
            fidelity = UNSET
        elif isinstance(self.fidelity, TraceProgramRequestFidelityType0):
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
        if strategy is not UNSET:
            field_dict["strategy"] = strategy
        if snug_fraction is not UNSET:
            field_dict["snug_fraction"] = snug_fraction
        if yield_gradient_fraction is not UNSET:
            field_dict["yield_gradient_fraction"] = yield_gradient_fraction
        if bolt_compliance_uncertainty is not UNSET:
            field_dict["bolt_compliance_uncertainty"] = bolt_compliance_uncertainty
        if clamped_compliance_uncertainty is not UNSET:
            field_dict["clamped_compliance_uncertainty"] = clamped_compliance_uncertainty
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
        if thread_friction_min is not UNSET:
            field_dict["thread_friction_min"] = thread_friction_min
        if thread_friction_max is not UNSET:
            field_dict["thread_friction_max"] = thread_friction_max
        if bearing_friction_min is not UNSET:
            field_dict["bearing_friction_min"] = bearing_friction_min
        if bearing_friction_max is not UNSET:
            field_dict["bearing_friction_max"] = bearing_friction_max
        if method is not UNSET:
            field_dict["method"] = method
        if tightening_factor is not UNSET:
            field_dict["tightening_factor"] = tightening_factor
        if tightening_torque is not UNSET:
            field_dict["tightening_torque"] = tightening_torque
        if torque_tolerance is not UNSET:
            field_dict["torque_tolerance"] = torque_tolerance
        if prevailing_torque is not UNSET:
            field_dict["prevailing_torque"] = prevailing_torque
        if prevailing_torque_min is not UNSET:
            field_dict["prevailing_torque_min"] = prevailing_torque_min
        if controlled is not UNSET:
            field_dict["controlled"] = controlled
        if bridge_joint is not UNSET:
            field_dict["bridge_joint"] = bridge_joint
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
        d = dict(src_dict)

        def _parse_plate1_thickness(data: object) -> float | str:
            return cast(float | str, data)

        plate1_thickness = _parse_plate1_thickness(d.pop("plate1_thickness"))

        def _parse_strategy(data: object) -> None | TraceProgramRequestStrategyType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                strategy_type_0 = TraceProgramRequestStrategyType0(data)

                return strategy_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestStrategyType0 | Unset, data)

        strategy = _parse_strategy(d.pop("strategy", UNSET))

        def _parse_snug_fraction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        snug_fraction = _parse_snug_fraction(d.pop("snug_fraction", UNSET))

        def _parse_yield_gradient_fraction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        yield_gradient_fraction = _parse_yield_gradient_fraction(d.pop("yield_gradient_fraction", UNSET))

        def _parse_bolt_compliance_uncertainty(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bolt_compliance_uncertainty = _parse_bolt_compliance_uncertainty(d.pop("bolt_compliance_uncertainty", UNSET))

        def _parse_clamped_compliance_uncertainty(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        clamped_compliance_uncertainty = _parse_clamped_compliance_uncertainty(
            d.pop("clamped_compliance_uncertainty", UNSET)
        )

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

        def _parse_property_class(data: object) -> None | TraceProgramRequestPropertyClassType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                property_class_type_0 = TraceProgramRequestPropertyClassType0(data)

                return property_class_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestPropertyClassType0 | Unset, data)

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

        def _parse_hole_series(data: object) -> None | TraceProgramRequestHoleSeriesType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                hole_series_type_0 = TraceProgramRequestHoleSeriesType0(data)

                return hole_series_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestHoleSeriesType0 | Unset, data)

        hole_series = _parse_hole_series(d.pop("hole_series", UNSET))

        def _parse_utilization(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        utilization = _parse_utilization(d.pop("utilization", UNSET))

        def _parse_head(data: object) -> None | TraceProgramRequestHeadType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                head_type_0 = TraceProgramRequestHeadType0(data)

                return head_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestHeadType0 | Unset, data)

        head = _parse_head(d.pop("head", UNSET))

        def _parse_joint_type(data: object) -> None | TraceProgramRequestJointTypeType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                joint_type_type_0 = TraceProgramRequestJointTypeType0(data)

                return joint_type_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestJointTypeType0 | Unset, data)

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

        def _parse_surface_roughness(data: object) -> None | TraceProgramRequestSurfaceRoughnessType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                surface_roughness_type_0 = TraceProgramRequestSurfaceRoughnessType0(data)

                return surface_roughness_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestSurfaceRoughnessType0 | Unset, data)

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

        def _parse_method(data: object) -> None | TraceProgramRequestMethodType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                method_type_0 = TraceProgramRequestMethodType0(data)

                return method_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestMethodType0 | Unset, data)

        method = _parse_method(d.pop("method", UNSET))

        def _parse_tightening_factor(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        tightening_factor = _parse_tightening_factor(d.pop("tightening_factor", UNSET))

        def _parse_tightening_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        tightening_torque = _parse_tightening_torque(d.pop("tightening_torque", UNSET))

        def _parse_torque_tolerance(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        torque_tolerance = _parse_torque_tolerance(d.pop("torque_tolerance", UNSET))

        def _parse_prevailing_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        prevailing_torque = _parse_prevailing_torque(d.pop("prevailing_torque", UNSET))

        def _parse_prevailing_torque_min(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        prevailing_torque_min = _parse_prevailing_torque_min(d.pop("prevailing_torque_min", UNSET))

        def _parse_controlled(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        controlled = _parse_controlled(d.pop("controlled", UNSET))

        def _parse_bridge_joint(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        bridge_joint = _parse_bridge_joint(d.pop("bridge_joint", UNSET))

        def _parse_rolling(data: object) -> None | TraceProgramRequestRollingType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                rolling_type_0 = TraceProgramRequestRollingType0(data)

                return rolling_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestRollingType0 | Unset, data)

        rolling = _parse_rolling(d.pop("rolling", UNSET))

        def _parse_head_standard(data: object) -> None | TraceProgramRequestHeadStandardType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                head_standard_type_0 = TraceProgramRequestHeadStandardType0(data)

                return head_standard_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestHeadStandardType0 | Unset, data)

        head_standard = _parse_head_standard(d.pop("head_standard", UNSET))

        def _parse_washer(data: object) -> None | TraceProgramRequestWasherType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                washer_type_0 = TraceProgramRequestWasherType0(data)

                return washer_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestWasherType0 | Unset, data)

        washer = _parse_washer(d.pop("washer", UNSET))

        def _parse_nut(data: object) -> None | TraceProgramRequestNutType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                nut_type_0 = TraceProgramRequestNutType0(data)

                return nut_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestNutType0 | Unset, data)

        nut = _parse_nut(d.pop("nut", UNSET))

        def _parse_clamped_material(data: object) -> None | TraceProgramRequestClampedMaterialType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                clamped_material_type_0 = TraceProgramRequestClampedMaterialType0(data)

                return clamped_material_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestClampedMaterialType0 | Unset, data)

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
        ) -> None | TraceProgramRequestInternalThreadMaterialType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                internal_thread_material_type_0 = TraceProgramRequestInternalThreadMaterialType0(data)

                return internal_thread_material_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestInternalThreadMaterialType0 | Unset, data)

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

        def _parse_nut_property_class(data: object) -> None | TraceProgramRequestNutPropertyClassType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                nut_property_class_type_0 = TraceProgramRequestNutPropertyClassType0(data)

                return nut_property_class_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestNutPropertyClassType0 | Unset, data)

        nut_property_class = _parse_nut_property_class(d.pop("nut_property_class", UNSET))

        def _parse_fidelity(data: object) -> None | TraceProgramRequestFidelityType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                fidelity_type_0 = TraceProgramRequestFidelityType0(data)

                return fidelity_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TraceProgramRequestFidelityType0 | Unset, data)

        fidelity = _parse_fidelity(d.pop("fidelity", UNSET))

        def _parse_tolerance(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        tolerance = _parse_tolerance(d.pop("tolerance", UNSET))

        def _parse_outputs(data: object) -> list[TraceProgramRequestOutputsType0Item] | None | Unset:
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
                    outputs_type_0_item = TraceProgramRequestOutputsType0Item(outputs_type_0_item_data)

                    outputs_type_0.append(outputs_type_0_item)

                return outputs_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[TraceProgramRequestOutputsType0Item] | None | Unset, data)

        outputs = _parse_outputs(d.pop("outputs", UNSET))

        series = d.pop("series", UNSET)

        trace_program_request = cls(
            plate1_thickness=plate1_thickness,
            strategy=strategy,
            snug_fraction=snug_fraction,
            yield_gradient_fraction=yield_gradient_fraction,
            bolt_compliance_uncertainty=bolt_compliance_uncertainty,
            clamped_compliance_uncertainty=clamped_compliance_uncertainty,
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
            thread_friction_min=thread_friction_min,
            thread_friction_max=thread_friction_max,
            bearing_friction_min=bearing_friction_min,
            bearing_friction_max=bearing_friction_max,
            method=method,
            tightening_factor=tightening_factor,
            tightening_torque=tightening_torque,
            torque_tolerance=torque_tolerance,
            prevailing_torque=prevailing_torque,
            prevailing_torque_min=prevailing_torque_min,
            controlled=controlled,
            bridge_joint=bridge_joint,
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
            fidelity=fidelity,
            tolerance=tolerance,
            outputs=outputs,
            series=series,
        )

        return trace_program_request
