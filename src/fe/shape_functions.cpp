#include "fe/shape_functions.hpp"

#include "common/error.hpp"
#include "fe/element_faces.hpp"
#include "fe/quadrature.hpp"

namespace gapfem {

std::string_view shape_name(Shape s) {
  switch (s) {
  case Shape::Line2:
    return "Line2";
  case Shape::Line3:
    return "Line3";
  case Shape::Tri3:
    return "Tri3";
  case Shape::Tri6:
    return "Tri6";
  case Shape::Quad4:
    return "Quad4";
  case Shape::Quad8:
    return "Quad8";
  case Shape::Wedge6:
    return "Wedge6";
  case Shape::Wedge15:
    return "Wedge15";
  case Shape::Hex20:
    return "Hex20";
  case Shape::Tet4:
    return "Tet4";
  case Shape::Tet10:
    return "Tet10";
  case Shape::Hex8:
    return "Hex8";
  }
  return "?";
}

void shape_eval(Shape s, std::span<const double> xi, std::span<double> N, std::span<double> dN) {
  const int n = shape_n_nodes(s);
  FE_CHECK(static_cast<int>(N.size()) >= n && static_cast<int>(dN.size()) >= n * shape_dim(s),
           "shape_eval: output too small");
  const double x[3] = {xi.size() > 0 ? xi[0] : 0.0, xi.size() > 1 ? xi[1] : 0.0,
                       xi.size() > 2 ? xi[2] : 0.0};
  switch (s) {
  case Shape::Line2:
    ShapeFunctions<Shape::Line2>::eval(x, N.data(), dN.data());
    return;
  case Shape::Line3:
    ShapeFunctions<Shape::Line3>::eval(x, N.data(), dN.data());
    return;
  case Shape::Tri3:
    ShapeFunctions<Shape::Tri3>::eval(x, N.data(), dN.data());
    return;
  case Shape::Tri6:
    ShapeFunctions<Shape::Tri6>::eval(x, N.data(), dN.data());
    return;
  case Shape::Quad4:
    ShapeFunctions<Shape::Quad4>::eval(x, N.data(), dN.data());
    return;
  case Shape::Tet4:
    ShapeFunctions<Shape::Tet4>::eval(x, N.data(), dN.data());
    return;
  case Shape::Tet10:
    ShapeFunctions<Shape::Tet10>::eval(x, N.data(), dN.data());
    return;
  case Shape::Hex8:
    ShapeFunctions<Shape::Hex8>::eval(x, N.data(), dN.data());
    return;
  case Shape::Quad8:
    ShapeFunctions<Shape::Quad8>::eval(x, N.data(), dN.data());
    return;
  case Shape::Wedge6:
    ShapeFunctions<Shape::Wedge6>::eval(x, N.data(), dN.data());
    return;
  case Shape::Wedge15:
    ShapeFunctions<Shape::Wedge15>::eval(x, N.data(), dN.data());
    return;
  case Shape::Hex20:
    ShapeFunctions<Shape::Hex20>::eval(x, N.data(), dN.data());
    return;
  }
}

namespace {
using P = std::array<double, 3>;
constexpr std::array<P, 2> kLine2Nodes{{{-1, 0, 0}, {1, 0, 0}}};
constexpr std::array<P, 3> kLine3Nodes{{{-1, 0, 0}, {1, 0, 0}, {0, 0, 0}}};
constexpr std::array<P, 3> kTri3Nodes{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
constexpr std::array<P, 6> kTri6Nodes{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}}};
constexpr std::array<P, 4> kQuad4Nodes{{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}};
constexpr std::array<P, 4> kTet4Nodes{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
constexpr std::array<P, 10> kTet10Nodes{{{0, 0, 0},
                                         {1, 0, 0},
                                         {0, 1, 0},
                                         {0, 0, 1},
                                         {0.5, 0, 0},
                                         {0.5, 0.5, 0},
                                         {0, 0.5, 0},
                                         {0, 0, 0.5},
                                         {0.5, 0, 0.5},
                                         {0, 0.5, 0.5}}};
constexpr std::array<P, 8> kHex8Nodes{{{-1, -1, -1},
                                       {1, -1, -1},
                                       {1, 1, -1},
                                       {-1, 1, -1},
                                       {-1, -1, 1},
                                       {1, -1, 1},
                                       {1, 1, 1},
                                       {-1, 1, 1}}};
constexpr std::array<P, 8> kQuad8Nodes{
    {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}}};
constexpr std::array<P, 6> kWedge6Nodes{
    {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}};
constexpr std::array<P, 15> kWedge15Nodes{{{0, 0, -1},
                                           {1, 0, -1},
                                           {0, 1, -1},
                                           {0, 0, 1},
                                           {1, 0, 1},
                                           {0, 1, 1},
                                           {0.5, 0, -1},
                                           {0.5, 0.5, -1},
                                           {0, 0.5, -1},
                                           {0.5, 0, 1},
                                           {0.5, 0.5, 1},
                                           {0, 0.5, 1},
                                           {0, 0, 0},
                                           {1, 0, 0},
                                           {0, 1, 0}}};
constexpr std::array<P, 20> kHex20Nodes{
    {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1},  {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},
     {-1, 1, 1},   {0, -1, -1}, {1, 0, -1},  {0, 1, -1},  {-1, 0, -1}, {0, -1, 1}, {1, 0, 1},
     {0, 1, 1},    {-1, 0, 1},  {-1, -1, 0}, {1, -1, 0},  {1, 1, 0},   {-1, 1, 0}}};

// Abaqus face numbering (see element_faces.hpp), 0-based.
constexpr std::array<FaceDef, 6> kHexFaces{{{Shape::Quad4, 4, {0, 1, 2, 3}},
                                            {Shape::Quad4, 4, {4, 7, 6, 5}},
                                            {Shape::Quad4, 4, {0, 4, 5, 1}},
                                            {Shape::Quad4, 4, {1, 5, 6, 2}},
                                            {Shape::Quad4, 4, {2, 6, 7, 3}},
                                            {Shape::Quad4, 4, {3, 7, 4, 0}}}};
constexpr std::array<FaceDef, 4> kTet4Faces{{{Shape::Tri3, 3, {0, 1, 2}},
                                             {Shape::Tri3, 3, {0, 3, 1}},
                                             {Shape::Tri3, 3, {1, 3, 2}},
                                             {Shape::Tri3, 3, {2, 3, 0}}}};
// Tri6 order: corners, then midsides c1-c2, c2-c3, c3-c1 (edges 1-2:5, 2-3:6, 3-1:7, 1-4:8,
// 2-4:9, 3-4:10 in 1-based Tet10 numbering).
constexpr std::array<FaceDef, 4> kTet10Faces{{{Shape::Tri6, 6, {0, 1, 2, 4, 5, 6}},
                                              {Shape::Tri6, 6, {0, 3, 1, 7, 8, 4}},
                                              {Shape::Tri6, 6, {1, 3, 2, 8, 9, 5}},
                                              {Shape::Tri6, 6, {2, 3, 0, 9, 7, 6}}}};
// Quadratic faces list the corners in the order of the linear face, then the midsides of its
// edges in the same order (Quad8: 1-2, 2-3, 3-4, 4-1 of the face).
constexpr std::array<FaceDef, 6> kHex20Faces{{{Shape::Quad8, 8, {0, 1, 2, 3, 8, 9, 10, 11}},
                                              {Shape::Quad8, 8, {4, 7, 6, 5, 15, 14, 13, 12}},
                                              {Shape::Quad8, 8, {0, 4, 5, 1, 16, 12, 17, 8}},
                                              {Shape::Quad8, 8, {1, 5, 6, 2, 17, 13, 18, 9}},
                                              {Shape::Quad8, 8, {2, 6, 7, 3, 18, 14, 19, 10}},
                                              {Shape::Quad8, 8, {3, 7, 4, 0, 19, 15, 16, 11}}}};
// Wedge: S1 1-2-3, S2 4-6-5, S3 1-4-5-2, S4 2-5-6-3, S5 3-6-4-1 (Abaqus).
constexpr std::array<FaceDef, 5> kWedge6Faces{{{Shape::Tri3, 3, {0, 1, 2}},
                                               {Shape::Tri3, 3, {3, 5, 4}},
                                               {Shape::Quad4, 4, {0, 3, 4, 1}},
                                               {Shape::Quad4, 4, {1, 4, 5, 2}},
                                               {Shape::Quad4, 4, {2, 5, 3, 0}}}};
constexpr std::array<FaceDef, 5> kWedge15Faces{{{Shape::Tri6, 6, {0, 1, 2, 6, 7, 8}},
                                                {Shape::Tri6, 6, {3, 5, 4, 11, 10, 9}},
                                                {Shape::Quad8, 8, {0, 3, 4, 1, 12, 9, 13, 6}},
                                                {Shape::Quad8, 8, {1, 4, 5, 2, 13, 10, 14, 7}},
                                                {Shape::Quad8, 8, {2, 5, 3, 0, 14, 11, 12, 8}}}};
constexpr std::array<FaceDef, 4> kQuad8Edges{{{Shape::Line3, 3, {0, 1, 4}},
                                              {Shape::Line3, 3, {1, 2, 5}},
                                              {Shape::Line3, 3, {2, 3, 6}},
                                              {Shape::Line3, 3, {3, 0, 7}}}};
constexpr std::array<FaceDef, 4> kQuadEdges{{{Shape::Line2, 2, {0, 1}},
                                             {Shape::Line2, 2, {1, 2}},
                                             {Shape::Line2, 2, {2, 3}},
                                             {Shape::Line2, 2, {3, 0}}}};
constexpr std::array<FaceDef, 3> kTriEdges{
    {{Shape::Line2, 2, {0, 1}}, {Shape::Line2, 2, {1, 2}}, {Shape::Line2, 2, {2, 0}}}};
constexpr std::array<FaceDef, 3> kTri6Edges{
    {{Shape::Line3, 3, {0, 1, 3}}, {Shape::Line3, 3, {1, 2, 4}}, {Shape::Line3, 3, {2, 0, 5}}}};
} // namespace

std::span<const std::array<double, 3>> shape_node_coords(Shape s) {
  switch (s) {
  case Shape::Line2:
    return kLine2Nodes;
  case Shape::Line3:
    return kLine3Nodes;
  case Shape::Tri3:
    return kTri3Nodes;
  case Shape::Tri6:
    return kTri6Nodes;
  case Shape::Quad4:
    return kQuad4Nodes;
  case Shape::Tet4:
    return kTet4Nodes;
  case Shape::Tet10:
    return kTet10Nodes;
  case Shape::Hex8:
    return kHex8Nodes;
  case Shape::Quad8:
    return kQuad8Nodes;
  case Shape::Wedge6:
    return kWedge6Nodes;
  case Shape::Wedge15:
    return kWedge15Nodes;
  case Shape::Hex20:
    return kHex20Nodes;
  }
  return {};
}

std::span<const FaceDef> element_faces(Shape cell) {
  switch (cell) {
  case Shape::Hex8:
    return kHexFaces;
  case Shape::Tet4:
    return kTet4Faces;
  case Shape::Tet10:
    return kTet10Faces;
  case Shape::Quad4:
    return kQuadEdges;
  case Shape::Tri3:
    return kTriEdges;
  case Shape::Tri6:
    return kTri6Edges;
  case Shape::Quad8:
    return kQuad8Edges;
  case Shape::Wedge6:
    return kWedge6Faces;
  case Shape::Wedge15:
    return kWedge15Faces;
  case Shape::Hex20:
    return kHex20Faces;
  default:
    return {};
  }
}

std::span<const QuadraturePoint> full_integration_rule(Shape shape) {
  switch (shape) {
  case Shape::Line2:
    return kGaussLine2;
  case Shape::Line3:
    return kGaussLine3;
  case Shape::Tri3:
    return kTri1;
  case Shape::Tri6:
    return kTri3;
  case Shape::Quad4:
    return kGaussQuad4;
  case Shape::Tet4:
    return kTet1;
  case Shape::Tet10:
    return kTet4;
  case Shape::Hex8:
    return kGaussHex8;
  case Shape::Quad8:
    return kGaussQuad9;
  case Shape::Wedge6:
    return kWedge2;
  case Shape::Wedge15:
    return kWedge9;
  case Shape::Hex20:
    return kGaussHex27;
  }
  return {};
}

std::span<const QuadraturePoint> reduced_integration_rule(Shape shape) {
  switch (shape) {
  case Shape::Quad4:
    return kGaussQuad1;
  case Shape::Hex8:
    return kGaussHex1;
  case Shape::Quad8:
    return kGaussQuad4;
  case Shape::Hex20:
    return kGaussHex8;
  default:
    return full_integration_rule(shape);
  }
}

std::span<const QuadraturePoint> face_load_rule(Shape face_shape) {
  switch (face_shape) {
  case Shape::Line2:
    return kGaussLine2;
  case Shape::Line3:
    return kGaussLine3;
  case Shape::Tri3:
    return kTri3;
  case Shape::Tri6:
    return kTri6;
  case Shape::Quad4:
    return kGaussQuad4;
  case Shape::Quad8:
    return kGaussQuad9;
  default:
    return full_integration_rule(face_shape);
  }
}

} // namespace gapfem
