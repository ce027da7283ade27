from enum import StrEnum


class JointClampCapabilityStudyRequestJointClampCapabilityStudyBaseNutType0(StrEnum):
    ISO_4032 = "ISO 4032"
    ISO_4033 = "ISO 4033"
    ISO_4035 = "ISO 4035"

    def __str__(self) -> str:
        return str(self.value)
