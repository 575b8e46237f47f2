#!/usr/bin/env python3
"""Writes the decks of this corpus that cannot be edited as text: other encodings, NUL and control
bytes, CR-only line ends, lines beyond the reader's length limit. Each is the block model of
num_label_with_decimal.inp (with its mistake undone) with one mistake; run from this directory:

    python3 make_binary_decks.py && ./update.sh ../../build/release/gapfem <the decks>
"""


def base():
    text = open("num_label_with_decimal.inp").read().split("\n", 1)[1]
    return text.replace("\n2.5, 2, 3, 6, 5, 8, 9, 12, 11\n", "\n2, 2, 3, 6, 5, 8, 9, 12, 11\n")


def sub(text, old, new):
    assert old in text, old
    return text.replace(old, new, 1)


def write(name, data):
    with open(name, "wb") as f:
        f.write(data)


def main():
    B = base()
    bad = "** bad: {}\n".format
    write("syntax_utf16le_with_bom.inp",
          (bad("the deck saved as UTF-16 LE with BOM") + B).encode("utf-16"))
    write("syntax_utf16be_with_bom.inp",
          b"\xfe\xff" + (bad("the deck saved as UTF-16 BE with BOM") + B).encode("utf-16-be"))
    write("syntax_utf16le_without_bom.inp",
          (bad("the deck saved as UTF-16 LE without BOM") + B).encode("utf-16-le"))
    write("syntax_utf32le_without_bom.inp",
          (bad("the deck saved as UTF-32 LE without BOM") + B).encode("utf-32-le"))
    write("syntax_utf8_bom_then_bad_number.inp", b"\xef\xbb\xbf" + (
        bad("a bad number in a deck saved with a UTF-8 byte-order mark (which is skipped)") +
        sub(B, "3, 2., 0., 0.", "3, 2.x, 0., 0.")).encode())
    write("syntax_nul_in_number.inp", (bad("a NUL byte inside a node coordinate") +
                                       sub(B, "2, 1., 0., 0.", "2, 1.\0, 0., 0.")).encode())
    write("syntax_nul_in_keyword.inp", (bad("a NUL byte inside a keyword name") +
                                        sub(B, "*ELEMENT, TYPE=GAPUNI", "*ELE\0MENT, TYPE=GAPUNI")).encode())
    write("syntax_nul_bytes_binary.inp",
          (bad("NUL bytes on many lines (binary data, not a deck)") + "\0\0\0\n" * 6 + B).encode())
    write("syntax_cr_line_ends_bad_number.inp", (
        bad("a bad number in a deck with classic Mac (CR-only) line ends") +
        sub(B, "12, 2., 1., 1.", "12, 2., 1., 1.y")).replace("\n", "\r").encode())
    write("syntax_escape_sequence_in_number.inp", (
        bad("a terminal escape sequence in a number") +
        sub(B, "5, 1., 1., 0.", "5, 1.\x1b[31m, 1., 0.")).encode())
    write("syntax_invalid_utf8_in_set_name.inp", bad("a set name with a byte that is not UTF-8").encode() +
          sub(B, "GROUND, 1, 3", "GR\udcffOUND, 1, 3").encode("utf-8", "surrogateescape"))
    pad = " " * 70000
    write("syntax_long_node_line.inp", (bad("a node line padded beyond 65,536 characters") +
                                        sub(B, "12, 2., 1., 1.\n", "12, 2., 1.," + pad + "1.\n")).encode())
    write("syntax_long_gap_element_line.inp", (
        bad("a gap element line padded beyond 65,536 characters") +
        sub(B, "203, 3, 103\n", "203," + pad + "3, 103\n")).encode())
    write("syntax_long_nset_keyword_line.inp", (
        bad("an *NSET keyword line padded beyond 65,536 characters") +
        sub(B, "*NSET, NSET=TOP\n", "*NSET," + pad + "NSET=TOP\n")).encode())
    write("include/utf16_supports.inp", (
        "** the supports, saved as UTF-16 (read by include_utf16_file.inp)\n*BOUNDARY\nGROUND, 1, 3\n"
    ).encode("utf-16"))


if __name__ == "__main__":
    main()
