// Section keywords: *SOLID SECTION, *BEAM SECTION, *SHELL SECTION, *NODAL THICKNESS, *SPRING. The
// ELSET and MATERIAL references are resolved when the model data is complete (model_validate.cpp).
#include "io/inp/handlers.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

/// The data lines of a keyword that hold more than blanks (a line of only commas counts: its
/// fields are blank, the defaults). Lines after the ones a handler reads stay unread, and the
/// parser reports them.
std::vector<const DataLine*> lines_of(const Keyword& kw) {
  std::vector<const DataLine*> out;
  for (const auto& d : kw.data)
    if (!d.blank()) out.push_back(&d);
  return out;
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
  }
  s.controls_index[c.name] = static_cast<int>(s.model.section_controls.size());
  s.model.section_controls.push_back(std::move(c));
}

namespace {

/// Data lines by position (a blank line keeps its place: "blank line for the default"), without
/// the blank lines that trail the keyword's data.
std::vector<const DataLine*> positional_lines(const Keyword& kw) {
  std::vector<const DataLine*> out;
  for (const auto& d : kw.data) out.push_back(&d);
  while (!out.empty() && out.back()->empty()) out.pop_back();
  return out;
}

struct ShapeSpec {
  const char* name;
  BeamSection::Shape shape;
  std::initializer_list<const char*> dims;
  std::size_t first_positive; ///< dimensions before this one may be zero or negative (I: l)
};

const ShapeSpec kShapes[] = {
    {"RECT", BeamSection::Shape::Rect, {"width a", "height b"}, 0},
    {"CIRC", BeamSection::Shape::Circ, {"radius r"}, 0},
    {"PIPE", BeamSection::Shape::Pipe, {"outer radius r", "wall thickness t"}, 0},
    {"BOX", BeamSection::Shape::Box, {"width a", "height b", "t1", "t2", "t3", "t4"}, 0},
    {"I", BeamSection::Shape::I, {"offset l", "height h", "b1", "b2", "t1", "t2", "t3"}, 1},
    {"GENERAL", BeamSection::Shape::General, {"A", "I11", "I12", "I22", "J"}, 5},
    {"HEX", BeamSection::Shape::Hex, {"outer radius r", "wall thickness t"}, 0},
    {"L", BeamSection::Shape::L, {"width a", "height b", "t1", "t2"}, 0},
    // c may be 0 (a triangle) and d anything: checked with the section's other rules
    {"TRAPEZOID", BeamSection::Shape::Trapezoid, {"width a", "height b", "top width c", "d"}, 4},
};

std::string dim_list(const ShapeSpec& sp) {
  std::string out;
  for (const char* d : sp.dims) out += (out.empty() ? "" : ", ") + std::string(d);
  return out;
}

/// SECTION=, the dimensions and the n1 line shared by *BEAM SECTION and *BEAM GENERAL SECTION.
void read_beam_geometry(BuildState& s, const Keyword& kw, BeamSection& sec, bool general) {
  std::vector<std::string_view> names;
  for (const auto& sp : kShapes)
    if (general || sp.shape != BeamSection::Shape::General) names.push_back(sp.name);
  std::string choices;
  for (auto n : names) choices += (choices.empty() ? "" : ", ") + std::string(n);
  const std::string given = param_value(kw, "SECTION", !general);
  const ShapeSpec* spec = general && given.empty() ? &kShapes[5] : nullptr;
  for (const auto& sp : kShapes)
    if (!given.empty() && canonical(given) == sp.name &&
        (general || sp.shape != BeamSection::Shape::General))
      spec = &sp;
  if (spec == nullptr) {
    const std::string c = canonical(given);
    const bool known = c == "ARBITRARY" || c == "THICKPIPE" || c == "ELBOW" || c == "MESHED" ||
                       c == "NONLINEARGENERAL";
    throw InputError(kw.loc, fmt::format("SECTION={}", given),
                     fmt::format("{}gapfem's beam sections are {}",
                                 known ? "this section is not "
                                         "available in gapfem; "
                                       : "unknown section; ",
                                 choices));
  }
  sec.shape = spec->shape;
  sec.loc = kw.loc;
  const auto lines = positional_lines(kw);
  if (lines.empty() || lines[0]->empty())
    throw InputError(kw.loc, fmt::format("ELSET={}", sec.elset),
                     fmt::format("the section dimensions are missing; add a data line with {}",
                                 dim_list(*spec)));
  const FieldReader r = s.reader(kw, *lines[0]);
  r.at_most(spec->dims.size(), dim_list(*spec));
  std::size_t i = 0;
  for (const char* name : spec->dims) {
    const bool optional = spec->shape == BeamSection::Shape::General && i >= 2;
    const double v = optional ? r.real_or(i, 0.0, name) : r.real(i, name);
    if (i >= spec->first_positive && v <= 0)
      r.fail(fmt::format("field {} ({})", i + 1, name),
             fmt::format("section dimensions must be positive, not {}", v));
    sec.dims.push_back(v);
    ++i;
  }
  if (sec.shape == BeamSection::Shape::Pipe && sec.dims[1] >= sec.dims[0])
    r.fail("field 2 (wall thickness t)",
           fmt::format("the wall thickness {} must be smaller than the outer radius {} (use "
                       "SECTION=CIRC for a solid circle)",
                       sec.dims[1], sec.dims[0]));
  if (lines.size() > 1) lines[1]->read = true; // (blank: the default n1 direction)
  if (lines.size() > 1 && !lines[1]->empty()) {
    const FieldReader r2 = s.reader(kw, *lines[1]);
    r2.at_most(3, "n1 direction x, y, z");
    const Vec3 n{r2.real_or(0, 0.0, "n1 x"), r2.real_or(1, 0.0, "n1 y"),
                 r2.real_or(2, 0.0, "n1 z")};
    if (std::hypot(n[0], n[1], n[2]) == 0.0)
      r2.fail("n1 direction", "the approximate beam 1-direction must not be the zero vector");
    sec.n1 = n;
    sec.n1_given = true;
  }
}

/// Runs `read`; when it throws, the section is still registered (marked invalid) so that its
/// elements report nothing more (no false "has no section"), then the error goes on.
template <class F>
void guarded(BuildState& s, BeamSection& sec, const std::string& material, F&& read) {
  try {
    read();
  } catch (const InputError&) {
    sec.invalid = true;
    s.model.beam_sections.push_back(sec);
    s.beam_material.push_back(material);
    throw;
  }
}

void check_temperature_param(const Keyword& kw) {
  if (enum_param(kw, "TEMPERATURE", {"GRADIENTS", "VALUES"}, 0) == 1)
    throw InputError(kw.loc, "TEMPERATURE=VALUES",
                     "gapfem takes beam temperatures as the value at the section origin and its "
                     "gradients dT/dx2, dT/dx1 (TEMPERATURE=GRADIENTS, the default); remove the "
                     "parameter");
  // ROTARY INERTIA=EXACT is Abaqus's default and gapfem's (docs/theory/dynamics.md, "Mass of
  // each element type"); the isotropic approximation is not offered
  if (enum_param(kw, "ROTARY INERTIA", {"EXACT", "ISOTROPIC"}, 0) == 1)
    throw InputError(kw.loc, "ROTARY INERTIA=ISOTROPIC",
                     "gapfem forms the beam's exact rotary inertia from the section "
                     "(ROTARY INERTIA=EXACT, Abaqus's default); remove the parameter");
}

/// Line 3 of *BEAM GENERAL SECTION: E, G, alpha.
void read_general_constants(BuildState& s, const Keyword& kw, BeamSection& sec) {
  const auto lines = positional_lines(kw);
  if (lines.size() < 3 || lines[2]->empty())
    throw InputError(kw.loc, fmt::format("ELSET={}", sec.elset),
                     "the elastic constants are missing; give Young's modulus E, the torsional "
                     "shear modulus G and (optionally) the thermal expansion coefficient on the "
                     "third data line (leave the second blank for the default n1 direction)");
  const FieldReader r = s.reader(kw, *lines[2]);
  r.at_most(3, "E, G, alpha");
  sec.E = r.real(0, "Young's modulus E");
  sec.G = r.real(1, "shear modulus G");
  sec.alpha = r.real_or(2, 0.0, "thermal expansion coefficient");
  if (!(sec.E > 0.0)) r.fail("field 1 (E)", fmt::format("must be positive, not {}", sec.E));
  if (!(sec.G > 0.0)) r.fail("field 2 (G)", fmt::format("must be positive, not {}", sec.G));
}

} // namespace

void handle_beam_section(BuildState& s, const Keyword& kw) {
  s.beam_section_ok = false;
  BeamSection sec;
  sec.loc = kw.loc;
  sec.elset = set_param(s, kw, "ELSET", true);
  const std::string material = name_param(kw, "MATERIAL", true);
  guarded(s, sec, material, [&] {
    check_temperature_param(kw);
    read_beam_geometry(s, kw, sec, false);
  });
  const auto lines = positional_lines(kw);
  if (lines.size() > 2) {
    lines[2]->read = true; // Abaqus's third line: accepted with a remark
    s.warn(s.loc(kw, *lines[2]),
           "the number of section integration points has no effect in gapfem: elastic sections "
           "are integrated exactly and stresses are reported at the section's corner points");
  }
  s.model.beam_sections.push_back(std::move(sec));
  s.beam_material.push_back(material);
  s.beam_section_ok = true;
}

void handle_beam_general_section(BuildState& s, const Keyword& kw) {
  s.beam_section_ok = false;
  reject_param(kw, "DEPENDENCIES", "give constant section properties");
  BeamSection sec;
  sec.loc = kw.loc;
  sec.elset = set_param(s, kw, "ELSET", true);
  sec.general = true;
  guarded(s, sec, "", [&] {
    if (const auto rho = real_param(kw, "DENSITY")) {
      if (!(*rho > 0.0))
        throw InputError(kw.loc, param_text(kw, "DENSITY"), "the density must be positive");
      sec.density = *rho;
    }
    check_temperature_param(kw);
    read_beam_geometry(s, kw, sec, true);
    read_general_constants(s, kw, sec);
  });
  s.model.beam_sections.push_back(std::move(sec));
  s.beam_material.emplace_back();
  s.beam_section_ok = true;
}

void handle_section_points(BuildState& s, const Keyword& kw) {
  if (s.model.beam_sections.empty() || !s.beam_section_ok) return; // its section was reported
  BeamSection& sec = s.model.beam_sections.back();
  if (!sec.general)
    throw InputError(kw.loc, fmt::format("ELSET={}", sec.elset),
                     "*SECTION POINTS belongs to a *BEAM GENERAL SECTION; a *BEAM SECTION reports "
                     "at its own section points");
  bool any_line = false; // a line that failed is reported by itself
  for_each_line(s, kw, [&](const DataLine& line) {
    any_line = true;
    const FieldReader r = s.reader(kw, line);
    r.at_most(8, "up to four pairs x1, x2");
    std::size_t n = line.fields.size();
    while (n > 0 && line.fields[n - 1].empty()) --n;
    if (n % 2 != 0) r.fail(fmt::format("field {}", n), "give the points as pairs x1, x2");
    std::vector<std::array<double, 2>> pts;
    for (std::size_t i = 0; i < n; i += 2) pts.push_back({r.real(i, "x1"), r.real(i + 1, "x2")});
    // Abaqus: a last (0, 0) on a line is ignored unless it is the only point
    if (pts.size() > 1 && pts.back()[0] == 0.0 && pts.back()[1] == 0.0) pts.pop_back();
    sec.output_points.insert(sec.output_points.end(), pts.begin(), pts.end());
  });
  if (sec.output_points.empty() && !any_line)
    throw InputError(kw.loc, fmt::format("ELSET={}", sec.elset),
                     "give the section points as pairs x1, x2 on the data lines");
}

void handle_beam_transverse_shear(BuildState& s, const Keyword& kw) {
  if (s.model.beam_sections.empty() || !s.beam_section_ok) return; // its section was reported
  BeamSection& sec = s.model.beam_sections.back();
  const auto lines = lines_of(kw);
  if (lines.empty())
    throw InputError(kw.loc, fmt::format("ELSET={}", sec.elset),
                     "give K23, K13 and optionally the slenderness compensation factor");
  const FieldReader r = s.reader(kw, *lines[0]);
  r.at_most(3, "K23, K13, slenderness compensation factor");
  const double k23 = r.real_or(0, 0.0, "K23"), k13 = r.real_or(1, 0.0, "K13");
  if (k23 < 0 || k13 < 0)
    r.fail("K23, K13", fmt::format("shear stiffnesses must be positive, not {}, {}", k23, k13));
  sec.k23 = k23;
  sec.k13 = k13;
  if (!r.blank(2)) {
    const double scf = r.real(2, "slenderness compensation factor");
    if (scf < 0)
      r.fail("field 3 (slenderness compensation factor)",
             fmt::format("must not be negative, not {}", scf));
    sec.slenderness = scf;
  }
}

void handle_spring(BuildState& s, const Keyword& kw) {
  SpringSection sec;
  sec.elset = set_param(s, kw, "ELSET", true);
  sec.loc = kw.loc;
  sec.nonlinear = kw.has("NONLINEAR");
  if (kw.has("ORIENTATION")) // (resolved with the element types: orientation.cpp)
    sec.orientation = s.set_name(name_param(kw, "ORIENTATION", true));
  if (sec.nonlinear) return read_nonlinear_spring(s, kw, std::move(sec));
  if (kw.data.empty())
    throw InputError(kw.loc, fmt::format("ELSET={}", sec.elset),
                     "data lines are missing: line 1 gives the DOF(s) (blank for SPRINGA), the "
                     "following lines the stiffness");
  // line 1: DOFs (checked against the element types later); lines 2…: the stiffness table
  const std::span<const DataLine> rows(kw.data.data() + 1, kw.data.size() - 1);
  bool any_row = false;
  for (const auto& d : rows) any_row = any_row || !d.empty();
  if (!any_row)
    throw InputError(s.loc(kw, kw.data[0]), fmt::format("ELSET={}", sec.elset),
                     "the stiffness is missing; give it on the second data line (the first line "
                     "holds the DOFs, blank for SPRINGA)");
  // Abaqus's (and CalculiX's) layout: stiffness, frequency (steady-state dynamics only), then
  // the temperature [Keywords Reference, *SPRING]; the table is read as stiffness, temperature
  std::vector<DataLine> table;
  for (const DataLine& d : rows) {
    if (d.empty()) continue;
    const FieldReader r = s.reader(kw, d);
    r.at_most(3, "stiffness, frequency, temperature");
    if (!r.blank(1))
      r.fail("field 2",
             "this is the frequency, which only steady-state dynamics uses: leave it blank; a "
             "temperature goes in field 3 (the layout is stiffness, frequency, temperature)");
    DataLine t = d;
    t.fields.resize(1);
    if (d.fields.size() > 2) t.fields.push_back(d.fields[2]);
    table.push_back(std::move(t));
  }
  sec.stiffness = read_property_table(s, kw, table, {"stiffness"}, nullptr);
  s.model.spring_sections.push_back(std::move(sec));
  kw.data[0].read = true; // (read by check_spring once the element types are known)
  s.spring_dof_line.push_back(kw.data[0]);
}

namespace {

/// The one data line of *MASS / *ROTARY INERTIA, checked: `n` values, the first `required` of
/// them given; none negative (`what` names them).
std::array<double, 6> read_inertia_line(BuildState& s, const Keyword& kw, const std::string& elset,
                                        std::size_t n, std::size_t required,
                                        std::span<const std::string_view> names) {
  std::array<double, 6> v{};
  bool seen = false;
  for (const DataLine& line : kw.data) {
    if (line.blank()) continue;
    const FieldReader r = s.reader(kw, line);
    if (seen) r.fail("", fmt::format("{} takes one data line; this is a second one", kw.name));
    seen = true;
    r.at_most(n, names.front());
    for (std::size_t i = 0; i < n; ++i) {
      v[i] = i < required ? r.real(i, names[i + 1]) : r.real_or(i, 0.0, names[i + 1]);
      if (i < 3 && v[i] < 0.0)
        r.fail(fmt::format("field {} ({})", i + 1, names[i + 1]),
               fmt::format("{} must not be negative, not {}", names[i + 1], v[i]));
    }
  }
  if (!seen)
    throw InputError(kw.loc, fmt::format("ELSET={}", elset),
                     fmt::format("the data line is missing: give {}", names.front()));
  return v;
}

/// ALPHA= (mass-proportional damping, C = alpha M, in direct-integration dynamics) and
/// COMPOSITE= (a fraction of critical damping for mode-based procedures; Abaqus ignores it in
/// direct integration, and gapfem has no mode-based procedure): both at least 0.
void read_point_damping(BuildState& s, const Keyword& kw, const std::string& elset, double& alpha,
                        double& composite) {
  for (const char* name : {"ALPHA", "COMPOSITE"}) {
    const std::optional<double> v = real_param(kw, name);
    if (v && !(*v >= 0.0))
      throw InputError(kw.loc, param_text(kw, name),
                       fmt::format("{} must not be negative; give the {} or leave it out", name,
                                   name[0] == 'A' ? "mass-proportional damping factor (C = "
                                                    "ALPHA M)"
                                                  : "fraction of critical damping"));
    (name[0] == 'A' ? alpha : composite) = v.value_or(0.0);
  }
  if (composite > 0.0)
    s.warn(kw.loc, fmt::format("{}, ELSET={}: COMPOSITE is composite modal damping of mode-based "
                               "dynamics, whose damping gapfem takes from *MODAL DAMPING alone; "
                               "it has no effect (Abaqus ignores it in direct-integration "
                               "dynamics too)",
                               kw.name, elset));
}

/// One data line of *BEAM ADDED INERTIA (Keywords Reference): mass per length, x1, x2, the
/// angle of the inertia axes (degrees), I11, I22, I12 about the centre of mass; a physical
/// inertia (mass, I11, I22 at least 0, I11 I22 >= I12^2).
BeamAddedInertia read_added_inertia_line(const FieldReader& r) {
  r.at_most(7, "mass per length, x1, x2, angle, I11, I22, I12");
  BeamAddedInertia a;
  a.mass = r.real(0, "mass per unit length");
  a.x1 = r.real_or(1, 0.0, "x1");
  a.x2 = r.real_or(2, 0.0, "x2");
  a.angle = r.real_or(3, 0.0, "orientation angle");
  a.I11 = r.real_or(4, 0.0, "I11");
  a.I22 = r.real_or(5, 0.0, "I22");
  a.I12 = r.real_or(6, 0.0, "I12");
  if (!(a.mass >= 0.0))
    r.fail("field 1 (mass per unit length)",
           fmt::format("the added mass per unit length must not be negative, not {}", a.mass));
  if (!(a.I11 >= 0.0) || !(a.I22 >= 0.0))
    r.fail("fields 5-6 (I11, I22)", fmt::format("rotary inertias must not be negative, not {}, "
                                                "{}",
                                                a.I11, a.I22));
  if (a.I12 * a.I12 > a.I11 * a.I22 * (1.0 + 1e-12))
    r.fail("field 7 (I12)",
           fmt::format("|I12| = {} exceeds sqrt(I11 I22) = {}: not the inertia of a mass; give "
                       "the product of inertia about the centre of mass",
                       std::abs(a.I12), std::sqrt(a.I11 * a.I22)));
  return a;
}

} // namespace

void handle_mass(BuildState& s, const Keyword& kw) {
  enum_param(kw, "TYPE", {"ISOTROPIC"}, 0); // the translational mass is isotropic
  MassSection sec;
  sec.elset = set_param(s, kw, "ELSET", true);
  sec.loc = kw.loc;
  read_point_damping(s, kw, sec.elset, sec.alpha, sec.composite);
  static constexpr std::array<std::string_view, 2> kNames{"the mass", "mass"};
  sec.mass = read_inertia_line(s, kw, sec.elset, 1, 1, kNames)[0];
  s.model.mass_sections.push_back(std::move(sec));
}

void handle_rotary_inertia(BuildState& s, const Keyword& kw) {
  if (kw.has("ORIENTATION")) // turned to global axes by resolve_rotary_orientations
    s.rotary_orientations.emplace_back(s.model.mass_sections.size(),
                                       s.set_name(name_param(kw, "ORIENTATION", true)));
  MassSection sec;
  sec.elset = set_param(s, kw, "ELSET", true);
  sec.loc = kw.loc;
  read_point_damping(s, kw, sec.elset, sec.alpha, sec.composite);
  sec.rotary = true;
  static constexpr std::array<std::string_view, 7> kNames{
      "I11, I22, I33, I12, I13, I23", "I11", "I22", "I33", "I12", "I13", "I23"};
  sec.inertia = read_inertia_line(s, kw, sec.elset, 6, 3, kNames);
  s.model.mass_sections.push_back(std::move(sec));
}

void handle_beam_added_inertia(BuildState& s, const Keyword& kw) {
  if (s.model.beam_sections.empty() || !s.beam_section_ok) return; // its section was reported
  BeamSection& sec = s.model.beam_sections.back();
  double alpha = 0.0, composite = 0.0;
  read_point_damping(s, kw, sec.elset, alpha, composite);
  bool any_line = false; // a line that failed is reported by itself
  for_each_line(s, kw, [&](const DataLine& line) {
    any_line = true;
    BeamAddedInertia a = read_added_inertia_line(s.reader(kw, line));
    a.alpha = alpha;
    a.composite = composite;
    a.loc = s.loc(kw, line);
    sec.added_inertia.push_back(a);
  });
  if (!any_line)
    throw InputError(kw.loc, fmt::format("ELSET={}", sec.elset),
                     "give the added mass per unit length (and optionally x1, x2, the angle, I11, "
                     "I22, I12) on a data line");
}

} // namespace gapfem::inp

namespace gapfem::inp {

namespace {

/// *SHELL SECTION, or *SHELL GENERAL SECTION with MATERIAL= (`general`): the same homogeneous
/// elastic section, whose response gapfem integrates exactly through the thickness either way;
/// the general section's stresses are reported at 3 points (SNEG, middle, SPOS).
void read_shell_section(BuildState& s, const Keyword& kw, bool general) {
  s.shell_section_ok = false;
  ShellSection sec;
  sec.loc = kw.loc;
  sec.elset = set_param(s, kw, "ELSET", true);
  std::string material;
  try {
    reject_param(kw, "ORIENTATION",
                 "gapfem shell materials are isotropic, so no orientation is needed; remove the "
                 "parameter");
    reject_param(kw, "COMPOSITE", "give one homogeneous layer (thickness, points, material)");
    if (general) {
      for (const char* p : {"DENSITY", "ZERO", "USER", "DEPENDENCIES", "UNSYMM"})
        reject_param(kw, p, "gapfem reads the general shell section from a material only");
      if (!kw.has("MATERIAL"))
        throw InputError(kw.loc, fmt::format("ELSET={}", sec.elset),
                         "a general shell section given by its stiffness matrix is not supported "
                         "by gapfem; give MATERIAL= (an elastic material) and the thickness");
    }
    material = name_param(kw, "MATERIAL", true);
    reject_param(kw, "POISSON", "the thickness change of gapfem shells is not computed");
    enum_param(kw, "SECTION INTEGRATION", {"SIMPSON"}, 0);
    enum_param(kw, "TEMPERATURE", {"GRADIENT"}, 0);
    if (kw.has("OFFSET")) {
      const std::string o = canonical(param_value(kw, "OFFSET", true));
      if (o == "SPOS")
        sec.offset = 0.5;
      else if (o == "SNEG")
        sec.offset = -0.5;
      else if (o == "SMID")
        sec.offset = 0.0;
      else if (const auto v = parse_real(param_value(kw, "OFFSET", true)))
        sec.offset = *v;
      else
        throw InputError(kw.loc, fmt::format("OFFSET={}", param_value(kw, "OFFSET", true)),
                         "give SPOS, SNEG, SMID or the offset as a fraction of the thickness");
    }
    sec.nodal_thickness = kw.has("NODAL THICKNESS");
    const auto lines = lines_of(kw);
    if (lines.empty() && sec.nodal_thickness) { // the thicknesses come from the nodes
      s.model.shell_sections.push_back(std::move(sec));
      s.shell_material.push_back(material);
      s.shell_section_ok = true;
      return;
    }
    if (lines.empty())
      throw InputError(kw.loc, fmt::format("ELSET={}", sec.elset),
                       "the data line is missing; give the shell thickness and the number of "
                       "integration points through it (e.g. 0.01, 5)");
    const FieldReader r = s.reader(kw, *lines[0]);
    r.at_most(general ? 1 : 2, general ? "thickness" : "thickness, number of integration points");
    sec.thickness = sec.nodal_thickness ? r.real_or(0, 0.0, "thickness") : r.real(0, "thickness");
    if (!(sec.thickness > 0.0) && !(sec.nodal_thickness && sec.thickness == 0.0))
      r.fail("field 1 (thickness)",
             fmt::format("the shell thickness must be positive, not {}", sec.thickness));
    constexpr std::string_view rule =
        "Simpson's rule needs an odd number of points from 3 to 15 (1 for a heat-transfer shell "
        "without a gradient through its thickness), not {}";
    const long long n = general ? 3 : r.integer_or(1, 5, "integration points", 1, 15, rule);
    if (n % 2 == 0) r.fail("field 2 (integration points)", fmt::format(fmt::runtime(rule), n));
    sec.n_points = static_cast<int>(n);
  } catch (const InputError&) {
    sec.invalid = true;
    s.model.shell_sections.push_back(sec);
    s.shell_material.push_back(material);
    throw;
  }
  s.model.shell_sections.push_back(std::move(sec));
  s.shell_material.push_back(material);
  s.shell_section_ok = true;
}

} // namespace

void handle_shell_section(BuildState& s, const Keyword& kw) {
  read_shell_section(s, kw, false);
}

void handle_shell_general_section(BuildState& s, const Keyword& kw) {
  read_shell_section(s, kw, true);
}

void handle_nodal_thickness(BuildState& s, const Keyword& kw) {
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(2, "node or node set, thickness");
    const double t = r.real(1, "thickness");
    if (!(t > 0.0)) r.fail("field 2 (thickness)", fmt::format("must be positive, not {}", t));
    auto& nt = s.model.nodal_thickness;
    for (NodeId n : resolve_nodes(s, r, 0)) {
      if (nt.size() <= static_cast<std::size_t>(n)) nt.resize(static_cast<std::size_t>(n) + 1, 0.0);
      nt[n] = t;
    }
  });
}

void handle_transverse_shear(BuildState& s, const Keyword& kw) {
  if (s.parent == Parent::ShellSection) {
    if (s.model.shell_sections.empty() || !s.shell_section_ok) return; // reported
    ShellSection& sec = s.model.shell_sections.back();
    const auto lines = lines_of(kw);
    if (lines.empty())
      throw InputError(kw.loc, fmt::format("ELSET={}", sec.elset), "give K11, K22 and K12");
    const FieldReader r = s.reader(kw, *lines[0]);
    r.at_most(3, "K11, K22, K12");
    sec.k11 = r.real(0, "K11");
    sec.k22 = r.real_or(1, sec.k11, "K22");
    if (!(sec.k11 > 0.0) || !(sec.k22 > 0.0))
      r.fail("K11, K22",
             fmt::format("shear stiffnesses must be positive, not {}, {}", sec.k11, sec.k22));
    if (r.real_or(2, 0.0, "K12") != 0.0)
      r.fail("field 3 (K12)", "gapfem shells are isotropic: K12 must be 0 or blank");
    return;
  }
  handle_beam_transverse_shear(s, kw);
}

} // namespace gapfem::inp
