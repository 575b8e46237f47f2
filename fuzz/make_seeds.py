#!/usr/bin/env python3
"""Writes the fuzzers' seed corpus: every deck of the repository (examples/, tests/bad_input/,
the .inp files under tests/) and every deck written inline in the C++ tests (raw string literals
that hold a keyword line). Decks that name another file (*INCLUDE, INPUT=) are left out: the
fuzz targets skip them.  Usage: make_seeds.py OUTPUT_DIR"""
import hashlib
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
out = pathlib.Path(sys.argv[1])
out.mkdir(parents=True, exist_ok=True)

decks = []
for d in ("examples", "tests"):
    for p in sorted((root / d).rglob("*.inp")):
        decks.append(p.read_text(errors="replace"))
raw = re.compile(r'R"([^(\s]{0,16})\((.*?)\)\1"', re.S)
for p in sorted((root / "tests").rglob("*.cpp")):
    for m in raw.finditer(p.read_text(errors="replace")):
        text = m.group(2)
        if re.search(r"^\s*\*[A-Za-z]", text, re.M):
            decks.append(text)

n = 0
for text in decks:
    if "INPUT" in re.sub(r"[ \t]", "", text).upper():
        continue
    data = text.encode()
    (out / hashlib.sha1(data).hexdigest()).write_bytes(data)
    n += 1
print(f"{n} seed decks in {out}")
