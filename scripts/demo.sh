#!/usr/bin/env bash
# Newcomer's demo: installs the Debian packages it needs and builds the `ncinterp` executable
# (scripts/setup.sh --demo), then plays the bundled example tape (examples/gear.nc, a
# 12-tooth gear outline in 48 chords) through the SystemC system model with the verilated
# RTL, and writes its waves and JSON report.
# The VCD covers reset, the tape lead-in and the first block (the whole part at 1 MHz would
# be about 0.7 GB; docs/waves.md explains windows).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh" --demo
"$root/build/ncinterp" play "$root/examples/gear.nc" --engine rtl \
  --vcd "$root/waves/example.vcd" --vcd-to N1 --report "$root/waves/example.json"
cat <<MSG

Played examples/gear.nc on the RTL interpolator (SystemC system model, 1 MHz clock,
tape reader at 1000 characters/s).
  report: waves/example.json   (pulses, final position, path error, feed accuracy)
  waves:  waves/example.vcd    (reset, tape lead-in and block N1)
View the waves with:  gtkwave waves/example.vcd waves/interp.gtkw
How to read them:     docs/waves.md
MSG
