#include "io/inp/deck_text.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <sys/stat.h>

namespace gapfem::inp {
namespace fs = std::filesystem;

namespace {

/// Why stat() failed on `path`, as a sentence with its remedy.
std::string stat_problem(const fs::path& path, int err) {
  switch (err) {
  case ELOOP:
    return "it is a symbolic link loop (a link that leads back to itself, directly or through "
           "other links); point the link at the deck file";
  case ENOENT: {
    std::error_code ec;
    if (fs::is_symlink(fs::symlink_status(path, ec)))
      return fmt::format("it is a symbolic link to '{}', which does not exist; point the link "
                         "at the deck file",
                         fs::read_symlink(path, ec).string());
    return "it does not exist; check the name and the directory";
  }
  case ENOTDIR:
    return "a part of its path is a file, not a directory; check the path";
  case EACCES:
    return "a directory on its path may not be searched (permission denied); check the "
           "permissions";
  case ENAMETOOLONG:
    return "its name is too long for the file system; use a shorter path";
  default:
    return fmt::format("it cannot be examined ({})", std::strerror(err));
  }
}

/// Length of the UTF-8 sequence at text[i] (2 to 4), or 0 when the bytes there are not one.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = byte(i);
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF; // the allowed range of the second byte
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0; // not overlong
    if (c == 0xED) hi = 0x9F; // not a surrogate
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;
    if (c == 0xF4) hi = 0x8F; // at most U+10FFFF
  } else {
    return 0;
  }
  if (i + n > text.size() || byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return n;
}

} // namespace

std::string read_file(const fs::path& path, std::string& out, std::uintmax_t limit) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return stat_problem(path, errno);
  if (S_ISDIR(st.st_mode)) return "it is a directory, not an input file; name a .inp file in it";
  if (!S_ISREG(st.st_mode))
    return "it is not a regular file (a device, FIFO or socket); give the path of a deck file";
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot open it; check that you may read it";
  out.clear();
  char chunk[1 << 16];
  while (in) {
    in.read(chunk, sizeof chunk);
    const auto got = static_cast<std::size_t>(in.gcount());
    if (out.size() + got > limit)
      return fmt::format("it is larger than {} MiB, the most gapfem reads from one deck and its "
                         "included files; split the model or check that this is the right file",
                         limit >> 20);
    out.append(chunk, got);
  }
  if (in.bad()) return "reading it failed (an input/output error)";
  return {};
}

std::string_view skip_utf8_bom(std::string_view text) {
  return text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text;
}

std::string foreign_encoding(std::string_view text) {
  auto starts = [&](std::string_view bom) { return text.starts_with(bom); };
  using namespace std::string_view_literals;
  if (starts("\xFF\xFE\0\0"sv)) return "UTF-32 (little-endian, with a byte-order mark)";
  if (starts("\0\0\xFE\xFF"sv)) return "UTF-32 (big-endian, with a byte-order mark)";
  if (starts("\xFF\xFE"sv)) return "UTF-16 (little-endian, with a byte-order mark)";
  if (starts("\xFE\xFF"sv)) return "UTF-16 (big-endian, with a byte-order mark)";
  // without a byte-order mark: ASCII characters in UTF-16 or UTF-32 leave NUL bytes at fixed
  // places (every second byte, or three of every four), which no text gapfem reads has
  const std::size_t n = std::min<std::size_t>(text.size(), 1024) / 4 * 4;
  if (n == 0) return {};
  std::size_t zeros[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) zeros[i % 4] += text[i] == '\0';
  const double q = static_cast<double>(n / 4); // bytes per residue
  auto most = [&](std::size_t z) { return static_cast<double>(z) >= 0.9 * q; };
  auto few = [&](std::size_t z) { return static_cast<double>(z) <= 0.1 * q; };
  if (few(zeros[0]) && most(zeros[1]) && most(zeros[2]) && most(zeros[3]))
    return "UTF-32 (little-endian)";
  if (most(zeros[0]) && most(zeros[1]) && most(zeros[2]) && few(zeros[3]))
    return "UTF-32 (big-endian)";
  if (few(zeros[0]) && few(zeros[2]) && most(zeros[1]) && most(zeros[3]))
    return "UTF-16 (little-endian)";
  if (most(zeros[0]) && most(zeros[2]) && few(zeros[1]) && few(zeros[3]))
    return "UTF-16 (big-endian)";
  return {};
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find_first_of("\r\n", start);
    std::size_t next = end == std::string_view::npos ? text.size() : end + 1;
    if (end == std::string_view::npos)
      end = text.size();
    else if (text[end] == '\r' && next < text.size() && text[next] == '\n')
      ++next; // CRLF
    std::string_view line = text.substr(start, end - start);
    std::size_t e = line.size();
    while (e > 0 && (line[e - 1] == ' ' || line[e - 1] == '\t')) --e;
    lines.push_back(line.substr(0, e));
    start = next;
  }
  return lines;
}

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n' || c == '\t' || (c >= 0x20 && c < 0x7F)) {
      out.push_back(static_cast<char>(c));
      ++i;
      continue;
    }
    // valid UTF-8 stays, except the C1 controls U+0080-U+009F (C2 80 - C2 9F)
    const std::size_t n = c >= 0x80 ? utf8_length(text, i) : 0;
    if (n > 0 && !(c == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0)) {
      out.append(text.substr(i, n));
      i += n;
      continue;
    }
    out += fmt::format("\\x{:02X}", c);
    ++i;
  }
  return out;
}

} // namespace gapfem::inp
