from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.preload_ultrasonic_study_request_preload_ultrasonic_study_base_head_type_0 import (
    PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHeadType0,
)
from ..models.preload_ultrasonic_study_request_preload_ultrasonic_study_base_hole_series_type_0 import (
    PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHoleSeriesType0,
)
from ..models.preload_ultrasonic_study_request_preload_ultrasonic_study_base_joint_type_type_0 import (
    PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseJointTypeType0,
)
from ..models.preload_ultrasonic_study_request_preload_ultrasonic_study_base_property_class_type_0 import (
    PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBasePropertyClassType0,
)
from ..types import UNSET, Unset

T = TypeVar("T", bound="PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBase")


@_attrs_define
class PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBase:
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
        property_class (None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBasePropertyClassType0 | Unset): ISO
            898-1 property class: minimum yield and tensile strength (8.8: 640/800 MPa up to M16, 660/830 MPa above)
            Default: PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBasePropertyClassType0.VALUE_5.
        yield_strength (float | None | str | Unset): Minimum yield strength R_p0.2 (σ_T in [004]); overrides the
            property class
        bearing_outer_diameter (float | None | str | Unset): Outer diameter D_f of the bearing face; ISO 4017 hexagon
            head d_w,min when absent
        hole_diameter (float | None | str | Unset): Clearance-hole diameter d_h (inner diameter of the bearing face);
            ISO 273 of hole_series when absent
        hole_series (None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHoleSeriesType0 | Unset): ISO 273
            clearance-hole series used when hole_diameter is absent Default:
            PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHoleSeriesType0.MEDIUM.
        head (None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHeadType0 | Unset): Head type: 'hex' (l_SK =
            0.5 d) or 'socket' (0.4 d), VDI 2230-1 R3 Default:
            PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHeadType0.HEX.
        joint_type (None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseJointTypeType0 | Unset): 'through':
            bolt and nut (DSV); 'tapped': screwed into the last part (ESV) Default:
            PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseJointTypeType0.THROUGH.
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
        plate2_thickness (float | None | str | Unset): Thickness h_2 of clamped plate 2 (from the head side); absent or
            0: no such plate
        plate3_thickness (float | None | str | Unset): Thickness h_3 of clamped plate 3 (from the head side); absent or
            0: no such plate
        preload (float | None | str | Unset): Preload F to convert into elongation and time of flight (or give
            elongation or time_of_flight_change to get the preload)
        elongation (float | None | str | Unset): Measured mechanical elongation ΔL (as an instrument displays it, the
            stress factor applied), to get the preload and the time of flight
        time_of_flight_change (float | None | str | Unset): Measured change in the echo's round-trip time between the
            zero reading and the loaded reading (or give preload or elongation)
        sound_velocity (float | str | Unset): Longitudinal velocity of sound V in the unloaded bolt (calibrate it on the
            bolt)
        stress_factor (float | str | Unset): Stress factor S_F: mechanical over ultrasonic change in length, calibrated
            per bolt material [Dakota]
        temperature_factor (float | None | str | Unset): Temperature factor τ: relative change of the ultrasonic length
            per kelvin (thermal expansion and velocity together; [Dakota]'s T_F × 1e-6) Default: 0.0.
        reading_temperature_change (float | None | str | Unset): Bolt temperature at the loaded reading minus at the
            zero reading Default: 0.0.
        ultrasonic_length (float | None | str | Unset): The bolt's ultrasonic length L_U at the zero reading (for the
            temperature correction)
    """

    thread: str | Unset = UNSET
    grade: str | Unset = UNSET
    thread_diameter: float | None | str | Unset = UNSET
    thread_pitch: float | None | str | Unset = UNSET
    property_class: None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBasePropertyClassType0 | Unset = (
        PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBasePropertyClassType0.VALUE_5
    )
    yield_strength: float | None | str | Unset = UNSET
    bearing_outer_diameter: float | None | str | Unset = UNSET
    hole_diameter: float | None | str | Unset = UNSET
    hole_series: None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHoleSeriesType0 | Unset = (
        PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHoleSeriesType0.MEDIUM
    )
    head: None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHeadType0 | Unset = (
        PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHeadType0.HEX
    )
    joint_type: None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseJointTypeType0 | Unset = (
        PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseJointTypeType0.THROUGH
    )
    shank_length: float | None | str | Unset = 0.0
    shank_diameter: float | None | str | Unset = UNSET
    reduced_length: float | None | str | Unset = 0.0
    reduced_diameter: float | None | str | Unset = UNSET
    youngs_modulus: float | None | str | Unset = 210000000000.0
    nut_youngs_modulus: float | None | str | Unset = UNSET
    plate1_thickness: float | str | Unset = UNSET
    plate2_thickness: float | None | str | Unset = UNSET
    plate3_thickness: float | None | str | Unset = UNSET
    preload: float | None | str | Unset = UNSET
    elongation: float | None | str | Unset = UNSET
    time_of_flight_change: float | None | str | Unset = UNSET
    sound_velocity: float | str | Unset = UNSET
    stress_factor: float | str | Unset = UNSET
    temperature_factor: float | None | str | Unset = 0.0
    reading_temperature_change: float | None | str | Unset = 0.0
    ultrasonic_length: float | None | str | Unset = UNSET

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
        elif isinstance(self.property_class, PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBasePropertyClassType0):
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
        elif isinstance(self.hole_series, PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHoleSeriesType0):
            hole_series = self.hole_series.value
        else:
            hole_series = self.hole_series

        head: None | str | Unset
        if isinstance(self.head, Unset):
            head = UNSET
        elif isinstance(self.head, PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHeadType0):
            head = self.head.value
        else:
            head = self.head

        joint_type: None | str | Unset
        if isinstance(self.joint_type, Unset):
            joint_type = UNSET
        elif isinstance(self.joint_type, PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseJointTypeType0):
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

        plate2_thickness: float | None | str | Unset
        if isinstance(self.plate2_thickness, Unset):
            plate2_thickness = UNSET
        else:
            plate2_thickness = self.plate2_thickness

        plate3_thickness: float | None | str | Unset
        if isinstance(self.plate3_thickness, Unset):
            plate3_thickness = UNSET
        else:
            plate3_thickness = self.plate3_thickness

        preload: float | None | str | Unset
        if isinstance(self.preload, Unset):
            preload = UNSET
        else:
            preload = self.preload

        elongation: float | None | str | Unset
        if isinstance(self.elongation, Unset):
            elongation = UNSET
        else:
            elongation = self.elongation

        time_of_flight_change: float | None | str | Unset
        if isinstance(self.time_of_flight_change, Unset):
            time_of_flight_change = UNSET
        else:
            time_of_flight_change = self.time_of_flight_change

        sound_velocity: float | str | Unset
        if isinstance(self.sound_velocity, Unset):
            sound_velocity = UNSET
        else:
            sound_velocity = self.sound_velocity

        stress_factor: float | str | Unset
        if isinstance(self.stress_factor, Unset):
            stress_factor = UNSET
        else:
            stress_factor = self.stress_factor

        temperature_factor: float | None | str | Unset
        if isinstance(self.temperature_factor, Unset):
            temperature_factor = UNSET
        else:
            temperature_factor = self.temperature_factor

        reading_temperature_change: float | None | str | Unset
        if isinstance(self.reading_temperature_change, Unset):
            reading_temperature_change = UNSET
        else:
            reading_temperature_change = self.reading_temperature_change

        ultrasonic_length: float | None | str | Unset
        if isinstance(self.ultrasonic_length, Unset):
            ultrasonic_length = UNSET
        else:
            ultrasonic_length = self.ultrasonic_length

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
        if plate2_thickness is not UNSET:
            field_dict["plate2_thickness"] = plate2_thickness
        if plate3_thickness is not UNSET:
            field_dict["plate3_thickness"] = plate3_thickness
        if preload is not UNSET:
            field_dict["preload"] = preload
        if elongation is not UNSET:
            field_dict["elongation"] = elongation
        if time_of_flight_change is not UNSET:
            field_dict["time_of_flight_change"] = time_of_flight_change
        if sound_velocity is not UNSET:
            field_dict["sound_velocity"] = sound_velocity
        if stress_factor is not UNSET:
            field_dict["stress_factor"] = stress_factor
        if temperature_factor is not UNSET:
            field_dict["temperature_factor"] = temperature_factor
        if reading_temperature_change is not UNSET:
            field_dict["reading_temperature_change"] = reading_temperature_change
        if ultrasonic_length is not UNSET:
            field_dict["ultrasonic_length"] = ultrasonic_length

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
        ) -> None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBasePropertyClassType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                property_class_type_0 = PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBasePropertyClassType0(data)

                return property_class_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBasePropertyClassType0 | Unset, data)

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

        def _parse_hole_series(
            data: object,
        ) -> None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHoleSeriesType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                hole_series_type_0 = PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHoleSeriesType0(data)

                return hole_series_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHoleSeriesType0 | Unset, data)

        hole_series = _parse_hole_series(d.pop("hole_series", UNSET))

        def _parse_head(
            data: object,
        ) -> None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHeadType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                head_type_0 = PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHeadType0(data)

                return head_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseHeadType0 | Unset, data)

        head = _parse_head(d.pop("head", UNSET))

        def _parse_joint_type(
            data: object,
        ) -> None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseJointTypeType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                joint_type_type_0 = PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseJointTypeType0(data)

                return joint_type_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadUltrasonicStudyRequestPreloadUltrasonicStudyBaseJointTypeType0 | Unset, data)

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

        def _parse_plate2_thickness(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate2_thickness = _parse_plate2_thickness(d.pop("plate2_thickness", UNSET))

        def _parse_plate3_thickness(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        plate3_thickness = _parse_plate3_thickness(d.pop("plate3_thickness", UNSET))

        def _parse_preload(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        preload = _parse_preload(d.pop("preload", UNSET))

        def _parse_elongation(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        elongation = _parse_elongation(d.pop("elongation", UNSET))

        def _parse_time_of_flight_change(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        time_of_flight_change = _parse_time_of_flight_change(d.pop("time_of_flight_change", UNSET))

        def _parse_sound_velocity(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        sound_velocity = _parse_sound_velocity(d.pop("sound_velocity", UNSET))

        def _parse_stress_factor(data: object) -> float | str | Unset:
            if isinstance(data, Unset):
                return data
            return cast(float | str | Unset, data)

        stress_factor = _parse_stress_factor(d.pop("stress_factor", UNSET))

        def _parse_temperature_factor(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        temperature_factor = _parse_temperature_factor(d.pop("temperature_factor", UNSET))

        def _parse_reading_temperature_change(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        reading_temperature_change = _parse_reading_temperature_change(d.pop("reading_temperature_change", UNSET))

        def _parse_ultrasonic_length(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        ultrasonic_length = _parse_ultrasonic_length(d.pop("ultrasonic_length", UNSET))

        preload_ultrasonic_study_request_preload_ultrasonic_study_base = cls(
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
            plate2_thickness=plate2_thickness,
            plate3_thickness=plate3_thickness,
            preload=preload,
            elongation=elongation,
            time_of_flight_change=time_of_flight_change,
            sound_velocity=sound_velocity,
            stress_factor=stress_factor,
            temperature_factor=temperature_factor,
            reading_temperature_change=reading_temperature_change,
            ultrasonic_length=ultrasonic_length,
        )

        return preload_ultrasonic_study_request_preload_ultrasonic_study_base
