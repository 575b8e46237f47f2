#pragma once
/// @file deck_text.hpp
/// Deck files as text, before any keyword is seen: reading a file (regular files only, with the
/// true reason when a path cannot be read), encodings (a UTF-8 byte-order mark is skipped;
/// UTF-16/32 and binary files are named as such), line ends (LF, CRLF and the CR of classic Mac
/// files) and deck text made printable for messages.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace gapfem::inp {

/// Why a file cannot be read as deck text, or "" when `out` holds its contents. Only regular
/// files are read (a directory, FIFO, socket or device such as /dev/zero is refused before it is
/// opened), and at most `limit` bytes: a larger file is refused rather than exhausting memory.
/// The reason is the true one: a missing file, a symbolic link loop, a link to a missing file, a
/// path through a file, a directory that cannot be searched, a name too long.
std::string read_file(const std::filesystem::path& path, std::string& out, std::uintmax_t limit);

/// `text` without a leading UTF-8 byte-order mark (EF BB BF), which Windows editors write.
std::string_view skip_utf8_bom(std::string_view text);

/// The encoding of a text that is not ASCII/UTF-8 but UTF-16 or UTF-32 ("UTF-16 (little-endian)",
/// with or without a byte-order mark: text in those encodings has NUL bytes in fixed places), or
/// "" for text gapfem reads.
std::string foreign_encoding(std::string_view text);

/// The lines of a text without their line ends (LF, CRLF, or a CR alone as classic Mac OS wrote
/// them) and without trailing blanks. A final line end does not start another line.
std::vector<std::string_view> split_lines(std::string_view text);

/// `text` as it can be shown in a message: NUL and other control characters, the C1 controls
/// and bytes that are not UTF-8 are written as \xNN (tab and newline stay, and so does valid
/// UTF-8 such as "Grüße"). A message that quotes deck text is then never cut at a NUL byte, and
/// escape sequences never reach the terminal. Idempotent.
std::string printable(std::string_view text);

} // namespace gapfem::inp
