#pragma once
/// @file face_exchange.hpp
/// The heat a face exchanges with its surroundings per unit area, at one temperature: a film
/// h (T_sink - T) or radiation eps sigma ((T_sink - Z)^4 - (T - Z)^4) (docs/theory/heat.md), and
/// its derivative by T. Heat kernels interpolate it between the face's nodes (the nodal values
/// weighted by the face's consistent or lumped mass matrix, exact for a uniform temperature).
#include "model/loads.hpp"

namespace gapfem {

struct FaceExchange {
  double q = 0.0;     ///< heat into the face per unit area
  double dq_dT = 0.0; ///< its derivative by the face's temperature (<= 0)
};

inline bool is_face_exchange(DistLoadKind kind) {
  return kind == DistLoadKind::Film || kind == DistLoadKind::Radiation;
}

/// `magnitude`: the film coefficient or the emissivity (after amplitudes); `sink` the sink
/// temperature.
inline FaceExchange face_exchange(const DistributedLoad& ld, double magnitude, double sink,
                                  double T) {
  if (ld.kind == DistLoadKind::Radiation) {
    const double c = magnitude * ld.stefan_boltzmann;
    const double t = T - ld.absolute_zero, s = sink - ld.absolute_zero;
    return {c * (s * s * s * s - t * t * t * t), -4.0 * c * t * t * t};
  }
  return {magnitude * (sink - T), -magnitude};
}

} // namespace gapfem
