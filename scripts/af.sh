#!/usr/bin/env bash
# af.sh -- the one script with the shared build logic of the Anisotropic_fairing package.
#
#   bash scripts/af.sh deps    install the missing Debian 12 packages (as root, or through sudo)
#   bash scripts/af.sh build   deps, then configure (Release) and build everything into build/
#   bash scripts/af.sh main    build, then fair the bundled noisy fandisk with build/bin/anisotropic_fairing
#   bash scripts/af.sh test    build everything it installs (the distributed program too, whatever ran
#                              before), run all CTest tests under the read check (scripts/check_reads.py:
#                              a test that touches a file beside the repository, such as ../shared,
#                              fails the run), then `sanitize input`; non-zero exit on any failure:
#                              what CI runs
#   bash scripts/af.sh sanitize [input]  build into build-sanitize/ with AddressSanitizer and
#                              UndefinedBehaviorSanitizer, then run all CTest tests there; with
#                              `input`, only the program and the tests of reading and of the
#                              program (corpus_*, cli_*, test_input_errors)
#   bash scripts/af.sh figures [ARGS]  deps and the renderer's (VTK, Xvfb), build the program and
#                              bench/figure_peers into build-figures/, then render the manual's figures
#                              into doc/Anisotropic_fairing/fig/ (scripts/figures/make_figures.py ARGS)
#
# Works from any current directory.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

BUILD_DIR="build"
JOBS=2
DEB_PACKAGES=(libcgal-dev libeigen3-dev libboost-dev libtbb-dev nlohmann-json3-dev cmake g++ python3)   # nlohmann-json: the program's report; python3: the cli_* tests
DOC_PACKAGES=(doxygen libjs-mathjax)   # the test command's: the manual, checked without warnings, its formulas offline
RENDER_PACKAGES=(python3-vtk9 xvfb xauth)   # the renderer of --snapshot and of the figures (VTK under a virtual display)
PYTHON_PACKAGES=(pybind11-dev python3-dev python3-numpy python3-pytest python3-venv python3-skbuild python3-meshio python3-open3d python3-tqdm mypy ccache)   # the Python package (python/), pip install . (scikit-build, ccache), its tests (tqdm: the progress bar; VTK, for fair_vtk, comes with RENDER_PACKAGES) and stubs (mypy)
DISTRIBUTED_PACKAGES=(libpetsc-real-dev)   # the test command's: PETSc (with Open MPI) for anisotropic_fairing_mpi and its distributed_* tests
CHECK_PACKAGES=(strace)   # the test command's read check (scripts/check_reads.py)
CONFIGURE_ARGS=()   # more arguments for the configure step of build/ (the test command requires the distributed part)

# The main program: the one place to change what `af.sh main` runs.
# The default run, no tuning flag: fairs the noisy fandisk of the denoising benchmark (6475 vertices,
# closed) with the parameters the program chooses from the mesh (noise estimate, anisotropic tensor,
# stop at the noise level); report in build/fandisk_faired.json. Mean face-normal error to the
# noise-free fandisk: 3.74 degrees (noisy 28.42; the best isotropic run of a sweep: 10.16).
MAIN_EXE="$BUILD_DIR/bin/anisotropic_fairing"
MAIN_INPUT="examples/Anisotropic_fairing/data/fandisk_noisy.obj"
MAIN_OUTPUT="$BUILD_DIR/fandisk_faired.off"
MAIN_EXTRA_ARGS=(--report "$BUILD_DIR/fandisk_faired.json")

log() { printf '[af] %s\n' "$*" >&2; }
die() { printf '[af] error: %s\n' "$*" >&2; exit 1; }

usage() {
  sed -n '2,18p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2
}

is_installed() {
  [ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)" = "install ok installed" ]
}

cmd_deps() {
  command -v dpkg-query >/dev/null 2>&1 || die "dpkg-query not found: this script expects Debian 12"
  local missing=() p
  for p in "${DEB_PACKAGES[@]}"; do
    is_installed "$p" || missing+=("$p")
  done
  if [ "${#missing[@]}" -eq 0 ]; then
    log "dependencies already installed: ${DEB_PACKAGES[*]}"
    return 0
  fi
  local as_root=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null 2>&1 || die "missing packages (${missing[*]}); run as root or install sudo"
    as_root=(sudo)
  fi
  log "installing missing packages: ${missing[*]}"
  "${as_root[@]}" apt-get update
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y "${missing[@]}"
}

# ccache, when installed (the test command installs it): CMake (3.17 and later) takes this variable as a new
# build directory's compiler launcher, so that the Python package that python_package builds again with
# `pip install .` reuses the objects of build/ instead of compiling them a second time.
use_ccache() {
  if command -v ccache >/dev/null 2>&1; then export CMAKE_CXX_COMPILER_LAUNCHER="${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}"; fi
}

cmd_build() {
  cmd_deps
  use_ccache
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "${CONFIGURE_ARGS[@]}"
  cmake --build "$BUILD_DIR" -j"$JOBS"
}

cmd_main() {
  # only the program it runs: the tests and examples are the test command's
  cmd_deps
  use_ccache
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$BUILD_DIR" -j"$JOBS" --target anisotropic_fairing
  [ -x "$MAIN_EXE" ] || die "main program not built: $MAIN_EXE"
  log "running: $MAIN_EXE $MAIN_INPUT $MAIN_OUTPUT ${MAIN_EXTRA_ARGS[*]}"
  "$MAIN_EXE" "$MAIN_INPUT" "$MAIN_OUTPUT" "${MAIN_EXTRA_ARGS[@]}"
  echo "Output written to $ROOT/$MAIN_OUTPUT"
}

# The tests under the read check: strace follows every process of the CTest run (the tests, their
# compilers, Python, mpirun and the MPI processes) and the run fails, naming them, if any touched a path in
# the repository's parent directory outside the repository (CI has ../shared there; a fresh clone has
# nothing), even one a test copes without. (Hiding the parent in a mount namespace instead would only catch
# reads that make a test fail, and needs CAP_SYS_ADMIN, which containers deny more often than ptrace.)
# The check first proves itself (self-test: it must catch probes that read beside a scratch repository)
# and fails loudly if it cannot trace here; it does not fall back to an unchecked run. AF_READ_CHECK=off
# runs the tests unchecked, with a warning (refused when CI=true). Its cost: about a quarter more CPU time
# on tests that start many processes or compile (the corpus, cli, python, distributed, consumer tests),
# 2% on the numerical ones: under a minute on the suite. The sanitized run is not traced (LeakSanitizer
# cannot work under ptrace); its tests are ones the traced run has just run.
run_checked_tests() {
  if [ "${AF_READ_CHECK:-on}" = off ]; then
    [ "${CI:-}" != true ] || die "AF_READ_CHECK=off: the read check cannot be turned off in CI"
    log "WARNING: AF_READ_CHECK=off: the tests run WITHOUT the check that they read nothing beside the repository"
    "$@"
    return
  fi
  local python=/usr/bin/python3
  [ -x "$python" ] || python=python3
  "$python" scripts/check_reads.py self-test ||
    die "the read check does not work here (above); it needs strace and ptrace (in a container: --cap-add SYS_PTRACE). AF_READ_CHECK=off runs the tests without it"
  "$python" scripts/check_reads.py run --repo "$ROOT" -- "$@"
}

cmd_test() {
  DEB_PACKAGES+=("${DOC_PACKAGES[@]}" "${RENDER_PACKAGES[@]}" "${PYTHON_PACKAGES[@]}" "${DISTRIBUTED_PACKAGES[@]}" "${CHECK_PACKAGES[@]}")
  # the distributed part required, not left to the build directory's cache: build/ may have been configured
  # by `main` before PETSc was installed; an error if PETSc or MPI cannot be found
  CONFIGURE_ARGS+=(-DANISOTROPIC_FAIRING_BUILD_DISTRIBUTED=ON)
  cmd_build
  run_checked_tests ctest --test-dir "$BUILD_DIR" --output-on-failure --no-tests=error -j"$JOBS"
  cmd_sanitize input
}

# The manual's figures, from real runs of the program, rendered with VTK (Debian's python3-vtk9) under
# Xvfb; in their own build directory, so that they never wait for or disturb the full build.
cmd_figures() {
  DEB_PACKAGES+=("${RENDER_PACKAGES[@]}" python3-numpy)
  cmd_deps
  cmake -S . -B build-figures -DCMAKE_BUILD_TYPE=Release -DANISOTROPIC_FAIRING_BUILD_BENCHMARKS=ON -DBUILD_TESTING=OFF
  cmake --build build-figures -j"$JOBS" --target anisotropic_fairing figure_peers
  /usr/bin/python3 scripts/figures/make_figures.py --program build-figures/bin/anisotropic_fairing \
    --peers build-figures/bench/figure_peers "$@"
}

# The suite again, built with AddressSanitizer and UndefinedBehaviorSanitizer (any report fails the
# test that made it: -fno-sanitize-recover, halt_on_error), optimised (-O1) so that it stays fast, with
# line tables only (-g1: stack traces name the lines, at a fraction of full debug information's cost).
# `input`: only the program and the tests that read files or drive the program, the part that meets
# hostile input; the whole suite, sanitized, takes about 55 minutes on 2 cores (a 33-minute build),
# too long for CI's budget.
cmd_sanitize() {
  local scope="${1:-all}" targets=() tests=()
  case "$scope" in
    all) ;;
    input) targets=(--target anisotropic_fairing test_input_errors); tests=(-R '^(corpus_|cli_|test_input_errors$)') ;;
    *) die "sanitize: unknown scope $scope (all or input)" ;;
  esac
  cmd_deps
  local flags="-O1 -g1 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
  # (without the distributed program: MPI and PETSc are not built with the sanitizers)
  cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags -DNDEBUG" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DANISOTROPIC_FAIRING_BUILD_DISTRIBUTED=OFF
  cmake --build build-sanitize -j"$JOBS" "${targets[@]}"
  ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-sanitize --output-on-failure --no-tests=error -j"$JOBS" "${tests[@]}"
}

main() {
  [ "$#" -ge 1 ] || { usage; exit 2; }
  local sub="$1"; shift
  case "$sub" in
    deps)  cmd_deps "$@" ;;
    build) cmd_build "$@" ;;
    main)  cmd_main "$@" ;;
    test)  cmd_test "$@" ;;
    sanitize) cmd_sanitize "$@" ;;
    figures) cmd_figures "$@" ;;
    -h|--help|help) usage ;;
    *) usage; die "unknown subcommand: $sub" ;;
  esac
}

main "$@"
