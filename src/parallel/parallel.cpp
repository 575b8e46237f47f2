#include "parallel/parallel.hpp"

#include <array>
#include <cctype>
#include <cstdlib>
#include <string_view>

namespace gapfem::parallel {

namespace {
bool is_petsc_option(std::string_view arg) {
  if (arg.size() < 3 || arg[0] != '-' || arg[1] == '-') return false;
  const std::string_view name = arg.substr(1);
  static constexpr std::array<std::string_view, 10> prefixes{
      "ksp_", "pc_", "mat_", "inner_", "mg_", "log_view", "info", "malloc", "options_", "vec_"};
  for (std::string_view p : prefixes)
    if (name.starts_with(p)) return true;
  return false;
}
bool is_value(std::string_view arg) {
  if (arg.empty()) return false;
  if (arg.ends_with(".inp")) return false; // the deck, after a flag option
  if (arg[0] != '-') return true;
  // a negative number is a value, not an option
  return arg.size() > 1 && (std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.');
}
} // namespace

std::vector<std::string> take_petsc_options(int& argc, char** argv) {
  std::vector<std::string> taken;
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    if (!is_petsc_option(argv[i])) {
      argv[out++] = argv[i];
      continue;
    }
    taken.emplace_back(argv[i]);
    if (i + 1 < argc && is_value(argv[i + 1])) taken.emplace_back(argv[++i]);
  }
  argc = out;
  argv[argc] = nullptr;
  return taken;
}

} // namespace gapfem::parallel
