from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.blow_joint_study_request_blow_joint_study_base_joint_rate_from_type_0 import (
    BlowJointStudyRequestBlowJointStudyBaseJointRateFromType0,
)
from ..models.blow_joint_study_request_blow_joint_study_base_property_class_type_0 import (
    BlowJointStudyRequestBlowJointStudyBasePropertyClassType0,
)
from ..models.blow_joint_study_request_blow_joint_study_base_roller_geometry_type_0 import (
    BlowJointStudyRequestBlowJointStudyBaseRollerGeometryType0,
)
from ..models.blow_joint_study_request_blow_joint_study_base_source_type_0 import (
    BlowJointStudyRequestBlowJointStudyBaseSourceType0,
)
from ..models.blow_joint_study_request_blow_joint_study_base_spring_arrangement_type_0 import (
    BlowJointStudyRequestBlowJointStudyBaseSpringArrangementType0,
)
from ..models.blow_joint_study_request_blow_joint_study_base_torque_formula_type_0 import (
    BlowJointStudyRequestBlowJointStudyBaseTorqueFormulaType0,
)
from ..types import UNSET, Unset

T = TypeVar("T", bound="BlowJointStudyRequestBlowJointStudyBase")


@_attrs_define
class BlowJointStudyRequestBlowJointStudyBase:
    """inputs held fixed (defaults fill the rest)

    Attributes:
        source (BlowJointStudyRequestBlowJointStudyBaseSourceType0 | None | Unset): what strikes the joint: a raw energy
            and inertia ('energy'), the nut-runner's drive [000] ('nutrunner'), the rare-impact wrench's flywheel and
            rollers at impact.rare's release speed [002] ('rare_impact'), or a continuous tool limited by a ball clutch
            [001] ('clutch') Default: BlowJointStudyRequestBlowJointStudyBaseSourceType0.ENERGY.
        tool_energy (float | None | str | Unset): kinetic energy of the tool at the blow (source energy)
        tool_inertia (float | None | str | Unset): inertia of the striking tool J_t (source energy)
        tool_stiffness (float | None | str | Unset): torsional stiffness C between tool inertia and nut (anvil, spindle,
            socket); computed from shaft 7 and spindle 8 for the nut-runner [000, eq. 9]
        drive_torque (float | None | str | Unset): torque that keeps driving the tool during the blow (e.g. the motor),
            at the nut; absent: none
        coupling_slip_torque (float | None | str | Unset): slipping torque of the nut-runner's safety coupling 1 at the
            motor shaft, fed into the blow while it slips [000, text] (source nutrunner); absent: none
        blow_efficiency (float | None | str | Unset): fraction of the source's kinetic energy that reaches the blow (jaw
            engagement losses) Default: 1.0.
        motor_speed (float | None | str | Unset): Motor shaft speed ω at the end of spin-up (the working speed at
            impact) [000, eq. 3–5] (source nut-runner)
        coupling_mass (float | None | str | Unset): Mass of the safety coupling 1, a solid uniform disc [000, eq. 3–4]
            (source nut-runner)
        coupling_diameter (float | None | str | Unset): Outer diameter of the safety coupling 1, a solid uniform disc
            [000, eq. 3–4] (source nut-runner)
        motor_pulley_mass (float | None | str | Unset): Mass of the motor pulley 2, a solid uniform disc [000, eq. 3–4]
            (source nut-runner)
        motor_pulley_diameter (float | None | str | Unset): Diameter of the motor pulley 2, also taken as the belt's
            pitch diameter [000, eq. 3–5] (source nut-runner)
        flywheel_mass (float | None | str | Unset): Mass of the flywheel 3 (the driven pulley), a solid uniform disc
            [000, eq. 3–4] (source nut-runner)
        flywheel_diameter (float | None | str | Unset): Diameter of the flywheel 3 (the driven pulley), also taken as
            the belt's pitch diameter [000, eq. 3–5] (source nut-runner)
        drive_gear_mass (float | None | str | Unset): Mass of the drive gear 4, a solid uniform disc [000, eq. 3–4]
            (source nut-runner)
        drive_gear_diameter (float | None | str | Unset): Pitch diameter of the drive gear 4, also taken as its disc
            diameter [000, eq. 3–5] (source nut-runner)
        spindle_gear_mass (float | None | str | Unset): Mass of one spindle gear 5, a solid uniform disc [000, eq. 3–4]
            (source nut-runner)
        spindle_gear_diameter (float | None | str | Unset): Pitch diameter of one spindle gear 5, also taken as its disc
            diameter [000, eq. 3–5] (source nut-runner)
        spindle_count (int | None | str | Unset): Number of spindles z (one per wheel nut) [000, eq. 4, 10] (source nut-
            runner)
        shaft_diameter (float | None | str | Unset): Diameter of the flywheel shaft 7 [000, eq. 9] (source nut-runner)
        shaft_length (float | None | str | Unset): Twisted length of the flywheel shaft 7 [000, eq. 9] (source nut-
            runner)
        spindle_diameter (float | None | str | Unset): Diameter of a spindle 8 [000, eq. 9] (source nut-runner)
        spindle_length (float | None | str | Unset): Twisted length of a spindle 8 [000, eq. 9] (source nut-runner)
        shear_modulus (float | None | str | Unset): Shear modulus G of shaft and spindle; 8·10¹⁰ Pa (steel) in the
            source [000, eq. 9] (source nut-runner) Default: 80000000000.0.
        idle_spindle_friction_torque (float | None | str | Unset): Friction-clutch torque M_tr of each idle spindle,
            taken off the blow [000, eq. 10] (source nut-runner)
        motor_power (float | None | str | Unset): Motor power P, delivered at constant power during spin-up [000, eq. 2,
            5] (source nut-runner)
        flywheel_inertia (float | None | str | Unset): I_M: moment of inertia of the flywheel with half-coupling, shaft
            and striker [002, eq. 1] (source rare-impact)
        roller_mass (float | None | str | Unset): m_p: mass of one centrifugal roller [002, eq. 1] (source rare-impact)
        roller_count (int | None | str | Unset): n: number of centrifugal rollers [002, eq. 1] (source rare-impact)
        roller_radius (float | None | str | Unset): x_0: radius of the rollers' centres at rest [002, eq. 1] (source
            rare-impact)
        cone_angle (float | None | str | Unset): α: angle of the conical faces of half-coupling and striker [002, eq.
            1]; the paper's closed form is for 45° (source rare-impact)
        power_spring_rate (float | None | str | Unset): c_1: rate of the power spring [002, eq. 1] (source rare-impact)
        power_spring_preload (float | None | str | Unset): λ_1: preload deflection of the power spring [002, eq. 1]
            (source rare-impact)
        auxiliary_spring_rate (float | None | str | Unset): c_2: rate of the auxiliary spring [002, eq. 1] (source rare-
            impact)
        auxiliary_spring_preload (float | None | str | Unset): λ_2: preload deflection of the auxiliary spring [002, eq.
            1] (source rare-impact)
        release_travel (float | None | str | Unset): h_1: axial travel of half-coupling and shaft at which the striker
            is released [002, eq. 1] (source rare-impact)
        roller_geometry (BlowJointStudyRequestBlowJointStudyBaseRollerGeometryType0 | None | Unset): how the rollers sit
            between the cones (engine/procedures/striker_cycle.py draws them): 'symmetric_v' both faces conical, x = x0 +
            z1/(2 tan α), the paper's 45° release speed; 'single_cone' only the half-coupling's face conical, the printed
            constraint z1 = x1 tan α with consistent forces; 'paper' the printed [002, eq. 1] as it stands (its forces do
            not balance; for reproducing the paper) (source rare-impact) Default:
            BlowJointStudyRequestBlowJointStudyBaseRollerGeometryType0.SYMMETRIC_V.
        half_coupling_mass (float | None | str | Unset): m_1: mass of the half-coupling [002, eq. 1] (source rare-
            impact) Default: 0.15.
        stepped_shaft_mass (float | None | str | Unset): m_2: mass of the stepped central shaft [002, eq. 1] (source
            rare-impact) Default: 0.05.
        gravity (float | None | str | Unset): g: gravity along the stroke towards the anvil [002, eqs. 2-4]; 9.80665 for
            the paper's vertical tool, 0 for a horizontal one, negative for a tool pointing up (source rare-impact) Default:
            9.80665.
        motor_torque (float | None | str | Unset): M: motor torque on the flywheel (the stall torque when a no-load
            speed is given) [002, eq. 1] (source rare-impact) Default: 5.0.
        motor_no_load_speed (float | None | str | Unset): ω_nl: optional; given, the motor torque falls linearly from
            the stall torque to 0 at this speed; absent, the torque is constant (source rare-impact)
        ball_circle_diameter (float | None | str | Unset): D0, diameter of the circle of ball centres [001, eq. 1]
            (source clutch)
        groove_angle (float | None | str | Unset): α, flank angle of the grooves; F_a = F_t tan α [001, eq. 1]; the
            source recommends 20…70° (source clutch)
        ball_count (int | None | str | Unset): i, number of balls [001, eq. 1] (source clutch)
        load_factor (float | None | str | Unset): K_r, load non-uniformity factor between the balls, 0.85…0.9 [001, eq.
            1] (source clutch)
        flank_friction (float | None | str | Unset): f, Coulomb friction between ball and flank; the axial push becomes
            F_t tan(α − atan f); 0 is the paper's frictionless case [001, eq. 3] (source clutch)
        spring_arrangement (BlowJointStudyRequestBlowJointStudyBaseSpringArrangementType0 | None | Unset): 'common': one
            spring presses all balls through the disk (the paper's fig. 1), T = D0 F/(2 tan(α−ρ)); 'per_ball': each ball has
            its own spring, T = K_r D0 i F/(2 tan(α−ρ)), the paper's published formula [001, eq. 3] (source clutch) Default:
            BlowJointStudyRequestBlowJointStudyBaseSpringArrangementType0.COMMON.
        clutch_spring_force (float | None | str | Unset): force of the clutch spring (source clutch) [001, eq. 2]
        spring_force_tolerance (float | None | str | Unset): ± relative tolerance of the clutch spring force (source
            clutch) Default: 0.1.
        flank_friction_scatter (float | None | str | Unset): ± scatter of the clutch's flank friction (source clutch)
            Default: 0.03.
        struck_inertia (float | None | str | Unset): inertia of socket, extension and nut J_s (simulation) Default:
            0.0005.
        breakaway_factor (float | None | str | Unset): b: a nut at rest turns only when the torque exceeds b × the joint
            torque (static over kinetic friction) Default: 1.0.
        restitution (float | None | str | Unset): coefficient of restitution of the blow (1: lossless spring;
            simulation) Default: 1.0.
        joint_rate_from (BlowJointStudyRequestBlowJointStudyBaseJointRateFromType0 | None | Unset): the joint's torque
            rate: ISO 5393 hard (30° snug to target) or soft (720°) test joint, the joint's compliances and thread
            ('joint'), or a number Default: BlowJointStudyRequestBlowJointStudyBaseJointRateFromType0.ISO5393_HARD.
        joint_rate (float | None | str | Unset): torque rate k_j of the joint ('number'); 0 with snug_torque 0: a free
            struck side (the two-flywheel impact, simulation rung)
        snug_torque (float | None | str | Unset): joint torque when the blows start Default: 0.0.
        target_torque (float | None | str | Unset): target joint torque
        target_preload (float | None | str | Unset): target preload (needs the thread)
        preload_min (float | None | str | Unset): lowest acceptable preload
        preload_max (float | None | str | Unset): highest acceptable preload
        thread_diameter (float | None | str | Unset): nominal thread diameter d (for preload)
        thread_pitch (float | None | str | Unset): pitch P (ISO 261 coarse when absent)
        thread_friction (float | None | str | Unset): μ_G Default: 0.12.
        bearing_friction (float | None | str | Unset): μ_K Default: 0.12.
        friction_scatter (float | None | str | Unset): ± scatter of μ_G and μ_K (clutch window) Default: 0.02.
        bearing_outer_diameter (float | None | str | Unset): D_f = d_w (ISO 4017 when absent)
        hole_diameter (float | None | str | Unset): d_h (ISO 273 medium when absent)
        property_class (BlowJointStudyRequestBlowJointStudyBasePropertyClassType0 | None | Unset): ISO 898-1 property
            class: minimum yield and tensile strength (8.8: 640/800 MPa up to M16, 660/830 MPa above) Default:
            BlowJointStudyRequestBlowJointStudyBasePropertyClassType0.VALUE_5.
        yield_strength (float | None | str | Unset): Minimum yield strength R_p0.2 (σ_T in [004]); overrides the
            property class
        torque_formula (BlowJointStudyRequestBlowJointStudyBaseTorqueFormulaType0 | None | Unset): tightening relation
            Default: BlowJointStudyRequestBlowJointStudyBaseTorqueFormulaType0.VDI2230.
        bolt_compliance (float | None | str | Unset): δ_S (from clamped_length when absent) [004, eq. 4, 7]
        clamped_compliance (float | None | str | Unset): δ_P of the clamped parts ('joint'; absent: VDI 2230-1 R3 cone
            over clamped_length)
        clamped_length (float | None | str | Unset): clamp length l_K (bolt compliance when δ_S is absent)
        youngs_modulus (float | None | str | Unset): E of the bolt (and of the plates for the cone) Default:
            210000000000.0.
        max_blows (int | None | str | Unset): most blows to try Default: 100.
    """

    source: BlowJointStudyRequestBlowJointStudyBaseSourceType0 | None | Unset = (
        BlowJointStudyRequestBlowJointStudyBaseSourceType0.ENERGY
    )
    tool_energy: float | None | str | Unset = UNSET
    tool_inertia: float | None | str | Unset = UNSET
    tool_stiffness: float | None | str | Unset = UNSET
    drive_torque: float | None | str | Unset = UNSET
    coupling_slip_torque: float | None | str | Unset = UNSET
    blow_efficiency: float | None | str | Unset = 1.0
    motor_speed: float | None | str | Unset = UNSET
    coupling_mass: float | None | str | Unset = UNSET
    coupling_diameter: float | None | str | Unset = UNSET
    motor_pulley_mass: float | None | str | Unset = UNSET
    motor_pulley_diameter: float | None | str | Unset = UNSET
    flywheel_mass: float | None | str | Unset = UNSET
    flywheel_diameter: float | None | str | Unset = UNSET
    drive_gear_mass: float | None | str | Unset = UNSET
    drive_gear_diameter: float | None | str | Unset = UNSET
    spindle_gear_mass: float | None | str | Unset = UNSET
    spindle_gear_diameter: float | None | str | Unset = UNSET
    spindle_count: int | None | str | Unset = UNSET
    shaft_diameter: float | None | str | Unset = UNSET
    shaft_length: float | None | str | Unset = UNSET
    spindle_diameter: float | None | str | Unset = UNSET
    spindle_length: float | None | str | Unset = UNSET
    shear_modulus: float | None | str | Unset = 80000000000.0
    idle_spindle_friction_torque: float | None | str | Unset = UNSET
    motor_power: float | None | str | Unset = UNSET
    flywheel_inertia: float | None | str | Unset = UNSET
    roller_mass: float | None | str | Unset = UNSET
    roller_count: int | None | str | Unset = UNSET
    roller_radius: float | None | str | Unset = UNSET
    cone_angle: float | None | str | Unset = UNSET
    power_spring_rate: float | None | str | Unset = UNSET
    power_spring_preload: float | None | str | Unset = UNSET
    auxiliary_spring_rate: float | None | str | Unset = UNSET
    auxiliary_spring_preload: float | None | str | Unset = UNSET
    release_travel: float | None | str | Unset = UNSET
    roller_geometry: BlowJointStudyRequestBlowJointStudyBaseRollerGeometryType0 | None | Unset = (
        BlowJointStudyRequestBlowJointStudyBaseRollerGeometryType0.SYMMETRIC_V
    )
    half_coupling_mass: float | None | str | Unset = 0.15
    stepped_shaft_mass: float | None | str | Unset = 0.05
    gravity: float | None | str | Unset = 9.80665
    motor_torque: float | None | str | Unset = 5.0
    motor_no_load_speed: float | None | str | Unset = UNSET
    ball_circle_diameter: float | None | str | Unset = UNSET
    groove_angle: float | None | str | Unset = UNSET
    ball_count: int | None | str | Unset = UNSET
    load_factor: float | None | str | Unset = UNSET
    flank_friction: float | None | str | Unset = UNSET
    spring_arrangement: BlowJointStudyRequestBlowJointStudyBaseSpringArrangementType0 | None | Unset = (
        BlowJointStudyRequestBlowJointStudyBaseSpringArrangementType0.COMMON
    )
    clutch_spring_force: float | None | str | Unset = UNSET
    spring_force_tolerance: float | None | str | Unset = 0.1
    flank_friction_scatter: float | None | str | Unset = 0.03
    struck_inertia: float | None | str | Unset = 0.0005
    breakaway_factor: float | None | str | Unset = 1.0
    restitution: float | None | str | Unset = 1.0
    joint_rate_from: BlowJointStudyRequestBlowJointStudyBaseJointRateFromType0 | None | Unset = (
        BlowJointStudyRequestBlowJointStudyBaseJointRateFromType0.ISO5393_HARD
    )
    joint_rate: float | None | str | Unset = UNSET
    snug_torque: float | None | str | Unset = 0.0
    target_torque: float | None | str | Unset = UNSET
    target_preload: float | None | str | Unset = UNSET
    preload_min: float | None | str | Unset = UNSET
    preload_max: float | None | str | Unset = UNSET
    thread_diameter: float | None | str | Unset = UNSET
    thread_pitch: float | None | str | Unset = UNSET
    thread_friction: float | None | str | Unset = 0.12
    bearing_friction: float | None | str | Unset = 0.12
    friction_scatter: float | None | str | Unset = 0.02
    bearing_outer_diameter: float | None | str | Unset = UNSET
    hole_diameter: float | None | str | Unset = UNSET
    property_class: BlowJointStudyRequestBlowJointStudyBasePropertyClassType0 | None | Unset = (
        BlowJointStudyRequestBlowJointStudyBasePropertyClassType0.VALUE_5
    )
    yield_strength: float | None | str | Unset = UNSET
    torque_formula: BlowJointStudyRequestBlowJointStudyBaseTorqueFormulaType0 | None | Unset = (
        BlowJointStudyRequestBlowJointStudyBaseTorqueFormulaType0.VDI2230
    )
    bolt_compliance: float | None | str | Unset = UNSET
    clamped_compliance: float | None | str | Unset = UNSET
    clamped_length: float | None | str | Unset = UNSET
    youngs_modulus: float | None | str | Unset = 210000000000.0
    max_blows: int | None | str | Unset = 100

    def to_dict(self) -> dict[str, Any]:
        source: None | str | Unset
        if isinstance(self.source, Unset):
            source = UNSET
        elif isinstance(self.source, BlowJointStudyRequestBlowJointStudyBaseSourceType0):
            source = self.source.value
        else:
            source = self.source

        tool_energy: float | None | str | Unset
        if isinstance(self.tool_energy, Unset):
            tool_energy = UNSET
        else:
            tool_energy = self.tool_energy

        tool_inertia: float | None | str | Unset
        if isinstance(self.tool_inertia, Unset):
            tool_inertia = UNSET
        else:
            tool_inertia = self.tool_inertia

        tool_stiffness: float | None | str | Unset
        if isinstance(self.tool_stiffness, Unset):
            tool_stiffness = UNSET
        else:
            tool_stiffness = self.tool_stiffness

        drive_torque: float | None | str | Unset
        if isinstance(self.drive_torque, Unset):
            drive_torque = UNSET
        else:
            drive_torque = self.drive_torque

        coupling_slip_torque: float | None | str | Unset
        if isinstance(self.coupling_slip_torque, Unset):
            coupling_slip_torque = UNSET
        else:
            coupling_slip_torque = self.coupling_slip_torque

        blow_efficiency: float | None | str | Unset
        if isinstance(self.blow_efficiency, Unset):
            blow_efficiency = UNSET
        else:
            blow_efficiency = self.blow_efficiency

        motor_speed: float | None | str | Unset
        if isinstance(self.motor_speed, Unset):
            motor_speed = UNSET
        else:
            motor_speed = self.motor_speed

        coupling_mass: float | None | str | Unset
        if isinstance(self.coupling_mass, Unset):
            coupling_mass = UNSET
        else:
            coupling_mass = self.coupling_mass

        coupling_diameter: float | None | str | Unset
        if isinstance(self.coupling_diameter, Unset):
            coupling_diameter = UNSET
        else:
            coupling_diameter = self.coupling_diameter

        motor_pulley_mass: float | None | str | Unset
        if isinstance(self.motor_pulley_mass, Unset):
            motor_pulley_mass = UNSET
        else:
            motor_pulley_mass = self.motor_pulley_mass

        motor_pulley_diameter: float | None | str | Unset
        if isinstance(self.motor_pulley_diameter, Unset):
            motor_pulley_diameter = UNSET
        else:
            motor_pulley_diameter = self.motor_pulley_diameter

        flywheel_mass: float | None | str | Unset
        if isinstance(self.flywheel_mass, Unset):
            flywheel_mass = UNSET
        else:
            flywheel_mass = self.flywheel_mass

        flywheel_diameter: float | None | str | Unset
        if isinstance(self.flywheel_diameter, Unset):
            flywheel_diameter = UNSET
        else:
            flywheel_diameter = self.flywheel_diameter

        drive_gear_mass: float | None | str | Unset
        if isinstance(self.drive_gear_mass, Unset):
            drive_gear_mass = UNSET
        else:
            drive_gear_mass = self.drive_gear_mass

        drive_gear_diameter: float | None | str | Unset
        if isinstance(self.drive_gear_diameter, Unset):
            drive_gear_diameter = UNSET
        else:
            drive_gear_diameter = self.drive_gear_diameter

        spindle_gear_mass: float | None | str | Unset
        if isinstance(self.spindle_gear_mass, Unset):
            spindle_gear_mass = UNSET
        else:
            spindle_gear_mass = self.spindle_gear_mass

        spindle_gear_diameter: float | None | str | Unset
        if isinstance(self.spindle_gear_diameter, Unset):
            spindle_gear_diameter = UNSET
        else:
            spindle_gear_diameter = self.spindle_gear_diameter

        spindle_count: int | None | str | Unset
        if isinstance(self.spindle_count, Unset):
            spindle_count = UNSET
        else:
            spindle_count = self.spindle_count

        shaft_diameter: float | None | str | Unset
        if isinstance(self.shaft_diameter, Unset):
            shaft_diameter = UNSET
        else:
            shaft_diameter = self.shaft_diameter

        shaft_length: float | None | str | Unset
        if isinstance(self.shaft_length, Unset):
            shaft_length = UNSET
        else:
            shaft_length = self.shaft_length

        spindle_diameter: float | None | str | Unset
        if isinstance(self.spindle_diameter, Unset):
            spindle_diameter = UNSET
        else:
            spindle_diameter = self.spindle_diameter

        spindle_length: float | None | str | Unset
        if isinstance(self.spindle_length, Unset):
            spindle_length = UNSET
        else:
            spindle_length = self.spindle_length

        shear_modulus: float | None | str | Unset
        if isinstance(self.shear_modulus, Unset):
            shear_modulus = UNSET
        else:
            shear_modulus = self.shear_modulus

        idle_spindle_friction_torque: float | None | str | Unset
        if isinstance(self.idle_spindle_friction_torque, Unset):
            idle_spindle_friction_torque = UNSET
        else:
            idle_spindle_friction_torque = self.idle_spindle_friction_torque

        motor_power: float | None | str | Unset
        if isinstance(self.motor_power, Unset):
            motor_power = UNSET
        else:
            motor_power = self.motor_power

        flywheel_inertia: float | None | str | Unset
        if isinstance(self.flywheel_inertia, Unset):
            flywheel_inertia = UNSET
        else:
            flywheel_inertia = self.flywheel_inertia

        roller_mass: float | None | str | Unset
        if isinstance(self.roller_mass, Unset):
            roller_mass = UNSET
        else:
            roller_mass = self.roller_mass

        roller_count: int | None | str | Unset
        if isinstance(self.roller_count, Unset):
            roller_count = UNSET
        else:
            roller_count = self.roller_count

        roller_radius: float | None | str | Unset
        if isinstance(self.roller_radius, Unset):
            roller_radius = UNSET
        else:
            roller_radius = self.roller_radius

        cone_angle: float | None | str | Unset
        if isinstance(self.cone_angle, Unset):
            cone_angle = UNSET
        else:
            cone_angle = self.cone_angle

        power_spring_rate: float | None | str | Unset
        if isinstance(self.power_spring_rate, Unset):
            power_spring_rate = UNSET
        else:
            power_spring_rate = self.power_spring_rate

        power_spring_preload: float | None | str | Unset
        if isinstance(self.power_spring_preload, Unset):
            power_spring_preload = UNSET
        else:
            power_spring_preload = self.power_spring_preload

        auxiliary_spring_rate: float | None | str | Unset
        if isinstance(self.auxiliary_spring_rate, Unset):
            auxiliary_spring_rate = UNSET
        else:
            auxiliary_spring_rate = self.auxiliary_spring_rate

        auxiliary_spring_preload: float | None | str | Unset
        if isinstance(self.auxiliary_spring_preload, Unset):
            auxiliary_spring_preload = UNSET
        else:
            auxiliary_spring_preload = self.auxiliary_spring_preload

        release_travel: float | None | str | Unset
        if isinstance(self.release_travel, Unset):
            release_travel = UNSET
        else:
            release_travel = self.release_travel

        roller_geometry: None | str | Unset
        if isinstance(self.roller_geometry, Unset):
            roller_geometry = UNSET
        elif isinstance(self.roller_geometry, BlowJointStudyRequestBlowJointStudyBaseRollerGeometryType0):
            roller_geometry = self.roller_geometry.value
        else:
            roller_geometry = self.roller_geometry

        half_coupling_mass: float | None | str | Unset
        if isinstance(self.half_coupling_mass, Unset):
            half_coupling_mass = UNSET
        else:
            half_coupling_mass = self.half_coupling_mass

        stepped_shaft_mass: float | None | str | Unset
        if isinstance(self.stepped_shaft_mass, Unset):
            stepped_shaft_mass = UNSET
        else:
            stepped_shaft_mass = self.stepped_shaft_mass

        gravity: float | None | str | Unset
        if isinstance(self.gravity, Unset):
            gravity = UNSET
        else:
            gravity = self.gravity

        motor_torque: float | None | str | Unset
        if isinstance(self.motor_torque, Unset):
            motor_torque = UNSET
        else:
            motor_torque = self.motor_torque

        motor_no_load_speed: float | None | str | Unset
        if isinstance(self.motor_no_load_speed, Unset):
            motor_no_load_speed = UNSET
        else:
            motor_no_load_speed = self.motor_no_load_speed

        ball_circle_diameter: float | None | str | Unset
        if isinstance(self.ball_circle_diameter, Unset):
            ball_circle_diameter = UNSET
        else:
            ball_circle_diameter = self.ball_circle_diameter

        groove_angle: float | None | str | Unset
        if isinstance(self.groove_angle, Unset):
            groove_angle = UNSET
        else:
            groove_angle = self.groove_angle

        ball_count: int | None | str | Unset
        if isinstance(self.ball_count, Unset):
            ball_count = UNSET
        else:
            ball_count = self.ball_count

        load_factor: float | None | str | Unset
        if isinstance(self.load_factor, Unset):
            load_factor = UNSET
        else:
            load_factor = self.load_factor

        flank_friction: float | None | str | Unset
        if isinstance(self.flank_friction, Unset):
            flank_friction = UNSET
        else:
            flank_friction = self.flank_friction

        spring_arrangement: None | str | Unset
        if isinstance(self.spring_arrangement, Unset):
            spring_arrangement = UNSET
        elif isinstance(self.spring_arrangement, BlowJointStudyRequestBlowJointStudyBaseSpringArrangementType0):
            spring_arrangement = self.spring_arrangement.value
        else:
            spring_arrangement = self.spring_arrangement

        clutch_spring_force: float | None | str | Unset
        if isinstance(self.clutch_spring_force, Unset):
            clutch_spring_force = UNSET
        else:
            clutch_spring_force = self.clutch_spring_force

        spring_force_tolerance: float | None | str | Unset
        if isinstance(self.spring_force_tolerance, Unset):
            spring_force_tolerance = UNSET
        else:
            spring_force_tolerance = self.spring_force_tolerance

        flank_friction_scatter: float | None | str | Unset
        if isinstance(self.flank_friction_scatter, Unset):
            flank_friction_scatter = UNSET
        else:
            flank_friction_scatter = self.flank_friction_scatter

        struck_inertia: float | None | str | Unset
        if isinstance(self.struck_inertia, Unset):
            struck_inertia = UNSET
        else:
            struck_inertia = self.struck_inertia

        breakaway_factor: float | None | str | Unset
        if isinstance(self.breakaway_factor, Unset):
            breakaway_factor = UNSET
        else:
            breakaway_factor = self.breakaway_factor

        restitution: float | None | str | Unset
        if isinstance(self.restitution, Unset):
            restitution = UNSET
        else:
            restitution = self.restitution

        joint_rate_from: None | str | Unset
        if isinstance(self.joint_rate_from, Unset):
            joint_rate_from = UNSET
        elif isinstance(self.joint_rate_from, BlowJointStudyRequestBlowJointStudyBaseJointRateFromType0):
            joint_rate_from = self.joint_rate_from.value
        else:
            joint_rate_from = self.joint_rate_from

        joint_rate: float | None | str | Unset
        if isinstance(self.joint_rate, Unset):
            joint_rate = UNSET
        else:
            joint_rate = self.joint_rate

        snug_torque: float | None | str | Unset
        if isinstance(self.snug_torque, Unset):
            snug_torque = UNSET
        else:
            snug_torque = self.snug_torque

        target_torque: float | None | str | Unset
        if isinstance(self.target_torque, Unset):
            target_torque = UNSET
        else:
            target_torque = self.target_torque

        target_preload: float | None | str | Unset
        if isinstance(self.target_preload, Unset):
            target_preload = UNSET
        else:
            target_preload = self.target_preload

        preload_min: float | None | str | Unset
        if isinstance(self.preload_min, Unset):
            preload_min = UNSET
        else:
            preload_min = self.preload_min

        preload_max: float | None | str | Unset
        if isinstance(self.preload_max, Unset):
            preload_max = UNSET
        else:
            preload_max = self.preload_max

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

        friction_scatter: float | None | str | Unset
        if isinstance(self.friction_scatter, Unset):
            friction_scatter = UNSET
        else:
            friction_scatter = self.friction_scatter

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

        property_class: None | str | Unset
        if isinstance(self.property_class, Unset):
            property_class = UNSET
        elif isinstance(self.property_class, BlowJointStudyRequestBlowJointStudyBasePropertyClassType0):
            property_class = self.property_class.value
        else:
            property_class = self.property_class

        yield_strength: float | None | str | Unset
        if isinstance(self.yield_strength, Unset):
            yield_strength = UNSET
        else:
            yield_strength = self.yield_strength

        torque_formula: None | str | Unset
        if isinstance(self.torque_formula, Unset):
            torque_formula = UNSET
        elif isinstance(self.torque_formula, BlowJointStudyRequestBlowJointStudyBaseTorqueFormulaType0):
            torque_formula = self.torque_formula.value
        else:
            torque_formula = self.torque_formula

        bolt_compliance: float | None | str | Unset
        if isinstance(self.bolt_compliance, Unset):
            bolt_compliance = UNSET
        else:
            bolt_compliance = self.bolt_compliance

        clamped_compliance: float | None | str | Unset
        if isinstance(self.clamped_compliance, Unset):
            clamped_compliance = UNSET
        else:
            clamped_compliance = self.clamped_compliance

        clamped_length: float | None | str | Unset
        if isinstance(self.clamped_length, Unset):
            clamped_length = UNSET
        else:
            clamped_length = self.clamped_length

        youngs_modulus: float | None | str | Unset
        if isinstance(self.youngs_modulus, Unset):
            youngs_modulus = UNSET
        else:
            youngs_modulus = self.youngs_modulus

        max_blows: int | None | str | Unset
        if isinstance(self.max_blows, Unset):
            max_blows = UNSET
        else:
            max_blows = self.max_blows

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if source is not UNSET:
            field_dict["source"] = source
        if tool_energy is not UNSET:
            field_dict["tool_energy"] = tool_energy
        if tool_inertia is not UNSET:
            field_dict["tool_inertia"] = tool_inertia
        if tool_stiffness is not UNSET:
            field_dict["tool_stiffness"] = tool_stiffness
        if drive_torque is not UNSET:
            field_dict["drive_torque"] = drive_torque
        if coupling_slip_torque is not UNSET:
            field_dict["coupling_slip_torque"] = coupling_slip_torque
        if blow_efficiency is not UNSET:
            field_dict["blow_efficiency"] = blow_efficiency
        if motor_speed is not UNSET:
            field_dict["motor_speed"] = motor_speed
        if coupling_mass is not UNSET:
            field_dict["coupling_mass"] = coupling_mass
        if coupling_diameter is not UNSET:
            field_dict["coupling_diameter"] = coupling_diameter
        if motor_pulley_mass is not UNSET:
            field_dict["motor_pulley_mass"] = motor_pulley_mass
        if motor_pulley_diameter is not UNSET:
            field_dict["motor_pulley_diameter"] = motor_pulley_diameter
        if flywheel_mass is not UNSET:
            field_dict["flywheel_mass"] = flywheel_mass
        if flywheel_diameter is not UNSET:
            field_dict["flywheel_diameter"] = flywheel_diameter
        if drive_gear_mass is not UNSET:
            field_dict["drive_gear_mass"] = drive_gear_mass
        if drive_gear_diameter is not UNSET:
            field_dict["drive_gear_diameter"] = drive_gear_diameter
        if spindle_gear_mass is not UNSET:
            field_dict["spindle_gear_mass"] = spindle_gear_mass
        if spindle_gear_diameter is not UNSET:
            field_dict["spindle_gear_diameter"] = spindle_gear_diameter
        if spindle_count is not UNSET:
            field_dict["spindle_count"] = spindle_count
        if shaft_diameter is not UNSET:
            field_dict["shaft_diameter"] = shaft_diameter
        if shaft_length is not UNSET:
            field_dict["shaft_length"] = shaft_length
        if spindle_diameter is not UNSET:
            field_dict["spindle_diameter"] = spindle_diameter
        if spindle_length is not UNSET:
            field_dict["spindle_length"] = spindle_length
        if shear_modulus is not UNSET:
            field_dict["shear_modulus"] = shear_modulus
        if idle_spindle_friction_torque is not UNSET:
            field_dict["idle_spindle_friction_torque"] = idle_spindle_friction_torque
        if motor_power is not UNSET:
            field_dict["motor_power"] = motor_power
        if flywheel_inertia is not UNSET:
            field_dict["flywheel_inertia"] = flywheel_inertia
        if roller_mass is not UNSET:
            field_dict["roller_mass"] = roller_mass
        if roller_count is not UNSET:
            field_dict["roller_count"] = roller_count
        if roller_radius is not UNSET:
            field_dict["roller_radius"] = roller_radius
        if cone_angle is not UNSET:
            field_dict["cone_angle"] = cone_angle
        if power_spring_rate is not UNSET:
            field_dict["power_spring_rate"] = power_spring_rate
        if power_spring_preload is not UNSET:
            field_dict["power_spring_preload"] = power_spring_preload
        if auxiliary_spring_rate is not UNSET:
            field_dict["auxiliary_spring_rate"] = auxiliary_spring_rate
        if auxiliary_spring_preload is not UNSET:
            field_dict["auxiliary_spring_preload"] = auxiliary_spring_preload
        if release_travel is not UNSET:
            field_dict["release_travel"] = release_travel
        if roller_geometry is not UNSET:
            field_dict["roller_geometry"] = roller_geometry
        if half_coupling_mass is not UNSET:
            field_dict["half_coupling_mass"] = half_coupling_mass
        if stepped_shaft_mass is not UNSET:
            field_dict["stepped_shaft_mass"] = stepped_shaft_mass
        if gravity is not UNSET:
            field_dict["gravity"] = gravity
        if motor_torque is not UNSET:
            field_dict["motor_torque"] = motor_torque
        if motor_no_load_speed is not UNSET:
            field_dict["motor_no_load_speed"] = motor_no_load_speed
        if ball_circle_diameter is not UNSET:
            field_dict["ball_circle_diameter"] = ball_circle_diameter
        if groove_angle is not UNSET:
            field_dict["groove_angle"] = groove_angle
        if ball_count is not UNSET:
            field_dict["ball_count"] = ball_count
        if load_factor is not UNSET:
            field_dict["load_factor"] = load_factor
        if flank_friction is not UNSET:
            field_dict["flank_friction"] = flank_friction
        if spring_arrangement is not UNSET:
            field_dict["spring_arrangement"] = spring_arrangement
        if clutch_spring_force is not UNSET:
            field_dict["clutch_spring_force"] = clutch_spring_force
        if spring_force_tolerance is not UNSET:
            field_dict["spring_force_tolerance"] = spring_force_tolerance
        if flank_friction_scatter is not UNSET:
            field_dict["flank_friction_scatter"] = flank_friction_scatter
        if struck_inertia is not UNSET:
            field_dict["struck_inertia"] = struck_inertia
        if breakaway_factor is not UNSET:
            field_dict["breakaway_factor"] = breakaway_factor
        if restitution is not UNSET:
            field_dict["restitution"] = restitution
        if joint_rate_from is not UNSET:
            field_dict["joint_rate_from"] = joint_rate_from
        if joint_rate is not UNSET:
            field_dict["joint_rate"] = joint_rate
        if snug_torque is not UNSET:
            field_dict["snug_torque"] = snug_torque
        if target_torque is not UNSET:
            field_dict["target_torque"] = target_torque
        if target_preload is not UNSET:
            field_dict["target_preload"] = target_preload
        if preload_min is not UNSET:
            field_dict["preload_min"] = preload_min
        if preload_max is not UNSET:
            field_dict["preload_max"] = preload_max
        if thread_diameter is not UNSET:
            field_dict["thread_diameter"] = thread_diameter
        if thread_pitch is not UNSET:
            field_dict["thread_pitch"] = thread_pitch
        if thread_friction is not UNSET:
            field_dict["thread_friction"] = thread_friction
        if bearing_friction is not UNSET:
            field_dict["bearing_friction"] = bearing_friction
        if friction_scatter is not UNSET:
            field_dict["friction_scatter"] = friction_scatter
        if bearing_outer_diameter is not UNSET:
            field_dict["bearing_outer_diameter"] = bearing_outer_diameter
        if hole_diameter is not UNSET:
            field_dict["hole_diameter"] = hole_diameter
        if property_class is not UNSET:
            field_dict["property_class"] = property_class
        if yield_strength is not UNSET:
            field_dict["yield_strength"] = yield_strength
        if torque_formula is not UNSET:
            field_dict["torque_formula"] = torque_formula
        if bolt_compliance is not UNSET:
            field_dict["bolt_compliance"] = bolt_compliance
        if clamped_compliance is not UNSET:
            field_dict["clamped_compliance"] = clamped_compliance
        if clamped_length is not UNSET:
            field_dict["clamped_length"] = clamped_length
        if youngs_modulus is not UNSET:
            field_dict["youngs_modulus"] = youngs_modulus
        if max_blows is not UNSET:
            field_dict["max_blows"] = max_blows

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_source(data: object) -> BlowJointStudyRequestBlowJointStudyBaseSourceType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                source_type_0 = BlowJointStudyRequestBlowJointStudyBaseSourceType0(data)

                return source_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(BlowJointStudyRequestBlowJointStudyBaseSourceType0 | None | Unset, data)

        source = _parse_source(d.pop("source", UNSET))

        def _parse_tool_energy(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        tool_energy = _parse_tool_energy(d.pop("tool_energy", UNSET))

        def _parse_tool_inertia(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        tool_inertia = _parse_tool_inertia(d.pop("tool_inertia", UNSET))

        def _parse_tool_stiffness(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        tool_stiffness = _parse_tool_stiffness(d.pop("tool_stiffness", UNSET))

        def _parse_drive_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        drive_torque = _parse_drive_torque(d.pop("drive_torque", UNSET))

        def _parse_coupling_slip_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        coupling_slip_torque = _parse_coupling_slip_torque(d.pop("coupling_slip_torque", UNSET))

        def _parse_blow_efficiency(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        blow_efficiency = _parse_blow_efficiency(d.pop("blow_efficiency", UNSET))

        def _parse_motor_speed(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        motor_speed = _parse_motor_speed(d.pop("motor_speed", UNSET))

        def _parse_coupling_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        coupling_mass = _parse_coupling_mass(d.pop("coupling_mass", UNSET))

        def _parse_coupling_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        coupling_diameter = _parse_coupling_diameter(d.pop("coupling_diameter", UNSET))

        def _parse_motor_pulley_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        motor_pulley_mass = _parse_motor_pulley_mass(d.pop("motor_pulley_mass", UNSET))

        def _parse_motor_pulley_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        motor_pulley_diameter = _parse_motor_pulley_diameter(d.pop("motor_pulley_diameter", UNSET))

        def _parse_flywheel_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        flywheel_mass = _parse_flywheel_mass(d.pop("flywheel_mass", UNSET))

        def _parse_flywheel_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        flywheel_diameter = _parse_flywheel_diameter(d.pop("flywheel_diameter", UNSET))

        def _parse_drive_gear_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        drive_gear_mass = _parse_drive_gear_mass(d.pop("drive_gear_mass", UNSET))

        def _parse_drive_gear_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        drive_gear_diameter = _parse_drive_gear_diameter(d.pop("drive_gear_diameter", UNSET))

        def _parse_spindle_gear_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        spindle_gear_mass = _parse_spindle_gear_mass(d.pop("spindle_gear_mass", UNSET))

        def _parse_spindle_gear_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        spindle_gear_diameter = _parse_spindle_gear_diameter(d.pop("spindle_gear_diameter", UNSET))

        def _parse_spindle_count(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        spindle_count = _parse_spindle_count(d.pop("spindle_count", UNSET))

        def _parse_shaft_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        shaft_diameter = _parse_shaft_diameter(d.pop("shaft_diameter", UNSET))

        def _parse_shaft_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        shaft_length = _parse_shaft_length(d.pop("shaft_length", UNSET))

        def _parse_spindle_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        spindle_diameter = _parse_spindle_diameter(d.pop("spindle_diameter", UNSET))

        def _parse_spindle_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        spindle_length = _parse_spindle_length(d.pop("spindle_length", UNSET))

        def _parse_shear_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        shear_modulus = _parse_shear_modulus(d.pop("shear_modulus", UNSET))

        def _parse_idle_spindle_friction_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        idle_spindle_friction_torque = _parse_idle_spindle_friction_torque(d.pop("idle_spindle_friction_torque", UNSET))

        def _parse_motor_power(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        motor_power = _parse_motor_power(d.pop("motor_power", UNSET))

        def _parse_flywheel_inertia(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        flywheel_inertia = _parse_flywheel_inertia(d.pop("flywheel_inertia", UNSET))

        def _parse_roller_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        roller_mass = _parse_roller_mass(d.pop("roller_mass", UNSET))

        def _parse_roller_count(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        roller_count = _parse_roller_count(d.pop("roller_count", UNSET))

        def _parse_roller_radius(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        roller_radius = _parse_roller_radius(d.pop("roller_radius", UNSET))

        def _parse_cone_angle(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        cone_angle = _parse_cone_angle(d.pop("cone_angle", UNSET))

        def _parse_power_spring_rate(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        power_spring_rate = _parse_power_spring_rate(d.pop("power_spring_rate", UNSET))

        def _parse_power_spring_preload(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        power_spring_preload = _parse_power_spring_preload(d.pop("power_spring_preload", UNSET))

        def _parse_auxiliary_spring_rate(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        auxiliary_spring_rate = _parse_auxiliary_spring_rate(d.pop("auxiliary_spring_rate", UNSET))

        def _parse_auxiliary_spring_preload(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        auxiliary_spring_preload = _parse_auxiliary_spring_preload(d.pop("auxiliary_spring_preload", UNSET))

        def _parse_release_travel(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        release_travel = _parse_release_travel(d.pop("release_travel", UNSET))

        def _parse_roller_geometry(
            data: object,
        ) -> BlowJointStudyRequestBlowJointStudyBaseRollerGeometryType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                roller_geometry_type_0 = BlowJointStudyRequestBlowJointStudyBaseRollerGeometryType0(data)

                return roller_geometry_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(BlowJointStudyRequestBlowJointStudyBaseRollerGeometryType0 | None | Unset, data)

        roller_geometry = _parse_roller_geometry(d.pop("roller_geometry", UNSET))

        def _parse_half_coupling_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        half_coupling_mass = _parse_half_coupling_mass(d.pop("half_coupling_mass", UNSET))

        def _parse_stepped_shaft_mass(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        stepped_shaft_mass = _parse_stepped_shaft_mass(d.pop("stepped_shaft_mass", UNSET))

        def _parse_gravity(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        gravity = _parse_gravity(d.pop("gravity", UNSET))

        def _parse_motor_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        motor_torque = _parse_motor_torque(d.pop("motor_torque", UNSET))

        def _parse_motor_no_load_speed(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        motor_no_load_speed = _parse_motor_no_load_speed(d.pop("motor_no_load_speed", UNSET))

        def _parse_ball_circle_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        ball_circle_diameter = _parse_ball_circle_diameter(d.pop("ball_circle_diameter", UNSET))

        def _parse_groove_angle(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        groove_angle = _parse_groove_angle(d.pop("groove_angle", UNSET))

        def _parse_ball_count(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        ball_count = _parse_ball_count(d.pop("ball_count", UNSET))

        def _parse_load_factor(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        load_factor = _parse_load_factor(d.pop("load_factor", UNSET))

        def _parse_flank_friction(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        flank_friction = _parse_flank_friction(d.pop("flank_friction", UNSET))

        def _parse_spring_arrangement(
            data: object,
        ) -> BlowJointStudyRequestBlowJointStudyBaseSpringArrangementType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                spring_arrangement_type_0 = BlowJointStudyRequestBlowJointStudyBaseSpringArrangementType0(data)

                return spring_arrangement_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(BlowJointStudyRequestBlowJointStudyBaseSpringArrangementType0 | None | Unset, data)

        spring_arrangement = _parse_spring_arrangement(d.pop("spring_arrangement", UNSET))

        def _parse_clutch_spring_force(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        clutch_spring_force = _parse_clutch_spring_force(d.pop("clutch_spring_force", UNSET))

        def _parse_spring_force_tolerance(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        spring_force_tolerance = _parse_spring_force_tolerance(d.pop("spring_force_tolerance", UNSET))

        def _parse_flank_friction_scatter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        flank_friction_scatter = _parse_flank_friction_scatter(d.pop("flank_friction_scatter", UNSET))

        def _parse_struck_inertia(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        struck_inertia = _parse_struck_inertia(d.pop("struck_inertia", UNSET))

        def _parse_breakaway_factor(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        breakaway_factor = _parse_breakaway_factor(d.pop("breakaway_factor", UNSET))

        def _parse_restitution(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        restitution = _parse_restitution(d.pop("restitution", UNSET))

        def _parse_joint_rate_from(
            data: object,
        ) -> BlowJointStudyRequestBlowJointStudyBaseJointRateFromType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                joint_rate_from_type_0 = BlowJointStudyRequestBlowJointStudyBaseJointRateFromType0(data)

                return joint_rate_from_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(BlowJointStudyRequestBlowJointStudyBaseJointRateFromType0 | None | Unset, data)

        joint_rate_from = _parse_joint_rate_from(d.pop("joint_rate_from", UNSET))

        def _parse_joint_rate(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        joint_rate = _parse_joint_rate(d.pop("joint_rate", UNSET))

        def _parse_snug_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        snug_torque = _parse_snug_torque(d.pop("snug_torque", UNSET))

        def _parse_target_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        target_torque = _parse_target_torque(d.pop("target_torque", UNSET))

        def _parse_target_preload(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        target_preload = _parse_target_preload(d.pop("target_preload", UNSET))

        def _parse_preload_min(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        preload_min = _parse_preload_min(d.pop("preload_min", UNSET))

        def _parse_preload_max(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        preload_max = _parse_preload_max(d.pop("preload_max", UNSET))

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

        def _parse_friction_scatter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        friction_scatter = _parse_friction_scatter(d.pop("friction_scatter", UNSET))

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

        def _parse_property_class(
            data: object,
        ) -> BlowJointStudyRequestBlowJointStudyBasePropertyClassType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                property_class_type_0 = BlowJointStudyRequestBlowJointStudyBasePropertyClassType0(data)

                return property_class_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(BlowJointStudyRequestBlowJointStudyBasePropertyClassType0 | None | Unset, data)

        property_class = _parse_property_class(d.pop("property_class", UNSET))

        def _parse_yield_strength(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        yield_strength = _parse_yield_strength(d.pop("yield_strength", UNSET))

        def _parse_torque_formula(
            data: object,
        ) -> BlowJointStudyRequestBlowJointStudyBaseTorqueFormulaType0 | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                torque_formula_type_0 = BlowJointStudyRequestBlowJointStudyBaseTorqueFormulaType0(data)

                return torque_formula_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(BlowJointStudyRequestBlowJointStudyBaseTorqueFormulaType0 | None | Unset, data)

        torque_formula = _parse_torque_formula(d.pop("torque_formula", UNSET))

        def _parse_bolt_compliance(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bolt_compliance = _parse_bolt_compliance(d.pop("bolt_compliance", UNSET))

        def _parse_clamped_compliance(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        clamped_compliance = _parse_clamped_compliance(d.pop("clamped_compliance", UNSET))

        def _parse_clamped_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        clamped_length = _parse_clamped_length(d.pop("clamped_length", UNSET))

        def _parse_youngs_modulus(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        youngs_modulus = _parse_youngs_modulus(d.pop("youngs_modulus", UNSET))

        def _parse_max_blows(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        max_blows = _parse_max_blows(d.pop("max_blows", UNSET))

        blow_joint_study_request_blow_joint_study_base = cls(
            source=source,
            tool_energy=tool_energy,
            tool_inertia=tool_inertia,
            tool_stiffness=tool_stiffness,
            drive_torque=drive_torque,
            coupling_slip_torque=coupling_slip_torque,
            blow_efficiency=blow_efficiency,
            motor_speed=motor_speed,
            coupling_mass=coupling_mass,
            coupling_diameter=coupling_diameter,
            motor_pulley_mass=motor_pulley_mass,
            motor_pulley_diameter=motor_pulley_diameter,
            flywheel_mass=flywheel_mass,
            flywheel_diameter=flywheel_diameter,
            drive_gear_mass=drive_gear_mass,
            drive_gear_diameter=drive_gear_diameter,
            spindle_gear_mass=spindle_gear_mass,
            spindle_gear_diameter=spindle_gear_diameter,
            spindle_count=spindle_count,
            shaft_diameter=shaft_diameter,
            shaft_length=shaft_length,
            spindle_diameter=spindle_diameter,
            spindle_length=spindle_length,
            shear_modulus=shear_modulus,
            idle_spindle_friction_torque=idle_spindle_friction_torque,
            motor_power=motor_power,
            flywheel_inertia=flywheel_inertia,
            roller_mass=roller_mass,
            roller_count=roller_count,
            roller_radius=roller_radius,
            cone_angle=cone_angle,
            power_spring_rate=power_spring_rate,
            power_spring_preload=power_spring_preload,
            auxiliary_spring_rate=auxiliary_spring_rate,
            auxiliary_spring_preload=auxiliary_spring_preload,
            release_travel=release_travel,
            roller_geometry=roller_geometry,
            half_coupling_mass=half_coupling_mass,
            stepped_shaft_mass=stepped_shaft_mass,
            gravity=gravity,
            motor_torque=motor_torque,
            motor_no_load_speed=motor_no_load_speed,
            ball_circle_diameter=ball_circle_diameter,
            groove_angle=groove_angle,
            ball_count=ball_count,
            load_factor=load_factor,
            flank_friction=flank_friction,
            spring_arrangement=spring_arrangement,
            clutch_spring_force=clutch_spring_force,
            spring_force_tolerance=spring_force_tolerance,
            flank_friction_scatter=flank_friction_scatter,
            struck_inertia=struck_inertia,
            breakaway_factor=breakaway_factor,
            restitution=restitution,
            joint_rate_from=joint_rate_from,
            joint_rate=joint_rate,
            snug_torque=snug_torque,
            target_torque=target_torque,
            target_preload=target_preload,
            preload_min=preload_min,
            preload_max=preload_max,
            thread_diameter=thread_diameter,
            thread_pitch=thread_pitch,
            thread_friction=thread_friction,
            bearing_friction=bearing_friction,
            friction_scatter=friction_scatter,
            bearing_outer_diameter=bearing_outer_diameter,
            hole_diameter=hole_diameter,
            property_class=property_class,
            yield_strength=yield_strength,
            torque_formula=torque_formula,
            bolt_compliance=bolt_compliance,
            clamped_compliance=clamped_compliance,
            clamped_length=clamped_length,
            youngs_modulus=youngs_modulus,
            max_blows=max_blows,
        )

        return blow_joint_study_request_blow_joint_study_base
