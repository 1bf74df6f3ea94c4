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

and prints the score table. Standard library only. Bad lines are skipped and counted; a missing
evaluation is shown as "-" (the table says which vehicle has none). Exit status 0, or 1 when the
log or the hazard file cannot be read.
"""

import argparse
import json
import sys


def split_fields(text):
    """`a=1,b=2` -> dict; commas inside {...} do not split (MOOS habit)."""
    fields, depth, start = {}, 0, 0
    parts = []
    for i, c in enumerate(text):
        if c == '{':
            depth += 1
        elif c == '}':
            depth = max(0, depth - 1)
        elif c == ',' and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    for part in parts:
        if '=' in part:
            key, value = part.split('=', 1)
            fields[key.strip().lower()] = value.strip()
    return fields


def number(text):
    """An int or float for a numeric text, else None."""
    if text is None:
        return None
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return None


def read_truth(path):
    truth = {}
    with open(path, encoding='utf-8', errors='replace') as f:
        for line in f:
            line = line.split('//', 1)[0].strip()
            if '=' not in line:
                continue
            key, value = line.split('=', 1)
            if key.strip().lower() != 'hazard':
                continue
            fields = split_fields(value)
            if 'label' in fields and 'type' in fields:
                truth[fields['label']] = fields['type'].lower()
    return truth


def read_alog(path):
    """Yields (time, variable, source, value) for every well-formed line."""
    bad = 0
    with open(path, encoding='utf-8', errors='replace') as f:
        for line in f:
            if line.startswith('%%') or not line.strip():
                continue
            parts = line.rstrip('\n').split(None, 3)
            if len(parts) < 3:
                bad += 1
                continue
            try:
                t = float(parts[0])
            except ValueError:
                bad += 1
                continue
            yield t, parts[1], parts[2], parts[3] if len(parts) > 3 else ''
    if bad:
        print('mission_summary: %d malformed log lines skipped' % bad, file=sys.stderr)


def read_cpu(path):
    """[{name, cpu_user_s, cpu_system_s}] from the launcher's cpu.txt ([] if unreadable)."""
    out = []
    try:
        with open(path, encoding='utf-8') as f:
            for line in f:
                parts = line.split()
                if len(parts) == 3 and number(parts[1]) is not None and number(parts[2]) is not None:
                    out.append({'name': parts[0], 'cpu_user_s': number(parts[1]),
                                'cpu_system_s': number(parts[2])})
    except OSError:
        pass
    return out


def vehicle_record(vehicles, name):
    return vehicles.setdefault(name, {
        'setting': None, 'detections': 0, 'hazard_detections': 0, 'benign_detections': 0,
        'classifications': 0, 'correct_classifications': 0, 'reported': None,
        'handovers_sent': 0})


def summarise(alog, truth, final):
    vehicles, evals = {}, {}
    deploy_s, end_s = None, None
    for t, var, _source, value in read_alog(alog):
        if var == 'DEPLOY_ALL' and deploy_s is None:
            deploy_s = t
        elif var == 'UHZ_CONFIG_ACK':
            f = split_fields(value)
            if 'vname' in f:
                vehicle_record(vehicles, f['vname'])['setting'] = {
                    k: number(f.get(k)) for k in ('width', 'pd', 'pfa', 'pclass')}
        elif var == 'UHZ_DETECTION_REPORT':
            f = split_fields(value)
            if 'vname' in f:
                v = vehicle_record(vehicles, f['vname'])
                v['detections'] += 1
                kind = truth.get(f.get('label'))
                if kind == 'hazard':
                    v['hazard_detections'] += 1
                elif kind == 'benign':
                    v['benign_detections'] += 1
        elif var == 'UHZ_HAZARD_REPORT':
            f = split_fields(value)
            if 'vname' in f:
                v = vehicle_record(vehicles, f['vname'])
                v['classifications'] += 1
                if truth.get(f.get('label')) == f.get('type', '').lower():
                    v['correct_classifications'] += 1
        elif var == 'HAZARDSET_REPORT':
            parts = [p for p in value.split('#') if p]
            source = next((p.split('=', 1)[1] for p in parts if p.startswith('source=')), None)
            if source:
                vehicle_record(vehicles, source)['reported'] = sum(
                    1 for p in parts if 'label=' in p)
        elif var == 'HAZARD_HANDOVER':
            source = value.split('#', 1)[0]
            if source.startswith('source='):
                vehicle_record(vehicles, source[len('source='):])['handovers_sent'] += 1
        elif var == 'HAZARDSET_EVAL':
            f = split_fields(value)
            if 'vname' in f:
                record = {k: (number(v) if number(v) is not None else v) for k, v in f.items()}
                evals[f['vname']] = record
                if f['vname'] in final:
                    end_s = t
    sim_s = (end_s - deploy_s) if (end_s is not None and deploy_s is not None) else None
    return vehicles, evals, sim_s


def fmt(value, spec='%g'):
    return '-' if value is None else spec % value


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
    with open(a.out, 'w', encoding='utf-8') as f:
        json.dump(summary, f, indent=2, sort_keys=True)
        f.write('\n')
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
