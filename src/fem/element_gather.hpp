#pragma once
/// @file element_gather.hpp
/// Caller-owned scratch that gathers one element's local data (coordinates, DOF values,
/// temperatures, state, multipliers) into an ElementInput and holds its output buffers. One per
/// thread; no allocation after the first element of the largest type.
#include "fem/discretization.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace gapfem {

/// The solution-dependent fields an assembly pass reads (slot-sized vectors, node-sized
/// temperatures).
struct FieldView {
  std::span<const double> u;                 ///< trial values per slot
  std::span<const double> u_start;           ///< committed values per slot
  std::span<const double> temperature;       ///< predefined temperature per node now (may be empty)
  std::span<const double> temperature_start; ///< … at the increment start
  std::span<const double> initial_temperature;  ///< per node
  std::span<const double> temperature_gradient; ///< 2 per node now (may be empty)
  /// Committed velocity and acceleration per slot: given only in steps whose time integrator
  /// needs them (its trial rates depend on them); empty otherwise (read as zero)
  std::span<const double> v_start, a_start;
  /// Slots whose trial rates are prescribed (base motion: *BOUNDARY, TYPE=VELOCITY|ACCELERATION),
  /// 1 per slot, or empty: there elements see v_given and a_given (per slot) instead of the
  /// integrator's map of the displacement increment (docs/theory/dynamics.md, "Base motion")
  std::span<const std::uint8_t> rate_given;
  std::span<const double> v_given, a_given;
};

class ElementGather {
 public:
  /// Fill `input` for element i of block b; spans point into this object's buffers. `rates`:
  /// also the element's trial velocities and accelerations from ctx->rates and its committed ones
  /// (the assembler asks for them where an operator it applies needs them).
  ElementInput& gather(const Discretization& disc, ElementBlock& block, std::size_t i,
                       const FieldView& fields, const StepContext* ctx, bool rates = false);
  /// Output buffers sized for the current block, zeroed; the mass and damping blocks are sized
  /// and zeroed only when wanted (nothing is touched for them in static steps).
  ElementOutput& output(const ElementBlock& block, bool want_tangent, bool want_mass = false,
                        bool want_damping = false);
  ElementInput& input() { return _in; }

 private:
  /// The element's trial rates from the integrator's map and its committed rates.
  void gather_rates(std::span<const LocalIndex> slots, const FieldView& f,
                    const RateCoefficients& c);

  ElementInput _in;
  ElementOutput _out;
  std::vector<Vec3> _X;
  std::vector<double> _u, _u0, _T, _T0, _Ti, _G;
  std::vector<double> _v, _a, _v0, _a0;
  std::vector<double> _r, _K, _M, _D;
  std::vector<std::uint8_t> _free;
  std::vector<int> _cslot;
  std::vector<double> _cval, _ccomp, _ccoef, _ccol;
};

} // namespace gapfem
