#!/usr/bin/env bash
# Writes the outputs that a refactoring must leave byte-identical into one folder:
# the tape and its report for every bundled contour x Tamm method 1-3 x {no cutter, a 2 mm
# cutter on the left} x {--arcs chords, --arcs circle}, and the play and check reports of
# the bundled tapes on both engines.
# Idea: run it with the binary before and after a change and `diff -r` the two folders;
# an empty diff is the proof that behaviour did not move. Outputs are named relative to the
# folder, and what measures the machine rather than the program (wall-clock times, clocks
# per second) is dropped, so two runs of the same program give the same bytes.
#   scripts/golden_outputs.sh build/ncinterp /tmp/before
set -uo pipefail
exe=$(realpath "${1:?usage: golden_outputs.sh NCINTERP OUTDIR}")
out=${2:?usage: golden_outputs.sh NCINTERP OUTDIR}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
out=$(realpath "$out")
cd "$root"
for input in examples/contours/*.json examples/contours/*.dat examples/contours/*.nc; do
  name=$(basename "$input")
  for method in 1 2 3; do
    for cutter in 0 2; do
      for arcs in chords circle; do
        tag="$name.m$method.c$cutter.$arcs"
        # A refused combination is an output too: its message and exit code are compared.
        "$exe" tape "$input" -o "$out/$tag.tape" --method "$method" --cutter-radius "$cutter" \
          --arcs "$arcs" --report "$out/$tag.json" >"$out/$tag.stdout" 2>"$out/$tag.stderr"
        echo "exit $?" >>"$out/$tag.stdout"
      done
    done
  done
done
for tape in examples/*.nc; do
  name=$(basename "$tape")
  for engine in golden rtl; do
    "$exe" play "$tape" --engine "$engine" --report "$out/$name.play.$engine.json" \
      >"$out/$name.play.$engine.stdout" 2>&1
    echo "exit $?" >>"$out/$name.play.$engine.stdout"
  done
  "$exe" cosim "$tape" --report "$out/$name.cosim.json" >"$out/$name.cosim.stdout" 2>&1
  echo "exit $?" >>"$out/$name.cosim.stdout"
done
# Machine-dependent figures: the JSON "time_s" object, wall seconds, clocks per second.
for f in "$out"/*.json "$out"/*.stdout; do
  [ -e "$f" ] || continue
  sed -i -E -e '/"time_s": \{/,/\}/d' -e '/"(wall_seconds|cycles_per_second)"/d' \
    -e 's/; [0-9.]+ M cycles\/s//' -e "s#$out/##g" "$f"
done
echo "outputs in $out: $(ls "$out" | wc -l) files"
