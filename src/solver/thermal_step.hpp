#pragma once
/// @file thermal_step.hpp
/// What the analysis needs for heat transfer and coupled temperature-displacement steps, kept out
/// of analysis.cpp: procedure/element compatibility, initial temperatures, the DELTMX control of
/// transient increments and the heat balance of a step. Theory: docs/theory/thermal.md.
#include "common/archive.hpp"
#include "fem/discretization.hpp"
#include "fem/dof_map.hpp"
#include "results/results.hpp"

#include <span>
#include <vector>

namespace gapfem {

struct Model;
struct Step;
struct Incrementation;
struct IncrementRules;
class Assembler;

/// Every element must be able to take part in every step (Abaqus's rule): stress/displacement
/// steps take no element with temperature DOFs, heat transfer steps only heat-transfer elements
/// (temperature DOFs without displacements); coupled steps take any element. InputError naming the
/// step and one offending element otherwise.
void check_step_procedures(const Model& model);

/// The temperature DOFs start at the *INITIAL CONDITIONS, TYPE=TEMPERATURE values (0 elsewhere).
void set_initial_temperatures(const Model& model, const DofMap& dofs, std::span<double> u);

/// Transient heat transfer and coupled steps without DELTMX use fixed increments of the initial
/// size (Abaqus, *HEAT TRANSFER: "if DELTMX is omitted, fixed time increments will be used");
/// gapfem still cuts back a failed increment and then continues at the smaller size.
bool fixed_transient_increments(const Step& step);

/// Largest |u - u_start| over the temperature DOFs that are not prescribed (Abaqus measures
/// DELTMX "at any node except nodes with boundary conditions").
double max_free_temperature_change(const DofMap& dofs, const EquationMap& eqs,
                                   std::span<const double> u, std::span<const double> u_start);

/// The DELTMX decision after a converged increment with largest temperature change dT_max.
struct TemperatureAccuracy {
  bool redo = false;  ///< the increment exceeded DELTMX: repeat it with dt * ratio
  double ratio = 1.0; ///< redo: the reduction; otherwise the largest growth of the next increment
};
/// Abaqus's time-integration accuracy rule with the DELTMX tolerance (Analysis User's Manual,
/// "Time integration accuracy in transient problems"): dT_max > DELTMX redoes the increment with
/// dt_new = 0.85 (DELTMX / dT_max) dt; otherwise the next increment may grow to
/// (DELTMX / dT_max) dt, at most by the factor 2 of diffusion-dominated procedures. The convergence
/// rules of IncrementController limit it further.
TemperatureAccuracy deltmx_rule(double dT_max, double deltmx, double cutback = 0.85);

/// Heat balance of one step (StepChecks): reaction fluxes RFL + applied fluxes (CFLUX, DFLUX,
/// films) against the heat stored by the capacity. Transient steps integrate the fluxes over the
/// converged increments (backward Euler: flux at the increment end times dt) and take the stored
/// heat from the elements between the start and the end of the step; steady-state steps compare
/// the fluxes at the end of the step (nothing is stored). The error is
/// |RFL + applied - stored|, judged against `heat_scale`.
class HeatBalance {
 public:
  /// `active`: the step is a heat transfer or coupled step of a model with temperature DOFs.
  HeatBalance(bool active, bool transient, std::span<const double> u_step_start);
  bool active() const { return _active; }
  /// Restart: the sums so far.
  void save(ArchiveWriter& a) const;
  void restore(ArchiveReader& a);
  /// A converged (committed) increment of size dt with its reactions and external loads per slot.
  void add_increment(const DofMap& dofs, double dt, std::span<const double> reaction,
                     std::span<const double> f_ext);
  /// Fill the heat-balance fields of `c` at the end of the step (u_now: the committed solution).
  void finish(Discretization& disc, const StepContext& ctx, std::span<const double> u_now,
              std::span<const double> reaction, std::span<const double> f_ext, StepChecks& c) const;

 private:
  bool _active, _transient;
  std::vector<double> _u_begin;
  double _reaction = 0.0, _applied = 0.0, _scale = 0.0;
};

/// Sum of ElementKernel::stored_heat over all elements between the fields' u_start and u.
double total_stored_heat(Discretization& disc, const StepContext& ctx, std::span<const double> u,
                         std::span<const double> u_start);

} // namespace gapfem
