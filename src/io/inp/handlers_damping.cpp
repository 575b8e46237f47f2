// *DAMPING inside *MATERIAL: material Rayleigh damping (docs/theory/dynamics.md, "Rayleigh
// damping"; Abaqus Keywords Reference, *DAMPING,
// https://abaqus-docs.mit.edu/2017/English/SIMACAEKEYRefMap/simakey-r-damping.htm).
#include "io/inp/handlers.hpp"

#include <fmt/format.h>

namespace gapfem::inp {
namespace {

/// ALPHA= or BETA=: a non-negative number (TABULAR refused); nullopt when absent.
std::optional<double> rayleigh_factor(const Keyword& kw, std::string_view param,
                                      std::string_view what) {
  if (!kw.has(param)) return std::nullopt;
  if (canonical(param_value(kw, param, true)) == "TABULAR")
    throw InputError(kw.loc, param_text(kw, param),
                     fmt::format("temperature-dependent Rayleigh damping (TABULAR) is not "
                                 "supported; give the {} factor as one number",
                                 what));
  const double x = *real_param(kw, param);
  if (x < 0.0)
    throw InputError(kw.loc, param_text(kw, param),
                     fmt::format("the {} damping factor must be zero or positive, not {} (a "
                                 "negative factor would feed energy into the model)",
                                 what, x));
  return x;
}

/// Sets `field` from `value` (parameter bit `bit` of RayleighDamping::given), refusing a factor
/// the material's damping already has.
void set_once(const Keyword& kw, const std::string& material, std::string_view param,
              std::optional<double> value, unsigned bit, RayleighDamping& d, double& field) {
  if (!value) return;
  if (d.given & bit)
    throw InputError(kw.loc, param_text(kw, param),
                     fmt::format("{} is given twice for material {} (by two *DAMPING options); "
                                 "keep one value",
                                 param, material));
  d.given |= bit;
  field = *value;
}

} // namespace

void handle_damping(BuildState& s, const Keyword& kw) {
  // Abaqus also reads *DAMPING after *BEAM GENERAL SECTION and *SHELL GENERAL SECTION (sections
  // without a material); gapfem does not damp sections yet
  if (s.parent == Parent::BeamSection || s.parent == Parent::ShellSection)
    throw InputError(kw.loc, "",
                     "Rayleigh damping of a section (*DAMPING after a beam or shell section) is "
                     "not supported; give *DAMPING inside the *MATERIAL the section names (a "
                     "*BEAM GENERAL SECTION, which has no material, cannot be damped yet)");
  if (s.current_material < 0) return; // the *MATERIAL line was in error (reported)
  Material& m = s.model.materials[s.current_material];
  const auto alpha = rayleigh_factor(kw, "ALPHA", "mass-proportional (ALPHA)");
  const auto beta = rayleigh_factor(kw, "BETA", "stiffness-proportional (BETA)");
  const auto structural = real_param(kw, "STRUCTURAL");
  const auto composite = real_param(kw, "COMPOSITE");
  // Abaqus allows several *DAMPING options in one material, each giving other factors (Keywords
  // Reference); the same factor twice is an error here rather than a silent last-wins
  if (!m.damping) {
    m.damping.emplace();
    m.damping->loc = kw.loc;
  }
  RayleighDamping& d = *m.damping;
  set_once(kw, m.name, "ALPHA", alpha, 1u, d, d.alpha);
  set_once(kw, m.name, "BETA", beta, 2u, d, d.beta);
  set_once(kw, m.name, "STRUCTURAL", structural, 4u, d, d.structural);
  set_once(kw, m.name, "COMPOSITE", composite, 8u, d, d.composite);
  if (structural && *structural != 0.0)
    s.warn(kw.loc, fmt::format("*DAMPING, STRUCTURAL={} of material {}: structural damping "
                               "acts only in frequency-domain procedures, whose damping gapfem "
                               "takes from *MODAL DAMPING alone; it is ignored (as Abaqus "
                               "ignores it in *DYNAMIC)",
                               *structural, m.name));
  if (composite && *composite != 0.0)
    s.warn(kw.loc, fmt::format("*DAMPING, COMPOSITE={} of material {}: composite modal damping "
                               "acts only in mode-based procedures, whose damping gapfem takes "
                               "from *MODAL DAMPING alone; it is ignored (as Abaqus ignores it "
                               "in *DYNAMIC)",
                               *composite, m.name));
}

} // namespace gapfem::inp
