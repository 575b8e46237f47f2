// *ORIENTATION (orientation.hpp) and its use by *SPRING / *DASHPOT, ORIENTATION=.
// Abaqus Keywords Reference, *ORIENTATION
// (https://abaqus-docs.mit.edu/2017/English/SIMACAEKEYRefMap/simakey-r-orientation.htm): NAME
// required; DEFINITION=COORDINATES (default: points a, b and optionally the origin c, else the
// global origin), NODES (global node numbers for a, b, c) or OFFSET TO NODES ("cannot be used with
// spring, dashpot, or JOINTC elements"); SYSTEM=RECTANGULAR (default): c the origin, a on the
// local 1-axis, b in the local 1-2 plane; the optional second line gives the local direction about
// which an additional rotation (degrees) turns the two other directions.
#include "io/inp/orientation.hpp"

#include "io/inp/handlers.hpp"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace gapfem::inp {
namespace {

Vec3 minus(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) {
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}
Vec3 scaled(const Vec3& a, double f) {
  return {a[0] * f, a[1] * f, a[2] * f};
}

constexpr const char* kSystems[] = {"RECTANGULAR", "CYLINDRICAL", "SPHERICAL", "Z RECTANGULAR",
                                    "USER"};

/// The first data line: a, b[, c] as coordinates or as node numbers.
void read_points(BuildState& s, const Keyword& kw, const DataLine& line, OrientationDef& o) {
  const FieldReader r = s.reader(kw, line);
  const char* names[] = {"a", "b", "c"};
  if (o.definition == OrientationDef::Definition::Coordinates) {
    r.at_most(9, "a_x, a_y, a_z, b_x, b_y, b_z, c_x, c_y, c_z");
    o.has_origin = !r.blank(6) || !r.blank(7) || !r.blank(8);
    for (int p = 0; p < 3; ++p)
      for (int i = 0; i < 3; ++i)
        o.points[p][i] =
            p < 2 || o.has_origin
                ? r.real_or(3 * p + i, 0.0, fmt::format("coordinate of point {}", names[p]))
                : 0.0;
    for (Vec3& x : o.points) x = s.place(x); // (inside an instance: placed as its nodes are)
    return;
  }
  r.at_most(3, "node a, node b, node c");
  o.has_origin = !r.blank(2);
  for (int p = 0; p < (o.has_origin ? 3 : 2); ++p) {
    o.labels[p] = r.integer(p, fmt::format("node at point {}", names[p]), 1, kMaxLabel);
    o.nodes[p] = s.key(o.labels[p]);
  }
}

/// The optional second data line: local direction and additional rotation.
void read_rotation(BuildState& s, const Keyword& kw, const DataLine& line, OrientationDef& o) {
  const FieldReader r = s.reader(kw, line);
  r.at_most(2, "local direction, additional rotation in degrees");
  o.rotation_axis = static_cast<int>(r.integer_or(0, 1, "local direction", 1, 3));
  o.rotation = r.real_or(1, 0.0, "additional rotation");
}

} // namespace

std::optional<std::array<Vec3, 3>> rectangular_axes(const Vec3& a, const Vec3& b, const Vec3& c,
                                                    int rotation_axis, double rotation_deg) {
  const Vec3 ca = minus(a, c), cb = minus(b, c);
  const double la = norm(ca);
  const Vec3 n = cross(ca, cb);
  const double ln = norm(n);
  // b on the line c-a (to rounding, relative to the lengths given) spans no plane
  if (!(la > 0.0) || !(ln > 1e-12 * la * norm(cb))) return std::nullopt;
  std::array<Vec3, 3> e{scaled(ca, 1.0 / la), Vec3{}, scaled(n, 1.0 / ln)};
  e[1] = cross(e[2], e[0]);
  if (rotation_deg != 0.0) {
    // the two axes after rotation_axis (cyclically) turn by the angle about it
    const int i = rotation_axis % 3, j = (rotation_axis + 1) % 3;
    const double t = rotation_deg * std::numbers::pi / 180.0, cs = std::cos(t), sn = std::sin(t);
    const Vec3 ei = e[i], ej = e[j];
    for (int k = 0; k < 3; ++k) {
      e[i][k] = cs * ei[k] + sn * ej[k];
      e[j][k] = -sn * ei[k] + cs * ej[k];
    }
  }
  return e;
}

void handle_orientation(BuildState& s, const Keyword& kw) {
  OrientationDef o;
  o.name = s.set_name(name_param(kw, "NAME", true));
  o.loc = kw.loc;
  const auto it = s.orientations.find(o.name);
  if (it != s.orientations.end()) {
    const SourceLocation& first = it->second.loc;
    if (first.file == kw.loc.file && first.line == kw.loc.line) return; // a part read again
    throw InputError(kw.loc, param_text(kw, "NAME"),
                     fmt::format("the orientation {} is already defined at {}; orientation names "
                                 "must be unique",
                                 o.name, first.str()));
  }
  o.system = static_cast<OrientationDef::System>(enum_param(
      kw, "SYSTEM", {kSystems[0], kSystems[1], kSystems[2], kSystems[3], kSystems[4]}, 0));
  o.definition = static_cast<OrientationDef::Definition>(
      enum_param(kw, "DEFINITION", {"COORDINATES", "NODES", "OFFSET TO NODES"}, 0));
  int n_lines = 0;
  for_each_line(s, kw, [&](const DataLine& line) {
    ++n_lines;
    if (n_lines == 1 && o.definition != OrientationDef::Definition::OffsetToNodes &&
        o.system != OrientationDef::System::User)
      read_points(s, kw, line, o);
    else if (n_lines == 2)
      read_rotation(s, kw, line, o);
    else if (n_lines > 2)
      s.reader(kw, line).fail("", "*ORIENTATION takes at most two data lines (the points, then "
                                  "the local direction and additional rotation)");
  });
  s.orientations.emplace(o.name, std::move(o));
}

namespace {

/// The axes of `o` for a spring or dashpot, or an InputError's sentence in `why`.
std::optional<std::array<Vec3, 3>> spring_axes(const BuildState& s, const OrientationDef& o,
                                               std::string& why) {
  using D = OrientationDef::Definition;
  if (o.definition == D::OffsetToNodes) {
    why = "DEFINITION=OFFSET TO NODES cannot be used with spring or dashpot elements (Keywords "
          "Reference, *ORIENTATION); give the points' coordinates or global node numbers";
    return std::nullopt;
  }
  if (o.system != OrientationDef::System::Rectangular) {
    why = fmt::format("gapfem takes a rectangular orientation (SYSTEM=RECTANGULAR, the default) "
                      "for springs and dashpots, not SYSTEM={}; give the local axes as a "
                      "rectangular system",
                      kSystems[static_cast<int>(o.system)]);
    return std::nullopt;
  }
  std::array<Vec3, 3> p = o.points;
  if (o.definition == D::Nodes)
    for (int i = 0; i < (o.has_origin ? 3 : 2); ++i) {
      const NodeId n = s.model.mesh.find_node(o.nodes[i]);
      if (n < 0) {
        why = fmt::format("node {} of its first data line is not defined; give the numbers of "
                          "nodes that exist",
                          o.labels[i]);
        return std::nullopt;
      }
      p[i] = s.model.mesh.coords[n];
    }
  if (!o.has_origin) p[2] = Vec3{};
  auto e = rectangular_axes(p[0], p[1], p[2], o.rotation_axis, o.rotation);
  if (!e)
    why = "its points a, b and origin c span no plane (a = c, or b on the line from c to a); "
          "give a on the local 1-axis and b in the local 1-2 plane, off that axis";
  return e;
}

} // namespace

std::optional<std::array<Vec3, 3>> orientation_axes_at(const BuildState& s, const OrientationDef& o,
                                                       const Vec3& x, std::string& why,
                                                       bool* on_axis) {
  if (o.system != OrientationDef::System::Cylindrical) return spring_axes(s, o, why);
  using D = OrientationDef::Definition;
  if (o.definition == D::OffsetToNodes) {
    why = "DEFINITION=OFFSET TO NODES is not available here; give the axis points' coordinates "
          "or global node numbers";
    return std::nullopt;
  }
  std::array<Vec3, 2> p{o.points[0], o.points[1]};
  if (o.definition == D::Nodes)
    for (int i = 0; i < 2; ++i) {
      const NodeId n = s.model.mesh.find_node(o.nodes[i]);
      if (n < 0) {
        why = fmt::format("node {} of its first data line is not defined", o.labels[i]);
        return std::nullopt;
      }
      p[i] = s.model.mesh.coords[n];
    }
  const Vec3 axis = minus(p[1], p[0]);
  if (norm(axis) == 0.0) {
    why = "its points a and b coincide, so they define no axis";
    return std::nullopt;
  }
  const Vec3 e3 = scaled(axis, 1.0 / norm(axis));
  const Vec3 ax = minus(x, p[0]);
  const double along = ax[0] * e3[0] + ax[1] * e3[1] + ax[2] * e3[2];
  const Vec3 r = minus(ax, scaled(e3, along));
  if (!(norm(r) > 1e-12 * std::max(norm(axis), norm(ax)))) {
    why = "a point it is used at lies on the cylindrical system's axis, where the radial "
          "direction is undefined";
    if (on_axis) *on_axis = true;
    return std::nullopt;
  }
  const Vec3 e1 = scaled(r, 1.0 / norm(r));
  return std::array<Vec3, 3>{e1, cross(e3, e1), e3};
}

void resolve_spring_orientation(BuildState& s, SpringSection& sec, ElementType type) {
  if (sec.orientation.empty()) return;
  const char* keyword = sec.dashpot ? "*DASHPOT" : "*SPRING";
  const std::string entity = fmt::format("ORIENTATION={}", sec.orientation);
  if (type == ElementType::SPRINGA || type == ElementType::DASHPOTA) {
    s.error(sec.loc, entity,
            fmt::format("ORIENTATION applies to {0}1 and {0}2 elements only (Keywords "
                        "Reference, {1}); {2} acts along the line joining its nodes: remove "
                        "ORIENTATION, or use {0}2 with local DOFs",
                        sec.dashpot ? "DASHPOT" : "SPRING", keyword, element_info(type).name));
    return;
  }
  const auto it = s.orientations.find(sec.orientation);
  if (it == s.orientations.end()) {
    s.error(sec.loc, entity,
            fmt::format("no *ORIENTATION, NAME={} is defined; define it (a rectangular system: "
                        "point a on the local 1-axis, b in the local 1-2 plane) or correct the "
                        "name",
                        sec.orientation));
    return;
  }
  std::string why;
  sec.axes = spring_axes(s, it->second, why);
  if (!sec.axes)
    s.error(it->second.loc, fmt::format("NAME={}", sec.orientation),
            fmt::format("this orientation is used by ELSET={} at {}: {}", sec.elset, sec.loc.str(),
                        why));
}

void resolve_rotary_orientations(BuildState& s) {
  for (const auto& [index, name] : s.rotary_orientations) {
    MassSection& sec = s.model.mass_sections[index];
    const std::string entity = fmt::format("ORIENTATION={}", name);
    const auto it = s.orientations.find(name);
    if (it == s.orientations.end()) {
      s.error(sec.loc, entity,
              fmt::format("no *ORIENTATION, NAME={} is defined; define it (a rectangular system: "
                          "point a on the local 1-axis, b in the local 1-2 plane) or correct the "
                          "name",
                          name));
      continue;
    }
    std::string why;
    const auto axes = it->second.definition == OrientationDef::Definition::OffsetToNodes
                          ? std::nullopt
                          : spring_axes(s, it->second, why);
    if (it->second.definition == OrientationDef::Definition::OffsetToNodes)
      why = "DEFINITION=OFFSET TO NODES is not taken for a rotary inertia (a one-node element); "
            "give the points' coordinates or global node numbers";
    if (!axes) {
      s.error(it->second.loc, fmt::format("NAME={}", name),
              fmt::format("this orientation is used by *ROTARY INERTIA, ELSET={} at {}: {}",
                          sec.elset, sec.loc.str(), why));
      continue;
    }
    const auto& I = sec.inertia; // I11, I22, I33, I12, I13, I23
    const double L[3][3] = {{I[0], I[3], I[4]}, {I[3], I[1], I[5]}, {I[4], I[5], I[2]}};
    double G[3][3] = {};
    for (int a = 0; a < 3; ++a) // G_ab = sum_ij e_i[a] L_ij e_j[b]
      for (int b = 0; b < 3; ++b)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) G[a][b] += (*axes)[i][a] * L[i][j] * (*axes)[j][b];
    sec.inertia = {G[0][0], G[1][1], G[2][2], G[0][1], G[0][2], G[1][2]};
  }
}

} // namespace gapfem::inp
