#!/usr/bin/env bash
# Rewrite every <name>.expected in this directory from the actual stderr line of gapfem.
#
#   tests/bad_input/update.sh [path/to/gapfem] [name.inp ...]
#
# Default binary: build/release/gapfem of this checkout (or $GAPFEM). Without deck names,
# every *.inp here is run. A deck whose exit status is not 1, or whose stderr is not exactly
# one line, is refused: its .expected is left alone, the output is printed, and the script
# exits with status 1 after trying the others.
set -u
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bin="${1:-${GAPFEM:-$here/../../build/release/gapfem}}"
if [[ $# -gt 0 ]]; then shift; fi
if [[ ! -x "$bin" ]]; then
  echo "update.sh: gapfem binary not found or not executable: $bin" >&2
  exit 1
fi
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"
# the command of README.md; stdout and stderr are captured in temporary files
out_dir=/tmp/badin_out
tmp="$(mktemp -d "${TMPDIR:-/tmp}/badin_update.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

cd "$here" || exit 1
if [[ $# -gt 0 ]]; then decks=("$@"); else decks=(*.inp); fi

refused=0
updated=0
for deck in "${decks[@]}"; do
  deck="$(basename "$deck")"
  name="${deck%.inp}"
  if [[ ! -f "$deck" ]]; then
    echo "REFUSED $deck: no such deck" >&2
    refused=$((refused + 1))
    continue
  fi
  stdout_file="$tmp/$name.stdout"
  stderr_file="$tmp/$name.stderr"
  "$bin" -q --no-vtu -o "$out_dir" "$deck" >"$stdout_file" 2>"$stderr_file"
  rc=$?
  # count lines, also a last line without a trailing newline
  nlines=$(awk 'END { print NR }' "$stderr_file")
  if [[ $rc -ne 1 || $nlines -ne 1 ]]; then
    echo "REFUSED $deck: exit status $rc, $nlines stderr line(s) (want 1 and 1):" >&2
    sed 's/^/  stderr: /' "$stderr_file" >&2
    sed 's/^/  stdout: /' "$stdout_file" >&2
    refused=$((refused + 1))
    continue
  fi
  # one line with a trailing newline
  printf '%s\n' "$(head -n 1 "$stderr_file")" >"$name.expected"
  updated=$((updated + 1))
done

echo "update.sh: $updated .expected file(s) written, $refused deck(s) refused"
[[ $refused -eq 0 ]]
