#!/usr/bin/env python3
"""Wraps the C++ lines over 120 characters with clang-format (the repository's .clang-format), touching no
other line: `scripts/wrap_long_lines.py FILE...`. Lines inside raw strings or macros may need a hand."""
import subprocess, sys

LIMIT = 120
for path in sys.argv[1:]:
    for attempt in range(3):   # a wrapped statement may move a long line
        lines = open(path, encoding='utf-8').read().split('\n')
        long = [i + 1 for i, text in enumerate(lines) if len(text) > LIMIT]
        if not long: break
        args = ['clang-format', '-i', '--style=file'] + ['--lines=%d:%d' % (n, n) for n in long] + [path]
        subprocess.run(args, check=True)
