from enum import StrEnum


class ClutchBallSettingStudyRequestClutchBallSettingStudyBaseSpringMaterialType0(StrEnum):
    CUSTOM = "custom"
    EN10270_1_DH = "EN10270-1-DH"
    EN10270_1_SH = "EN10270-1-SH"
    VALUE_3 = "1.4310"

    def __str__(self) -> str:
        return str(self.value)
