#!/usr/bin/env bash
# Wall time of `ncinterp tape`, `ncinterp check` and `ncinterp play --engine golden` on
# routing-style parts of several lengths (bench/check/routing_part.py), one table row per
# length: blocks, machine clocks, check's wall time and peak memory, its verdict and largest
# total error, play's wall time.
# Idea: the same G-code for every binary, so two builds (before and after a change) can be
# compared by running this script with each; a check that runs past TIMEOUT seconds is
# stopped and reported as such.
# Usage: bench/check/check_time.sh [NCINTERP] [SIZES] [PASSES] [TIMEOUT] [RUN_ARGS]
# RUN_ARGS: options of both check and play, e.g. "--arch parallel".
#   e.g. bench/check/check_time.sh build/ncinterp "1000 10000 50000" 1 600
set -euo pipefail
ncinterp=${1:-build/ncinterp}
sizes=${2:-1000 10000 50000}
passes=${3:-1}
timeout_s=${4:-600}
run_args=${5:-}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '| blocks asked | tape blocks | tape s | clocks | check s | check MB | verdict | max total error mm | play s |\n'
printf '|---:|---:|---:|---:|---:|---:|---|---:|---:|\n'
for n in $sizes; do
  python3 "$here/routing_part.py" --blocks "$n" --passes "$passes" > "$work/part.nc"
  t0=$(date +%s.%N)
  "$ncinterp" tape "$work/part.nc" -o "$work/part.tape" --report "$work/tape.json" > /dev/null 2> "$work/tape.err"
  t1=$(date +%s.%N)
  blocks=$(jq .blocks "$work/tape.json")
  set +e
  # shellcheck disable=SC2086
  /usr/bin/time -f '%e %M' -o "$work/time" timeout "$timeout_s" \
    "$ncinterp" check "$work/part.tape" --contour "$work/part.nc" --report "$work/check.json" $run_args \
    > /dev/null 2> "$work/check.err"
  rc=$?
  set -e
  if [ "$rc" -eq 124 ]; then
    printf '| %s | %s | %.2f | | > %s | | stopped | | |\n' "$n" "$blocks" "$(awk "BEGIN{print $t1 - $t0}")" "$timeout_s"
    continue
  fi
  read -r wall kb < <(tail -1 "$work/time")
  clocks=$(jq .cycles "$work/check.json")
  verdict=$(jq -r .status "$work/check.json")
  err=$(jq '(.total_error.max_mm // .total_error.max) * 10000 | round / 10000' "$work/check.json")
  set +e
  # shellcheck disable=SC2086
  /usr/bin/time -f '%e' -o "$work/ptime" timeout "$timeout_s" \
    "$ncinterp" play "$work/part.tape" --engine golden --report "$work/play.json" $run_args > /dev/null 2>&1
  prc=$?
  set -e
  play=$(tail -1 "$work/ptime")
  [ "$prc" -eq 124 ] && play="> $timeout_s"
  printf '| %s | %s | %.2f | %s | %s | %d | %s (exit %s) | %s | %s |\n' "$n" "$blocks" "$(awk "BEGIN{print $t1 - $t0}")" \
    "$clocks" "$wall" $((kb / 1024)) "$verdict" "$rc" "$err" "$play"
done
