#pragma once
/// @file shell_strains.hpp
/// Strains of the shells at one point of the reference surface, templated on the scalar so the
/// kernel differentiates them with Jets (shell.hpp; docs/theory/structural.md §4.2).
///
/// With x_r = X + u and d = D + dd (dd the change of the director), the covariant strains are
///   membrane   e_ab = 1/2 (x,a . x,b - X,a . X,b)
///   bending    k_ab = 1/2 (x,a . d,b + x,b . d,a - X,a . D,b - X,b . D,a)
///   shear      g_a  = x,a . d - X,a . D
/// (a, b natural coordinates r, s); without NLGEOM the products of two changes are dropped, which
/// is their linearisation. Local components follow from T[a][i] = A^a . e_i.
#include "elements/structural/rotation.hpp"
#include "elements/structural/shell_geometry.hpp"

#include <array>
#include <type_traits>

namespace gapfem::shell {

using rotation::V3;

/// Nodal unknowns: displacements, director changes and (for drilling) the changes of the local
/// directions e1, e2 of each node under its rotation.
template <class T, int NN>
struct ShellNodal {
  std::array<V3<T>, NN> u{};
  std::array<V3<T>, NN> dd{};
};

template <class T>
struct Covariant {
  std::array<T, 3> m{}; ///< e_rr, e_ss, e_rs
  std::array<T, 3> k{}; ///< k_rr, k_ss, k_rs
  std::array<T, 2> g{}; ///< g_r, g_s
};

/// a0 . db + da . b0 (+ da . db with NLGEOM): the change of a product of two vectors.
template <class T>
T change(const Vec3& a0, const V3<T>& da, const Vec3& b0, const V3<T>& db, bool nl) {
  T v = rotation::dot3(a0, db) + rotation::dot3(da, b0);
  if (nl) v += rotation::dot3(da, db);
  return v;
}

/// sum_a c_a u_a[i]: the displacements are the independent variables 6a + i, so for jets the
/// combination is built directly (value and gradient; no Hessian), O(NN) instead of O(NN N^2).
template <class T, int NN>
V3<T> combine_displacements(const std::array<double, kMaxNodes>& c, const ShellNodal<T, NN>& nv) {
  V3<T> r;
  for (int i = 0; i < 3; ++i) {
    if constexpr (std::is_same_v<T, double>) {
      r[i] = 0.0;
      for (int a = 0; a < NN; ++a) r[i] += c[a] * nv.u[a][i];
    } else {
      T v(0.0);
      for (int a = 0; a < NN; ++a) {
        v.v += c[a] * nv.u[a][i].v;
        v.g[6 * a + i] = c[a];
      }
      r[i] = v;
    }
  }
  return r;
}

template <class T, int NN>
void surface_derivatives(const SurfacePoint& p, const ShellNodal<T, NN>& nv, V3<T>& ur, V3<T>& us) {
  ur = combine_displacements(p.sh.dr, nv);
  us = combine_displacements(p.sh.ds, nv);
}

/// sum_a c_a v_a of per-node vectors.
template <class T, std::size_t NN>
V3<T> combine(const std::array<double, kMaxNodes>& c, const std::array<V3<T>, NN>& v) {
  V3<T> r;
  for (int i = 0; i < 3; ++i) {
    r[i] = c[0] * v[0][i];
    for (std::size_t a = 1; a < NN; ++a) r[i] += c[a] * v[a][i];
  }
  return r;
}

/// The covariant transverse shear strains (g_r, g_s) alone (MITC tying points).
template <class T, int NN>
std::array<T, 2> covariant_shear(const SurfacePoint& p, const ShellNodal<T, NN>& nv, bool nl) {
  V3<T> ur, us;
  surface_derivatives(p, nv, ur, us);
  const V3<T> dd = combine(p.sh.N, nv.dd);
  return {change(p.A1, ur, p.D, dd, nl), change(p.A2, us, p.D, dd, nl)};
}

template <class T, int NN>
Covariant<T> covariant(const SurfacePoint& p, const ShellNodal<T, NN>& nv, bool nl) {
  V3<T> ur, us;
  surface_derivatives(p, nv, ur, us);
  const V3<T> dd = combine(p.sh.N, nv.dd), ddr = combine(p.sh.dr, nv.dd),
              dds = combine(p.sh.ds, nv.dd);
  Covariant<T> c;
  c.m[0] = 0.5 * change(p.A1, ur, p.A1, ur, nl);
  c.m[1] = 0.5 * change(p.A2, us, p.A2, us, nl);
  c.m[2] = 0.5 * change(p.A1, ur, p.A2, us, nl);
  c.k[0] = change(p.A1, ur, p.Dr, ddr, nl);
  c.k[1] = change(p.A2, us, p.Ds, dds, nl);
  c.k[2] = 0.5 * (change(p.A1, ur, p.Ds, dds, nl) + change(p.A2, us, p.Dr, ddr, nl));
  c.g[0] = change(p.A1, ur, p.D, dd, nl);
  c.g[1] = change(p.A2, us, p.D, dd, nl);
  return c;
}

/// Local Voigt components (11, 22, engineering 12) of a covariant symmetric tensor (rr, ss, rs).
template <class T>
std::array<T, 3> to_local(const SurfacePoint& p, const std::array<T, 3>& c) {
  const auto& t = p.T;
  std::array<T, 3> v;
  v[0] = c[0] * (t[0][0] * t[0][0]) + c[2] * (2.0 * t[0][0] * t[1][0]) + c[1] * (t[1][0] * t[1][0]);
  v[1] = c[0] * (t[0][1] * t[0][1]) + c[2] * (2.0 * t[0][1] * t[1][1]) + c[1] * (t[1][1] * t[1][1]);
  v[2] = c[0] * (2.0 * t[0][0] * t[0][1]) + c[2] * (2.0 * (t[0][0] * t[1][1] + t[1][0] * t[0][1])) +
         c[1] * (2.0 * t[1][0] * t[1][1]);
  return v;
}

/// Local transverse shear strains (13, 23) of covariant (g_r, g_s).
template <class T>
std::array<T, 2> shear_to_local(const SurfacePoint& p, const T& gr, const T& gs) {
  return {gr * p.T[0][0] + gs * p.T[1][0], gr * p.T[0][1] + gs * p.T[1][1]};
}

/// The strains of the section at one point in local components.
template <class T>
struct SectionStrains {
  std::array<T, 3> eps{}; ///< membrane 11, 22, 12 (engineering)
  std::array<T, 3> kap{}; ///< bending 11, 22, 12 (engineering twist)
  std::array<T, 2> gam{}; ///< transverse shear 13, 23
};

} // namespace gapfem::shell
