#!/usr/bin/env bash
# `ncinterp bitstream` tells the truth about a board: builds it and checks the verdict
# against nextpnr's own utilisation line (its log in the work directory): a design that
# fits must give exit 0, a non-empty .bin and the cells / Fmax summary; one that does not
# must give exit 2 (the design fails the board), the clear "does not fit: the design needs N logic cells, the PART has
# M" line with nextpnr's numbers, and no .bin.
# Usage: bitstream_verdict.sh NCINTERP BOARD OUT_DIR [must-fit]
# With "must-fit" a design that does not fit fails the test (the iCEBreaker must fit).
set -uo pipefail
ncinterp=$1 board=$2 out=$3 must_fit=${4:-}
rm -rf "$out/$board.bin" "$out/$board.build"
mkdir -p "$out"
"$ncinterp" bitstream --board "$board" -o "$out/$board.bin" --work-dir "$out/$board.build" \
  >"$out/$board.stdout" 2>"$out/$board.stderr"
code=$?
cat "$out/$board.stdout" "$out/$board.stderr"
# Every placement seed's log has the same utilisation line: the first one's.
line=$(grep -E 'ICESTORM_LC:\s+[0-9]+/\s*[0-9]+' "$out/$board.build/nextpnr_seed1.log" | tail -1)
[[ -n $line ]] || { echo "FAIL: no utilisation line in nextpnr_seed1.log"; exit 1; }
used=$(sed -E 's/.*ICESTORM_LC:\s+([0-9]+)\/\s*([0-9]+).*/\1/' <<<"$line")
avail=$(sed -E 's/.*ICESTORM_LC:\s+([0-9]+)\/\s*([0-9]+).*/\2/' <<<"$line")
echo "nextpnr: $used of $avail logic cells"
if (( used > avail )); then
  [[ -z $must_fit ]] || { echo "FAIL: $board must fit"; exit 1; }
  (( code == 2 )) || { echo "FAIL: exit $code for a design that does not fit"; exit 1; }
  grep -q "does not fit: the design needs $used logic cells, the .* has $avail" "$out/$board.stderr" ||
    { echo "FAIL: no clear 'does not fit' message"; exit 1; }
  [[ ! -e $out/$board.bin ]] || { echo "FAIL: a .bin was left behind"; exit 1; }
  echo "PASS: $board does not fit ($used of $avail), reported as such"
else
  (( code == 0 )) || { echo "FAIL: exit $code for a design that fits"; exit 1; }
  [[ -s $out/$board.bin ]] || { echo "FAIL: no bitstream"; exit 1; }
  grep -q "$used of $avail logic cells" "$out/$board.stdout" || { echo "FAIL: no cell count"; exit 1; }
  grep -q "Fmax .* MHz (board clock 12 MHz" "$out/$board.stdout" || { echo "FAIL: no Fmax"; exit 1; }
  echo "PASS: $board fits ($used of $avail) and has its bitstream"
fi
