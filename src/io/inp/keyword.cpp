#include "io/inp/keyword.hpp"

#include <cctype>

namespace gapfem::inp {
namespace {
bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f';
}
char upper(char c) {
  return static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
}
} // namespace

std::string canonical(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text)
    if (!is_blank(c)) out.push_back(upper(c));
  return out;
}

std::string display_upper(std::string_view text) {
  std::string out;
  bool pending_blank = false;
  for (char c : trim(text)) {
    if (is_blank(c)) {
      pending_blank = true;
      continue;
    }
    if (pending_blank && !out.empty()) out.push_back(' ');
    pending_blank = false;
    out.push_back(upper(c));
  }
  return out;
}

std::string_view trim(std::string_view text) {
  std::size_t b = 0, e = text.size();
  while (b < e && is_blank(text[b])) ++b;
  while (e > b && is_blank(text[e - 1])) --e;
  return text.substr(b, e - b);
}

std::string to_upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = upper(c);
  return out;
}

bool DataLine::empty() const {
  for (const auto& f : fields)
    if (!f.empty()) return false;
  return true;
}

bool DataLine::blank() const {
  return trim(text).empty();
}

const Parameter* Keyword::find(std::string_view param) const {
  const std::string k = canonical(param);
  for (const auto& p : params)
    if (p.key == k) return &p;
  return nullptr;
}

std::optional<std::string> Keyword::value(std::string_view param) const {
  const Parameter* p = find(param);
  if (!p) return std::nullopt;
  return p->value;
}

} // namespace gapfem::inp
