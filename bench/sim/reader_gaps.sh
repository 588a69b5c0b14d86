#!/usr/bin/env bash
# Gap clocks against the tape reader's speed: plays each tape in lock step (verilated RTL
# and golden model of one arch, `ncinterp cosim --arch`) at each reader speed and prints
# the clocks in which the player waited for a block (busy low between blocks), which must
# be 0 for the machine to keep its programmed feed.
# Usage: reader_gaps.sh [--arch serial|parallel] [--clock-hz HZ] NCINTERP "CPS..." TAPE...
#   e.g. bench/sim/reader_gaps.sh --arch parallel build/ncinterp "1000 500 200 100" examples/*.nc
#   --arch: the machine (ncinterp's --arch; its default, serial, when not given)
# Idea: a block is ready when its last frame has been read (and, for an arc, prepared);
# it plays without a gap when that happens before the block ahead of it has finished
# (docs/interpolator.md 3.5). The slowest reader with 0 gap clocks is the figure asked for.
set -euo pipefail
arch=() clock_hz=1000000
while [[ ${1:-} == --* ]]; do
  case $1 in
    --arch) arch=(--arch "$2"); shift 2 ;;
    --clock-hz) clock_hz=$2; shift 2 ;;
    *) echo "reader_gaps.sh: unknown option $1" >&2; exit 1 ;;
  esac
done
ncinterp=$1 speeds=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| tape | reader (characters/s) | clocks | blocks | gap clocks |"
echo "|---|---:|---:|---:|---:|"
for tape in "$@"; do
  for cps in $speeds; do
    "$ncinterp" cosim "$tape" "${arch[@]}" --clock-hz "$clock_hz" --reader-cps "$cps" \
      --report "$work/r.json" >/dev/null 2>&1 || {
      echo "| $(basename "$tape") | $cps | run failed | | |"
      continue
    }
    jq -r --arg t "$(basename "$tape")" --arg c "$cps" \
      '"| \($t) | \($c) | \(.cycles) | \(.blocks) | \(.gap_cycles // .gap_clocks) |"' "$work/r.json"
  done
done
