#!/usr/bin/env bash
# Soak: many random contours (parts with fillets and holes, reference tables, cubic chains,
# NACA airfoils, circles) through the first stage, the tape, the golden model and the
# verilated RTL, each judged by the trajectory checker (docs/verification.md). Outside CI.
# Usage: scripts/soak.sh [CASES=500] [SEED=1] [ENGINE=both] [more ncinterp_soak options]
# Failing cases go to $BUILD/soak-failures/ (input, tape, report, commands to reproduce).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${NCINTERP_BUILD:-$root/build}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target ncinterp_soak --parallel 2
exec "$build/bench/soak/ncinterp_soak" --cases "${1:-500}" --seed "${2:-1}" --engine "${3:-both}" \
  --dump "$build/soak-failures" "${@:4}"
