#!/usr/bin/env bash
# The interpolator as the iCE40 flow builds it, back as simulatable Verilog: yosys
# synth_ice40, with the project's options (rtl/fpga/synth_ice40.options), maps rtl/*.sv
# (top interp_top, default parameters, in the serial or the parallel arch) to SB_LUT4 / SB_CARRY / SB_DFF* / SB_RAM40_4K cells, then a second yosys run flattens those cells' own simulation models
# (yosys's ice40/cells_sim.v) into the netlist, which Verilator then compiles.
# Idea: a test of the RTL cannot see what synthesis does with it. Don't-care values ('x)
# are the case in point: Verilator picks 0 for them, yosys whatever saves logic, so a 'x on
# a path that matters simulates right and synthesises wrong (an arc geometry error flag
# left 'x made synth_ice40 reject every arc and remove the whole arc preparation). The
# netlist simulated in lock step with the golden model catches that.
# Usage: gate_netlist.sh serial|parallel OUT.v FILE.sv...   (the package file first)
#   serial    interp_top with BitSerial = 1, as the boards have it (its DDA's registers in a
#             block RAM: SB_RAM40_4K and its model)
#   parallel  BitSerial = 0
set -euo pipefail
case ${1:-} in
  serial) parameters="chparam -set BitSerial 1 interp_top;" ;;
  parallel) parameters="chparam -set BitSerial 0 interp_top;" ;;
  *) echo "gate_netlist.sh: the first argument is serial or parallel" >&2; exit 2 ;;
esac
shift
out=$1
shift
cells=$(dirname "$(command -v yosys)")/../share/yosys/ice40/cells_sim.v
mapped="$out.ice40.v"
# The project's synth_ice40 options: the netlist tested here is the one the boards get.
synth_options=$(grep -v '^#' "$(dirname "$0")/../../../rtl/fpga/synth_ice40.options")
yosys -q -p "read_verilog -sv $*; $parameters synth_ice40 $synth_options -top interp_top; write_verilog -noattr $mapped" >/dev/null
# ICE40_HX: the HX family's cell timing branch; the models' logic does not depend on it.
yosys -q -p "read_verilog $mapped; read_verilog -D ICE40_HX $cells; hierarchy -top interp_top;
             proc; flatten; opt_clean; write_verilog -noattr $out.tmp" 2>/dev/null
mv "$out.tmp" "$out"
rm -f "$mapped"
