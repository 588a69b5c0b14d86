#!/usr/bin/env bash
# Installs every dependency from Debian packages (bookworm) and configures the build.
# Idea: one script a newcomer runs on a fresh machine; it is idempotent, so the README's
# two commands can both start with it. Run as root or with sudo available.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config git
  verilator libsystemc-dev            # RTL simulation, system model
  libgtest-dev libgmock-dev           # tests
  libcli11-dev nlohmann-json3-dev     # command line, JSON reports
  libboost-dev                        # Boost.Geometry's R-tree (the checker's contour distance)
  libplplot-dev                       # SVG plots (PLplot's svg driver)
  yosys nextpnr-ice40 fpga-icestorm   # synthesis, area and Fmax
  z3 boolector                        # SMT solvers of the formal proofs (scripts/formal.sh)
  iverilog                            # reference simulator for the benchmark
  gtkwave xvfb x11-apps               # waves; the screenshot of waves/interp.gtkw (xwd)
  parallel                            # ncinterp sweep's local runner (GNU parallel)
  jq                                  # bench/sim/reader_gaps.sh reads cosim reports
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo_cmd=""; [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -q
  $sudo_cmd apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
root=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" --parallel "$(nproc)"
