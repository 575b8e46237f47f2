// Material and other property keywords: *MATERIAL with *ELASTIC, *DENSITY, *EXPANSION,
// *CONDUCTIVITY, *SPECIFIC HEAT; *INITIAL CONDITIONS, *PHYSICAL CONSTANTS.
#include "io/inp/handlers.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numeric>

namespace gapfem::inp {
namespace {

Material& current_material(BuildState& s) {
  return s.model.materials[s.current_material];
}

/// Rejects a second use of the same material option.
void once(BuildState& s, const Keyword& kw, const PropertyTable& t) {
  if (!t.empty())
    throw InputError(kw.loc, "",
                     fmt::format("{} is given twice for material {}; keep one definition", kw.name,
                                 current_material(s).name));
}

std::string positive_first(const std::vector<double>& v) {
  return v[0] > 0 ? std::string() : fmt::format("the value must be positive, not {}", v[0]);
}

} // namespace

void handle_material(BuildState& s, const Keyword& kw) {
  s.current_material = -1;
  const std::string name = name_param(kw, "NAME", true);
  if (const auto it = s.material_index.find(name); it != s.material_index.end())
    throw InputError(kw.loc, fmt::format("material {}", name),
                     fmt::format("this material is defined twice (first at {}); use another NAME",
                                 s.model.materials[it->second].loc.str()));
  Material m;
  m.name = name;
  m.loc = kw.loc;
  s.model.materials.push_back(std::move(m));
  s.current_material = static_cast<int>(s.model.materials.size()) - 1;
  s.material_index[name] = s.current_material;
}

void handle_elastic(BuildState& s, const Keyword& kw) {
  if (s.current_material < 0) return;                     // *MATERIAL line was in error
  s.bad_material_options.insert({s.current_material, 0}); // until it is read
  // ISO is the abbreviation CalculiX decks use (CalculiX User's Manual, *ELASTIC)
  enum_param(kw, "TYPE", {"ISOTROPIC", "ISO"}, 0);
  reject_param(kw, "MODULI", "give the instantaneous isotropic moduli E and nu");
  once(s, kw, current_material(s).elastic);
  current_material(s).elastic = read_property_table(
      s, kw, kw.data, {"Young's modulus E", "Poisson's ratio nu"},
      [](const auto& v) {
        if (v[0] <= 0) return fmt::format("Young's modulus must be positive, not {}", v[0]);
        if (v[1] <= -1.0 || v[1] >= 0.5)
          return fmt::format("Poisson's ratio must lie between -1 and 0.5 (exclusive), not {}",
                             v[1]);
        return std::string();
      },
      1); // a blank Poisson's ratio is 0, as Abaqus reads a blank field
  s.bad_material_options.erase({s.current_material, 0});
}

void handle_density(BuildState& s, const Keyword& kw) {
  if (s.current_material < 0) return;
  once(s, kw, current_material(s).density);
  current_material(s).density = read_property_table(s, kw, kw.data, {"density"}, positive_first);
}

void handle_expansion(BuildState& s, const Keyword& kw) {
  if (s.current_material < 0) return;
  enum_param(kw, "TYPE", {"ISO", "ISOTROPIC"}, 0);
  once(s, kw, current_material(s).expansion);
  current_material(s).expansion_zero = real_param(kw, "ZERO").value_or(0.0);
  current_material(s).expansion =
      read_property_table(s, kw, kw.data, {"expansion coefficient"}, nullptr);
}

void handle_conductivity(BuildState& s, const Keyword& kw) {
  if (s.current_material < 0) return;
  s.bad_material_options.insert({s.current_material, 1}); // until it is read
  enum_param(kw, "TYPE", {"ISO", "ISOTROPIC"}, 0);
  once(s, kw, current_material(s).conductivity);
  current_material(s).conductivity =
      read_property_table(s, kw, kw.data, {"conductivity"}, positive_first);
  s.bad_material_options.erase({s.current_material, 1});
}

void handle_specific_heat(BuildState& s, const Keyword& kw) {
  if (s.current_material < 0) return;
  once(s, kw, current_material(s).specific_heat);
  current_material(s).specific_heat =
      read_property_table(s, kw, kw.data, {"specific heat"}, positive_first);
}

namespace {

/// TYPE=VELOCITY: node or set, DOF (1-6), velocity in the node's system, one per line.
void read_initial_velocities(BuildState& s, const Keyword& kw) {
  s.model.initial_velocity_loc = kw.loc;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(3, "node or node set, degree of freedom, velocity");
    const auto dof = static_cast<int>(r.integer(1, "degree of freedom", 1, 6));
    const double v = r.real(2, "velocity");
    for (NodeId n : resolve_nodes(s, r, 0))
      s.model.initial_velocities.push_back({n, dof, v, false});
  });
}

/// TYPE=ROTATING VELOCITY: node or set, omega, point a, point b (the axis from a to b); an
/// optional line after it with a translational velocity (x, y, z) superposed. Global components.
void read_rotating_velocities(BuildState& s, const Keyword& kw) {
  s.model.initial_velocity_loc = kw.loc;
  std::vector<NodeId> last;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    if (!last.empty() && line.fields.size() == 3) { // the translation of the line before
      const Vec3 t{r.real(0, "velocity x"), r.real(1, "velocity y"), r.real(2, "velocity z")};
      for (NodeId n : last)
        for (int i = 0; i < 3; ++i) s.model.initial_velocities.push_back({n, i + 1, t[i], true});
      last.clear();
      return;
    }
    r.at_most(8, "node or node set, angular velocity, axis point a (x, y, z), point b (x, y, z)");
    const double w = r.real(1, "angular velocity");
    const Vec3 a{r.real(2, "a x"), r.real(3, "a y"), r.real(4, "a z")};
    const Vec3 b{r.real(5, "b x"), r.real(6, "b y"), r.real(7, "b z")};
    const Vec3 ab{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double len = std::sqrt(ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]);
    if (!(len > 0.0))
      r.fail("fields 3-8",
             "the axis points a and b coincide; give two distinct points on the axis");
    const Vec3 e{ab[0] / len, ab[1] / len, ab[2] / len};
    last = resolve_nodes(s, r, 0);
    for (NodeId n : last) {
      const Vec3& x = s.model.mesh.coords[n];
      const Vec3 d{x[0] - a[0], x[1] - a[1], x[2] - a[2]};
      const Vec3 v{w * (e[1] * d[2] - e[2] * d[1]), w * (e[2] * d[0] - e[0] * d[2]),
                   w * (e[0] * d[1] - e[1] * d[0])};
      for (int i = 0; i < 3; ++i) {
        s.model.initial_velocities.push_back({n, i + 1, v[i], true});
        s.model.initial_velocities.push_back({n, i + 4, w * e[i], true}); // rotational DOFs
      }
    }
  });
}

} // namespace

void handle_initial_conditions(BuildState& s, const Keyword& kw) {
  const std::string type = canonical(param_value(kw, "TYPE", true));
  if (type == "VELOCITY") return read_initial_velocities(s, kw);
  if (type == "ROTATINGVELOCITY") return read_rotating_velocities(s, kw);
  if (type != "TEMPERATURE")
    throw InputError(kw.loc, fmt::format("TYPE={}", kw.value("TYPE").value_or("")),
                     "gapfem supports TYPE=TEMPERATURE, VELOCITY and ROTATING VELOCITY initial "
                     "conditions");
  s.model.has_initial_temperature = true;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(2, "node or node set, temperature");
    const double value = r.real(1, "temperature");
    for (NodeId n : resolve_nodes(s, r, 0)) s.initial_temperatures.emplace_back(n, value);
  });
}

void handle_physical_constants(BuildState& s, const Keyword& kw) {
  PhysicalConstants& c = s.model.constants;
  c.loc = kw.loc;
  for (const auto& p : kw.params) {
    if (p.key == "ABSOLUTEZERO")
      c.absolute_zero = real_param(kw, "ABSOLUTE ZERO");
    else if (p.key == "STEFANBOLTZMANN")
      c.stefan_boltzmann = real_param(kw, "STEFAN BOLTZMANN");
    else
      s.warn(kw.loc, fmt::format("parameter {} is not used by gapfem and was ignored", p.name));
  }
}

} // namespace gapfem::inp
