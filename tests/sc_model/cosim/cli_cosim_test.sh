#!/usr/bin/env bash
# End-to-end checks of `ncinterp cosim`: exit codes, the one-line messages, the report and
# the VCD window. Usage: cli_cosim_test.sh NCINTERP EXAMPLE_TAPE
set -uo pipefail
ncinterp=$1
tape=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
fast=(--clock-hz 1e5 --reader-cps 1e5)

# 1. A good tape: the engines agree to the end, exit 0, report with status "match".
out=$("$ncinterp" cosim "$tape" "${fast[@]}" --report "$work/ok.json" 2>&1); rc=$?
[ $rc -eq 0 ] || fail "good tape: exit $rc: $out"
grep -q "agree on all" <<<"$out" || fail "good tape: no summary: $out"
grep -q '"status": "match"' "$work/ok.json" || fail "good tape: report status"
grep -q '"end": "done"' "$work/ok.json" || fail "good tape: report end"

# 2. An injected golden-model fault: exit 2, one line naming cycle, block and signal, VCD.
out=$("$ncinterp" cosim "$tape" "${fast[@]}" --inject-fault stuck-step:20000:y \
      --vcd "$work/m.vcd" --vcd-window 100 --report "$work/m.json" 2>&1); rc=$?
[ $rc -eq 2 ] || fail "fault: exit $rc: $out"
grep -q "differ at cycle 20000, block N[0-9]*, signal step_y_o: expected 1, actual 0 (19999 cycles matched)" <<<"$out" \
  || fail "fault: message: $out"
[ -s "$work/m.vcd" ] || fail "fault: no VCD"
grep -q '\$var .* step_y_o ' "$work/m.vcd" || fail "fault: VCD lacks step_y_o"
grep -q '"signal": "step_y_o"' "$work/m.json" || fail "fault: report"

# 3. A bad tape: both engines stop with the same error: exit 1, "TAPE: block N, offset K".
printf '%%\nN1 G01 X0.001 F100.000\nN2 G01 Q1\n' > "$work/bad.nc"
out=$("$ncinterp" cosim "$work/bad.nc" "${fast[@]}" 2>&1); rc=$?
[ $rc -eq 1 ] || fail "bad tape: exit $rc: $out"
grep -q "bad.nc: block N2, offset 32: unknown address letter" <<<"$out" || fail "bad tape: message: $out"

# 4. Cycle limit: exit 3 with a clear message; unreadable tape: exit 1; no stray files.
out=$("$ncinterp" cosim "$tape" --max-cycles 500 2>&1); rc=$?
[ $rc -eq 3 ] || fail "limit: exit $rc: $out"
grep -q "cycle limit (500 cycles)" <<<"$out" || fail "limit: message: $out"
out=$("$ncinterp" cosim "$work/missing.nc" --report "$work/missing.json" 2>&1); rc=$?
[ $rc -eq 1 ] || fail "missing tape: exit $rc"
[ ! -e "$work/missing.json" ] || fail "missing tape: a report was written"
[ -z "$(find "$work" -name '.*')" ] || fail "temporary files left: $(find "$work" -name '.*')"
echo "all cosim CLI checks passed"
