#include "io/inp/fields.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <limits>

namespace gapfem::inp {
namespace {
bool digit(char c) {
  return c >= '0' && c <= '9';
}

std::string field_entity(std::size_t i, std::string_view what) {
  return what.empty() ? fmt::format("field {}", i + 1) : fmt::format("field {} ({})", i + 1, what);
}
} // namespace

std::optional<double> parse_real(std::string_view text) {
  text = trim(text);
  std::string s;
  std::size_t i = 0;
  const std::size_t n = text.size();
  if (i < n && (text[i] == '+' || text[i] == '-')) s.push_back(text[i++]);
  int mantissa_digits = 0;
  while (i < n && digit(text[i])) {
    s.push_back(text[i++]);
    ++mantissa_digits;
  }
  if (i < n && text[i] == '.') {
    s.push_back(text[i++]);
    while (i < n && digit(text[i])) {
      s.push_back(text[i++]);
      ++mantissa_digits;
    }
  }
  if (mantissa_digits == 0) return std::nullopt;
  if (i < n && (text[i] == 'e' || text[i] == 'E' || text[i] == 'd' || text[i] == 'D')) {
    s.push_back('e');
    ++i;
    if (i < n && (text[i] == '+' || text[i] == '-')) s.push_back(text[i++]);
    int exp_digits = 0;
    while (i < n && digit(text[i])) {
      s.push_back(text[i++]);
      ++exp_digits;
    }
    if (exp_digits == 0) return std::nullopt;
  }
  if (i != n) return std::nullopt;
  errno = 0;
  const double v = std::strtod(s.c_str(), nullptr);
  if (errno == ERANGE && std::isinf(v)) return std::nullopt;
  return v;
}

std::optional<long long> parse_integer(std::string_view text) {
  text = trim(text);
  std::size_t i = 0;
  bool negative = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
  if (i == text.size()) return std::nullopt;
  long long v = 0;
  for (; i < text.size(); ++i) {
    if (!digit(text[i])) return std::nullopt;
    if (v > (std::numeric_limits<long long>::max() - 9) / 10) return std::nullopt;
    v = v * 10 + (text[i] - '0');
  }
  return negative ? -v : v;
}

const std::string& FieldReader::text(std::size_t i) const {
  static const std::string empty;
  return i < _line.fields.size() ? _line.fields[i] : empty;
}

double FieldReader::real(std::size_t i, std::string_view what) const {
  if (blank(i))
    fail(field_entity(i, what), "this value is required but the field is missing or blank");
  return *opt_real(i, what);
}

double FieldReader::real_or(std::size_t i, double def, std::string_view what) const {
  return opt_real(i, what).value_or(def);
}

std::optional<double> FieldReader::opt_real(std::size_t i, std::string_view what) const {
  if (blank(i)) return std::nullopt;
  const auto v = parse_real(_line.fields[i]);
  if (!v)
    fail(
        field_entity(i, what),
        fmt::format("'{}' is not a number; write it like 2, -0.5, 1.E6 or 1.0D3", _line.fields[i]));
  return v;
}

long long FieldReader::integer(std::size_t i, std::string_view what) const {
  if (blank(i))
    fail(field_entity(i, what), "this value is required but the field is missing or blank");
  const auto v = parse_integer(_line.fields[i]);
  if (!v)
    fail(field_entity(i, what),
         fmt::format("'{}' is not an integer; write a whole number such as 12", _line.fields[i]));
  return *v;
}

long long FieldReader::integer_or(std::size_t i, long long def, std::string_view what) const {
  return blank(i) ? def : integer(i, what);
}

void FieldReader::at_most(std::size_t n, std::string_view layout) const {
  for (std::size_t i = n; i < _line.fields.size(); ++i)
    if (!_line.fields[i].empty())
      fail(field_entity(i, ""),
           fmt::format("unexpected value '{}': this data line has at most {} fields ({})",
                       _line.fields[i], n, layout));
}

void FieldReader::fail(std::string entity, std::string message) const {
  // "field N (...)": the message echoes the value as written, unless it quotes it already
  unsigned n = 0;
  if (std::sscanf(entity.c_str(), "field %u", &n) == 1 && n >= 1 && n <= _line.fields.size() &&
      entity.rfind("fields", 0) != 0) {
    const std::string& text = _line.fields[n - 1];
    if (!text.empty() && message.find(text) == std::string::npos)
      message += fmt::format(" (given: {})", text);
  }
  throw InputError(_loc, std::move(entity), std::move(message));
}

} // namespace gapfem::inp
