"""What the launcher (missions/common/launch_lib.sh) writes beside a run's log.

  summary.json  missions/common/mission_summary.py's result; its `evals` are the grader's
                HAZARDSET_EVAL fields per vehicle (older files: `scores`, or a dict by vehicle)
  cpu.txt       one `NAME USER_S SYSTEM_S` line per process (CPU seconds)
"""

import json

from .text import json_number, key_values


def read_summary(path):
    """summary.json as a dict; OSError when unreadable, ValueError when not a JSON object."""
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    if not isinstance(data, dict):
        raise ValueError("summary %s is not a JSON object" % path)
    return data


def summary_evals(data):
    """[{field: text}] of the evaluations in a summary (keys in lower case, values as text);
    entries that are neither an object nor a `key=value` text give {}."""
    evals = data.get("evals", data.get("scores", []))
    if isinstance(evals, dict):
        evals = [dict(v, vname=k) if isinstance(v, dict) else v for k, v in evals.items()]
    out = []
    for e in evals if isinstance(evals, list) else []:
        if isinstance(e, str):
            out.append(key_values(e))
        elif isinstance(e, dict):
            out.append({str(k).lower(): str(v) for k, v in e.items()})
        else:
            out.append({})
    return out


def read_cpu(path):
    """[{name, cpu_user_s, cpu_system_s}] from cpu.txt; lines that are not a name and two
    numbers are skipped, an unreadable file gives []."""
    out = []
    try:
        with open(path, encoding="utf-8") as f:
            for line in f:
                parts = line.split()
                if len(parts) != 3:
                    continue
                user_s, system_s = json_number(parts[1]), json_number(parts[2])
                if user_s is not None and system_s is not None:
                    out.append({"name": parts[0], "cpu_user_s": user_s, "cpu_system_s": system_s})
    except OSError:
        pass
    return out
