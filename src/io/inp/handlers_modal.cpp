// The mode-based procedures' keywords (docs/theory/frequency.md §6): *SPECTRUM (model data),
// *RESPONSE SPECTRUM, *MODAL DAMPING and *SELECT EIGENMODES (history data).
#include "io/inp/handlers.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

/// A *SPECTRUM data line into its curves: a new curve where the damping changes (ascending),
/// frequencies ascending within a curve.
void spectrum_point(const FieldReader& r, Spectrum& sp) {
  r.at_most(3, "magnitude, frequency, damping");
  const double v = r.real(0, "magnitude");
  const double f = r.real(1, "frequency");
  const double z = r.real_or(2, 0.0, "damping");
  if (f < 0.0) r.fail("field 2 (frequency)", "a frequency (cycles per time) must not be negative");
  if (z < 0.0 || z >= 1.0)
    r.fail("field 3 (damping)", "the damping is a fraction of critical damping, from 0 to below 1");
  if (sp.curves.empty() || z != sp.curves.back().damping) {
    if (!sp.curves.empty() && z < sp.curves.back().damping)
      r.fail("field 3 (damping)",
             fmt::format("the damping values must increase from one curve to the next ({} after "
                         "{}): give the curves in ascending damping",
                         z, sp.curves.back().damping));
    sp.curves.push_back({z, {}, {}});
  }
  Spectrum::Curve& c = sp.curves.back();
  if (!c.frequency.empty() && f <= c.frequency.back())
    r.fail("field 2 (frequency)",
           fmt::format("the frequencies of a damping curve must increase ({} after {})", f,
                       c.frequency.back()));
  c.frequency.push_back(f);
  c.value.push_back(v);
}

/// The index of the spectrum `name`; InputError naming the defined ones otherwise.
int spectrum_index(const BuildState& s, const FieldReader& r, const std::string& name) {
  for (std::size_t i = 0; i < s.model.spectra.size(); ++i)
    if (s.model.spectra[i].name == name) return static_cast<int>(i);
  r.fail(
      "field 1 (spectrum)",
      fmt::format("no *SPECTRUM is named {}; define it with *SPECTRUM, NAME={} in the model data",
                  name, name));
}

/// One *RESPONSE SPECTRUM direction: spectrum, direction cosines (normalised), scale, duration.
ResponseSpectrumSettings::Direction spectrum_direction(const BuildState& s, const FieldReader& r) {
  r.at_most(6, "spectrum, X, Y, Z direction cosines, scale factor, time duration");
  ResponseSpectrumSettings::Direction d;
  d.spectrum = spectrum_index(s, r, to_upper(r.text(0)));
  double n = 0.0;
  for (int i = 0; i < 3; ++i) {
    d.cosines[i] = r.real_or(1 + i, 0.0, "direction cosine");
    n += d.cosines[i] * d.cosines[i];
  }
  if (!(n > 0.0))
    r.fail("fields 2-4 (direction)", "the direction cosines are all zero; give the direction of "
                                     "the excitation (1, 0, 0 for X)");
  for (double& c : d.cosines) c /= std::sqrt(n);
  d.scale = r.real_or(4, 1.0, "scale factor");
  d.duration = r.real_or(5, 0.0, "time duration");
  if (d.duration < 0.0) r.fail("field 6 (time duration)", "the duration must not be negative");
  return d;
}

} // namespace

void handle_spectrum(BuildState& s, const Keyword& kw) {
  Spectrum sp;
  sp.name = name_param(kw, "NAME", true);
  sp.loc = kw.loc;
  for (const Spectrum& other : s.model.spectra)
    if (other.name == sp.name)
      throw InputError(kw.loc, fmt::format("spectrum {}", sp.name),
                       fmt::format("this spectrum is defined twice (first at {}); use another NAME",
                                   other.loc.str()));
  reject_param(kw, "CREATE", "give the spectrum's values as data lines");
  reject_param(kw, "INPUT", "give the spectrum's values as data lines in the deck (or *INCLUDE)");
  sp.type = static_cast<Spectrum::Type>(
      enum_param(kw, "TYPE", {"ACCELERATION", "VELOCITY", "DISPLACEMENT", "G"}, 0));
  if (const auto g = real_param(kw, "G")) {
    if (sp.type != Spectrum::Type::G)
      throw InputError(kw.loc, param_text(kw, "G"), "G= is the acceleration of gravity of TYPE=G");
    if (!(*g > 0.0)) throw InputError(kw.loc, param_text(kw, "G"), "G must be positive");
    sp.g = *g;
  } else if (sp.type == Spectrum::Type::G) {
    throw InputError(kw.loc, "TYPE=G",
                     "a spectrum in units of g needs G=, the acceleration of gravity");
  }
  for (const DataLine& line : kw.data)
    if (!line.blank()) spectrum_point(s.reader(kw, line), sp);
  if (sp.curves.empty())
    throw InputError(kw.loc, fmt::format("spectrum {}", sp.name),
                     "no values are given; add data lines magnitude, frequency, damping");
  s.model.spectra.push_back(std::move(sp));
}

void handle_response_spectrum(BuildState& s, const Keyword& kw) {
  set_procedure(s, kw, Procedure::ResponseSpectrum);
  ResponseSpectrumSettings& rs = s.step.spectrum;
  rs.loc = kw.loc;
  const int comp = enum_param(kw, "COMP", {"SRSS", "ALGEBRAIC", "R40", "R30"}, 0);
  if (comp >= 2)
    throw InputError(kw.loc, param_text(kw, "COMP"),
                     "the 40 % and 30 % rules are not supported by gapfem; use COMP=SRSS or "
                     "ALGEBRAIC");
  rs.algebraic = comp == 1;
  rs.sum = static_cast<ModalSum>(
      enum_param(kw, "SUM", {"ABS", "SRSS", "CQC", "NRL", "TENP", "DSC", "GRP"}, 0));
  reject_param(kw, "RIGID RESPONSE",
               "the rigid (missing-mass) response is not supported by gapfem; extract enough "
               "modes for the effective masses to reach the model's mass");
  for (const DataLine& line : kw.data) {
    if (line.blank()) continue;
    const FieldReader r = s.reader(kw, line);
    if (rs.directions.size() == 3)
      r.fail("", "a response spectrum has at most three directions (three data lines)");
    rs.directions.push_back(spectrum_direction(s, r));
    const auto& a = rs.directions.front().cosines;
    const auto& b = rs.directions.back().cosines;
    if (rs.directions.size() > 1 && std::abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) > 1e-6)
      r.fail("fields 2-4 (direction)", "the directions of the second and third lines must be at "
                                       "right angles to the first (Abaqus)");
  }
  if (rs.directions.empty())
    throw InputError(kw.loc, "",
                     "no direction is given; add a data line: spectrum name, X, Y, Z direction "
                     "cosines, scale factor");
}

void handle_modal_damping(BuildState& s, const Keyword& kw) {
  ModalDamping md;
  md.loc = kw.loc;
  reject_param(kw, "STRUCTURAL",
               "structural (hysteretic) modal damping is not supported by gapfem; give viscous "
               "fractions of critical damping (at resonance a structural factor s acts as the "
               "fraction s / 2)");
  const bool composite =
      (kw.has("MODAL") && enum_param(kw, "MODAL", {"DIRECT", "COMPOSITE"}, 0) == 1) ||
      (kw.has("VISCOUS") &&
       enum_param(kw, "VISCOUS", {"FRACTION OF CRITICAL DAMPING", "COMPOSITE", "RAYLEIGH"}, 0) ==
           1);
  if (composite)
    throw InputError(kw.loc, "COMPOSITE",
                     "composite modal damping (from the materials' *DAMPING, COMPOSITE) is not "
                     "supported by gapfem; give the fractions of critical damping directly");
  if (kw.has("RAYLEIGH") ||
      (kw.has("VISCOUS") &&
       enum_param(kw, "VISCOUS", {"FRACTION OF CRITICAL DAMPING", "COMPOSITE", "RAYLEIGH"}, 0) ==
           2))
    md.kind = ModalDamping::Kind::Rayleigh;
  md.by_frequency = enum_param(kw, "DEFINITION", {"MODE NUMBERS", "FREQUENCY RANGE"}, 0) == 1;
  if (md.by_frequency && md.kind == ModalDamping::Kind::Rayleigh)
    throw InputError(kw.loc, "DEFINITION=FREQUENCY RANGE",
                     "Rayleigh modal damping is given by mode ranges; use DEFINITION=MODE NUMBERS");
  for (const DataLine& line : kw.data) {
    if (line.blank()) continue;
    const FieldReader r = s.reader(kw, line);
    ModalDamping::Range g;
    if (md.by_frequency) {
      r.at_most(2, "frequency, damping fraction");
      g.frequency = r.real(0, "frequency");
      g.zeta = r.real(1, "damping fraction");
      if (!md.ranges.empty() && g.frequency <= md.ranges.back().frequency)
        r.fail("field 1 (frequency)", "the frequencies must increase from line to line");
    } else {
      r.at_most(md.kind == ModalDamping::Kind::Rayleigh ? 4 : 3,
                md.kind == ModalDamping::Kind::Rayleigh
                    ? "first mode, last mode, alpha, beta"
                    : "first mode, last mode, damping fraction");
      // blank mode numbers: every mode (CalculiX writes ",,alpha,beta" and ",,zeta")
      const bool all = r.blank(0) && r.blank(1);
      g.first = static_cast<int>(r.integer_or(0, 1, "first mode", 1, 100000));
      g.last =
          all ? 100000 : static_cast<int>(r.integer_or(1, g.first, "last mode", g.first, 100000));
      if (md.kind == ModalDamping::Kind::Rayleigh) {
        g.alpha = r.real_or(2, 0.0, "alpha");
        g.beta = r.real_or(3, 0.0, "beta");
        if (g.alpha < 0.0 || g.beta < 0.0)
          r.fail("fields 3-4 (alpha, beta)", "Rayleigh factors must not be negative");
      } else {
        g.zeta = r.real(2, "damping fraction");
      }
    }
    if (g.zeta < 0.0 || g.zeta >= 1.0)
      r.fail("damping fraction", "a fraction of critical damping lies from 0 to below 1");
    md.ranges.push_back(g);
  }
  s.step.modal_damping = std::move(md);
}

void handle_select_eigenmodes(BuildState& s, const Keyword& kw) {
  const bool generate = kw.has("GENERATE");
  reject_param(kw, "DEFINITION",
               "list the modes by number (or first, last, increment with "
               "GENERATE)");
  for (const DataLine& line : kw.data) {
    if (line.blank()) continue;
    const FieldReader r = s.reader(kw, line);
    if (generate) {
      r.at_most(3, "first mode, last mode, increment");
      const auto first = r.integer(0, "first mode", 1, 100000);
      const auto last = r.integer_or(1, first, "last mode", first, 100000);
      const auto inc = r.integer_or(2, 1, "increment", 1, 100000);
      for (auto k = first; k <= last; k += inc)
        s.step.selected_modes.push_back(static_cast<int>(k));
    } else {
      for (std::size_t i = 0; i < r.size(); ++i)
        if (!r.blank(i))
          s.step.selected_modes.push_back(static_cast<int>(r.integer(i, "mode", 1, 100000)));
    }
  }
  std::sort(s.step.selected_modes.begin(), s.step.selected_modes.end());
  s.step.selected_modes.erase(
      std::unique(s.step.selected_modes.begin(), s.step.selected_modes.end()),
      s.step.selected_modes.end());
  if (s.step.selected_modes.empty())
    throw InputError(kw.loc, "", "no modes are listed; give their numbers on data lines");
}

} // namespace gapfem::inp
