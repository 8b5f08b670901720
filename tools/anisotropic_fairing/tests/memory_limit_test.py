#!/usr/bin/env python3
"""The memory check before a run (CTest: tool_memory_limit).

    memory_limit_test.py --tool BIN --mesh MESH --work DIR

A run predicted to need more memory than the process may take is refused before its set-up: exit 1, the
report's status insufficient_memory with both numbers in the message and the report, no output written.
--memory-limit sets what the run may take (a size, or off: no check), --resample's mesh included; under an
address-space limit (`ulimit -v`, set here with setrlimit in the child) the program finds it and names it.
The mesh is MESH refined twice by the program's --resample (about 100,000 vertices), so that the run's
need is far above what a program's start varies by. Python 3 standard library only; exits 1 if any check
failed, naming each.
"""
import argparse, json, os, resource, shutil, subprocess, sys

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print('check failed: ' + what)


def run(tool, args, address_space=None):
    def limit():
        if address_space is not None:
            resource.setrlimit(resource.RLIMIT_AS, (address_space, resource.RLIM_INFINITY))
    p = subprocess.run([tool] + args + ['--quiet'], capture_output=True, text=True, preexec_fn=limit)
    return p.returncode, p.stderr


def sanitized(tool):
    # AddressSanitizer reserves terabytes of address space: an address-space limit cannot be tried on it
    with open(tool, 'rb') as f:
        return b'__asan_init' in f.read()


def main():
    a = argparse.ArgumentParser()
    a.add_argument('--tool', required=True)
    a.add_argument('--mesh', required=True)
    a.add_argument('--work', required=True)
    o = a.parse_args()
    shutil.rmtree(o.work, ignore_errors=True)
    os.makedirs(o.work)
    mesh, out, report = (os.path.join(o.work, n) for n in ('refined.ply', 'out.ply', 'run.json'))
    code, err = run(o.tool, [o.mesh, mesh, '--resample', '2', '--relative-time-step', '1e-9', '--steps', '1',
                             '--stop', 'off'])
    check(code == 0, 'the refined mesh is made: ' + err)

    # a limit given
    code, err = run(o.tool, [mesh, out, '--memory-limit', '1M', '--report', report])
    j = json.load(open(report))
    print('--memory-limit 1M: exit %d, %s' % (code, err.strip()))
    check(code == 1 and j['status'] == 'insufficient_memory', 'refused: exit 1, status insufficient_memory')
    check('MB of memory and 1 MB are available (the memory_limit given)' in err, 'the message names both numbers')
    check(j['predicted_memory_mb'] > 100 and j['available_memory_mb'] == 1 and
          j['memory_limited_by'] == 'the memory_limit given', 'the report gives both numbers and the limit')
    check(j['steps'] == [] and j['runs'] == [], 'refused before any step')
    check(not os.path.exists(out), 'no output written')
    need = j['predicted_memory_mb'] * 2**20

    # --resample's mesh, made after the run, is checked before it
    code, err = run(o.tool, [o.mesh, out, '--resample', '4', '--memory-limit', '100M', '--report', report])
    j = json.load(open(report))
    print('--resample 4 --memory-limit 100M: exit %d, %s' % (code, err.strip()))
    check(code == 1 and j['status'] == 'insufficient_memory' and 'faces, which need about' in err and
          '100 MB are available (the memory_limit given)' in err and j['steps'] == [], '--resample refused up front')
    check(not os.path.exists(out), 'no output written')

    code, err = run(o.tool, [mesh, out, '--memory-limit', 'lots'])
    check(code == 2 and '--memory-limit expects a size' in err, 'a bad size is a usage error: ' + err.strip())

    if sanitized(o.tool):
        print('a sanitized build: the address-space limit is not tried')
    else:
        # the address space at the check: a generous limit (tighter than the memory the system has available,
        # so that it is the one found) less what the report says was available under it
        meminfo = dict(l.split(':', 1) for l in open('/proc/meminfo'))
        generous = int(meminfo['MemAvailable'].split()[0]) * 1024 // 2
        code, err = run(o.tool, [mesh, out, '--memory-limit', '1', '--report', report], generous)
        j = json.load(open(report))
        check(j['memory_limited_by'] == 'the memory_limit given', 'memory_limit wins over a looser limit')
        code, err = run(o.tool, [mesh, out, '--report', report, '--steps', '0'], generous)
        j = json.load(open(report))
        check(j['memory_limited_by'] == 'the address-space limit (ulimit -v)',
              'ulimit -v found: %s' % j['memory_limited_by'])
        space = generous - j['available_memory_mb'] * 2**20
        os.remove(out)

        tight = int(space + need / 2)
        code, err = run(o.tool, [mesh, out, '--report', report], tight)
        j = json.load(open(report))
        print('ulimit -v %d MB: exit %d, %s' % (tight >> 20, code, err.strip()))
        check(code == 1 and j['status'] == 'insufficient_memory', 'refused under ulimit -v')
        check('(the address-space limit (ulimit -v))' in err, 'the message names ulimit -v')
        check(j['setup_seconds'] == 0 and j['steps'] == [], 'refused before the set-up')
        check(not os.path.exists(out), 'no output written')

        code, err = run(o.tool, [mesh, out, '--report', report, '--memory-limit', 'off'], tight)
        j = json.load(open(report))
        print('ulimit -v %d MB, --memory-limit off: exit %d, %s' % (tight >> 20, code, err.strip()[-200:]))
        check(j['status'] != 'insufficient_memory' and j['available_memory_mb'] is None,
              '--memory-limit off runs without the check')

    print('%d checks failed' % len(failures))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
