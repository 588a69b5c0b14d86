#!/bin/bash
# Screenshot of GTKWave opening waves/example.vcd with waves/interp.gtkw, as a user sees it
# (docs/waves-gtkwave.png). Run under a virtual X server:
#   scripts/demo.sh            # writes waves/example.vcd
#   xvfb-run -a -s "-screen 0 1600x1000x24" scripts/gtkwave_screenshot.sh OUT.xwd
# (xwd is in Debian's x11-apps; convert the .xwd to PNG with any image tool.)
set -euo pipefail
out=${1:?usage: gtkwave_screenshot.sh OUT.xwd}
out=$(realpath -m "$out")
cd "$(dirname "$0")/.."
gtkwave waves/example.vcd waves/interp.gtkw >/dev/null 2>&1 &
pid=$!
sleep 12  # load the VCD and draw
xwd -root -silent >"$out"
kill "$pid"
