#!/usr/bin/env python3
"""The tests read nothing beside the repository: runs a command (the test command's ctest) under strace
and fails, listing them, if any of its processes touched a file or directory in the repository's parent
directory outside the repository (such as ../shared, the data set CI puts beside the clone).

  check_reads.py run [--repo DIR] [--allow DIR]... -- COMMAND [ARG...]
      runs COMMAND and all its processes (ctest, its tests, their compilers, Python, mpirun and the
      MPI processes) under `strace -f`, following every system call that names a file (open, stat,
      access, exec, chdir, ...; paths resolved by strace against the process's directory or the
      directory descriptor). Exit status: COMMAND's when it fails, else 1 when anything beside the
      repository was touched (each path listed with the program and the test that touched it), else 0.
  check_reads.py self-test
      the check on a temporary tree repo/ + shared/: each probe that touches shared/ must be reported (Python,
      cat, an absolute path, a shell's existence test, relative paths after cd, chdir and through a directory
      descriptor, symbolic links in repo/, a thread, an open split by other processes' calls, a failed open,
      processes under mpirun when installed); reads inside repo/ and what section 'What counts' leaves out
      must not. Exit 1 if the check misses or invents anything or cannot trace here; 77 (skipped) when
      already traced, as inside `af.sh test`'s checked run, which runs it just before.

What counts: any path strictly inside the parent directory of DIR (default: the repository holding this
script), outside DIR and every --allow DIR, below a name that was in the parent when the run started,
whether the call succeeded or failed (a test that looks for ../shared/x is reported even if it copes
without). Not reported: the parent itself (its name in a path), probes for names absent from it (upward
searches for configuration files, such as pytest's, read nothing), what the run itself creates there (its
temporary files when the parent is /tmp), the temporary directory when it is beside the repository, and,
when the parent is the home directory, its hidden entries (the tools' ~/.cache, ~/.config: ccache, pip).

Needs strace (Debian: strace) and permission to trace (ptrace; in a container: --cap-add SYS_PTRACE).
Standard library only."""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import traceback

# what strace follows: every call with a file name (%file: open, openat, stat, access, execve, chdir,
# readlink, mkdir, unlink, rename, ...), openat2 and fchdir, and the calls that make processes, so that
# each process's working directory and command line are known
TRACED = "%file,openat2,fchdir,clone,clone3,fork,vfork"
STRACE = ["strace", "-f", "--seccomp-bpf", "-q", "-e", "signal=none", "-y", "-s", "4096", "-e", "trace=" + TRACED]

# calls whose path arguments are not (only) the first string
PATH_STRINGS = {"symlink": (1,), "symlinkat": (1,), "rename": (0, 1), "renameat": (0, 1), "renameat2": (0, 1),
                "link": (0, 1), "linkat": (0, 1), "mount": (), "umount2": (0,)}
PROCESS_CALLS = {"clone", "clone3", "fork", "vfork"}

TOKEN = re.compile(r'"(?P<s>(?:[^"\\]|\\.)*)"(?:\.\.\.)?'          # a string argument
                   r'|(?P<fd>AT_FDCWD|-?\d+)<(?P<d>(?:[^>\\]|\\.)*)>'  # a descriptor with its path (-y)
                   r'|(?P<open>\[)|(?P<close>\])')
RESULT = re.compile(r'\)\s+=\s+(?P<ret>-?\d+|\?|0x[0-9a-fA-F]+)(?P<deco><(?:[^>\\]|\\.)*>)?(?:\s+(?P<err>E[A-Z0-9]+)\b.*)?\s*$')
FDCWD = re.compile(r'AT_FDCWD<((?:[^>\\]|\\.)*)>')
LINE = re.compile(r'^(?P<pid>\d+)\s+(?P<rest>.*)$')
EXITED = re.compile(r'^\+\+\+ (exited|killed) ')
RESUMED = re.compile(r'^<\.\.\. (?P<name>\w+) resumed>\s?(?P<rest>.*)$')
ESCAPE = re.compile(rb'\\(x[0-9a-fA-F]{2}|[0-7]{1,3}|.)')
SIMPLE_ESCAPES = {b'n': b'\n', b't': b'\t', b'r': b'\r', b'v': b'\v', b'f': b'\f', b'a': b'\a', b'b': b'\b'}


def unescape(text):
    """strace's quoting (\\", \\\\, \\n, \\xHH, octal) back to the path it stands for."""
    if "\\" not in text:
        return text
    def one(m):
        e = m.group(1)
        if e[:1] == b'x':
            return bytes([int(e[1:], 16)])
        if e[:1].isdigit():
            return bytes([int(e, 8) & 0xFF])
        return SIMPLE_ESCAPES.get(e, e)
    return ESCAPE.sub(one, text.encode("utf-8", "surrogateescape")).decode("utf-8", "surrogateescape")


def inside(path, root):
    return path == root or path.startswith(root.rstrip("/") + "/")


class Checker:
    """Reads strace's output line by line and keeps the processes and the paths beside the repository."""

    def __init__(self, repo, allow=(), cwd=None):
        real = os.path.realpath(repo)
        self.roots = sorted({os.path.abspath(repo), real})
        self.parents = sorted({os.path.dirname(r) for r in self.roots})
        if "/" in self.parents:
            raise SystemExit("check_reads: the repository %s is directly below /: its parent holds the whole system, "
                             "so there is no 'beside the repository' to check; clone it one directory deeper" % repo)
        allow = list(allow)
        # the temporary directory, when it is one of the things beside the repository (TMPDIR=../tmp)
        temp = os.path.realpath(tempfile.gettempdir())
        if any(temp.startswith(p.rstrip("/") + "/") for p in self.parents):
            allow.append(temp)
        self.allowed = self.roots + sorted({p for a in allow for p in (os.path.abspath(a), os.path.realpath(a))})
        # what is beside the repository: the names in its parent before the run (not what the run creates there,
        # such as temporary files when the parent is /tmp)
        self.before = {p: set(os.listdir(p)) for p in self.parents}
        home = os.path.realpath(os.path.expanduser("~"))
        self.home_parent = home in {os.path.realpath(p) for p in self.parents}
        self.initial_cwd = cwd or os.getcwd()
        self.cwd, self.parent, self.cmd = {}, {}, {}
        self.exited = set()   # pids to forget when they come back (pid numbers are reused in a long run)
        self.root_pid = None
        self.root_exec = False
        self.pending = {}
        self.found = {}   # path -> (syscall line, program, test)
        self.lines = 0
        self.real_cache = {}

    # -- processes --------------------------------------------------------------------------------
    def cwd_of(self, pid):
        p = pid
        seen = 0
        while p is not None and seen < 1000:
            if p in self.cwd:
                return self.cwd[p]
            p, seen = self.parent.get(p), seen + 1
        return self.initial_cwd

    def cmd_of(self, pid):
        p, seen = pid, 0
        while p is not None and seen < 1000:
            if p in self.cmd:
                return self.cmd[p]
            p, seen = self.parent.get(p), seen + 1
        return "?"

    def test_of(self, pid):
        """The command line of the process the traced command started (a test, for ctest)."""
        p, seen = pid, 0
        while p in self.parent and self.parent[p] != self.root_pid and seen < 1000:
            p, seen = self.parent[p], seen + 1
        return self.cmd_of(p)

    # -- paths ------------------------------------------------------------------------------------
    def beside(self, path):
        """True when path (absolute, normalised) is beside the repository, in the sense of the module's text."""
        for parent in self.parents:
            if not path.startswith(parent.rstrip("/") + "/"):
                continue
            if any(inside(path, a) for a in self.allowed):
                return False
            first = path[len(parent.rstrip("/")) + 1:].split("/", 1)[0]
            if self.home_parent and first.startswith("."):
                return False
            # a name the run made, or a probe for one that is not there (nothing read), is not beside it
            return first in self.before[parent]
        return False

    def real(self, path):
        r = self.real_cache.get(path)
        if r is None:
            r = self.real_cache[path] = os.path.realpath(path)
        return r

    def note(self, path, line, pid):
        if not path.startswith("/"):
            return
        path = os.path.normpath(path)
        # a path inside the repository may lead out of it through a symbolic link
        candidates = [path]
        if any(inside(path, a) for a in self.allowed):
            candidates.append(self.real(path))
        for p in candidates:
            if self.beside(p) and p not in self.found:
                self.found[p] = (line, self.cmd_of(pid), self.test_of(pid))

    # -- strace's lines ---------------------------------------------------------------------------
    def feed(self, raw):
        self.lines += 1
        m = LINE.match(raw.rstrip("\n"))
        if not m:
            return
        pid, rest = int(m.group("pid")), m.group("rest")
        if self.root_pid is None:
            self.root_pid = pid
        if pid in self.exited:
            self.forget(pid)
        if EXITED.match(rest):
            self.exited.add(pid)
            return
        r = RESUMED.match(rest)
        if r:
            rest = self.pending.pop(pid, r.group("name") + "(") + r.group("rest")
        if rest.endswith(" <unfinished ...>"):
            self.pending[pid] = rest[:-len(" <unfinished ...>")]
            return
        self.syscall(pid, rest)

    def forget(self, pid):
        self.exited.discard(pid)
        for table in (self.cwd, self.parent, self.cmd, self.pending):
            table.pop(pid, None)

    def syscall(self, pid, text):
        m = re.match(r"(\w+)\(", text)
        if not m:
            return
        name = m.group(1)
        res = result_of(text)
        if res is None:
            return
        args = text[m.end():res.start()]
        ret = res.group("ret")
        succeeded = ret != "-1"
        if name in PROCESS_CALLS:
            if succeeded and ret.isdigit() and int(ret) > 0:
                child = int(ret)
                if child in self.exited:
                    self.forget(child)
                self.parent[child] = pid
                self.cwd.setdefault(child, self.cwd_of(pid))   # unless its own lines came first
            return
        strings, decorations, before = [], [], None
        depth = 0
        for t in TOKEN.finditer(args):
            if t.group("open"):
                depth += 1
            elif t.group("close"):
                depth -= 1
            elif t.group("fd") is not None:
                d = unescape(t.group("d"))
                decorations.append(d)
                before = (d, t.group("fd"), t.end())
            elif t.group("s") is not None:
                if depth == 0:
                    base = None
                    if before and args[before[2]:t.start()].strip() == ",":
                        base = before[0]
                    strings.append((unescape(t.group("s")), base))
                elif name in ("execve", "execveat"):
                    strings.append((None, unescape(t.group("s"))))   # argv
        if res.group("deco"):
            decorations.append(unescape(res.group("deco")[1:-1]))
        if name in ("execve", "execveat") and succeeded:
            argv = [s[1] for s in strings if s[0] is None]
            self.cmd[pid] = " ".join(argv) if argv else "?"
            if pid == self.root_pid:
                self.root_exec = True
        paths = [s for s in strings if s[0] is not None]
        chosen = PATH_STRINGS.get(name, (0,))
        fdcwd = FDCWD.search(args)   # AT_FDCWD<...> is the process's working directory: learn it
        if fdcwd:
            cwd = unescape(fdcwd.group(1))
            self.cwd[pid] = cwd
        else:
            cwd = self.cwd_of(pid)
        for i in chosen:
            if i < len(paths):
                path, base = paths[i]
                if path == "":
                    continue
                full = path if path.startswith("/") else os.path.join(base if base and base.startswith("/") else cwd, path)
                self.note(full, text, pid)
                if name == "chdir" and succeeded:
                    self.cwd[pid] = os.path.normpath(full)
        for d in decorations:
            self.note(d, text, pid)
        if name == "fchdir" and succeeded and decorations and decorations[0].startswith("/"):
            self.cwd[pid] = decorations[0]

    def report(self, out=sys.stderr, limit=40):
        if not self.found:
            return 0
        print("[read check] the tests touched %d path(s) beside the repository %s (in %s), which a fresh clone "
              "does not have:" % (len(self.found), self.roots[-1], " and ".join(self.parents)), file=out)
        for i, (path, (line, program, test)) in enumerate(sorted(self.found.items())):
            if i == limit:
                print("  ... and %d more" % (len(self.found) - limit), file=out)
                break
            print("  %s\n      by %s%s\n      call: %s" % (path, shorten(program),
                                                           "" if test == program else "\n      in test: " + shorten(test),
                                                           shorten(line, 300)), file=out)
        print("[read check] copy what a test needs into the repository (test/Anisotropic_fairing/data/, with its "
              "source in data/README.md) and read it from there", file=out)
        return 1


def result_of(text):
    """The match of RESULT on the call's end: ') = 3</path>', ')   = -1 ENOENT (...)' (strace pads to a column);
    the last ' = ' that is one, so that no string argument can pass for it."""
    end = len(text)
    while True:
        i = text.rfind(" = ", 0, end)
        if i < 0:
            return None
        j = i
        while j > 0 and text[j - 1] == " ":
            j -= 1
        res = RESULT.match(text, j - 1) if j > 0 else None
        if res:
            return res
        end = i


def shorten(text, n=400):
    return text if len(text) <= n else text[:n] + " ..."


def traced():
    """True when this process is already under a tracer (strace cannot trace inside strace)."""
    try:
        with open("/proc/self/status") as f:
            return any(l.startswith("TracerPid:") and l.split()[1] != "0" for l in f)
    except OSError:
        return False


def strace_usable():
    if traced():
        return "already under a tracer (ptrace does not nest)"
    if shutil.which("strace") is None:
        return "strace is not installed (Debian: apt-get install strace)"
    r = subprocess.run(["strace", "-f", "--seccomp-bpf", "-qq", "-e", "trace=openat", "-o", os.devnull, "true"],
                       capture_output=True, text=True)
    if r.returncode != 0:
        return "strace cannot trace here (%s); it needs ptrace (in a container: --cap-add SYS_PTRACE; " \
               "Yama: kernel.yama.ptrace_scope <= 2)" % (r.stderr.strip() or "exit %d" % r.returncode)
    return None


def traced_run(command, checker, cwd=None, env=None):
    """COMMAND under strace, its output read through a named pipe as it comes; returns COMMAND's exit status."""
    problem = strace_usable()
    if problem:
        raise SystemExit("check_reads: " + problem)
    tmp = tempfile.mkdtemp(prefix="af-read-check-")
    fifo = os.path.join(tmp, "strace.fifo")
    os.mkfifo(fifo)
    try:
        failure = []
        def read():
            try:
                with open(fifo, "r", encoding="utf-8", errors="surrogateescape") as f:
                    for line in f:
                        if failure:
                            continue   # still read strace's output, or it would wait on the pipe for ever
                        try:
                            checker.feed(line)
                        except Exception:   # reported below: a check that stopped reading passes nothing
                            failure.append(traceback.format_exc())
            except Exception as e:
                failure.append(repr(e))
        reader = threading.Thread(target=read, daemon=True)
        reader.start()
        proc = subprocess.Popen(STRACE + ["-o", fifo, "--"] + list(command), cwd=cwd, env=env)
        status = proc.wait()
        if reader.is_alive():
            # strace exited: if it never opened the pipe (it could not start), open it to end the reader
            try:
                fd = os.open(fifo, os.O_WRONLY | os.O_NONBLOCK)
                os.close(fd)
            except OSError:
                pass
        reader.join()
        if failure:
            raise SystemExit("check_reads: reading strace's output failed: " + failure[0])
        if not checker.root_exec:
            raise SystemExit("check_reads: strace traced nothing (exit status %d): the check did not run" % status)
        return status
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def cmd_run(args):
    if not args.command:
        raise SystemExit("check_reads run: no command (check_reads.py run -- ctest ...)")
    checker = Checker(args.repo, args.allow)
    status = traced_run(args.command, checker)
    print("[read check] %d lines of strace output, %d processes" % (checker.lines, len(checker.cmd)), file=sys.stderr)
    found = checker.report()
    if status != 0:
        return status
    if found:
        return 1
    print("[read check] nothing beside the repository %s was touched" % checker.roots[-1], file=sys.stderr)
    return 0


def mpi_probe():
    """mpirun's command for 2 processes (Open MPI as root and on fewer cores allowed), or None."""
    mpirun = shutil.which("mpirun")
    if mpirun is None:
        return None
    version = subprocess.run([mpirun, "--version"], capture_output=True, text=True).stdout
    flags = ["--allow-run-as-root", "--oversubscribe"] if "Open MPI" in version or "OpenRTE" in version else []
    return [mpirun] + flags + ["-np", "2"]


SKIPPED = 77   # the CTest test's SKIP_RETURN_CODE


def cmd_self_test(args):
    if traced():
        # the CTest test read_check inside the checked suite of `af.sh test`, which ran this self-test just before
        print("check_reads self-test: skipped: already under a tracer, the read check itself (`af.sh test` "
              "runs this self-test before the suite)", file=sys.stderr)
        return SKIPPED
    problem = strace_usable()
    if problem:
        print("check_reads self-test: FAILED: " + problem, file=sys.stderr)
        return 1
    tmp = os.path.realpath(tempfile.mkdtemp(prefix="af-read-check-self-test-"))
    try:
        repo, shared = os.path.join(tmp, "repo"), os.path.join(tmp, "shared")
        os.makedirs(os.path.join(repo, "build", "sub"))
        os.makedirs(os.path.join(shared, "data"))
        py = sys.executable
        def python(code):
            return "%s -c \"%s\"" % (py, code)
        S = "../shared/data/"
        # (file beside the repository, the probe that touches it): each catchable by one part of the check
        probes = [
            ("python", python("open('%spython.obj').read()" % S)),
            ("absolute", "cat %s/data/absolute.obj > /dev/null" % shared),
            ("exists", "test -e %sexists.obj" % S),                                   # stat only, no descriptor
            ("in_subdirectory", "(cd build/sub && cat ../../%sin_subdirectory.obj > /dev/null)" % S),
            ("chdir_then_access", python("import os; os.chdir('build/sub'); os.access('../../%schdir_then_access.obj', os.R_OK)" % S)),
            ("dirfd_relative", python("import os; d = os.open('build', os.O_RDONLY); os.stat('../%sdirfd_relative.obj', dir_fd=d)" % S)),
            ("symlink_stat", "test -e link/symlink_stat.obj"),                          # through repo/link, no descriptor
            ("symlink_removed", "(ln -s ../../shared/data build/gone; cat build/gone/symlink_removed.obj > /dev/null; rm build/gone)"),
            # an open that waits (a named pipe, written through a hard link inside repo/) while other processes
            # run: strace splits it into <unfinished ...> and <... resumed> lines
            ("blocking_open", "(cat %sblocking_open.obj > /dev/null & sleep 0.3; echo x > build/pipe; wait)" % S),
            ("thread", python("import threading; t = threading.Thread(target=lambda: open('%sthread.obj').read()); t.start(); t.join()" % S)),
            ("failed_in_sibling", "cat %sfailed_in_sibling.obj/not_a_directory 2> /dev/null || true" % S),
        ]
        mpi = mpi_probe() if not args.no_mpi else None
        if mpi:
            probes.append(("mpi", "%s sh -c 'cat %smpi.obj > /dev/null'" % (" ".join(mpi), S)))
        for name, _ in probes:
            if name == "blocking_open":
                os.mkfifo(os.path.join(shared, "data", name + ".obj"))
                os.link(os.path.join(shared, "data", name + ".obj"), os.path.join(repo, "build", "pipe"))
                continue
            with open(os.path.join(shared, "data", name + ".obj"), "w") as f:
                f.write("v 0 0 0\n")
        with open(os.path.join(repo, "inside.txt"), "w") as f:
            f.write("inside\n")
        os.symlink(os.path.join("..", "shared", "data"), os.path.join(repo, "link"))
        # not reported: reads inside repo/, a probe for an absent name beside it, what the run makes beside it,
        # and (the parent being the home directory here) a tool's hidden directory there
        os.makedirs(os.path.join(tmp, ".cache"))
        with open(os.path.join(tmp, ".cache", "tool.conf"), "w") as f:
            f.write("\n")
        os.environ["HOME"] = tmp
        script = "\n".join(["set -e",   # (each probe fails the script if it fails, but failed_in_sibling)
                             "cat inside.txt build/../inside.txt ../.cache/tool.conf > /dev/null",
                             "test ! -e ../absent_beside_the_repository",
                             "mkdir ../made_by_the_run && echo x > ../made_by_the_run/f && cat ../made_by_the_run/f > /dev/null"]
                            + [command for _, command in probes])
        expected = {os.path.join(shared, "data", name + ".obj") for name, _ in probes}
        expected.remove(os.path.join(shared, "data", "failed_in_sibling.obj"))
        expected.add(os.path.join(shared, "data", "failed_in_sibling.obj", "not_a_directory"))
        checker = Checker(repo, cwd=repo)
        status = traced_run(["sh", "-c", script], checker, cwd=repo)
        found = set(checker.found)
        ok = True
        if status != 0:
            print("check_reads self-test: the probe script failed (exit %d)" % status, file=sys.stderr)
            ok = False
        for p in sorted(expected - found):
            print("check_reads self-test: MISSED %s" % p, file=sys.stderr)
            ok = False
        # reads of the probe's own files beside the repository, through other calls (stat, the directory
        # data/ listed by ls), are also right to report; anything else is not
        extra = {p for p in found - expected if not inside(p, shared)}
        for p in sorted(extra):
            print("check_reads self-test: WRONGLY REPORTED %s" % p, file=sys.stderr)
            ok = False
        # the report names the program and the test
        out = open(os.devnull, "w")
        if checker.report(out) != 1:
            ok = False
        print("check_reads self-test: %s (%d probes%s, %d paths reported, %d lines of strace output)"
              % ("passed" if ok else "FAILED", len(probes), ", mpirun on 2 processes among them" if mpi else
                 ", mpirun not installed", len(found), checker.lines), file=sys.stderr)
        return 0 if ok else 1
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="sub", required=True)
    r = sub.add_parser("run", help="run a command under the check")
    r.add_argument("--repo", default=os.path.dirname(here), help="the repository (default: the one holding this script)")
    r.add_argument("--allow", action="append", default=[], help="another directory beside the repository the command may use")
    r.add_argument("command", nargs=argparse.REMAINDER)
    s = sub.add_parser("self-test", help="the check must report programs that read beside a repository")
    s.add_argument("--no-mpi", action="store_true", help="without the probe under mpirun")
    args = ap.parse_args()
    if args.sub == "run":
        if args.command and args.command[0] == "--":
            args.command = args.command[1:]
        return cmd_run(args)
    return cmd_self_test(args)


if __name__ == "__main__":
    sys.exit(main())
