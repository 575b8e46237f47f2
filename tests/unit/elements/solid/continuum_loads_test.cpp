// Distributed loads on continuum elements (equivalent nodal forces of pressure, GRAV and body
// forces), the factory's input checks, and the shape functions / quadrature in src/fem.
#include "continuum_fixture.hpp"
#include "fe/element_faces.hpp"
#include "fe/quadrature.hpp"

#include <Eigen/Dense>
#include <numbers>

namespace gapfem::test {
namespace {

const std::vector<ElementType> kAllTypes = continuum_types();

Eigen::Vector3d v3(const Vec3& a) {
  return {a[0], a[1], a[2]};
}

// Pressure p on each face: the nodal forces add up to p * area * (inward unit normal) for flat
// faces (3-D: area vector = (x2 - x1) x (x3 - x1) / 2 for triangles; the undistorted hexahedron's
// faces are unit squares). Plane: p * t * L * n; axisymmetric straight edge: p * 2 pi r_mid * L * n
// (Pappus). Checked in the reference configuration and, at u = 0, with the follower form.
TEST(ContinuumLoads, PressureResultantEqualsPressureTimesArea) {
  const double p = 3.0, t = 2.5;
  for (ElementType type : kAllTypes) {
    const Shape cs = shape_of(type); // simplices distorted (straight edges), boxes and wedges not
    const bool distort =
        cs == Shape::Tri3 || cs == Shape::Tri6 || cs == Shape::Tet4 || cs == Shape::Tet10;
    ElementHarness h(type, reference_nodes(type, distort), {}, t);
    const int nd = dofs_per_node(type);
    const auto faces = element_faces(shape_of(type));
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const auto& x : h.X) centroid += v3(x) / static_cast<double>(h.X.size());
    for (bool follower : {false, true}) {
      h.ctx.nlgeom = follower;
      for (std::size_t k = 0; k < faces.size(); ++k) {
        const FaceDef& fd = faces[k];
        DistributedLoad ld;
        ld.kind = DistLoadKind::Pressure;
        ld.face = static_cast<int>(k + 1);
        const std::vector<double> f = h.load(ld, p, 0.0);
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (std::size_t a = 0; a < h.X.size(); ++a)
          for (int i = 0; i < nd; ++i) sum(i) += f[a * nd + i];
        Eigen::Vector3d want;
        const Eigen::Vector3d x0 = v3(h.X[fd.nodes[0]]), x1 = v3(h.X[fd.nodes[1]]);
        if (nd == 3) {
          const Eigen::Vector3d x2 = v3(h.X[fd.nodes[2]]);
          Eigen::Vector3d area = 0.5 * (x1 - x0).cross(x2 - x0);
          if (fd.shape == Shape::Quad4 || fd.shape == Shape::Quad8)
            area *= 2.0; // planar parallelogram (rectangle)
          want = p * area;
        } else {
          const Eigen::Vector3d d = x1 - x0;
          const Eigen::Vector3d n_len(-d(1), d(0), 0.0); // inward normal times length
          const double scale = element_info(type).plane == PlaneKind::Axisymmetric
                                   ? 2.0 * std::numbers::pi * 0.5 * (x0(0) + x1(0))
                                   : t;
          want = p * scale * n_len;
        }
        // The resultant points into the element (towards the centroid).
        EXPECT_GT(want.dot(centroid - 0.5 * (x0 + x1)), 0.0);
        EXPECT_NEAR((sum - want).norm(), 0.0, 1e-12 * want.norm())
            << element_info(type).name << " face " << k + 1;
      }
    }
  }
}

// GRAV: sum of nodal forces = rho * g * V * direction with V the exact volume: unit cube,
// |det| / 6 for the tetrahedra, t * A (plane), 2 pi r_c A (axisymmetric, Pappus). BX: same with
// the magnitude as force per volume.
TEST(ContinuumLoads, GravityResultantEqualsWeight) {
  const double t = 2.5, g = 9810.0;
  TestMaterial m;
  for (ElementType type : kAllTypes) {
    const Shape cs = shape_of(type); // simplices distorted (straight edges), boxes and wedges not
    const bool distort =
        cs == Shape::Tri3 || cs == Shape::Tri6 || cs == Shape::Tet4 || cs == Shape::Tet10;
    ElementHarness h(type, reference_nodes(type, distort), m, t);
    double V = 0.0;
    const Eigen::Vector3d x0 = v3(h.X[0]), x1 = v3(h.X[1]), x2 = v3(h.X[2]);
    switch (shape_of(type)) {
    case Shape::Hex8:
    case Shape::Hex20:
      V = 1.0;
      break;
    case Shape::Wedge6:
    case Shape::Wedge15: // triangle of area 1/2, height 2
      V = 1.0;
      break;
    case Shape::Tet4:
    case Shape::Tet10:
      V = std::abs((x1 - x0).cross(x2 - x0).dot(v3(h.X[3]) - x0)) / 6.0;
      break;
    case Shape::Tri3:
    case Shape::Tri6: {
      const double A = 0.5 * std::abs((x1 - x0).cross(x2 - x0)(2));
      V = element_info(type).plane == PlaneKind::Axisymmetric
              ? 2.0 * std::numbers::pi * (x0(0) + x1(0) + x2(0)) / 3.0 * A
              : t * A;
      break;
    }
    default: // unit square centred at r = 1.5
      V = element_info(type).plane == PlaneKind::Axisymmetric ? 2.0 * std::numbers::pi * 1.5 : t;
    }
    DistributedLoad ld;
    ld.kind = DistLoadKind::Gravity;
    ld.direction = {0.0, -1.0, 0.0};
    ASSERT_TRUE(h.kernel->supports_load(DistLoadKind::Gravity, 0));
    std::vector<double> K;
    std::vector<double> f = h.load(ld, g, 0.0, &K);
    const int nd = dofs_per_node(type);
    double fy = 0.0, fx = 0.0;
    for (std::size_t a = 0; a < h.X.size(); ++a) {
      fx += f[a * nd];
      fy += f[a * nd + 1];
    }
    EXPECT_NEAR(fy, -m.density * g * V, 1e-12 * m.density * g * V) << element_info(type).name;
    EXPECT_NEAR(fx, 0.0, 1e-14);
    ld.kind = DistLoadKind::BodyForce;
    f = h.load(ld, 2.0, 0.0, &K);
    fy = 0.0;
    for (std::size_t a = 0; a < h.X.size(); ++a) fy += f[a * nd + 1];
    EXPECT_NEAR(fy, -2.0 * V, 1e-12 * V) << element_info(type).name;
    for (double k : K) EXPECT_EQ(k, 0.0); // body loads do not follow the deformation
  }
}

TEST(ContinuumFactory, GravityWithoutDensityIsAnInputError) {
  TestMaterial m;
  m.density = 0.0;
  auto model = one_element_model(ElementType::C3D8, reference_nodes(ElementType::C3D8), m);
  Step step;
  DistributedLoad ld;
  ld.elem = 0;
  ld.kind = DistLoadKind::Gravity;
  step.dloads.push_back(ld);
  model->steps.push_back(step);
  std::vector<ElemId> elems{0};
  try {
    make_element_kernel(
        KernelContext{*model, ElementType::C3D8, model->element_property[0], elems});
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("GRAV on element 1 needs *DENSITY in material STEEL"),
              std::string::npos)
        << e.what();
  }
}

// The coupled temperature-displacement types route to the coupled kernels
// (elements/solid/coupled_continuum.hpp), which need the thermal conductivity of the material.
TEST(ContinuumFactory, CoupledTemperatureDisplacementTypesNeedConductivity) {
  for (ElementType t : {ElementType::C3D8T, ElementType::C3D4T, ElementType::CPE4T,
                        ElementType::CPS4T, ElementType::CAX4T}) {
    auto model = one_element_model(ElementType::C3D8, reference_nodes(ElementType::C3D8));
    std::vector<ElemId> elems{0};
    try {
      make_element_kernel(KernelContext{*model, t, model->element_property[0], elems});
      ADD_FAILURE() << element_info(t).name;
    } catch (const InputError& e) {
      EXPECT_NE(e.message().find("need *CONDUCTIVITY"), std::string::npos) << e.what();
    }
  }
}

TEST(ContinuumFactory, MissingElasticIsAnInputError) {
  auto model = one_element_model(ElementType::CPE4, reference_nodes(ElementType::CPE4));
  model->materials[0].elastic = {};
  std::vector<ElemId> elems{0};
  EXPECT_THROW(make_element_kernel(
                   KernelContext{*model, ElementType::CPE4, model->element_property[0], elems}),
               InputError);
}

// Shape functions: partition of unity, N_a(x_b) = delta_ab, and parametric derivatives that match
// central differences (quadratic functions: the central difference is exact up to round-off).
TEST(ContinuumShape, PartitionOfUnityKroneckerAndDerivatives) {
  for (Shape s :
       {Shape::Line2, Shape::Line3, Shape::Tri3, Shape::Tri6, Shape::Quad4, Shape::Quad8,
        Shape::Tet4, Shape::Tet10, Shape::Wedge6, Shape::Wedge15, Shape::Hex8, Shape::Hex20}) {
    const int n = shape_n_nodes(s), dim = shape_dim(s);
    std::vector<double> N(n), dN(n * dim), Np(n), Nm(n), tmp(n * dim);
    const auto nodes = shape_node_coords(s);
    ASSERT_EQ(static_cast<int>(nodes.size()), n);
    for (int b = 0; b < n; ++b) {
      shape_eval(s, nodes[b], N, dN);
      for (int a = 0; a < n; ++a) EXPECT_NEAR(N[a], a == b ? 1.0 : 0.0, 1e-15) << shape_name(s);
    }
    const std::array<double, 3> xi{0.21, 0.13, 0.17};
    shape_eval(s, xi, N, dN);
    double sum = 0.0;
    for (double v : N) sum += v;
    EXPECT_NEAR(sum, 1.0, 1e-15);
    const double h = 1e-4;
    for (int k = 0; k < dim; ++k) {
      auto xp = xi, xm = xi;
      xp[k] += h;
      xm[k] -= h;
      shape_eval(s, xp, Np, tmp);
      shape_eval(s, xm, Nm, tmp);
      for (int a = 0; a < n; ++a)
        EXPECT_NEAR(dN[a * dim + k], (Np[a] - Nm[a]) / (2 * h), 1e-10) << shape_name(s);
    }
  }
}

// Quadrature: weights add up to the reference measure and each rule integrates monomials up to its
// degree exactly (1-D Gauss n points: 2n - 1; triangle 3 points: 2, 6 points: 4; tetrahedron 4
// points: 2). Exact integrals: int_tri x^i y^j = i! j! / (i + j + 2)!, int_tet x^i = i! / (i + 3)!.
TEST(ContinuumQuadrature, RulesIntegrateTheirDegreeExactly) {
  auto integrate = [](std::span<const QuadraturePoint> rule, auto f) {
    double s = 0.0;
    for (const auto& q : rule) s += q.weight * f(q.xi[0], q.xi[1], q.xi[2]);
    return s;
  };
  EXPECT_NEAR(integrate(kGaussLine3, [](double x, double, double) { return x * x * x * x; }),
              2.0 / 5.0, 1e-15);
  EXPECT_NEAR(
      integrate(kGaussHex8, [](double x, double y, double z) { return x * x * y * y * z * z; }),
      8.0 / 27.0, 1e-15);
  EXPECT_NEAR(integrate(kGaussQuad4,
                        [](double x, double y, double) { return x * x * y * y + x * y * y * y; }),
              4.0 / 9.0, 1e-15);
  EXPECT_NEAR(integrate(kTri3, [](double x, double y, double) { return x * y; }), 1.0 / 24.0,
              1e-15);
  EXPECT_NEAR(integrate(kTri6, [](double x, double y, double) { return x * x * y * y; }),
              4.0 / 720.0, 1e-15);
  EXPECT_NEAR(integrate(kTri6, [](double x, double, double) { return x * x * x * x; }),
              24.0 / 720.0, 1e-15);
  EXPECT_NEAR(integrate(kTet4, [](double x, double, double) { return x * x; }), 2.0 / 120.0, 1e-15);
  EXPECT_NEAR(integrate(kTet4, [](double x, double y, double) { return x * y; }), 1.0 / 120.0,
              1e-15);
  EXPECT_NEAR(integrate(kTet1, [](double, double, double) { return 1.0; }), 1.0 / 6.0, 1e-16);
  // 3x3 Gauss: degree 5 per direction; wedges: triangle rule x Gauss (int_wedge = int_tri int_z)
  EXPECT_NEAR(integrate(kGaussQuad9, [](double x, double y, double) { return std::pow(x * y, 4); }),
              4.0 / 25.0, 1e-15);
  EXPECT_NEAR(integrate(kGaussHex27,
                        [](double x, double y, double z) { return std::pow(x * y * z, 4) + x; }),
              8.0 / 125.0, 1e-15);
  EXPECT_NEAR(integrate(kWedge2, [](double x, double, double z) { return 1.0 + x + z * z; }),
              1.0 + 1.0 / 3.0 + 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(
      integrate(kWedge9, [](double x, double y, double z) { return x * y * std::pow(z, 4); }),
      1.0 / 24.0 * 2.0 / 5.0, 1e-15);
  EXPECT_NEAR(integrate(kWedge6, [](double x, double, double z) { return x * x * z * z; }),
              2.0 / 24.0 * 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(integrate(kTri1, [](double x, double, double) { return x; }), 1.0 / 6.0, 1e-16);
}

} // namespace
} // namespace gapfem::test
