// *CONTROLS: Abaqus/Standard's solution controls. PARAMETERS=FIELD sets the convergence criteria
// of one field (or all: FIELD=GLOBAL), PARAMETERS=TIME INCREMENTATION the iteration counts and
// factors of the automatic incrementation, RESET the defaults; ANALYSIS=DISCONTINUOUS allows more
// iterations before the divergence check, as in Abaqus. The values that map onto gapfem's Newton
// and increment control are used; the others are accepted with a warning that they have no effect.
// The controls stay in effect in later steps until changed or reset.
#include "io/inp/handlers.hpp"

#include <fmt/format.h>

namespace gapfem::inp {
namespace {

struct Slot {
  const char* symbol;
  bool used; ///< gapfem honours it
};

// Abaqus's field order of PARAMETERS=FIELD.
constexpr Slot kFieldSlots[] = {{"R_n", true},        {"C_n", true},       {"q_0", true},
                                {"q_u", true},        {"R_P", false},      {"epsilon", true},
                                {"C_epsilon", false}, {"epsilon_l", true}, {"epsilon_d", false}};
// PARAMETERS=TIME INCREMENTATION, first line and second line.
constexpr Slot kIterationSlots[] = {
    {"I_0", true},      {"I_R", false},  {"I_P", false}, {"I_C", true},  {"I_L", true},
    {"I_G", true},      {"I_S", true},   {"I_A", true},  {"I_J", false}, {"I_T", false},
    {"I_S^max", false}, {"I_PD", false}, {"I_AD", false}};
constexpr Slot kFactorSlots[] = {{"D_f", true},  {"D_C", false}, {"D_B", true},  {"D_A", true},
                                 {"D_S", false}, {"D_H", false}, {"D_D", true},  {"W_G", false},
                                 {"D_G", false}, {"D_M", false}, {"D_PD", false}};

/// Warns once per keyword about the given fields gapfem does not use.
void warn_unused(BuildState& s, const FieldReader& r, std::span<const Slot> slots,
                 std::string_view what) {
  std::string unused;
  for (std::size_t i = 0; i < slots.size(); ++i)
    if (!r.blank(i) && !slots[i].used)
      unused += fmt::format("{}{}", unused.empty() ? "" : ", ", slots[i].symbol);
  if (!unused.empty())
    s.warn(r.loc(), fmt::format("*CONTROLS, PARAMETERS={}: {} ha{} no effect in gapfem (it has no "
                                "logarithmic rate check, no alternative residual criterion and no "
                                "dynamic procedures); the value is ignored",
                                what, unused, unused.find(',') == std::string::npos ? "s" : "ve"));
}

double positive(const FieldReader& r, std::size_t i, double def, const Slot& slot) {
  const double v = r.real_or(i, def, slot.symbol);
  if (!(v > 0))
    r.fail(fmt::format("field {} ({})", i + 1, slot.symbol),
           fmt::format("must be positive, not {}; leave the field blank for the default", v));
  return v;
}

int count(const FieldReader& r, std::size_t i, int def, const Slot& slot) {
  return static_cast<int>(r.integer_or(i, def, slot.symbol, 1, 1000000));
}

double factor(const FieldReader& r, std::size_t i, double def, const Slot& slot, bool above_one) {
  const double v = r.real_or(i, def, slot.symbol);
  if (above_one ? !(v > 1.0) : !(v > 0.0 && v < 1.0))
    r.fail(fmt::format("field {} ({})", i + 1, slot.symbol),
           fmt::format("must be {}, not {}", above_one ? "larger than 1" : "between 0 and 1", v));
  return v;
}

void read_field(BuildState& s, const Keyword& kw, SolutionControls& c) {
  const int which =
      enum_param(kw, "FIELD", {"GLOBAL", "DISPLACEMENT", "ROTATION", "TEMPERATURE"}, 0);
  const DataLine* line = nullptr;
  for (const DataLine& l : kw.data)
    if (!l.blank()) { // (a line of only commas: the defaults)
      l.read = true;
      if (line)
        s.error(s.loc(kw, l), "", "*CONTROLS, PARAMETERS=FIELD has one data line; remove this one");
      else
        line = &l;
    }
  if (!line) return; // no data line: the defaults
  const FieldReader r = s.reader(kw, *line);
  r.at_most(std::size(kFieldSlots),
            "R_n, C_n, q_0, q_u, R_P, epsilon, C_epsilon, epsilon_l, epsilon_d");
  warn_unused(s, r, kFieldSlots, "FIELD");
  auto apply = [&](SolutionControls::Field& f) {
    f.residual = positive(r, 0, f.residual, kFieldSlots[0]);
    f.correction = positive(r, 1, f.correction, kFieldSlots[1]);
    f.initial_flux = positive(r, 2, f.initial_flux, kFieldSlots[2]);
    if (!r.blank(3)) f.user_flux = positive(r, 3, 1.0, kFieldSlots[3]);
    f.zero_flux = positive(r, 5, f.zero_flux, kFieldSlots[5]);
    f.linear = positive(r, 7, f.linear, kFieldSlots[7]);
  };
  if (which == 0)
    for (auto& f : c.field) apply(f);
  else
    apply(c.field[static_cast<std::size_t>(which - 1)]);
}

void read_time_incrementation(BuildState& s, const Keyword& kw, SolutionControls& c) {
  int index = 0;
  for (const DataLine& l : kw.data) {
    if (l.blank()) continue; // (a line of only commas keeps its place: the defaults)
    if (index == 3) break;   // three lines at most: the parser reports any further ones
    const FieldReader r = s.reader(kw, l);
    if (index == 0) {
      r.at_most(std::size(kIterationSlots), "I_0, I_R, I_P, I_C, I_L, I_G, I_S, I_A, I_J, I_T, …");
      warn_unused(s, r, kIterationSlots, "TIME INCREMENTATION");
      c.divergence_check_after = count(r, 0, c.divergence_check_after, kIterationSlots[0]);
      c.max_iterations = count(r, 3, c.max_iterations, kIterationSlots[3]);
      c.hard_iterations = count(r, 4, c.hard_iterations, kIterationSlots[4]);
      c.easy_iterations = count(r, 5, c.easy_iterations, kIterationSlots[5]);
      c.max_severe_iterations = count(r, 6, c.max_severe_iterations, kIterationSlots[6]);
      c.max_attempts = count(r, 7, c.max_attempts, kIterationSlots[7]);
    } else if (index == 1) {
      r.at_most(std::size(kFactorSlots), "D_f, D_C, D_B, D_A, D_S, D_H, D_D, W_G, …");
      warn_unused(s, r, kFactorSlots, "TIME INCREMENTATION");
      c.cutback = factor(r, 0, c.cutback, kFactorSlots[0], false);
      c.shrink = factor(r, 2, c.shrink, kFactorSlots[2], false);
      c.deltmx_cutback = factor(r, 3, c.deltmx_cutback, kFactorSlots[3], false);
      c.growth = factor(r, 6, c.growth, kFactorSlots[6], true);
    } else {
      s.warn(r.loc(), "*CONTROLS, PARAMETERS=TIME INCREMENTATION: the third data line (factors "
                      "for dynamic and contact-specific cut-backs) has no effect in gapfem");
    }
    ++index;
  }
}

} // namespace

void handle_controls(BuildState& s, const Keyword& kw) {
  SolutionControls& c = s.step.controls;
  if (kw.has("RESET")) {
    if (kw.has("PARAMETERS"))
      throw InputError(kw.loc, "RESET",
                       "RESET and PARAMETERS exclude each other; use two *CONTROLS keywords");
    c = SolutionControls{};
  }
  if (kw.has("ANALYSIS")) {
    enum_param(kw, "ANALYSIS", {"DISCONTINUOUS"}, 0);
    // Abaqus: more iterations before the divergence (and rate) checks for discontinuous problems
    c.divergence_check_after = 8;
  }
  if (!kw.has("PARAMETERS")) {
    if (!kw.has("RESET") && !kw.has("ANALYSIS"))
      throw InputError(kw.loc, "",
                       "*CONTROLS needs PARAMETERS=FIELD or TIME INCREMENTATION, ANALYSIS="
                       "DISCONTINUOUS, or RESET");
    return;
  }
  switch (enum_param(kw, "PARAMETERS", {"FIELD", "TIME INCREMENTATION", "LINE SEARCH"}, 0)) {
  case 0:
    read_field(s, kw, c);
    break;
  case 1:
    read_time_incrementation(s, kw, c);
    break;
  default:
    kw.mark_read(); // (ignored with this warning)
    s.warn(kw.loc, "*CONTROLS, PARAMETERS=LINE SEARCH has no effect in gapfem: its Newton method "
                   "has no line search (contact and friction use active-set and stick predictors "
                   "instead)");
    break;
  }
}

void handle_restart(BuildState& s, const Keyword& kw) {
  const bool read = kw.has("READ"), write = kw.has("WRITE");
  if (read == write)
    throw InputError(kw.loc, "",
                     "give WRITE (write restart data, in model or history data) or "
                     "READ (continue an earlier job, first in a restart deck)");
  auto positive = [&](std::string_view name, std::string_view what) -> std::optional<int> {
    const auto v = int_param(kw, name, what, 0, kMaxInt);
    return v ? std::optional<int>(static_cast<int>(*v)) : std::nullopt;
  };
  if (read) {
    for (const char* p : {"FREQUENCY", "NUMBER INTERVAL", "OVERLAY", "TIME MARKS"})
      if (kw.has(p))
        throw InputError(kw.loc, p,
                         "belongs to *RESTART, WRITE; *RESTART, READ takes STEP, INC "
                         "and END STEP");
    if (s.in_step)
      throw InputError(kw.loc, "READ",
                       "*RESTART, READ comes before the first *STEP of a restart deck (the steps "
                       "after it are the new ones)");
    RestartRead r;
    r.step = positive("STEP", "the step to continue from").value_or(0);
    r.increment = positive("INC", "the increment to continue from").value_or(0);
    r.end_step = kw.has("END STEP");
    r.loc = kw.loc;
    if (s.model.restart_read)
      throw InputError(kw.loc, "READ",
                       "a deck continues one earlier job: give *RESTART, READ once");
    s.model.restart_read = r;
    return;
  }
  for (const char* p : {"STEP", "INC", "END STEP"})
    if (kw.has(p))
      throw InputError(kw.loc, p,
                       "belongs to *RESTART, READ; *RESTART, WRITE takes FREQUENCY or "
                       "NUMBER INTERVAL, OVERLAY and TIME MARKS");
  RestartWrite w;
  w.loc = kw.loc;
  const auto frequency =
      positive("FREQUENCY", "the restart frequency (every n-th increment; 0: none)");
  const auto interval =
      positive("NUMBER INTERVAL", "the number of restart intervals per step (0: none)");
  if (frequency && interval)
    throw InputError(kw.loc, "NUMBER INTERVAL",
                     "give FREQUENCY (every n-th increment) or NUMBER INTERVAL (n times per step), "
                     "not both");
  if (interval)
    w.number_interval = *interval;
  else
    w.frequency = frequency.value_or(1); // Abaqus/Standard's default
  w.overlay = kw.has("OVERLAY");
  if (kw.has("TIME MARKS") && yes_no_param(kw, "TIME MARKS", false))
    throw InputError(kw.loc, "TIME MARKS=YES",
                     "gapfem writes NUMBER INTERVAL restart data at the first increment that "
                     "reaches each interval and does not shorten increments to end exactly on "
                     "it; use TIME MARKS=NO");
  (s.in_step ? s.step.restart : s.model_restart) = w;
}

} // namespace gapfem::inp
