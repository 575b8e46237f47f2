#include "linalg/constrained_solver.hpp"

#include "linalg/kkt_solver.hpp"

#include <deque>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <mutex>
#include <stdexcept>

namespace gapfem {
namespace {

/// The registry, with the serial backend of this layer in it from the start.
std::deque<SolverBackend>& registry() { // a deque: found entries stay where they are
  static std::deque<SolverBackend> backends{SolverBackend{
      "cholmod",
      "CHOLMOD (UMFPACK when indefinite or unsymmetric) with exact constraints; one process", true,
      false, "", [](const KktTuning& tuning) { return std::make_unique<KktSolver>(tuning); }}};
  return backends;
}

std::mutex g_registry_mutex;

} // namespace

void register_solver_backend(SolverBackend backend) {
  const std::lock_guard lock(g_registry_mutex);
  for (SolverBackend& b : registry())
    if (b.name == backend.name) {
      b = std::move(backend);
      return;
    }
  registry().push_back(std::move(backend));
}

const SolverBackend* find_solver_backend(std::string_view name) {
  const std::lock_guard lock(g_registry_mutex);
  for (const SolverBackend& b : registry())
    if (b.name == name) return &b;
  return nullptr;
}

std::vector<std::string> solver_backend_names() {
  const std::lock_guard lock(g_registry_mutex);
  std::vector<std::string> names;
  for (const SolverBackend& b : registry()) names.push_back(b.name);
  return names;
}

std::unique_ptr<ConstrainedSolver> make_constrained_solver(std::string_view name,
                                                           const KktTuning& tuning) {
  const SolverBackend* b = find_solver_backend(name);
  if (!b)
    throw std::runtime_error(fmt::format("there is no solver '{}'; this gapfem has: {}", name,
                                         fmt::join(solver_backend_names(), ", ")));
  if (!b->unavailable.empty()) throw std::runtime_error(b->unavailable);
  return b->make(tuning);
}

} // namespace gapfem
