#!/usr/bin/env python3
"""Writes the fuzzers' seed corpus: every deck of the repository (examples/, tests/bad_input/,
the .inp files under tests/) and every deck written inline in the C++ tests (raw string literals
that hold a keyword line), as bytes, and variants of every tenth deck with the bytes of issue 43
(byte-order marks, UTF-16, CR line ends, NUL, integers beyond 32 and 64 bits, 1e400, a line of
commas, a line over the length limit). Decks that name another file (*INCLUDE, INPUT=) are left
out: the fuzz targets skip them.  Usage: make_seeds.py OUTPUT_DIR"""
import hashlib
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
out = pathlib.Path(sys.argv[1])
out.mkdir(parents=True, exist_ok=True)

decks = []  # as bytes: the corpus holds decks in UTF-16, with NUL bytes and CR-only line ends
for d in ("examples", "tests"):
    for p in sorted((root / d).rglob("*.inp")):
        if p.is_file():
            decks.append(p.read_bytes())
raw = re.compile(r'R"([^(\s]{0,16})\((.*?)\)\1"', re.S)
for p in sorted((root / "tests").rglob("*.cpp")):
    for m in raw.finditer(p.read_text(errors="replace")):
        text = m.group(2)
        if re.search(r"^\s*\*[A-Za-z]", text, re.M):
            decks.append(text.encode())


def variants(data):
    """The deck as the issue-43 campaign met decks: with a byte-order mark, in UTF-16, with CR
    line ends, a NUL byte, integers beyond 32 and 64 bits, a real beyond the double range, a line
    of commas and a line over the length limit (65,536 characters)."""
    yield b"\xef\xbb\xbf" + data
    try:
        yield data.decode().encode("utf-16")
    except UnicodeDecodeError:
        pass
    yield data.replace(b"\n", b"\r")
    yield data.replace(b".", b".\x00", 1)
    for big in (b"2147483648", b"4294967296", b"9223372036854775808", b"1e20"):
        yield re.sub(rb"(?m)^(\*STEP[^\n]*)$", rb"\1, INC=" + big, data, count=1)
        yield re.sub(rb"(?m)^([0-9]+),", big + b",", data, count=1)
    yield re.sub(rb"(?m)^(-?[0-9]+, *)-?[0-9.]+", rb"\g<1>1e400", data, count=1)
    yield re.sub(rb"(?m)^(\*NODE[^\n]*\n)", rb"\1,,,,\n", data, count=1)
    yield re.sub(rb"(?m)^([0-9]+,)", rb"\1" + b" " * 66000, data, count=1)


n = 0
for i, data in enumerate(decks):
    if b"INPUT" in re.sub(rb"[ \t]", b"", data).upper():
        continue
    # every deck, and the variants of every tenth (the corpus stays small)
    for seed in [data] + (list(variants(data)) if i % 10 == 0 else []):
        (out / hashlib.sha1(seed).hexdigest()).write_bytes(seed)
        n += 1
print(f"{n} seed decks in {out}")
