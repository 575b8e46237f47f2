#!/usr/bin/env bash
# Runs the libFuzzer targets of the sanitize build for a bounded time each (default 30 s), seeded
# from the repository's decks (fuzz/make_seeds.py). Exits non-zero when a target finds a crash,
# a sanitizer report, a leak, an out-of-memory or a timeout; the reproducer is left in
# build/sanitize/fuzz-findings/. Usage: fuzz/run.sh [seconds per target] [extra libFuzzer flags]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
shift || true
build=build/sanitize
seeds="$build/fuzz-seeds"
python3 fuzz/make_seeds.py "$seeds"
mkdir -p "$build/fuzz-findings"
# short malloc stacks and no entropic scheduling: twice the executions per second (measured)
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:malloc_context_size=2"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
for target in fuzz_deck_reader fuzz_model_builder; do
  corpus="$build/fuzz-corpus/$target"
  mkdir -p "$corpus"
  echo "== $target: ${seconds} s"
  # -max_len above the reader's line limit (65,536), so that lines over it can be mutated too;
  # -dict: byte-order marks, NUL and control bytes, huge integers (fuzz/deck.dict)
  "$build/fuzz/$target" "$corpus" "$seeds" -max_total_time="$seconds" -max_len=70000 -entropic=0 \
    -dict=fuzz/deck.dict -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$build/fuzz-findings/$target-" "$@" 2>&1 | tail -n 25
done
