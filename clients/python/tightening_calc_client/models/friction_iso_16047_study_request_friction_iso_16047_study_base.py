from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.friction_iso_16047_study_request_friction_iso_16047_study_base_clamp_forces_type_1 import (
        FrictionIso16047StudyRequestFrictionIso16047StudyBaseClampForcesType1,
    )
    from ..models.friction_iso_16047_study_request_friction_iso_16047_study_base_thread_torques_type_1 import (
        FrictionIso16047StudyRequestFrictionIso16047StudyBaseThreadTorquesType1,
    )
    from ..models.friction_iso_16047_study_request_friction_iso_16047_study_base_tightening_torques_type_1 import (
        FrictionIso16047StudyRequestFrictionIso16047StudyBaseTighteningTorquesType1,
    )


T = TypeVar("T", bound="FrictionIso16047StudyRequestFrictionIso16047StudyBase")


@_attrs_define
class FrictionIso16047StudyRequestFrictionIso16047StudyBase:
    """inputs held fixed (defaults fill the rest)

    Attributes:
        tightening_torques (FrictionIso16047StudyRequestFrictionIso16047StudyBaseTighteningTorquesType1 | list[float] |
            None | Unset): Tightening torque T of each test, at the clamp force evaluated (one value per test)
        thread_torques (FrictionIso16047StudyRequestFrictionIso16047StudyBaseThreadTorquesType1 | list[float] | None |
            Unset): Thread torque T_th of each test, in the same order
        clamp_forces (FrictionIso16047StudyRequestFrictionIso16047StudyBaseClampForcesType1 | list[float] | None |
            Unset): Clamp force F of each test, in the same order
        thread (str | Unset): Designation instead of thread_diameter: 'M12', 'M12x1.25', 'M10 ISO 4762 12.9', '1/2-13
            UNC', '1/2-13 UNC Grade 5' (ISO M1.6…M64 coarse and fine, UNC/UNF 1/4…1-1/2; GET /api/v1/fasteners lists them).
            A head standard or grade in it sets head_standard and grade
        thread_diameter (float | None | str | Unset): Nominal thread diameter d, when no thread designation is given
        thread_pitch (float | None | str | Unset): Thread pitch P with thread_diameter; ISO 261 coarse pitch when absent
        pitch_diameter (float | None | str | Unset): Pitch diameter d2 (ISO 68-1 from d and P, or the designation's,
            when absent)
        bearing_outer_diameter (float | None | str | Unset): Outside diameter d_o of the bearing contact (a
            designation's hexagon head d_w,min, ISO 4017, when absent)
        hole_diameter (float | None | str | Unset): Inside diameter d_i of the bearing contact: the hole of the test
            washer (a designation's ISO 273 medium clearance hole when absent)
        bearing_diameter (float | None | str | Unset): Mean bearing diameter D_b = (d_o + d_i)/2 given directly
            (overrides the two above)
    """

    tightening_torques: (
        FrictionIso16047StudyRequestFrictionIso16047StudyBaseTighteningTorquesType1 | list[float] | None | Unset
    ) = UNSET
    thread_torques: (
        FrictionIso16047StudyRequestFrictionIso16047StudyBaseThreadTorquesType1 | list[float] | None | Unset
    ) = UNSET
    clamp_forces: FrictionIso16047StudyRequestFrictionIso16047StudyBaseClampForcesType1 | list[float] | None | Unset = (
        UNSET
    )
    thread: str | Unset = UNSET
    thread_diameter: float | None | str | Unset = UNSET
    thread_pitch: float | None | str | Unset = UNSET
    pitch_diameter: float | None | str | Unset = UNSET
    bearing_outer_diameter: float | None | str | Unset = UNSET
    hole_diameter: float | None | str | Unset = UNSET
    bearing_diameter: float | None | str | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.friction_iso_16047_study_request_friction_iso_16047_study_base_clamp_forces_type_1 import (
            FrictionIso16047StudyRequestFrictionIso16047StudyBaseClampForcesType1,  # noqa: PLC0415
        )
        from ..models.friction_iso_16047_study_request_friction_iso_16047_study_base_thread_torques_type_1 import (
            FrictionIso16047StudyRequestFrictionIso16047StudyBaseThreadTorquesType1,  # noqa: PLC0415
        )
        from ..models.friction_iso_16047_study_request_friction_iso_16047_study_base_tightening_torques_type_1 import (
            FrictionIso16047StudyRequestFrictionIso16047StudyBaseTighteningTorquesType1,  # noqa: PLC0415
        )

        tightening_torques: dict[str, Any] | list[float] | None | Unset
        if isinstance(self.tightening_torques, Unset):
            tightening_torques = UNSET
        elif isinstance(self.tightening_torques, list):
            tightening_torques = self.tightening_torques

        elif isinstance(
            self.tightening_torques, FrictionIso16047StudyRequestFrictionIso16047StudyBaseTighteningTorquesType1
        ):
            tightening_torques = self.tightening_torques.to_dict()
        else:
            tightening_torques = self.tightening_torques

        thread_torques: dict[str, Any] | list[float] | None | Unset
        if isinstance(self.thread_torques, Unset):
            thread_torques = UNSET
        elif isinstance(self.thread_torques, list):
            thread_torques = self.thread_torques

        elif isinstance(self.thread_torques, FrictionIso16047StudyRequestFrictionIso16047StudyBaseThreadTorquesType1):
            thread_torques = self.thread_torques.to_dict()
        else:
            thread_torques = self.thread_torques

        clamp_forces: dict[str, Any] | list[float] | None | Unset
        if isinstance(self.clamp_forces, Unset):
            clamp_forces = UNSET
        elif isinstance(self.clamp_forces, list):
            clamp_forces = self.clamp_forces

        elif isinstance(self.clamp_forces, FrictionIso16047StudyRequestFrictionIso16047StudyBaseClampForcesType1):
            clamp_forces = self.clamp_forces.to_dict()
        else:
            clamp_forces = self.clamp_forces

        thread = self.thread

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

        pitch_diameter: float | None | str | Unset
        if isinstance(self.pitch_diameter, Unset):
            pitch_diameter = UNSET
        else:
            pitch_diameter = self.pitch_diameter

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

        bearing_diameter: float | None | str | Unset
        if isinstance(self.bearing_diameter, Unset):
            bearing_diameter = UNSET
        else:
            bearing_diameter = self.bearing_diameter

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if tightening_torques is not UNSET:
            field_dict["tightening_torques"] = tightening_torques
        if thread_torques is not UNSET:
            field_dict["thread_torques"] = thread_torques
        if clamp_forces is not UNSET:
            field_dict["clamp_forces"] = clamp_forces
        if thread is not UNSET:
            field_dict["thread"] = thread
        if thread_diameter is not UNSET:
            field_dict["thread_diameter"] = thread_diameter
        if thread_pitch is not UNSET:
            field_dict["thread_pitch"] = thread_pitch
        if pitch_diameter is not UNSET:
            field_dict["pitch_diameter"] = pitch_diameter
        if bearing_outer_diameter is not UNSET:
            field_dict["bearing_outer_diameter"] = bearing_outer_diameter
        if hole_diameter is not UNSET:
            field_dict["hole_diameter"] = hole_diameter
        if bearing_diameter is not UNSET:
            field_dict["bearing_diameter"] = bearing_diameter

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.friction_iso_16047_study_request_friction_iso_16047_study_base_clamp_forces_type_1 import (
            FrictionIso16047StudyRequestFrictionIso16047StudyBaseClampForcesType1,  # noqa: PLC0415
        )
        from ..models.friction_iso_16047_study_request_friction_iso_16047_study_base_thread_torques_type_1 import (
            FrictionIso16047StudyRequestFrictionIso16047StudyBaseThreadTorquesType1,  # noqa: PLC0415
        )
        from ..models.friction_iso_16047_study_request_friction_iso_16047_study_base_tightening_torques_type_1 import (
            FrictionIso16047StudyRequestFrictionIso16047StudyBaseTighteningTorquesType1,  # noqa: PLC0415
        )

        d = dict(src_dict)

        def _parse_tightening_torques(
            data: object,
        ) -> FrictionIso16047StudyRequestFrictionIso16047StudyBaseTighteningTorquesType1 | list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                tightening_torques_type_0 = cast(list[float], data)

                return tightening_torques_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                tightening_torques_type_1 = (
                    FrictionIso16047StudyRequestFrictionIso16047StudyBaseTighteningTorquesType1.from_dict(data)
                )

                return tightening_torques_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(
                FrictionIso16047StudyRequestFrictionIso16047StudyBaseTighteningTorquesType1
                | list[float]
                | None
                | Unset,
                data,
            )

        tightening_torques = _parse_tightening_torques(d.pop("tightening_torques", UNSET))

        def _parse_thread_torques(
            data: object,
        ) -> FrictionIso16047StudyRequestFrictionIso16047StudyBaseThreadTorquesType1 | list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                thread_torques_type_0 = cast(list[float], data)

                return thread_torques_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                thread_torques_type_1 = (
                    FrictionIso16047StudyRequestFrictionIso16047StudyBaseThreadTorquesType1.from_dict(data)
                )

                return thread_torques_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(
                FrictionIso16047StudyRequestFrictionIso16047StudyBaseThreadTorquesType1 | list[float] | None | Unset,
                data,
            )

        thread_torques = _parse_thread_torques(d.pop("thread_torques", UNSET))

        def _parse_clamp_forces(
            data: object,
        ) -> FrictionIso16047StudyRequestFrictionIso16047StudyBaseClampForcesType1 | list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                clamp_forces_type_0 = cast(list[float], data)

                return clamp_forces_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                clamp_forces_type_1 = FrictionIso16047StudyRequestFrictionIso16047StudyBaseClampForcesType1.from_dict(
                    data
                )

                return clamp_forces_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(
                FrictionIso16047StudyRequestFrictionIso16047StudyBaseClampForcesType1 | list[float] | None | Unset, data
            )

        clamp_forces = _parse_clamp_forces(d.pop("clamp_forces", UNSET))

        thread = d.pop("thread", UNSET)

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

        def _parse_pitch_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        pitch_diameter = _parse_pitch_diameter(d.pop("pitch_diameter", UNSET))

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

        def _parse_bearing_diameter(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        bearing_diameter = _parse_bearing_diameter(d.pop("bearing_diameter", UNSET))

        friction_iso_16047_study_request_friction_iso_16047_study_base = cls(
            tightening_torques=tightening_torques,
            thread_torques=thread_torques,
            clamp_forces=clamp_forces,
            thread=thread,
            thread_diameter=thread_diameter,
            thread_pitch=thread_pitch,
            pitch_diameter=pitch_diameter,
            bearing_outer_diameter=bearing_outer_diameter,
            hole_diameter=hole_diameter,
            bearing_diameter=bearing_diameter,
        )

        return friction_iso_16047_study_request_friction_iso_16047_study_base
