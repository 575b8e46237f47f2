#include "linalg/constrained_solver.hpp"

#include "common/error.hpp"
#include "linalg/kkt_solver.hpp"
#include "linalg/krylov_eigen.hpp"
#include "linalg/norms.hpp"

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

std::unique_ptr<KrylovEigenSolver> ConstrainedSolver::krylov_eigen_solver() const {
  return make_spectra_krylov();
}

KktStatistics ConstrainedSolver::solve(CsrMatrix& K, std::span<const double> b,
                                       const ConstraintBlock& C, std::span<double> du,
                                       std::span<double> dl, bool symmetric,
                                       const KktOptions& options, RunStatistics* stats) {
  KktStatistics out;
  if (!options.matrix_current) { // no kept factor: only the current matrix serves
    out.needs_matrix = true;
    return out;
  }
  const auto factor = factorize(K, C, symmetric, stats);
  {
    ScopedTimer timer(stats, TimeCategory::Solve);
    if (stats) ++stats->linear_solves;
    factor->solve(b, C.g, du, dl);
  }
  out.solves = 1;
  // what the solve leaves of the rows: C du - E dl + g
  std::vector<double> row(static_cast<std::size_t>(C.n_rows()));
  C.multiply(du, row);
  for (int r = 0; r < C.n_rows(); ++r) row[r] += C.g[r] - C.row_compliance(r) * dl[r];
  out.constraint_residual = norm_inf(row);
  return out;
}

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
