#include "output/nodal_average.hpp"

#include "fe/quadrature.hpp"
#include "fe/shape_functions.hpp"
#include "model/element_types.hpp"
#include "output/output_file.hpp"

#include <Eigen/Dense>
#include <array>
#include <cctype>

namespace gapfem::output {
namespace {

Shape corner_shape(Shape s) {
  switch (s) {
  case Shape::Line3:
    return Shape::Line2;
  case Shape::Tri6:
    return Shape::Tri3;
  case Shape::Quad8:
    return Shape::Quad4;
  case Shape::Tet10:
    return Shape::Tet4;
  case Shape::Wedge15:
    return Shape::Wedge6;
  case Shape::Hex20:
    return Shape::Hex8;
  default:
    return s;
  }
}

/// The corner shape functions of `corner` at parametric point `xi`.
Eigen::RowVectorXd corner_values(Shape corner, const std::array<double, 3>& xi) {
  const int n = shape_n_nodes(corner);
  std::array<double, 27 * 3> dN{};
  Eigen::RowVectorXd N(n);
  shape_eval(corner, xi, std::span<double>(N.data(), static_cast<std::size_t>(n)),
             std::span<double>(dN.data(), static_cast<std::size_t>(n * shape_dim(corner))));
  return N;
}

} // namespace

int nodal_slot(std::string_view name, int width) {
  if (width == 6) return voigt_slot(name);
  if (width == 1) return 0; // a scalar (ENER's SENER)
  const char last = name.empty() ? '\0' : name.back();
  const bool one_digit =
      name.size() < 2 || !std::isdigit(static_cast<unsigned char>(name[name.size() - 2]));
  return one_digit && last >= '1' && last <= '3' ? last - '1' : -1;
}

std::vector<double> extrapolation_matrix(Shape shape, int n_points) {
  std::span<const QuadraturePoint> rule = full_integration_rule(shape);
  if (static_cast<int>(rule.size()) != n_points) rule = reduced_integration_rule(shape);
  if (static_cast<int>(rule.size()) != n_points) return {};
  const Shape corner = corner_shape(shape);
  const int nc = shape_n_nodes(corner);
  if (n_points < nc) return {};
  Eigen::MatrixXd A(n_points, nc);
  for (int p = 0; p < n_points; ++p) A.row(p) = corner_values(corner, rule[p].xi);
  const Eigen::MatrixXd AtA = A.transpose() * A;
  Eigen::LDLT<Eigen::MatrixXd> ldlt(AtA);
  if (ldlt.info() != Eigen::Success || ldlt.rcond() < 1e-10) return {};
  const Eigen::MatrixXd fit = ldlt.solve(A.transpose()); // nc x n_points: corner values
  const auto nodes = shape_node_coords(shape);
  const int nn = static_cast<int>(nodes.size());
  std::vector<double> out(static_cast<std::size_t>(nn * n_points));
  for (int a = 0; a < nn; ++a) {
    const Eigen::RowVectorXd row = corner_values(corner, nodes[a]) * fit;
    for (int p = 0; p < n_points; ++p) out[static_cast<std::size_t>(a * n_points + p)] = row[p];
  }
  return out;
}

const std::vector<double>& NodalAverager::matrix(Shape shape, int n_points) {
  const auto key = std::make_pair(static_cast<int>(shape), n_points);
  auto it = _cache.find(key);
  if (it == _cache.end()) it = _cache.emplace(key, extrapolation_matrix(shape, n_points)).first;
  return it->second;
}

NodalField NodalAverager::average(const Model& model, const Frame& frame, ElemVar var,
                                  const std::vector<char>* mask) {
  NodalField f;
  f.width = var == ElemVar::HFL || var == ElemVar::COORD ? 3 : var == ElemVar::ENER ? 1 : 6;
  const auto nn = static_cast<std::size_t>(model.mesh.n_nodes());
  f.values.assign(nn * static_cast<std::size_t>(f.width), 0.0);
  f.count.assign(nn, 0);
  std::vector<int> slots;
  std::vector<double> local;
  for (const ElementResult& r : frame.elements) {
    const ElemId e = r.elem;
    if (mask && !(*mask)[static_cast<std::size_t>(e)]) continue;
    const ElementTypeInfo& info = element_info(model.mesh.elem_types[e]);
    if (!info.cell ||
        (info.family != ElementFamily::Continuum && info.family != ElementFamily::HeatTransfer))
      continue;
    const OutputBlock* b = r.data.find(var);
    if (!b || b->n_points <= 0 || b->section_points != 1) continue;
    const int nc = static_cast<int>(b->names.size());
    slots.resize(static_cast<std::size_t>(nc));
    for (int c = 0; c < nc; ++c) slots[c] = nodal_slot(b->names[c], f.width);
    const auto nodes = model.mesh.element_nodes(e);
    const int n_el = static_cast<int>(nodes.size());
    const std::vector<double>& E = matrix(*info.cell, b->n_points);
    local.assign(static_cast<std::size_t>(n_el * nc), 0.0);
    for (int a = 0; a < n_el; ++a)
      for (int p = 0; p < b->n_points; ++p) {
        // no rule matched (or too few points): every node gets the element's mean
        const double w =
            E.empty() ? 1.0 / b->n_points : E[static_cast<std::size_t>(a * b->n_points + p)];
        for (int c = 0; c < nc; ++c)
          local[static_cast<std::size_t>(a * nc + c)] +=
              w * b->values[static_cast<std::size_t>(p * nc + c)];
      }
    for (int a = 0; a < n_el; ++a) {
      const auto n = static_cast<std::size_t>(nodes[a]);
      for (int c = 0; c < nc; ++c)
        if (slots[c] >= 0)
          f.values[n * static_cast<std::size_t>(f.width) + static_cast<std::size_t>(slots[c])] +=
              local[static_cast<std::size_t>(a * nc + c)];
      ++f.count[n];
    }
  }
  for (std::size_t n = 0; n < nn; ++n)
    if (f.count[n] > 1)
      for (int c = 0; c < f.width; ++c)
        f.values[n * static_cast<std::size_t>(f.width) + static_cast<std::size_t>(c)] /= f.count[n];
  return f;
}

} // namespace gapfem::output
