#include "common/error.hpp"

#include <fmt/format.h>

namespace gapfem {

std::string SourceLocation::str() const {
  if (file.empty() && line == 0) return keyword;
  std::string out = file;
  if (line > 0) out += fmt::format(":{}", line);
  if (!keyword.empty()) out += fmt::format(" ({})", keyword);
  return out;
}

static std::string format_input_error(const SourceLocation& loc, const std::string& entity,
                                      const std::string& message) {
  std::string out;
  if (!loc.file.empty()) out += loc.file + (loc.line > 0 ? fmt::format(":{}", loc.line) : "") + ": ";
  if (!loc.keyword.empty()) out += loc.keyword + ": ";
  if (!entity.empty()) out += entity + ": ";
  out += message;
  return out;
}

InputError::InputError(SourceLocation loc, std::string entity, std::string message)
    : Error(format_input_error(loc, entity, message)), _loc(std::move(loc)),
      _entity(std::move(entity)), _message(std::move(message)) {}

void throw_internal(const char* file, int line, const char* cond, const std::string& msg) {
  throw InternalError(fmt::format("internal error at {}:{}: {} ({})", file, line, msg, cond));
}

} // namespace gapfem
