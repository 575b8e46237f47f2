#pragma once
/// @file assembler.hpp
/// Loops over element blocks, gathers local data, calls kernels and scatters residual, tangent and
/// constraint rows into global storage. Threaded over element chunks with per-thread scratch.
#include "fem/element_gather.hpp"
#include "linalg/constraint_block.hpp"
#include "linalg/matrix_inserter.hpp"

#include <array>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace gapfem {

struct AssemblyResult {
  int status_changes = 0;
  int branch_changes = 0;         ///< sum of ElementOutput::branch_changes
  bool stiffness_changed = false; ///< ElementOutput::stiffness_changed of some element
  bool unsymmetric = false;
  bool friction = false; ///< some element has a closed gap with friction (ElementOutput::friction)
  std::array<double, kNumFields> flux_sum{}; ///< sum of |element residual entries| per field
  std::array<long, kNumFields> flux_count{};
  std::vector<ElemId> changed; ///< elements whose contact status changed in this evaluation
  double gap_seconds = 0.0;    ///< wall time spent on gap-element blocks (the "gap work")
  /// the smallest ElementOutput::dt_ratio of the evaluation (infinity: no element asked)
  double dt_ratio = std::numeric_limits<double>::infinity();
};

/// The weights of the kernels' operators in an assembled matrix, k K + c C + m M (ElementOutput's
/// tangent, damping and mass blocks): a step with a time integrator takes its weights (1, dv/du,
/// da/du; solver/time_integrator.hpp), an eigenproblem K alone {1, 0, 0} or M alone {0, 0, 1}.
/// When the context defines rates (StepContext::rates) the residual also gets the inertia and
/// damping forces M a + C v of every kernel whose operator is weighted. A kernel that adds its
/// damping itself (ElementKernel::damping_in_residual) is left alone while rates are defined.
struct OperatorWeights {
  double k = 1.0;       ///< stiffness (the kernels' tangent)
  double c = 0.0;       ///< damping
  double m = 0.0;       ///< mass
  double inertia = 1.0; ///< the factor of the inertia forces M a in the residual (HHT)
  bool operator==(const OperatorWeights&) const = default;
};

/// What an assembly under rates may also return per slot, each unweighted and only where not
/// empty (overwritten): the inertia forces M a (HHT's history), the damping forces C v of the
/// damping operators it applies, the momenta M v (kinetic energy): solver/step_problem_dynamic.cpp.
struct RateForces {
  std::span<double> inertia, damping, momentum;
  bool any() const { return !inertia.empty() || !damping.empty() || !momentum.empty(); }
};

/// A distributed load with its magnitude evaluated at the current time.
struct ActiveLoad {
  const DistributedLoad* load = nullptr;
  double magnitude = 0.0;
  double sink_temperature = 0.0;
};

class Assembler {
 public:
  explicit Assembler(Discretization& disc, int threads = 1);
  int threads() const { return _threads; }

  /// Internal forces per slot (f_int, overwritten), the matrix k K + c C + m M over equations (if
  /// K: zeroed, then written through one inserter lane per thread; `weights`, default K alone)
  /// and active constraint rows (if C, overwritten); `rate_forces`: M a, C v and M v alone.
  AssemblyResult assemble(const FieldView& fields, const StepContext& ctx, std::span<double> f_int,
                          MatrixInserter* K, ConstraintBlock* C,
                          const OperatorWeights& weights = {}, const RateForces& rate_forces = {});
  /// Equivalent nodal loads of distributed loads, added to f_ext (per slot); solution-dependent
  /// loads add -df/du to K if given (only its symmetric part when `symmetrize`).
  void assemble_loads(std::span<const ActiveLoad> loads, const FieldView& fields,
                      const StepContext& ctx, std::span<double> f_ext, MatrixInserter* K,
                      bool symmetrize = true);
  /// Eigenvalue buckling's initial-stress matrix of the perturbation du (per slot) at the given
  /// state into K over equations (zeroed first): each element's ElementKernel::stress_stiffness,
  /// or the central difference of its NLGEOM tangent along du where it has none
  /// (assembler_stress.cpp).
  void stress_stiffness(const FieldView& fields, const StepContext& ctx, std::span<const double> du,
                        MatrixInserter& K);
  /// Residual of one element at the given state (no tangent); out has n_dofs entries.
  void element_residual(ElemId e, const FieldView& fields, const StepContext& ctx,
                        std::vector<double>& out, std::vector<LocalIndex>& slots);
  /// Largest fraction (0, 1] of the correction du (per slot) that every element accepts
  /// (ElementKernel::step_limit).
  double step_limit(const FieldView& fields, const StepContext& ctx, std::span<const double> du);
  /// Augmented-Lagrange updates of all elements (at a converged state); returns how many changed.
  int augment(const FieldView& fields, const StepContext& ctx);
  /// Per-slot diagonal of the tangent of all elements (optionally without gap elements).
  std::vector<double> diagonal_stiffness(const FieldView& fields, const StepContext& ctx,
                                         bool skip_gaps);
  /// Output quantities of one element at the given state.
  void recover(ElemId e, const FieldView& fields, const StepContext& ctx, ElementRecovery& out);

 private:
  /// The elements [b, e) of one block into f, K's lane and the thread's constraint rows.
  void assemble_chunk(ElementBlock& block, std::size_t b, std::size_t e, int thread,
                      const FieldView& fields, const StepContext& ctx, std::span<double> f,
                      MatrixInserter* K, int lane, bool rows, const OperatorWeights& w,
                      const RateForces& rate_out, AssemblyResult& res);

  Discretization& _disc;
  int _threads;
  std::vector<ElementGather> _scratch;
  std::vector<ConstraintBlock> _thread_constraints;
  std::vector<std::vector<double>> _thread_f;
  /// per thread and rate force (M a, C v, M v): the sums of multi-threaded blocks
  std::vector<std::array<std::vector<double>, 3>> _thread_rates;
  std::vector<std::array<std::vector<double>, 3>> _rate_scratch; ///< per thread: one element's
};

/// Threads to use by default: min(hardware threads / the run's processes on this machine, 2), at
/// least 1 (GAPFEM_THREADS, read by the application layer, overrides it: AnalysisOptions::threads).
int default_thread_count(int ranks_here = 1);

} // namespace gapfem
