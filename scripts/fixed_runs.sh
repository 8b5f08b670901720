#!/usr/bin/env bash
# A fixed set of tool runs (denoising pair, every automatic choice, borders, attributes in each mode,
# P1, control points, curvature) written to DIR, for checking that a refactoring changes no output:
#   bash scripts/fixed_runs.sh TOOL DIR_BEFORE; ...; bash scripts/fixed_runs.sh TOOL DIR_AFTER
#   python3 scripts/compare_runs.py DIR_BEFORE DIR_AFTER      (numbers to 1e-12 relative)
set -euo pipefail
tool=$(realpath "$1"); out=$2; mkdir -p "$out"
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
data=$root/test/Anisotropic_fairing/data; ex=$root/examples/Anisotropic_fairing/data
run() { local name=$1; shift; "$tool" "$@" --quiet --report "$out/$name.json" > "$out/$name.stdout" 2> "$out/$name.stderr" || echo "exit $?" >> "$out/$name.stderr"; }
run fandisk_default      "$data/fandisk0.3_noisy.obj" "$out/fandisk_default.obj"
run fandisk_isotropic    "$data/fandisk0.3_noisy.obj" "$out/fandisk_isotropic.obj" --tensor isotropic --relative-time-step 1e-3 --steps 3
run fandisk_anisotropic  "$data/fandisk0.3_noisy.obj" "$out/fandisk_anisotropic.obj" --tensor anisotropic --relative-time-step 1e-4 --steps 5 --lambda 8 --epsilon 1e-3
run fandisk_linear       "$data/fandisk0.3_noisy.obj" "$out/fandisk_linear.obj" --element linear --tensor isotropic --relative-time-step 1e-3 --steps 3
run fandisk_control      "$data/fandisk0.3_noisy.obj" "$out/fandisk_control.ply" --output control --curvature --relative-time-step 1e-3 --steps 2
run camelhead_default    "$data/camelhead.off" "$out/camelhead_default.off"
run face_default         "$data/face.obj" "$out/face_default.obj"
run face_vertices        "$data/face.obj" "$out/face_vertices.obj" --boundary vertices --relative-time-step 1e-3 --steps 3
run hemisphere_uniform   "$data/hemisphere.off" "$out/hemisphere_uniform.off" --tensor uniform
run bunny_fidelity       "$data/bunny.off" "$out/bunny_fidelity.off" --relative-time-step 1e-3 --relative-fidelity 10 --steps 4 --stop off
for mode in separate coupled attributes; do
  run quality_$mode "$ex/octahedron_quality.ply" "$out/quality_$mode.ply" --attributes quality --mode $mode --relative-time-step 1e-3 --relative-fidelity 100 --steps 2
done
run quality_default "$ex/octahedron_quality.ply" "$out/quality_default.ply" --attributes quality
