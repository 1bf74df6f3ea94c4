"""The values of the postings the tools count, as pHazardMgr and uFldHazardMetric write them
(docs/mission-logic.md): `#`-separated reports and hand-overs. Field lists such as
UHZ_DETECTION_REPORT or HAZARDSET_EVAL are plain `key=value` lists (text.key_values).
"""

from .text import key_values

REPORT_HEADER_KEYS = ("name", "transit_path_width", "search_region")
HANDOVER_HEADER_PARTS = 3   # source=..#dest=..#prior=.. then one part per object


def hazardset_report(value):
    """(source, [labels]) of a HAZARDSET_REPORT `source=V#name=V#x=..,y=..,label=L#...`; source
    is "" when the report names none."""
    source, labels = "", []
    for part in value.split("#"):
        part = part.strip()
        if part.startswith("source"):
            source = part.split("=", 1)[-1].strip()
        elif part.startswith(REPORT_HEADER_KEYS):
            continue
        else:
            at = part.find("label=")
            if at >= 0:
                label = part[at + len("label="):].split(",", 1)[0].strip()
                if label:
                    labels.append(label)
    return source, labels


def hazard_handover(value):
    """(header fields, number of objects) of a HAZARD_HANDOVER `source=A#dest=B#prior=P#obj#...`."""
    parts = value.split("#")
    header = {}
    for part in parts[:HANDOVER_HEADER_PARTS]:
        header.update(key_values(part))
    return header, max(0, len(parts) - HANDOVER_HEADER_PARTS)
