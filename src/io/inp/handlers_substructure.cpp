// Reduced linear parts (docs/substructures.md): *MATRIX INPUT and *MATRIX ASSEMBLE (stiffness
// matrices brought from another code), *SUBSTRUCTURE GENERATE with *RETAINED NODAL DOFS (a
// generation step), the use of a substructure (*ELEMENT, TYPE=Zn, *SUBSTRUCTURE PROPERTY) and
// *SUBSTRUCTURE PATH (recovery of its internal results).
#include "io/inp/handlers.hpp"
#include "model/substructure_file.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <set>

namespace gapfem::inp {
namespace {

/// An Abaqus DOF number gapfem knows (1-6, 11-25) from field f.
int dof_field(const FieldReader& r, std::size_t f, const char* what) {
  return dof_number(r, f, what);
}

/// Rotation about the axis a -> b by `degrees` (right hand), row-major.
std::array<double, 9> axis_rotation(const Vec3& a, const Vec3& b, double degrees) {
  Vec3 n{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& c : n) c /= l;
  const double t = degrees * 3.14159265358979323846 / 180.0, c = std::cos(t), s = std::sin(t);
  const double C = 1 - c;
  return {c + n[0] * n[0] * C,        n[0] * n[1] * C - n[2] * s, n[0] * n[2] * C + n[1] * s,
          n[1] * n[0] * C + n[2] * s, c + n[1] * n[1] * C,        n[1] * n[2] * C - n[0] * s,
          n[2] * n[0] * C - n[1] * s, n[2] * n[1] * C + n[0] * s, c + n[2] * n[2] * C};
}

std::array<double, 9> multiply(const std::array<double, 9>& A, const std::array<double, 9>& B) {
  std::array<double, 9> C{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) C[i * 3 + j] += A[i * 3 + k] * B[k * 3 + j];
  return C;
}

} // namespace

void handle_matrix_input(BuildState& s, const Keyword& kw) {
  if (s.scope.instance != 0 || s.recording)
    throw InputError(kw.loc, "", "*MATRIX INPUT is model data of the whole model, not of a part");
  MatrixInput m;
  m.name = name_param(kw, "NAME", true);
  m.loc = kw.loc;
  if (kw.has("MATRIX"))
    throw InputError(kw.loc, "MATRIX",
                     "gapfem cannot read matrices from Abaqus's .sim files; give the matrix in "
                     "Abaqus's text format (row node, row DOF, column node, column DOF, value)");
  for (const MatrixInput& other : s.model.matrix_inputs)
    if (other.name == m.name)
      throw InputError(kw.loc, fmt::format("NAME={}", m.name),
                       fmt::format("a matrix of this name is defined already (at {}); give each "
                                   "*MATRIX INPUT its own NAME",
                                   other.loc.str()));
  const double scale = real_param(kw, "SCALE FACTOR").value_or(1.0);
  if (!(scale != 0.0) || !std::isfinite(scale))
    throw InputError(kw.loc, "SCALE FACTOR", "give a non-zero scale factor");
  m.symmetric = enum_param(kw, "TYPE", {"SYMMETRIC", "UNSYMMETRIC"}, 0) == 0;
  // (row, col) -> value, to check the mirrored entries of a symmetric matrix given in full
  std::map<std::tuple<Label, int, Label, int>, std::pair<double, SourceLocation>> seen;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(5, "row node, row DOF, column node, column DOF, value");
    MatrixInput::Term t;
    constexpr std::string_view rule =
        "node {} is out of range: node numbers run from 1 to 999999999 (gapfem does not read "
        "Abaqus's internal nodes, whose numbers are negative or zero)";
    const long long rn = r.integer(0, "row node", 1, kMaxLabel, rule);
    const long long cn = r.integer(2, "column node", 1, kMaxLabel, rule);
    t.row_node = rn;
    t.col_node = cn;
    t.row_dof = dof_field(r, 1, "row DOF");
    t.col_dof = dof_field(r, 3, "column DOF");
    t.value = scale * r.real(4, "value");
    if (!std::isfinite(t.value)) r.fail("field 5 (value)", "the value is not a finite number");
    const auto key = std::make_tuple(t.row_node, t.row_dof, t.col_node, t.col_dof);
    if (const auto it = seen.find(key); it != seen.end())
      r.fail("", fmt::format("this term is given twice (first at {}); give each term once",
                             it->second.second.str()));
    if (m.symmetric) {
      const auto mirror = std::make_tuple(t.col_node, t.col_dof, t.row_node, t.row_dof);
      if (const auto it = seen.find(mirror); it != seen.end() && mirror != key) {
        if (it->second.first != t.value)
          r.fail("", fmt::format("the matrix is symmetric but this term ({}) differs from its "
                                 "mirror at {} ({}); give one triangle, or TYPE=UNSYMMETRIC",
                                 t.value, it->second.second.str(), it->second.first));
        seen.emplace(key, std::make_pair(t.value, r.loc()));
        return; // the mirror is already there
      }
    }
    seen.emplace(key, std::make_pair(t.value, r.loc()));
    m.terms.push_back(t);
  });
  if (m.terms.empty())
    throw InputError(kw.loc, fmt::format("NAME={}", m.name),
                     "the matrix has no terms; give lines of row node, row DOF, column node, "
                     "column DOF, value (or INPUT=file)");
  s.model.matrix_inputs.push_back(std::move(m));
}

void handle_matrix_assemble(BuildState& s, const Keyword& kw) {
  if (s.scope.instance != 0 || s.recording)
    throw InputError(kw.loc, "",
                     "*MATRIX ASSEMBLE is model data of the whole model, not of a part");
  for (const char* p : {"MASS", "VISCOUS DAMPING", "STRUCTURAL DAMPING"})
    if (kw.has(p))
      s.warn(kw.loc, fmt::format("{}= acts only in dynamic procedures, which gapfem does not run; "
                                 "the matrix is not used",
                                 p));
  if (!kw.has("STIFFNESS")) {
    if (kw.has("MASS") || kw.has("VISCOUS DAMPING") || kw.has("STRUCTURAL DAMPING")) return;
    throw InputError(kw.loc, "", "give STIFFNESS=name of a *MATRIX INPUT");
  }
  const std::string name = name_param(kw, "STIFFNESS", true);
  const auto it = std::find_if(s.model.matrix_inputs.begin(), s.model.matrix_inputs.end(),
                               [&](const MatrixInput& m) { return m.name == name; });
  if (it == s.model.matrix_inputs.end())
    throw InputError(kw.loc, fmt::format("STIFFNESS={}", name),
                     fmt::format("no matrix is named {}; read it first with *MATRIX INPUT, NAME={}",
                                 name, name));
  const MatrixInput& m = *it;
  // the matrix's own node labels, or (NSET=) the set's nodes taken in the order of those labels
  std::vector<Label> labels;
  for (const auto& t : m.terms) {
    labels.push_back(t.row_node);
    labels.push_back(t.col_node);
  }
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  std::map<Label, NodeId> node_of;
  if (kw.has("NSET")) {
    const std::string nset = set_param(s, kw, "NSET", true);
    const auto* set = find_nset(s, nset);
    if (!set)
      throw InputError(kw.loc, fmt::format("NSET={}", nset),
                       undefined_name(s, nset, NameKind::NodeSet, kw.name, "a node set",
                                      "define it with *NSET before *MATRIX ASSEMBLE"));
    if (s.unsorted_sets.count(nset))
      throw InputError(kw.loc, fmt::format("NSET={}", nset),
                       "gapfem keeps node sets sorted, so an UNSORTED set cannot give the order of "
                       "the matrix's nodes; number the model's nodes as the matrix does, or list "
                       "the set in ascending node order");
    std::vector<NodeId> nodes = *set;
    std::sort(nodes.begin(), nodes.end(), [&](NodeId a, NodeId b) {
      return s.model.mesh.node_labels[a] < s.model.mesh.node_labels[b];
    });
    if (nodes.size() != labels.size())
      throw InputError(kw.loc, fmt::format("NSET={}", nset),
                       fmt::format("matrix {} has {} nodes but the set holds {}; the set gives the "
                                   "model node of each matrix node, in ascending label order",
                                   name, labels.size(), nodes.size()));
    for (std::size_t i = 0; i < labels.size(); ++i) node_of[labels[i]] = nodes[i];
  } else {
    for (Label l : labels) {
      const NodeId n = s.model.mesh.find_node(l);
      if (n < 0)
        throw InputError(m.loc, fmt::format("NAME={}", name),
                         fmt::format("node {} of the matrix is not a node of the model; define it "
                                     "with *NODE, or map the matrix's nodes with *MATRIX "
                                     "ASSEMBLE, NSET=",
                                     l));
      node_of[l] = n;
    }
  }
  for (const auto& t : m.terms) {
    MatrixTerm a{node_of.at(t.row_node), node_of.at(t.col_node), t.row_dof, t.col_dof, t.value};
    s.model.matrix_terms.push_back(a);
    const bool diagonal = t.row_node == t.col_node && t.row_dof == t.col_dof;
    if (m.symmetric && !diagonal) { // the other triangle
      std::swap(a.row_node, a.col_node);
      std::swap(a.row_dof, a.col_dof);
      s.model.matrix_terms.push_back(a);
    }
  }
}

void handle_substructure_generate(BuildState& s, const Keyword& kw) {
  set_procedure(s, kw, Procedure::SubstructureGenerate);
  SubstructureGeneration g;
  g.loc = kw.loc;
  if (!kw.has("TYPE")) // CalculiX's *SUBSTRUCTURE GENERATE has no TYPE=
    s.warn(kw.loc, "TYPE= is missing (CalculiX's layout): the substructure is generated as Z1");
  g.type = kw.has("TYPE") ? to_upper(trim(param_value(kw, "TYPE", true))) : std::string("Z1");
  const auto number = g.type.size() > 1 && g.type[0] == 'Z'
                          ? parse_integer(std::string_view(g.type).substr(1))
                          : std::nullopt;
  if (!number || *number < 1 || *number > 9999)
    throw InputError(kw.loc, fmt::format("TYPE={}", g.type),
                     "a substructure type is Z followed by a number from 1 to 9999 (Z1, Z2, …)");
  g.number = static_cast<int>(*number);
  g.overwrite = kw.has("OVERWRITE");
  if (kw.has("LIBRARY")) g.library = std::string(trim(param_value(kw, "LIBRARY", true)));
  g.recovery = yes_no_param(kw, "RECOVERY MATRIX", true);
  g.mass = yes_no_param(kw, "MASS MATRIX", false);
  for (const char* p : {"STRUCTURAL DAMPING MATRIX", "VISCOUS DAMPING MATRIX", "GRAVITY LOAD"})
    if (yes_no_param(kw, p, false))
      throw InputError(kw.loc, fmt::format("{}=YES", p),
                       "gapfem generates the reduced stiffness and mass (and the recovery data) "
                       "only; remove this parameter");
  for (const char* p : {"NSET", "ELSET"})
    if (kw.has(p))
      s.warn(kw.loc, fmt::format("{}= limits the recovery region in Abaqus; gapfem keeps the "
                                 "recovery data of the whole substructure",
                                 p));
  s.step.generation = std::move(g);
}

/// *SUBSTRUCTURE MATRIX OUTPUT: an output request (the reduced matrices written to a results or
/// text file); gapfem writes them to the substructure library only, so it is a warning.
void handle_substructure_matrix_output(BuildState& s, const Keyword& kw) {
  kw.mark_read();
  if (!s.step.generation) {
    s.warn(kw.loc, "*SUBSTRUCTURE MATRIX OUTPUT outside a *SUBSTRUCTURE GENERATE step writes "
                   "nothing");
    return;
  }
  const SubstructureGeneration& g = *s.step.generation;
  s.warn(kw.loc,
         fmt::format("the reduced matrices are written to the substructure library {}_{}"
                     ".sub (gapfem's format, read back by *ELEMENT, TYPE={}, FILE=), not "
                     "to a separate matrix file{}",
                     g.library.empty() ? std::string("<job>") : g.library, g.type, g.type,
                     kw.has("FILE NAME") ? fmt::format(" ({})", param_value(kw, "FILE NAME", false))
                                         : std::string()));
}

void handle_retained_nodal_dofs(BuildState& s, const Keyword& kw) {
  if (!s.step.generation)
    throw InputError(kw.loc, "",
                     "*RETAINED NODAL DOFS belongs to a *SUBSTRUCTURE GENERATE step; put it after "
                     "*SUBSTRUCTURE GENERATE");
  SubstructureGeneration& g = *s.step.generation;
  const bool sorted = yes_no_param(kw, "SORTED", true);
  if (g.retained_loc.line == 0) g.retained_loc = kw.loc;
  std::map<NodeId, std::vector<int>> dofs; // (sorted by node id while read)
  std::vector<NodeId> order;
  std::set<NodeId> all; // nodes retained with every DOF they carry
  for (const auto& [n, d] : g.retained) {
    dofs[n] = d;
    order.push_back(n);
    if (d.empty()) all.insert(n);
  }
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(3, "node or node set, first DOF, last DOF");
    const std::vector<NodeId> nodes = resolve_nodes(s, r, 0);
    int first = 1, last = 6;
    if (!r.blank(1)) {
      first = dof_field(r, 1, "first DOF");
      last = r.blank(2) ? first : dof_field(r, 2, "last DOF");
      if (last < first) r.fail("field 3 (last DOF)", "the last DOF is below the first");
    }
    for (NodeId n : nodes) {
      auto [it, added] = dofs.try_emplace(n);
      if (added) order.push_back(n);
      // a node without DOFs keeps every DOF it carries: an empty list (resolved at generation)
      if (r.blank(1) || (!added && it->second.empty())) {
        it->second.clear();
        all.insert(n);
        continue;
      }
      if (all.count(n)) continue;
      for (int d = first; d <= last; ++d) {
        DofType t{};
        if (!dof_from_abaqus(d, t)) continue; // 7-10: DOFs gapfem does not have
        if (std::find(it->second.begin(), it->second.end(), d) == it->second.end())
          it->second.push_back(d);
      }
      std::sort(it->second.begin(), it->second.end());
    }
  });
  if (sorted)
    std::sort(order.begin(), order.end(), [&](NodeId a, NodeId b) {
      return s.model.mesh.node_labels[a] < s.model.mesh.node_labels[b];
    });
  g.retained.clear();
  for (NodeId n : order) g.retained.emplace_back(n, dofs[n]);
}

void handle_substructure_property(BuildState& s, const Keyword& kw) {
  SubstructureProperty p;
  p.elset = set_param(s, kw, "ELSET", true);
  p.loc = kw.loc;
  if (auto tol = real_param(kw, "POSITION TOL")) {
    if (*tol < 0)
      throw InputError(kw.loc, param_text(kw, "POSITION TOL"), "give a tolerance of 0 or more");
    p.position_tolerance = *tol;
  }
  std::vector<const DataLine*> lines;
  for (const DataLine& d : kw.data) lines.push_back(&d);
  while (!lines.empty() && lines.back()->empty()) lines.pop_back();
  if (lines.empty() || lines.size() == 3 || lines.size() > 4)
    throw InputError(kw.loc, fmt::format("ELSET={}", p.elset),
                     "give a translation line; a rotation line (points a, b on the axis, angle "
                     "in degrees); and, to reflect, two lines with three points of the mirror "
                     "plane (a blank rotation line before them for a reflection alone)");
  for (const DataLine* l : lines) l->read = true; // (a blank rotation line keeps its place)
  auto vec = [&](const FieldReader& r, std::size_t f, const char* what) {
    return Vec3{r.real_or(f, 0.0, what), r.real_or(f + 1, 0.0, what), r.real_or(f + 2, 0.0, what)};
  };
  // x' = t + Rot(Refl(x)): reflected first, then rotated about the axis through a, then
  // translated; each an affine map x -> A x + s
  auto affine = [](const std::array<double, 9>& A, const Vec3& point) {
    Vec3 shift = point; // a map that keeps `point` fixed: s = point - A point
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) shift[i] -= A[i * 3 + j] * point[j];
    return shift;
  };
  Vec3 t{};
  {
    const FieldReader r = s.reader(kw, *lines[0]);
    r.at_most(3, "translation x, y, z");
    t = vec(r, 0, "translation");
  }
  std::array<double, 9> R{1, 0, 0, 0, 1, 0, 0, 0, 1}, M = R;
  Vec3 sR{}, sM{};
  if (lines.size() >= 2 && !lines[1]->empty()) {
    const FieldReader r = s.reader(kw, *lines[1]);
    r.at_most(7, "axis point a (x, y, z), axis point b (x, y, z), angle in degrees");
    const Vec3 a = vec(r, 0, "axis point a"), b = vec(r, 3, "axis point b");
    const double angle = r.real(6, "angle");
    if (!(std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]) > 0))
      r.fail("", "the two points of the rotation axis coincide");
    R = axis_rotation(a, b, angle);
    sR = affine(R, a);
  }
  if (lines.size() == 4) { // reflection in the plane through a, b, c
    const FieldReader r3 = s.reader(kw, *lines[2]), r4 = s.reader(kw, *lines[3]);
    r3.at_most(6, "plane points a (x, y, z) and b (x, y, z)");
    r4.at_most(3, "plane point c (x, y, z)");
    const Vec3 a = vec(r3, 0, "plane point a"), b = vec(r3, 3, "plane point b"),
               c = vec(r4, 0, "plane point c");
    const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    Vec3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(l > 0)) r4.fail("", "the three points of the reflection plane lie on a line");
    for (double& x : n) x /= l;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) M[i * 3 + j] = (i == j ? 1.0 : 0.0) - 2.0 * n[i] * n[j];
    sM = affine(M, a);
  }
  p.rotation = multiply(R, M);
  for (int i = 0; i < 3; ++i) {
    p.translation[i] = t[i] + sR[i];
    for (int j = 0; j < 3; ++j) p.translation[i] += R[i * 3 + j] * sM[j];
  }
  s.model.substructure_properties.push_back(std::move(p));
}

void handle_substructure_path(BuildState& s, const Keyword& kw) {
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    for (std::size_t f = 0; f < r.size(); ++f) {
      if (r.blank(f)) continue;
      for (ElemId e : resolve_elements(s, r, f)) {
        if (s.model.mesh.elem_types[e] != ElementType::SUBSTRUCTURE)
          r.fail(fmt::format("element {}", s.model.element_label(e)),
                 fmt::format("*SUBSTRUCTURE PATH names substructure (Zn) elements whose internal "
                             "results are recovered; this one is {}",
                             with_article(s.model.element_type_name(e))));
        const SubstructureType& t = s.model.substructures[s.model.mesh.variant(e)];
        if (!t.recoverable)
          r.fail(fmt::format("element {}", s.model.element_label(e)),
                 fmt::format("'{}' holds no recovery data ({} was generated with RECOVERY "
                             "MATRIX=NO); generate it again with RECOVERY MATRIX=YES",
                             t.file, t.name));
        if (std::find(s.step.recover_substructures.begin(), s.step.recover_substructures.end(),
                      e) == s.step.recover_substructures.end())
          s.step.recover_substructures.push_back(e);
      }
    }
  });
  if (s.step.recover_substructures.empty())
    throw InputError(kw.loc, "",
                     "name the substructure elements (numbers or element sets) whose internal "
                     "results are recovered on the data lines");
}

std::int32_t load_substructure_type(BuildState& s, const Keyword& kw, const std::string& type) {
  namespace fs = std::filesystem;
  const fs::path deck_dir = fs::path(kw.loc.file).parent_path();
  fs::path file;
  if (kw.has("FILE")) {
    file = fs::path(trim(param_value(kw, "FILE", true)));
    if (file.extension() != ".sub") file = file.string() + "_" + type + ".sub";
    if (file.is_relative()) file = deck_dir / file;
  } else {
    // the library in the deck's folder that holds this type
    std::vector<fs::path> found;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(deck_dir.empty() ? "." : deck_dir, ec)) {
      const std::string name = e.path().filename().string();
      const std::string tail = "_" + type + ".sub";
      if (name.size() > tail.size() &&
          name.compare(name.size() - tail.size(), tail.size(), tail) == 0)
        found.push_back(e.path());
    }
    if (found.size() != 1)
      throw InputError(kw.loc, fmt::format("TYPE={}", type),
                       found.empty()
                           ? fmt::format("no substructure library holds {} in this deck's folder; "
                                         "give its library with FILE= (the generation job's name, "
                                         "or its LIBRARY=)",
                                         type)
                           : fmt::format("{} libraries in this deck's folder hold {}; say which "
                                         "with FILE=",
                                         found.size(), type));
    file = found[0];
  }
  for (std::size_t i = 0; i < s.model.substructures.size(); ++i)
    if (fs::path(s.model.substructures[i].file) == file && s.model.substructures[i].name == type)
      return static_cast<std::int32_t>(i);
  SubstructureLibrary lib;
  try {
    lib = read_substructure_file(file, false);
  } catch (const SubstructureFileError& e) {
    throw InputError(kw.loc, fmt::format("TYPE={}", type), e.what());
  }
  if (lib.type.name != type)
    throw InputError(
        kw.loc, fmt::format("TYPE={}", type),
        fmt::format("'{}' holds substructure {}, not {}", file.string(), lib.type.name, type));
  lib.type.recoverable = lib.has_recovery;
  s.model.substructures.push_back(std::move(lib.type));
  return static_cast<std::int32_t>(s.model.substructures.size()) - 1;
}

} // namespace gapfem::inp
