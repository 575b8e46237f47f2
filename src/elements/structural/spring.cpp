#include "elements/structural/spring.hpp"

#include "elements/reference_scale.hpp"
#include "elements/structural/dashpot.hpp"
#include "elements/structural/structural_common.hpp"
#include "model/model.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem {

using namespace structural;

FixedAction fixed_action(ElementType type, const SpringSection& section, ModelSpace space) {
  FixedAction act;
  const bool two = type == ElementType::SPRING2 || type == ElementType::DASHPOT2;
  const int dof[2] = {section.dof1, section.dof2};
  for (int node = 0; node < (two ? 2 : 1); ++node) {
    auto& dofs = node == 0 ? act.dofs0 : act.dofs1;
    int& n = node == 0 ? act.n0 : act.n1;
    const double sign = node == 0 ? 1.0 : -1.0;
    if (!section.axes) { // one global DOF
      FE_CHECK(dof_from_abaqus(dof[node], dofs[0]), "spring/dashpot DOF not checked");
      n = 1;
      act.B[node] = sign;
      continue;
    }
    // local DOF i: along (about) the orientation's axis (i - 1) % 3, on all three translations
    // (rotations) of the node, the two in-plane translations in planar models
    const int first = dof[node] <= 3 ? 0 : 3;
    const Vec3& axis = (*section.axes)[(dof[node] - 1) % 3];
    n = space == ModelSpace::ThreeD ? 3 : 2;
    for (int k = 0; k < n; ++k) {
      dofs[k] = static_cast<DofType>(first + k);
      act.B[node * act.n0 + k] = sign * axis[k];
    }
  }
  return act;
}

SpringKernel::SpringKernel(ElementType type, const SpringSection& section, ModelSpace space)
    : _type(type), _stiffness(section.stiffness), _nonlinear(section.nonlinear) {
  if (_nonlinear) {
    _table.x = section.relative;
    _table.y = section.force;
    _table.extrapolation = Curve::Extrapolation::Constant;
  }
  switch (type) {
  case ElementType::SPRING1:
  case ElementType::SPRING2:
    _act = fixed_action(type, section, space);
    break;
  case ElementType::SPRINGA:
    _ndim = space == ModelSpace::ThreeD ? 3 : 2;
    _act.n0 = _act.n1 = _ndim;
    for (int i = 0; i < _ndim; ++i) _act.dofs0[i] = _act.dofs1[i] = static_cast<DofType>(i);
    break;
  default:
    FE_CHECK(false, "SpringKernel built for a non-spring element type");
  }
}

std::span<const DofType> SpringKernel::node_dofs(int local_node) const {
  return local_node == 0 ? std::span<const DofType>(_act.dofs0.data(), _act.n0)
                         : std::span<const DofType>(_act.dofs1.data(), _act.n1);
}

std::string SpringKernel::validate(const ElementInput& in) const {
  if (_type != ElementType::SPRINGA) return {};
  Vec3 b = in.X[1]; // (the length without overflow: reference_scale.hpp)
  if (_ndim == 2) b[2] = in.X[0][2];
  if (!(point_distance(in.X[0], b) > 1e-12 * (in.ctx ? in.ctx->model_size : 1.0)))
    return "the two nodes of this SPRINGA element coincide, so its line of action is undefined; "
           "move one node or use SPRING2 with explicit degrees of freedom";
  return {};
}

void SpringKernel::force(const ElementInput& in, double du, double& F, double& dF) const {
  if (_nonlinear) {
    F = _table.value(du);
    dF = _table.slope(du);
    return;
  }
  dF = table_value(_stiffness, average(in.temperature));
  F = dF * du;
}

double SpringKernel::relative_displacement(const ElementInput& in) const {
  if (_type == ElementType::SPRINGA) {
    const bool nlgeom = in.ctx != nullptr && in.ctx->nlgeom;
    return axial_kinematics(_ndim, in.X, in.u, nlgeom).delta;
  }
  double du = 0.0;
  for (int k = 0; k < _act.n_dofs(); ++k) du += _act.B[k] * in.u[k];
  return du;
}

void SpringKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  double F = 0.0, dF = 0.0;
  if (_type == ElementType::SPRINGA) {
    const bool nlgeom = in.ctx != nullptr && in.ctx->nlgeom;
    const AxialKinematics kin = axial_kinematics(_ndim, in.X, in.u, nlgeom);
    force(in, kin.delta, F, dF);
    axial_assemble(kin, nlgeom, F, dF, out);
    return;
  }
  // r = F B, K = F'(du) B B^T (B = [1] or [1, -1] on global DOFs: k u_i, k (u_i - u_j))
  const int n = _act.n_dofs();
  force(in, relative_displacement(in), F, dF);
  for (int i = 0; i < n; ++i) out.residual[i] += F * _act.B[i];
  if (!out.want_tangent) return;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) out.tangent[i * n + j] += dF * _act.B[i] * _act.B[j];
}

bool SpringKernel::stress_stiffness(const ElementInput& in, std::span<const double> du,
                                    std::span<double> K) const {
  if (_type != ElementType::SPRINGA) return true;
  const AxialKinematics kin = axial_kinematics(_ndim, in.X, in.u, true);
  if (!(kin.l > 0.0)) return false;
  double F = 0.0, dF = 0.0;
  force(in, kin.delta, F, dF);
  axial_stress_stiffness(kin, dF * axial_stretch(kin, du), K);
  return true;
}

bool SpringKernel::supports_output(ElemVar var) const {
  return var == ElemVar::S || var == ElemVar::E;
}

void SpringKernel::recover(const ElementInput& in, ElementRecovery& out) const {
  const double du = relative_displacement(in);
  double F = 0.0, dF = 0.0;
  force(in, du, F, dF);
  add_block(out, ElemVar::S, kS11, 1).values[0] = F;
  add_block(out, ElemVar::E, kE11, 1).values[0] = du;
}

namespace {
bool is_dashpot(ElementType t) {
  return t == ElementType::DASHPOT1 || t == ElementType::DASHPOT2 || t == ElementType::DASHPOTA;
}

/// ORIENTATION= on a SPRING1/2 or DASHPOT1/2: resolved by the reader (an error there stops the
/// run before kernels are made); in a planar model the local direction must lie in its plane.
void check_orientation(const Model& model, const SpringSection& sec, ElementType type,
                       const std::string& entity) {
  const bool axial = type == ElementType::SPRINGA || type == ElementType::DASHPOTA;
  if (axial || !sec.axes)
    throw InputError(sec.loc, entity,
                     fmt::format("ORIENTATION={} cannot be used here: it applies to SPRING1/2 and "
                                 "DASHPOT1/2 elements and must name a rectangular *ORIENTATION",
                                 sec.orientation));
  if (model.space == ModelSpace::ThreeD) return;
  const bool two = type == ElementType::SPRING2 || type == ElementType::DASHPOT2;
  for (int dof : {sec.dof1, two ? sec.dof2 : sec.dof1}) {
    const Vec3& n = (*sec.axes)[(dof - 1) % 3];
    if (std::abs(n[2]) > 1e-12)
      throw InputError(sec.loc, entity,
                       fmt::format("local direction {} of ORIENTATION={} leaves the plane of this "
                                   "{} model (its z component is {}); give an orientation whose "
                                   "local {} axis lies in the x-y plane",
                                   dof, sec.orientation, model_space_name(model.space), n[2], dof));
  }
}
} // namespace

std::unique_ptr<ElementKernel> make_spring_kernel(const KernelContext& ctx) {
  const Model& model = ctx.model;
  const std::string_view name = element_info(ctx.type).name;
  const bool dashpot = is_dashpot(ctx.type);
  const char* keyword = dashpot ? "*DASHPOT" : "*SPRING";
  const ElemId first = ctx.elements.empty() ? -1 : ctx.elements[0];
  if (ctx.property.kind != PropertyRef::Kind::Spring || ctx.property.index < 0 ||
      ctx.property.index >= static_cast<int>(model.spring_sections.size()))
    throw InputError(model.element_location(first),
                     first >= 0 ? fmt::format("element {}", model.element_label(first)) : "",
                     fmt::format("{} elements need a {} property; add {}, ELSET=... "
                                 "for the element set that contains them",
                                 name, keyword, keyword));
  const SpringSection& sec = model.spring_sections[ctx.property.index];
  const std::string entity = fmt::format("ELSET={}", sec.elset);
  if (sec.dashpot != dashpot)
    throw InputError(sec.loc, entity,
                     fmt::format("{} elements take {}, not {}; give the element set its own "
                                 "keyword",
                                 name, keyword, dashpot ? "*SPRING" : "*DASHPOT"));
  if (!sec.nonlinear && (sec.stiffness.empty() || sec.stiffness.n_values < 1))
    throw InputError(sec.loc, entity,
                     dashpot ? "no dashpot coefficient is given; add a data line with it"
                             : "no spring stiffness is given; add a data line with the stiffness");
  const bool planar = model.space != ModelSpace::ThreeD;
  auto check_dof = [&](int dof, const char* which) {
    DofType d{};
    if (!dof_from_abaqus(dof, d) || is_temperature(d))
      throw InputError(sec.loc, entity,
                       fmt::format("{} degree of freedom {} is not a displacement or rotation "
                                   "(1-6); give the DOF the {} acts on",
                                   which, dof, dashpot ? "dashpot" : "spring"));
    if (planar && dof > 2)
      throw InputError(sec.loc, entity,
                       fmt::format("{} degree of freedom {} does not exist in this {} model; "
                                   "only DOFs 1 and 2 are available",
                                   which, dof, model_space_name(model.space)));
  };
  const bool one = ctx.type == ElementType::SPRING1 || ctx.type == ElementType::DASHPOT1;
  const bool two = ctx.type == ElementType::SPRING2 || ctx.type == ElementType::DASHPOT2;
  if (one || two) check_dof(sec.dof1, one ? "the" : "the first node's");
  if (two) check_dof(sec.dof2, "the second node's");
  if (!sec.orientation.empty()) check_orientation(model, sec, ctx.type, entity);
  if (dashpot) return std::make_unique<DashpotKernel>(ctx.type, sec, model.space);
  return std::make_unique<SpringKernel>(ctx.type, sec, model.space);
}

} // namespace gapfem
