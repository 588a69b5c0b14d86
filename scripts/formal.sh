#!/usr/bin/env bash
# Formal proofs of the interpolator's promises: yosys 0.23 + yosys-smtbmc (z3 or boolector).
#
# Idea: every proof is one harness module in rtl/formal/ that instantiates the RTL module
# under proof, constrains its inputs with assume, keeps its own model state and asserts on
# the module's ports. rtl/formal/proofs lists the proofs (harness, method, depth, parameters,
# RTL files); rtl/formal/mutations lists small bugs injected into copies of the RTL, each of
# which must make one named assertion fail with a counterexample. The RTL files themselves
# are never changed. A harness may observe an internal signal of the module under proof with
# a "// formal-tap: <harness wire> = <hierarchical name>" line: after flatten the script
# drives that (otherwise undriven) wire from the named signal with yosys' connect. Taps are
# only used in assertions (an undriven wire would make them fail, never pass).
#
# Flow per proof: read_verilog -formal -sv, hierarchy, proc, flatten, connect (taps), prep,
# async2sync, dffunmap, write_smt2 -wires; then yosys-smtbmc: BMC (-t N), k-induction (-i
# -t N, after the BMC base case) or cover (-c -t N). A failure writes a VCD.
#
# Usage: scripts/formal.sh [--deep] [--solver z3|boolector] [--work DIR] [--jobs N]
#                          [--only PROOF] [--mutant MUTATION] [--no-mutants] [--list]
#                          [--check-mutants] [--mutations FILE]
#   --deep       the longer proofs (bigger widths, deeper BMC: the proofs file's deep columns)
#                and the mutations marked "deep = yes"
#   --only P     run proof P only (exit 0 if it passes)
#   --mutant M   run mutation M only (exit 0 if its proof fails on the named assertion)
#   --no-mutants proofs only
#   --check-mutants  no solver: every mutation names a proof and a file, and its line
#                `from` is found exactly once there (a stale mutation fails at once)
#   --mutations F    read the mutations from F instead of rtl/formal/mutations
# Prints a table (property, method, depth, result, seconds) and "N passed, N failed".
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
formal_dir="$root/rtl/formal"
deep=0
solver=z3
work=""
only=""
only_mutant=""
mutants=1
list=0
check_mutants=0
mutations_file=""
jobs=1
while (($#)); do
  case "$1" in
    --deep) deep=1 ;;
    --solver) solver="$2"; shift ;;
    --work) work="$2"; shift ;;
    --only) only="$2"; shift ;;
    --mutant) only_mutant="$2"; shift ;;
    --no-mutants) mutants=0 ;;
    --list) list=1 ;;
    --check-mutants) check_mutants=1 ;;
    --mutations) mutations_file="$2"; shift ;;
    --jobs) jobs="$2"; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d'; exit 0 ;;
    *) echo "formal.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
for tool in yosys yosys-smtbmc "$solver"; do
  command -v "$tool" >/dev/null || { echo "formal.sh: $tool not found (scripts/setup.sh installs it)" >&2; exit 2; }
done
[ -n "$work" ] || work=$(mktemp -d /tmp/ncinterp-formal.XXXXXX)
mkdir -p "$work"

# --- the proofs file: name harness mode depth deep_depth params deep_params rtl-modules...
declare -A p_harness p_mode p_depth p_params p_rtl
proof_names=()
while read -r name harness mode depth deep_depth params deep_params rtl; do
  [[ -z "$name" || "$name" == \#* ]] && continue
  proof_names+=("$name")
  p_harness[$name]=$harness
  p_mode[$name]=$mode
  if ((deep)); then p_depth[$name]=$deep_depth; p_params[$name]=$deep_params
  else p_depth[$name]=$depth; p_params[$name]=$params; fi
  p_rtl[$name]=$rtl
done <"$formal_dir/proofs"

# --- the mutations file: blocks of "key = value" lines, each block opened by [name]
declare -A m_proof m_file m_from m_to m_fails m_depth m_deep
mutant_names=()
current=""
while IFS= read -r line; do
  [[ -z "${line// }" || "$line" == \#* ]] && continue
  if [[ "$line" =~ ^\[(.+)\]$ ]]; then
    current=${BASH_REMATCH[1]}
    mutant_names+=("$current")
    continue
  fi
  key=${line%%=*}; key=${key// /}
  value=${line#*=}; value=${value# }
  case "$key" in
    proof) m_proof[$current]=$value ;;
    file) m_file[$current]=$value ;;
    from) m_from[$current]=$value ;;
    to) m_to[$current]=$value ;;
    fails) m_fails[$current]=$value ;;
    depth) m_depth[$current]=$value ;;
    deep) m_deep[$current]=$value ;;
    *) echo "formal.sh: mutations: unknown key '$key' in [$current]" >&2; exit 2 ;;
  esac
done <"${mutations_file:-$formal_dir/mutations}"

# The mutations the run checks: a "deep = yes" one (its counterexample lies beyond the
# default depths) only with --deep; --mutant M runs any.
run_mutants=()
for mut in "${mutant_names[@]}"; do
  [ "${m_deep[$mut]:-no}" = yes ] && ((!deep)) && continue
  run_mutants+=("$mut")
done

if ((list)); then
  printf 'proof %s\n' "${proof_names[@]}"
  printf 'mutant %s\n' "${run_mutants[@]}"
  for mut in "${mutant_names[@]}"; do
    [ "${m_deep[$mut]:-no}" = yes ] && echo "deep mutant $mut"
  done
  exit 0
fi

if ((check_mutants)); then
  stale=0
  for mut in "${mutant_names[@]}"; do
    problem=""
    if [ -z "${m_proof[$mut]:-}" ] || [ -z "${p_mode[${m_proof[$mut]}]:-}" ]; then
      problem="names no proof of rtl/formal/proofs ('${m_proof[$mut]:-}')"
    elif [ ! -f "$root/${m_file[$mut]:-}" ]; then
      problem="its file '${m_file[$mut]:-}' does not exist"
    else
      count=$(grep -cF -- "${m_from[$mut]}" "$root/${m_file[$mut]}" || true)
      [ "$count" = 1 ] || problem="its line is found $count times in ${m_file[$mut]}: ${m_from[$mut]}"
    fi
    if [ -n "$problem" ]; then
      echo "mutant $mut: $problem"
      stale=$((stale + 1))
    fi
  done
  echo "${#mutant_names[@]} mutations, $stale stale"
  ((stale == 0)) || exit 1
  exit 0
fi

# build_smt2 NAME RTL_DIR OUT_DIR [DEFINES]: the harness of proof NAME with the RTL from RTL_DIR.
build_smt2() {
  local name=$1 rtl_dir=$2 out=$3 defines=${4:-} harness=${p_harness[$1]}
  local files=() m script
  # The package of shared constants comes first when it exists (modules may import it).
  [ -f "$rtl_dir/0_interp_pkg.sv" ] && files+=("$rtl_dir/0_interp_pkg.sv")
  for m in ${p_rtl[$name]}; do files+=("$rtl_dir/$m.sv"); done
  files+=("$formal_dir/$harness.sv")
  script="read_verilog -formal -sv $defines ${files[*]}"$'\n'
  if [ "${p_params[$name]}" != "-" ]; then
    local kv
    for kv in ${p_params[$name]//,/ }; do
      script+="chparam -set ${kv%%=*} ${kv#*=} $harness"$'\n'
    done
  fi
  script+="hierarchy -check -top $harness"$'\n'"proc"$'\n'"flatten"$'\n'
  # Taps: "// formal-tap: wire = hierarchical.name". -nounset: the tap wire has no driver to
  # remove, but without it `connect` also cuts the wire's aliases (e.g. the compare wire
  # proc made for `if (tap)`), which would leave them free: the solver could then choose
  # them. `check -assert` fails the build on any wire used without a driver.
  local tap
  while read -r tap; do
    script+="connect -nounset -set ${tap%%=*} ${tap#*=}"$'\n'
  done < <(sed -n 's#^ *// formal-tap: *\([^ =]*\) *= *\([^ ]*\) *$#\1=\2#p' "$formal_dir/$harness.sv")
  script+="prep -top $harness"$'\n'"async2sync"$'\n'"dffunmap"$'\n'"check -assert"$'\n'
  script+="write_smt2 -wires $out/model.smt2"$'\n'
  printf '%s' "$script" >"$out/model.ys"
  yosys -q -l "$out/yosys.log" -s "$out/model.ys" >/dev/null 2>&1
}

# run_proof NAME RTL_DIR OUT_DIR [MODE DEPTH DEFINES]: prints "result method"; result PASS,
# FAIL or ERROR. FAIL leaves the counterexample in OUT_DIR/*.vcd and the solver log in
# OUT_DIR/*.log.
run_proof() {
  local name=$1 rtl_dir=$2 out=$3 mode=${4:-${p_mode[$1]}} depth=${5:-${p_depth[$1]}}
  rm -rf "$out"; mkdir -p "$out"
  if ! build_smt2 "$name" "$rtl_dir" "$out" "${6:-}"; then echo "ERROR yosys"; return; fi
  local smt=(yosys-smtbmc -s "$solver" --unroll -t "$depth")
  # BMC checks every step on its own: with a step size (-t 0:4:N) yosys-smtbmc 0.23 writes
  # a counterexample VCD that stops before the failing step. No --presat: the covers show
  # the assumptions are not vacuous.
  local bmc=(yosys-smtbmc -s "$solver" --unroll -t "$depth")
  case "$mode" in
    bmc|prove)
      if ! "${bmc[@]}" --dump-vcd "$out/trace.vcd" "$out/model.smt2" >"$out/bmc.log" 2>&1; then
        grep -q "Status: FAILED" "$out/bmc.log" && { echo "FAIL bmc"; return; }
        echo "ERROR bmc"; return
      fi
      if [ "$mode" = prove ]; then
        if ! "${smt[@]}" -i --dump-vcd "$out/induction.vcd" "$out/model.smt2" >"$out/induction.log" 2>&1; then
          grep -q "Status: FAILED" "$out/induction.log" && { echo "FAIL induction"; return; }
          echo "ERROR induction"; return
        fi
      fi
      echo "PASS $mode" ;;
    cover)
      if ! "${smt[@]}" -c --dump-vcd "$out/cover.vcd" "$out/model.smt2" >"$out/cover.log" 2>&1; then
        grep -q "Status: FAILED" "$out/cover.log" && { echo "FAIL cover"; return; }
        echo "ERROR cover"; return
      fi
      echo "PASS cover" ;;
    *) echo "ERROR mode"; return ;;
  esac
}

method_of() {
  case "${p_mode[$1]}" in
    prove) echo "k-induction" ;;
    bmc) echo "BMC" ;;
    cover) echo "cover" ;;
  esac
}

rows=()
passed=0
failed=0
record() {  # property method depth result seconds
  rows+=("$(printf '%-48s %-12s %6s  %-36s %8s' "$1" "$2" "$3" "$4" "$5")")
  if [[ "$4" == PASS* || "$4" == caught* ]]; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
}

# A proof: must pass.
check_proof() {
  local name=$1 start result
  start=$(date +%s.%N)
  result=$(run_proof "$name" "$root/rtl" "$work/$name")
  local seconds
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  local shown=${result%% *}
  [ "$shown" = PASS ] || shown="$result (see $work/$name)"
  record "$name" "$(method_of "$name")" "${p_depth[$name]}" "$shown" "$seconds"
}

# A mutation: the RTL is copied, the one line changed, and the proof must fail in its BMC
# (a real counterexample, not an induction step) on the named assertion, with a VCD.
check_mutant() {
  local mut=$1 proof=${m_proof[$1]} start seconds result verdict
  start=$(date +%s.%N)
  local out="$work/mutant_$mut" rtl_copy="$work/mutant_$mut.rtl"
  rm -rf "$rtl_copy"; mkdir -p "$rtl_copy"
  cp "$root"/rtl/*.sv "$rtl_copy/"
  local target="$rtl_copy/$(basename "${m_file[$mut]}")" text count
  text=$(<"$target")
  count=$(grep -cF -- "${m_from[$mut]}" "$target" || true)
  if [ "$count" != 1 ]; then
    verdict="NOT APPLIED: pattern found $count times in ${m_file[$mut]}"
  else
    printf '%s\n' "${text/"${m_from[$mut]}"/"${m_to[$mut]}"}" >"$target"
    # Without the induction invariants: the property itself must fail.
    result=$(run_proof "$proof" "$rtl_copy" "$out" bmc "${m_depth[$mut]}" -DFORMAL_PROPERTIES_ONLY)
    if [[ "$result" == "FAIL bmc" ]]; then
      local failing
      failing=$(sed -n 's/.*Assert failed in [^:]*: *\(.*\)$/\1/p' "$out/bmc.log" | head -n1)
      # `fails` may name alternatives, a|b: the solver reports the first assertion its
      # counterexample breaks, which can change with the netlist.
      local expected want named=0
      IFS='|' read -ra expected <<<"${m_fails[$mut]}"
      for want in "${expected[@]}"; do
        [[ -n "$want" && "$failing" == *"$want"* ]] && named=1
      done
      if [[ $named == 1 && -s "$out/trace.vcd" ]]; then
        verdict="caught: ${failing} fails"
      else
        verdict="WRONG ASSERTION: '${failing}' (expected ${m_fails[$mut]})"
      fi
    else
      verdict="NOT CAUGHT: $result (see $out)"
    fi
  fi
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  record "mutant $mut -> $proof" "BMC" "${m_depth[$mut]}" "$verdict" "$seconds"
}

if [ -n "$only" ]; then
  [ -n "${p_mode[$only]:-}" ] || { echo "formal.sh: no proof '$only'" >&2; exit 2; }
  check_proof "$only"
elif [ -n "$only_mutant" ]; then
  [ -n "${m_proof[$only_mutant]:-}" ] || { echo "formal.sh: no mutation '$only_mutant'" >&2; exit 2; }
  check_mutant "$only_mutant"
elif ((jobs > 1)); then
  # Each proof and mutation in its own process; the table is collected in list order.
  args=(--work "$work" --solver "$solver")
  ((deep)) && args+=(--deep)
  {
    for n in "${proof_names[@]}"; do echo "--only $n"; done
    if ((mutants)); then for m in "${run_mutants[@]}"; do echo "--mutant $m"; done; fi
  } | parallel -k -j "$jobs" --colsep ' ' "$0 ${args[*]} {1} {2} | sed -n '3p'" >"$work/rows.txt" || true
  while IFS= read -r row; do
    rows+=("$row")
    # A mutant's row reads "NOT CAUGHT: PASS ..." when its proof passed: a failure.
    if [[ "$row" != *"NOT CAUGHT"* && ("$row" == *" PASS "* || "$row" == *" caught: "*) ]]; then
      passed=$((passed + 1))
    else
      failed=$((failed + 1))
    fi
  done <"$work/rows.txt"
else
  for n in "${proof_names[@]}"; do check_proof "$n"; done
  if ((mutants)); then for m in "${run_mutants[@]}"; do check_mutant "$m"; done; fi
fi

printf '%-48s %-12s %6s  %-36s %8s\n' property method depth result seconds
printf '%s\n' "$(printf '%.0s-' {1..114})"
printf '%s\n' "${rows[@]}"
echo "$passed passed, $failed failed"
((failed == 0))
