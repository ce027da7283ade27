from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.preload_tightening_study_request_preload_tightening_study_base_clamped_material_type_0 import (
    PreloadTighteningStudyRequestPreloadTighteningStudyBaseClampedMaterialType0,
)
from ..models.preload_tightening_study_request_preload_tightening_study_base_head_standard_type_0 import (
    PreloadTighteningStudyRequestPreloadTighteningStudyBaseHeadStandardType0,
)
from ..models.preload_tightening_study_request_preload_tightening_study_base_hole_series_type_0 import (
    PreloadTighteningStudyRequestPreloadTighteningStudyBaseHoleSeriesType0,
)
from ..models.preload_tightening_study_request_preload_tightening_study_base_internal_thread_material_type_0 import (
    PreloadTighteningStudyRequestPreloadTighteningStudyBaseInternalThreadMaterialType0,
)
from ..models.preload_tightening_study_request_preload_tightening_study_base_nut_property_class_type_0 import (
    PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutPropertyClassType0,
)
from ..models.preload_tightening_study_request_preload_tightening_study_base_nut_type_0 import (
    PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutType0,
)
from ..models.preload_tightening_study_request_preload_tightening_study_base_preload_convention_type_0 import (
    PreloadTighteningStudyRequestPreloadTighteningStudyBasePreloadConventionType0,
)
from ..models.preload_tightening_study_request_preload_tightening_study_base_property_class_type_0 import (
    PreloadTighteningStudyRequestPreloadTighteningStudyBasePropertyClassType0,
)
from ..models.preload_tightening_study_request_preload_tightening_study_base_torque_formula_type_0 import (
    PreloadTighteningStudyRequestPreloadTighteningStudyBaseTorqueFormulaType0,
)
from ..models.preload_tightening_study_request_preload_tightening_study_base_washer_type_0 import (
    PreloadTighteningStudyRequestPreloadTighteningStudyBaseWasherType0,
)
from ..types import UNSET, Unset

T = TypeVar("T", bound="PreloadTighteningStudyRequestPreloadTighteningStudyBase")


@_attrs_define
class PreloadTighteningStudyRequestPreloadTighteningStudyBase:
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
        property_class (None | PreloadTighteningStudyRequestPreloadTighteningStudyBasePropertyClassType0 | Unset): ISO
            898-1 property class: minimum yield and tensile strength (8.8: 640/800 MPa up to M16, 660/830 MPa above)
            Default: PreloadTighteningStudyRequestPreloadTighteningStudyBasePropertyClassType0.VALUE_5.
        yield_strength (float | None | str | Unset): Minimum yield strength R_p0.2 (σ_T in [004]); overrides the
            property class
        thread_friction (float | None | str | Unset): Thread friction coefficient μ_G (f_p in [004]) Default: 0.12.
        bearing_friction (float | None | str | Unset): Bearing-face friction coefficient μ_K (f_T in [004]) Default:
            0.12.
        bearing_outer_diameter (float | None | str | Unset): Outer diameter D_f of the bearing face; ISO 4017 hexagon
            head d_w,min when absent
        hole_diameter (float | None | str | Unset): Clearance-hole diameter d_h (inner diameter of the bearing face);
            ISO 273 of hole_series when absent
        hole_series (None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseHoleSeriesType0 | Unset): ISO 273
            clearance-hole series used when hole_diameter is absent Default:
            PreloadTighteningStudyRequestPreloadTighteningStudyBaseHoleSeriesType0.MEDIUM.
        utilization (float | None | str | Unset): ν: share of the yield strength the equivalent stress may use at
            assembly (VDI 2230: 0.9; [004, eq. 3]: ξ/n_T, 0.71…0.83) Default: 0.9.
        preload_convention (None | PreloadTighteningStudyRequestPreloadTighteningStudyBasePreloadConventionType0 |
            Unset): 'vdi2230': β of VDI 2230 step R7 (plastic torsion, factor 3/2); 'elastic': β of [004, eq. 5] with τ/σ =
            2(d2/d0)·tan(ψ+ρ') Default:
            PreloadTighteningStudyRequestPreloadTighteningStudyBasePreloadConventionType0.VDI2230.
        torque_formula (None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseTorqueFormulaType0 | Unset):
            'vdi2230': M_A = F(0.16P + 0.58 d2 μ_G + μ_K D_Km/2); 'exact': [004, eq. 10–13] with the annular friction
            radius; 'approx': [004, eq. 15/19] with d2 ≈ d Default:
            PreloadTighteningStudyRequestPreloadTighteningStudyBaseTorqueFormulaType0.VDI2230.
        preload (float | None | str | Unset): Preload F0 to use instead of the largest permissible assembly preload
        head_standard (None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseHeadStandardType0 | Unset): Head
            standard (bearing diameter d_w, drive): hexagon ISO 4017/4014 when absent (ASME B18.2.1 hex for inch threads)
        washer (None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseWasherType0 | Unset): Plain washer under
            the head (spreads the pressure on the clamped part)
        nut (None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutType0 | Unset): Hexagon nut (a through-
            bolted joint: surface pressure under the nut); absent: tapped
        clamped_material (None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseClampedMaterialType0 | Unset):
            Material under the head and nut: its limiting surface pressure p_G (VDI 2230-1 Table A9; plastics: compressive
            yield)
        limiting_surface_pressure (float | None | str | Unset): Limiting surface pressure p_G of the clamped part;
            overrides clamped_material
        internal_thread_material (None |
            PreloadTighteningStudyRequestPreloadTighteningStudyBaseInternalThreadMaterialType0 | Unset): Material of the
            tapped hole: its shear strength τ_BM for the stripping check
        internal_thread_shear_strength (float | None | str | Unset): Shear strength τ_BM of the internal thread;
            overrides internal_thread_material
        engagement_length (float | None | str | Unset): Length of thread engagement in the tapped hole as built, entry
            chamfers included (VDI 2230-1 R11: m_ges = m_eff + 2P)
        working_bolt_force (float | None | str | Unset): Largest bolt force in service F_S,max (surface pressure in
            service, VDI 2230-1 R10)
        nut_property_class (None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutPropertyClassType0 |
            Unset): Property class of the nut (ISO 898-2; 04/05: thin nuts): its proof load caps F_M,zul; absent: the lowest
            class the nut standard is made in that pairs with the bolt
    """

    thread: str | Unset = UNSET
    grade: str | Unset = UNSET
    thread_diameter: float | None | str | Unset = UNSET
    thread_pitch: float | None | str | Unset = UNSET
    property_class: None | PreloadTighteningStudyRequestPreloadTighteningStudyBasePropertyClassType0 | Unset = (
        PreloadTighteningStudyRequestPreloadTighteningStudyBasePropertyClassType0.VALUE_5
    )
    yield_strength: float | None | str | Unset = UNSET
    thread_friction: float | None | str | Unset = 0.12
    bearing_friction: float | None | str | Unset = 0.12
    bearing_outer_diameter: float | None | str | Unset = UNSET
    hole_diameter: float | None | str | Unset = UNSET
    hole_series: None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseHoleSeriesType0 | Unset = (
        PreloadTighteningStudyRequestPreloadTighteningStudyBaseHoleSeriesType0.MEDIUM
    )
    utilization: float | None | str | Unset = 0.9
    preload_convention: None | PreloadTighteningStudyRequestPreloadTighteningStudyBasePreloadConventionType0 | Unset = (
        PreloadTighteningStudyRequestPreloadTighteningStudyBasePreloadConventionType0.VDI2230
    )
    torque_formula: None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseTorqueFormulaType0 | Unset = (
        PreloadTighteningStudyRequestPreloadTighteningStudyBaseTorqueFormulaType0.VDI2230
    )
    preload: float | None | str | Unset = UNSET
    head_standard: None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseHeadStandardType0 | Unset = UNSET
    washer: None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseWasherType0 | Unset = UNSET
    nut: None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutType0 | Unset = UNSET
    clamped_material: None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseClampedMaterialType0 | Unset = UNSET
    limiting_surface_pressure: float | None | str | Unset = UNSET
    internal_thread_material: (
        None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseInternalThreadMaterialType0 | Unset
    ) = UNSET
    internal_thread_shear_strength: float | None | str | Unset = UNSET
    engagement_length: float | None | str | Unset = UNSET
    working_bolt_force: float | None | str | Unset = UNSET
    nut_property_class: None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutPropertyClassType0 | Unset = (
        UNSET
    )

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
        elif isinstance(self.property_class, PreloadTighteningStudyRequestPreloadTighteningStudyBasePropertyClassType0):
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
        elif isinstance(self.hole_series, PreloadTighteningStudyRequestPreloadTighteningStudyBaseHoleSeriesType0):
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
            self.preload_convention, PreloadTighteningStudyRequestPreloadTighteningStudyBasePreloadConventionType0
        ):
            preload_convention = self.preload_convention.value
        else:
            preload_convention = self.preload_convention

        torque_formula: None | str | Unset
        if isinstance(self.torque_formula, Unset):
            torque_formula = UNSET
        elif isinstance(self.torque_formula, PreloadTighteningStudyRequestPreloadTighteningStudyBaseTorqueFormulaType0):
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
        elif isinstance(self.head_standard, PreloadTighteningStudyRequestPreloadTighteningStudyBaseHeadStandardType0):
            head_standard = self.head_standard.value
        else:
            head_standard = self.head_standard

        washer: None | str | Unset
        if isinstance(self.washer, Unset):
            washer = UNSET
        elif isinstance(self.washer, PreloadTighteningStudyRequestPreloadTighteningStudyBaseWasherType0):
            washer = self.washer.value
        else:
            washer = self.washer

        nut: None | str | Unset
        if isinstance(self.nut, Unset):
            nut = UNSET
        elif isinstance(self.nut, PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutType0):
            nut = self.nut.value
        else:
            nut = self.nut

        clamped_material: None | str | Unset
        if isinstance(self.clamped_material, Unset):
            clamped_material = UNSET
        elif isinstance(
            self.clamped_material, PreloadTighteningStudyRequestPreloadTighteningStudyBaseClampedMaterialType0
        ):
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
            self.internal_thread_material,
            PreloadTighteningStudyRequestPreloadTighteningStudyBaseInternalThreadMaterialType0,
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
            self.nut_property_class, PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutPropertyClassType0
        ):
            nut_property_class = self.nut_property_class.value
        else:
            nut_property_class = self.nut_property_class

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
        ) -> None | PreloadTighteningStudyRequestPreloadTighteningStudyBasePropertyClassType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                property_class_type_0 = PreloadTighteningStudyRequestPreloadTighteningStudyBasePropertyClassType0(data)

                return property_class_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadTighteningStudyRequestPreloadTighteningStudyBasePropertyClassType0 | Unset, data)

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
        ) -> None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseHoleSeriesType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                hole_series_type_0 = PreloadTighteningStudyRequestPreloadTighteningStudyBaseHoleSeriesType0(data)

                return hole_series_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseHoleSeriesType0 | Unset, data)

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
        ) -> None | PreloadTighteningStudyRequestPreloadTighteningStudyBasePreloadConventionType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                preload_convention_type_0 = (
                    PreloadTighteningStudyRequestPreloadTighteningStudyBasePreloadConventionType0(data)
                )

                return preload_convention_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(
                None | PreloadTighteningStudyRequestPreloadTighteningStudyBasePreloadConventionType0 | Unset, data
            )

        preload_convention = _parse_preload_convention(d.pop("preload_convention", UNSET))

        def _parse_torque_formula(
            data: object,
        ) -> None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseTorqueFormulaType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                torque_formula_type_0 = PreloadTighteningStudyRequestPreloadTighteningStudyBaseTorqueFormulaType0(data)

                return torque_formula_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseTorqueFormulaType0 | Unset, data)

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
        ) -> None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseHeadStandardType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                head_standard_type_0 = PreloadTighteningStudyRequestPreloadTighteningStudyBaseHeadStandardType0(data)

                return head_standard_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseHeadStandardType0 | Unset, data)

        head_standard = _parse_head_standard(d.pop("head_standard", UNSET))

        def _parse_washer(
            data: object,
        ) -> None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseWasherType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                washer_type_0 = PreloadTighteningStudyRequestPreloadTighteningStudyBaseWasherType0(data)

                return washer_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseWasherType0 | Unset, data)

        washer = _parse_washer(d.pop("washer", UNSET))

        def _parse_nut(data: object) -> None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                nut_type_0 = PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutType0(data)

                return nut_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutType0 | Unset, data)

        nut = _parse_nut(d.pop("nut", UNSET))

        def _parse_clamped_material(
            data: object,
        ) -> None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseClampedMaterialType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                clamped_material_type_0 = PreloadTighteningStudyRequestPreloadTighteningStudyBaseClampedMaterialType0(
                    data
                )

                return clamped_material_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(
                None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseClampedMaterialType0 | Unset, data
            )

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
        ) -> None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseInternalThreadMaterialType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                internal_thread_material_type_0 = (
                    PreloadTighteningStudyRequestPreloadTighteningStudyBaseInternalThreadMaterialType0(data)
                )

                return internal_thread_material_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(
                None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseInternalThreadMaterialType0 | Unset, data
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
        ) -> None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutPropertyClassType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                nut_property_class_type_0 = (
                    PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutPropertyClassType0(data)
                )

                return nut_property_class_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(
                None | PreloadTighteningStudyRequestPreloadTighteningStudyBaseNutPropertyClassType0 | Unset, data
            )

        nut_property_class = _parse_nut_property_class(d.pop("nut_property_class", UNSET))

        preload_tightening_study_request_preload_tightening_study_base = cls(
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
        )

        return preload_tightening_study_request_preload_tightening_study_base
