#pragma once
/// @file procedures.hpp
/// The step procedures gapfem has (solver/procedure.hpp), one file each; procedure.cpp registers
/// them.
#include "solver/procedure.hpp"

namespace gapfem {

/// *STATIC: Newton increments; automatic stabilization (procedure_static.cpp).
std::unique_ptr<StepProcedure> make_static_procedure(Analysis::Impl& a);
/// *HEAT TRANSFER and *COUPLED TEMPERATURE-DISPLACEMENT: transient terms, DELTMX, heat balance
/// (procedure_heat_transfer.cpp).
std::unique_ptr<StepProcedure> make_heat_transfer_procedure(Analysis::Impl& a);
/// *SUBSTRUCTURE GENERATE: one reduction of the stiffness, no increments
/// (procedure_substructure.cpp; the reduction itself: substructure_generate.cpp).
std::unique_ptr<StepProcedure> make_substructure_generate_procedure(Analysis::Impl& a);
/// *DYNAMIC: implicit direct integration, HHT or backward Euler (procedure_dynamic.cpp).
std::unique_ptr<StepProcedure> make_dynamic_procedure(Analysis::Impl& a);
/// *FREQUENCY: eigenmodes about the base state, no increments (procedure_frequency.cpp).
std::unique_ptr<StepProcedure> make_frequency_procedure(Analysis::Impl& a);
/// *BUCKLE: eigenvalue buckling about the base state, no increments (procedure_buckle.cpp).
std::unique_ptr<StepProcedure> make_buckle_procedure(Analysis::Impl& a);
/// *STATIC in a *STEP, PERTURBATION: the linear response about the base state
/// (procedure_static_perturbation.cpp).
std::unique_ptr<StepProcedure> make_static_perturbation_procedure(Analysis::Impl& a);
/// *STEADY STATE DYNAMICS (mode-based): harmonic response per frequency
/// (procedure_steady_state.cpp).
std::unique_ptr<StepProcedure> make_steady_state_procedure(Analysis::Impl& a);
/// *MODAL DYNAMIC: transient response on the modes, exact per increment
/// (procedure_modal_dynamic.cpp).
std::unique_ptr<StepProcedure> make_modal_dynamic_procedure(Analysis::Impl& a);
/// *RESPONSE SPECTRUM: peaks from the last *FREQUENCY step's modes
/// (procedure_response_spectrum.cpp).
std::unique_ptr<StepProcedure> make_response_spectrum_procedure(Analysis::Impl& a);

} // namespace gapfem
