from enum import StrEnum


class TraceImportFormat(StrEnum):
    CSV = "csv"
    OPC_UA = "opc_ua"
    OPEN_PROTOCOL = "open_protocol"
    REXROTH = "rexroth"

    def __str__(self) -> str:
        return str(self.value)
