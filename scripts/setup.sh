#!/usr/bin/env bash
# Quick start, command 1: install dependencies, build gapfem (release) and run the flagship example.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
example=examples/01_pipe_on_supports
out=build/examples/01_pipe_on_supports
mkdir -p "$out"
./build/release/gapfem -o "$out" "$example/pipe_on_supports.inp"
echo
echo "gapfem is built: $(pwd)/build/release/gapfem"
echo "Flagship example results: $(pwd)/$out/pipe_on_supports.{dat,sta,results.json,pvd}"
