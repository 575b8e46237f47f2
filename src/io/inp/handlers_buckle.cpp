// *BUCKLE: eigenvalue buckling about the base state (a linear perturbation step;
// docs/theory/buckling.md). gapfem runs both EIGENSOLVERs with its Lanczos method, so the data line
// is read in the layout of the solver the deck names.
#include "io/inp/handlers.hpp"

#include <fmt/format.h>

namespace gapfem::inp {
namespace {

/// The data line of each solver (Abaqus Keywords Reference, *BUCKLE):
///   SUBSPACE: count, maximum eigenvalue of interest, vectors, iterations
///   LANCZOS:  count, minimum eigenvalue, maximum eigenvalue, block size, block steps
/// CalculiX (SOLVER=): count, accuracy, Lanczos vectors, iterations.
void read_buckle_line(const FieldReader& r, BuckleSettings& b, bool calculix) {
  // SUBSPACE and CalculiX need the count; LANCZOS may leave it blank (every one in the range)
  const bool required = calculix || b.solver == BuckleSettings::Solver::Subspace;
  b.count = static_cast<int>(required ? r.integer(0, "number of eigenvalues", 1, 100000)
                                      : r.integer_or(0, 0, "number of eigenvalues", 0, 100000));
  if (calculix) {
    r.at_most(4, "number of buckling factors, accuracy, Lanczos vectors, iterations");
    return;
  }
  if (b.solver == BuckleSettings::Solver::Subspace) {
    r.at_most(4, "number of eigenvalues, maximum eigenvalue, vectors, iterations");
    b.max_eigenvalue = r.opt_real(1, "maximum eigenvalue of interest");
    b.vectors = static_cast<int>(r.integer_or(2, 0, "number of vectors", 0, 100000));
    b.iterations = static_cast<int>(r.integer_or(3, 0, "maximum iterations", 0, 100000000));
    return;
  }
  r.at_most(5, "number of eigenvalues, minimum eigenvalue, maximum eigenvalue, block size, "
               "block steps");
  b.min_eigenvalue = r.opt_real(1, "minimum eigenvalue of interest");
  b.max_eigenvalue = r.opt_real(2, "maximum eigenvalue of interest");
  if (b.min_eigenvalue && b.max_eigenvalue && *b.min_eigenvalue > *b.max_eigenvalue)
    r.fail("field 2 (minimum eigenvalue)",
           fmt::format("the minimum eigenvalue {} is above the maximum eigenvalue {}",
                       *b.min_eigenvalue, *b.max_eigenvalue));
  if (b.count == 0 && !b.max_eigenvalue)
    r.fail("field 1 (number of eigenvalues)",
           "give the number of eigenvalues, or a maximum eigenvalue: without either the "
           "extraction has no end");
}

} // namespace

void handle_buckle(BuildState& s, const Keyword& kw) {
  set_procedure(s, kw, Procedure::Buckle);
  BuckleSettings& b = s.step.buckle;
  b.loc = kw.loc;
  reject_param(kw, "SIM", "gapfem's modes are written to its own results files; remove SIM");
  const bool calculix = kw.has("SOLVER");
  if (calculix)
    s.warn(kw.loc, "*BUCKLE, SOLVER=: a CalculiX option of its own solver; gapfem reads the data "
                   "line in CalculiX's layout (count, accuracy, vectors, iterations) and uses its "
                   "Lanczos method");
  b.solver = static_cast<BuckleSettings::Solver>(
      enum_param(kw, "EIGENSOLVER", {"SUBSPACE", "LANCZOS"}, 0));
  bool given = false;
  for (const DataLine& line : kw.data) {
    if (line.blank()) continue;
    read_buckle_line(s.reader(kw, line), b, calculix);
    given = true;
    break; // one data line: the parser reports any further ones
  }
  if (!given || (b.count == 0 && !b.max_eigenvalue))
    throw InputError(kw.loc, "",
                     "give the number of eigenvalues in field 1 of the data line (e.g. 1 for the "
                     "lowest buckling load)");
}

} // namespace gapfem::inp
