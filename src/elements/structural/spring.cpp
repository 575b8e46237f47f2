#include "elements/structural/spring.hpp"

#include "elements/reference_scale.hpp"
#include "elements/structural/dashpot.hpp"
#include "elements/structural/structural_common.hpp"
#include "model/model.hpp"

#include <fmt/format.h>

namespace gapfem {

using namespace structural;

SpringKernel::SpringKernel(ElementType type, const SpringSection& section, ModelSpace space)
    : _type(type), _stiffness(section.stiffness) {
  switch (type) {
  case ElementType::SPRING1:
    FE_CHECK(dof_from_abaqus(section.dof1, _dofs0[0]), "SPRING1 DOF not checked");
    _n0 = 1;
    break;
  case ElementType::SPRING2:
    FE_CHECK(dof_from_abaqus(section.dof1, _dofs0[0]) && dof_from_abaqus(section.dof2, _dofs1[0]),
             "SPRING2 DOFs not checked");
    _n0 = _n1 = 1;
    break;
  case ElementType::SPRINGA:
    _ndim = space == ModelSpace::ThreeD ? 3 : 2;
    _n0 = _n1 = _ndim;
    for (int i = 0; i < _ndim; ++i) _dofs0[i] = _dofs1[i] = static_cast<DofType>(i);
    break;
  default:
    FE_CHECK(false, "SpringKernel built for a non-spring element type");
  }
}

std::span<const DofType> SpringKernel::node_dofs(int local_node) const {
  return local_node == 0 ? std::span<const DofType>(_dofs0.data(), _n0)
                         : std::span<const DofType>(_dofs1.data(), _n1);
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

double SpringKernel::stiffness(const ElementInput& in) const {
  return table_value(_stiffness, average(in.temperature));
}

double SpringKernel::relative_displacement(const ElementInput& in) const {
  switch (_type) {
  case ElementType::SPRING1:
    return in.u[0];
  case ElementType::SPRING2:
    return in.u[0] - in.u[1];
  default: {
    const bool nlgeom = in.ctx != nullptr && in.ctx->nlgeom;
    return axial_kinematics(_ndim, in.X, in.u, nlgeom).delta;
  }
  }
}

void SpringKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  const double k = stiffness(in);
  switch (_type) {
  case ElementType::SPRING1:
    out.residual[0] += k * in.u[0];
    if (out.want_tangent) out.tangent[0] += k;
    return;
  case ElementType::SPRING2: {
    const double F = k * (in.u[0] - in.u[1]);
    out.residual[0] += F;
    out.residual[1] -= F;
    if (out.want_tangent) {
      out.tangent[0] += k;
      out.tangent[1] -= k;
      out.tangent[2] -= k;
      out.tangent[3] += k;
    }
    return;
  }
  default: {
    const bool nlgeom = in.ctx != nullptr && in.ctx->nlgeom;
    const AxialKinematics kin = axial_kinematics(_ndim, in.X, in.u, nlgeom);
    axial_assemble(kin, nlgeom, k * kin.delta, k, out);
  }
  }
}

bool SpringKernel::supports_output(ElemVar var) const {
  return var == ElemVar::S || var == ElemVar::E;
}

void SpringKernel::recover(const ElementInput& in, ElementRecovery& out) const {
  const double du = relative_displacement(in);
  add_block(out, ElemVar::S, kS11, 1).values[0] = stiffness(in) * du;
  add_block(out, ElemVar::E, kE11, 1).values[0] = du;
}

namespace {
bool is_dashpot(ElementType t) {
  return t == ElementType::DASHPOT1 || t == ElementType::DASHPOT2 || t == ElementType::DASHPOTA;
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
  if (dashpot) return std::make_unique<DashpotKernel>(ctx.type, sec, model.space);
  return std::make_unique<SpringKernel>(ctx.type, sec, model.space);
}

} // namespace gapfem
