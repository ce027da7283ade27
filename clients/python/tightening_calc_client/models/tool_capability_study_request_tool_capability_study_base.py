from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.tool_capability_study_request_tool_capability_study_base_study_type_0 import (
    ToolCapabilityStudyRequestToolCapabilityStudyBaseStudyType0,
)
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.tool_capability_study_request_tool_capability_study_base_hard_joint_samples_type_1 import (
        ToolCapabilityStudyRequestToolCapabilityStudyBaseHardJointSamplesType1,
    )
    from ..models.tool_capability_study_request_tool_capability_study_base_soft_joint_samples_type_1 import (
        ToolCapabilityStudyRequestToolCapabilityStudyBaseSoftJointSamplesType1,
    )
    from ..models.tool_capability_study_request_tool_capability_study_base_torque_samples_type_1 import (
        ToolCapabilityStudyRequestToolCapabilityStudyBaseTorqueSamplesType1,
    )


T = TypeVar("T", bound="ToolCapabilityStudyRequestToolCapabilityStudyBase")


@_attrs_define
class ToolCapabilityStudyRequestToolCapabilityStudyBase:
    """inputs held fixed (defaults fill the rest)

    Attributes:
        torque_samples (list[float] | None | ToolCapabilityStudyRequestToolCapabilityStudyBaseTorqueSamplesType1 |
            Unset): Measured torques of the test, one per tightening (paste them, or give mean_torque and torque_sd instead)
        mean_torque (float | None | str | Unset): Mean of the measured torques, when the samples themselves are not
            given
        torque_sd (float | None | str | Unset): Standard deviation (n − 1) of the measured torques, with mean_torque
        sample_count (int | None | str | Unset): Number of measured torques behind mean_torque and torque_sd (for the
            sample-size check); with the ISO 5393 run means, the tightenings in each run
        hard_joint_samples (list[float] | None | ToolCapabilityStudyRequestToolCapabilityStudyBaseHardJointSamplesType1
            | Unset): ISO 5393 run on the hard test joint: its measured torques (with soft_joint_samples; the two runs are
            pooled into one sample)
        soft_joint_samples (list[float] | None | ToolCapabilityStudyRequestToolCapabilityStudyBaseSoftJointSamplesType1
            | Unset): ISO 5393 run on the soft test joint: its measured torques (with hard_joint_samples)
        hard_mean_torque (float | None | str | Unset): Mean torque of the hard-joint run, when its samples are not given
            (with hard_torque_sd, the soft run's two and sample_count, the tightenings in each run)
        hard_torque_sd (float | None | str | Unset): Standard deviation (n − 1) of the hard-joint run
        soft_mean_torque (float | None | str | Unset): Mean torque of the soft-joint run
        soft_torque_sd (float | None | str | Unset): Standard deviation (n − 1) of the soft-joint run
        nominal_torque (float | None | str | Unset): Nominal (target) torque; with relative_tolerance it gives the
            limits (lower_limit and upper_limit, when given, win)
        relative_tolerance (float | None | str | Unset): Tolerance ± as a share of the nominal torque (0.1 is ±10 %)
            Default: 0.1.
        lower_limit (float | None | str | Unset): Lower tolerance limit L (with upper_limit, instead of nominal ±
            tolerance)
        upper_limit (float | None | str | Unset): Upper tolerance limit U (with lower_limit)
        study (None | ToolCapabilityStudyRequestToolCapabilityStudyBaseStudyType0 | Unset): What the values are: one run
            of one tool (machine: Cm, Cmk, at least 50 values) or values from production (process: Cp, Cpk, 25 subgroups of
            5) Default: ToolCapabilityStudyRequestToolCapabilityStudyBaseStudyType0.MACHINE.
        required_index (float | None | str | Unset): Index both Cm and Cmk (or Cp and Cpk) must reach: 1.67 is the usual
            limit, as secondary sources state it; set your own specification's Default: 1.67.
    """

    torque_samples: list[float] | None | ToolCapabilityStudyRequestToolCapabilityStudyBaseTorqueSamplesType1 | Unset = (
        UNSET
    )
    mean_torque: float | None | str | Unset = UNSET
    torque_sd: float | None | str | Unset = UNSET
    sample_count: int | None | str | Unset = UNSET
    hard_joint_samples: (
        list[float] | None | ToolCapabilityStudyRequestToolCapabilityStudyBaseHardJointSamplesType1 | Unset
    ) = UNSET
    soft_joint_samples: (
        list[float] | None | ToolCapabilityStudyRequestToolCapabilityStudyBaseSoftJointSamplesType1 | Unset
    ) = UNSET
    hard_mean_torque: float | None | str | Unset = UNSET
    hard_torque_sd: float | None | str | Unset = UNSET
    soft_mean_torque: float | None | str | Unset = UNSET
    soft_torque_sd: float | None | str | Unset = UNSET
    nominal_torque: float | None | str | Unset = UNSET
    relative_tolerance: float | None | str | Unset = 0.1
    lower_limit: float | None | str | Unset = UNSET
    upper_limit: float | None | str | Unset = UNSET
    study: None | ToolCapabilityStudyRequestToolCapabilityStudyBaseStudyType0 | Unset = (
        ToolCapabilityStudyRequestToolCapabilityStudyBaseStudyType0.MACHINE
    )
    required_index: float | None | str | Unset = 1.67

    def to_dict(self) -> dict[str, Any]:
        from ..models.tool_capability_study_request_tool_capability_study_base_hard_joint_samples_type_1 import (
            ToolCapabilityStudyRequestToolCapabilityStudyBaseHardJointSamplesType1,  # noqa: PLC0415
        )
        from ..models.tool_capability_study_request_tool_capability_study_base_soft_joint_samples_type_1 import (
            ToolCapabilityStudyRequestToolCapabilityStudyBaseSoftJointSamplesType1,  # noqa: PLC0415
        )
        from ..models.tool_capability_study_request_tool_capability_study_base_torque_samples_type_1 import (
            ToolCapabilityStudyRequestToolCapabilityStudyBaseTorqueSamplesType1,  # noqa: PLC0415
        )

        torque_samples: dict[str, Any] | list[float] | None | Unset
        if isinstance(self.torque_samples, Unset):
            torque_samples = UNSET
        elif isinstance(self.torque_samples, list):
            torque_samples = self.torque_samples

        elif isinstance(self.torque_samples, ToolCapabilityStudyRequestToolCapabilityStudyBaseTorqueSamplesType1):
            torque_samples = self.torque_samples.to_dict()
        else:
            torque_samples = self.torque_samples

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

        sample_count: int | None | str | Unset
        if isinstance(self.sample_count, Unset):
            sample_count = UNSET
        else:
            sample_count = self.sample_count

        hard_joint_samples: dict[str, Any] | list[float] | None | Unset
        if isinstance(self.hard_joint_samples, Unset):
            hard_joint_samples = UNSET
        elif isinstance(self.hard_joint_samples, list):
            hard_joint_samples = self.hard_joint_samples

        elif isinstance(
            self.hard_joint_samples, ToolCapabilityStudyRequestToolCapabilityStudyBaseHardJointSamplesType1
        ):
            hard_joint_samples = self.hard_joint_samples.to_dict()
        else:
            hard_joint_samples = self.hard_joint_samples

        soft_joint_samples: dict[str, Any] | list[float] | None | Unset
        if isinstance(self.soft_joint_samples, Unset):
            soft_joint_samples = UNSET
        elif isinstance(self.soft_joint_samples, list):
            soft_joint_samples = self.soft_joint_samples

        elif isinstance(
            self.soft_joint_samples, ToolCapabilityStudyRequestToolCapabilityStudyBaseSoftJointSamplesType1
        ):
            soft_joint_samples = self.soft_joint_samples.to_dict()
        else:
            soft_joint_samples = self.soft_joint_samples

        hard_mean_torque: float | None | str | Unset
        if isinstance(self.hard_mean_torque, Unset):
            hard_mean_torque = UNSET
        else:
            hard_mean_torque = self.hard_mean_torque

        hard_torque_sd: float | None | str | Unset
        if isinstance(self.hard_torque_sd, Unset):
            hard_torque_sd = UNSET
        else:
            hard_torque_sd = self.hard_torque_sd

        soft_mean_torque: float | None | str | Unset
        if isinstance(self.soft_mean_torque, Unset):
            soft_mean_torque = UNSET
        else:
            soft_mean_torque = self.soft_mean_torque

        soft_torque_sd: float | None | str | Unset
        if isinstance(self.soft_torque_sd, Unset):
            soft_torque_sd = UNSET
        else:
            soft_torque_sd = self.soft_torque_sd

        nominal_torque: float | None | str | Unset
        if isinstance(self.nominal_torque, Unset):
            nominal_torque = UNSET
        else:
            nominal_torque = self.nominal_torque

        relative_tolerance: float | None | str | Unset
        if isinstance(self.relative_tolerance, Unset):
            relative_tolerance = UNSET
        else:
            relative_tolerance = self.relative_tolerance

        lower_limit: float | None | str | Unset
        if isinstance(self.lower_limit, Unset):
            lower_limit = UNSET
        else:
            lower_limit = self.lower_limit

        upper_limit: float | None | str | Unset
        if isinstance(self.upper_limit, Unset):
            upper_limit = UNSET
        else:
            upper_limit = self.upper_limit

        study: None | str | Unset
        if isinstance(self.study, Unset):
            study = UNSET
        elif isinstance(self.study, ToolCapabilityStudyRequestToolCapabilityStudyBaseStudyType0):
            study = self.study.value
        else:
            study = self.study

        required_index: float | None | str | Unset
        if isinstance(self.required_index, Unset):
            required_index = UNSET
        else:
            required_index = self.required_index

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if torque_samples is not UNSET:
            field_dict["torque_samples"] = torque_samples
        if mean_torque is not UNSET:
            field_dict["mean_torque"] = mean_torque
        if torque_sd is not UNSET:
            field_dict["torque_sd"] = torque_sd
        if sample_count is not UNSET:
            field_dict["sample_count"] = sample_count
        if hard_joint_samples is not UNSET:
            field_dict["hard_joint_samples"] = hard_joint_samples
        if soft_joint_samples is not UNSET:
            field_dict["soft_joint_samples"] = soft_joint_samples
        if hard_mean_torque is not UNSET:
            field_dict["hard_mean_torque"] = hard_mean_torque
        if hard_torque_sd is not UNSET:
            field_dict["hard_torque_sd"] = hard_torque_sd
        if soft_mean_torque is not UNSET:
            field_dict["soft_mean_torque"] = soft_mean_torque
        if soft_torque_sd is not UNSET:
            field_dict["soft_torque_sd"] = soft_torque_sd
        if nominal_torque is not UNSET:
            field_dict["nominal_torque"] = nominal_torque
        if relative_tolerance is not UNSET:
            field_dict["relative_tolerance"] = relative_tolerance
        if lower_limit is not UNSET:
            field_dict["lower_limit"] = lower_limit
        if upper_limit is not UNSET:
            field_dict["upper_limit"] = upper_limit
        if study is not UNSET:
            field_dict["study"] = study
        if required_index is not UNSET:
            field_dict["required_index"] = required_index

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.tool_capability_study_request_tool_capability_study_base_hard_joint_samples_type_1 import (
            ToolCapabilityStudyRequestToolCapabilityStudyBaseHardJointSamplesType1,  # noqa: PLC0415
        )
        from ..models.tool_capability_study_request_tool_capability_study_base_soft_joint_samples_type_1 import (
            ToolCapabilityStudyRequestToolCapabilityStudyBaseSoftJointSamplesType1,  # noqa: PLC0415
        )
        from ..models.tool_capability_study_request_tool_capability_study_base_torque_samples_type_1 import (
            ToolCapabilityStudyRequestToolCapabilityStudyBaseTorqueSamplesType1,  # noqa: PLC0415
        )

        d = dict(src_dict)

        def _parse_torque_samples(
            data: object,
        ) -> list[float] | None | ToolCapabilityStudyRequestToolCapabilityStudyBaseTorqueSamplesType1 | Unset:
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
                torque_samples_type_1 = ToolCapabilityStudyRequestToolCapabilityStudyBaseTorqueSamplesType1.from_dict(
                    data
                )

                return torque_samples_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(
                list[float] | None | ToolCapabilityStudyRequestToolCapabilityStudyBaseTorqueSamplesType1 | Unset, data
            )

        torque_samples = _parse_torque_samples(d.pop("torque_samples", UNSET))

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

        def _parse_sample_count(data: object) -> int | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | str | Unset, data)

        sample_count = _parse_sample_count(d.pop("sample_count", UNSET))

        def _parse_hard_joint_samples(
            data: object,
        ) -> list[float] | None | ToolCapabilityStudyRequestToolCapabilityStudyBaseHardJointSamplesType1 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                hard_joint_samples_type_0 = cast(list[float], data)

                return hard_joint_samples_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                hard_joint_samples_type_1 = (
                    ToolCapabilityStudyRequestToolCapabilityStudyBaseHardJointSamplesType1.from_dict(data)
                )

                return hard_joint_samples_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(
                list[float] | None | ToolCapabilityStudyRequestToolCapabilityStudyBaseHardJointSamplesType1 | Unset,
                data,
            )

        hard_joint_samples = _parse_hard_joint_samples(d.pop("hard_joint_samples", UNSET))

        def _parse_soft_joint_samples(
            data: object,
        ) -> list[float] | None | ToolCapabilityStudyRequestToolCapabilityStudyBaseSoftJointSamplesType1 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                soft_joint_samples_type_0 = cast(list[float], data)

                return soft_joint_samples_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                soft_joint_samples_type_1 = (
                    ToolCapabilityStudyRequestToolCapabilityStudyBaseSoftJointSamplesType1.from_dict(data)
                )

                return soft_joint_samples_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(
                list[float] | None | ToolCapabilityStudyRequestToolCapabilityStudyBaseSoftJointSamplesType1 | Unset,
                data,
            )

        soft_joint_samples = _parse_soft_joint_samples(d.pop("soft_joint_samples", UNSET))

        def _parse_hard_mean_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        hard_mean_torque = _parse_hard_mean_torque(d.pop("hard_mean_torque", UNSET))

        def _parse_hard_torque_sd(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        hard_torque_sd = _parse_hard_torque_sd(d.pop("hard_torque_sd", UNSET))

        def _parse_soft_mean_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        soft_mean_torque = _parse_soft_mean_torque(d.pop("soft_mean_torque", UNSET))

        def _parse_soft_torque_sd(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        soft_torque_sd = _parse_soft_torque_sd(d.pop("soft_torque_sd", UNSET))

        def _parse_nominal_torque(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        nominal_torque = _parse_nominal_torque(d.pop("nominal_torque", UNSET))

        def _parse_relative_tolerance(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        relative_tolerance = _parse_relative_tolerance(d.pop("relative_tolerance", UNSET))

        def _parse_lower_limit(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        lower_limit = _parse_lower_limit(d.pop("lower_limit", UNSET))

        def _parse_upper_limit(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        upper_limit = _parse_upper_limit(d.pop("upper_limit", UNSET))

        def _parse_study(data: object) -> None | ToolCapabilityStudyRequestToolCapabilityStudyBaseStudyType0 | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                study_type_0 = ToolCapabilityStudyRequestToolCapabilityStudyBaseStudyType0(data)

                return study_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | ToolCapabilityStudyRequestToolCapabilityStudyBaseStudyType0 | Unset, data)

        study = _parse_study(d.pop("study", UNSET))

        def _parse_required_index(data: object) -> float | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | str | Unset, data)

        required_index = _parse_required_index(d.pop("required_index", UNSET))

        tool_capability_study_request_tool_capability_study_base = cls(
            torque_samples=torque_samples,
            mean_torque=mean_torque,
            torque_sd=torque_sd,
            sample_count=sample_count,
            hard_joint_samples=hard_joint_samples,
            soft_joint_samples=soft_joint_samples,
            hard_mean_torque=hard_mean_torque,
            hard_torque_sd=hard_torque_sd,
            soft_mean_torque=soft_mean_torque,
            soft_torque_sd=soft_torque_sd,
            nominal_torque=nominal_torque,
            relative_tolerance=relative_tolerance,
            lower_limit=lower_limit,
            upper_limit=upper_limit,
            study=study,
            required_index=required_index,
        )

        return tool_capability_study_request_tool_capability_study_base
