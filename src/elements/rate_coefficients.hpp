#pragma once
/// @file rate_coefficients.hpp
/// What element kernels see of a step's time integrator (solver/time_integrator.hpp): never the
/// increment dt, only the coefficients of the affine maps from the increment of the solution to
/// its trial rates. For backward Euler, Newmark and HHT the trial velocity and acceleration of a
/// DOF are affine in (u - u_n, v_n, a_n):
///   v = v_du (u - u_n) + v_v v_n + v_a a_n
///   a = a_du (u - u_n) + a_v v_n + a_a a_n
/// so d v / d u = v_du and d a / d u = a_du are the weights of the damping and mass operators in
/// the effective tangent. A kernel with a nonlinear stored quantity Q(u) (the heat capacity's
/// internal energy E(T)) takes the same map for Q's rate: Q' = v_du (Q(u) - Q(u_n)) + v_v Q'_n +
/// v_a Q''_n, whose derivative is v_du dQ/du.

namespace gapfem {

struct RateCoefficients {
  bool first_order = false;  ///< trial velocities (rates) are defined: capacity, viscous damping
  bool second_order = false; ///< trial accelerations are defined too: inertia
  double v_du = 0.0, v_v = 0.0, v_a = 0.0; ///< the velocity's map
  double a_du = 0.0, a_v = 0.0, a_a = 0.0; ///< the acceleration's map

  bool defined() const { return first_order || second_order; }
  /// Does the velocity (acceleration) depend on the committed rates?
  bool velocity_has_history() const { return v_v != 0.0 || v_a != 0.0; }
  bool acceleration_has_history() const { return a_v != 0.0 || a_a != 0.0; }
  double velocity(double du, double v0, double a0) const {
    return velocity_has_history() ? v_du * du + v_v * v0 + v_a * a0 : v_du * du;
  }
  double acceleration(double du, double v0, double a0) const {
    return acceleration_has_history() ? a_du * du + a_v * v0 + a_a * a0 : a_du * du;
  }

  /// Backward Euler over an increment dt (first order): v = (u - u_n) / dt; none for dt <= 0.
  /// v_du is formed as 1.0 / dt, the factor the heat kernels have always multiplied by.
  static RateCoefficients backward_euler(double dt) {
    RateCoefficients c;
    if (dt > 0.0) {
      c.first_order = true;
      c.v_du = 1.0 / dt;
    }
    return c;
  }
};

} // namespace gapfem
