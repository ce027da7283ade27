from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.joint_audit_study_request_joint_audit_study_base_head_type_0 import (
    JointAuditStudyRequestJointAuditStudyBaseHeadType0,
)
from ..models.joint_audit_study_request_joint_audit_study_base_hole_series_type_0 import (
    JointAuditStudyRequestJointAuditStudyBaseHoleSeriesType0,
)
from ..models.joint_audit_study_request_joint_audit_study_base_joint_type_type_0 import (
    JointAuditStudyRequestJointAuditStudyBaseJointTypeType0,
)
from ..models.joint_audit_study_request_joint_audit_study_base_property_class_type_0 import (
    JointAuditStudyRequestJointAuditStudyBasePropertyClassType0,
)
from ..models.joint_audit_study_request_joint_audit_study_base_surface_roughness_type_0 import (
    JointAuditStudyRequestJointAuditStudyBaseSurfaceRoughnessType0,
)
from ..types import UNSET, Unset

T = TypeVar("T", bound="JointAuditStudyRequestJointAuditStudyBase")


@_attrs_define
class JointAuditStudyRequestJointAuditStudyBase:
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
        property_class (JointAuditStudyRequestJointAuditStudyBasePropertyClassType0 | None | Unset): ISO 898-1 property
            class: minimum yield and tensile strength (8.8: 640/800 MPa up to M16, 660/830 MPa above) Default:
            JointAuditStudyRequestJointAuditStudyBasePropertyClassType0.VALUE_5.
        yield_strength (float | None | str | Unset): Minimum yield strength R_p0.2 (σ_T in [004]); overrides the
            property class
        bearing_outer_diameter (float | None | str | Unset): Outer diameter D_f of the bearing face; ISO 4017 hexagon
            head d_w,min when absent
        hole_diameter (float | None | str | Unset): Clearance-hole diameter d_h (inner diameter of the bearing face);
            ISO 273 of hole_series when absent
        hole_series (JointAuditStudyRequestJointAuditStudyBaseHoleSeriesType0 | None | Unset): ISO 273 clearance-hole
            series used when hole_diameter is absent Default:
            JointAuditStudyRequestJointAuditStudyBaseHoleSeriesType0.MEDIUM.
        head (JointAuditStudyRequestJointAuditStudyBaseHeadType0 | None | Unset): Head type: 'hex' (l_SK = 0.5 d) or
            'socket' (0.4 d), VDI 2230-1 R3 Default: JointAuditStudyRequestJointAuditStudyBaseHeadType0.HEX.
        joint_type (JointAuditStudyRequestJointAuditStudyBaseJointTypeType0 | None | Unset): 'through': bolt and nut
            (DSV); 'tapped': screwed into the last part (ESV) Default:
            JointAuditStudyRequestJointAuditStudyBaseJointTypeType0.THROUGH.
        shank_length (float | None | str | Unset): Length of plain shank inside the grip; the rest of the grip is free
            thread Default: 0.0.
        shank_diameter (float | None | str | Unset): Plain shank diameter; d when absent
        reduced_length (float | None | str | Unset): Length of a reduced (waisted) shank inside the grip Default: 0.0.
        reduced_diameter (float | None | str | Unset): Diameter d_T of the reduced shank (needed when reduced_length >
            0); the strength limit F_M,zul is taken at the smallest section (VDI 2230-1 R7)
        youngs_modulus (float | None | str | Unset): Young's modulus of the bolt E_S Default: 210000000000.0.
        nut_youngs_modulus (float | None | str | Unset): Young's modulus E_M of the nut or of the part with the tapped
            thread; E_S when absent
        plate1_thickness (float | str | Unset): Thickness h_1 of clamped plate 1 (from the head side)
        plate1_youngs_modulus (float | None | str | Unset): Young's modulus E_1 of plate 1 (steel 210 GPa) Default:
            210000000000.0.
        plate2_thickness (float | None | str | Unset): Thickness h_2 of clamped plate 2 (from the head side); absent or
            0: no such plate
        plate2_youngs_modulus (float | None | str | Unset): Young's modulus E_2 of plate 2; plate 1's when absent
        plate2_outer_diameter (float | None | str | Unset): Outer diameter D_A,2 of plate 2 (VDI 2230-1 R3: its part of
            the cone is capped there, a sleeve below d_W); outer_diameter (plate 1's) when absent
        plate3_thickness (float | None | str | Unset): Thickness h_3 of clamped plate 3 (from the head side); absent or
            0: no such plate
        plate3_youngs_modulus (float | None | str | Unset): Young's modulus E_3 of plate 3; plate 1's when absent
        plate3_outer_diameter (float | None | str | Unset): Outer diameter D_A,3 of plate 3 (VDI 2230-1 R3: its part of
            the cone is capped there, a sleeve below d_W); outer_diameter (plate 1's) when absent
        outer_diameter (float | None | str | Unset): Outer diameter D_A of the clamped parts (equivalent); absent:
            plates wide enough for the full deformation cone. Must be ≥ the bearing diameter d_W
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
        transverse_load (float | None | str | Unset): Transverse load F_Q,max per bolt carried by interface friction
            Default: 0.0.
        fitted_diameter (float | None | str | Unset): Fitted bolt: diameter d_τ of the fitted shank that carries F_Q in
            shear and bearing (VDI 2230-1 R12); absent: the interfaces carry F_Q by friction alone
        torsional_moment (float | None | str | Unset): Torsional moment M_Y,max about the bolt axis carried by interface
            friction (VDI 2230-1 R2/R12); needs friction_radius Default: 0.0.
        torque_interfaces (int | None | str | Unset): Number q_M of interfaces that carry the torsional moment Default:
            1.
        friction_radius (float | None | str | Unset): Friction radius r_a of the interface for the torsional moment
            (needed with M_Y > 0)
        surface_roughness (JointAuditStudyRequestJointAuditStudyBaseSurfaceRoughnessType0 | None | Unset): Mean
            roughness depth class of the bearing faces and interfaces (embedding, VDI R4) Default:
            JointAuditStudyRequestJointAuditStudyBaseSurfaceRoughnessType0.RZ10_40.
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
        tightening_torque (float | str | Unset): Torque specification M_A, the tool's nominal torque (including the
            prevailing torque)
        torque_tolerance (float | None | str | Unset): Relative torque tolerance ± of the tool (0.05 for ±5 %) Default:
            0.0.
        prevailing_torque (float | None | str | Unset): Prevailing (locking) torque M_ü that produces no preload
            Default: 0.0.
        prevailing_torque_min (float | None | str | Unset): Smallest prevailing torque M_ü,min (sets the highest
            preload); prevailing_torque when absent
        static_friction_ratio_min (float | None | str | Unset): Smallest ratio of static to kinetic friction r =
            μ_static/μ_kinetic at the reading (1: no excess; lubricated steel on steel, [FrictionTables]) Default: 1.0.
        static_friction_ratio_max (float | None | str | Unset): Largest ratio r = μ_static/μ_kinetic (1.15: dry steel on
            steel, static 0.45…0.80 against kinetic 0.40…0.70, [FrictionTables]; measure your own where it matters) Default:
            1.15.
    """

    thread: str | Unset = UNSET
    grade: str | Unset = UNSET
    thread_diameter: float | None | str | Unset = UNSET
    thread_pitch: float | None | str | Unset = UNSET
    property_class: JointAuditStudyRequestJointAuditStudyBasePropertyClassType0 | None | Unset = (
        JointAuditStudyRequestJointAuditStudyBasePropertyClassType0.VALUE_5
    )
    yield_strength: float | None | str | Unset = UNSET
    bearing_outer_diameter: float | None | str | Unset = UNSET
    hole_diameter: float | None | str | Unset = UNSET
    hole_series: JointAuditStudyRequestJointAuditStudyBaseHoleSeriesType0 | None | Unset = (
        JointAuditStudyRequestJointAuditStudyBaseHoleSeriesType0.MEDIUM
    )
    head: JointAuditStudyRequestJointAuditStudyBaseHeadType0 | None | Unset = (
        JointAuditStudyRequestJointAuditStudyBaseHeadType0.HEX
    )
    joint_type: JointAuditStudyRequestJointAuditStudyBaseJointTypeType0 | None | Unset = (
        JointAuditStudyRequestJointAuditStudyBaseJointTypeType0.THROUGH
    )
    shank_length: float | None | str | Unset = 0.0
    shank_diameter: float | None | str | Unset = UNSET
    reduced_length: float | None | str | Unset = 0.0
    reduced_diameter: float | None | str | Unset = UNSET
    youngs_modulus: float | None | str | Unset = 210000000000.0
    nut_youngs_modulus: float | None | str | Unset = UNSET
    plate1_thickness: float | str | Unset = UNSET
    plate1_youngs_modulus: float | None | str | Unset = 210000000000.0
    plate2_thickness: float | None | str | Unset = UNSET
    plate2_youngs_modulus: float | None | str | Unset = UNSET
    plate2_outer_diameter: float | None | str | Unset = UNSET
    plate3_thickness: float | None | str | Unset = UNSET
    plate3_youngs_modulus: float | None | str | Unset = UNSET
    plate3_outer_diameter: float | None | str | Unset = UNSET
    outer_diameter: float | None | str | Unset = UNSET
    bolt_offset: float | None | str | Unset = 0.0
    load_lever: float | None | str | Unset = 0.0
    opening_edge: float | None | str | Unset = 0.0
    interface_length: float | None | str | Unset = UNSET
    interface_width: float | None | str | Unset = UNSET
    transverse_load: float | None | str | Unset = 0.0
    fitted_diameter: float | None | str | Unset = UNSET
    torsional_moment: float | None | str | Unset = 0.0
    torque_interfaces: int | None | str | Unset = 1
    friction_radius: float | None | str | Unset = UNSET
    surface_roughness: JointAuditStudyRequestJointAuditStudyBaseSurfaceRoughnessType0 | None | Unset = (
        JointAuditStudyRequestJointAuditStudyBaseSurfaceRoughnessType0.RZ10_40
    )
    service_temperature: float | None | str | Unset = UNSET
    thread_friction_min: float | None | str | Unset = 0.12
    thread_friction_max: float | None | str | Unset = UNSET
    bearing_friction_min: float | None | str | Unset = 0.12
    bearing_friction_max: float | None | str | Unset = UNSET
    tightening_torque: float | str | Unset = UNSET
    torque_tolerance: float | None | str | Unset = 0.0
    prevailing_torque: float | None | str | Unset = 0.0
    prevailing_torque_min: float | None | str | Unset = UNSET
    static_friction_ratio_min: float | None | str | Unset = 1.0
    static_friction_ratio_max: float | None | str | Unset = 1.15

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
        elif isinstance(self.property_class, JointAuditStudyRequestJointAuditStudyBasePropertyClassType0):
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
        elif isinstance(self.hole_series, JointAuditStudyRequestJointAuditStudyBaseHoleSeriesType0):
            hole_series = self.hole_series.value
        else:
            hole_series = self.hole_series

        head: None | str | Unset
        if isinstance(self.head, Unset):
            head = UNSET
        elif isinstance(self.head, JointAuditStudyRequestJointAuditStudyBaseHeadType0):
            head = self.head.value
        else:
            head = self.head

        joint_type: None | str | Unset
        if isinstance(self.joint_type, Unset):
            joint_type = UNSET
        elif isinstance(self.joint_type, JointAuditStudyRequestJointAuditStudyBaseJointTypeType0):
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

        plate1_thickness: float | str | Unset
        if isinstance(self.plate1_thickness, Unset):
            plate1_thickness = UNSET
        else:
            plate1_thickness = self.plate1_thickness

        plate1_youngs_modulus: float | None | str | Unset
        if isinstance(self.plate1_youngs_modulus, Unset):
            plate1_youngs_modulus = UNSET
        else:
            plate1_youngs_modulus = self.plate1_youngs_modulus

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

        transverse_load: float | None | str | Unset
        if isinstance(self.transverse_load, Unset):
            transverse_load = UNSET
        else:
            transverse_load = self.transverse_load

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

        surface_roughness: None | str | Unset
        if isinstance(self.surface_roughness, Unset):
            surface_roughness = UNSET
        elif isinstance(self.surface_roughness, JointAuditStudyRequestJointAuditStudyBaseSurfaceRoughnessType0):
            surface_roughness = self.surface_roughness.value
        else:
            surface_roughness = self.surface_roughness

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

        tightening_torque: float | str | Unset
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

        static_friction_ratio_min: float | None | str | Unset
        if isinstance(self.static_friction_ratio_min, Unset):
            static_friction_ratio_min = UNSET
        else:
            static_friction_ratio_min = self.static_friction_ratio_min

        static_friction_ratio_max: float | None | str | Unset
        if isinstance(self.static_friction_ratio_max, Unset):
            static_friction_ratio_max = UNSET
        else:
            static_friction_ratio_max = self.static_friction_ratio_max

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
        if bearing_outer_diameter is not UNSET:
            field_dict["bearing_outer_diameter"] = bearing_outer_diameter
        if hole_diameter is not UNSET:
            field_dict["hole_diameter"] = hole_diameter
        if hole_series is not UNSET:
            field_dict["hole_series"] = hole_series
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
        if plate1_thickness is not UNSET:
            field_dict["plate1_thickness"] = plate1_thickness
        if plate1_youngs_modulus is not UNSET:
            field_dict["plate1_youngs_modulus"] = plate1_youngs_modulus
        if plate2_thickness is not UNSET:
            field_dict["plate2_thickness"] = plate2_thickness
        if plate2_youngs_modulus is not UNSET:
            field_dict["plate2_youngs_modulus"] = plate2_youngs_modulus
        if plate2_outer_diameter is not UNSET:
            field_dict["plate2_outer_diameter"] = plate2_outer_diameter
        if plate3_thickness is not UNSET:
            field_dict["plate3_thickness"] = plate3_thickness
        if plate3_youngs_modulus is not UNSET:
            field_dict["plate3_youngs_modulus"] = plate3_youngs_modulus
        if plate3_outer_diameter is not UNSET:
            field_dict["plate3_outer_diameter"] = plate3_outer_diameter
        if outer_diameter is not UNSET:
            field_dict["outer_diameter"] = outer_diameter
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
        if transverse_load is not UNSET:
            field_dict["transverse_load"] = transverse_load
        if fitted_diameter is not UNSET:
            field_dict["fitted_diameter"] = fitted_diameter
        if torsional_moment is not UNSET:
            field_dict["torsional_moment"] = torsional_moment
        if torque_interfaces is not UNSET:
            field_dict["torque_interfaces"] = torque_interfaces
        if friction_radius is not UNSET:
            field_dict["friction_radius"] = friction_radius
        if surface_roughness is not UNSET:
            field_dict["surface_roughness"] = surface_roughness
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
        if tightening_torque is not UNSET:
            field_dict["tightening_torque"] = tightening_torque
        if torque_tolerance is not UNSET:
            field_dict["torque_tolerance"] = torque_tolerance
        if prevailing_torque is not UNSET:
            field_dict["prevailing_torque"] = prevailing_torque
        if prevailing_torque_min is not UNSET:
            field_dict["prevailing_torque_min"] = prevailing_torque_min
        if static_friction_ratio_min is not UNSET:
            field_dict["static_friction_ratio_min"] = static_friction_ratio_min
        if static_friction_ratio_max is not UNSET:
            field_dict["static_friction_ratio_max"] = static_friction_ratio_max

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
        ) -> JointAuditStudyRequestJointAuditStudyBasePropertyClassType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                property_class_type_0 = JointAuditStudyRequestJointAuditStudyBasePropertyClassType0(data)

                return property_class_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointAuditStudyRequestJointAuditStudyBasePropertyClassType0 | None | Unset, data)

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

        def _parse_hole_series(data: object) -> JointAuditStudyRequestJointAuditStudyBaseHoleSeriesType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                hole_series_type_0 = JointAuditStudyRequestJointAuditStudyBaseHoleSeriesType0(data)

                return hole_series_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointAuditStudyRequestJointAuditStudyBaseHoleSeriesType0 | None | Unset, data)

        hole_series = _parse_hole_series(d.pop("hole_series", UNSET))

        def _parse_head(data: object) -> JointAuditStudyRequestJointAuditStudyBaseHeadType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                head_type_0 = JointAuditStudyRequestJointAuditStudyBaseHeadType0(data)

                return head_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointAuditStudyRequestJointAuditStudyBaseHeadType0 | None | Unset, data)

        head = _parse_head(d.pop("head", UNSET))

        def _parse_joint_type(data: object) -> JointAuditStudyRequestJointAuditStudyBaseJointTypeType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                joint_type_type_0 = JointAuditStudyRequestJointAuditStudyBaseJointTypeType0(data)

                return joint_type_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointAuditStudyRequestJointAuditStudyBaseJointTypeType0 | None | Unset, data)

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

        def _parse_plate1_thickness(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        plate1_thickness = _parse_plate1_thickness(d.pop("plate1_thickness", UNSET))

        def _parse_plate1_youngs_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate1_youngs_modulus = _parse_plate1_youngs_modulus(d.pop("plate1_youngs_modulus", UNSET))

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

        def _parse_transverse_load(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        transverse_load = _parse_transverse_load(d.pop("transverse_load", UNSET))

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

        def _parse_surface_roughness(
            data: object,
        ) -> JointAuditStudyRequestJointAuditStudyBaseSurfaceRoughnessType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                surface_roughness_type_0 = JointAuditStudyRequestJointAuditStudyBaseSurfaceRoughnessType0(data)

                return surface_roughness_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointAuditStudyRequestJointAuditStudyBaseSurfaceRoughnessType0 | None | Unset, data)

        surface_roughness = _parse_surface_roughness(d.pop("surface_roughness", UNSET))

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

        def _parse_tightening_torque(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

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

        def _parse_static_friction_ratio_min(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        static_friction_ratio_min = _parse_static_friction_ratio_min(d.pop("static_friction_ratio_min", UNSET))

        def _parse_static_friction_ratio_max(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        static_friction_ratio_max = _parse_static_friction_ratio_max(d.pop("static_friction_ratio_max", UNSET))

        joint_audit_study_request_joint_audit_study_base = cls(
            thread=thread,
            grade=grade,
            thread_diameter=thread_diameter,
            thread_pitch=thread_pitch,
            property_class=property_class,
            yield_strength=yield_strength,
            bearing_outer_diameter=bearing_outer_diameter,
            hole_diameter=hole_diameter,
            hole_series=hole_series,
            head=head,
            joint_type=joint_type,
            shank_length=shank_length,
            shank_diameter=shank_diameter,
            reduced_length=reduced_length,
            reduced_diameter=reduced_diameter,
            youngs_modulus=youngs_modulus,
            nut_youngs_modulus=nut_youngs_modulus,
            plate1_thickness=plate1_thickness,
            plate1_youngs_modulus=plate1_youngs_modulus,
            plate2_thickness=plate2_thickness,
            plate2_youngs_modulus=plate2_youngs_modulus,
            plate2_outer_diameter=plate2_outer_diameter,
            plate3_thickness=plate3_thickness,
            plate3_youngs_modulus=plate3_youngs_modulus,
            plate3_outer_diameter=plate3_outer_diameter,
            outer_diameter=outer_diameter,
            bolt_offset=bolt_offset,
            load_lever=load_lever,
            opening_edge=opening_edge,
            interface_length=interface_length,
            interface_width=interface_width,
            transverse_load=transverse_load,
            fitted_diameter=fitted_diameter,
            torsional_moment=torsional_moment,
            torque_interfaces=torque_interfaces,
            friction_radius=friction_radius,
            surface_roughness=surface_roughness,
            service_temperature=service_temperature,
            thread_friction_min=thread_friction_min,
            thread_friction_max=thread_friction_max,
            bearing_friction_min=bearing_friction_min,
            bearing_friction_max=bearing_friction_max,
            tightening_torque=tightening_torque,
            torque_tolerance=torque_tolerance,
            prevailing_torque=prevailing_torque,
            prevailing_torque_min=prevailing_torque_min,
            static_friction_ratio_min=static_friction_ratio_min,
            static_friction_ratio_max=static_friction_ratio_max,
        )

        return joint_audit_study_request_joint_audit_study_base
