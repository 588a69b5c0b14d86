#!/usr/bin/env bash
# Sets up (installs packages, builds) and runs every test through ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
cd "$root/build"
ctest --output-on-failure --parallel "$(nproc)" --timeout 900
