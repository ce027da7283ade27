from enum import StrEnum


class JointClampCapabilityStudyRequestJointClampCapabilityStudyBaseHeadStandardType0(StrEnum):
    EN_1665 = "EN 1665"
    ISO_10642 = "ISO 10642"
    ISO_4014 = "ISO 4014"
    ISO_4017 = "ISO 4017"
    ISO_4762 = "ISO 4762"

    def __str__(self) -> str:
        return str(self.value)
