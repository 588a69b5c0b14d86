#!/usr/bin/env bash
# The CAM-style example files (examples/contours/cam/ and its refused/), one table row each:
# taped or refused (and why), blocks, traverses, passes, and check's verdict and largest
# total error. The table in docs/first-stage.md 1.3.3 is this script's output.
# Usage: bench/check/cam_table.sh [NCINTERP]
set -euo pipefail
ncinterp=${1:-build/ncinterp}
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '| file | result | blocks | G00 | passes (depth mm: blocks) | check | max total error mm |\n'
printf '|---|---|---:|---:|---|---|---:|\n'
for f in "$root"/examples/contours/cam/*.* "$root"/examples/contours/cam/refused/*.*; do
  name=${f#"$root"/examples/contours/cam/}
  if ! "$ncinterp" tape "$f" -o "$work/t.tape" --report "$work/r.json" > /dev/null 2> "$work/err"; then
    msg=$(head -1 "$work/err" | sed "s|^$root/examples/contours/cam/||; s/|/\\\\|/g" | cut -c1-160)
    printf '| %s | refused: %s | | | | | |\n' "$name" "$msg"
    continue
  fi
  blocks=$(jq .blocks "$work/r.json")
  g00=$(jq .traverse_blocks "$work/r.json")
  passes=$(jq -r '[.passes[] | "\(if .depth_mm == null then "no Z" else .depth_mm end): \(.blocks)"] | join(", ")' "$work/r.json")
  set +e
  "$ncinterp" check "$work/t.tape" --contour "$f" --reader-cps 100000 --report "$work/c.json" > /dev/null 2> "$work/cerr"
  rc=$?
  set -e
  if [ -s "$work/c.json" ] && [ "$rc" -ne 1 ]; then
    verdict="$(jq -r .status "$work/c.json") (exit $rc)"
    err=$(jq '.total_error.max_mm * 10000 | round / 10000' "$work/c.json")
  else
    verdict="not run: $(head -1 "$work/cerr" | sed 's/|/\\|/g' | cut -c1-80)"
    err=""
  fi
  printf '| %s | taped | %s | %s | %s | %s | %s |\n' "$name" "$blocks" "$g00" "$passes" "$verdict" "$err"
done
