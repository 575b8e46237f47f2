// *PARAMETER and <name> substitution (parameters.hpp): a recursive-descent reading of Python's
// arithmetic expressions, and the pass over the lexed deck that defines and substitutes.
#include "io/inp/parameters.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <stdexcept>

namespace gapfem::inp {
namespace {

using Value = ParameterValue;
using Table = std::map<std::string, Value>;

bool is_number(const Value& v) {
  return !std::holds_alternative<std::string>(v);
}
double as_double(const Value& v) {
  if (const auto* i = std::get_if<long long>(&v)) return static_cast<double>(*i);
  if (const auto* d = std::get_if<double>(&v)) return *d;
  throw std::invalid_argument(
      fmt::format("the string '{}' is used where a number is needed", std::get<std::string>(v)));
}

/// One Python expression, read left to right (precedence climbing as Python's grammar has it).
class ExpressionReader {
 public:
  ExpressionReader(std::string_view text, const Table& table) : _t(text), _table(table) {}

  Value read() {
    Value v = sum();
    skip();
    if (_p != _t.size())
      throw std::invalid_argument(
          fmt::format("unexpected '{}' at character {}", _t.substr(_p, 1), _p + 1));
    return v;
  }

 private:
  void skip() {
    while (_p < _t.size() && std::isspace(static_cast<unsigned char>(_t[_p]))) ++_p;
  }
  bool eat(std::string_view s) {
    skip();
    if (_t.substr(_p, s.size()) != s) return false;
    _p += s.size();
    return true;
  }

  Value sum() {
    Value v = term();
    for (;;) {
      if (eat("+")) {
        v = add(v, term(), false);
      } else if (eat("-")) {
        v = add(v, term(), true);
      } else {
        return v;
      }
    }
  }

  static Value add(const Value& a, const Value& b, bool minus) {
    if (!minus && !is_number(a) && !is_number(b))
      return std::get<std::string>(a) + std::get<std::string>(b);
    const auto* ia = std::get_if<long long>(&a);
    const auto* ib = std::get_if<long long>(&b);
    if (ia && ib) return minus ? *ia - *ib : *ia + *ib;
    return minus ? as_double(a) - as_double(b) : as_double(a) + as_double(b);
  }

  Value term() {
    Value v = factor();
    for (;;) {
      skip();
      if (_t.substr(_p, 2) == "**") return v; // (a power binds tighter: read by factor)
      if (eat("//")) {
        v = floor_divide(v, factor());
      } else if (eat("*")) {
        const Value b = factor();
        const auto* ia = std::get_if<long long>(&v);
        const auto* ib = std::get_if<long long>(&b);
        v = ia && ib ? Value(*ia * *ib) : Value(as_double(v) * as_double(b));
      } else if (eat("/")) {
        const double d = as_double(factor());
        if (d == 0.0) throw std::invalid_argument("division by zero");
        v = as_double(v) / d; // Python 3: always a float
      } else if (eat("%")) {
        const double d = as_double(factor()), a = as_double(v);
        if (d == 0.0) throw std::invalid_argument("modulo by zero");
        const double r = a - d * std::floor(a / d);
        v = std::holds_alternative<long long>(v) && std::abs(d - std::round(d)) == 0.0
                ? Value(static_cast<long long>(r))
                : Value(r);
      } else {
        return v;
      }
    }
  }

  static Value floor_divide(const Value& a, const Value& b) {
    const double d = as_double(b);
    if (d == 0.0) throw std::invalid_argument("division by zero");
    const double q = std::floor(as_double(a) / d);
    if (std::holds_alternative<long long>(a) && std::holds_alternative<long long>(b))
      return static_cast<long long>(q);
    return q;
  }

  Value factor() {
    if (eat("-")) {
      const Value v = factor();
      if (const auto* i = std::get_if<long long>(&v)) return -*i;
      return -as_double(v);
    }
    if (eat("+")) return factor();
    return power();
  }

  Value power() {
    const Value base = atom();
    if (!eat("**")) return base;
    const Value exponent = factor(); // right-associative, binds a unary minus on its right
    const auto* ib = std::get_if<long long>(&base);
    const auto* ie = std::get_if<long long>(&exponent);
    if (ib && ie && *ie >= 0 && *ie < 63) {
      long long r = 1;
      for (long long k = 0; k < *ie; ++k) r *= *ib;
      return r;
    }
    return std::pow(as_double(base), as_double(exponent));
  }

  Value atom() {
    skip();
    if (_p >= _t.size()) throw std::invalid_argument("the expression ends too early");
    const char c = _t[_p];
    if (eat("(")) {
      const Value v = sum();
      if (!eat(")")) throw std::invalid_argument("a ')' is missing");
      return v;
    }
    if (c == '\'' || c == '"') return string_literal(c);
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return name();
    throw std::invalid_argument(fmt::format("unexpected '{}' at character {}", c, _p + 1));
  }

  Value string_literal(char quote) {
    const std::size_t end = _t.find(quote, _p + 1);
    if (end == std::string_view::npos) throw std::invalid_argument("a string is not closed");
    std::string s(_t.substr(_p + 1, end - _p - 1));
    _p = end + 1;
    return s;
  }

  Value number() {
    const std::size_t start = _p;
    bool real = false;
    while (_p < _t.size()) {
      const char c = _t[_p];
      if (std::isdigit(static_cast<unsigned char>(c))) {
        ++_p;
      } else if (c == '.') {
        real = true;
        ++_p;
      } else if ((c == 'e' || c == 'E') && _p + 1 < _t.size()) {
        real = true;
        ++_p;
        if (_t[_p] == '+' || _t[_p] == '-') ++_p;
      } else {
        break;
      }
    }
    const std::string text(_t.substr(start, _p - start));
    if (!real) {
      long long v = 0;
      const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (ec == std::errc() && ptr == text.data() + text.size()) return v;
    }
    char* end = nullptr;
    const double d = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size())
      throw std::invalid_argument(fmt::format("'{}' is not a number", text));
    return d;
  }

  Value name() {
    const std::size_t start = _p;
    while (_p < _t.size() &&
           (std::isalnum(static_cast<unsigned char>(_t[_p])) || _t[_p] == '_' || _t[_p] == '.'))
      ++_p;
    std::string id(_t.substr(start, _p - start));
    if (id.rfind("math.", 0) == 0) id = id.substr(5);
    if (eat("(")) return call(id);
    if (const auto it = _table.find(id); it != _table.end()) return it->second;
    if (id == "pi") return 3.14159265358979323846;
    if (id == "e") return 2.71828182845904523536;
    throw std::invalid_argument(fmt::format("'{}' is not defined (a parameter must be defined "
                                            "by a *PARAMETER line above its use)",
                                            id));
  }

  Value call(const std::string& f) {
    std::vector<Value> args;
    if (!eat(")")) {
      do {
        args.push_back(sum());
      } while (eat(","));
      if (!eat(")")) throw std::invalid_argument(fmt::format("a ')' is missing after {}(", f));
    }
    return apply(f, args);
  }

  static Value apply(const std::string& f, const std::vector<Value>& a) {
    using F1 = double (*)(double);
    static const std::map<std::string, F1> one = {
        {"sin", std::sin},   {"cos", std::cos},     {"tan", std::tan},     {"asin", std::asin},
        {"acos", std::acos}, {"atan", std::atan},   {"sqrt", std::sqrt},   {"exp", std::exp},
        {"log", std::log},   {"log10", std::log10}, {"fabs", std::fabs},   {"sinh", std::sinh},
        {"cosh", std::cosh}, {"tanh", std::tanh},   {"floor", std::floor}, {"ceil", std::ceil}};
    const auto arity = [&](std::size_t n) {
      if (a.size() != n)
        throw std::invalid_argument(fmt::format("{}() takes {} argument(s)", f, n));
    };
    if (const auto it = one.find(f); it != one.end()) {
      arity(1);
      const double r = it->second(as_double(a[0]));
      if (!std::isfinite(r))
        throw std::invalid_argument(fmt::format("{}() is not defined there", f));
      return f == "floor" || f == "ceil" ? Value(static_cast<long long>(r)) : Value(r);
    }
    if (f == "atan2" || f == "pow") {
      arity(2);
      return f == "atan2" ? std::atan2(as_double(a[0]), as_double(a[1]))
                          : std::pow(as_double(a[0]), as_double(a[1]));
    }
    if (f == "radians" || f == "degrees") {
      arity(1);
      const double k = 3.14159265358979323846 / 180.0;
      return f == "radians" ? as_double(a[0]) * k : as_double(a[0]) / k;
    }
    if (f == "abs") {
      arity(1);
      if (const auto* i = std::get_if<long long>(&a[0])) return *i < 0 ? -*i : *i;
      return std::abs(as_double(a[0]));
    }
    if (f == "int") {
      arity(1);
      return static_cast<long long>(std::trunc(as_double(a[0])));
    }
    if (f == "float") {
      arity(1);
      return as_double(a[0]);
    }
    if (f == "round") {
      arity(1);
      return static_cast<long long>(std::nearbyint(as_double(a[0]))); // Python: to even
    }
    if ((f == "min" || f == "max") && !a.empty()) {
      Value best = a[0];
      for (const Value& v : a)
        if (f == "min" ? as_double(v) < as_double(best) : as_double(v) > as_double(best)) best = v;
      return best;
    }
    throw std::invalid_argument(fmt::format("the function {}() is not known", f));
  }

  std::string_view _t;
  const Table& _table;
  std::size_t _p = 0;
};

/// `text` with every <name> replaced; names not defined are collected in `missing`.
std::string substitute(std::string_view text, const Table& table, std::string& missing) {
  std::string out;
  std::size_t p = 0;
  while (p < text.size()) {
    const std::size_t open = text.find('<', p);
    const std::size_t close = open == std::string_view::npos ? open : text.find('>', open + 1);
    if (close == std::string_view::npos) {
      out.append(text.substr(p));
      break;
    }
    out.append(text.substr(p, open - p));
    const std::string name(trim(text.substr(open + 1, close - open - 1)));
    if (const auto it = table.find(name); it != table.end()) {
      out += parameter_text(it->second);
    } else {
      if (missing.empty()) missing = name;
      out.append(text.substr(open, close - open + 1));
    }
    p = close + 1;
  }
  return out;
}

/// One *PARAMETER block: each line `name = expression` (a # starts a comment).
void define(const Keyword& kw, Table& table, Diagnostics& diag, const std::string& file) {
  for (const DataLine& line : kw.data) {
    line.read = true;
    std::string_view text = line.text;
    if (const auto hash = text.find('#'); hash != std::string_view::npos)
      text = text.substr(0, hash);
    text = trim(text);
    if (text.empty()) continue;
    const SourceLocation loc{file, line.line, kw.name};
    const auto eq = text.find('=');
    const std::string name(trim(text.substr(0, eq == std::string_view::npos ? 0 : eq)));
    const bool valid_name =
        !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_') &&
        std::all_of(name.begin(), name.end(),
                    [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
    if (eq == std::string_view::npos || !valid_name) {
      diag.error(loc, "",
                 "a parameter definition is `name = expression` (Python's syntax: a "
                 "name of letters, digits and _ that starts with a letter)");
      continue;
    }
    try {
      table[name] = evaluate_parameter(text.substr(eq + 1), table);
    } catch (const std::invalid_argument& e) {
      diag.error(loc, fmt::format("parameter {}", name), e.what());
    }
  }
}

} // namespace

ParameterValue evaluate_parameter(std::string_view expression, const Table& parameters) {
  return ExpressionReader(expression, parameters).read();
}

std::string parameter_text(const ParameterValue& value) {
  if (const auto* i = std::get_if<long long>(&value)) return std::to_string(*i);
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  const double d = std::get<double>(value);
  std::string t = fmt::format("{}", d); // the shortest text that reads back to d
  if (t.find_first_of(".eEn") == std::string::npos) t += ".0";
  return t;
}

void substitute_parameters(Deck& deck, Diagnostics& diag) {
  const bool any = std::any_of(deck.keywords.begin(), deck.keywords.end(),
                               [](const Keyword& kw) { return kw.key == "PARAMETER"; });
  if (!any) return;
  Table table;
  std::vector<Keyword> kept;
  kept.reserve(deck.keywords.size());
  for (Keyword& kw : deck.keywords) {
    const std::string& file = deck.files[static_cast<std::size_t>(kw.file)];
    if (kw.key == "PARAMETER") {
      define(kw, table, diag, file);
      continue;
    }
    std::string missing;
    for (Parameter& p : kw.params) p.value = substitute(p.value, table, missing);
    if (!missing.empty()) {
      diag.error(kw.loc, fmt::format("<{}>", missing),
                 "this parameter is not defined; define it with *PARAMETER above its first use");
      kw.failed = true; // not run: its values would raise follow-on errors
    }
    for (DataLine& line : kw.data) {
      if (line.text.find('<') == std::string::npos) continue;
      std::string line_missing;
      DataLine replaced = split_data_line(substitute(line.text, table, line_missing));
      replaced.file = line.file;
      replaced.line = line.line;
      line = std::move(replaced);
      if (!line_missing.empty()) {
        diag.error(SourceLocation{file, line.line, kw.name}, fmt::format("<{}>", line_missing),
                   "this parameter is not defined; define it with *PARAMETER above its first use");
        kw.failed = true;
      }
    }
    kept.push_back(std::move(kw));
  }
  deck.keywords = std::move(kept);
}

} // namespace gapfem::inp
