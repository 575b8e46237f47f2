// Boundary conditions and loads: *BOUNDARY, *CLOAD, *CFLUX, *DLOAD, *DSLOAD, *DFLUX, *DSFLUX,
// *FILM, *SFILM (*TEMPERATURE and *CONTACT INTERFERENCE: handlers_temperature.cpp).
//
// Each keyword merges its entries into the step's active list (which starts as the previous
// step's list with propagated = true):
//   OP=MOD (default): an entry with the same key as an active entry of the same keyword family
//     replaces it, other entries are added;
//   OP=NEW: first removes every entry of the family inherited from earlier steps (propagated),
//     then adds. Entries defined earlier in the same step are kept, so several OP=NEW keywords
//     of one family in a step add up (CalculiX documents the same: OP=NEW acts once per step).
// *BOUNDARY, OP=NEW also removes boundary conditions given in the model data: the Abaqus Analysis
// User's Guide ("Boundary conditions", 34.3.1 in 2016 / 27.3.1 in 6.6) states that boundary
// conditions prescribed as model data "can be modified or removed during analysis steps", and
// the *BOUNDARY keyword page defines OP=NEW as removing all boundary conditions currently in
// effect; model-data conditions are in effect, so they are removed as well.
#include "io/inp/handlers.hpp"
#include "io/inp/load_merge.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <tuple>

namespace gapfem::inp {
namespace {

/// DOF lists of the boundary-condition types (Abaqus Analysis User's Guide, "Boundary conditions",
/// type format).
bool bc_type_dofs(const std::string& name, std::vector<int>& dofs) {
  static const std::map<std::string, std::vector<int>> types = {
      {"XSYMM", {1, 5, 6}},  {"YSYMM", {2, 4, 6}},
      {"ZSYMM", {3, 4, 5}},  {"XASYMM", {2, 3, 4}},
      {"YASYMM", {1, 3, 5}}, {"ZASYMM", {1, 2, 6}},
      {"PINNED", {1, 2, 3}}, {"ENCASTRE", {1, 2, 3, 4, 5, 6}},
  };
  const auto it = types.find(name);
  if (it == types.end()) return false;
  dofs = it->second;
  return true;
}

/// Element label written in field `field` (an element number rather than a set name)?
bool is_label(const FieldReader& r, std::size_t field) {
  long long v = 0;
  return check_integer(r.text(field), 0, 0, v) != IntCheck::NotWhole; // digits (of any size)
}

/// "P3" → 3 for prefix "P"; 0 for the bare prefix; -1 when the label has another form.
int face_of(const std::string& label, std::string_view prefix) {
  if (label.rfind(prefix, 0) != 0) return -1;
  const std::string_view rest = std::string_view(label).substr(prefix.size());
  if (rest.empty()) return 0;
  const auto n = parse_integer(rest);
  return n && *n >= 1 && *n <= 9 && rest[0] != '+' && rest[0] != '-' ? static_cast<int>(*n) : -1;
}

/// The face of a load exists on the element for this use (FaceUse::Pressure or Thermal).
void check_face(const BuildState& s, const FieldReader& r, ElemId e, int face, FaceUse use) {
  const ElementType t = s.model.mesh.elem_types[e];
  const int nf = n_faces(t, use);
  if (face <= nf) return;
  if (nf > 0)
    r.fail(elem_entity(s, e),
           fmt::format("face {} does not exist; this element type has faces 1-{}", face, nf));
  if (use == FaceUse::Pressure && n_faces(t, FaceUse::Thermal) > 0)
    r.fail(elem_entity(s, e), "the faces of this element type take heat fluxes and films only; a "
                              "pressure needs a continuum element with displacements");
  r.fail(elem_entity(s, e), "this element type has no faces for this load");
}

const Surface& find_surface(BuildState& s, const FieldReader& r) {
  const std::string name = to_upper(r.text(0));
  const auto it = s.model.surfaces.find(name);
  if (it == s.model.surfaces.end())
    r.fail(fmt::format("surface {}", name),
           undefined_name(s, name, NameKind::Surface, r.loc().keyword, "a surface of element faces",
                          "define it with *SURFACE, NAME=… in the model data"));
  if (it->second.node_based)
    r.fail(fmt::format("surface {}", name),
           "this is a node-based surface (TYPE=NODE); a distributed load needs element faces: "
           "define the surface with TYPE=ELEMENT");
  return it->second;
}

/// Common end of every distributed-load keyword: merge into the step's list. The key is element,
/// kind and face, plus the axis for BX/BY/BZ (three independent loads on one element).
void merge_dloads(BuildState& s, const Keyword& kw, std::vector<DistributedLoad>& loads) {
  const std::string family = kw.name;
  merge(
      s.step.dloads, loads, op_new(kw),
      [&](const DistributedLoad& d) { return d.loc.keyword == family; },
      [](const DistributedLoad& d) {
        int axis = d.hydrostatic ? 3 : -1; // HPI/HPE and PI/PE are different loads
        if (d.kind == DistLoadKind::BodyForce || d.kind == DistLoadKind::LineLoad)
          for (int i = 0; i < 3; ++i)
            if (d.direction[i] != 0.0) axis = i;
        return std::tuple(d.elem, static_cast<int>(d.kind), d.face, axis);
      });
}

void require_temperature(const BuildState& s, const FieldReader& r, ElemId e) {
  if (!element_info(s.model.mesh.elem_types[e]).temperature)
    r.fail(elem_entity(s, e), "this element has no temperature DOF, so it cannot take a heat flux "
                              "or film condition; use a heat-transfer or coupled element type");
}
/// SNEG/SPOS/FNEG/FPOS name the sides of a shell.
void require_shell_side(const BuildState& s, const FieldReader& r, ElemId e,
                        const std::string& label) {
  if (element_info(s.model.mesh.elem_types[e]).family != ElementFamily::Shell)
    r.fail(elem_entity(s, e),
           fmt::format("{} names a side of a heat-transfer shell (DS3, DS4, DS8); this element "
                       "is not a shell, so give its face as {}n (n = face number)",
                       label, label[0]));
}
void require_displacement(const BuildState& s, const FieldReader& r, ElemId e) {
  if (!element_info(s.model.mesh.elem_types[e]).displacement)
    r.fail(elem_entity(s, e),
           "this element has no displacement DOFs, so it cannot take a mechanical load");
}

/// The *DLOAD labels a beam element takes: those of Abaqus's beam library gapfem has (P1 and PZ,
/// BZ only in space; pipes also their pressures).
std::string beam_load_labels(ElementType t) {
  const bool planar = element_info(t).space == SpaceRequirement::Planar;
  const bool pipe = t == ElementType::PIPE31 || t == ElementType::PIPE32;
  return fmt::format("{}{}",
                     planar ? "P2 (force per length along the section's n2), PX, PY (global "
                              "directions), BX, BY (force per volume) and GRAV"
                            : "P1, P2 (force per length along the section's n1, n2), PX, PY, PZ "
                              "(global directions), BX, BY, BZ (force per volume) and GRAV",
                     pipe ? ", and as a pipe PI, PE (internal, external pressure), HPI and HPE"
                          : "");
}

/// A distributed load on a beam: P1/P2 (local n1/n2), PX/PY/PZ (global), GRAV, BX/BY/BZ; any
/// other label is an error listing the beam's labels.
DistributedLoad beam_dload(const BuildState& s, const FieldReader& r, ElemId e, DistributedLoad d,
                           const std::string& label) {
  d.elem = e;
  const ElementType t = s.model.mesh.elem_types[e];
  const std::string_view name = element_info(t).name;
  const bool planar = element_info(t).space == SpaceRequirement::Planar;
  auto reject = [&](const std::string& why) {
    r.fail(elem_entity(s, e), fmt::format("{}; a {} takes {}", why, name, beam_load_labels(t)));
  };
  if (d.kind == DistLoadKind::PipePressure) return d;
  if (d.kind == DistLoadKind::Pressure) {
    if (d.face == 0) reject("P is not a beam load: a beam has no faces for a pressure");
    if (d.face > 2) reject(fmt::format("{} is not a beam load", label));
    if (planar && d.face == 1)
      reject("P1 is not a load of a planar beam (it acts along n1 = (0, 0, -1), out of the "
             "plane)");
    d.kind = DistLoadKind::LineLoad;
  } else if ((d.kind == DistLoadKind::LineLoad || d.kind == DistLoadKind::BodyForce) && planar &&
             d.direction[2] != 0.0) {
    reject(fmt::format("{} acts out of the plane of a planar beam", label));
  }
  return d;
}

} // namespace

/// *BOUNDARY, TYPE= (docs/theory/dynamics.md, "Base motion"): VELOCITY and ACCELERATION are
/// history data, not with FIXED (the Keywords Reference: FIXED "cannot be used with the TYPE
/// parameter"), ACCELERATION in *DYNAMIC steps only (also checked when the step runs, for a
/// *BOUNDARY before the procedure keyword and for conditions carried into a later step).
static BoundaryType boundary_type(const BuildState& s, const Keyword& kw, bool history,
                                  bool fixed) {
  const int i = enum_param(kw, "TYPE", {"DISPLACEMENT", "VELOCITY", "ACCELERATION"}, 0);
  const auto type = static_cast<BoundaryType>(i);
  if (type == BoundaryType::Displacement) return type;
  const std::string what = param_text(kw, "TYPE");
  if (!history)
    throw InputError(kw.loc, what,
                     "a prescribed velocity or acceleration is history data; give it on a "
                     "*BOUNDARY inside a step");
  if (fixed)
    throw InputError(kw.loc, what,
                     "FIXED holds the displacement reached at the step start and cannot be used "
                     "with TYPE=VELOCITY or ACCELERATION; remove FIXED or TYPE");
  if (type == BoundaryType::Acceleration && s.scratch.procedure_given &&
      s.step.procedure != Procedure::Dynamic)
    throw InputError(kw.loc, what,
                     fmt::format("a prescribed acceleration needs a *DYNAMIC step; step {} is *{}. "
                                 "Prescribe a displacement (or TYPE=VELOCITY) here, or make the "
                                 "step *DYNAMIC",
                                 s.step.number, procedure_name(s.step.procedure)));
  return type;
}

void handle_boundary(BuildState& s, const Keyword& kw) {
  const bool history = s.in_step;
  if (!history)
    for (const char* p : {"OP", "AMPLITUDE", "FIXED"})
      if (kw.has(p))
        throw InputError(
            kw.loc, p,
            fmt::format("{} is a history-data parameter; use it on a *BOUNDARY inside a step", p));
  const bool fixed = kw.has("FIXED");
  const BoundaryType type = boundary_type(s, kw, history, fixed);
  const int amplitude = amplitude_param(s, kw);
  const bool is_new = history && op_new(kw);
  std::vector<BoundaryEntry> entries;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    std::vector<int> dofs;
    double value = 0.0;
    if (!r.blank(1) && !is_label(r, 1)) {
      const std::string named = canonical(r.text(1));
      if (!bc_type_dofs(named, dofs))
        r.fail(fmt::format("field 2 ({})", r.text(1)),
               "write a DOF number or one of ENCASTRE, PINNED, XSYMM, YSYMM, ZSYMM, XASYMM, "
               "YASYMM, ZASYMM");
      r.at_most(2, "node or node set, boundary type");
    } else {
      r.at_most(4, "node or node set, first DOF, last DOF, value");
      const int first = dof_number(r, 1, "degree of freedom");
      const int last = r.blank(2) ? first : dof_number(r, 2, "degree of freedom");
      if (last < first)
        r.fail("field 3 (last DOF)",
               fmt::format("the last DOF {} is smaller than the first DOF {}", last, first));
      if (first <= 6 && last >= 7)
        r.fail(fmt::format("DOFs {}-{}", first, last),
               "this range includes DOFs 7-10, which gapfem does not have; give DOFs 1-6 and 11 on "
               "separate lines");
      for (int d = first; d <= last; ++d) dofs.push_back(d);
      value = r.real_or(3, 0.0, "value");
      if (!history && value != 0.0 && !s.model_boundary_value_warned) {
        // Abaqus allows only zero values here; CalculiX decks give non-zero ones, meaning the
        // value applied in the first step (unambiguous, so read with one remark)
        s.warn(r.loc(), "a model-data *BOUNDARY with a non-zero value (as CalculiX decks write "
                        "it): the value is applied in the first step with the step's default "
                        "variation, as if the line were inside step 1");
        s.model_boundary_value_warned = true;
      }
    }
    for (NodeId n : resolve_nodes(s, r, 0))
      for (int d : dofs) {
        BoundaryEntry b;
        b.node = n;
        dof_from_abaqus(d, b.dof);
        if (type != BoundaryType::Displacement && d > 6)
          r.fail(fmt::format("DOF {}", d),
                 "TYPE=VELOCITY and TYPE=ACCELERATION prescribe displacements and rotations "
                 "(DOFs 1-6) only");
        b.type = type;
        b.value = fixed ? 0.0 : value;
        b.amplitude = amplitude;
        b.fixed = fixed;
        b.loc = r.loc();
        entries.push_back(b);
      }
  });
  auto all = [](const BoundaryEntry&) { return true; };
  auto key = [](const BoundaryEntry& b) { return std::pair(b.node, static_cast<int>(b.dof)); };
  if (history)
    merge(s.step.boundary, entries, is_new, all, key);
  else
    merge(s.model_boundary, entries, false, all, key);
}

/// *CLOAD (DOF 1-6) and *CFLUX (DOF 11) share the NodalLoad list; OP=NEW acts
/// per keyword.
static void nodal_loads(BuildState& s, const Keyword& kw, bool flux) {
  const int amplitude = amplitude_param(s, kw);
  const bool imaginary = !flux && kw.has("IMAGINARY"); // *STEADY STATE DYNAMICS's out-of-phase part
  std::vector<NodalLoad> entries;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(3, "node or node set, DOF, magnitude");
    DofType dof = DofType::NT;
    if (flux) {
      constexpr std::string_view rule =
          "a concentrated heat flux acts on a temperature DOF: 11 (or 12-25 through the thickness "
          "of a heat-transfer shell), not {}; write 11 or leave it blank";
      const long long d = r.blank(1) ? 11 : r.integer(1, "DOF", 11, kMaxAbaqusDof, rule);
      dof_from_abaqus(static_cast<int>(d), dof);
    } else {
      const long long d = r.integer(1, "DOF", 1, kMaxAbaqusDof, "*CLOAD acts on DOFs 1-6, not {}");
      if (d >= 11) r.fail("field 2 (DOF)", "use *CFLUX for concentrated heat fluxes on DOF 11");
      if (d > 6) r.fail("field 2 (DOF)", fmt::format("*CLOAD acts on DOFs 1-6, not {}", d));
      dof_from_abaqus(static_cast<int>(d), dof);
    }
    const double value = r.real(2, "magnitude");
    for (NodeId n : resolve_nodes(s, r, 0)) {
      NodalLoad l;
      l.node = n;
      l.dof = dof;
      l.value = value;
      l.amplitude = amplitude;
      l.imaginary = imaginary;
      l.loc = r.loc();
      entries.push_back(l);
    }
  });
  merge(
      s.step.cloads, entries, op_new(kw),
      [flux](const NodalLoad& l) { return is_temperature(l.dof) == flux; },
      [](const NodalLoad& l) { return std::tuple(l.node, static_cast<int>(l.dof), l.imaginary); });
}

void handle_cload(BuildState& s, const Keyword& kw) {
  nodal_loads(s, kw, false);
}
void handle_cflux(BuildState& s, const Keyword& kw) {
  nodal_loads(s, kw, true);
}

namespace {
/// A pipe carries one internal and one external pressure: PI with HPI (or PE with HPE) on the
/// same element would each claim the wall's pressure for the hoop stress.
void check_one_pipe_pressure(const BuildState& s, const Keyword& kw) {
  std::map<std::pair<ElemId, int>, const DistributedLoad*> seen;
  for (const DistributedLoad& d : s.step.dloads) {
    if (d.kind != DistLoadKind::PipePressure) continue;
    const auto [it, fresh] = seen.try_emplace({d.elem, d.face}, &d);
    if (fresh || it->second->hydrostatic == d.hydrostatic) continue;
    const char* both = d.face == 1 ? "PI and HPI" : "PE and HPE";
    throw InputError(kw.loc, fmt::format("element {}", s.model.element_label(d.elem)),
                     fmt::format("the pipe has both {} ({} and {}); give one {} pressure per "
                                 "element (remove one with OP=NEW or in another step)",
                                 both, it->second->loc.str(), d.loc.str(),
                                 d.face == 1 ? "internal" : "external"));
  }
}
} // namespace

namespace {
/// The load of a *DLOAD line by its label (field 2) and the fields that label takes.
void read_dload_label(const FieldReader& r, const std::string& label, DistributedLoad& d) {
  const bool hydro_label = label == "HPI" || label == "HPE";
  if (label == "GRAV") {
    r.at_most(6, "element or element set, GRAV, magnitude, direction x, y, z");
    const Vec3 v{r.real_or(3, 0.0, "direction x"), r.real_or(4, 0.0, "direction y"),
                 r.real_or(5, 0.0, "direction z")};
    const double len = std::hypot(v[0], v[1], v[2]);
    if (len == 0.0)
      r.fail("fields 4-6 (direction)", "GRAV needs a non-zero direction vector, e.g. 0, 0, -1");
    d.kind = DistLoadKind::Gravity;
    d.direction = {v[0] / len, v[1] / len, v[2] / len};
  } else if (label == "CENTRIF") {
    r.at_most(9, "element or element set, CENTRIF, omega^2, a point of the axis x, y, z, the "
                 "axis direction x, y, z");
    const Vec3 a{r.real_or(6, 0.0, "axis direction x"), r.real_or(7, 0.0, "axis direction y"),
                 r.real_or(8, 0.0, "axis direction z")};
    const double len = std::hypot(a[0], a[1], a[2]);
    if (len == 0.0)
      r.fail("fields 7-9 (axis direction)",
             "CENTRIF needs the direction of the rotation axis, e.g. 0, 0, 1");
    d.kind = DistLoadKind::Centrifugal;
    d.point = {r.real_or(3, 0.0, "axis point x"), r.real_or(4, 0.0, "axis point y"),
               r.real_or(5, 0.0, "axis point z")};
    d.direction = {a[0] / len, a[1] / len, a[2] / len};
  } else if (label == "BX" || label == "BY" || label == "BZ") {
    r.at_most(3, "element or element set, BX/BY/BZ, magnitude");
    d.kind = DistLoadKind::BodyForce;
    d.direction[label[1] - 'X'] = 1.0;
  } else if (label == "PI" || label == "PE") {
    r.at_most(4, "element or element set, PI/PE, magnitude, effective diameter");
    d.kind = DistLoadKind::PipePressure;
    d.face = label == "PI" ? 1 : 2;
    d.diameter = r.real_or(3, 0.0, "effective diameter");
    if (d.diameter < 0.0)
      r.fail("field 4 (effective diameter)",
             fmt::format("must be positive (or blank for the section's), not {}", d.diameter));
  } else if (hydro_label) {
    r.at_most(6, "element or element set, HPI/HPE, magnitude, zero-pressure height z0, "
                 "reference height z1, effective diameter");
    d.kind = DistLoadKind::PipePressure;
    d.face = label == "HPI" ? 1 : 2;
    d.hydrostatic = true;
    d.z0 = r.real(3, "zero-pressure height z0");
    d.z1 = r.real(4, "reference height z1");
    if (d.z0 == d.z1)
      r.fail("fields 4-5 (z0, z1)",
             fmt::format("the zero-pressure height and the reference height (where the "
                         "pressure is the magnitude) must differ, both are {}",
                         d.z0));
    d.diameter = r.real_or(5, 0.0, "effective diameter");
    if (d.diameter < 0.0)
      r.fail("field 6 (effective diameter)",
             fmt::format("must be positive (or blank for the section's), not {}", d.diameter));
  } else if (label == "PX" || label == "PY" || label == "PZ") {
    r.at_most(3, "element or element set, PX/PY/PZ, magnitude");
    d.kind = DistLoadKind::LineLoad;
    d.direction[label[1] - 'X'] = 1.0;
  } else if (const int face = face_of(label, "P"); face > 0) {
    r.at_most(3, "element or element set, Pn, magnitude");
    d.kind = DistLoadKind::Pressure;
    d.face = face;
  } else if (face == 0) {
    r.at_most(3, "element or element set, P, magnitude");
    d.kind = DistLoadKind::Pressure; // on shells; other elements need a face (checked below)
    d.face = 0;
  } else {
    r.fail(fmt::format("field 2 ({})", r.text(1)),
           "this load label is not supported by gapfem; use Pn (pressure on face n), GRAV, BX, "
           "BY or BZ (beams: P1, P2, PX, PY, PZ, GRAV; pipes also PI, PE, HPI, HPE)");
  }
}

/// The pipe twin of a beam type (B31 → PIPE31), or nullptr: gapfem's pipes are in space.
const char* pipe_twin(ElementType t) {
  if (t == ElementType::B31) return "PIPE31";
  if (t == ElementType::B32) return "PIPE32";
  return nullptr;
}

/// A *DLOAD with a pipe label (PI, PE, HPI, HPE) on an element that is not a pipe.
[[noreturn]] void pipe_label_on_other(const BuildState& s, const FieldReader& r, ElemId e,
                                      const std::string& label) {
  const ElementType t = s.model.mesh.elem_types[e];
  const ElementTypeInfo& info = element_info(t);
  const bool inner = label == "PI" || label == "HPI";
  if (info.family != ElementFamily::Beam)
    r.fail(elem_entity(s, e),
           fmt::format("{} is a pressure on pipe elements (PIPE31, PIPE32); {}", label,
                       info.family == ElementFamily::Shell
                           ? "use P for a pressure on a shell"
                           : "use Pn for a pressure on face n of a continuum element"));
  const char* twin = pipe_twin(t);
  r.fail(elem_entity(s, e),
         fmt::format("{} ({} pipe pressure) acts on pipe elements (PIPE31, PIPE32) only; a {} "
                     "takes {}; {}",
                     label, inner ? "internal" : "external", info.name, beam_load_labels(t),
                     twin ? fmt::format("for a pipe pressure make the elements {} with *BEAM "
                                        "SECTION, SECTION=PIPE",
                                        twin)
                          : std::string("gapfem's pipe elements (PIPE31, PIPE32) are in space")));
}

/// Adds the load of a *DLOAD line to element e (one of its set: `single` when the line names e
/// alone); an element of a set that cannot take the load is skipped where Abaqus skips it.
void add_element_dload(BuildState& s, const FieldReader& r, ElemId e, DistributedLoad d,
                       const std::string& label, bool single, std::vector<DistributedLoad>& loads) {
  const ElementTypeInfo& info = element_info(s.model.mesh.elem_types[e]);
  const bool pipe = s.model.mesh.elem_types[e] == ElementType::PIPE31 ||
                    s.model.mesh.elem_types[e] == ElementType::PIPE32;
  if (d.kind == DistLoadKind::PipePressure && !pipe) {
    if (single || info.family == ElementFamily::Beam) pipe_label_on_other(s, r, e, label);
    return;
  }
  if (d.kind == DistLoadKind::Centrifugal && info.family != ElementFamily::Continuum &&
      info.displacement && info.family != ElementFamily::Spring &&
      info.family != ElementFamily::Gap)
    r.fail(elem_entity(s, e), fmt::format("CENTRIF is available on continuum elements; this {} "
                                          "would turn without its centrifugal force: model the "
                                          "rotating part with continuum elements, or apply the "
                                          "force as *CLOAD",
                                          info.name));
  if (info.family == ElementFamily::Beam) {
    loads.push_back(beam_dload(s, r, e, d, label));
    return;
  }
  if (d.kind == DistLoadKind::Pressure && (d.face == 0) != (info.family == ElementFamily::Shell)) {
    if (d.face == 0)
      r.fail("field 2 (P)", fmt::format("element {} is not a shell: give the face of the "
                                        "pressure, P1, P2, … (face numbers of {}), or use "
                                        "*DSLOAD on a surface",
                                        s.model.element_label(e), info.name));
    r.fail(fmt::format("field 2 ({})", label),
           fmt::format("element {} is a shell ({}), loaded on its reference surface by P "
                       "(its force along the shell's positive normal); use P",
                       s.model.element_label(e), info.name));
  }
  if (info.family == ElementFamily::Shell) {
    if (d.kind == DistLoadKind::Pressure) require_displacement(s, r, e); // not on DS3 …
    d.elem = e;
    loads.push_back(d);
    return;
  }
  if (d.kind == DistLoadKind::LineLoad) {
    if (single)
      r.fail(elem_entity(s, e), fmt::format("{} is a load per unit length on beams; use Pn "
                                            "(pressure on face n), GRAV or BX/BY/BZ here",
                                            label));
    return;
  }
  if (d.kind != DistLoadKind::Pressure) {
    // body loads act on elements with volume; springs, gaps and heat-only elements in a set are
    // skipped, named alone they are an error
    // (a point mass takes GRAV alone)
    const bool massless = info.family == ElementFamily::Spring ||
                          info.family == ElementFamily::Gap || !info.displacement ||
                          (info.family == ElementFamily::Mass &&
                           (d.kind != DistLoadKind::Gravity || info.type == ElementType::ROTARYI));
    if (massless) {
      if (single)
        r.fail(elem_entity(s, e), "body loads need an element with volume and displacement DOFs");
      return;
    }
  } else {
    require_displacement(s, r, e);
    check_face(s, r, e, d.face, FaceUse::Pressure);
  }
  d.elem = e;
  loads.push_back(d);
}
} // namespace

void handle_dload(BuildState& s, const Keyword& kw) {
  const int amplitude = amplitude_param(s, kw);
  std::vector<DistributedLoad> loads;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    const std::string label = canonical(r.text(1));
    if (label == "ROTA" || label == "CORIO")
      r.fail(fmt::format("field 2 ({})", r.text(1)),
             "rotary acceleration (ROTA) and Coriolis (CORIO) loads are not available in gapfem "
             "(CENTRIF is); apply them as *CLOAD at the nodes or as BX/BY/BZ body forces");
    DistributedLoad d;
    d.magnitude = r.real(2, "magnitude");
    d.amplitude = amplitude;
    d.loc = r.loc();
    const bool single = is_label(r, 0);
    const auto elems = resolve_elements(s, r, 0);
    read_dload_label(r, label, d);
    for (ElemId e : elems) add_element_dload(s, r, e, d, label, single, loads);
  });
  merge_dloads(s, kw, loads);
  check_one_pipe_pressure(s, kw);
}

void handle_dsload(BuildState& s, const Keyword& kw) {
  const int amplitude = amplitude_param(s, kw);
  std::vector<DistributedLoad> loads;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(3, "surface, P, magnitude");
    if (canonical(r.text(1)) != "P")
      r.fail(fmt::format("field 2 ({})", r.text(1)),
             "*DSLOAD supports the label P (pressure) only");
    const double mag = r.real(2, "magnitude");
    for (const auto& f : find_surface(s, r).faces) {
      require_displacement(s, r, f.elem);
      check_face(s, r, f.elem, f.face, FaceUse::Pressure);
      DistributedLoad d;
      d.elem = f.elem;
      d.kind = DistLoadKind::Pressure;
      d.face = f.face;
      d.magnitude = mag;
      d.amplitude = amplitude;
      d.loc = r.loc();
      loads.push_back(d);
    }
  });
  merge_dloads(s, kw, loads);
}

void handle_dflux(BuildState& s, const Keyword& kw) {
  const int amplitude = amplitude_param(s, kw);
  std::vector<DistributedLoad> loads;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(3, "element or element set, BF or Sn, magnitude");
    const std::string label = canonical(r.text(1));
    DistributedLoad d;
    d.magnitude = r.real(2, "magnitude");
    d.amplitude = amplitude;
    d.loc = r.loc();
    if (label == "BF") {
      d.kind = DistLoadKind::BodyFlux;
    } else if (label == "SNEG" || label == "SPOS") { // the sides of heat-transfer shells
      d.kind = DistLoadKind::SurfaceFlux;
      d.face = label == "SNEG" ? 1 : 2;
    } else if (const int face = face_of(label, "S"); face > 0) {
      d.kind = DistLoadKind::SurfaceFlux;
      d.face = face;
    } else {
      r.fail(fmt::format("field 2 ({})", r.text(1)),
             "use BF (body flux), Sn (surface flux on face n) or, on heat-transfer shells, SNEG "
             "or SPOS");
    }
    for (ElemId e : resolve_elements(s, r, 0)) {
      require_temperature(s, r, e);
      if (label == "SNEG" || label == "SPOS") require_shell_side(s, r, e, label);
      if (d.face > 0) check_face(s, r, e, d.face, FaceUse::Thermal);
      d.elem = e;
      loads.push_back(d);
    }
  });
  merge_dloads(s, kw, loads);
}

void handle_dsflux(BuildState& s, const Keyword& kw) {
  const int amplitude = amplitude_param(s, kw);
  std::vector<DistributedLoad> loads;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(3, "surface, S, magnitude");
    if (canonical(r.text(1)) != "S")
      r.fail(fmt::format("field 2 ({})", r.text(1)), "*DSFLUX supports the label S only");
    const double mag = r.real(2, "magnitude");
    for (const auto& f : find_surface(s, r).faces) {
      require_temperature(s, r, f.elem);
      check_face(s, r, f.elem, f.face, FaceUse::Thermal);
      DistributedLoad d;
      d.elem = f.elem;
      d.kind = DistLoadKind::SurfaceFlux;
      d.face = f.face;
      d.magnitude = mag;
      d.amplitude = amplitude;
      d.loc = r.loc();
      loads.push_back(d);
    }
  });
  merge_dloads(s, kw, loads);
}

/// Places a face exchange (film F, radiation R) given on one data line: on the faces of a surface
/// (the label `letter` alone), or on face n of elements (`letter`n; on heat-transfer shells
/// `letter`NEG / `letter`POS, their sides); `d` carries everything but element and face.
static void place_face_exchange(BuildState& s, const FieldReader& r, bool surface, char letter,
                                const char* keyword, DistributedLoad d,
                                std::vector<DistributedLoad>& loads) {
  const std::string label = canonical(r.text(1));
  const std::string L(1, letter);
  if (surface) {
    if (label != L)
      r.fail(fmt::format("field 2 ({})", r.text(1)),
             fmt::format("{} supports the label {} only", keyword, L));
    for (const auto& f : find_surface(s, r).faces) {
      require_temperature(s, r, f.elem);
      check_face(s, r, f.elem, f.face, FaceUse::Thermal);
      d.elem = f.elem;
      d.face = f.face;
      loads.push_back(d);
    }
    return;
  }
  const bool side = label == L + "NEG" || label == L + "POS"; // the sides of heat-transfer shells
  d.face = side ? (label == L + "NEG" ? 1 : 2) : face_of(label, L);
  if (d.face <= 0)
    r.fail(fmt::format("field 2 ({})", r.text(1)),
           fmt::format("write the label as {0}n (n = face number) or, on heat-transfer shells, "
                       "{0}NEG or {0}POS",
                       L));
  for (ElemId e : resolve_elements(s, r, 0)) {
    require_temperature(s, r, e);
    if (side) require_shell_side(s, r, e, label);
    check_face(s, r, e, d.face, FaceUse::Thermal);
    d.elem = e;
    loads.push_back(d);
  }
}

/// *FILM (element faces Fn) and *SFILM (surface, F): sink temperature and film
/// coefficient.
static void film(BuildState& s, const Keyword& kw, bool surface) {
  const int sink_amplitude = amplitude_param(s, kw);
  const int film_amplitude = amplitude_param(s, kw, "FILM AMPLITUDE");
  std::vector<DistributedLoad> loads;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(4, surface ? "surface, F, sink temperature, film coefficient"
                         : "element or element set, Fn, sink temperature, film coefficient");
    DistributedLoad d;
    d.kind = DistLoadKind::Film;
    d.sink_temperature = r.real(2, "sink temperature");
    d.magnitude = r.real(3, "film coefficient");
    d.amplitude = sink_amplitude;
    d.film_amplitude = film_amplitude;
    d.loc = r.loc();
    place_face_exchange(s, r, surface, 'F', surface ? "*SFILM" : "*FILM", d, loads);
  });
  merge_dloads(s, kw, loads);
}

void handle_film(BuildState& s, const Keyword& kw) {
  film(s, kw, false);
}
void handle_sfilm(BuildState& s, const Keyword& kw) {
  film(s, kw, true);
}

/// *RADIATE (element faces Rn; RNEG/RPOS on heat-transfer shells) and *SRADIATE (surface, R):
/// radiation to the surroundings, eps sigma ((T_sink - Z)^4 - (T - Z)^4) into the face, with
/// sigma and Z of *PHYSICAL CONSTANTS.
static void radiate(BuildState& s, const Keyword& kw, bool surface) {
  const int sink_amplitude = amplitude_param(s, kw);
  const PhysicalConstants& pc = s.model.constants;
  if (!pc.stefan_boltzmann) {
    s.error(kw.loc, "",
            "radiation needs the Stefan-Boltzmann constant in the model's units: add "
            "*PHYSICAL CONSTANTS, STEFAN BOLTZMANN=<sigma> (and ABSOLUTE ZERO=<Z> when "
            "temperatures are not absolute) before the first *STEP");
    return kw.mark_read();
  }
  std::vector<DistributedLoad> loads;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(4, surface ? "surface, R, sink temperature, emissivity"
                         : "element or element set, Rn, sink temperature, emissivity");
    const std::string label = canonical(r.text(1));
    DistributedLoad d;
    d.kind = DistLoadKind::Radiation;
    d.sink_temperature = r.real(2, "sink temperature");
    d.magnitude = r.real(3, "emissivity");
    if (d.magnitude < 0.0 || d.magnitude > 1.0)
      r.fail("field 4 (emissivity)", "the emissivity must lie between 0 and 1");
    d.stefan_boltzmann = *pc.stefan_boltzmann;
    d.absolute_zero = pc.absolute_zero.value_or(0.0);
    d.amplitude = sink_amplitude;
    d.loc = r.loc();
    if (label.find("CR") != std::string::npos)
      r.fail(fmt::format("field 2 ({})", r.text(1)),
             "cavity radiation (CalculiX's RnCR with *VIEWFACTOR) is not available; radiation "
             "to the surroundings is Rn");
    if (label.find("NU") != std::string::npos)
      r.fail(fmt::format("field 2 ({})", r.text(1)),
             "a non-uniform radiation (RnNU) needs the user subroutine RADIATION, which gapfem "
             "does not call; give the sink temperature and the emissivity on the line (Rn)");
    place_face_exchange(s, r, surface, 'R', surface ? "*SRADIATE" : "*RADIATE", d, loads);
  });
  merge_dloads(s, kw, loads);
}

void handle_radiate(BuildState& s, const Keyword& kw) {
  radiate(s, kw, false);
}
void handle_sradiate(BuildState& s, const Keyword& kw) {
  radiate(s, kw, true);
}

} // namespace gapfem::inp
