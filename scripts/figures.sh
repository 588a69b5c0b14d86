#!/usr/bin/env bash
# Reruns the quick measurements and rewrites the tables of docs/ that show them, so the docs
# show what the code measures today. Each table sits between two marker lines,
#   <!-- figures:NAME -->  ...  <!-- /figures:NAME -->
# and starts with the date, the commit and the machine it was measured on.
#   scripts/figures.sh [--quick] [--build DIR] [--no-write] [SECTION...]
#   SECTION: area (docs/area.md: figures:area, figures:fmax), sim (docs/performance.md:
#   figures:sim), check (figures:check), motion (docs/motion-control.md: figures:motion),
#   firststage (figures:firststage), gaps
#   (figures:gaps-*); default all (without gaps with --quick). tests (docs/verification.md:
#   figures:test-times) runs the whole test suite label by label and only when named;
#   lockstep (docs/motion-control.md: figures:lockstep) too.
#   --quick     one placement seed instead of five, shorter benchmark runs (minutes, not a
#               quarter of an hour); the tables say which
#   --no-write  print the tables, leave docs/ alone
# Idea: what is measured is data at the top of this file. A new architecture, parameter set
# or board is one more line in a list below, and its row appears in the table. The long runs
# (the W sweep, the grid, soaks, deep proofs, fuzzing) keep their own scripts and the dated
# line in the doc that shows them.
# Needs the packages of scripts/setup.sh and a configured build (scripts/setup.sh does both);
# the targets it runs are built first.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

# ---- What is measured -----------------------------------------------------------------
# Area and Fmax (yosys synth_ice40 with rtl/fpga/synth_ice40.options, nextpnr-ice40), one
# row per line: "label | kind | parameters | part:package ...".
#   kind core:  interp_top with every port (about 210: more than any package bonds), so
#               synthesis only: LUT4, flip-flops, carry cells, block RAMs;
#   kind ice40: rtl/fpga/interp_ice40_top.sv, the interpolator with the pins a board needs
#               and the feed modulus fixed (a 12 MHz clock), synthesised once and placed on
#               each part listed (a row per part: the cells and Fmax are the part's);
#   kind board: `ncinterp bitstream --board NAME`, the whole board (UART, FIFO, stretchers,
#               status line); parameters = the board's name, part from the board.
#   parameters: NAME=VALUE ... given to chparam (the defaults: W = 16, FeedWidth 32). The
#   arch is BitSerial (1 serial, 0 parallel); CircleMode=0 is the lines-only configuration.
area_rows=(
  "interp_top, serial | core | BitSerial=1 | -"
  "interp_top, parallel | core | BitSerial=0 | -"
  "interp_top, serial, lines only | core | BitSerial=1 CircleMode=0 | -"
  "interp_ice40_top, serial | ice40 | BitSerial=1 | hx1k:tq144 up5k:sg48 hx8k:ct256"
  "interp_ice40_top, parallel | ice40 | BitSerial=0 | hx1k:tq144 up5k:sg48 hx8k:ct256"
  "interp_ice40_top, serial, lines only | ice40 | BitSerial=1 CircleMode=0 | hx1k:tq144 up5k:sg48 hx8k:ct256"
  "interp_ice40_top, parallel, lines only | ice40 | BitSerial=0 CircleMode=0 | hx1k:tq144 up5k:sg48 hx8k:ct256"
  "interp_ice40_top, serial, ramp 500 mm/s^2 | ice40 | BitSerial=1 AccelMmS2=500 | hx1k:tq144 up5k:sg48 hx8k:ct256"
  "interp_ice40_top, parallel, ramp 500 mm/s^2 | ice40 | BitSerial=0 AccelMmS2=500 | hx1k:tq144 up5k:sg48 hx8k:ct256"
  "iCEstick board (HX1K) | board | icestick | -"
  "iCEBreaker board (UP5K) | board | icebreaker | -"
)
# Per module, before flattening (LUT4 / flip-flops / carry of each module; a module with
# several instances counts once): "doc | marker | top file or - | top | parameters".
module_tables=(
  "docs/board.md | board-modules | rtl/board | board_top | board_top:BitSerial=1 board_top:CircleMode=1"
)
# Placement seeds for the Fmax table (the median is given; Fmax moves by a few percent from
# seed to seed at this utilisation).
fmax_seeds="1 2 3 4 5"
quick_fmax_seeds="1"

# Simulation speed, bench/sim/sim_bench: one run per line, "tape | sim_bench arguments".
# (--skip-icarus: Icarus Verilog 11 does not parse the RTL's immediate assertions.)
sim_runs=(
  "examples/gear.nc | --arch serial --skip-icarus"
  "examples/gear.nc | --arch parallel --skip-icarus"
  "examples/circle_r50.nc | --arch serial --engines golden,rtl,cosim,system-golden,system-rtl"
  "examples/circle_r50.nc | --arch parallel --engines golden,rtl,cosim,system-golden,system-rtl"
)
sim_seconds=2
quick_sim_seconds=0.5

# `ncinterp check` on the bundled contours: "input | ncinterp tape arguments"; each tape is
# checked with every ENGINE:ARCH of check_engines (wall time of the whole command).
check_inputs=(
  "examples/contours/circle_r50.json | --tol 0.01 --method 3"
  "examples/contours/circle_r50.json | --tol 0.01 --method 3 --arcs circle"
  "examples/contours/profile.json | --tol 0.01 --method 3"
  "examples/contours/reference_table.json | --tol 0.01 --method 3"
  "examples/contours/naca2412_selig.dat | --tol 0.01 --method 3"
  "examples/contours/part.nc | --tol 0.01 --method 3 --arcs circle"
)
check_engines="golden:serial rtl:serial golden:parallel rtl:parallel"

# Cycle time with the feed ramp (docs/motion-control.md): the check inputs' tapes played
# on the board's machine (12 MHz, the UART's 11520 frames/s, serial arch) with no ramps and
# with every block ramped from rest to rest at each acceleration limit (mm/s^2).
motion_accels="500 2000"
motion_machine="--clock-hz 12e6 --reader-cps 11520 --arch serial"
# The feed plan of the same tapes (ncinterp tape --accel): a realistic machine's limit and
# corner rule (the rapid rate is the default 5 m/min), exact stop as planned and as played
# (check, from the first block's load), continuous mode planned per look-ahead.
plan_machine="--accel 500 --junction-deviation 0.01"

# Every bundled example with the feed ramp, in lock step (section lockstep, only when named:
# about three minutes): "input | ncinterp tape arguments" (- for a tape), a glob expanded.
# Each tape plays in `cosim` on both archs without the ramp and at lockstep_accel, and
# `check --accel` holds it to the acceleration rule on both archs.
lockstep_inputs=(
  "examples/gear.nc | -"
  "examples/circle_r50.nc | -"
  "examples/contours/*.json | --tol 0.01 --method 3"
  "examples/contours/*.dat | --tol 0.01 --method 3"
  "examples/contours/part.nc | --tol 0.01 --method 3 --arcs circle"
  "examples/contours/cam/*.* | --tol 0.01 --arcs circle --tool"
)
lockstep_accel=500
lockstep_machine="--reader-cps 100000"

# Gap clocks (the player idle between blocks) against the reader and the feed, one table
# per line: "name | script and its options | reader speeds or feeds | tapes or contour and
# clocks". Tapes: examples/*.nc, bench/sim/small_arcs.nc, and two written by the first
# stage, part_arcs.nc (examples/contours/part.nc --arcs circle) and profile.nc
# (examples/contours/profile.json). Not in --quick (a few minutes of lock step).
gap_tables=(
  "gaps-reader | reader_gaps.sh --arch parallel | 1000 500 400 300 100 30 | examples/gear.nc examples/circle_r50.nc part_arcs.nc profile.nc"
  "gaps-fast-reader | reader_gaps.sh --arch parallel | 200000 50000 30000 10000 | examples/gear.nc part_arcs.nc"
  "gaps-serial-reader | reader_gaps.sh --arch serial | 4000 2000 1500 1000 500 100 30 | examples/circle_r50.nc part_arcs.nc bench/sim/small_arcs.nc"
  "gaps-serial-fast-reader | reader_gaps.sh --arch serial | 200000 50000 30000 10000 | examples/gear.nc part_arcs.nc"
  "gaps-serial-12mhz | reader_gaps.sh --arch serial --clock-hz 12000000 | 4000 2000 1500 1000 500 | bench/sim/small_arcs.nc"
  "gaps-board-clock | reader_gaps.sh --arch parallel --clock-hz 12000000 | 200000 30000 1000 | examples/gear.nc"
  "gaps-serial-board-clock | reader_gaps.sh --arch serial --clock-hz 12000000 | 200000 30000 1000 | examples/gear.nc"
  "gaps-feed | dry_run_gaps.sh | 1000 2000 5000 10000 20000 | examples/contours/circle_r50.json 1000000 12000000"
)

# Test time per ctest label (section tests, never run by default: it runs the whole
# suite, label by label, with as many jobs as cores; scripts/test.sh runs them all):
# "label | ctest selection".
test_labels=(
  "unit | -L unit"
  "integration | -L integration"
  "formal | -L formal"
)

# First-stage speed: bench/firststage/firststage_bench --section speed.
firststage_repeats=5
quick_firststage_repeats=1

# ---- Options ----------------------------------------------------------------------------
quick=0 write=1 build=$root/build sections=()
while (($#)); do
  case $1 in
    --quick) quick=1 ;;
    --no-write) write=0 ;;
    --build) build=$2; shift ;;
    area | sim | check | motion | lockstep | firststage | gaps | tests) sections+=("$1") ;;
    -h | --help) sed -n '2,20p' "$0"; exit 0 ;;
    *) echo "figures.sh: unknown argument '$1' (--help)" >&2; exit 1 ;;
  esac
  shift
done
if ((!${#sections[@]})); then
  sections=(area sim check motion firststage)
  ((quick)) || sections+=(gaps)
fi
if ((quick)); then
  fmax_seeds=$quick_fmax_seeds sim_seconds=$quick_sim_seconds
  firststage_repeats=$quick_firststage_repeats
fi
if [ ! -f "$build/CMakeCache.txt" ] || grep -qE '^NCINTERP_(BENCH|TESTS):BOOL=OFF' "$build/CMakeCache.txt"; then
  echo "figures.sh: no full build in $build (run scripts/setup.sh first: the demo's build has no benchmarks)" >&2
  exit 1
fi
work=$(mktemp -d /tmp/ncinterp-figures.XXXXXX)
trap 'rm -rf "$work"' EXIT
cd "$root"

trim() { local s=$1; s=${s#"${s%%[![:space:]]*}"}; printf '%s' "${s%"${s##*[![:space:]]}"}"; }
field() { trim "$(cut -d'|' -f"$2" <<<"$1")"; }
# A value of a JSON report (jq path without the dot), printf-formatted if a format is given.
json_get() {
  local v
  v=$(jq -r ".$2" "$1")
  if (($# > 2)); then printf "$3" "$v"; else printf '%s' "$v"; fi
}

# The first line of every table: when, at which commit, on what.
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo "unknown")
git -C "$root" diff --quiet HEAD 2>/dev/null || commit="$commit with local changes"
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
stamp() {
  printf 'Measured %s at commit %s by `scripts/figures.sh%s %s` on %s cores (%s).\n' \
    "$(date +%Y-%m-%d)" "$commit" "$( ((quick)) && echo ' --quick')" "$1" "$(nproc)" "$cpu"
}

# Replaces the lines between <!-- figures:NAME --> and <!-- /figures:NAME --> in FILE.
put() {
  local file=$1 name=$2 table=$3
  if ((!write)); then
    printf '\n== %s (%s)\n' "$name" "$file"; cat "$table"; return
  fi
  if ! grep -qxF "<!-- figures:$name -->" "$file" || ! grep -qxF "<!-- /figures:$name -->" "$file"; then
    echo "figures.sh: $file has no markers for figures:$name" >&2; exit 1
  fi
  awk -v first="<!-- figures:$name -->" -v last="<!-- /figures:$name -->" -v table="$table" '
    $0 == first { print; while ((getline line < table) > 0) print line; skip = 1; next }
    $0 == last  { skip = 0 }
    !skip       { print }' "$file" >"$work/doc.tmp"
  cat "$work/doc.tmp" >"$file"
  echo "figures.sh: $file, figures:$name"
}

build_targets() { cmake --build "$build" --target "$@" >/dev/null; }

rtl_sources() { echo rtl/0_interp_pkg.sv $(ls rtl/*.sv | grep -v 0_interp_pkg); }
synth_options=$(grep -v '^#' rtl/fpga/synth_ice40.options)

# yosys `stat` of a log: LUT4 / FF / carry / block RAM of the last (flattened) statistics.
stat_of() {
  awk '/Number of cells:/ { lut = ff = carry = ram = 0 }
       $1 == "SB_LUT4" { lut = $2 } $1 ~ /^SB_DFF/ { ff += $2 } $1 == "SB_CARRY" { carry = $2 }
       $1 ~ /^SB_RAM40_4K/ { ram += $2 }
       END { printf "%d | %d | %d | %d", lut, ff, carry, ram }' "$1"
}
# nextpnr-ice40 log: "cells of part" and the Fmax of the design's clock.
# Both print nothing (and succeed) for a log of a design that did not place.
cells_of() { sed -nE 's/.*ICESTORM_LC: *([0-9]+)\/ *([0-9]+).*/\1 of \2/p' "$1" | head -1; }
fmax_of() { { grep "Max frequency for clock" "$1" || true; } | tail -1 | sed -E 's/.*: ([0-9.]+) MHz.*/\1/'; }
chparams() {
  local top=$1 p out=""
  for p in $2; do out+="chparam -set ${p%%=*} ${p#*=} $top; "; done
  printf '%s' "$out"
}

section_area() {
  local area=$work/area.md fmax=$work/fmax.md row label kind params part dir seeds_done
  build_targets ncinterp
  {
    stamp area
    echo "yosys $(yosys -V | awk '{print $2}'), nextpnr-ice40 $(nextpnr-ice40 --version 2>&1 | sed -n 's/.*(Version \(.*\))/\1/p' | head -1); \`synth_ice40 $synth_options\`; W = 16. Placed cells and Fmax: placement seed 1."
    echo
    echo "| design | LUT4 | flip-flops | carry | block RAM | logic cells placed | Fmax MHz (seed 1) |"
    echo "|---|---:|---:|---:|---:|---:|---:|"
  } >"$area"
  {
    stamp area
    echo "Placement seeds $fmax_seeds; the design's clock, nextpnr's \"Max frequency\" after routing."
    echo
    echo "| design | part | Fmax per seed (MHz) | median |"
    echo "|---|---|---|---:|"
  } >"$fmax"
  for row in "${area_rows[@]}"; do
    label=$(field "$row" 1) kind=$(field "$row" 2) params=$(field "$row" 3) part=$(field "$row" 4)
    dir=$work/area/${label//[^A-Za-z0-9]/_}
    mkdir -p "$dir"
    echo "figures.sh: area: $label" >&2
    case $kind in
      core)
        yosys -q -l "$dir/yosys.log" -p "read_verilog -sv $(rtl_sources); $(chparams interp_top "$params")
          synth_ice40 $synth_options -top interp_top; stat" >/dev/null
        echo "| $label | $(stat_of "$dir/yosys.log") | - (every port) | - |" >>"$area" ;;
      ice40)
        yosys -q -l "$dir/yosys.log" -p "read_verilog -sv $(rtl_sources) rtl/fpga/interp_ice40_top.sv;
          $(chparams interp_ice40_top "$params") synth_ice40 $synth_options -top interp_ice40_top -json $dir/top.json; stat" >/dev/null
        local one log first=${fmax_seeds%% *} cells median
        for one in $part; do
          local fmaxes=() seed
          for seed in $fmax_seeds; do
            log=$dir/nextpnr-${one%%:*}-$seed.log
            nextpnr-ice40 "--${one%%:*}" --package "${one#*:}" --json "$dir/top.json" \
              --pcf-allow-unconstrained --seed "$seed" --freq 100 --timing-allow-fail >"$log" 2>&1 || true
            fmaxes+=("$(fmax_of "$log")")
            # A design that does not fit the part does not fit with any seed.
            grep -q "Max frequency" "$log" || break
          done
          log=$dir/nextpnr-${one%%:*}-$first.log
          cells=$(cells_of "$log")
          if [ -z "$cells" ]; then
            cells="does not place: $({ grep -m1 -iE 'error|unable' "$log" || true; } | cut -c1-80)"
          elif ! grep -q "Max frequency" "$log"; then
            cells="$cells: does not fit"
          fi
          echo "| $label | $(stat_of "$dir/yosys.log") | $cells (${one%%:*}) | ${fmaxes[0]:--} |" >>"$area"
          median=$(printf '%s\n' "${fmaxes[@]}" | { grep . || true; } | sort -n | awk '{a[NR]=$0} END {if (NR) print a[int((NR+1)/2)]}')
          local per_seed
          per_seed=$(IFS=,; echo "${fmaxes[*]}" | sed 's/,/, /g')
          echo "| $label | ${one%%:*} | ${per_seed:-does not fit} | ${median:--} |" >>"$fmax"
        done ;;
      board)
        local out status=0 cells board_fmax
        out=$("$build/ncinterp" bitstream --board "$params" -o "$dir/$params.bin" 2>&1) || status=$?
        local logs=$dir/$params.bin.build
        cells=$(cells_of "$logs/nextpnr_seed1.log" 2>/dev/null || true)
        board_fmax=$(fmax_of "$logs/nextpnr_seed1.log" 2>/dev/null || true)
        if ((status == 2)); then
          cells=$(sed -nE 's/.*needs ([0-9]+) logic cells, the ([A-Z0-9]+) has ([0-9]+).*/\1 asked, \3 on the \2: does not fit/p' <<<"$out" | head -1)
          [ -n "$cells" ] || cells=$(head -1 <<<"$out")
        elif ((status != 0)); then
          cells="bitstream failed: $(head -1 <<<"$out")"
        fi
        echo "| $label | $(stat_of "$logs/yosys.log") | ${cells:--} | ${board_fmax:--} |" >>"$area" ;;
      *) echo "figures.sh: unknown kind '$kind' in area_rows" >&2; exit 1 ;;
    esac
  done
  put docs/area.md area "$area"
  put docs/area.md fmax "$fmax"
  local doc marker files top params p
  for row in "${module_tables[@]}"; do
    doc=$(field "$row" 1) marker=$(field "$row" 2) files=$(field "$row" 3) top=$(field "$row" 4)
    params=$(field "$row" 5)
    echo "figures.sh: area: modules of $top" >&2
    local extra="" include="" chp=""
    if [ "$files" != "-" ]; then extra=$(ls "$files"/*.sv | tr '\n' ' '); include="-I$files"; fi
    for p in $params; do  # MODULE:NAME=VALUE
      local mod=${p%%:*} kv=${p#*:}
      chp+="chparam -set ${kv%%=*} ${kv#*=} $mod; "
    done
    yosys -q -l "$work/modules.log" -p "read_verilog -sv $include $(rtl_sources) $extra; $chp
      synth_ice40 $synth_options -noflatten -top $top; stat" >/dev/null
    {
      stamp area
      echo
      echo "\`synth_ice40 -noflatten -top $top\` ($params), per module (a module with several instances counts once):"
      echo
      echo "| module | LUT4 | flip-flops | carry |"
      echo "|---|---:|---:|---:|"
      # yosys prints every module's statistics twice; each printing restarts the sums.
      awk '
        /^=== / { mod = $2; sub(/^\$paramod\$[0-9a-f]+\\/, "", mod); sub(/^\$paramod\\/, "", mod); sub(/\\.*/, "", mod); ff[mod] = 0 }
        /^=== design hierarchy ===/ { mod = "" }
        mod != "" && $1 == "SB_LUT4" { lut[mod] = $2 }
        mod != "" && $1 ~ /^SB_DFF/ { ff[mod] += $2 }
        mod != "" && $1 == "SB_CARRY" { carry[mod] = $2 }
        END { for (m in lut) if (m != "") printf "| %s | %d | %d | %d |\n", m, lut[m], ff[m], carry[m] }
      ' "$work/modules.log" | sort
    } >"$work/modules.md"
    put "$doc" "$marker" "$work/modules.md"
  done
}

section_sim() {
  local out=$work/sim.md run tape args seconds=$sim_seconds
  build_targets sim_bench ncinterp
  { stamp sim; echo; } >"$out"
  for run in "${sim_runs[@]}"; do
    tape=$(field "$run" 1) args=$(field "$run" 2)
    echo "figures.sh: sim: $tape $args" >&2
    local extra=()
    ((quick)) && extra=(--icarus-cycles 200000)
    # shellcheck disable=SC2086
    "$build/bench/sim/sim_bench" --tape "$tape" --seconds "$seconds" "${extra[@]}" $args >"$work/sim.out"
    {
      echo "\`build/bench/sim/sim_bench --tape $tape $args\` ($(head -1 "$work/sim.out" | sed 's/^tape [^:]*: //')):"
      echo
      grep '^|' "$work/sim.out"
      echo
    } >>"$out"
  done
  build_targets verilator_floor
  echo "\`build/bench/sim/verilator_floor\`: $("$build/bench/sim/verilator_floor" | tail -1)." >>"$out"
  put docs/performance.md sim "$out"
}

section_check() {
  local out=$work/check.md row input args engine
  build_targets ncinterp
  {
    stamp check
    echo
    printf '| input | `ncinterp tape` options | blocks | clocks |'
    for engine in $check_engines; do printf ' %s, %s: s |' "${engine%%:*}" "${engine#*:}"; done
    printf '\n|---|---|---:|---:|'
    for engine in $check_engines; do printf -- '---:|'; done
    echo
  } >"$out"
  for row in "${check_inputs[@]}"; do
    input=$(field "$row" 1) args=$(field "$row" 2)
    echo "figures.sh: check: $input $args" >&2
    # shellcheck disable=SC2086
    "$build/ncinterp" tape "$input" -o "$work/c.tape" $args >/dev/null 2>&1
    local line="| $(basename "$input") | \`$args\` |" times="" blocks="" clocks=""
    for engine in $check_engines; do
      local start end
      start=$(date +%s.%N)
      "$build/ncinterp" check "$work/c.tape" --contour "$input" --engine "${engine%%:*}" \
        --arch "${engine#*:}" --report "$work/c.json" >/dev/null
      end=$(date +%s.%N)
      times+=" $(awk -v a="$start" -v b="$end" 'BEGIN {printf "%.2f", b - a}') |"
      blocks=$(sed -nE 's/.*"blocks": *([0-9]+).*/\1/p' "$work/c.json" | head -1)
      clocks=$(sed -nE 's/.*"cycles": *([0-9]+).*/\1/p' "$work/c.json" | head -1)
    done
    echo "$line ${blocks:-?} | ${clocks:-?} |$times" >>"$out"
  done
  put docs/performance.md check "$out"
}

section_motion() {
  local out=$work/motion.md plan=$work/plan.md row input args accel
  build_targets ncinterp
  {
    stamp motion
    echo
    echo "\`ncinterp tape INPUT ARGS $plan_machine\` (continuous mode is planned only: G64 is not built)."
    echo
    echo '| input | blocks | no ramp: s | exact stop: s | played: s | continuous, 1 block read ahead: s | 2 blocks: s | 4 blocks: s | the whole tape: s |'
    echo '|---|---:|---:|---:|---:|---:|---:|---:|---:|'
  } >"$plan"
  {
    stamp motion
    echo
    printf '| input | blocks | no ramps: s |'
    for accel in $motion_accels; do printf ' %s mm/s^2: s | max X, Y: mm/s^2 |' "$accel"; done
    printf '\n|---|---:|---:|'
    for accel in $motion_accels; do printf -- '---:|---:|'; done
    echo
  } >"$out"
  for row in "${check_inputs[@]}"; do
    input=$(field "$row" 1) args=$(field "$row" 2)
    echo "figures.sh: motion: $input $args" >&2
    # shellcheck disable=SC2086
    "$build/ncinterp" tape "$input" -o "$work/m.tape" $args $plan_machine --report "$work/p.json" >/dev/null 2>&1
    local line blocks
    # shellcheck disable=SC2086
    "$build/ncinterp" check "$work/m.tape" --contour "$input" $motion_machine --report "$work/m.json" >/dev/null
    blocks=$(json_get "$work/m.json" blocks)
    line="| $(basename "$input") \`$args\` | $blocks | $(json_get "$work/m.json" cycle_seconds '%.2f') |"
    for accel in $motion_accels; do
      # shellcheck disable=SC2086
      "$build/ncinterp" check "$work/m.tape" --contour "$input" $motion_machine --accel "$accel" \
        --report "$work/m.json" >/dev/null
      line+=" $(json_get "$work/m.json" cycle_seconds '%.2f') | $(json_get "$work/m.json" acceleration.max_mm_s2.x '%.0f'), $(json_get "$work/m.json" acceleration.max_mm_s2.y '%.0f') |"
      [[ $accel == 500 ]] && cp "$work/m.json" "$work/m500.json"
    done
    echo "$line" >>"$out"
    line="| $(basename "$input") \`$args\` | $blocks | $(json_get "$work/p.json" feed_plan.programmed_seconds '%.2f') |"
    line+=" $(json_get "$work/p.json" feed_plan.exact_stop_seconds '%.2f') | $(json_get "$work/m500.json" feed_plan.played_seconds '%.2f') |"
    local k
    for k in 0 1 2 3; do line+=" $(json_get "$work/p.json" "feed_plan.continuous_planned_only[$k].seconds" '%.2f') |"; done
    echo "$line" >>"$plan"
  done
  put docs/motion-control.md motion "$out"
  put docs/motion-control.md feed-plan "$plan"
}

section_lockstep() {
  local out=$work/lockstep.md row glob args input tape arch failed=0
  build_targets ncinterp
  {
    stamp lockstep
    echo
    echo "\`ncinterp cosim TAPE $lockstep_machine --arch ARCH\` without the ramp and with \`--accel $lockstep_accel\`; \`ncinterp check TAPE $lockstep_machine --arch ARCH --accel $lockstep_accel\`."
    echo
    echo "| input | tape arguments | blocks | serial: s, no ramp | ramped | parallel: s, no ramp | ramped | RTL = golden, same pulses and end | acceleration rule: worst of limit + allowance, serial, parallel |"
    echo "|---|---|---:|---:|---:|---:|---:|---|---|"
  } >"$out"
  for row in "${lockstep_inputs[@]}"; do
    glob=$(field "$row" 1) args=$(field "$row" 2)
    for input in $glob; do
      echo "figures.sh: lockstep: $input" >&2
      tape=$input
      if [[ $args != - ]]; then
        tape=$work/l.tape
        # shellcheck disable=SC2086
        "$build/ncinterp" tape "$input" -o "$tape" $args >/dev/null 2>&1
      fi
      local times="" worst="" same=yes first="" ends taped="(a tape)"
      [[ $args == - ]] || taped="\`$args\`"
      for arch in serial parallel; do
        # shellcheck disable=SC2086
        "$build/ncinterp" cosim "$tape" $lockstep_machine --arch $arch --report "$work/plain.json" >/dev/null || true
        # shellcheck disable=SC2086
        "$build/ncinterp" cosim "$tape" $lockstep_machine --arch $arch --accel $lockstep_accel \
          --report "$work/ramped.json" >/dev/null || true
        # Every run ends done with the RTL matching the golden model, and all four give the
        # same pulses per axis and direction and the same end.
        for run in plain ramped; do
          ends=$(jq -c '[.status, .end, .pulses, .final_position_blu]' "$work/$run.json")
          first=${first:-$ends}
          [[ $ends == '["match","done",'* && $ends == "$first" ]] || same=NO
          times+=" $(jq -r '.cycles / .clock_hz' "$work/$run.json" | xargs printf '%.2f') |"
        done
        # shellcheck disable=SC2086
        "$build/ncinterp" check "$tape" $lockstep_machine --arch $arch --accel $lockstep_accel \
          --report "$work/c.json" >/dev/null || same=NO
        worst+="${worst:+, }$(json_get "$work/c.json" acceleration.worst_of_limit_and_allowance '%.3f')"
      done
      [[ $same == yes ]] || failed=1
      echo "| $(basename "$input") | $taped | $(json_get "$work/plain.json" blocks) |$times $same | $worst |" >>"$out"
    done
  done
  put docs/motion-control.md lockstep "$out"
  ((!failed)) || { echo "figures.sh: lockstep: a run differs (the table's NO rows)" >&2; exit 1; }
}

section_firststage() {
  local out=$work/firststage.md
  build_targets firststage_bench
  echo "figures.sh: firststage" >&2
  "$build/bench/firststage/firststage_bench" --section speed --repeats "$firststage_repeats" \
    >"$work/fs.out"
  {
    stamp firststage
    echo
    grep '^|' "$work/fs.out"
  } >"$out"
  put docs/performance.md firststage "$out"
}

section_gaps() {
  local row name script speeds tapes t
  build_targets ncinterp
  command -v jq >/dev/null || { echo "figures.sh: gaps needs jq (scripts/setup.sh)" >&2; exit 1; }
  "$build/ncinterp" tape examples/contours/part.nc --arcs circle -o "$work/part_arcs.nc" >/dev/null 2>&1
  "$build/ncinterp" tape examples/contours/profile.json -o "$work/profile.nc" >/dev/null 2>&1
  for row in "${gap_tables[@]}"; do
    name=$(field "$row" 1) script=$(field "$row" 2) speeds=$(field "$row" 3) tapes=$(field "$row" 4)
    echo "figures.sh: $name" >&2
    local args=() shown=()
    for t in $tapes; do
      case $t in
        part_arcs.nc | profile.nc) args+=("$work/$t") ;;
        *) args+=("$t") ;;
      esac
      shown+=("$t")
    done
    local cmd=(bash "bench/sim/${script%% *}")
    # shellcheck disable=SC2206
    local opts=(${script#"${script%% *}"})
    {
      stamp gaps
      if [[ $script == dry_run_gaps.sh* ]]; then
        local contour=${args[0]} clocks="${args[*]:1}"
        echo "\`bench/sim/$script build/ncinterp $contour \"$speeds\" \"$clocks\"\`:"
        echo
        "${cmd[@]}" "${opts[@]}" "$build/ncinterp" "$contour" "$speeds" "$clocks"
      else
        echo "\`bench/sim/$script build/ncinterp \"$speeds\" ${shown[*]}\`:"
        echo
        "${cmd[@]}" "${opts[@]}" "$build/ncinterp" "$speeds" "${args[@]}"
      fi
    } >"$work/$name.md"
    put docs/performance.md "$name" "$work/$name.md"
  done
}

section_tests() {
  local out=$work/tests.md row label selection
  build_targets all
  {
    stamp tests
    echo
    echo "| label | tests | failed | wall s (\`ctest -j$(nproc)\`) |"
    echo "|---|---:|---:|---:|"
  } >"$out"
  for row in "${test_labels[@]}"; do
    label=$(field "$row" 1) selection=$(field "$row" 2)
    echo "figures.sh: tests: $label" >&2
    local start end status=0
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    (cd "$build" && ctest $selection -j"$(nproc)" --timeout 900) >"$work/ctest.log" 2>&1 || status=$?
    end=$(date +%s.%N)
    local total failed
    total=$(sed -nE 's/.*tests passed, ([0-9]+) tests failed out of ([0-9]+)/\2/p' "$work/ctest.log")
    failed=$(sed -nE 's/.*tests passed, ([0-9]+) tests failed out of ([0-9]+)/\1/p' "$work/ctest.log")
    echo "| $label | ${total:-0} | ${failed:-0} | $(awk -v a="$start" -v b="$end" 'BEGIN {printf "%.0f", b - a}') |" >>"$out"
  done
  put docs/verification.md test-times "$out"
}

for s in "${sections[@]}"; do
  "section_$s"
done
