// *SUBSTRUCTURE GENERATE steps: no increments; the stiffness at the step start reduced onto the
// retained DOFs and written to the library (the reduction: substructure_generate.cpp).
#include "solver/analysis_impl.hpp"
#include "solver/procedures.hpp"

namespace gapfem {

namespace {

class SubstructureGenerateProcedure final : public StepProcedure {
 public:
  using StepProcedure::StepProcedure;
  bool incremental() const override { return false; }
  void run(StepRun& r) override { _a.generate_substructure(r); }
};

} // namespace

std::unique_ptr<StepProcedure> make_substructure_generate_procedure(Analysis::Impl& a) {
  return std::make_unique<SubstructureGenerateProcedure>(a);
}

} // namespace gapfem
