#!/usr/bin/env python3
"""Runs one group of the table cli_cases.json against the program anisotropic_fairing (CTest: cli_<group>).

    cli_test.py --tool BIN --cases cli_cases.json --group NAME --example-data DIR --work DIR
    cli_test.py --tool BIN --docs PROGRAM_PAGE.txt --example-data DIR --work DIR   (the test cli_option_docs)

Each run of a group lists the arguments and what must hold afterwards; the checks are the functions
named check_<key> below, one per key of a run (see the comment at the top of cli_cases.json).
Python 3 standard library only. Exits 1 if any check failed, naming each.
"""
import argparse, glob, hashlib, json, math, os, re, shutil, subprocess, sys

failures = []
checks = [0]


def check(ok, what):
    checks[0] += 1
    if not ok:
        failures.append(what)
        print('check failed: ' + what)


# ---- files ---------------------------------------------------------------------------------------
def read_lines(path):
    with open(path, encoding='latin-1') as f:
        return f.read().split('\n')


def ply_table(lines, element):
    """(column names, rows of tokens) of an ASCII PLY element."""
    counts, columns, current, h = [], {}, None, 0
    for h, line in enumerate(lines):
        t = line.split()
        if t[:1] == ['element']:
            current = t[1]
            counts.append((t[1], int(t[2])))
            columns[current] = []
        elif t[:1] == ['property'] and current:
            columns[current].append(t[-1])
        elif line.strip() == 'end_header':
            break
    start = h + 1
    for name, n in counts:
        if name == element:
            return columns[name], [l.split() for l in lines[start:start + n]]
        start += n
    return [], []


def off_table(lines):
    body = [l for l in lines if l.strip() and not l.strip().startswith('#')]
    nv = int(body[1].split()[0])
    return [], [l.split() for l in body[2:2 + nv]]


def table(path, which):
    """The rows of tokens of a file's vertices ('vertex'), or of an OBJ's lines tagged `which` (v, vt, f)."""
    lines = read_lines(path)
    if path.endswith('.ply'):
        return ply_table(lines, which)
    if path.endswith('.off'):
        return off_table(lines)
    tag = 'v' if which == 'vertex' else which
    return [], [l.split()[1:] for l in lines if l.split()[:1] == [tag]]


def select(columns, row, cols):
    """The tokens of `cols` (names of PLY properties, or indices) in a row, joined by one blank."""
    out = []
    for c in cols:
        i = c if isinstance(c, int) else columns.index(c) if c in columns else None
        check(i is not None and i < len(row), 'column %r in %s' % (c, columns or row))
        out.append(row[i] if i is not None and i < len(row) else '?')
    return ' '.join(out)


def significant_digits(token):
    m = re.sub(r'[eE].*$', '', token.lstrip('+-')).replace('.', '').lstrip('0')
    return len(m)


# ---- the checks of a table of a file (key "tables": a list of these) ------------------------------
def check_table(spec, work):
    path = os.path.join(work, spec['file'])
    what = '%s %s' % (spec['file'], spec.get('table', 'vertex'))
    if not os.path.exists(path):
        check(False, '%s: no such file' % spec['file'])
        return
    columns, rows = table(path, spec.get('table', 'vertex'))
    check_table_shape(spec, path, what, columns, rows)
    check_table_values(spec, what, columns, rows)
    check_table_against_files(spec, work, what, columns, rows)


def check_table_shape(spec, path, what, columns, rows):
    """The rows, the columns and the header lines of the table."""
    if 'rows' in spec:
        check(len(rows) == spec['rows'], '%s: %d rows, expected %d' % (what, len(rows), spec['rows']))
    for col in spec.get('has_columns', []):
        check(col in columns, '%s: property %s written' % (what, col))
    if 'columns' in spec:   # exactly these properties, in this order
        check(columns == spec['columns'], '%s: properties %s, expected %s' % (what, columns, spec['columns']))
    for line in spec.get('header_has', []):   # PLY header lines
        header = [l.strip() for l in read_lines(path)]
        check(line in header[:header.index('end_header')] if 'end_header' in header else False,
              '%s: header has %r' % (what, line))


def check_table_values(spec, what, columns, rows):
    """The values of the table's rows."""
    for e in spec.get('equal', []):   # exact tokens per row
        for i, expected in enumerate(e['values']):
            got = select(columns, rows[i], e['cols']) if i < len(rows) else 'missing'
            check(got == expected, '%s row %d %s: %r == %r' % (what, i, e['cols'], got, expected))
    for c in spec.get('changed', []):   # at least `min` rows differ from the values given
        n = sum(1 for i, old in enumerate(c['values']) if i < len(rows) and select(columns, rows[i], c['cols']) != old)
        need = len(c['values']) if c.get('min') == 'all' else c.get('min', 1)
        check(n >= need, '%s %s changed in %d rows, expected at least %d' % (what, c['cols'], n, need))
    for r in spec.get('int_range', []):   # integers within [min, max]
        for i, row in enumerate(rows):
            for col in r['cols']:
                v = select(columns, row, [col])
                check(re.match(r'^-?[0-9]+$', v) and r['min'] <= int(v) <= r['max'],
                      '%s row %d: %s %s an integer in %d..%d' % (what, i, col, v, r['min'], r['max']))
    if 'close' in spec:   # every value within tol of `value`
        c = spec['close']
        for i, row in enumerate(rows):
            v = float(select(columns, row, c['cols']))
            check(abs(v - c['value']) <= c['tol'],
                  '%s row %d: %s %r == %r to %g' % (what, i, c['cols'], v, c['value'], c['tol']))
    if 'all_equal' in spec:   # every value of these columns within tol of row 0's first
        c = spec['all_equal']
        first = float(select(columns, rows[0], c['cols'][:1]))
        for i, row in enumerate(rows):
            for v in select(columns, row, c['cols']).split():
                check(abs(float(v) - first) <= c['tol'], '%s row %d: %s == %r to %g' % (what, i, v, first, c['tol']))
    if 'negative' in spec:
        v = select(columns, rows[0], [spec['negative']])
        check(v.startswith('-'), '%s: %s %s negative' % (what, spec['negative'], v))
    if 'tokens_per_row' in spec:
        for i, row in enumerate(rows):
            check(len(row) == spec['tokens_per_row'],
                  '%s row %d: %d tokens, expected %d' % (what, i, len(row), spec['tokens_per_row']))
    if 'row_regex' in spec:
        for i, row in enumerate(rows):
            check(re.search(spec['row_regex'], ' '.join(row)),
                  '%s row %d %r matches %s' % (what, i, ' '.join(row), spec['row_regex']))
    if 'max_significant_digits' in spec:
        most = max(significant_digits(t) for row in rows for t in row)
        check(most == spec['max_significant_digits'],
              '%s: at most %d significant digits, expected %d' % (what, most, spec['max_significant_digits']))
    if 'row' in spec:   # one row (negative index: from the end)
        r = spec['row']
        got = select(columns, rows[r['index']], r['cols']) if -len(rows) <= r['index'] < len(rows) else 'missing'
        check(got == r['value'], '%s row %d: %r == %r' % (what, r['index'], got, r['value']))


def check_table_against_files(spec, work, what, columns, rows):
    """The table against the same table of another file."""
    if 'within' in spec:   # every row's columns no farther (Euclidean) than `distance` from another file's
        o = spec['within']
        ocolumns, orows = table(os.path.join(work, o['file']), spec.get('table', 'vertex'))
        check(len(rows) == len(orows), '%s: %d rows, %s %d' % (what, len(rows), o['file'], len(orows)))
        far = 0.0
        for row, orow in zip(rows, orows):
            a = [float(x) for x in select(columns, row, o['cols']).split()]
            b = [float(x) for x in select(ocolumns, orow, o['cols']).split()]
            far = max(far, sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5)
        check(far <= o['distance'],
              '%s %s within %g of %s (largest %.17g)' % (what, o['cols'], o['distance'], o['file'], far))
        check(far > o.get('moved', 0), '%s moved by more than %g (largest %.17g)' % (what, o.get('moved', 0), far))
    for key, same in (('same_as', True), ('differs_from', False)):   # the same columns of another file
        if key not in spec:
            continue
        o = spec[key]
        ocolumns, orows = table(os.path.join(work, o['file']), spec.get('table', 'vertex'))
        a = [select(columns, row, o['cols']) for row in rows]
        b = [select(ocolumns, row, o['cols']) for row in orows]
        if not same:
            check(a != b, '%s differs from %s' % (what, o['file']))
        elif 'tol' not in o:
            check(a == b, '%s %s identical to %s' % (what, o['cols'], o['file']))
        else:
            check(len(a) == len(b), '%s: %d rows, %s %d' % (what, len(a), o['file'], len(b)))
            worst = max([abs(float(x) - float(y)) for p, q in zip(a, b) for x, y in zip(p.split(), q.split())] or [0])
            same_rows = sum(1 for p, q in zip(a, b) if p == q)
            print('%d of %d rows identical; largest difference %g' % (same_rows, len(a), worst))
            check(worst <= o['tol'], '%s within %g of %s (largest difference %g)' % (what, o['tol'], o['file'], worst))
    if 'less_than' in spec:   # row 0's value below the same value of another file
        o = spec['less_than']
        ocolumns, orows = table(os.path.join(work, o['file']), spec.get('table', 'vertex'))
        a, b = float(select(columns, rows[0], [o['col']])), float(select(ocolumns, orows[0], [o['col']]))
        check(a < b, '%s: %s %r < %r of %s' % (what, o['col'], a, b, o['file']))

# ---- the report ----------------------------------------------------------------------------------
# every report, of a success or a failure, holds every key of the manual page's report table
PROGRAM_PAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', 'doc', 'Anisotropic_fairing',
                            'Command_line_program.txt')
REQUIRED_STEP = ('step time solver_iterations residual area energy H_integral max_displacement assemble_seconds '
                 'solve_seconds time_step noise_displacement').split()


def check_report(path, run):
    """Every report: parses, no non-finite literal, every required key, steps numbered 1..n."""
    if not os.path.exists(path):
        check(False, 'no report %s' % path)
        return
    text = open(path).read()
    check(not re.search(r':\s*-?(nan|inf)', text), '%s: non-finite literal in the JSON' % path)
    try:
        j = json.loads(text)
    except ValueError as e:
        check(False, '%s does not parse: %s' % (path, e))
        return
    for k in report_keys_of_page(PROGRAM_PAGE):
        check(k in j, '%s: top-level key %s' % (path, k))
    steps = j.get('steps') if isinstance(j.get('steps'), list) else []
    check(isinstance(j.get('steps'), list), '%s: steps is a list' % path)
    for i, s in enumerate(steps):
        for k in REQUIRED_STEP:
            check(k in s, '%s: steps[%d] has %s' % (path, i, k))
        check(s.get('step') == i + 1, '%s: steps[%d].step is %s, expected %d' % (path, i, s.get('step'), i + 1))
    for k, v in run.get('report_is', {}).items():
        check(k in j and j[k] == v and type(j[k]) == type(v), '%s: %s is %r, expected %r' % (path, k, j.get(k), v))
    for k, v in run.get('report_is_not', {}).items():
        check(j.get(k) != v, '%s: %s is not %r' % (path, k, v))
    for pattern in run.get('report_matches', []):
        check(re.search(pattern, text), '%s matches %s' % (path, pattern))
    if 'steps' in run:
        lo, hi = run['steps'] if isinstance(run['steps'], list) else (run['steps'], run['steps'])
        check(lo <= len(steps) <= hi, '%s: %d steps, expected %d..%d' % (path, len(steps), lo, hi))


# ---- one run -------------------------------------------------------------------------------------
def temporaries(work):
    return glob.glob(os.path.join(work, '**', '.*.tmp*'), recursive=True)


def file_digests(work):
    digests = {}
    for path in glob.glob(os.path.join(work, '**', '*'), recursive=True):
        if os.path.isfile(path):
            with open(path, 'rb') as f:
                digests[path] = hashlib.sha256(f.read()).hexdigest()
    return digests


def do_run(run, tool, work, data):
    args = [a.replace('@DATA@', data) for a in run['args']]
    before = file_digests(work)
    p = subprocess.run([tool] + args, cwd=work, capture_output=True, text=True, timeout=120)
    print('anisotropic_fairing %s\n  -> exit %d\n  stderr: %s' % (' '.join(args), p.returncode, p.stderr.rstrip()))
    what = run.get('what', ' '.join(run['args']))
    output = os.path.join(work, run['output']) if 'output' in run else None
    check(p.returncode == run.get('exit', 0),
          '%s: exit code %d, expected %d' % (what, p.returncode, run.get('exit', 0)))
    if run.get('clean_failure'):   # one line starting with "anisotropic_fairing: ", no output, no temporary
        err = p.stderr[:-1] if p.stderr.endswith('\n') else p.stderr
        check('\n' not in err, '%s: stderr has one line: [%s]' % (what, p.stderr))
        check(re.match('^anisotropic_fairing: .', err), '%s: stderr starts with "anisotropic_fairing: "' % what)
        check(output is None or not os.path.exists(output), "%s: no output %s" % (what, run.get("output")))
    elif output:
        check(os.path.exists(output), '%s: %s written' % (what, run['output']))
    check(not temporaries(work), '%s: no temporary file left (%s)' % (what, temporaries(work)))
    if p.returncode != 0:   # a failure changes no file that existed, but the report it was asked for
        after = file_digests(work)
        asked = os.path.join(work, run['report']) if 'report' in run else None
        for path, digest in before.items():
            check(path == asked or after.get(path) == digest,
                  '%s: %s unchanged by the failure' % (what, os.path.relpath(path, work)))
    for pattern in run.get('stderr', []):
        check(re.search(pattern, p.stderr), '%s: stderr matches %s' % (what, pattern))
    if 'stderr_lines' in run:   # every line of stderr matches
        for line in p.stderr.splitlines():
            check(re.search(run['stderr_lines'], line),
                  '%s: stderr line %r matches %s' % (what, line, run['stderr_lines']))
    for pattern in run.get('stderr_not', []):
        check(not re.search(pattern, p.stderr), '%s: stderr does not match %s' % (what, pattern))
    if 'report' in run:
        check_report(os.path.join(work, run['report']), run)
    if 'first_line' in run:
        check(read_lines(output)[0] == run['first_line'], '%s: first line %s' % (what, run['first_line']))
    for spec in run.get('tables', []):
        check_table(spec, work)


# ---- the manual's option list and report keys against the program ----------------------------------
def report_keys_of_page(manual):
    """the keys the page's JSON report table names in its first column"""
    text = open(manual, encoding='utf-8').read()
    table = text[text.index('\\section af_tool_report'):]
    keys = []
    for line in table.splitlines():
        if line.startswith('| `'):
            keys += re.findall(r'`([a-z_0-9]+)`', line.split(' | ')[0])
    return keys


def check_docs(tool, manual, example_data, work):
    version = subprocess.run([tool, '--version'], capture_output=True, text=True)
    pattern = r'anisotropic_fairing \d+\.\d+\.\d+ .*\nCGAL \S+, Eigen \d+\.\d+\.\d+, Boost \d+\.\d+\.\d+\n$'
    check(version.returncode == 0 and re.match(pattern, version.stdout),
          '--version prints the versions and exits 0: %r' % version.stdout)
    # the option list is made from --help by scripts/option_docs.py, which says what differs
    generator = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', 'scripts', 'option_docs.py')
    docs = subprocess.run([sys.executable, generator, tool, '--check'], capture_output=True, text=True)
    check(docs.returncode == 0,
          'the manual (%s) gives the options exactly as --help does:\n%s%s' % (manual, docs.stdout, docs.stderr))
    # every key a report holds is in the page's table, and the table names no other
    os.makedirs(work, exist_ok=True)
    report = os.path.join(work, 'keys.json')
    run = subprocess.run([tool, os.path.join(example_data, 'octahedron_quality.ply'), os.path.join(work, 'keys.ply'),
                          '--quiet', '--attributes', 'quality', '--steps', '1', '--report', report],
                         capture_output=True, text=True)
    check(run.returncode == 0, 'a one-step run with attributes succeeds: %s' % run.stderr)
    if run.returncode == 0:
        written, listed = set(json.load(open(report))), report_keys_of_page(manual)
        check(len(listed) == len(set(listed)), 'the page names each report key once: %s' %
              sorted(k for k in set(listed) if listed.count(k) > 1))
        check(written == set(listed),
              'the report keys are those of the page\'s table: not in the table %s, not in the report %s' %
              (sorted(written - set(listed)), sorted(set(listed) - written)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--tool', required=True)
    ap.add_argument('--cases')
    ap.add_argument('--group')
    ap.add_argument('--example-data')
    ap.add_argument('--work')
    ap.add_argument('--docs', metavar='PROGRAM_PAGE')
    a = ap.parse_args()
    if a.docs:
        check_docs(a.tool, a.docs, a.example_data, a.work)
    else:
        groups = json.load(open(a.cases))['groups']
        if a.group not in groups:
            sys.exit('cli_test.py: no group %s in %s' % (a.group, a.cases))
        group = groups[a.group]
        shutil.rmtree(a.work, ignore_errors=True)
        os.makedirs(a.work)
        here = os.path.join(os.path.dirname(os.path.abspath(a.cases)), 'data')
        for f in group.get('inputs', []):
            shutil.copy(os.path.join(here, f), a.work)
        for name, source in group.get('with_normals', {}).items():   # an OFF file as NOFF, every normal 0 0 1
            lines = [l for l in read_lines(source.replace('@DATA@', a.example_data))
                     if l.strip() and not l.startswith('#')]
            nv = int(lines[1].split()[0])
            body = ['NOFF', lines[1]] + [l + ' 0 0 1' for l in lines[2:2 + nv]] + lines[2 + nv:]
            open(os.path.join(a.work, name), 'w').write('\n'.join(body) + '\n')
        for run in group['runs']:
            do_run(run, a.tool, a.work, a.example_data)
    if failures:
        sys.exit('%d of %d checks failed' % (len(failures), checks[0]))
    print('all %d checks passed' % checks[0])


if __name__ == '__main__':
    main()
