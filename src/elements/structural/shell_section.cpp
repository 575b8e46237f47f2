#include "elements/structural/shell_section.hpp"

#include "elements/structural/structural_common.hpp"
#include "elements/structural/structural_factory.hpp"
#include "model/model.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem::shell {

using namespace structural;

namespace {

inline constexpr std::array<std::string_view, 3> kShellS{"S11", "S22", "S12"};
inline constexpr std::array<std::string_view, 3> kShellE{"E11", "E22", "E12"};
inline constexpr std::array<std::string_view, 8> kShellSF{"SF1", "SF2", "SF3", "SF4",
                                                          "SF5", "SM1", "SM2", "SM3"};

/// Averaged unit normals at the nodes of all shell elements of the model (zero where none).
std::vector<Vec3> averaged_normals(const Model& model) {
  std::vector<Vec3> sum(static_cast<std::size_t>(model.mesh.n_nodes()), Vec3{0.0, 0.0, 0.0});
  std::array<Vec3, kMaxNodes> X;
  for (ElemId e = 0; e < model.mesh.n_elements(); ++e) {
    if (element_info(model.mesh.elem_types[e]).family != ElementFamily::Shell) continue;
    const auto nodes = model.mesh.element_nodes(e);
    for (std::size_t a = 0; a < nodes.size(); ++a) X[a] = model.mesh.coords[nodes[a]];
    const std::span<const Vec3> xs(X.data(), nodes.size());
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      const Vec3 n = element_normal_at_node(xs, static_cast<int>(a));
      for (int i = 0; i < 3; ++i) sum[nodes[a]][i] += n[i];
    }
  }
  for (Vec3& v : sum) {
    const double l = norm(v);
    if (l > 0.0) v = scale(1.0 / l, v);
  }
  return sum;
}

} // namespace

const ShellSection& shell_section_of(const KernelContext& ctx) {
  const auto& list = ctx.model.shell_sections;
  const ElemId e = ctx.elements.empty() ? -1 : ctx.elements[0];
  if (ctx.property.kind != PropertyRef::Kind::Shell || ctx.property.index < 0 ||
      ctx.property.index >= static_cast<int>(list.size()))
    throw InputError(ctx.model.element_location(e),
                     e >= 0 ? fmt::format("element {}", ctx.model.element_label(e)) : "",
                     fmt::format("{} elements need a *SHELL SECTION; add *SHELL SECTION, "
                                 "ELSET=..., MATERIAL=... for the element set that contains them",
                                 element_info(ctx.type).name));
  return list[ctx.property.index];
}

std::vector<double> block_thicknesses(const KernelContext& ctx, const ShellSection& sec) {
  const Model& model = ctx.model;
  std::vector<double> thickness;
  for (ElemId e : ctx.elements)
    for (NodeId node : model.mesh.element_nodes(e)) {
      double t = sec.thickness;
      if (sec.nodal_thickness) {
        const auto& nt = model.nodal_thickness;
        t = node < static_cast<NodeId>(nt.size()) ? nt[node] : 0.0;
        if (!(t > 0.0))
          throw InputError(sec.loc, fmt::format("ELSET={}", sec.elset),
                           fmt::format("the section has NODAL THICKNESS but node {} of element {} "
                                       "has no thickness; give it in *NODAL THICKNESS",
                                       model.node_label(node), model.element_label(e)));
      }
      thickness.push_back(t);
    }
  return thickness;
}

ShellData shell_data(const KernelContext& ctx) {
  const Model& model = ctx.model;
  const ShellSection& sec = shell_section_of(ctx);
  const std::string entity = fmt::format("ELSET={}", sec.elset);
  ShellData d;
  d.type = ctx.type;
  d.material = section_material(model, sec.material, sec.loc, entity);
  d.n_points = sec.n_points;
  if (d.n_points < 3)
    throw InputError(sec.loc, entity,
                     fmt::format("{} elements need at least 3 section points through the "
                                 "thickness (only heat-transfer shells may use 1); give 3 or more "
                                 "(odd) on the data line",
                                 element_info(ctx.type).name));
  d.offset = sec.offset;
  d.k11 = sec.k11;
  d.k22 = sec.k22;
  check_density_for_gravity(ctx, d.material);
  const std::vector<Vec3> avg = averaged_normals(model);
  // a node's director is the average of the normals of the shells that meet there, unless this
  // element's own normal differs from it by more than 20 degrees (a fold: the element keeps its
  // own)
  const double cos20 = std::cos(20.0 * M_PI / 180.0);
  std::array<Vec3, kMaxNodes> X;
  for (ElemId e : ctx.elements) {
    const auto nodes = model.mesh.element_nodes(e);
    for (std::size_t a = 0; a < nodes.size(); ++a) X[a] = model.mesh.coords[nodes[a]];
    const std::span<const Vec3> xs(X.data(), nodes.size());
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      const Vec3 own = element_normal_at_node(xs, static_cast<int>(a));
      const Vec3& mean = avg[nodes[a]];
      d.directors.push_back(dot(own, mean) >= cos20 ? mean : own);
    }
  }
  d.thickness = block_thicknesses(ctx, sec);
  return d;
}

SectionLaw section_law(const ShellData& d, const ElementInput& in) {
  SectionLaw l;
  elastic_at(d.material, average(in.temperature), l.E, l.nu);
  l.G = l.E / (2.0 * (1.0 + l.nu));
  l.eps_th = element_thermal_strain(d.material, in);
  if (!in.temperature_gradient.empty() && !d.material.expansion.empty()) {
    // a linear temperature through the thickness, T + z dT/dn: the thermal strain's slope at the
    // element's temperature times the gradient (exact for a constant expansion coefficient)
    double g = 0.0;
    const std::size_t nn = in.temperature_gradient.size() / 2;
    for (std::size_t a = 0; a < nn; ++a) g += in.temperature_gradient[2 * a] / nn;
    l.kap_th = d.material.thermal_strain_derivative(*average(in.temperature)) * g;
  }
  l.offset = d.offset;
  l.k11 = d.k11;
  l.k22 = d.k22;
  l.n_points = d.n_points;
  return l;
}

std::array<double, 64> section_matrix(const SectionLaw& l, double t) {
  std::array<double, 64> C{};
  const double c = l.E / (1.0 - l.nu * l.nu);
  const double Q[3][3] = {
      {c, c * l.nu, 0.0}, {c * l.nu, c, 0.0}, {0.0, 0.0, c * 0.5 * (1.0 - l.nu)}};
  const double zm = -l.offset * t;
  const double A = t, B = t * zm, D = t * t * t / 12.0 + t * zm * zm;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      C[8 * i + j] = A * Q[i][j];
      C[8 * i + 3 + j] = C[8 * (3 + i) + j] = B * Q[i][j];
      C[8 * (3 + i) + 3 + j] = D * Q[i][j];
    }
  C[8 * 6 + 6] = l.k11 > 0.0 ? l.k11 : 5.0 / 6.0 * l.G * t;
  C[8 * 7 + 7] = l.k22 > 0.0 ? l.k22 : 5.0 / 6.0 * l.G * t;
  return C;
}

ShellOutputBlocks add_shell_output_blocks(int np, int ns, ElementRecovery& out) {
  add_block(out, ElemVar::SF, kShellSF, np);
  add_block(out, ElemVar::S, kShellS, np * ns);
  add_block(out, ElemVar::E, kShellE, np * ns);
  const std::size_t n = out.blocks.size();
  ShellOutputBlocks b{&out.blocks[n - 3], &out.blocks[n - 2], &out.blocks[n - 1]};
  b.S->section_points = b.E->section_points = ns;
  return b;
}

void recover_shell_output(const SectionLaw& l, std::span<const SectionStrains<double>> e,
                          std::span<const double> thickness, ElementRecovery& out) {
  const int np = static_cast<int>(e.size()), ns = l.n_points;
  const ShellOutputBlocks b = add_shell_output_blocks(np, ns, out);
  OutputBlock& SF = *b.SF;
  OutputBlock& S = *b.S;
  OutputBlock& E = *b.E;
  const double c = l.E / (1.0 - l.nu * l.nu);
  auto Q = [&](const std::array<double, 3>& a) {
    return std::array<double, 3>{c * (a[0] + l.nu * a[1]), c * (a[1] + l.nu * a[0]),
                                 c * 0.5 * (1.0 - l.nu) * a[2]};
  };
  for (int p = 0; p < np; ++p) {
    const double t = thickness[p], zm = -l.offset * t;
    std::array<double, 3> em = e[p].eps;
    em[0] -= l.eps_th;
    em[1] -= l.eps_th;
    std::array<double, 3> km = e[p].kap;
    km[0] -= l.kap_th;
    km[1] -= l.kap_th;
    const auto qe = Q(em), qk = Q(km);
    const double A = t, B = t * zm, D = t * t * t / 12.0 + t * zm * zm;
    const double K1 = l.k11 > 0.0 ? l.k11 : 5.0 / 6.0 * l.G * t;
    const double K2 = l.k22 > 0.0 ? l.k22 : 5.0 / 6.0 * l.G * t;
    double* sf = SF.values.data() + 8 * p;
    for (int i = 0; i < 3; ++i) {
      sf[i] = A * qe[i] + B * qk[i];
      sf[5 + i] = B * qe[i] + D * qk[i];
    }
    sf[3] = K1 * e[p].gam[0];
    sf[4] = K2 * e[p].gam[1];
    for (int k = 0; k < ns; ++k) {
      const double z = zm - 0.5 * t + t * k / (ns - 1);
      const int row = p * ns + k;
      std::array<double, 3> strain;
      for (int i = 0; i < 3; ++i) strain[i] = e[p].eps[i] + z * e[p].kap[i];
      std::array<double, 3> mech = strain;
      mech[0] -= l.eps_th + z * l.kap_th;
      mech[1] -= l.eps_th + z * l.kap_th;
      const auto s = Q(mech);
      for (int i = 0; i < 3; ++i) {
        E.values[3 * row + i] = strain[i];
        S.values[3 * row + i] = s[i];
      }
    }
  }
}

} // namespace gapfem::shell
