#!/usr/bin/env python3
"""What the default run would pick if it added the normal-field candidate to its result (issue 53, point 3): the
flow the default run keeps today (SURE of the positions among its three flows, the `kept` column of
bench/gmnf/results_all.md), replaced by the normal field where the face-normal estimate puts the normal field
lower. Reads the per-case tables that `bench_estimate_soundness CASES_DIR "" normals|on-result [minus]` prints
(each candidate: estimate / loss / linearised loss / relative squared angle / mean angle, steps, stop) and says
on how many cases that pick is within 5% of the best candidate's mean angle, and where it differs from today's.

    python3 bench/selection_with_normal_field.py TABLE.md...   (run from the repository's root)"""
import math, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))


def kept_today():
    kept = {}
    for line in open(os.path.join(HERE, 'gmnf', 'results_all.md')):
        c = [x.strip() for x in line.strip().strip('|').split('|')]
        if len(c) > 10 and ',' in c[9]: kept[c[0]] = c[9].split(',')[0]
    return kept


def read_table(path):
    cases = {}
    for line in open(path):
        if not line.startswith('| ') or line.startswith('| case'): continue
        c = [x.strip() for x in line.strip().strip('|').split('|')]
        if len(c) < 5 or c[4] in ('-', ''): continue
        candidates = {}
        for part in c[1].split('; '):
            name, rest = part.split(': ', 1)
            f = [x.strip() for x in rest.split('/')]
            estimate = f[0].replace('>=', '')   # a carried estimate: a bound it could only exceed
            candidates[name] = (float(estimate) if estimate != 'nan' else math.nan, float(f[4].split(',')[0]))
        cases[c[0]] = candidates
    return cases


def main():
    kept = kept_today()
    for path in sys.argv[1:]:
        within, counted, lines = 0, 0, []
        for case, c in read_table(path).items():
            k = kept.get(case)
            if k not in c: continue
            best = min(angle for _, angle in c.values())
            pick = 'normal field' if 'normal field' in c and c['normal field'][0] < c[k][0] else k
            ratio, today = c[pick][1] / best, c[k][1] / best
            counted += 1
            within += ratio <= 1.05
            if ratio > 1.05 or pick != k:
                lines.append('  %s: today %s %.3f -> %s %.3f' % (case, k, today, pick, ratio))
        print('%s: within 5%% of the best on %d of %d cases' % (path, within, counted))
        print('\n'.join(lines))


if __name__ == '__main__':
    main()
