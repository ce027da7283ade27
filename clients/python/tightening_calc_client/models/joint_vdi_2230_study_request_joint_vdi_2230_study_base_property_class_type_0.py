from enum import StrEnum


class JointVdi2230StudyRequestJointVdi2230StudyBasePropertyClassType0(StrEnum):
    VALUE_0 = "4.6"
    VALUE_1 = "4.8"
    VALUE_2 = "5.6"
    VALUE_3 = "5.8"
    VALUE_4 = "6.8"
    VALUE_5 = "8.8"
    VALUE_6 = "9.8"
    VALUE_7 = "10.9"
    VALUE_8 = "12.9"

    def __str__(self) -> str:
        return str(self.value)
