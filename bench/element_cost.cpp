// element_cost: the cost of one residual-and-tangent evaluation of every continuum element type
// (the element part of an assembly), small strain and NLGEOM, printed per type and relative to
// C3D8. One element on its reference cell (edge 1), a fixed small displacement field, the kernel
// from the real factory; the loop is repeated until it takes at least 0.2 s.
//
//   build/release/bench/element_cost [--min-time 0.2]
#include "elements/element_kernel.hpp"
#include "fe/shape_functions.hpp"
#include "model/model.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <memory>

using namespace gapfem;

namespace {

std::shared_ptr<Model> one_element(ElementType t) {
  auto m = std::make_shared<Model>();
  const ElementTypeInfo& info = element_info(t);
  const auto xi = shape_node_coords(*info.cell);
  for (std::size_t a = 0; a < xi.size(); ++a) {
    Vec3 x{xi[a][0] + 2.0, xi[a][1], shape_dim(*info.cell) == 3 ? xi[a][2] : 0.0};
    m->mesh.node_labels.push_back(static_cast<Label>(a + 1));
    m->mesh.coords.push_back(x);
    m->mesh.node_index[static_cast<Label>(a + 1)] = static_cast<NodeId>(a);
    m->mesh.conn.push_back(static_cast<NodeId>(a));
  }
  m->mesh.elem_labels.push_back(1);
  m->mesh.elem_types.push_back(t);
  m->mesh.conn_offset.push_back(static_cast<std::int64_t>(xi.size()));
  m->mesh.elem_src.push_back({});
  m->mesh.elem_index[1] = 0;
  m->space = info.space == SpaceRequirement::ThreeD         ? ModelSpace::ThreeD
             : info.space == SpaceRequirement::Axisymmetric ? ModelSpace::Axisymmetric
                                                            : ModelSpace::Planar;
  Material mat;
  mat.name = "STEEL";
  mat.elastic.n_values = 2;
  mat.elastic.values = {210000.0, 0.3};
  m->materials.push_back(mat);
  SolidSection sec;
  sec.elset = "ALL";
  sec.material = 0;
  m->solid_sections.push_back(sec);
  m->element_property.push_back({PropertyRef::Kind::Solid, 0});
  m->initial_temperature.assign(xi.size(), 0.0);
  return m;
}

/// Seconds per evaluation (residual and tangent).
double cost(ElementType t, bool nlgeom, double min_time) {
  auto model = one_element(t);
  std::vector<ElemId> elems{0};
  auto kernel = make_element_kernel(KernelContext{*model, t, model->element_property[0], elems});
  const int n = kernel->n_dofs();
  std::vector<double> u(n), r(n), K(static_cast<std::size_t>(n) * n);
  for (int i = 0; i < n; ++i) u[i] = 1e-3 * std::sin(1.0 + i);
  StepContext ctx;
  ctx.nlgeom = nlgeom;
  ctx.space = model->space;
  ElementInput in;
  in.elem = 0;
  in.label = EntityLabel{1};
  in.X = model->mesh.coords;
  in.u = u;
  in.u_start = u;
  in.ctx = &ctx;
  using clock = std::chrono::steady_clock;
  long reps = 16;
  for (;;) {
    const auto t0 = clock::now();
    for (long k = 0; k < reps; ++k) {
      std::fill(r.begin(), r.end(), 0.0);
      std::fill(K.begin(), K.end(), 0.0);
      ElementOutput out;
      out.residual = r;
      out.tangent = K;
      kernel->evaluate(in, out);
    }
    const double s = std::chrono::duration<double>(clock::now() - t0).count();
    if (s >= min_time) return s / static_cast<double>(reps);
    reps *= 2;
  }
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"cost of one element evaluation (residual + tangent) per continuum type"};
  double min_time = 0.2;
  app.add_option("--min-time", min_time, "seconds per measurement");
  CLI11_PARSE(app, argc, argv);
  std::map<std::string, std::pair<double, double>> rows;
  double ref_small = 0.0, ref_nl = 0.0;
  fmt::print("{:<8} {:>5} {:>12} {:>12} {:>9} {:>9}\n", "type", "dofs", "small [us]", "nlgeom [us]",
             "/C3D8", "/C3D8 nl");
  std::vector<std::tuple<std::string, int, double, double>> out;
  for (const ElementTypeInfo& info : all_element_types()) {
    if (info.family != ElementFamily::Continuum || info.temperature) continue;
    const double a = cost(info.type, false, min_time), b = cost(info.type, true, min_time);
    if (info.type == ElementType::C3D8) ref_small = a, ref_nl = b;
    const int dofs = info.n_nodes * (info.space == SpaceRequirement::ThreeD ? 3 : 2);
    out.emplace_back(std::string(info.name), dofs, a, b);
  }
  for (const auto& [name, dofs, a, b] : out)
    fmt::print("{:<8} {:>5} {:>12.2f} {:>12.2f} {:>9.2f} {:>9.2f}\n", name, dofs, a * 1e6, b * 1e6,
               a / ref_small, b / ref_nl);
  return 0;
}
