from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define

T = TypeVar("T", bound="CorrelationIn")


@_attrs_define
class CorrelationIn:
    """Two varied inputs joined by a Gaussian copula of this rank (Spearman) correlation.

    Attributes:
        a (str): one varied input
        b (str): another varied input
        rank_correlation (float): Spearman's ρ_S, −0.99…0.99
    """

    a: str
    b: str
    rank_correlation: float

    def to_dict(self) -> dict[str, Any]:
        a = self.a

        b = self.b

        rank_correlation = self.rank_correlation

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "a": a,
                "b": b,
                "rank_correlation": rank_correlation,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        a = d.pop("a")

        b = d.pop("b")

        rank_correlation = d.pop("rank_correlation")

        correlation_in = cls(
            a=a,
            b=b,
            rank_correlation=rank_correlation,
        )

        return correlation_in
