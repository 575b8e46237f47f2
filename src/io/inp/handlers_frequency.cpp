// *FREQUENCY: natural frequency extraction about the base state (a linear perturbation step;
// docs/theory/frequency.md). gapfem runs every EIGENSOLVER with its shift-invert Lanczos method,
// so the data line is read in the layout of the solver the deck names.
#include "io/inp/handlers.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

/// A frequency field: positive or zero, cycles per time.
std::optional<double> frequency_field(const FieldReader& r, std::size_t i, const char* what) {
  const auto f = r.opt_real(i, what);
  if (f && !(*f >= 0.0))
    r.fail(fmt::format("field {} ({})", i + 1, what),
           fmt::format("a frequency is given in cycles per time and must not be negative, not {}",
                       *f));
  return f;
}

/// The data line of each solver (Abaqus Keywords Reference, *FREQUENCY):
///   LANCZOS:  count, minimum frequency, maximum frequency, shift point (cycles/time)^2, block
///             size, block steps
///   AMS:      count, minimum frequency, maximum frequency, ...
///   SUBSPACE: count, maximum frequency, shift point (cycles/time)^2, vectors, iterations
/// CalculiX: count, lower frequency, upper frequency (its Lanczos layout).
void read_frequency_line(const FieldReader& r, FrequencySettings& f) {
  const auto count = r.integer_or(0, 0, "number of eigenvalues", 0, 100000);
  f.count = static_cast<int>(count);
  if (f.solver == FrequencySettings::Solver::Subspace) {
    r.at_most(5, "number of eigenvalues, maximum frequency, shift, vectors, iterations");
    f.max_frequency = frequency_field(r, 1, "maximum frequency");
    if (const auto s = r.opt_real(2, "shift point (cycles/time)^2")) {
      if (*s < 0.0)
        r.fail("field 3 (shift point)", "the shift (cycles/time)^2 must not be negative");
      f.shift = std::sqrt(*s);
    }
    return;
  }
  r.at_most(7, "number of eigenvalues, minimum frequency, maximum frequency, shift point, block "
               "size, block steps");
  f.min_frequency = frequency_field(r, 1, "minimum frequency");
  f.max_frequency = frequency_field(r, 2, "maximum frequency");
  if (const auto sh = r.opt_real(3, "shift point (cycles/time)^2")) {
    if (*sh < 0.0)
      r.fail("field 4 (shift point)", "the shift (cycles/time)^2 must not be negative");
    f.shift = std::sqrt(*sh);
  }
  if (f.min_frequency && f.max_frequency && *f.min_frequency > *f.max_frequency)
    r.fail("field 2 (minimum frequency)",
           fmt::format("the minimum frequency {} is above the maximum frequency {}",
                       *f.min_frequency, *f.max_frequency));
}

} // namespace

void handle_frequency(BuildState& s, const Keyword& kw) {
  set_procedure(s, kw, Procedure::Frequency);
  FrequencySettings& f = s.step.frequency;
  f.loc = kw.loc;
  reject_param(kw, "ACOUSTIC COUPLING", "gapfem has no acoustic elements");
  reject_param(kw, "RESIDUAL MODES",
               "residual modes belong to the modal procedures that follow a frequency step; "
               "remove RESIDUAL MODES");
  reject_param(kw, "SIM", "gapfem's modes are written to its own results files; remove SIM");
  for (const char* p : {"STORAGE", "GLOBAL", "CYCMPC", "SOLVER", "MATRIX STORAGE"})
    if (kw.has(p)) {
      s.warn(kw.loc, fmt::format("*FREQUENCY, {}: a CalculiX option of its own solver and files; "
                                 "gapfem's Lanczos method does not use it",
                                 p));
      break;
    }
  f.solver = static_cast<FrequencySettings::Solver>(
      enum_param(kw, "EIGENSOLVER", {"LANCZOS", "SUBSPACE", "AMS"}, 0));
  if (kw.has("NORMALIZATION"))
    f.mass_normalized = enum_param(kw, "NORMALIZATION", {"DISPLACEMENT", "MASS"}, 0) == 1;
  for (const DataLine& line : kw.data) {
    if (line.blank()) continue;
    read_frequency_line(s.reader(kw, line), f);
    break; // one data line: the parser reports any further ones
  }
  if (f.count == 0 && !f.max_frequency)
    throw InputError(kw.loc, "",
                     "give the number of eigenvalues (field 1 of the data line) or a maximum "
                     "frequency: without either the extraction has no end");
}

} // namespace gapfem::inp
