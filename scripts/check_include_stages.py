#!/usr/bin/env python3
"""Checks that the internal headers include only their own stage or earlier ones, in the order of the
pipeline (include/CGAL/Anisotropic_fairing/internal/README.md), and that every stage folder says what
it holds. Exit 1 with the offending includes otherwise."""
import os, re, sys
STAGES = ['types', 'mesh', 'loop', 'element', 'assembly', 'solve', 'flow', 'surface', 'run']
root = os.path.join(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..'),
                    'include', 'CGAL', 'Anisotropic_fairing', 'internal')
include = re.compile(r'#include <CGAL/Anisotropic_fairing/internal/(\w+)/[\w/]+\.h>')
bad = []
for stage in sorted(os.listdir(root)):
    folder = os.path.join(root, stage)
    if not os.path.isdir(folder): continue
    if stage not in STAGES: bad.append('%s: a folder that is not a stage of the pipeline' % stage); continue
    if not os.path.isfile(os.path.join(folder, 'README.md')): bad.append('%s: no README.md' % stage)
    # a stage's subfolders (flow/stop/) belong to it
    headers = sorted(os.path.relpath(os.path.join(d, f), folder) for d, _, files in os.walk(folder) for f in files if f.endswith('.h'))
    for name in headers:
        for line, text in enumerate(open(os.path.join(folder, name)), 1):
            m = include.search(text)
            if m and (m.group(1) not in STAGES or STAGES.index(m.group(1)) > STAGES.index(stage)):
                bad.append('%s/%s:%d includes a later stage: %s' % (stage, name, line, text.strip()))
print('\n'.join(bad) if bad else 'every internal include runs from a stage to itself or an earlier one')
sys.exit(1 if bad else 0)
