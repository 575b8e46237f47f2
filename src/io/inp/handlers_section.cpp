// Section keywords: *SOLID SECTION, *BEAM SECTION, *SPRING. The ELSET and MATERIAL references are
// resolved when the model data is complete (model_validate.cpp).
#include "io/inp/handlers.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

/// Non-empty data lines of a keyword.
std::vector<const DataLine*> lines_of(const Keyword& kw) {
  std::vector<const DataLine*> out;
  for (const auto& d : kw.data)
    if (!d.empty()) out.push_back(&d);
  return out;
}

void extra_lines_warning(BuildState& s, const Keyword& kw, std::size_t used) {
  const auto lines = lines_of(kw);
  if (lines.size() > used)
    s.warn(s.loc(kw, *lines[used]),
           fmt::format("{} uses only {} data line(s) here; the data from this line on was ignored",
                       kw.name, used));
}

} // namespace

void handle_solid_section(BuildState& s, const Keyword& kw) {
  reject_param(kw, "ORIENTATION",
               "gapfem materials are isotropic, so no orientation is needed; remove the parameter");
  SolidSection sec;
  sec.elset = set_param(s, kw, "ELSET", true);
  const std::string material = name_param(kw, "MATERIAL", true);
  s.solid_controls.push_back(name_param(kw, "CONTROLS", false));
  sec.loc = kw.loc;
  const auto lines = lines_of(kw);
  if (!lines.empty()) {
    const FieldReader r = s.reader(kw, *lines[0]);
    r.at_most(1, "thickness (plane elements) or cross-section area (trusses)");
    if (auto t = r.opt_real(0, "thickness or area")) {
      if (*t <= 0)
        r.fail("field 1 (thickness or area)", fmt::format("must be positive, not {}", *t));
      sec.thickness = *t;
      sec.thickness_given = true;
    }
    extra_lines_warning(s, kw, 1);
  }
  s.model.solid_sections.push_back(std::move(sec));
  s.solid_material.push_back(material);
}

void handle_section_controls(BuildState& s, const Keyword& kw) {
  SectionControls c;
  c.name = name_param(kw, "NAME", true);
  c.loc = kw.loc;
  if (const auto it = s.controls_index.find(c.name); it != s.controls_index.end()) {
    const SourceLocation& first = s.model.section_controls[it->second].loc;
    if (first.file == kw.loc.file && first.line == kw.loc.line) return; // a part read again
    throw InputError(kw.loc, fmt::format("NAME={}", c.name),
                     fmt::format("section controls {} are defined twice; give each *SECTION "
                                 "CONTROLS its own NAME",
                                 c.name));
  }
  const int hg = enum_param(kw, "HOURGLASS",
                            {"ENHANCED", "STIFFNESS", "RELAX STIFFNESS", "VISCOUS", "COMBINED"}, 0);
  if (hg >= 2) {
    // registered all the same, so the sections naming it report nothing more
    s.controls_index[c.name] = static_cast<int>(s.model.section_controls.size());
    s.model.section_controls.push_back(c);
    throw InputError(kw.loc, fmt::format("NAME={}", c.name),
                     fmt::format("HOURGLASS={} is an Abaqus/Explicit hourglass control; "
                                 "Abaqus/Standard and gapfem offer HOURGLASS=ENHANCED (the "
                                 "default) and HOURGLASS=STIFFNESS",
                                 param_value(kw, "HOURGLASS", true)));
  }
  c.hourglass = hg == 1 ? HourglassControl::Stiffness : HourglassControl::Enhanced;
  for (const char* p :
       {"DISTORTION CONTROL", "LENGTH RATIO", "KINEMATIC SPLIT", "SECOND ORDER ACCURACY"})
    if (kw.has(p))
      s.warn(kw.loc, fmt::format("*SECTION CONTROLS, {} is an Abaqus/Explicit control and has no "
                                 "effect in Abaqus/Standard or gapfem",
                                 p));
  for (const char* p : {"ELEMENT DELETION", "MAX DEGRADATION", "VISCOSITY"})
    if (kw.has(p))
      s.warn(kw.loc, fmt::format("*SECTION CONTROLS, {} applies to damaged or cohesive elements, "
                                 "which gapfem does not have; it has no effect",
                                 p));
  const auto lines = lines_of(kw);
  if (!lines.empty()) {
    const FieldReader r = s.reader(kw, *lines[0]);
    r.at_most(3, "displacement hourglass scaling factor, rotational and out-of-plane (shell) "
                 "factors");
    if (auto f = r.opt_real(0, "displacement hourglass scaling factor")) {
      if (!(*f > 0))
        r.fail("field 1 (displacement hourglass scaling factor)",
               fmt::format("must be positive, not {}", *f));
      c.scale = *f;
    }
    for (std::size_t i = 1; i < 3; ++i)
      if (auto f = r.opt_real(i, "shell hourglass scaling factor"); f && *f != 1.0)
        s.warn(s.loc(kw, *lines[0]),
               fmt::format("field {} of *SECTION CONTROLS scales the hourglass control of shell "
                           "elements; gapfem's solid elements do not use it",
                           i + 1));
    extra_lines_warning(s, kw, 1);
  }
  s.controls_index[c.name] = static_cast<int>(s.model.section_controls.size());
  s.model.section_controls.push_back(std::move(c));
}

void handle_beam_section(BuildState& s, const Keyword& kw) {
  BeamSection sec;
  sec.elset = set_param(s, kw, "ELSET", true);
  const std::string material = name_param(kw, "MATERIAL", true);
  const int shape = enum_param(kw, "SECTION", {"RECT", "CIRC", "PIPE"}, -1);
  if (shape < 0) param_value(kw, "SECTION", true); // throws "SECTION= is required"
  sec.shape = shape == 0   ? BeamSection::Shape::Rect
              : shape == 1 ? BeamSection::Shape::Circ
                           : BeamSection::Shape::Pipe;
  sec.loc = kw.loc;
  const auto lines = lines_of(kw);
  if (lines.empty())
    throw InputError(
        kw.loc, fmt::format("ELSET={}", sec.elset),
        "the section dimensions are missing; add a data line (RECT: a, b; CIRC: r; PIPE: r, t)");
  const FieldReader r = s.reader(kw, *lines[0]);
  const char* names[3][2] = {
      {"width a", "height b"}, {"radius r", ""}, {"outer radius r", "wall thickness t"}};
  const int n_dims = sec.shape == BeamSection::Shape::Circ ? 1 : 2;
  r.at_most(static_cast<std::size_t>(n_dims), shape == 0   ? "a, b"
                                              : shape == 1 ? "r"
                                                           : "outer radius r, wall thickness t");
  for (int i = 0; i < n_dims; ++i) {
    const double v = r.real(static_cast<std::size_t>(i), names[shape][i]);
    if (v <= 0)
      r.fail(fmt::format("field {} ({})", i + 1, names[shape][i]),
             fmt::format("section dimensions must be positive, not {}", v));
    sec.dims.push_back(v);
  }
  if (sec.shape == BeamSection::Shape::Pipe && sec.dims[1] >= sec.dims[0])
    r.fail("field 2 (wall thickness t)",
           fmt::format("the wall thickness {} must be smaller than the outer radius {} (use "
                       "SECTION=CIRC for a solid circle)",
                       sec.dims[1], sec.dims[0]));
  if (lines.size() > 1) {
    const FieldReader r2 = s.reader(kw, *lines[1]);
    r2.at_most(3, "n1 direction x, y, z");
    const Vec3 n{r2.real_or(0, 0.0, "n1 x"), r2.real_or(1, 0.0, "n1 y"),
                 r2.real_or(2, 0.0, "n1 z")};
    if (std::hypot(n[0], n[1], n[2]) == 0.0)
      r2.fail("n1 direction", "the approximate beam 1-direction must not be the zero vector");
    sec.n1 = n;
    sec.n1_given = true;
  }
  extra_lines_warning(s, kw, 2);
  s.model.beam_sections.push_back(std::move(sec));
  s.beam_material.push_back(material);
}

void handle_spring(BuildState& s, const Keyword& kw) {
  reject_param(kw, "NONLINEAR", "give a linear stiffness (optionally temperature dependent)");
  reject_param(kw, "ORIENTATION", "springs act in the global DOF directions");
  SpringSection sec;
  sec.elset = set_param(s, kw, "ELSET", true);
  sec.loc = kw.loc;
  if (kw.data.empty())
    throw InputError(kw.loc, fmt::format("ELSET={}", sec.elset),
                     "data lines are missing: line 1 gives the DOF(s) (blank for SPRINGA), the "
                     "following lines the stiffness");
  // line 1: DOFs (checked against the element types later); lines 2…: stiffness[, temperature]
  const std::span<const DataLine> rows(kw.data.data() + 1, kw.data.size() - 1);
  bool any_row = false;
  for (const auto& d : rows) any_row = any_row || !d.empty();
  if (!any_row)
    throw InputError(s.loc(kw, kw.data[0]), fmt::format("ELSET={}", sec.elset),
                     "the stiffness is missing; give it on the second data line (the first line "
                     "holds the DOFs, blank for SPRINGA)");
  sec.stiffness = read_property_table(s, kw, rows, {"stiffness"}, nullptr);
  s.model.spring_sections.push_back(std::move(sec));
  s.spring_dof_line.push_back(kw.data[0]);
}

} // namespace gapfem::inp
