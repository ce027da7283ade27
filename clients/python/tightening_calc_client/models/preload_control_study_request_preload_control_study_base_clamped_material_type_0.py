from enum import StrEnum


class PreloadControlStudyRequestPreloadControlStudyBaseClampedMaterialType0(StrEnum):
    C45_NORMALISED = "C45 (normalised)"
    E295 = "E295"
    EN_AC_42100_T6 = "EN AC-42100 T6"
    EN_AC_46000_DIE_CAST = "EN AC-46000 (die cast)"
    EN_AW_6082_T6 = "EN AW-6082 T6"
    EN_AW_7075_T6 = "EN AW-7075 T6"
    EN_GJL_250 = "EN-GJL-250"
    EN_GJS_400 = "EN-GJS-400"
    EN_GJS_500 = "EN-GJS-500"
    MGAL9ZN1_DIE_CAST = "MgAl9Zn1 (die cast)"
    PA66_CONDITIONED = "PA66 (conditioned)"
    PA66_GF30_CONDITIONED = "PA66 GF30 (conditioned)"
    PC = "PC"
    POM = "POM"
    S235JR = "S235JR"
    TIAL6V4 = "TiAl6V4"
    VALUE_3 = "42CrMo4 (QT)"
    X5CRNI18_10 = "X5CrNi18-10"

    def __str__(self) -> str:
        return str(self.value)
