#!/usr/bin/env bash
# Gap clocks of the two archs against the feed: writes a contour's tape with arc blocks at
# each feed, plays it on the golden model of the parallel arch (one DDA iteration per
# clock) and of the serial one (`ncinterp check --arch serial`, 2P clocks per iteration,
# P = W rounded up to a power of two) at each clock frequency, and prints the clocks in
# which the player waited for a block.
# Usage: dry_run_gaps.sh NCINTERP CONTOUR "FEEDS (mm/min)" "CLOCKS (Hz)" [READER_CPS]
#   e.g. bench/sim/dry_run_gaps.sh build/ncinterp examples/contours/circle_r50.json \
#        "500 1000 2000 5000 10000" "1000000 12000000"
# Idea: an arc is ready when it has been read and prepared; the serial dry run prepares
# it in 2PN clocks instead of N, so it leaves gaps once the block ahead plays in fewer
# clocks than that, i.e. above a feed that grows with the clock (docs/interpolator.md 3.5).
set -euo pipefail
ncinterp=$1 contour=$2 feeds=$3 clocks=$4 cps=${5:-1000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
gaps() {  # TAPE CLOCK ARCH: the gap clocks of one run
  "$ncinterp" check "$1" --clock-hz "$2" --reader-cps "$cps" --arch "$3" --report "$work/r.json" \
    >/dev/null
  jq -r '"\(.gap_clocks) | \(.cycles)"' "$work/r.json"
}
echo "| feed (mm/min) | clock (Hz) | gap clocks, parallel | clocks | gap clocks, serial | clocks |"
echo "|---:|---:|---:|---:|---:|---:|"
for feed in $feeds; do
  "$ncinterp" tape "$contour" --arcs circle --feed "$feed" -o "$work/t.nc" >/dev/null
  for clock in $clocks; do
    echo "| $feed | $clock | $(gaps "$work/t.nc" "$clock" parallel) | $(gaps "$work/t.nc" "$clock" serial) |"
  done
done
