#!/usr/bin/env bash
# Sets up (every package, the whole build) and runs every test through ctest: what CI runs.
# Arguments go to ctest, e.g. `scripts/test.sh -L unit` for the quick ones (the labels:
# docs/verification.md, "Test labels").
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
cd "$root/build"
ctest --output-on-failure --parallel "$(nproc)" --timeout 900 "$@"
