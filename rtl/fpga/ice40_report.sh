#!/usr/bin/env bash
# Area and speed report of the iCE40 board top (interp_ice40_top.sv): LUT4s, flip-flops and
# carry cells per module (yosys synth_ice40 -noflatten), then placement on one part with
# several nextpnr seeds: logic cells and the median Fmax, with the critical path of the
# median seed.
# Usage: ice40_report.sh WORK_DIR PART PACKAGE "SEEDS" FILE.sv...
#   e.g. ice40_report.sh /tmp/r hx8k ct256 "1 2 3 4 5" rtl/0_interp_pkg.sv rtl/*.sv \
#        rtl/fpga/interp_ice40_top.sv     (0_interp_pkg.sv first: yosys reads a package first)
# Idea: the per-module numbers come from the hierarchy before flattening, so logic whose
# outputs the board leaves unconnected is still counted there; the placed total is the
# flattened design, where synthesis has removed it (docs/area.md).
set -euo pipefail
work=$1 part=$2 package=$3 seeds=$4
shift 4
here=$(cd "$(dirname "$0")" && pwd)
synth_options=$(grep -v '^#' "$here/synth_ice40.options")
mkdir -p "$work"
yosys -q -l "$work/modules.log" -p "read_verilog -sv $*; synth_ice40 $synth_options -noflatten -top interp_ice40_top; stat" >/dev/null
# yosys prints every module's statistics twice (before and after the hierarchy summary):
# each printing restarts the module's flip-flop sum. Counts are per module, not per instance.
echo "| module | LUT4 | FF | carry |"
echo "|---|---:|---:|---:|"
awk '
  /^=== / { mod = $2; sub(/^\$paramod\$[0-9a-f]+\\/, "", mod); sub(/^\$paramod\\/, "", mod); sub(/\\.*/, "", mod); ff[mod] = 0 }
  /^=== design hierarchy ===/ { mod = "" }
  mod != "" && / SB_LUT4 / { lut[mod] = $2 }
  mod != "" && / SB_DFF/ { ff[mod] += $2 }
  mod != "" && / SB_CARRY / { carry[mod] = $2 }
  END { for (m in lut) if (m != "") printf "| %s | %d | %d | %d |\n", m, lut[m], ff[m], carry[m] }
' "$work/modules.log" | sort
fmaxes=()
for seed in $seeds; do
  line=$("$here/ice40_place.sh" "$work/seed$seed" "$part" "$package" 1000000 "$seed" "$@" | tail -1)
  echo "$line"
  fmaxes+=("$(sed -E 's/.*Fmax ([0-9.]+) MHz.*/\1/' <<<"$line") $seed")
done
median=$(printf '%s\n' "${fmaxes[@]}" | sort -n | awk '{a[NR]=$0} END {print a[int((NR+1)/2)]}')
echo "median Fmax: ${median% *} MHz (seed ${median#* }); critical path of that seed:"
grep -A200 "Critical path report for clock" "$work/seed${median#* }/nextpnr.log" |
  awk '$4 == "Source" {printf "  %6s ns  %s\n", $3, $5}' | head -40
