#!/usr/bin/env bash
# fuzz.sh -- run the libFuzzer targets over the tool's mesh reading and a two-step fairing.
#
#   bash scripts/fuzz.sh FORMAT [SECONDS=600]   FORMAT: off, obj, ply-ascii or ply-binary
#
# Builds build-fuzz/ with clang (AddressSanitizer and UndefinedBehaviorSanitizer), starts from the
# files of that format in test/Anisotropic_fairing/corpus and examples/Anisotropic_fairing/data, and
# keeps what it finds in build-fuzz/findings-FORMAT (crashing inputs: crash-*, leak-*, timeout-*,
# oom-*). A crashing input, once fixed, goes into test/Anisotropic_fairing/corpus with its expected
# exit code in corpus/expected.txt.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
FORMAT="${1:?FORMAT: off, obj, ply-ascii or ply-binary}"
SECONDS_TO_RUN="${2:-600}"
case "$FORMAT" in
  off) target=fuzz_mesh_off; pattern='*.off' ;;
  obj) target=fuzz_mesh_obj; pattern='*.obj' ;;
  ply-ascii|ply-binary) target=fuzz_mesh_ply; pattern='*.ply' ;;
  *) echo "unknown FORMAT $FORMAT" >&2; exit 2 ;;
esac
command -v clang++ >/dev/null || { echo "clang++ not found (apt-get install clang libclang-rt-14-dev)" >&2; exit 1; }
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBUILD_TESTING=OFF \
  -DANISOTROPIC_FAIRING_BUILD_FUZZERS=ON -DANISOTROPIC_FAIRING_WITH_TBB=OFF > /dev/null
cmake --build build-fuzz --target "$target" -j2
seeds="build-fuzz/seeds-$FORMAT"
findings="build-fuzz/findings-$FORMAT"
mkdir -p "$seeds" "$findings"
for f in test/Anisotropic_fairing/corpus/$pattern examples/Anisotropic_fairing/data/$pattern; do
  [ -f "$f" ] || continue
  if [ "$FORMAT" = ply-ascii ] && ! head -c 200 "$f" | grep -q 'format ascii'; then continue; fi
  if [ "$FORMAT" = ply-binary ] && ! head -c 200 "$f" | grep -q 'format binary'; then continue; fi
  [ "$(stat -c %s "$f")" -le 200000 ] && cp "$f" "$seeds/"
done
cd "$findings"
"../$target" -max_total_time="$SECONDS_TO_RUN" -timeout=20 -rss_limit_mb=2048 -max_len=20000 \
  -print_final_stats=1 . "../seeds-$FORMAT" 2>&1 | tail -25
