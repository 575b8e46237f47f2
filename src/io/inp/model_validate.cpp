// Completing the model data: materials of sections, element → property binding, spring DOFs,
// material options required by the element types, the model space, and the gap checks that need
// element types and coordinates (spec gap-elements.md §0b, §1.7, §2.2).
#include "io/inp/handlers.hpp"

#include <cmath>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <string>

namespace gapfem::inp {
namespace {

using Kind = PropertyRef::Kind;

const char* keyword_of(Kind k) {
  switch (k) {
  case Kind::Solid:
    return "*SOLID SECTION";
  case Kind::Beam:
    return "*BEAM SECTION";
  case Kind::Shell:
    return "*SHELL SECTION";
  case Kind::Spring:
    return "*SPRING";
  case Kind::Gap:
    return "*GAP";
  case Kind::User:
    return "*UEL PROPERTY";
  case Kind::Substructure:
    return "*SUBSTRUCTURE PROPERTY";
  case Kind::Mass:
    return "*MASS";
  default:
    return "?";
  }
}

/// The property keyword an element family takes.
Kind kind_for(ElementFamily f) {
  switch (f) {
  case ElementFamily::Continuum:
  case ElementFamily::Truss:
  case ElementFamily::HeatTransfer:
    return Kind::Solid;
  case ElementFamily::Beam:
    return Kind::Beam;
  case ElementFamily::Shell:
    return Kind::Shell;
  case ElementFamily::Spring:
    return Kind::Spring;
  case ElementFamily::Gap:
    return Kind::Gap;
  case ElementFamily::User:
    return Kind::User;
  case ElementFamily::Substructure:
    return Kind::Substructure;
  case ElementFamily::Mass:
    return Kind::Mass;
  }
  return Kind::None;
}

/// The property keyword an element type takes (its family's; *DASHPOT for the dashpots, which
/// share the spring's property record).
const char* keyword_of_type(const ElementTypeInfo& info) {
  const ElementType t = info.type;
  if (t == ElementType::DASHPOT1 || t == ElementType::DASHPOT2 || t == ElementType::DASHPOTA)
    return "*DASHPOT";
  return keyword_of(kind_for(info.family));
}

std::string elem_name(const BuildState& s, ElemId e) {
  return fmt::format("element {} ({})", s.model.element_label(e), s.model.element_type_name(e));
}

int resolve_material(BuildState& s, const std::string& name, const SourceLocation& loc) {
  const auto it = s.material_index.find(name);
  if (it != s.material_index.end()) return it->second;
  if (s.bad_materials.count(name)) return -1; // its *MATERIAL was in error (reported)
  s.error(loc, fmt::format("MATERIAL={}", name),
          fmt::format("material {} is not defined; define it with *MATERIAL, NAME={}", name, name));
  return -1;
}

/// Binds the elements of one property's ELSET; reports missing sets, wrong families and elements
/// that already have a property.
void bind_property(BuildState& s, Kind kind, int index, const std::string& elset,
                   const SourceLocation& loc, std::vector<SourceLocation>& owner_loc) {
  const auto* set = find_elset(s, elset);
  if (!set) {
    if (!s.bad_sets.count(elset))
      s.error(loc, fmt::format("ELSET={}", elset),
              undefined_name(s, elset, NameKind::ElementSet, loc.keyword, "an element set",
                             "define it with *ELSET or ELSET= on *ELEMENT"));
    return;
  }
  bool family_reported = false, twice_reported = false;
  for (ElemId e : *set) {
    const ElementTypeInfo& info = element_info(s.model.mesh.elem_types[e]);
    if (kind_for(info.family) != kind) {
      if (!family_reported)
        s.error(loc, elem_name(s, e),
                kind == Kind::Gap
                    ? fmt::format("ELSET {} of *GAP must hold only gap elements (GAPUNI, GAPCYL, "
                                  "GAPSPHER, GAPUNIT, DGAP); remove this element from the set",
                                  elset)
                    : fmt::format("this element is in ELSET {} but {} element needs a {}, not a "
                                  "{}; remove it from the set",
                                  elset, with_article(info.name), keyword_of_type(info),
                                  keyword_of(kind)));
      family_reported = true;
      owner_loc[e] = loc; // reported: no "has no section" for it later
      continue;
    }
    PropertyRef& ref = s.model.element_property[e];
    if (ref.kind != Kind::None) {
      if (!twice_reported)
        s.error(loc, elem_name(s, e),
                fmt::format("this element gets two property definitions, {} and {}; remove it from "
                            "one of the two ELSETs",
                            owner_loc[e].str(), loc.str()));
      twice_reported = true;
      continue;
    }
    ref = PropertyRef{kind, index};
    owner_loc[e] = loc;
  }
}

/// SPRING1/DASHPOT1: dof; SPRING2/DASHPOT2: dof1, dof2; SPRINGA/DASHPOTA: blank first line.
/// (*DASHPOT is kept as a SpringSection with `dashpot` set: handlers_dashpot.cpp.)
void check_spring(BuildState& s, int index) {
  SpringSection& sec = s.model.spring_sections[index];
  const auto* set = find_elset(s, sec.elset);
  if (!set || set->empty()) return;
  const ElementType type = s.model.mesh.elem_types[set->front()];
  const char* keyword = sec.dashpot ? "*DASHPOT" : "*SPRING";
  const char* what = sec.dashpot ? "dashpot" : "spring";
  for (ElemId e : *set)
    if (s.model.mesh.elem_types[e] != type) {
      s.error(sec.loc, elem_name(s, e),
              fmt::format("ELSET {} mixes {} types ({} and {}); use one {} per type", sec.elset,
                          what, element_info(type).name,
                          element_info(s.model.mesh.elem_types[e]).name, keyword));
      return;
    }
  resolve_spring_orientation(s, sec, type);
  const bool axial = type == ElementType::SPRINGA || type == ElementType::DASHPOTA;
  const bool one = type == ElementType::SPRING1 || type == ElementType::DASHPOT1;
  const DataLine& line = s.spring_dof_line[index];
  SourceLocation loc{s.model.source_files[line.file], line.line, keyword};
  const FieldReader r(line, loc);
  try {
    auto dof = [&](std::size_t f) {
      return static_cast<int>(r.integer(f, f == 0 ? "DOF at node 1" : "DOF at node 2", 1, 6,
                                        sec.dashpot ? "dashpots act on DOFs 1-6, not {}"
                                                    : "springs act on DOFs 1-6, not {}"));
    };
    if (axial) {
      if (!line.empty())
        r.fail(fmt::format("ELSET={}", sec.elset),
               fmt::format("for {} elements the first data line must be blank (the {} acts along "
                           "the line between its nodes); put the {} on the second line",
                           element_info(type).name, what,
                           sec.dashpot ? "dashpot data" : "stiffness"));
    } else if (one) {
      r.at_most(1, "DOF");
      sec.dof1 = dof(0);
    } else {
      r.at_most(2, "DOF at node 1, DOF at node 2");
      sec.dof1 = dof(0);
      sec.dof2 = dof(1);
      if (sec.dof1 == sec.dof2)
        for (ElemId e : *set)
          if (const auto n = s.model.mesh.element_nodes(e); n[0] == n[1])
            s.error(s.model.element_location(e), elem_name(s, e),
                    fmt::format("node {} is both nodes of this {} and both DOFs are {} ({} "
                                "at {}), so it never stretches and carries no force; give two "
                                "distinct nodes, or two DOFs of the node to couple",
                                s.model.node_label(n[0]), what, sec.dof1, keyword, sec.loc.str()));
    }
  } catch (const InputError& e) {
    s.diag.error(e);
  }
}

void check_space(BuildState& s) {
  const Mesh& mesh = s.model.mesh;
  ElemId first[4] = {-1, -1, -1, -1}; // by SpaceRequirement
  for (ElemId e = 0; e < mesh.n_elements(); ++e) {
    const auto sp = static_cast<int>(element_info(mesh.elem_types[e]).space);
    if (first[sp] < 0) first[sp] = e;
  }
  const ElemId planar = first[static_cast<int>(SpaceRequirement::Planar)];
  const ElemId axi = first[static_cast<int>(SpaceRequirement::Axisymmetric)];
  const ElemId solid = first[static_cast<int>(SpaceRequirement::ThreeD)];
  auto clash = [&](ElemId a, ElemId b, const char* what) {
    s.error(s.model.element_location(b), elem_name(s, b),
            fmt::format("{} cannot be mixed in one model: {} (defined at {}) and this element; use "
                        "element types of one space only",
                        what, elem_name(s, a), s.model.element_location(a).str()));
  };
  if (planar >= 0 && axi >= 0) clash(planar, axi, "planar and axisymmetric elements");
  if (solid >= 0 && (planar >= 0 || axi >= 0))
    clash(solid, planar >= 0 ? planar : axi, "three-dimensional and two-dimensional elements");
  s.model.space = planar >= 0 ? ModelSpace::Planar
                  : axi >= 0  ? ModelSpace::Axisymmetric
                              : ModelSpace::ThreeD;
}

/// Gap checks that need element types, coordinates and the model space.
/// *GAP CONDUCTANCE / RADIATION / HEAT GENERATION act through the temperature DOFs of GAPUNIT and
/// DGAP elements; on an element set of mechanical gaps only they would be ignored: say so.
void check_gap_thermal_options(BuildState& s, const GapSection& gap,
                               const std::vector<ElemId>& set) {
  const std::pair<bool, const SourceLocation*> options[] = {
      {gap.conductance.given || gap.conductance_pressure.given,
       gap.conductance.given ? &gap.conductance.loc : &gap.conductance_pressure.loc},
      {gap.radiation.given, &gap.radiation.loc},
      {gap.heat_generation.given, &gap.heat_generation.loc}};
  ElementType mechanical = ElementType::GAPUNI;
  for (ElemId e : set) {
    const ElementType t = s.model.mesh.elem_types[e];
    if (t == ElementType::GAPUNIT || t == ElementType::DGAP) return;
    if (element_info(t).family == ElementFamily::Gap) mechanical = t;
  }
  for (const auto& [given, loc] : options)
    if (given && !set.empty())
      s.warn(*loc, fmt::format("ELSET={} holds {} elements, which carry no temperature, so this "
                               "option has no effect; use GAPUNIT or DGAP elements for heat "
                               "transfer across the gap",
                               gap.elset, element_info(mechanical).name));
}

void check_gap(BuildState& s, const GapSection& gap) {
  const auto* set = find_elset(s, gap.elset);
  if (!set) return;
  check_gap_thermal_options(s, gap, *set);
  const Mesh& mesh = s.model.mesh;
  const double tol = 1e-12 * s.model.model_size();
  const bool two_d = s.model.space != ModelSpace::ThreeD;
  const Vec3& n = gap.direction;
  const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  bool sphere_warned = false;
  for (ElemId e : *set) {
    const ElementType t = mesh.elem_types[e];
    if (element_info(t).family != ElementFamily::Gap) continue; // reported by bind_property()
    if (t == ElementType::GAPSPHER && gap.direction_given && !sphere_warned) {
      s.warn(gap.loc, fmt::format("ELSET={}: fields 2-4 (direction) are not used by GAPSPHER "
                                  "elements (spec §2.2: blank) and were ignored",
                                  gap.elset));
      sphere_warned = true;
    }
    std::string problem;
    if ((t == ElementType::GAPCYL || t == ElementType::GAPSPHER) && gap.d == 0.0)
      problem = "GAPCYL and GAPSPHER need a non-zero d (positive: maximum separation, negative: "
                "minimum separation)";
    else if (t == ElementType::GAPCYL && !gap.direction_given)
      problem = "GAPCYL needs the cylinder axis in fields 2-4 of the *GAP data line";
    else if ((t == ElementType::GAPUNI || t == ElementType::GAPUNIT) && two_d &&
             gap.direction_given && std::abs(n[2]) > 1e-12 * norm)
      problem = fmt::format("in {} model the gap direction must lie in the x-y plane; set n_z = 0",
                            with_article(model_space_name(s.model.space)));
    else if (t == ElementType::GAPCYL && two_d &&
             std::hypot(n[0], n[1]) > 1e-12 * norm) // spec §1.7: radial contact in the plane
      problem = fmt::format("in {} model the GAPCYL axis must be the z-axis (0, 0, 1), normal "
                            "to the plane, so that contact is radial in the x-y plane",
                            with_article(model_space_name(s.model.space)));
    else if ((t == ElementType::GAPUNI || t == ElementType::GAPUNIT) && !gap.direction_given) {
      const auto nodes = mesh.element_nodes(e);
      const Vec3& a = mesh.coords[nodes[0]];
      const Vec3& b = mesh.coords[nodes[1]];
      if (std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]) <= tol)
        problem = "the direction is computed from the node coordinates but the two nodes coincide; "
                  "give the direction cosines in fields 2-4 of the *GAP data line";
    }
    if (!problem.empty()) {
      s.error(s.model.element_location(e), elem_name(s, e),
              fmt::format("{} (*GAP at {})", problem, gap.loc.str()));
      if (t != ElementType::GAPUNI && t != ElementType::GAPUNIT) return; // same for all elements
    }
  }
}

/// *UEL PROPERTY: every element of the set is of one user element type, and the data lines hold
/// its PROPERTIES reals and I PROPERTIES integers.
void check_uel_property(BuildState& s, UelProperty& p) {
  const auto* set = find_elset(s, p.elset);
  if (!set || set->empty()) return;
  const Mesh& mesh = s.model.mesh;
  for (ElemId e : *set)
    if (mesh.elem_types[e] != ElementType::USER) return; // reported by bind_property()
  const std::int32_t v = mesh.variant(set->front());
  for (ElemId e : *set)
    if (mesh.variant(e) != v) {
      s.error(p.loc, elem_name(s, e),
              fmt::format("ELSET {} mixes user element types ({} and {}); give each type its own "
                          "*UEL PROPERTY",
                          p.elset, s.model.element_type_name(set->front()),
                          s.model.element_type_name(e)));
      return;
    }
  const UserElementType& t = s.model.user_elements[static_cast<std::size_t>(v)];
  p.type = v;
  const std::vector<double> values = std::move(p.properties);
  p.properties.clear();
  const auto want = static_cast<std::size_t>(t.n_properties + t.n_int_properties);
  if (t.linear && !values.empty()) {
    s.error(p.loc, fmt::format("ELSET={}", p.elset),
            fmt::format("{} is a LINEAR user element, defined by its *MATRIX alone: its *UEL "
                        "PROPERTY takes no data lines",
                        t.name));
    return;
  }
  if (values.size() != want) {
    s.error(p.loc, fmt::format("ELSET={}", p.elset),
            fmt::format("{} takes {} real and {} integer properties (PROPERTIES= and I PROPERTIES= "
                        "of its *USER ELEMENT), {} values in all, 8 per line, reals first; {} are "
                        "given",
                        t.name, t.n_properties, t.n_int_properties, want, values.size()));
    return;
  }
  p.properties.assign(values.begin(), values.begin() + t.n_properties);
  for (std::size_t k = static_cast<std::size_t>(t.n_properties); k < values.size(); ++k) {
    const double x = values[k];
    if (x != std::floor(x) || !(x >= -2147483648.0 && x <= 2147483647.0)) {
      s.error(p.loc, fmt::format("ELSET={}", p.elset),
              fmt::format("value {} is integer property {} of {} (after its {} real properties), "
                          "which must be a whole number from -2147483648 to 2147483647 (UEL's "
                          "JPROPS are 32-bit integers), not {}",
                          k + 1, k + 1 - t.n_properties, t.name, t.n_properties, x));
      return;
    }
    p.int_properties.push_back(static_cast<int>(x));
  }
}

/// Zn elements: their nodes lie where the substructure's retained nodes go (x = R X + t, within
/// POSITION TOL), and a rotated or reflected substructure retains whole vectors at each node.
void check_substructure_placement(BuildState& s) {
  const Model& m = s.model;
  for (ElemId e = 0; e < m.mesh.n_elements(); ++e) {
    if (m.mesh.elem_types[e] != ElementType::SUBSTRUCTURE) continue;
    const PropertyRef ref = m.element_property[e];
    if (ref.kind != Kind::Substructure) continue; // reported
    const SubstructureProperty& p = m.substructure_properties[ref.index];
    const SubstructureType& t = m.substructures[m.mesh.variant(e)];
    const double tol = p.position_tolerance >= 0 ? p.position_tolerance : 1e-4 * t.size;
    const auto nodes = m.mesh.element_nodes(e);
    const bool identity = p.rotation == std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      Vec3 x = p.translation;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) x[i] += p.rotation[i * 3 + j] * t.coords[a][j];
      const Vec3& y = m.mesh.coords[nodes[a]];
      const double d = std::hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]);
      if (tol > 0 && d > tol) {
        s.error(m.element_location(e), elem_name(s, e),
                fmt::format("node {} (position {} of the element) lies {:.4g} from where {} puts "
                            "its retained node {} ({:.6g}, {:.6g}, {:.6g}); the usage nodes must "
                            "match the generation's retained nodes in their order (SORTED: "
                            "ascending labels), placed by *SUBSTRUCTURE PROPERTY (at {}); or "
                            "raise POSITION TOL",
                            m.node_label(nodes[a]), a + 1, d, t.name, t.node_labels[a], x[0], x[1],
                            x[2], p.loc.str()));
        break;
      }
      if (identity) continue;
      for (int group = 0; group < 2; ++group) {
        int count = 0;
        for (int dof : t.node_dofs[a]) count += dof > 3 * group && dof <= 3 * group + 3;
        if (count != 0 && count != 3) {
          s.error(p.loc, elem_name(s, e),
                  fmt::format("{} retains only some of the {} at its node {} (position {}), so "
                              "it cannot be rotated or reflected; retain DOFs {}-{} there, or "
                              "place it by translation only",
                              t.name, group ? "rotations" : "translations", t.node_labels[a], a + 1,
                              3 * group + 1, 3 * group + 3));
          return;
        }
      }
    }
  }
}

/// User element types: a LINEAR type needs its stiffness.
void check_user_types(BuildState& s) {
  for (const UserElementType& t : s.model.user_elements)
    if (t.linear && t.stiffness.empty())
      s.error(t.loc, fmt::format("TYPE={}", t.name),
              "a LINEAR user element needs its stiffness: add *MATRIX, TYPE=STIFFNESS after the "
              "*USER ELEMENT data lines");
}

/// Material options needed by the elements that use each material.
/// The heat-transfer twin of a continuum stress element (C3D20R -> DC3D20, CPE4 -> DC2D4, …).
std::optional<ElementType> heat_twin(ElementType t) {
  const ElementTypeInfo& info = element_info(t);
  if (info.family != ElementFamily::Continuum || info.temperature || !info.cell)
    return std::nullopt;
  const std::string prefix = info.plane == PlaneKind::Axisymmetric ? "DCAX"
                             : info.plane != PlaneKind::None       ? "DC2D"
                                                                   : "DC3D";
  return element_type_from_name(prefix + std::to_string(shape_n_nodes(*info.cell)));
}

/// CalculiX runs heat transfer on stress elements (C3D8, C3D20R, CAX8, …): an element whose
/// material has *CONDUCTIVITY but no *ELASTIC is read as its heat-transfer twin, one warning per
/// type (docs/keywords.md, "CalculiX dialect").
void heat_elements_of_stress_types(BuildState& s) {
  Model& m = s.model;
  struct Change {
    ElementType to;
    int count = 0;
    SourceLocation first; ///< the first such element's definition
  };
  std::map<ElementType, Change> changed;
  for (ElemId e = 0; e < m.mesh.n_elements(); ++e) {
    const PropertyRef ref = m.element_property[e];
    if (ref.kind != Kind::Solid) continue;
    const int mi = m.solid_sections[ref.index].material;
    if (mi < 0) continue;
    const Material& mat = m.materials[mi];
    if (mat.has_elastic() || mat.conductivity.empty()) continue;
    const ElementType t = m.mesh.elem_types[e];
    const auto twin = heat_twin(t);
    if (!twin) continue;
    Change& c = changed.try_emplace(t, Change{*twin, 0, m.element_location(e)}).first->second;
    ++c.count;
    m.mesh.elem_types[e] = *twin;
  }
  for (const auto& [from, c] : changed)
    s.warn(
        c.first,
        fmt::format("{} {} element(s) have a material with *CONDUCTIVITY and no *ELASTIC: they "
                    "are read as {} heat-transfer elements (CalculiX's use of stress elements in "
                    "heat transfer); a step that needs their displacements is an error",
                    c.count, element_info(from).name, element_info(c.to).name));
}

void check_materials(BuildState& s) {
  heat_elements_of_stress_types(s);
  std::map<std::pair<int, int>, bool> reported; // (material, 0 elastic / 1 conductivity)
  for (ElemId e = 0; e < s.model.mesh.n_elements(); ++e) {
    const PropertyRef ref = s.model.element_property[e];
    int m = -1;
    std::string set;
    if (ref.kind == Kind::Solid) {
      m = s.model.solid_sections[ref.index].material;
      set = s.model.solid_sections[ref.index].elset;
    } else if (ref.kind == Kind::Beam) {
      m = s.model.beam_sections[ref.index].material;
      set = s.model.beam_sections[ref.index].elset;
    } else if (ref.kind == Kind::Shell) {
      m = s.model.shell_sections[ref.index].material;
      set = s.model.shell_sections[ref.index].elset;
    }
    if (m < 0) continue;
    const Material& mat = s.model.materials[m];
    const ElementTypeInfo& info = element_info(s.model.mesh.elem_types[e]);
    auto need = [&](int what, bool has, const char* option) {
      if (has || reported[{m, what}] || s.bad_material_options.count({m, what})) return;
      reported[{m, what}] = true;
      s.error(
          mat.loc, fmt::format("material {}", mat.name),
          fmt::format(
              "{} (ELSET {}) needs {} but the material has none; add {} after *MATERIAL, NAME={}",
              elem_name(s, e), set, option, option, mat.name));
    };
    if (info.displacement) need(0, mat.has_elastic(), "*ELASTIC");
    if (info.temperature) need(1, !mat.conductivity.empty(), "*CONDUCTIVITY");
  }
}

} // namespace

namespace {
/// At the end of the model data: a part, instance or assembly left open, and a node named (by
/// an *ELEMENT or *NSET) before a *NODE line that was never read.
void check_open_blocks(BuildState& s) {
  const Model& m = s.model;
  if (s.recording) {
    s.error(s.recording->loc, fmt::format("part {}", s.recording->name),
            "the part has no *END PART; close it before the assembly and the steps");
    s.recording = nullptr;
  }
  if (s.instance.open) {
    s.error(s.instance.loc, fmt::format("instance {}", s.instance.name),
            "the instance has no *END INSTANCE; close it before *END ASSEMBLY");
    s.instance.open = false;
  }
  if (s.in_assembly)
    s.error(s.assembly_loc, "",
            "this *ASSEMBLY has no *END ASSEMBLY; close it before the first *STEP");
  // nodes named before their *NODE line whose line was never read (its keyword reported)
  for (NodeId n : s.awaiting) {
    const SourceRef& at = s.node_src[n];
    s.error(SourceLocation{m.source_files[at.file], at.line, "*NODE"},
            fmt::format("node {}", m.node_label(n)),
            "an *ELEMENT or *NSET above names this node, but this line did not define it; "
            "correct the *NODE keyword above the line");
    break; // one is enough
  }
}

} // namespace

void finish_model_data(BuildState& s) {
  if (s.model_done) return;
  s.model_done = true;
  // With errors already reported, the model is still bound (the steps refer to it) but its
  // checks stay silent: elements without a section, a material without *ELASTIC, ... would only
  // be false follow-ons of a definition reported in error.
  struct Mute {
    Diagnostics& d;
    ~Mute() { d.set_muted(false); }
  } mute{s.diag};
  s.diag.set_muted(s.diag.n_errors() > 0);
  Model& m = s.model;
  check_open_blocks(s);
  for (const auto& [name, part] : s.parts) {
    if (part.instances == 0)
      s.warn(part.loc, fmt::format("part {} is never instanced (*INSTANCE, PART={}), so it is "
                                   "not part of the model",
                                   name, name));
  }
  try {
    for (std::size_t i = 0; i < m.solid_sections.size(); ++i)
      m.solid_sections[i].material =
          resolve_material(s, s.solid_material[i], m.solid_sections[i].loc);
    for (std::size_t i = 0; i < m.solid_sections.size(); ++i)
      if (const std::string& c = s.solid_controls[i]; !c.empty()) {
        const auto it = s.controls_index.find(c);
        if (it != s.controls_index.end())
          m.solid_sections[i].controls = it->second;
        else
          s.error(m.solid_sections[i].loc, fmt::format("CONTROLS={}", c),
                  fmt::format("section controls {} are not defined; define them with *SECTION "
                              "CONTROLS, NAME={}",
                              c, c));
      }
    for (std::size_t i = 0; i < m.beam_sections.size(); ++i)
      if (!m.beam_sections[i].general && !m.beam_sections[i].invalid) // GENERAL: own constants
        m.beam_sections[i].material =
            resolve_material(s, s.beam_material[i], m.beam_sections[i].loc);
    for (std::size_t i = 0; i < m.shell_sections.size(); ++i)
      if (!m.shell_sections[i].invalid)
        m.shell_sections[i].material =
            resolve_material(s, s.shell_material[i], m.shell_sections[i].loc);

    m.element_property.assign(static_cast<std::size_t>(m.mesh.n_elements()), PropertyRef{});
    std::vector<SourceLocation> owner(static_cast<std::size_t>(m.mesh.n_elements()));
    for (std::size_t i = 0; i < m.solid_sections.size(); ++i)
      bind_property(s, Kind::Solid, static_cast<int>(i), m.solid_sections[i].elset,
                    m.solid_sections[i].loc, owner);
    for (std::size_t i = 0; i < m.beam_sections.size(); ++i)
      bind_property(s, Kind::Beam, static_cast<int>(i), m.beam_sections[i].elset,
                    m.beam_sections[i].loc, owner);
    for (std::size_t i = 0; i < m.shell_sections.size(); ++i)
      bind_property(s, Kind::Shell, static_cast<int>(i), m.shell_sections[i].elset,
                    m.shell_sections[i].loc, owner);
    for (std::size_t i = 0; i < m.spring_sections.size(); ++i) {
      bind_property(s, Kind::Spring, static_cast<int>(i), m.spring_sections[i].elset,
                    m.spring_sections[i].loc, owner);
      check_spring(s, static_cast<int>(i));
    }
    for (std::size_t i = 0; i < m.gap_sections.size(); ++i)
      bind_property(s, Kind::Gap, static_cast<int>(i), m.gap_sections[i].elset,
                    m.gap_sections[i].loc, owner);
    for (std::size_t i = 0; i < m.uel_properties.size(); ++i) {
      bind_property(s, Kind::User, static_cast<int>(i), m.uel_properties[i].elset,
                    m.uel_properties[i].loc, owner);
      check_uel_property(s, m.uel_properties[i]);
    }
    for (std::size_t i = 0; i < m.mass_sections.size(); ++i)
      bind_property(s, Kind::Mass, static_cast<int>(i), m.mass_sections[i].elset,
                    m.mass_sections[i].loc, owner);
    check_user_types(s);
    for (std::size_t i = 0; i < m.substructure_properties.size(); ++i)
      bind_property(s, Kind::Substructure, static_cast<int>(i), m.substructure_properties[i].elset,
                    m.substructure_properties[i].loc, owner);
    check_substructure_placement(s);

    // elements without a property: one error per element type (naming the first element)
    std::map<ElementType, std::pair<ElemId, int>> missing;
    // (user elements without properties: LINEAR ones and those with no PROPS and JPROPS)
    auto needs_property = [&](ElemId e) {
      if (m.mesh.elem_types[e] != ElementType::USER) return true;
      const UserElementType& t = m.user_elements[static_cast<std::size_t>(m.mesh.variant(e))];
      return !t.linear && t.n_properties + t.n_int_properties > 0;
    };
    for (ElemId e = 0; e < m.mesh.n_elements(); ++e)
      if (m.element_property[e].kind == Kind::None && owner[e].empty() && needs_property(e)) {
        auto& [first, count] = missing.try_emplace(m.mesh.elem_types[e], e, 0).first->second;
        (void)first;
        ++count;
      }
    for (const auto& [type, fc] : missing) {
      const auto [e, count] = fc;
      const ElementTypeInfo& info = element_info(type);
      const std::string_view name = m.element_type_name(e);
      s.error(m.element_location(e), elem_name(s, e),
              fmt::format("this element has no {}: add it to the ELSET of a {}{}",
                          type == ElementType::USER           ? "properties"
                          : type == ElementType::SUBSTRUCTURE ? "placement"
                                                              : "section",
                          keyword_of_type(info),
                          count > 1 ? fmt::format(" ({} {} elements have none)", count, name)
                                    : std::string()));
    }

    check_materials(s);
    check_space(s);
    resolve_rotary_orientations(s);
    build_deferred_constraints(s);
    for (const auto& gap : m.gap_sections) check_gap(s, gap);

    m.initial_temperature.assign(static_cast<std::size_t>(m.mesh.n_nodes()), 0.0);
    for (const auto& [n, t] : s.initial_temperatures) m.initial_temperature[n] = t;
  } catch (const InputError& e) {
    s.diag.error(e);
  }
}

void finish_deck(BuildState& s) {
  if (s.in_step) {
    s.error(s.step.loc, fmt::format("step {}", s.step.number),
            "the step has no *END STEP; add *END STEP at the end of the step");
    close_step(s);
  }
  // The model-wide checks below (elements without a section, a material without *ELASTIC, ...)
  // would only repeat, as false follow-on errors, the definitions already reported in error: a
  // deck with errors in its keyword blocks gets those alone; the checks run once they are fixed.
  if (s.diag.n_errors() > 0) return;
  finish_model_data(s);
  check_constraints(s);
  check_cyclic_symmetry(s);
}

} // namespace gapfem::inp
