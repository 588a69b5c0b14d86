#!/usr/bin/env bash
# Runs one libFuzzer target (tests/fuzz/fuzz_TARGET.cpp) for SECONDS, ASan + UBSan, seeded
# with its checked-in corpus (tests/fuzz/corpus/TARGET/, the examples among it), and prints
# executions, coverage (libFuzzer's cov/ft) and findings (docs/verification.md, "Fuzzing").
# Usage: scripts/fuzz.sh TARGET SECONDS [more libFuzzer options]
#   TARGET: tape_lockstep gcode json_contour reference_table airfoil
# Builds build-fuzz/ (clang++, -DNCINTERP_FUZZ=ON) when needed; the corpus grows in
# build-fuzz/corpus/TARGET/, crashes, timeouts and leaks go to build-fuzz/findings/TARGET/,
# the whole libFuzzer output to build-fuzz/fuzz-TARGET.log. Exit 0: no finding.
# Runs with nice: the machine is shared.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
targets="tape_lockstep gcode json_contour reference_table airfoil"
if [[ $# -lt 2 || ! " $targets " =~ " $1 " || ! $2 =~ ^[0-9]+$ ]]; then
  echo "usage: $0 TARGET SECONDS [libFuzzer options]; TARGET: $targets" >&2
  exit 1
fi
target=$1 seconds=$2
shift 2
build=${NCINTERP_FUZZ_BUILD:-$root/build-fuzz}

if ! command -v clang++ >/dev/null; then
  echo "$0: needs clang++ with libFuzzer: apt-get install clang libclang-rt-14-dev" >&2
  exit 1
fi
if ! echo 'extern "C" int LLVMFuzzerTestOneInput(const char*, long) { return 0; }' |
    clang++ -x c++ -fsanitize=fuzzer,address,undefined - -o /dev/null 2>/dev/null; then
  echo "$0: clang++ cannot link libFuzzer: apt-get install libclang-rt-14-dev" >&2
  exit 1
fi

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
mkdir -p "$build"
# One build at a time: several fuzzers may be started together.
(
  flock 9
  # Configured every time (quick when nothing changed): a build.ninja made before an RTL or
  # source file was deleted names that file, and ninja alone cannot regenerate past it.
  CCACHE_BASEDIR=$root cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER=clang++ -DNCINTERP_FUZZ=ON "${launcher[@]}" >/dev/null
  CCACHE_BASEDIR=$root nice cmake --build "$build" --target "fuzz_$target" --parallel 2
) 9>"$build/.build.lock"

corpus=$build/corpus/$target findings=$build/findings/$target
mkdir -p "$corpus" "$findings"
# -timeout is wall time per input: 120 s, because on a shared machine a niced fuzzer can be
# starved for tens of seconds (a 0.7 s input once "timed out" at 30 s at load average 6).
options=(-max_total_time="$seconds" -timeout=120 -rss_limit_mb=2048 -print_final_stats=1
         -artifact_prefix="$findings/")
# The tape is text with parity in bit 7: a dictionary of its words as frames.
if [[ $target == tape_lockstep ]]; then
  python3 - "$build/tape.dict" <<'PY'
import sys
words = ["%\n", "N1 ", "G01 ", "G02 ", "G03 ", "G17 G21 G91 G93\n", "X", "Y", "I", "J",
         "F", ".000", "-", "M02\n", "M30\n", "\n", "(", ")", " ", "\r", "65.535"]
def frames(w):
    return "".join("\\x%02X" % (ord(c) | (0x80 if bin(ord(c)).count("1") % 2 else 0)) for c in w)
with open(sys.argv[1], "w") as f:
    for w in words:
        f.write('"%s"\n' % frames(w))
PY
  options+=(-dict="$build/tape.dict")
fi
log=$build/fuzz-$target.log
# Findings: crash-, leak-, timeout- and oom- inputs. libFuzzer also saves slow-unit- inputs
# (over 10 s, -report_slow_units): listed, not counted (the timeout is what makes a hang).
count_findings() { find "$findings" -type f ! -name 'slow-unit-*' | wc -l; }
before=$(count_findings)
echo "fuzzing $target for $seconds s (log: $log)"
set +e
# The CPU time next to the wall time: on a shared machine the fuzzer gets less than its hour.
TIMEFORMAT='%U %S'
{ time ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1} \
    nice "$build/tests/fuzz/fuzz_$target" "${options[@]}" "$@" "$corpus" "$root/tests/fuzz/corpus/$target" \
    >"$log" 2>&1; } 2>"$build/fuzz-$target.cpu"
status=$?
set -e
after=$(count_findings)
slow=$(find "$findings" -type f -name 'slow-unit-*' | wc -l)
last=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
execs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' || echo "?")
echo "target:     $target"
echo "time:       $(grep -oE 'Done [0-9]+ runs in [0-9]+ second' "$log" || echo "stopped (see log)")"
echo "cpu:        $(awk '{printf "%.0f s (user + system)", $1 + $2}' "$build/fuzz-$target.cpu")"
echo "executions: $execs"
echo "coverage:   $(echo "$last" | grep -oE 'cov: [0-9]+ ft: [0-9]+' || echo '?')"
echo "corpus:     $(echo "$last" | grep -oE 'corp: [0-9]+/[0-9]+[a-zA-Z]*' || echo '?')"
echo "findings:   $((after - before)) new in $findings (libFuzzer exit $status)"
echo "slow units: $slow in $findings (inputs over 10 s; not findings)"
grep -E 'FUZZ FINDING|ERROR: AddressSanitizer|runtime error|ERROR: libFuzzer|SUMMARY' "$log" | head -5 || true
[[ $status -eq 0 && $after -eq $before ]]
