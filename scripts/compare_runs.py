#!/usr/bin/env python3
"""Compares two directories written by fixed_runs.sh: every number in every output file and JSON
report (timings excepted) must agree to 1e-12 relative; the words between the numbers exactly."""
import json, os, re, sys
NUMBER = re.compile(r'[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|nan|inf')
def close(a, b): return a == b or abs(a - b) <= 1e-12 * max(abs(a), abs(b), 1e-300)
def ignored(key): return key.endswith('seconds') or key in ('input', 'output')   # timings, and the paths of the two runs
def flatten(x, key=''):
    if isinstance(x, dict):
        for k, v in x.items():
            if not ignored(k): yield from flatten(v, key + '.' + k)
    elif isinstance(x, list):
        for i, v in enumerate(x): yield from flatten(v, '%s[%d]' % (key, i))
    else: yield key, x
def compare_text(a, b):
    ta, tb = NUMBER.split(a), NUMBER.split(b)
    if ta != tb: return 'words differ'
    for x, y in zip(NUMBER.findall(a), NUMBER.findall(b)):
        if not close(float(x), float(y)): return 'number %s against %s' % (x, y)
    return None
a, b = sys.argv[1], sys.argv[2]; bad = 0
for name in sorted(set(os.listdir(a)) | set(os.listdir(b))):
    pa, pb = os.path.join(a, name), os.path.join(b, name)
    if not (os.path.exists(pa) and os.path.exists(pb)): print(name, 'only in one'); bad += 1; continue
    if name.endswith('.json'):
        ja, jb = dict(flatten(json.load(open(pa)))), dict(flatten(json.load(open(pb))))
        diff = [k for k in ja.keys() | jb.keys() if k not in ja or k not in jb or
                (isinstance(ja[k], (int, float)) and isinstance(jb[k], (int, float)) and not close(ja[k], jb[k])) or
                (not isinstance(ja[k], (int, float)) and ja[k] != jb[k] and compare_text(str(ja[k]), str(jb[k])))]
        why = diff and 'JSON keys differ: ' + ', '.join(sorted(diff)[:5])
    elif name.endswith('.stderr') or name.endswith('.stdout'):
        strip = lambda s: re.sub(r'\d+\.\d+ ?s\b', 's', s)
        why = compare_text(strip(open(pa).read()), strip(open(pb).read()))
    else:
        why = compare_text(open(pa, errors='replace').read(), open(pb, errors='replace').read())
    if why: print(name + ':', why); bad += 1
print('%d files differ' % bad); sys.exit(1 if bad else 0)
