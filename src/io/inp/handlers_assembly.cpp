// Abaqus/CAE's deck structure: *PART … *END PART (a mesh with its sets and sections, read once
// per instance), *ASSEMBLY … *END ASSEMBLY, *INSTANCE … *END INSTANCE (a placed copy of a part:
// translation line, then rotation line "a, b, angle" about the axis through points a and b).
// The keywords of a part are kept when it is read and dispatched again for every instance with
// that instance's scope (BuildState::Scope): labels become instance keys, set names get the
// "INSTANCE." prefix, coordinates are placed. The parser calls record_keyword() before anything
// else and runs the replay at *END INSTANCE (parser.cpp).
#include "io/inp/handlers.hpp"
#include "io/inp/parser.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

/// Keywords a part may hold (canonical names). Others (materials, steps, …) belong to the model.
bool part_keyword(const std::string& key) {
  static const char* const kAllowed[] = {"NODE",
                                         "SYSTEM",
                                         "NGEN",
                                         "NFILL",
                                         "ELEMENT",
                                         "ELGEN",
                                         "NSET",
                                         "ELSET",
                                         "SURFACE",
                                         "SOLIDSECTION",
                                         "BEAMSECTION",
                                         "BEAMGENERALSECTION",
                                         "SHELLSECTION",
                                         "SHELLGENERALSECTION",
                                         "TRANSVERSESHEARSTIFFNESS",
                                         "SECTIONPOINTS",
                                         "NODALTHICKNESS",
                                         "SPRING",
                                         "GAP",
                                         "SURFACEBEHAVIOR",
                                         "FRICTION",
                                         "CONTACTDAMPING",
                                         "GAPCONDUCTANCE",
                                         "GAPRADIATION",
                                         "GAPHEATGENERATION",
                                         "EQUATION",
                                         "MPC",
                                         "KINEMATICCOUPLING",
                                         "COUPLING",
                                         "KINEMATIC",
                                         "DISTRIBUTING",
                                         "TRANSFORM",
                                         "ORIENTATION",
                                         "USERELEMENT",
                                         "MATRIX",
                                         "UELPROPERTY"};
  for (const char* k : kAllowed)
    if (key == k) return true;
  return false;
}

/// Is `key` a keyword the parser knows? (Unknown ones are reported when the part is read.)
bool known_keyword(const std::string& key) {
  for (const auto& spec : keyword_table())
    if (canonical(spec.name.substr(1)) == key) return true;
  return false;
}

std::array<double, 9> rotation(const Vec3& axis, double degrees) {
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const double k[3] = {axis[0] / n, axis[1] / n, axis[2] / n};
  const double t = degrees * std::acos(-1.0) / 180.0;
  const double c = std::cos(t), s = std::sin(t), v = 1.0 - c;
  // Rodrigues: R = c I + s [k]x + (1 - c) k k^T
  return {c + v * k[0] * k[0],        v * k[0] * k[1] - s * k[2], v * k[0] * k[2] + s * k[1],
          v * k[1] * k[0] + s * k[2], c + v * k[1] * k[1],        v * k[1] * k[2] - s * k[0],
          v * k[2] * k[0] - s * k[1], v * k[2] * k[1] + s * k[0], c + v * k[2] * k[2]};
}

} // namespace

bool record_keyword(BuildState& s, Keyword& kw) {
  if (s.recording && kw.key != "ENDPART") {
    if (known_keyword(kw.key) && !part_keyword(kw.key))
      s.error(kw.loc, fmt::format("part {}", s.recording->name),
              fmt::format("*{} cannot appear inside *PART; a part holds nodes, elements, sets, "
                          "surfaces and sections. Move it after *END PART (materials and "
                          "interactions are model data, steps come after *END ASSEMBLY)",
                          display_upper(kw.name.size() > 1 ? kw.name.substr(1) : kw.name)));
    else
      s.recording->keywords.push_back(&kw);
    return true;
  }
  if (s.instance.open && kw.key != "ENDINSTANCE") {
    if (known_keyword(kw.key) && !part_keyword(kw.key))
      s.error(kw.loc, fmt::format("instance {}", s.instance.name),
              fmt::format("*{} cannot appear inside *INSTANCE; close the instance with *END "
                          "INSTANCE first",
                          display_upper(kw.name.size() > 1 ? kw.name.substr(1) : kw.name)));
    else
      s.instance.keywords.push_back(&kw);
    return true;
  }
  return false;
}

void handle_part(BuildState& s, const Keyword& kw) {
  const std::string name = name_param(kw, "NAME", true);
  if (s.transparent_parts) { // no *ASSEMBLY or *INSTANCE anywhere in the deck
    if (s.noted_keywords.insert("PART").second)
      s.warn(kw.loc, "*PART in a deck without *ASSEMBLY or *INSTANCE (CalculiX reads such decks): "
                     "the part's contents are read as model data of the whole model");
    return;
  }
  if (s.in_assembly)
    throw InputError(kw.loc, fmt::format("part {}", name),
                     "*PART cannot appear inside *ASSEMBLY; define the parts first, then the "
                     "assembly that instances them");
  if (s.model.mesh.n_nodes() > 0 && !s.assembly_seen && s.parts.empty())
    throw InputError(kw.loc, fmt::format("part {}", name),
                     "this deck defines nodes outside any part before its first *PART; a deck "
                     "with parts defines every node in a part or in the assembly");
  s.assembly_seen = true;
  auto [it, inserted] = s.parts.try_emplace(name);
  if (!inserted)
    throw InputError(kw.loc, fmt::format("part {}", name),
                     fmt::format("part {} is defined twice (first at {}); give each part its own "
                                 "name",
                                 name, it->second.loc.str()));
  it->second.name = name;
  it->second.loc = kw.loc;
  s.recording = &it->second;
}

void handle_end_part(BuildState& s, const Keyword& kw) {
  if (s.transparent_parts) return;
  if (!s.recording)
    throw InputError(kw.loc, "", "*END PART without a matching *PART; remove it or add *PART");
  s.recording = nullptr;
}

void handle_assembly(BuildState& s, const Keyword& kw) {
  if (s.in_assembly)
    throw InputError(kw.loc, "", "*ASSEMBLY inside *ASSEMBLY; close the first with *END ASSEMBLY");
  name_param(kw, "NAME", true); // the assembly's name is not used
  s.in_assembly = true;
  s.assembly_seen = true;
  s.assembly_loc = kw.loc;
}

void handle_end_assembly(BuildState& s, const Keyword& kw) {
  if (!s.in_assembly)
    throw InputError(kw.loc, "",
                     "*END ASSEMBLY without a matching *ASSEMBLY; remove it or add *ASSEMBLY");
  s.in_assembly = false;
}

void handle_instance(BuildState& s, const Keyword& kw) {
  // until it is known to be good, the instance is open but failed: its keywords and *END
  // INSTANCE are consumed without follow-on errors
  s.instance = BuildState::InstanceDef{};
  s.instance.open = true;
  s.instance.failed = true;
  s.instance.loc = kw.loc;
  const std::string name = name_param(kw, "NAME", true);
  const std::string part = name_param(kw, "PART", true);
  s.instance.name = name;
  const std::string ent = fmt::format("instance {}", name);
  if (!s.in_assembly)
    throw InputError(kw.loc, ent, "*INSTANCE must be inside *ASSEMBLY … *END ASSEMBLY");
  if (name.find('.') != std::string::npos)
    throw InputError(kw.loc, ent,
                     "an instance name cannot contain '.', which separates it from labels and "
                     "set names (PART-1-1.12)");
  if (s.instance_index.count(name))
    throw InputError(
        kw.loc, ent,
        fmt::format("instance {} is defined twice; give each instance its own name", name));
  if (!s.parts.count(part) && s.bad_parts.count(part)) return; // reported at its *PART
  if (!s.parts.count(part))
    throw InputError(kw.loc, fmt::format("PART={}", part),
                     fmt::format("part {} is not defined; define it with *PART, NAME={} … *END "
                                 "PART before the assembly",
                                 part, part));
  BuildState::InstanceDef def;
  def.open = true;
  def.name = name;
  def.part = part;
  def.loc = kw.loc;
  def.scope.prefix = name + ".";
  int line_no = 0;
  for (const DataLine& line : kw.data) {
    if (line.empty()) continue;
    const FieldReader r = s.reader(kw, line);
    if (line_no == 0) { // translation
      r.at_most(3, "x, y, z of the translation");
      def.scope.translation = {r.real_or(0, 0.0, "x"), r.real_or(1, 0.0, "y"),
                               r.real_or(2, 0.0, "z")};
    } else if (line_no == 1) { // rotation: a, b, angle
      r.at_most(7, "a_x, a_y, a_z, b_x, b_y, b_z, angle");
      const Vec3 a{r.real_or(0, 0.0, "a_x"), r.real_or(1, 0.0, "a_y"), r.real_or(2, 0.0, "a_z")};
      const Vec3 b{r.real_or(3, 0.0, "b_x"), r.real_or(4, 0.0, "b_y"), r.real_or(5, 0.0, "b_z")};
      const double angle = r.real_or(6, 0.0, "angle");
      const Vec3 axis{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      if (std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]) <=
          1e-12 * (1.0 + std::abs(a[0]) + std::abs(a[1]) + std::abs(a[2])))
        r.fail(ent, "the two points of the rotation axis coincide; give two distinct points a "
                    "and b on the axis, then the angle in degrees");
      def.scope.axis_point = a;
      def.scope.rotation = rotation(axis, angle);
    } else {
      r.fail(ent, "*INSTANCE has at most two data lines: the translation, then the rotation "
                  "(two points on the axis and the angle)");
    }
    ++line_no;
  }
  def.scope.placed = line_no > 0;
  s.instance = std::move(def);
}

void handle_end_instance(BuildState& s, const Keyword& kw) {
  // the replay itself runs in the parser (it dispatches the part's keywords)
  if (!s.instance.open)
    throw InputError(kw.loc, "",
                     "*END INSTANCE without a matching *INSTANCE; remove it or add *INSTANCE");
}

} // namespace gapfem::inp
