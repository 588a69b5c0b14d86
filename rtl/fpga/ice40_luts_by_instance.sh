#!/usr/bin/env bash
# Where the LUT4s of the flattened iCE40 board top go: synth_ice40 (flattened, as placed)
# of interp_ice40_top, then every SB_LUT4 counted by the instance path of the net it drives
# (yosys keeps the hierarchical names on nets), down to the decoder's and the arc
# preparation's submodules.
# Usage: ice40_luts_by_instance.sh WORK_DIR FILE.sv...   (0_interp_pkg.sv first), e.g.
#   rtl/fpga/ice40_luts_by_instance.sh /tmp/l rtl/0_interp_pkg.sv \
#       $(ls rtl/*.sv | grep -v 0_interp_pkg) rtl/fpga/interp_ice40_top.sv
# Idea: the per-module view (-noflatten, ice40_report.sh) counts logic the board removes and
# cannot merge across module borders; this one counts what is placed. It is approximate at
# the borders: a LUT that merges logic of two modules is counted where its output net is named.
set -euo pipefail
work=$1
shift
synth_options=$(grep -v '^#' "$(dirname "$0")/synth_ice40.options")
mkdir -p "$work"
yosys -q -p "read_verilog -sv $*; synth_ice40 $synth_options -top interp_ice40_top; write_verilog -noattr $work/net.v" >/dev/null
awk '
  /SB_LUT4 / { in_lut = 1 }
  in_lut && /\.O\(/ {
    net = $0; sub(/.*\.O\(/, "", net); sub(/\).*/, "", net); sub(/^\\/, "", net)
    n = split(net, part, ".")
    where = part[1] "." part[2]
    if (n > 3 && part[2] == "u_decoder") where = where "." part[3]
    if (n > 4 && part[3] == "u_arc") where = where "." part[4]
    if (n <= 2 || where ~ /_SB_/) where = "(other: top level, merged)"
    luts[where]++; total++; in_lut = 0
  }
  END { for (w in luts) printf "%6d  %s\n", luts[w], w; printf "%6d  total\n", total }
' "$work/net.v" | sort -rn
