#!/usr/bin/env python3
"""The result of a finished mission run: summary.json and the score table (launch_lib.sh).

Reads the run's .alog (pLogger's format: TIME VARIABLE SOURCE VALUE after '%%' header lines)
and the ground truth (the hazard file), and writes summary.json:

  title, mission, seed, warp, moosdb        as launched
  sim_seconds                               DEPLOY_ALL to the last final vehicle's evaluation
  real_seconds                              the launcher's wall time (given)
  final_vehicles, score                     the final vehicles and the last one's norm_score
  truth                                     {"hazards": H, "benign": B}
  evals                                     the grader's latest HAZARDSET_EVAL per vehicle, as
                                            numbers (the form tools/render_mission.py reads)
  vehicles                                  per vehicle: the acknowledged sensor setting,
                                            detections (of hazards / benign objects),
                                            classifications (and how many were right), the
                                            size of the last HAZARDSET_REPORT, hand-overs sent

and prints the score table. Standard library only; the files are read by tools/mission_files
(the rules of the C++ readers: a value that is not a finite number, `nan` included, is not a
number; such a field of an evaluation stays text and shows as "-"). Bad lines are skipped and
counted; a missing evaluation is shown as "-" (the table says which vehicle has none). Exit
status 0, or 1 when the log or the hazard file cannot be read or summary.json cannot be written
(--out follows tools/mission_files/output_file.py: a device, FIFO or link is written through).
"""

import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from mission_files.alog import AlogSkips, read_alog  # noqa: E402  (tools/mission_files)
from mission_files.hazard_file import read_hazard_file  # noqa: E402
from mission_files.messages import hazard_handover, hazardset_report  # noqa: E402
from mission_files.output_file import write_output_file  # noqa: E402
from mission_files.run_files import read_cpu  # noqa: E402
from mission_files.text import json_number, key_values  # noqa: E402


def read_truth(path):
    """{label: "hazard" or "benign"} of the objects the sensor loads from the hazard file."""
    return {o['label']: o['type'] for o in read_hazard_file(path).objects}


def vehicle_record(vehicles, name):
    return vehicles.setdefault(name, {
        'setting': None, 'detections': 0, 'hazard_detections': 0, 'benign_detections': 0,
        'classifications': 0, 'correct_classifications': 0, 'reported': None,
        'handovers_sent': 0})


def summarise(alog, truth, final):
    vehicles, evals = {}, {}
    deploy_s, end_s = None, None
    malformed = []
    skips = AlogSkips()   # unusable times and over-long lines: counted, one warning a kind
    entries = read_alog(alog, on_malformed=lambda line_no, _why: malformed.append(line_no),
                        skips=skips)
    for t, var, _source, value, _line_no in entries:
        if var == 'DEPLOY_ALL' and deploy_s is None:
            deploy_s = t
        elif var == 'UHZ_CONFIG_ACK':
            f = key_values(value)
            if 'vname' in f:
                vehicle_record(vehicles, f['vname'])['setting'] = {
                    k: json_number(f.get(k)) for k in ('width', 'pd', 'pfa', 'pclass')}
        elif var == 'UHZ_DETECTION_REPORT':
            f = key_values(value)
            if 'vname' in f:
                v = vehicle_record(vehicles, f['vname'])
                v['detections'] += 1
                kind = truth.get(f.get('label'))
                if kind == 'hazard':
                    v['hazard_detections'] += 1
                elif kind == 'benign':
                    v['benign_detections'] += 1
        elif var == 'UHZ_HAZARD_REPORT':
            f = key_values(value)
            if 'vname' in f:
                v = vehicle_record(vehicles, f['vname'])
                v['classifications'] += 1
                if truth.get(f.get('label')) == f.get('type', '').lower():
                    v['correct_classifications'] += 1
        elif var == 'HAZARDSET_REPORT':
            source, labels = hazardset_report(value)
            if source:
                vehicle_record(vehicles, source)['reported'] = len(labels)
        elif var == 'HAZARD_HANDOVER':
            source = hazard_handover(value)[0].get('source')
            if source:
                vehicle_record(vehicles, source)['handovers_sent'] += 1
        elif var == 'HAZARDSET_EVAL':
            f = key_values(value)
            if 'vname' in f:
                # A field that is not a number (`nan` included) stays text: summary.json is
                # strict JSON, and the table shows "-" for it.
                record = {k: (json_number(v) if json_number(v) is not None else v)
                          for k, v in f.items()}
                evals[f['vname']] = record
                if f['vname'] in final:
                    end_s = t
    if malformed:
        print('mission_summary: %d malformed log lines skipped' % len(malformed), file=sys.stderr)
    for message in skips.warnings(alog):
        print('mission_summary: ' + message, file=sys.stderr)
    sim_s = (end_s - deploy_s) if (end_s is not None and deploy_s is not None) else None
    return vehicles, evals, sim_s


def fmt(value, spec='%g'):
    """A number in `spec`; "-" for a missing value or one that is not a number."""
    numeric = isinstance(value, (int, float)) and not isinstance(value, bool)
    return spec % value if numeric else '-'


def table(summary):
    lines = []
    header = ('vehicle', 'sensor W/pd/pfa/pclass', 'detections H+B', 'classified (right)',
              'reported', 'correct', 'missed', 'false alarms', 'score')
    rows = []
    for name in sorted(summary['vehicles']):
        v = summary['vehicles'][name]
        e = next((x for x in summary['evals'] if x.get('vname') == name), {})
        s = v['setting'] or {}
        sensor = '/'.join(fmt(s.get(k)) for k in ('width', 'pd', 'pfa', 'pclass')) if s else '-'
        rows.append((name, sensor,
                     '%d = %d+%d' % (v['detections'], v['hazard_detections'], v['benign_detections']),
                     '%d (%d)' % (v['classifications'], v['correct_classifications']),
                     fmt(v['reported'], '%d'), fmt(e.get('correct_hazards'), '%d'),
                     fmt(e.get('missed_hazards'), '%d'), fmt(e.get('false_alarms'), '%d'),
                     fmt(e.get('norm_score'), '%.2f')))
    widths = [max(len(str(r[i])) for r in rows + [header]) for i in range(len(header))]
    for r in [header] + rows:
        lines.append('  '.join(str(c).ljust(w) for c, w in zip(r, widths)).rstrip())
    return lines


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split('\n', 1)[0])
    p.add_argument('--alog', required=True)
    p.add_argument('--hazards', required=True)
    p.add_argument('--out', required=True)
    p.add_argument('--title', default='')
    p.add_argument('--mission', default='')
    p.add_argument('--seed', type=int)
    p.add_argument('--warp', type=float)
    p.add_argument('--moosdb', default='lite')
    p.add_argument('--real-seconds', type=float)
    p.add_argument('--cpu', help='cpu.txt of the launcher: "name user_s system_s" lines')
    p.add_argument('--final', nargs='*', default=[])
    a = p.parse_args(argv)
    try:
        truth = read_truth(a.hazards)
        vehicles, evals, sim_s = summarise(a.alog, truth, set(a.final))
    except OSError as e:
        print('mission_summary: %s' % e, file=sys.stderr)
        return 1
    last_final = a.final[-1] if a.final else None
    score = evals.get(last_final, {}).get('norm_score') if last_final else None
    score = None if isinstance(score, str) else score
    summary = {
        'title': a.title, 'mission': a.mission, 'seed': a.seed, 'warp': a.warp,
        'moosdb': a.moosdb, 'sim_seconds': sim_s, 'real_seconds': a.real_seconds,
        'final_vehicles': a.final, 'score': score,
        'truth': {'hazards': sum(1 for k in truth.values() if k == 'hazard'),
                  'benign': sum(1 for k in truth.values() if k == 'benign')},
        'evals': [evals[k] for k in sorted(evals)],
        'vehicles': vehicles,
        'processes': read_cpu(a.cpu) if a.cpu else [],
    }
    try:
        # The rule of every user-named output: replaced atomically, a device or FIFO written
        # through, a link kept (tools/mission_files/output_file.py).
        write_output_file(a.out, json.dumps(summary, indent=2, sort_keys=True) + '\n')
    except OSError as e:
        print('mission_summary: %s' % e, file=sys.stderr)
        return 1
    print()
    print(a.title)
    print('seed %s, warp %g, MOOSDB %s: %s s simulated in %s s' % (
        a.seed, a.warp or 0, a.moosdb, fmt(sim_s, '%.0f'), fmt(a.real_seconds, '%.1f')))
    print('truth: %d hazards, %d benign objects' % (summary['truth']['hazards'],
                                                    summary['truth']['benign']))
    print()
    for line in table(summary):
        print(line)
    if summary['processes']:
        total = sum(p['cpu_user_s'] + p['cpu_system_s'] for p in summary['processes'])
        print()
        print('CPU seconds (user+system): %.1f in all; ' % total + ', '.join(
            '%s %.1f' % (p['name'], p['cpu_user_s'] + p['cpu_system_s'])
            for p in summary['processes']))
    print()
    if last_final:
        missing = [v for v in a.final if v not in evals]
        if missing:
            print('No evaluation for: %s (empty report)' % ', '.join(missing))
        print('Mission score (%s\'s report): %s / 100' % (last_final, fmt(score, '%.2f')))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
