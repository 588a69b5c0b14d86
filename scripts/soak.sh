#!/usr/bin/env bash
# Soak: many random contours (parts with fillets and holes, reference tables, cubic chains,
# NACA airfoils, circles) through the first stage, the tape, the golden model and the
# verilated RTL, each judged by the trajectory checker (docs/verification.md). Outside CI.
# Usage: scripts/soak.sh [CASES=500] [SEED=1] [ENGINE=both] [more ncinterp_soak options]
# Failing cases go to $BUILD/soak-failures/ (input, tape, report, commands to reproduce).
# A long soak runs in shards of SOAK_SHARD cases (default 100), SOAK_JOBS at a time (default
# 1; the first shard builds the RTL variants alone), under GNU parallel with a job log:
# rerunning the same command resumes where it stopped: the shards that ran to their end
# are kept, a killed one (or one with failures: the same seeds fail again) runs again.
# Each shard's output is in $BUILD/soak-runs/<seed>+<cases>/; the totals end the output.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${NCINTERP_BUILD:-$root/build}
cases=${1:-500} seed=${2:-1} engine=${3:-both}
shard=${SOAK_SHARD:-100} jobs=${SOAK_JOBS:-1}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target ncinterp_soak --parallel 2
soak=("$build/bench/soak/ncinterp_soak" --engine "$engine" --dump "$build/soak-failures" "${@:4}")
if ((cases <= shard)); then exec "${soak[@]}" --cases "$cases" --seed "$seed"; fi

runs="$build/soak-runs/$seed+$cases"
mkdir -p "$runs"
# The commit the soak measures: a resumed run at another commit says so.
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
[ -f "$runs/commit" ] || echo "$commit" >"$runs/commit"
[ "$(cat "$runs/commit")" = "$commit" ] ||
  echo "soak.sh: warning: $runs began at commit $(cat "$runs/commit"), this is $commit" >&2
shards=$(((cases + shard - 1) / shard))
run_shard() {  # shard index: its first seed and case count; its log, written when it ends
  local i=$1 first=$((seed + $1 * shard)) n=$((cases - $1 * shard < shard ? cases - $1 * shard : shard))
  $soak_cmd --cases "$n" --seed "$first" >"$runs/shard-$i.log.part" 2>&1
  local rc=$?
  # 0: every case passed, 1: some failed; anything else (killed, crashed) is no result, and
  # --resume-failed runs the shard again.
  if ((rc <= 1)); then mv "$runs/shard-$i.log.part" "$runs/shard-$i.log"; else rm -f "$runs/shard-$i.log"; fi
  return $rc
}
export -f run_shard
export seed cases shard runs
export soak_cmd="${soak[*]}"
# The first shard builds the RTL variants into the cache alone; the rest may run together.
status=0
parallel --joblog "$runs/joblog.first" --resume-failed -j 1 run_shard ::: 0 || status=1
if ((shards > 1)); then
  parallel --joblog "$runs/joblog" --resume-failed -j "$jobs" run_shard ::: $(seq 1 $((shards - 1))) || status=1
fi
# Totals per arch from the shards' summary lines: "soak ARCH: N cases, G golden runs ...,
# R RTL lock steps (V on variants), F failed; C clocks in T s".
cat "$runs"/shard-*.log | awk -v dir="$runs" '
  /^soak (serial|parallel):/ {
    a = $2; sub(":", "", a); n[a] += $3
    for (k = 2; k <= NF; k++) {
      if ($k == "golden") g[a] += $(k - 1); if ($k == "RTL") r[a] += $(k - 1)
      if ($k ~ /^failed/) f[a] += $(k - 1); if ($k == "clocks") c[a] += $(k - 1); if ($k == "s") t[a] += $(k - 1)
    }
  }
  / FAIL/ { fails++ }
  END {
    for (a in n) printf "soak %s: %d cases, %d golden runs, %d RTL lock steps, %d failed; %.3g clocks in %.0f s (%s)\n",
                        a, n[a], g[a], r[a], f[a], c[a], t[a], dir
    printf "soak: %d FAIL lines\n", fails
  }'
exit $status
