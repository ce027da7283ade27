from enum import StrEnum


class TraceAnalysisStudyRequestTraceAnalysisStudyBaseNutPropertyClassType0(StrEnum):
    VALUE_0 = "04"
    VALUE_1 = "05"
    VALUE_2 = "4"
    VALUE_3 = "5"
    VALUE_4 = "6"
    VALUE_5 = "8"
    VALUE_6 = "9"
    VALUE_7 = "10"
    VALUE_8 = "12"

    def __str__(self) -> str:
        return str(self.value)
