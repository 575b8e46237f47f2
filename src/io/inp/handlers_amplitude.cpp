// *AMPLITUDE: named time variations of loads and boundary conditions. DEFINITION=TABULAR,
// EQUALLY SPACED, SMOOTH STEP, PERIODIC, MODULATED and DECAY with TIME, VALUE, INPUT and
// SCALEX/SCALEY/SHIFTX/SHIFTY, as the Abaqus Keywords Reference (*AMPLITUDE) and the Analysis
// User's Guide ("Amplitude curves") define them (docs/theory/dynamics.md, "Base motion").
#include "io/inp/handlers.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

using Kind = Amplitude::Kind;

/// DEFINITION=: the kind, EQUALLY SPACED flagged; the Abaqus definitions gapfem lacks refused.
Kind definition(const Keyword& kw, bool& equally_spaced) {
  equally_spaced = false;
  if (!kw.has("DEFINITION")) return Kind::Tabular;
  const std::string v = canonical(param_value(kw, "DEFINITION", true));
  if (v == "TABULAR") return Kind::Tabular;
  if (v == "EQUALLYSPACED") {
    equally_spaced = true;
    return Kind::Tabular;
  }
  if (v == "SMOOTHSTEP") return Kind::SmoothStep;
  if (v == "PERIODIC") return Kind::Periodic;
  if (v == "MODULATED") return Kind::Modulated;
  if (v == "DECAY") return Kind::Decay;
  const bool abaqus = v == "SOLUTIONDEPENDENT" || v == "BUBBLE" || v == "USER" || v == "ACTUATOR" ||
                      v == "PSDDEFINITION" || v == "SPECTRUM";
  throw InputError(kw.loc, param_text(kw, "DEFINITION"),
                   fmt::format("{}; gapfem has DEFINITION=TABULAR, EQUALLY SPACED, SMOOTH STEP, "
                               "PERIODIC, MODULATED and DECAY",
                               abaqus ? "this Abaqus amplitude definition is not supported"
                                      : "this is not an amplitude definition"));
}

/// The numbers of a data line (trailing blanks dropped), `max` at most.
std::vector<double> numbers(const FieldReader& r, std::size_t max, std::string_view layout,
                            std::string_view what) {
  r.at_most(max, layout);
  std::size_t last = r.line().fields.size();
  while (last > 0 && r.line().fields[last - 1].empty()) --last;
  std::vector<double> v(last);
  for (std::size_t i = 0; i < last; ++i) v[i] = r.real(i, what);
  return v;
}

/// TABULAR and SMOOTH STEP: time, value pairs, up to four a line, times increasing strictly.
void read_pairs(BuildState& s, const Keyword& kw, Amplitude& a, bool& ok) {
  const int failed = for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(8, "up to four pairs of time, amplitude");
    std::size_t last = line.fields.size();
    while (last > 0 && line.fields[last - 1].empty()) --last;
    if (last % 2 != 0)
      r.fail("", "give time, amplitude pairs: this line has an odd number of values");
    for (std::size_t i = 0; i < last; i += 2) {
      const double t = r.real(i, "time");
      const double v = r.real(i + 1, "amplitude");
      if (!a.t.empty() && !(t > a.t.back()))
        r.fail(fmt::format("time {}", t),
               fmt::format("amplitude times must increase strictly; {} follows {}", t, a.t.back()));
      a.t.push_back(t);
      a.a.push_back(v);
    }
  });
  ok = ok && failed == 0;
}

/// EQUALLY SPACED: values a1, a2, … (up to eight a line) at BEGIN, BEGIN + FIXED INTERVAL, ….
void read_equally_spaced(BuildState& s, const Keyword& kw, Amplitude& a, bool& ok) {
  const std::optional<double> dt = real_param(kw, "FIXED INTERVAL");
  if (!dt)
    throw InputError(kw.loc, "DEFINITION=EQUALLY SPACED",
                     "FIXED INTERVAL= is required: give the time between the values");
  if (!(*dt > 0) || !std::isfinite(*dt))
    throw InputError(kw.loc, param_text(kw, "FIXED INTERVAL"),
                     "the fixed interval must be a positive time");
  const double begin = real_param(kw, "BEGIN").value_or(0.0);
  const int failed = for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    for (double v : numbers(r, 8, "up to eight amplitude values", "amplitude")) {
      a.t.push_back(begin + *dt * static_cast<double>(a.a.size()));
      a.a.push_back(v);
    }
  });
  ok = failed == 0;
}

/// PERIODIC: N, omega, t0, A0; then A1, B1, A2, B2, … (up to four pairs a line), N pairs.
void read_periodic(BuildState& s, const Keyword& kw, Amplitude& a, bool& ok) {
  long long n = -1;
  bool first = true;
  const int failed = for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    if (first) {
      first = false;
      r.at_most(4, "N, circular frequency, starting time, initial amplitude");
      n = r.integer(0, "number of terms N", 0, 1000000);
      a.omega = r.real(1, "circular frequency");
      a.t0 = r.real_or(2, 0.0, "starting time");
      a.a0 = r.real_or(3, 0.0, "initial amplitude");
      return;
    }
    const std::vector<double> v = numbers(r, 8, "up to four pairs of A_n, B_n", "coefficient");
    if (v.size() % 2 != 0) {
      ok = false;
      r.fail("", "give A_n, B_n pairs: this line has an odd number of values");
    }
    a.coef.insert(a.coef.end(), v.begin(), v.end());
  });
  if (!ok || failed > 0) return;
  if (n < 0)
    throw InputError(kw.loc, fmt::format("amplitude {}", a.name),
                     "no data: give N, circular frequency, starting time, initial amplitude, then "
                     "the N pairs A_n, B_n");
  if (static_cast<long long>(a.coef.size()) != 2 * n)
    throw InputError(kw.loc, fmt::format("amplitude {}", a.name),
                     fmt::format("N = {} terms are announced but {} pairs A_n, B_n are given", n,
                                 a.coef.size() / 2));
}

/// MODULATED (A0, A, t0, omega1, omega2) and DECAY (A0, A, t0, td): one line.
void read_function(BuildState& s, const Keyword& kw, Amplitude& a) {
  const bool modulated = a.kind == Kind::Modulated;
  int lines = 0;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    if (lines++ > 0)
      r.fail("", modulated ? "DEFINITION=MODULATED takes one data line"
                           : "DEFINITION=DECAY "
                             "takes one data line");
    r.at_most(modulated ? 5 : 4, modulated ? "A0, A, t0, omega1, omega2" : "A0, A, t0, td");
    a.a0 = r.real_or(0, 0.0, "initial amplitude A0");
    a.amp = r.real(1, "amplitude A");
    a.t0 = r.real_or(2, 0.0, "starting time t0");
    if (modulated) {
      a.omega = r.real(3, "circular frequency omega1");
      a.omega2 = r.real(4, "circular frequency omega2");
    } else {
      a.td = r.real(3, "decay time td");
      if (!(a.td > 0)) r.fail(fmt::format("td {}", a.td), "the decay time td must be positive");
    }
  });
  if (lines == 0)
    throw InputError(kw.loc, fmt::format("amplitude {}", a.name),
                     modulated ? "no data line: give A0, A, t0, omega1, omega2"
                               : "no data line: give A0, A, t0, td");
}

/// SCALEX, SCALEY, SHIFTX, SHIFTY; FIXED INTERVAL and BEGIN only with EQUALLY SPACED.
void read_transform(const Keyword& kw, Amplitude& a, bool equally_spaced) {
  if (!equally_spaced)
    for (const char* p : {"FIXED INTERVAL", "BEGIN"})
      if (kw.has(p))
        throw InputError(kw.loc, p, fmt::format("{} belongs to DEFINITION=EQUALLY SPACED", p));
  reject_param(kw, "SMOOTH",
               "gapfem interpolates tabular amplitudes linearly and does not smooth them; remove "
               "SMOOTH, or use DEFINITION=SMOOTH STEP for a smooth curve");
  a.scale_x = real_param(kw, "SCALEX").value_or(1.0);
  a.scale_y = real_param(kw, "SCALEY").value_or(1.0);
  a.shift_x = real_param(kw, "SHIFTX").value_or(0.0);
  a.shift_y = real_param(kw, "SHIFTY").value_or(0.0);
  if (!(a.scale_x > 0) || !std::isfinite(a.scale_x))
    throw InputError(kw.loc, param_text(kw, "SCALEX"), "the time scale must be positive");
}

} // namespace

void handle_amplitude(BuildState& s, const Keyword& kw) {
  const std::string name = name_param(kw, "NAME", true);
  if (const auto it = s.amplitude_index.find(name); it != s.amplitude_index.end())
    throw InputError(kw.loc, fmt::format("amplitude {}", name),
                     fmt::format("this amplitude is defined twice (first at {}); use another NAME",
                                 s.model.amplitudes[it->second].loc.str()));
  Amplitude a;
  a.name = name;
  a.loc = kw.loc;
  a.time = enum_param(kw, "TIME", {"STEP TIME", "TOTAL TIME"}, 0) == 0 ? Amplitude::TimeBase::Step
                                                                       : Amplitude::TimeBase::Total;
  a.absolute = enum_param(kw, "VALUE", {"RELATIVE", "ABSOLUTE"}, 0) == 1;
  bool equally_spaced = false;
  a.kind = definition(kw, equally_spaced);
  read_transform(kw, a, equally_spaced);
  bool ok = true;
  switch (a.kind) {
  case Kind::Tabular:
  case Kind::SmoothStep:
    if (equally_spaced)
      read_equally_spaced(s, kw, a, ok);
    else
      read_pairs(s, kw, a, ok);
    if (a.t.empty() && ok)
      throw InputError(
          kw.loc, fmt::format("amplitude {}", name),
          equally_spaced ? "no amplitude values are given; add data lines a1, a2, …"
                         : "no time, amplitude pairs are given; add data lines t1, a1, t2, a2, …");
    break;
  case Kind::Periodic:
    read_periodic(s, kw, a, ok);
    break;
  case Kind::Modulated:
  case Kind::Decay:
    read_function(s, kw, a);
    break;
  }
  a.finish();
  s.amplitude_index[name] = static_cast<int>(s.model.amplitudes.size());
  s.model.amplitudes.push_back(std::move(a));
}

} // namespace gapfem::inp
