// User elements: *USER ELEMENT (its active-DOF data lines), *MATRIX (the constant matrices of a
// LINEAR type) and *UEL PROPERTY (the properties of the elements of a set). docs/user-elements.md.
#include "io/inp/handlers.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

/// UELMAT (a user element with an Abaqus material) is an input error wherever it is asked for.
constexpr const char* kNoUelmat =
    "user elements with an Abaqus material (UELMAT) are not supported; define the material "
    "behaviour inside UEL from its PROPS";

/// The DOF numbers of fields first.. of a line (each known to gapfem, none twice).
std::vector<int> read_dofs(const FieldReader& r, std::size_t first) {
  std::vector<int> dofs;
  for (std::size_t f = first; f < r.size(); ++f) {
    if (r.blank(f)) continue;
    const int d = dof_number(r, f, "DOF");
    if (std::find(dofs.begin(), dofs.end(), d) != dofs.end())
      r.fail(fmt::format("field {} (DOF)", f + 1),
             fmt::format("DOF {} is listed twice for this node; list each active DOF once", d));
    dofs.push_back(d);
  }
  if (dofs.empty()) r.fail("", "no DOF is listed; give the active DOF numbers, e.g. 1, 2, 3");
  return dofs;
}

/// The active DOFs per node position: line 1 for node 1, then "position, DOFs" where the list
/// changes; a list holds until the next change.
std::vector<std::vector<int>> read_node_dofs(BuildState& s, const Keyword& kw, int n_nodes,
                                             const std::string& type) {
  std::vector<const DataLine*> lines;
  for (const DataLine& d : kw.data)
    if (!d.empty()) lines.push_back(&d);
  if (lines.empty())
    throw InputError(kw.loc, fmt::format("TYPE={}", type),
                     "the data line with the active DOFs is missing; give them (e.g. 1, 2, 3) on "
                     "the line after *USER ELEMENT");
  std::vector<std::vector<int>> dofs(static_cast<std::size_t>(n_nodes));
  dofs[0] = read_dofs(s.reader(kw, *lines[0]), 0);
  int last = 1;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const FieldReader r = s.reader(kw, *lines[k]);
    const std::string rule = fmt::format("{} has {} nodes, so a node position is 1 to {}, not {{}}",
                                         type, n_nodes, n_nodes);
    const long long pos = r.integer(0, "node position", 1, n_nodes, rule);
    if (pos <= last)
      r.fail("field 1 (node position)",
             fmt::format("node position {} comes after position {}; give the positions where the "
                         "DOF list changes in increasing order (the first data line is node 1's)",
                         pos, last));
    for (int p = last; p < pos - 1; ++p) dofs[p] = dofs[last - 1];
    dofs[static_cast<std::size_t>(pos - 1)] = read_dofs(r, 1);
    last = static_cast<int>(pos);
  }
  for (int p = last; p < n_nodes; ++p) dofs[p] = dofs[last - 1];
  return dofs;
}

/// All numbers of the data lines, blank fields skipped (Abaqus writes "1.5 ," for a row of one).
std::vector<double> read_numbers(BuildState& s, const Keyword& kw, const char* what) {
  std::vector<double> v;
  for (const DataLine& d : kw.data) {
    const FieldReader r = s.reader(kw, d);
    for (std::size_t f = 0; f < r.size(); ++f)
      if (!r.blank(f)) v.push_back(r.real(f, what));
  }
  return v;
}

} // namespace

void handle_user_element(BuildState& s, const Keyword& kw) {
  s.current_user_element = -1;
  const std::string type = to_upper(trim(param_value(kw, "TYPE", true)));
  for (const char* p : {"FILE", "OLD ELEMENT", "STEP", "INCREMENT"})
    if (kw.has(p))
      throw InputError(kw.loc, p,
                       "gapfem does not read user-element matrices from an Abaqus results file "
                       "(.fil); give NODES=, LINEAR and the matrix with *MATRIX, TYPE=STIFFNESS");
  for (const char* p : {"INTEGRATION", "TENSOR"})
    if (kw.has(p)) throw InputError(kw.loc, p, kNoUelmat);
  const auto number = type.size() > 1 && type[0] == 'U'
                          ? parse_integer(std::string_view(type).substr(1))
                          : std::nullopt;
  if (!number || *number < 1 || *number > 9999)
    throw InputError(kw.loc, fmt::format("TYPE={}", type),
                     "a user element type is U followed by a number from 1 to 9999 (U1, U2, …)");
  for (std::size_t i = 0; i < s.model.user_elements.size(); ++i) {
    const UserElementType& old = s.model.user_elements[i];
    if (old.name != type) continue;
    // a part's *USER ELEMENT is read again for each of its instances: the same definition
    if (old.loc.file == kw.loc.file && old.loc.line == kw.loc.line) {
      s.current_user_element = static_cast<int>(i);
      s.user_element_replayed = true;
      return;
    }
    throw InputError(kw.loc, fmt::format("TYPE={}", type),
                     fmt::format("this user element type is defined twice (first at {}); give "
                                 "each *USER ELEMENT its own TYPE",
                                 old.loc.str()));
  }
  UserElementType t;
  t.name = type;
  t.number = static_cast<int>(*number);
  t.loc = kw.loc;
  t.linear = kw.has("LINEAR");
  t.unsymmetric = kw.has("UNSYMM");
  // (bounds far beyond any real element keep a typing error from asking for gigabytes)
  auto count = [&](std::string_view p, std::string_view what, long long def, long long min,
                   long long max) {
    return static_cast<int>(int_param(kw, p, what, min, max).value_or(def));
  };
  if (!kw.has("NODES"))
    throw InputError(kw.loc, fmt::format("TYPE={}", type),
                     "NODES= is missing: give the number of nodes of each element");
  t.n_nodes = count("NODES", "the number of nodes", 0, 1, 10000);
  if (t.linear)
    for (const char* p : {"PROPERTIES", "I PROPERTIES", "VARIABLES"})
      if (kw.has(p))
        throw InputError(kw.loc, p,
                         "a LINEAR user element is defined by its *MATRIX alone; remove this "
                         "parameter, or remove LINEAR to call the UEL subroutine");
  t.n_properties = count("PROPERTIES", "the number of real properties", 0, 0, 100000);
  t.n_int_properties = count("I PROPERTIES", "the number of integer properties", 0, 0, 100000);
  t.n_variables =
      t.linear ? 0
               : count("VARIABLES", "the number of solution-dependent variables", 1, 1, 1000000);
  t.node_dofs = read_node_dofs(s, kw, t.n_nodes, type);
  // COORDS holds max(COORDINATES, the largest active DOF up to 3) values per node
  int largest = 0;
  for (const auto& d : t.node_dofs)
    for (int x : d)
      if (x <= 3) largest = std::max(largest, x);
  t.n_coords = std::max(count("COORDINATES", "the number of coordinates", 1, 1, 3), largest);
  s.model.user_elements.push_back(std::move(t));
  s.current_user_element = static_cast<int>(s.model.user_elements.size()) - 1;
  s.user_element_replayed = false;
}

void handle_matrix(BuildState& s, const Keyword& kw) {
  if (s.current_user_element < 0) return; // the *USER ELEMENT line was in error (reported)
  UserElementType& t = s.model.user_elements[static_cast<std::size_t>(s.current_user_element)];
  const int which = enum_param(kw, "TYPE", {"STIFFNESS", "MASS"}, -1);
  if (which < 0) throw InputError(kw.loc, "", "TYPE= is missing: give TYPE=STIFFNESS or TYPE=MASS");
  if (s.user_element_replayed) return; // read with the part's first instance
  if (!t.linear)
    throw InputError(kw.loc, fmt::format("TYPE={}", which ? "MASS" : "STIFFNESS"),
                     fmt::format("*MATRIX defines LINEAR user elements, but {} calls the UEL "
                                 "subroutine; add LINEAR to its *USER ELEMENT or remove *MATRIX",
                                 t.name));
  std::vector<double>& target = which == 0 ? t.stiffness : t.mass;
  if (!target.empty())
    throw InputError(kw.loc, fmt::format("TYPE={}", which ? "MASS" : "STIFFNESS"),
                     fmt::format("{} has this matrix already; give each TYPE once", t.name));
  const std::vector<double> v = read_numbers(s, kw, "matrix entry");
  const auto n = static_cast<std::size_t>(t.n_dofs());
  const std::size_t want = t.unsymmetric ? n * n : n * (n + 1) / 2;
  if (v.size() != want)
    throw InputError(
        kw.loc, fmt::format("{} of {}", which ? "mass matrix" : "stiffness matrix", t.name),
        t.unsymmetric
            ? fmt::format("{} has {} DOFs, so with UNSYMM the matrix is {} values ({} x {}, row "
                          "by row); {} are given",
                          t.name, n, want, n, n, v.size())
            : fmt::format("{} has {} DOFs, so the symmetric matrix is its lower triangle by rows, "
                          "{} values (K11 / K21 K22 / K31 K32 K33 …); {} are given",
                          t.name, n, want, v.size()));
  target.assign(n * n, 0.0);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < (t.unsymmetric ? n : i + 1); ++j) {
      target[i * n + j] = v[k];
      if (!t.unsymmetric) target[j * n + i] = v[k];
      ++k;
    }
  if (which == 0) t.stiffness_loc = kw.loc;
}

void handle_uel_property(BuildState& s, const Keyword& kw) {
  UelProperty p;
  p.elset = set_param(s, kw, "ELSET", true);
  p.loc = kw.loc;
  for (const char* m : {"MATERIAL", "ORIENTATION"})
    if (kw.has(m)) throw InputError(kw.loc, m, kNoUelmat);
  for (const char* d : {"ALPHA", "BETA"})
    if (kw.has(d))
      s.warn(kw.loc, fmt::format("{}= (Rayleigh damping of linear user elements) acts only in "
                                 "direct-integration dynamics, which gapfem does not run; it "
                                 "changes nothing here",
                                 d));
  // the values are checked against the element type once the set's elements are bound
  for (const DataLine& d : kw.data) {
    const FieldReader r = s.reader(kw, d);
    for (std::size_t f = 0; f < r.size(); ++f)
      if (!r.blank(f)) p.properties.push_back(r.real(f, "property"));
  }
  s.model.uel_properties.push_back(std::move(p));
}

} // namespace gapfem::inp
