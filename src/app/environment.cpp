#include "app/environment.hpp"

#include "common/memory.hpp"

#include <cstdlib>
#include <string_view>

namespace gapfem {
namespace {

/// A switch that is on unless set to 0 or off.
void on_off(const char* name, bool& value) {
  if (const char* env = std::getenv(name))
    value = std::string_view(env) != "0" && std::string_view(env) != "off";
}

/// A positive whole number, or nothing.
long positive(const char* name) {
  const char* env = std::getenv(name);
  const long n = env ? std::atol(env) : 0;
  return n > 0 ? n : 0;
}

} // namespace

void apply_environment(AnalysisOptions& o) {
  if (const char* env = std::getenv("GAPFEM_FACTOR_REUSE")) {
    const std::string_view v(env);
    if (v == "always") o.factor_reuse = FactorReuse::Always;
    if (v == "never") o.factor_reuse = FactorReuse::Never;
  }
  on_off("GAPFEM_RESIDUAL_ONLY", o.residual_only);
  on_off("GAPFEM_PENALTY_ROWS", o.kernels.penalty_rows);
  on_off("GAPFEM_FRICTION_ROWS", o.kernels.friction_rows);
  on_off("GAPFEM_FACTOR_UPDATES", o.kkt.factor_updates);
  on_off("GAPFEM_DENSE_MULTIPLIERS", o.kkt.dense_multipliers);
  if (const long n = positive("GAPFEM_THREADS")) o.threads = static_cast<int>(n);
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"})
    if (const long n = positive(name)) {
      o.ranks_here = static_cast<int>(n);
      break;
    }
  if (const long n = positive("GAPFEM_TEST_KILL_AFTER_INCREMENT")) o.kill_after_increments = n;
  if (const char* env = std::getenv("GAPFEM_MEMORY_LIMIT"))
    set_memory_limit(std::strtoull(env, nullptr, 10));
  else
    set_memory_limit(std::nullopt);
}

bool launched_by_mpirun() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(var)) return true;
  return false;
}

} // namespace gapfem
