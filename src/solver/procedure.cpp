#include "solver/procedure.hpp"

#include "solver/procedures.hpp"

#include <fmt/format.h>
#include <map>
#include <stdexcept>

namespace gapfem {

namespace {

/// The procedures gapfem has; a new one adds its line here (docs/architecture.md).
std::map<Procedure, ProcedureFactory> builtin_procedures() {
  return {{Procedure::Static, make_static_procedure},
          {Procedure::HeatTransfer, make_heat_transfer_procedure},
          {Procedure::CoupledTempDisp, make_heat_transfer_procedure},
          {Procedure::SubstructureGenerate, make_substructure_generate_procedure},
          {Procedure::Dynamic, make_dynamic_procedure},
          {Procedure::Frequency, make_frequency_procedure},
          {Procedure::ResponseSpectrum, make_response_spectrum_procedure},
          {Procedure::Buckle, make_buckle_procedure},
          {Procedure::SteadyStateDynamics, make_steady_state_procedure},
          {Procedure::ModalDynamic, make_modal_dynamic_procedure}};
}

/// The table, the built-in procedures in it before anything else is registered or made.
std::map<Procedure, ProcedureFactory>& table() {
  static std::map<Procedure, ProcedureFactory> t = builtin_procedures();
  return t;
}

} // namespace

void register_procedure(Procedure p, ProcedureFactory make) {
  table()[p] = std::move(make);
}

std::unique_ptr<StepProcedure> make_procedure(const Step& step, Analysis::Impl& analysis) {
  if (step.perturbation && step.procedure == Procedure::Static)
    return make_static_perturbation_procedure(analysis);
  const Procedure p = step.procedure;
  const auto it = table().find(p);
  if (it == table().end())
    throw std::logic_error(fmt::format("no class runs steps of procedure {}", procedure_name(p)));
  return it->second(analysis);
}

} // namespace gapfem
