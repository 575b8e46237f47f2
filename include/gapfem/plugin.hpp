#pragma once
/// @file gapfem/plugin.hpp
/// gapfem's element plugin interface: nonlinear user elements written in C or C++.
///
/// A plugin is a shared library (or a C/C++ source that `gapfem --user plugin.cpp deck.inp`
/// compiles into one) that exports two functions with C linkage:
///
///     extern "C" int gapfem_plugin_abi_version(void);  // return GAPFEM_PLUGIN_ABI_VERSION
///     extern "C" int gapfem_element(gapfem_element_call* call);
///
/// gapfem calls gapfem_element for every element of every user element type of the deck that is
/// not LINEAR (*USER ELEMENT, TYPE=Un, NODES=, PROPERTIES=, I PROPERTIES=, VARIABLES=, with
/// *UEL PROPERTY), exactly where Abaqus calls its UEL subroutine; `call->type` is the n of Un.
/// The function returns 0 on success; anything else stops the analysis with the text the
/// function wrote into `call->message` (exit status 2).
///
/// Conventions (the same physics as a UEL, in gapfem's sign and C's array order):
/// - residual = internal force minus the element's own external load: -RHS of a UEL;
/// - tangent = d residual / d u, n_dofs x n_dofs, row-major: AMATRX of a UEL (transposed).
///   Without UNSYMM on *USER ELEMENT gapfem uses its symmetric part;
/// - u holds the total values at the end of the increment (the current Newton estimate), du the
///   change over the increment; the DOFs run node by node, each node's in the order of its
///   *USER ELEMENT data line;
/// - state arrives holding the values at the start of the increment (state_start holds them
///   too) and must leave holding the values at its end; energy (8 values, Abaqus's ENERGY
///   layout) likewise. A cut-back throws both away: every call of an increment attempt starts
///   from the same start values;
/// - *pnewdt arrives large; set it below 1 to abandon the increment and try it again with
///   *pnewdt times the time increment, above 1 to bound the growth of the next increment;
/// - the function may be called from several threads, but never concurrently: gapfem serialises
///   the calls of one library.
///
/// ABI: the layout of gapfem_element_call is fixed for an ABI version; a plugin built for
/// another version is refused with a message. Version history: 1 (gapfem 0.1).
#include <stdint.h>

#define GAPFEM_PLUGIN_ABI_VERSION 1

#ifdef __cplusplus
extern "C" {
#endif

/// One element evaluation (ABI version 1). Pointers are valid for the call only.
typedef struct gapfem_element_call {
  int32_t abi_version; ///< the ABI version of the gapfem that calls
  int32_t type;        ///< n of the element's type Un
  int64_t element;     ///< the element's number in the deck
  int32_t n_nodes;     ///< NODES=
  int32_t n_coords;    ///< coordinates per node (MCRD)
  int32_t n_dofs;      ///< DOFs of the element (NDOFEL)
  int32_t n_state;     ///< VARIABLES=
  int32_t n_properties, n_int_properties;
  const double* coords;          ///< reference coordinates, node by node: coords[a * n_coords + i]
  const double* u;               ///< [n_dofs] total values, end of the increment
  const double* du;              ///< [n_dofs] change over the increment
  const double* properties;      ///< [n_properties] real properties (*UEL PROPERTY)
  const int32_t* int_properties; ///< [n_int_properties] integer properties
  const double* state_start;     ///< [n_state] state at the start of the increment
  double* state;                 ///< [n_state] in: start values; out: values at the end
  double* energy;                ///< [8] in: start values; out: values at the end
  double step_time, total_time;  ///< at the start of the increment (TIME(1), TIME(2))
  double dt;                     ///< the time increment (DTIME)
  double period;                 ///< the step's time period (PERIOD)
  int32_t step, increment;       ///< KSTEP, KINC; increment 0 (dt = 0): a stiffness probe at
                                 ///< the start of a step, whose results are not committed
  int32_t procedure;             ///< LFLAGS(1): 1 static, 2 static with fixed increments, ...
  int32_t nlgeom;                ///< LFLAGS(2)
  double* residual;              ///< [n_dofs] out, zeroed on entry
  double* tangent;               ///< [n_dofs * n_dofs] out, zeroed on entry, row-major
  double* pnewdt;                ///< in: a large value; out: the time-increment request
  char* message;                 ///< out: why the call failed (NUL-terminated)
  int32_t message_size;          ///< bytes available at message
} gapfem_element_call;

typedef int (*gapfem_element_fn)(gapfem_element_call* call);
typedef int (*gapfem_plugin_abi_version_fn)(void);

#ifdef __cplusplus
} // extern "C"

#include <cstdio>
#include <span>

namespace gapfem::plugin {

/// Views of a call's arrays with their sizes (C++20).
struct Element {
  gapfem_element_call& call;
  std::span<const double> coords() const {
    return {call.coords, static_cast<std::size_t>(call.n_nodes * call.n_coords)};
  }
  std::span<const double> u() const { return {call.u, static_cast<std::size_t>(call.n_dofs)}; }
  std::span<const double> du() const { return {call.du, static_cast<std::size_t>(call.n_dofs)}; }
  std::span<const double> properties() const {
    return {call.properties, static_cast<std::size_t>(call.n_properties)};
  }
  std::span<const int32_t> int_properties() const {
    return {call.int_properties, static_cast<std::size_t>(call.n_int_properties)};
  }
  std::span<const double> state_start() const {
    return {call.state_start, static_cast<std::size_t>(call.n_state)};
  }
  std::span<double> state() const { return {call.state, static_cast<std::size_t>(call.n_state)}; }
  std::span<double> energy() const { return {call.energy, 8}; }
  std::span<double> residual() const {
    return {call.residual, static_cast<std::size_t>(call.n_dofs)};
  }
  /// tangent(i, j) = d residual_i / d u_j
  double& tangent(int i, int j) const { return call.tangent[i * call.n_dofs + j]; }
  /// Fails the call with a message (return its value from gapfem_element).
  template <typename... A>
  int fail(const char* format, A... args) const {
    if (call.message && call.message_size > 0)
      std::snprintf(call.message, static_cast<std::size_t>(call.message_size), format, args...);
    return 1;
  }
};

} // namespace gapfem::plugin
#endif
