#include "io/inp/diagnostics.hpp"

#include "io/inp/deck_text.hpp"

#include <fmt/format.h>
#include <map>

namespace gapfem::inp {

InputError printable(const InputError& e) {
  SourceLocation loc = e.location();
  loc.file = printable(loc.file);
  loc.keyword = printable(loc.keyword);
  return InputError(std::move(loc), printable(e.entity()), printable(e.message()));
}

void Diagnostics::error(const InputError& e) {
  if (_muted) {
    ++_suppressed;
    return;
  }
  _errors.push_back(printable(e));
  if (static_cast<int>(_errors.size()) >= _max_errors) throw TooManyErrors{};
}

void Diagnostics::warning(const SourceLocation& loc, const std::string& message) {
  std::string out;
  if (!loc.file.empty())
    out += loc.file + (loc.line > 0 ? fmt::format(":{}", loc.line) : "") + ": ";
  if (!loc.keyword.empty()) out += loc.keyword + ": ";
  out += message;
  _warnings.push_back(printable(out));
}

void Diagnostics::throw_if_errors() const {
  if (_errors.empty()) return;
  if (_errors.size() == 1) throw _errors.front();
  // one error repeated for many entities (a mistake in a *GAP that every gap element shows) is
  // listed kShown times, then counted
  constexpr int kShown = 3;
  std::map<std::pair<std::string, std::string>, int> total, listed;
  for (const auto& e : _errors) ++total[{e.location().keyword, e.message()}];
  std::string list;
  for (const auto& e : _errors) {
    const std::pair<std::string, std::string> key{e.location().keyword, e.message()};
    int& n = listed[key];
    if (n == kShown) continue;
    list += '\n';
    list += e.what();
    if (++n == kShown && total[key] > kShown)
      list += fmt::format("\n... and {} more errors with the same message ({}: {})",
                          total[key] - kShown, key.first, key.second);
  }
  const bool capped = static_cast<int>(_errors.size()) >= _max_errors;
  std::string head =
      capped ? fmt::format("the deck has at least {} input errors (reading stopped there); fix "
                           "these first and run again:",
                           _errors.size())
             : fmt::format("the deck has {} input errors; fix each of them:", _errors.size());
  const InputError& first = _errors.front();
  throw InputError(first.location(), "", head + list);
}

} // namespace gapfem::inp
