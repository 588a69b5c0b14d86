#!/usr/bin/env bash
# Synthesises RTL with yosys and fails on any synthesis error or any latch.
# Usage: yosys_synth_check.sh TOP FILE.sv...
# Idea: the RTL must be synthesizable without latches (team standard); yosys exits non-zero
# when read/synth fails or when the latch selection is not empty.
set -euo pipefail
top=$1
shift
yosys -q -p "read_verilog -sv $*; synth -top $top; \
select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr t:\$_DLATCH_* t:\$_DLATCHSR_* t:\$_SR_*; \
tee -o /dev/stdout stat"
