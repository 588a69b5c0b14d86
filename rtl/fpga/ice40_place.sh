#!/usr/bin/env bash
# Synthesises the iCE40 board top (interp_ice40_top.sv) and places and routes it with
# nextpnr-ice40; prints the logic cells used and the Fmax of one seed, and fails when the
# design does not fit in MAX_LC logic cells (or is not placed and routed at all).
# Usage: ice40_place.sh WORK_DIR PART PACKAGE MAX_LC SEED FILE.sv...
#   e.g. ice40_place.sh /tmp/w hx1k tq144 1280 1 rtl/*.sv rtl/fpga/interp_ice40_top.sv
# Idea: a deterministic area test (fixed tool versions, fixed seed); the numbers are the
# nextpnr log's "ICESTORM_LC: N/M" and "Max frequency for clock" lines. The part's pins
# are left unconstrained (--pcf-allow-unconstrained): only whether the logic fits and how
# fast it is is measured here, the board's pinout is the board's.
set -euo pipefail
work=$1 part=$2 package=$3 max_lc=$4 seed=$5
shift 5
synth_options=$(grep -v '^#' "$(dirname "$0")/synth_ice40.options")
mkdir -p "$work"
yosys -q -l "$work/yosys.log" -p "read_verilog -sv $*; synth_ice40 $synth_options -top interp_ice40_top -json $work/top.json" >/dev/null
status=0
nextpnr-ice40 "--$part" --package "$package" --json "$work/top.json" --pcf-allow-unconstrained \
  --seed "$seed" --freq 100 --timing-allow-fail >"$work/nextpnr.log" 2>&1 || status=$?
lc_line=$(grep -m1 "ICESTORM_LC:" "$work/nextpnr.log" || true)
lcs=$(sed -E 's/.*ICESTORM_LC: *([0-9]+)\/ *([0-9]+).*/\1/' <<<"$lc_line")
fmax=$(grep "Max frequency for clock" "$work/nextpnr.log" | tail -1 | sed -E 's/.*: ([0-9.]+) MHz.*/\1/' || true)
echo "part $part-$package seed $seed: logic cells ${lcs:-?} (limit $max_lc), Fmax ${fmax:-?} MHz"
if [[ -z "$lcs" ]]; then
  echo "no utilisation line in $work/nextpnr.log" >&2
  exit 1
fi
if (( lcs > max_lc )); then
  echo "FAIL: $lcs logic cells > $max_lc" >&2
  exit 1
fi
if (( status != 0 )); then
  echo "FAIL: nextpnr-ice40 exit $status: $(grep -m1 -i 'error' "$work/nextpnr.log" || true)" >&2
  exit 1
fi
