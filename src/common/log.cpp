#include "common/log.hpp"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace gapfem::log {
namespace {
std::mutex g_mutex;
std::atomic<Level> g_level{Level::Info};
void default_sink(Level lvl, std::string_view msg) {
  std::FILE* out = lvl >= Level::Warning ? stderr : stdout;
  const char* prefix = lvl == Level::Warning ? "warning: " : lvl == Level::Error ? "error: " : "";
  std::fprintf(out, "%s%.*s\n", prefix, static_cast<int>(msg.size()), msg.data());
  std::fflush(out);
}
Sink& sink_ref() {
  static Sink sink = default_sink;
  return sink;
}
} // namespace

Sink set_sink(Sink sink) {
  std::lock_guard lock(g_mutex);
  Sink old = std::move(sink_ref());
  sink_ref() = sink ? std::move(sink) : Sink(default_sink);
  return old;
}
void set_level(Level lvl) { g_level = lvl; }
Level level() { return g_level; }
void write(Level lvl, std::string_view message) {
  std::lock_guard lock(g_mutex);
  sink_ref()(lvl, message);
}

} // namespace gapfem::log
