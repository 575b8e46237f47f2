// job.dat for *FREQUENCY steps (dat_writer.hpp): the step's header, Abaqus's eigenvalue,
// participation factor and effective mass tables, and the header of each mode's node output.
#include "model/model.hpp"
#include "output/dat_writer.hpp"

#include <cmath>

namespace gapfem {

namespace {

/// A number as Abaqus's tables show it: plain when moderate, else 5 digits with an exponent.
std::string number(double v) {
  const double a = std::abs(v);
  if (a == 0.0) return "0.0000";
  if (a >= 1e-2 && a < 1e5) return fmt::format("{:#.5G}", v);
  return fmt::format("{:.5E}", v);
}

/// The six direction columns of a row.
void direction_row(fmt::memory_buffer& buf, std::string_view label,
                   const std::array<double, 6>& v) {
  auto out = std::back_inserter(buf);
  fmt::format_to(out, "{:>8}", label);
  for (double x : v) fmt::format_to(out, " {:>12}", number(x));
  fmt::format_to(out, "\n");
}

constexpr const char* kDirections =
    " MODE NO  X-COMPONENT  Y-COMPONENT  Z-COMPONENT   X-ROTATION   Y-ROTATION   Z-ROTATION\n\n";

} // namespace

void DatWriter::write_perturbation_header(const Step& step) {
  auto out = std::back_inserter(_out.buffer());
  if (step.procedure == Procedure::ResponseSpectrum) {
    const char* sums[] = {"ABS", "SRSS", "CQC", "NRL", "TENP", "DSC", "GRP"};
    fmt::format_to(out, "{:>10}RESPONSE SPECTRUM: PEAK RESPONSE FROM THE MODES (SUM={}, COMP={})\n",
                   "", sums[static_cast<int>(step.spectrum.sum)],
                   step.spectrum.algebraic ? "ALGEBRAIC" : "SRSS");
    fmt::format_to(out, "{:>10}THE NODE OUTPUT BELOW IS THE PEAK (NON-NEGATIVE) RESPONSE\n", "");
    return;
  }
  if (step.procedure == Procedure::SteadyStateDynamics) {
    const SteadyStateSettings& ss = step.steady_state;
    fmt::format_to(out, "{:>10}STEADY STATE DYNAMICS: HARMONIC RESPONSE ON THE MODES\n", "");
    fmt::format_to(out, "{:>10}FREQUENCY SCALE {}, POINTS SPREAD OVER {}\n", "",
                   ss.logarithmic ? "LOGARITHMIC" : "LINEAR",
                   ss.interval == SteadyStateSettings::Interval::Range
                       ? "THE RANGE"
                       : "THE INTERVALS BETWEEN EIGENFREQUENCIES");
    return;
  }
  if (step.procedure == Procedure::ModalDynamic) {
    fmt::format_to(out, "{:>10}MODAL DYNAMIC: TRANSIENT RESPONSE ON THE MODES FROM REST\n", "");
    fmt::format_to(out, "{:>10}TIME INCREMENT {:>38.4E}\n", "", step.modal_dynamic.dt);
    fmt::format_to(out, "{:>10}TIME PERIOD {:>41.4E}\n", "", step.modal_dynamic.period);
    return;
  }
  if (step.procedure == Procedure::Static) {
    fmt::format_to(out, "{:>10}STATIC LINEAR PERTURBATION ABOUT THE BASE STATE\n", "");
    fmt::format_to(out, "{:>10}THE OUTPUT BELOW IS THE PERTURBATION RESPONSE ALONE\n", "");
    return;
  }
  if (step.procedure == Procedure::Buckle) {
    const BuckleSettings& b = step.buckle;
    fmt::format_to(out,
                   "{:>10}EIGENVALUE BUCKLING PREDICTION (LINEAR PERTURBATION ABOUT THE BASE "
                   "STATE)\n",
                   "");
    fmt::format_to(out, "{:>10}EIGENSOLVER={} (LANCZOS)\n", "",
                   b.solver == BuckleSettings::Solver::Lanczos ? "LANCZOS" : "SUBSPACE");
    if (b.count > 0) fmt::format_to(out, "{:>10}NUMBER OF EIGENVALUES {:>31}\n", "", b.count);
    if (b.min_eigenvalue)
      fmt::format_to(out, "{:>10}MINIMUM EIGENVALUE OF INTEREST {:>22.4E}\n", "",
                     *b.min_eigenvalue);
    if (b.max_eigenvalue)
      fmt::format_to(out, "{:>10}MAXIMUM EIGENVALUE OF INTEREST {:>22.4E}\n", "",
                     *b.max_eigenvalue);
    fmt::format_to(out, "{:>10}EIGENVECTORS NORMALIZED BY LARGEST DISPLACEMENT OR ROTATION\n", "");
    fmt::format_to(out,
                   "{:>10}BUCKLING LOADS ARE THE BASE STATE LOADS PLUS EIGENVALUE TIMES THE "
                   "LOADS OF THIS STEP\n",
                   "");
    return;
  }
  const FrequencySettings& f = step.frequency;
  const char* solver[] = {"LANCZOS", "SUBSPACE", "AMS"};
  fmt::format_to(out, "{:>10}EIGENVALUE EXTRACTION (LINEAR PERTURBATION ABOUT THE BASE STATE)\n",
                 "");
  fmt::format_to(out, "{:>10}EIGENSOLVER={} (SHIFT-INVERT LANCZOS)\n", "",
                 solver[static_cast<int>(f.solver)]);
  if (f.count > 0)
    fmt::format_to(out, "{:>10}NUMBER OF EIGENVALUES {:>31}\n", "", f.count);
  else
    fmt::format_to(out, "{:>10}ALL EIGENVALUES IN THE FREQUENCY RANGE\n", "");
  if (f.min_frequency)
    fmt::format_to(out, "{:>10}LOWEST FREQUENCY OF INTEREST {:>24.4E}\n", "", *f.min_frequency);
  if (f.max_frequency)
    fmt::format_to(out, "{:>10}HIGHEST FREQUENCY OF INTEREST {:>23.4E}\n", "", *f.max_frequency);
  if (f.shift) fmt::format_to(out, "{:>10}SHIFT POINT (CYCLES/TIME) {:>27.4E}\n", "", *f.shift);
  fmt::format_to(out, "{:>10}EIGENVECTORS NORMALIZED BY {}\n", "",
                 f.mass_normalized ? "GENERALIZED MASS" : "LARGEST DISPLACEMENT OR ROTATION");
  if (step.nlgeom)
    fmt::format_to(out, "{:>10}INITIAL STRESS AND LOAD STIFFNESS OF THE BASE STATE (NLGEOM)\n", "");
}

void DatWriter::modes(const Model& model, int step_index, const EigenSummary& sum) {
  auto& buf = _out.buffer();
  auto out = std::back_inserter(buf);
  fmt::format_to(out, "\n\n{:>30}{}\n\n", "", output::spaced("EIGENVALUE OUTPUT"));
  if (sum.buckling) { // load multipliers: no frequencies, masses or participation
    fmt::format_to(out, " MODE NO      EIGENVALUE\n\n");
    for (const ModeInfo& m : sum.modes)
      fmt::format_to(out, "{:>8}  {:>14}\n", m.mode, number(m.eigenvalue));
    return;
  }
  fmt::format_to(out, " MODE NO      EIGENVALUE              FREQUENCY         GENERALIZED MASS"
                      "   COMPOSITE MODAL DAMPING\n");
  fmt::format_to(out, "{:>32}(RAD/TIME)   (CYCLES/TIME)\n\n", "");
  for (const ModeInfo& m : sum.modes)
    fmt::format_to(out, "{:>8}  {:>14}  {:>14}  {:>14}  {:>14}  {:>14}\n", m.mode,
                   number(m.eigenvalue), number(m.circular()), number(m.frequency()),
                   number(m.generalized_mass), number(0.0));
  fmt::format_to(out, "\n\n{:>27}{}\n\n", "", output::spaced("PARTICIPATION FACTORS"));
  fmt::format_to(out, "{}", kDirections);
  for (const ModeInfo& m : sum.modes)
    direction_row(buf, fmt::format("{}", m.mode), m.participation);
  fmt::format_to(out, "\n\n{:>27}{}\n\n", "", output::spaced("EFFECTIVE MASS"));
  fmt::format_to(out, "{}", kDirections);
  for (const ModeInfo& m : sum.modes)
    direction_row(buf, fmt::format("{}", m.mode), m.effective_mass);
  fmt::format_to(out, "\n");
  direction_row(buf, "TOTAL", sum.total_effective_mass);
  fmt::format_to(out, "\n MASS OF THE FREE DEGREES OF FREEDOM PER DIRECTION (WHAT THE EFFECTIVE "
                      "MASSES ADD UP TO OVER ALL MODES)\n");
  direction_row(buf, "", sum.model_mass);
  if (sum.rigid_body_modes > 0)
    fmt::format_to(out, "\n {} RIGID-BODY MODE(S): EIGENVALUE NEAR ZERO\n", sum.rigid_body_modes);
  (void)model;
  (void)step_index;
  _out.flush();
}

void DatWriter::write_mode_header(const Model& model, const Frame& frame) {
  auto out = std::back_inserter(_out.buffer());
  const std::string heading =
      model.heading.substr(0, std::min<std::size_t>(60, model.heading.find('\n')));
  const ModeInfo& m = *frame.mode;
  fmt::format_to(out, "\n\n{:<66}STEP {:>4}  MODE {:>4}\n\n", heading, frame.step, m.mode);
  if (model.steps[static_cast<std::size_t>(frame.step - 1)].procedure == Procedure::Buckle) {
    fmt::format_to(out, " EIGENVALUE (BUCKLING LOAD MULTIPLIER) {:>11.4E}\n", m.eigenvalue);
    return;
  }
  fmt::format_to(out,
                 " EIGENVALUE {:>11.4E},  FREQUENCY {:>11.4E} CYCLES/TIME,  GENERALIZED MASS "
                 "{:>11.4E}\n",
                 m.eigenvalue, m.frequency(), m.generalized_mass);
}

} // namespace gapfem
