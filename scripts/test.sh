#!/usr/bin/env bash
# Quick start, command 2 (and CI, .ci/run): build gapfem with clang under AddressSanitizer and
# UndefinedBehaviorSanitizer (the "sanitize" preset), run the whole test suite (unit,
# verification, regression, the bad-input corpus and the CalculiX comparisons) in that build,
# then fuzz the deck reader and the model builder for a bounded time (fuzz/run.sh). First, the
# layers of docs/architecture.md are checked from the includes (scripts/check_layers.py) and no
# function in src/ is over 120 lines (scripts/check_function_length.py).
# Exits non-zero when any test fails or a fuzzer finds anything.
# The optimised build of command 1 runs the same suite with: ctest --preset release
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
python3 scripts/check_layers.py
python3 scripts/check_function_length.py
cmake --preset sanitize >/dev/null
cmake --build --preset sanitize -j"$(nproc)"
ctest --preset sanitize --timeout 900
bash fuzz/run.sh "${GAPFEM_FUZZ_SECONDS:-30}"
