from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="ImpactRareResults")


@_attrs_define
class ImpactRareResults:
    """
    Attributes:
        release_speed (float | None | Unset): ω_M: flywheel speed when the half-coupling reaches h_1 and frees the
            striker [002, after eq. 4] for the chosen roller geometry (simulation: the first crossing of h_1) [rad/s]
        spin_up_time (float | None | Unset): time from motor start to release [002, eq. 1] [s]
        release_radius (float | None | Unset): r: roller centre radius at release, x_0 + κ·h_1 for the chosen geometry
            [m]
        half_coupling_release_speed (float | None | Unset): axial speed of the half-coupling (away from the anvil) at
            release, carried into stage 2 [m/s]
        engagement_acceleration (float | None | Unset): B: the striker's acceleration at the start of stage 2 [002, eq.
            5] (was oscillation_B) [m/s^2]
        engagement_frequency (float | None | Unset): k: angular frequency of the striker's stage-2 motion [002, eq. 5]
            (was oscillation_k) [rad/s]
        max_striker_travel (float | None | Unset): the farthest the springs carry the striker in stage 2 (2B/k² from
            rest [002, eq. 5], more with the release velocity) [m]
        engagement_time (float | None | Unset): time from release for the striker to travel h_2 [002, eq. 5]; null if
            never [s]
        engagement_window (float | None | Unset): φ_eng/ω_M: time the anvil's opening takes to pass [002, after eq. 5]
            [s]
        engagement_start (float | None | Unset): time from motor start at which the striker is freed and the engagement
            window opens (= spin_up_time) [s]
        engagement_end (float | None | Unset): time from motor start at which the anvil's opening has passed:
            spin_up_time + engagement_window [s]
        full_engagement (bool | None | Unset): true when the striker reaches h_2 inside the window (no edge blow)
            [dimensionless]
        engagement_margin (float | None | Unset): (window − engagement time)/window: the spare fraction of the window;
            negative means an edge blow [dimensionless]
        blow_time (float | None | Unset): time from motor start of the blow (striker at h_2): the end of stage 2 [s]
        spring_height_limit (float | None | Unset): the upper engagement height [002, eq. 6] allows for balanced
            preloads, 2M_2g/(c_3 − c_1), 0 when nothing is reachable (g ≤ 0); null when there is no upper limit (c_3 ≤ c_1)
            [m]
        min_return_spring_rate (float | None | Unset): smallest c_3 that brings the striker back the jaw height from
            rest in the paper's reduction of [002, eq. 3] (half-coupling at rest, rollers unloaded) [N/m]
        relock_margin (float | None | Unset): c_2λ_2 + m_2g − c_3λ_3f: the static re-lock condition, [002, eq. 4] at the
            end of the travel (the relock check also follows the shaft's motion) [N]
        return_time (float | None | Unset): stage 3: time from the blow until the striker is back the jaw height h_3
            [002, eq. 3], rollers and half-coupling moving [s]
        striker_home_time (float | None | Unset): time from motor start at which the striker is home and the balls can
            re-lock it: the end of stage 3 [s]
        relock_time (float | None | Unset): stage 4: time for the stepped shaft to travel back h_1 against the cone
            friction [002, eq. 4] [s]
        cycle_time (float | None | Unset): time from motor start to the re-lock: the end of stage 4 and of the impact
            [s]
    """

    release_speed: float | None | Unset = UNSET
    spin_up_time: float | None | Unset = UNSET
    release_radius: float | None | Unset = UNSET
    half_coupling_release_speed: float | None | Unset = UNSET
    engagement_acceleration: float | None | Unset = UNSET
    engagement_frequency: float | None | Unset = UNSET
    max_striker_travel: float | None | Unset = UNSET
    engagement_time: float | None | Unset = UNSET
    engagement_window: float | None | Unset = UNSET
    engagement_start: float | None | Unset = UNSET
    engagement_end: float | None | Unset = UNSET
    full_engagement: bool | None | Unset = UNSET
    engagement_margin: float | None | Unset = UNSET
    blow_time: float | None | Unset = UNSET
    spring_height_limit: float | None | Unset = UNSET
    min_return_spring_rate: float | None | Unset = UNSET
    relock_margin: float | None | Unset = UNSET
    return_time: float | None | Unset = UNSET
    striker_home_time: float | None | Unset = UNSET
    relock_time: float | None | Unset = UNSET
    cycle_time: float | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        release_speed: float | None | Unset
        if isinstance(self.release_speed, Unset):
            release_speed = UNSET
        else:
            release_speed = self.release_speed

        spin_up_time: float | None | Unset
        if isinstance(self.spin_up_time, Unset):
            spin_up_time = UNSET
        else:
            spin_up_time = self.spin_up_time

        release_radius: float | None | Unset
        if isinstance(self.release_radius, Unset):
            release_radius = UNSET
        else:
            release_radius = self.release_radius

        half_coupling_release_speed: float | None | Unset
        if isinstance(self.half_coupling_release_speed, Unset):
            half_coupling_release_speed = UNSET
        else:
            half_coupling_release_speed = self.half_coupling_release_speed

        engagement_acceleration: float | None | Unset
        if isinstance(self.engagement_acceleration, Unset):
            engagement_acceleration = UNSET
        else:
            engagement_acceleration = self.engagement_acceleration

        engagement_frequency: float | None | Unset
        if isinstance(self.engagement_frequency, Unset):
            engagement_frequency = UNSET
        else:
            engagement_frequency = self.engagement_frequency

        max_striker_travel: float | None | Unset
        if isinstance(self.max_striker_travel, Unset):
            max_striker_travel = UNSET
        else:
            max_striker_travel = self.max_striker_travel

        engagement_time: float | None | Unset
        if isinstance(self.engagement_time, Unset):
            engagement_time = UNSET
        else:
            engagement_time = self.engagement_time

        engagement_window: float | None | Unset
        if isinstance(self.engagement_window, Unset):
            engagement_window = UNSET
        else:
            engagement_window = self.engagement_window

        engagement_start: float | None | Unset
        if isinstance(self.engagement_start, Unset):
            engagement_start = UNSET
        else:
            engagement_start = self.engagement_start

        engagement_end: float | None | Unset
        if isinstance(self.engagement_end, Unset):
            engagement_end = UNSET
        else:
            engagement_end = self.engagement_end

        full_engagement: bool | None | Unset
        if isinstance(self.full_engagement, Unset):
            full_engagement = UNSET
        else:
            full_engagement = self.full_engagement

        engagement_margin: float | None | Unset
        if isinstance(self.engagement_margin, Unset):
            engagement_margin = UNSET
        else:
            engagement_margin = self.engagement_margin

        blow_time: float | None | Unset
        if isinstance(self.blow_time, Unset):
            blow_time = UNSET
        else:
            blow_time = self.blow_time

        spring_height_limit: float | None | Unset
        if isinstance(self.spring_height_limit, Unset):
            spring_height_limit = UNSET
        else:
            spring_height_limit = self.spring_height_limit

        min_return_spring_rate: float | None | Unset
        if isinstance(self.min_return_spring_rate, Unset):
            min_return_spring_rate = UNSET
        else:
            min_return_spring_rate = self.min_return_spring_rate

        relock_margin: float | None | Unset
        if isinstance(self.relock_margin, Unset):
            relock_margin = UNSET
        else:
            relock_margin = self.relock_margin

        return_time: float | None | Unset
        if isinstance(self.return_time, Unset):
            return_time = UNSET
        else:
            return_time = self.return_time

        striker_home_time: float | None | Unset
        if isinstance(self.striker_home_time, Unset):
            striker_home_time = UNSET
        else:
            striker_home_time = self.striker_home_time

        relock_time: float | None | Unset
        if isinstance(self.relock_time, Unset):
            relock_time = UNSET
        else:
            relock_time = self.relock_time

        cycle_time: float | None | Unset
        if isinstance(self.cycle_time, Unset):
            cycle_time = UNSET
        else:
            cycle_time = self.cycle_time

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update({})
        if release_speed is not UNSET:
            field_dict["release_speed"] = release_speed
        if spin_up_time is not UNSET:
            field_dict["spin_up_time"] = spin_up_time
        if release_radius is not UNSET:
            field_dict["release_radius"] = release_radius
        if half_coupling_release_speed is not UNSET:
            field_dict["half_coupling_release_speed"] = half_coupling_release_speed
        if engagement_acceleration is not UNSET:
            field_dict["engagement_acceleration"] = engagement_acceleration
        if engagement_frequency is not UNSET:
            field_dict["engagement_frequency"] = engagement_frequency
        if max_striker_travel is not UNSET:
            field_dict["max_striker_travel"] = max_striker_travel
        if engagement_time is not UNSET:
            field_dict["engagement_time"] = engagement_time
        if engagement_window is not UNSET:
            field_dict["engagement_window"] = engagement_window
        if engagement_start is not UNSET:
            field_dict["engagement_start"] = engagement_start
        if engagement_end is not UNSET:
            field_dict["engagement_end"] = engagement_end
        if full_engagement is not UNSET:
            field_dict["full_engagement"] = full_engagement
        if engagement_margin is not UNSET:
            field_dict["engagement_margin"] = engagement_margin
        if blow_time is not UNSET:
            field_dict["blow_time"] = blow_time
        if spring_height_limit is not UNSET:
            field_dict["spring_height_limit"] = spring_height_limit
        if min_return_spring_rate is not UNSET:
            field_dict["min_return_spring_rate"] = min_return_spring_rate
        if relock_margin is not UNSET:
            field_dict["relock_margin"] = relock_margin
        if return_time is not UNSET:
            field_dict["return_time"] = return_time
        if striker_home_time is not UNSET:
            field_dict["striker_home_time"] = striker_home_time
        if relock_time is not UNSET:
            field_dict["relock_time"] = relock_time
        if cycle_time is not UNSET:
            field_dict["cycle_time"] = cycle_time

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_release_speed(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        release_speed = _parse_release_speed(d.pop("release_speed", UNSET))

        def _parse_spin_up_time(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spin_up_time = _parse_spin_up_time(d.pop("spin_up_time", UNSET))

        def _parse_release_radius(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        release_radius = _parse_release_radius(d.pop("release_radius", UNSET))

        def _parse_half_coupling_release_speed(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        half_coupling_release_speed = _parse_half_coupling_release_speed(d.pop("half_coupling_release_speed", UNSET))

        def _parse_engagement_acceleration(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        engagement_acceleration = _parse_engagement_acceleration(d.pop("engagement_acceleration", UNSET))

        def _parse_engagement_frequency(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        engagement_frequency = _parse_engagement_frequency(d.pop("engagement_frequency", UNSET))

        def _parse_max_striker_travel(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        max_striker_travel = _parse_max_striker_travel(d.pop("max_striker_travel", UNSET))

        def _parse_engagement_time(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        engagement_time = _parse_engagement_time(d.pop("engagement_time", UNSET))

        def _parse_engagement_window(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        engagement_window = _parse_engagement_window(d.pop("engagement_window", UNSET))

        def _parse_engagement_start(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        engagement_start = _parse_engagement_start(d.pop("engagement_start", UNSET))

        def _parse_engagement_end(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        engagement_end = _parse_engagement_end(d.pop("engagement_end", UNSET))

        def _parse_full_engagement(data: object) -> bool | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(bool | None | Unset, data)

        full_engagement = _parse_full_engagement(d.pop("full_engagement", UNSET))

        def _parse_engagement_margin(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        engagement_margin = _parse_engagement_margin(d.pop("engagement_margin", UNSET))

        def _parse_blow_time(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        blow_time = _parse_blow_time(d.pop("blow_time", UNSET))

        def _parse_spring_height_limit(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        spring_height_limit = _parse_spring_height_limit(d.pop("spring_height_limit", UNSET))

        def _parse_min_return_spring_rate(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        min_return_spring_rate = _parse_min_return_spring_rate(d.pop("min_return_spring_rate", UNSET))

        def _parse_relock_margin(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        relock_margin = _parse_relock_margin(d.pop("relock_margin", UNSET))

        def _parse_return_time(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        return_time = _parse_return_time(d.pop("return_time", UNSET))

        def _parse_striker_home_time(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        striker_home_time = _parse_striker_home_time(d.pop("striker_home_time", UNSET))

        def _parse_relock_time(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        relock_time = _parse_relock_time(d.pop("relock_time", UNSET))

        def _parse_cycle_time(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        cycle_time = _parse_cycle_time(d.pop("cycle_time", UNSET))

        impact_rare_results = cls(
            release_speed=release_speed,
            spin_up_time=spin_up_time,
            release_radius=release_radius,
            half_coupling_release_speed=half_coupling_release_speed,
            engagement_acceleration=engagement_acceleration,
            engagement_frequency=engagement_frequency,
            max_striker_travel=max_striker_travel,
            engagement_time=engagement_time,
            engagement_window=engagement_window,
            engagement_start=engagement_start,
            engagement_end=engagement_end,
            full_engagement=full_engagement,
            engagement_margin=engagement_margin,
            blow_time=blow_time,
            spring_height_limit=spring_height_limit,
            min_return_spring_rate=min_return_spring_rate,
            relock_margin=relock_margin,
            return_time=return_time,
            striker_home_time=striker_home_time,
            relock_time=relock_time,
            cycle_time=cycle_time,
        )

        impact_rare_results.additional_properties = d
        return impact_rare_results

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
