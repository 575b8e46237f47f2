#!/usr/bin/env bash
# Quick start, command 2: build gapfem and run the whole test suite (unit, verification,
# regression and CalculiX comparisons). Exits non-zero when any test fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
ctest --preset release --timeout 900
