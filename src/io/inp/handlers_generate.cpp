// Abaqus's mesh generators and *SYSTEM (docs/keywords.md): *SYSTEM (the local system later node
// coordinates are given in), *NGEN (nodes along a line,
// a circular arc or a parabola between two end nodes), *NFILL (lines of equally spaced nodes
// between two bounding node sets) and *ELGEN (rows, layers and planes of elements copied from a
// master element with node and element number increments). They create what *NODE and *ELEMENT
// lines would; a node or element they generate over an existing number redefines it ("if any node
// is specified more than once, the last specification given is used", Abaqus "Node definition").
#include "io/inp/handlers.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// The most nodes or elements one data line may generate (guards against typos like 1E9).
constexpr long long kMaxGenerated = 100'000'000;

void check_count(const FieldReader& r, long long count) {
  if (count > kMaxGenerated)
    r.fail("", fmt::format("this line would generate {} nodes or elements (at most {}); check the "
                           "counts and increments",
                           count, kMaxGenerated));
}

/// The node a generator's field names; it must be defined above (an error otherwise).
NodeId defined_node(BuildState& s, const FieldReader& r, std::size_t field, std::string_view what) {
  const long long label = r.integer(field, what, 1, kMaxLabel, kLabelRule);
  const Label key = s.key(label);
  const NodeId n = s.model.mesh.find_node(key);
  if (n >= 0 && !s.awaiting.count(n)) return n;
  if (s.bad_nodes.count(key)) throw InputError(r.loc(), "", ""); // reported at its definition
  r.fail(fmt::format("node {}", label),
         fmt::format("the {} is not defined above this line; define it with *NODE first", what));
}

/// Defines node `local` of instance `instance` (its part's numbering) at (placed) coordinates x,
/// or moves it there when it exists (the last definition wins).
NodeId define_node(BuildState& s, const FieldReader& r, int instance, long long local,
                   const Vec3& x) {
  if (local < 1 || local > kMaxLabel)
    r.fail("", fmt::format("a generated node number {} is out of range: node numbers run from 1 "
                           "to 999999999; check the increments",
                           local));
  Mesh& mesh = s.model.mesh;
  const Label key = make_key(instance, local);
  if (const NodeId old = mesh.find_node(key); old >= 0) {
    mesh.coords[old] = x;
    s.node_src[old] = s.ref(r.line());
    s.awaiting.erase(old);
    return old;
  }
  const NodeId id = mesh.n_nodes();
  mesh.node_labels.push_back(key);
  mesh.coords.push_back(x);
  mesh.node_index.emplace(key, id);
  s.node_src.push_back(s.ref(r.line()));
  return id;
}

/// Adds element `key` with the master's type and `nodes` (an error when the number exists).
ElemId add_generated_element(BuildState& s, const FieldReader& r, Label key, ElemId master,
                             const std::vector<NodeId>& nodes) {
  Mesh& mesh = s.model.mesh;
  if (const ElemId old = mesh.find_element(key); old >= 0)
    r.fail(fmt::format("element {}", s.model.label_of_key(key)),
           fmt::format("this generated element number is defined already (at {}); give each "
                       "element its own number",
                       fmt::format("{}:{}", s.model.source_files[mesh.elem_src[old].file],
                                   mesh.elem_src[old].line)));
  const ElemId id = mesh.n_elements();
  mesh.elem_labels.push_back(key);
  mesh.elem_types.push_back(mesh.elem_types[master]);
  if (!mesh.elem_variant.empty()) {
    const int variant = static_cast<std::size_t>(master) < mesh.elem_variant.size()
                            ? mesh.elem_variant[master]
                            : -1;
    mesh.elem_variant.resize(static_cast<std::size_t>(id), -1);
    mesh.elem_variant.push_back(variant);
  }
  mesh.conn.insert(mesh.conn.end(), nodes.begin(), nodes.end());
  mesh.conn_offset.push_back(static_cast<std::int64_t>(mesh.conn.size()));
  mesh.elem_src.push_back(s.ref(r.line()));
  mesh.elem_index.emplace(key, id);
  return id;
}

/// Rectangular coordinates of a point given in SYSTEM R (x, y, z), C (r, theta, z) or S (r,
/// theta, phi), angles in degrees.
Vec3 rectangular(int system, const Vec3& c) {
  const double d = kPi / 180.0;
  if (system == 1) return {c[0] * std::cos(c[1] * d), c[0] * std::sin(c[1] * d), c[2]};
  if (system == 2)
    return {c[0] * std::cos(c[1] * d) * std::cos(c[2] * d),
            c[0] * std::sin(c[1] * d) * std::cos(c[2] * d), c[0] * std::sin(c[2] * d)};
  return c;
}

Vec3 lerp(const Vec3& a, const Vec3& b, double t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

double norm(const Vec3& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// The point at fraction t of the circular arc from a to b about centre c (the shorter arc; with
/// a normal n, the arc turning about n from a to b, which may be 180 degrees or more), its radius
/// varying linearly from |a - c| to |b - c|.
Vec3 arc_point(const FieldReader& r, const Vec3& a, const Vec3& b, const Vec3& c,
               const std::optional<Vec3>& normal, double t) {
  const Vec3 va{a[0] - c[0], a[1] - c[1], a[2] - c[2]}, vb{b[0] - c[0], b[1] - c[1], b[2] - c[2]};
  const double ra = norm(va), rb = norm(vb);
  if (!(ra > 0.0) || !(rb > 0.0))
    r.fail("", "an end node lies on the centre of the arc (LINE=C): give the centre of the circle "
               "in field 4 or fields 5-7");
  Vec3 n = normal ? *normal : cross(va, vb);
  const double nn = norm(n);
  if (!(nn > 1e-12 * ra * rb))
    r.fail("", "the two end nodes and the centre of the arc (LINE=C) lie on one line: the arc's "
               "plane is undefined; for an arc of 180 degrees or more give its normal in fields "
               "8-10");
  n = {n[0] / nn, n[1] / nn, n[2] / nn};
  const Vec3 ua{va[0] / ra, va[1] / ra, va[2] / ra};
  const Vec3 wa = cross(n, ua); // in-plane, 90 degrees ahead of ua about n
  double angle = std::atan2(dot(vb, wa), dot(vb, ua));
  if (angle <= 0.0) angle += 2.0 * kPi;
  const double phi = t * angle, radius = ra + t * (rb - ra);
  Vec3 p;
  for (int i = 0; i < 3; ++i)
    p[i] = c[i] + radius * (std::cos(phi) * ua[i] + std::sin(phi) * wa[i]);
  return p;
}

/// The extra point of LINE=C/P: node (field 3) or coordinates (fields 4-6 in SYSTEM).
Vec3 extra_point(BuildState& s, const FieldReader& r, int system) {
  if (!r.blank(3)) return s.model.mesh.coords[defined_node(s, r, 3, "node of the extra point")];
  if (r.blank(4) && r.blank(5) && r.blank(6))
    r.fail("", "LINE=C and LINE=P need an extra point: its node number in field 4, or its "
               "coordinates in fields 5-7");
  return s.place(s.from_system(rectangular(
      system, {r.real_or(4, 0.0, "first coordinate of the extra point"),
               r.real_or(5, 0.0, "second coordinate"), r.real_or(6, 0.0, "third coordinate")})));
}

/// The normal of an arc of 180 degrees or more (fields 8-10), when given.
std::optional<Vec3> arc_normal(const FieldReader& r) {
  if (r.blank(7) && r.blank(8) && r.blank(9)) return std::nullopt;
  return Vec3{r.real_or(7, 0.0, "first component of the arc's normal"),
              r.real_or(8, 0.0, "second component of the arc's normal"),
              r.real_or(9, 0.0, "third component of the arc's normal")};
}

/// The number of intervals between first and last with increment inc (an error unless whole).
long long intervals(const FieldReader& r, long long first, long long last, long long inc,
                    std::string_view what) {
  const long long span = last - first;
  if (span == 0 || span % inc != 0 || span / inc < 1)
    r.fail("", fmt::format("the {} {} and {} are not a whole positive number of increments {} "
                           "apart; check the node numbers and the increment",
                           what, first, last, inc));
  return span / inc;
}

} // namespace

void handle_system(BuildState& s, const Keyword& kw) {
  BuildState::Scope& sc = s.scope;
  sc.local_system = false; // without data lines: back to the global system
  std::vector<const DataLine*> lines;
  for (const DataLine& d : kw.data)
    if (!d.empty()) lines.push_back(&d);
  if (lines.empty()) return kw.mark_read();
  if (lines.size() > 2) s.reader(kw, *lines[2]).fail("", "*SYSTEM takes at most two data lines");
  const FieldReader r = s.reader(kw, *lines[0]);
  r.at_most(6, "origin Xa, Ya, Za, a point on the local X1-axis Xb, Yb, Zb");
  const Vec3 a{r.real_or(0, 0.0, "Xa"), r.real_or(1, 0.0, "Ya"), r.real_or(2, 0.0, "Za")};
  std::array<double, 9> axes{1, 0, 0, 0, 1, 0, 0, 0, 1};
  if (!r.blank(3) || !r.blank(4) || !r.blank(5)) {
    Vec3 x1{r.real_or(3, 0.0, "Xb") - a[0], r.real_or(4, 0.0, "Yb") - a[1],
            r.real_or(5, 0.0, "Zb") - a[2]};
    Vec3 z{0.0, 0.0, 1.0};
    double scale = 1.0;      // |z| below 1e-12 of it: the points are in line
    if (lines.size() == 2) { // the X1-Y1 plane through point c, on the side of +Y1
      const FieldReader r2 = s.reader(kw, *lines[1]);
      r2.at_most(3, "a point in the local X1-Y1 plane Xc, Yc, Zc");
      const Vec3 c{r2.real_or(0, 0.0, "Xc") - a[0], r2.real_or(1, 0.0, "Yc") - a[1],
                   r2.real_or(2, 0.0, "Zc") - a[2]};
      z = cross(x1, c);
      scale = norm(x1) * norm(c);
    } else { // Z unchanged, X1 projected onto the X-Y plane
      x1[2] = 0.0;
    }
    const double lx = norm(x1), lz = norm(z);
    if (!(lx > 0.0) || !(lz > 1e-12 * scale))
      r.fail("", "the points do not define the local axes: point b must lie off the origin (and, "
                 "without a second line, off the global Z-axis through it), and point c off the "
                 "X1-axis");
    x1 = {x1[0] / lx, x1[1] / lx, x1[2] / lx};
    z = {z[0] / lz, z[1] / lz, z[2] / lz};
    const Vec3 y1 = cross(z, x1);
    for (int i = 0; i < 3; ++i) {
      axes[3 * i] = x1[i];
      axes[3 * i + 1] = y1[i];
      axes[3 * i + 2] = z[i];
    }
  } else if (lines.size() == 2) {
    s.reader(kw, *lines[1])
        .fail("", "a point in the X1-Y1 plane needs the point on the X1-axis "
                  "(fields 4-6 of the first line)");
  }
  for (const DataLine* d : lines) d->read = true;
  sc.local_system = true;
  sc.system_origin = a;
  sc.system_axes = axes;
}

void handle_ngen(BuildState& s, const Keyword& kw) {
  const int line_kind = enum_param(kw, "LINE", {"L", "C", "P"}, 0);
  const int system = enum_param(kw, "SYSTEM", {"RC", "C", "S", "R"}, 0) % 3;
  const std::string nset = set_param(s, kw, "NSET", false);
  std::vector<NodeId> added;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(line_kind == 1   ? 10
              : line_kind == 2 ? 7
                               : 3,
              "first end node, second end node, increment, extra node, its coordinates (LINE=C "
              "and P), the arc's normal (LINE=C)");
    const NodeId a = defined_node(s, r, 0, "first end node");
    const NodeId b = defined_node(s, r, 1, "second end node");
    const long long inc = r.integer_or(2, 1, "increment in node numbers", -kMaxLabel, kMaxLabel);
    const long long la = r.integer(0, "first end node", 1, kMaxLabel, kLabelRule);
    const long long lb = r.integer(1, "second end node", 1, kMaxLabel, kLabelRule);
    if (inc == 0) r.fail("", "the increment in node numbers must not be 0");
    const long long n = intervals(r, la, lb, inc, "end nodes");
    check_count(r, n);
    const Vec3 xa = s.model.mesh.coords[a], xb = s.model.mesh.coords[b];
    const Vec3 extra = line_kind > 0 ? extra_point(s, r, system) : Vec3{};
    const std::optional<Vec3> normal = line_kind == 1 ? arc_normal(r) : std::nullopt;
    added.push_back(a);
    for (long long k = 1; k < n; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(n);
      Vec3 x = lerp(xa, xb, t);
      if (line_kind == 1) x = arc_point(r, xa, xb, extra, normal, t);
      if (line_kind == 2) // the parabola through the ends and the midpoint (t = 1/2)
        for (int i = 0; i < 3; ++i)
          x[i] =
              xa[i] * (1 - t) * (1 - 2 * t) + 4 * extra[i] * t * (1 - t) + xb[i] * t * (2 * t - 1);
      added.push_back(define_node(s, r, s.scope.instance, la + k * inc, x));
    }
    added.push_back(b);
  });
  if (!nset.empty()) add_to_nset(s, nset, added);
}

void handle_nfill(BuildState& s, const Keyword& kw) {
  for (const char* p : {"SINGULAR", "TWO STEP"})
    reject_param(kw, p, "fill between the two bounding sets without it");
  // BIAS: which end a ratio concentrates the nodes toward is not in the pages we could read, and
  // guessing it would move nodes silently: uniform spacing only [decision]
  if (const auto bias = real_param(kw, "BIAS"); bias && *bias != 1.0)
    throw InputError(kw.loc, param_text(kw, "BIAS"),
                     "biased node spacing is not supported by gapfem; fill with uniform spacing "
                     "(BIAS=1) or give the nodes with *NODE or *NGEN");
  const std::string nset = set_param(s, kw, "NSET", false);
  std::vector<NodeId> added;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(4, "first bounding node set, second bounding node set, number of intervals, "
                 "increment in node numbers");
    std::vector<const std::vector<NodeId>*> bounds;
    for (std::size_t f = 0; f < 2; ++f) {
      const std::string name = s.set_name(to_upper(trim(r.text(f))));
      const auto* set = find_nset(s, name);
      if (!set && s.bad_sets.count(name)) throw InputError(r.loc(), "", ""); // reported
      if (!set)
        r.fail(fmt::format("node set {}", r.text(f)),
               "this node set is not defined above this line; define it with *NSET first");
      bounds.push_back(set);
    }
    const long long m = r.integer(2, "number of intervals", 1, kMaxLabel);
    const long long inc = r.integer_or(3, 1, "increment in node numbers", -kMaxLabel, kMaxLabel);
    if (inc == 0) r.fail("", "the increment in node numbers must not be 0");
    // the extra nodes of the longer set are ignored (Abaqus); interval k ends at s_k
    const std::size_t pairs = std::min(bounds[0]->size(), bounds[1]->size());
    check_count(r, m > kMaxGenerated / std::max<long long>(1, static_cast<long long>(pairs))
                       ? kMaxGenerated + 1
                       : m * static_cast<long long>(pairs));
    for (std::size_t i = 0; i < pairs; ++i) {
      const NodeId a = (*bounds[0])[i], b = (*bounds[1])[i];
      const Label ka = s.model.mesh.node_labels[a]; // new nodes: in the instance of the first
      const long long la = key_local(ka);
      const Vec3 xa = s.model.mesh.coords[a], xb = s.model.mesh.coords[b];
      added.push_back(a);
      for (long long k = 1; k < m; ++k) {
        const double t = static_cast<double>(k) / static_cast<double>(m);
        added.push_back(define_node(s, r, key_instance(ka), la + k * inc, lerp(xa, xb, t)));
      }
      added.push_back(b);
    }
  });
  if (!nset.empty()) add_to_nset(s, nset, added);
}

void handle_elgen(BuildState& s, const Keyword& kw) {
  const std::string elset = set_param(s, kw, "ELSET", false);
  std::vector<ElemId> added;
  Mesh& mesh = s.model.mesh;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(10, "master element, then for rows, layers and planes: count, node increment, "
                  "element increment");
    const long long master_label = r.integer(0, "master element", 1, kMaxLabel, kLabelRule);
    const ElemId master = mesh.find_element(s.key(master_label));
    if (master < 0) {
      if (s.bad_elements.count(s.key(master_label))) throw InputError(r.loc(), "", "");
      r.fail(fmt::format("element {}", master_label),
             "the master element is not defined above this line; define it with *ELEMENT first");
    }
    long long count[3], node_inc[3], elem_inc[3];
    for (int d = 0; d < 3; ++d) {
      count[d] = r.integer_or(1 + 3 * d, 1, "number of elements", 1, kMaxLabel);
      node_inc[d] = r.integer_or(2 + 3 * d, 1, "increment in node numbers", -kMaxLabel, kMaxLabel);
      elem_inc[d] =
          r.integer_or(3 + 3 * d, 1, "increment in element numbers", -kMaxLabel, kMaxLabel);
    }
    check_count(r, count[0] > kMaxGenerated / count[1] / count[2] ? kMaxGenerated + 1
                                                                  : count[0] * count[1] * count[2]);
    std::vector<Label> keys; // (copied: adding elements moves the connectivity)
    for (NodeId n : mesh.element_nodes(master)) keys.push_back(mesh.node_labels[n]);
    added.push_back(master);
    for (long long k = 0; k < count[2]; ++k)
      for (long long j = 0; j < count[1]; ++j)
        for (long long i = 0; i < count[0]; ++i) {
          if (i == 0 && j == 0 && k == 0) continue; // the master itself
          const long long label =
              master_label + i * elem_inc[0] + j * elem_inc[1] + k * elem_inc[2];
          const long long shift = i * node_inc[0] + j * node_inc[1] + k * node_inc[2];
          if (label < 1 || label > kMaxLabel)
            r.fail("", fmt::format("a generated element number {} is out of range: element "
                                   "numbers run from 1 to 999999999; check the increments",
                                   label));
          std::vector<NodeId> nodes;
          for (Label nk : keys) {
            const Label moved = make_key(key_instance(nk), key_local(nk) + shift);
            const NodeId n = key_local(nk) + shift >= 1 ? mesh.find_node(moved) : -1;
            if (n < 0)
              r.fail(fmt::format("element {}", label),
                     fmt::format("node {} of this generated element is not defined; define it "
                                 "above (*NODE, *NGEN, *NFILL) or check the node increments",
                                 static_cast<long long>(key_local(nk)) + shift));
            nodes.push_back(n);
          }
          added.push_back(add_generated_element(
              s, r, make_key(key_instance(mesh.elem_labels[master]), label), master, nodes));
        }
  });
  if (!elset.empty()) add_to_elset(s, elset, added);
}

} // namespace gapfem::inp
