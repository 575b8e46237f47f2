#include "solver/procedure.hpp"

#include "solver/procedures.hpp"

#include <fmt/format.h>
#include <map>
#include <mutex>
#include <stdexcept>

namespace gapfem {

namespace {

std::map<Procedure, ProcedureFactory>& table() {
  static std::map<Procedure, ProcedureFactory> t;
  return t;
}

/// The procedures gapfem has; a new one adds its line here (docs/architecture.md).
void register_builtin_procedures() {
  register_procedure(Procedure::Static, make_static_procedure);
  register_procedure(Procedure::HeatTransfer, make_heat_transfer_procedure);
  register_procedure(Procedure::CoupledTempDisp, make_heat_transfer_procedure);
  register_procedure(Procedure::SubstructureGenerate, make_substructure_generate_procedure);
}

std::once_flag builtin_once;

} // namespace

void register_procedure(Procedure p, ProcedureFactory make) {
  table()[p] = std::move(make);
}

std::unique_ptr<StepProcedure> make_procedure(Procedure p, Analysis::Impl& analysis) {
  std::call_once(builtin_once, register_builtin_procedures);
  const auto it = table().find(p);
  if (it == table().end())
    throw std::logic_error(fmt::format("no class runs steps of procedure {}", procedure_name(p)));
  return it->second(analysis);
}

} // namespace gapfem
