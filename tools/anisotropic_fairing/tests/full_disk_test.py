#!/usr/bin/env python3
"""The program on a file system that fills up (CTest: tool_full_disk), and on inputs that are not files.

    full_disk_test.py --tool BIN --shim LIB --mesh MESH --work DIR

LIB (tests/full_disk_shim.cpp, loaded with LD_PRELOAD) makes every write to a file under DIR/full/ fail
with ENOSPC. Each failure must say why in the system's words ("No space left on device", "Is a directory"),
exit 1 with the report's status write_error or read_error, and leave no file behind: no output, no report, no
temporary file. Python 3 standard library only; exits 1 if any check failed, naming each.
"""
import argparse, json, os, shutil, subprocess, sys

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print('check failed: ' + what)


def run(tool, args, env):
    p = subprocess.run([tool] + args + ['--steps', '1', '--quiet'], capture_output=True, text=True, env=env)
    return p.returncode, p.stderr


def main():
    a = argparse.ArgumentParser()
    a.add_argument('--tool', required=True)
    a.add_argument('--shim', required=True)
    a.add_argument('--mesh', required=True)
    a.add_argument('--work', required=True)
    o = a.parse_args()
    shutil.rmtree(o.work, ignore_errors=True)
    full, room = os.path.join(o.work, 'full'), os.path.join(o.work, 'room')
    os.makedirs(full)
    os.makedirs(room)
    env = dict(os.environ, LD_PRELOAD=os.path.abspath(o.shim), AF_FULL_DISK_PREFIX=os.path.abspath(full) + '/',
               ASAN_OPTIONS=os.environ.get('ASAN_OPTIONS', '') + ':verify_asan_link_order=0')

    # the output on the full disk
    out = os.path.join(full, 'out.off')
    code, err = run(o.tool, [o.mesh, out], env)
    print('output on a full disk: exit %d, %s' % (code, err.strip()))
    check(code == 1, 'a full disk under the output: exit 1')
    check('cannot write %s: No space left on device' % out in err, 'the output names the system\'s reason')
    check(os.listdir(full) == [], 'nothing left on the full disk: %s' % os.listdir(full))

    # the report on the full disk, the output where there is room: neither is written
    out, report = os.path.join(room, 'out.off'), os.path.join(full, 'run.json')
    code, err = run(o.tool, [o.mesh, out, '--report', report], env)
    print('report on a full disk: exit %d, %s' % (code, err.strip()))
    check(code == 1, 'a full disk under the report: exit 1')
    check('cannot write the report %s: No space left on device' % report in err, 'the report names the reason')
    check(os.listdir(full) == [] and os.listdir(room) == [], 'no output, no report, no temporary file: %s %s'
          % (os.listdir(full), os.listdir(room)))

    # the output on the full disk, the report where there is room: the report says why
    out, report = os.path.join(full, 'out.off'), os.path.join(room, 'run.json')
    code, err = run(o.tool, [o.mesh, out, '--report', report], env)
    check(code == 1 and os.listdir(full) == [], 'a full disk under the output, with a report elsewhere: exit 1')
    r = json.load(open(report)) if os.path.exists(report) else {}
    check(r.get('status') == 'write_error' and 'No space left on device' in r.get('message', ''),
          'the report says write_error and why: %s' % r.get('message'))
    os.remove(report) if os.path.exists(report) else None

    # a directory as INPUT (named like a mesh), and as OUTPUT
    folder = os.path.join(o.work, 'scans.off')
    os.makedirs(folder)
    code, err = run(o.tool, [folder, os.path.join(room, 'x.off')], dict(os.environ))
    print('a directory as INPUT: exit %d, %s' % (code, err.strip()))
    check(code == 1 and 'cannot open %s: it is a directory' % folder in err, 'a directory as INPUT is named one')
    code, err = run(o.tool, [os.path.join(o.work, 'missing.off'), os.path.join(room, 'x.off')], dict(os.environ))
    check(code == 1 and 'no such file' in err, 'a missing INPUT: no such file')
    code, err = run(o.tool, [o.mesh, folder], dict(os.environ))
    print('a directory as OUTPUT: exit %d, %s' % (code, err.strip()))
    check(code == 1 and 'cannot write %s: it is a directory' % folder in err, 'a directory as OUTPUT is named one')

    print('%d failed' % len(failures))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
