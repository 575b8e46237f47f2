#pragma once
/// @file log.hpp
/// Levelled logging. Library code never writes to std::cout directly: it logs, and the application
/// decides where messages go (terminal, message file) through a sink.
#include <fmt/format.h>

#include <functional>
#include <string>
#include <string_view>

namespace gapfem::log {

enum class Level { Debug = 0, Info, Progress, Warning, Error, Quiet };

using Sink = std::function<void(Level, std::string_view)>;

/// Replace the sink (default: Info and above to stderr/stdout). Returns the previous sink.
Sink set_sink(Sink sink);
void set_level(Level level);
Level level();
void write(Level level, std::string_view message);

template <typename... Args>
void debug(fmt::format_string<Args...> f, Args&&... args) {
  if (level() <= Level::Debug) write(Level::Debug, fmt::format(f, std::forward<Args>(args)...));
}
template <typename... Args>
void info(fmt::format_string<Args...> f, Args&&... args) {
  if (level() <= Level::Info) write(Level::Info, fmt::format(f, std::forward<Args>(args)...));
}
template <typename... Args>
void progress(fmt::format_string<Args...> f, Args&&... args) {
  if (level() <= Level::Progress) write(Level::Progress, fmt::format(f, std::forward<Args>(args)...));
}
template <typename... Args>
void warning(fmt::format_string<Args...> f, Args&&... args) {
  if (level() <= Level::Warning) write(Level::Warning, fmt::format(f, std::forward<Args>(args)...));
}
template <typename... Args>
void error(fmt::format_string<Args...> f, Args&&... args) {
  if (level() <= Level::Error) write(Level::Error, fmt::format(f, std::forward<Args>(args)...));
}

} // namespace gapfem::log
