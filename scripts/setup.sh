#!/usr/bin/env bash
# Installs the Debian packages (bookworm) and builds. Idempotent, so the README's two
# commands can both start with it. Run as root or with sudo available.
#   setup.sh          every package, the whole build (every test, benchmark and tool)
#   setup.sh --demo   only what the demo needs, and only the `ncinterp` executable; a build
#                     directory configured for the first time gets no tests, no benchmarks
#                     and no SVG plots (the CMake options NCINTERP_TESTS, NCINTERP_BENCH and
#                     NCINTERP_PLOT, which scripts/test.sh turns back on): PLplot's package
#                     alone brings some 190 packages, more than the rest of the demo's
set -euo pipefail
demo=0
[[ ${1:-} == --demo ]] && demo=1
# What `ncinterp` needs to build and run (the demo).
packages=(
  build-essential cmake ninja-build pkg-config
  verilator libsystemc-dev            # RTL simulation, system model
  libcli11-dev nlohmann-json3-dev     # command line, JSON reports
  libboost-dev                        # Boost.Geometry's R-tree (the checker's contour distance)
)
if ((!demo)); then
  packages+=(
    git
    libplplot-dev                       # SVG plots (PLplot's svg driver)
    libgtest-dev libgmock-dev           # tests
    yosys nextpnr-ice40 fpga-icestorm   # synthesis, area and Fmax
    z3 boolector                        # SMT solvers of the formal proofs (scripts/formal.sh)
    iverilog                            # reference simulator for the benchmark
    gtkwave xvfb x11-apps               # waves; the screenshot of waves/interp.gtkw (xwd)
    parallel                            # ncinterp sweep's local runner (GNU parallel)
    jq                                  # bench/sim/reader_gaps.sh reads cosim reports
  )
fi
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
build=$root/build
if ((demo)); then
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DNCINTERP_TESTS=OFF -DNCINTERP_BENCH=OFF -DNCINTERP_PLOT=OFF >/dev/null
  fi
  cmake --build "$build" --parallel "$(nproc)" --target ncinterp
else
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DNCINTERP_TESTS=ON -DNCINTERP_BENCH=ON -DNCINTERP_PLOT=ON >/dev/null
  cmake --build "$build" --parallel "$(nproc)"
fi
