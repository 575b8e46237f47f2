#pragma once
/// @file handlers.hpp
/// The keyword handlers (one function per keyword) called by the parser's keyword table. Each
/// handler reads one keyword block into the BuildState; it reports per-line problems to the
/// diagnostics and may throw InputError for problems of the keyword line itself.
#include "io/inp/model_builder.hpp"

namespace gapfem::inp {

/// @name *HEADING, *PREPRINT, *NODE, *ELEMENT, *NSET, *ELSET, *SURFACE (handlers_mesh.cpp)
///@{
void handle_heading(BuildState& s, const Keyword& kw);
void handle_node(BuildState& s, const Keyword& kw);
void handle_element(BuildState& s, const Keyword& kw);
void handle_system(BuildState& s, const Keyword& kw);
void handle_ngen(BuildState& s, const Keyword& kw);
void handle_nfill(BuildState& s, const Keyword& kw);
void handle_elgen(BuildState& s, const Keyword& kw);
void handle_nset(BuildState& s, const Keyword& kw);
void handle_elset(BuildState& s, const Keyword& kw);
void handle_surface(BuildState& s, const Keyword& kw);
///@}

/// @name *PART, *ASSEMBLY, *INSTANCE (handlers_assembly.cpp)
///@{
/// Inside *PART … *END PART or *INSTANCE … *END INSTANCE: keeps the keyword for the instances'
/// replay (or reports one that cannot appear there) and returns true; otherwise false.
bool record_keyword(BuildState& s, Keyword& kw);
void handle_part(BuildState& s, const Keyword& kw);
void handle_end_part(BuildState& s, const Keyword& kw);
void handle_assembly(BuildState& s, const Keyword& kw);
void handle_end_assembly(BuildState& s, const Keyword& kw);
void handle_instance(BuildState& s, const Keyword& kw);
void handle_end_instance(BuildState& s, const Keyword& kw);
///@}

/// @name Materials, *AMPLITUDE, *INITIAL CONDITIONS, *PHYSICAL CONSTANTS (handlers_material.cpp)
///@{
void handle_material(BuildState& s, const Keyword& kw);
void handle_elastic(BuildState& s, const Keyword& kw);
void handle_density(BuildState& s, const Keyword& kw);
void handle_expansion(BuildState& s, const Keyword& kw);
void handle_conductivity(BuildState& s, const Keyword& kw);
void handle_specific_heat(BuildState& s, const Keyword& kw);
void handle_amplitude(BuildState& s, const Keyword& kw);
void handle_initial_conditions(BuildState& s, const Keyword& kw);
void handle_physical_constants(BuildState& s, const Keyword& kw);
/// *DAMPING in a material: Rayleigh ALPHA, BETA (handlers_damping.cpp)
void handle_damping(BuildState& s, const Keyword& kw);
///@}

/// @name *MATRIX INPUT, *MATRIX ASSEMBLE, substructures (handlers_substructure.cpp)
///@{
void handle_matrix_input(BuildState& s, const Keyword& kw);
void handle_matrix_assemble(BuildState& s, const Keyword& kw);
void handle_substructure_generate(BuildState& s, const Keyword& kw);
void handle_retained_nodal_dofs(BuildState& s, const Keyword& kw);
void handle_substructure_matrix_output(BuildState& s, const Keyword& kw);
void handle_substructure_property(BuildState& s, const Keyword& kw);
void handle_substructure_path(BuildState& s, const Keyword& kw);
/// The substructure type TYPE=Zn of an *ELEMENT keyword: its library (FILE=, or the one library
/// in the deck's folder that holds it) read into Model::substructures; its index there.
std::int32_t load_substructure_type(BuildState& s, const Keyword& kw, const std::string& type);
///@}

/// @name *USER ELEMENT, *MATRIX, *UEL PROPERTY (handlers_user.cpp)
///@{
void handle_user_element(BuildState& s, const Keyword& kw);
void handle_matrix(BuildState& s, const Keyword& kw);
void handle_uel_property(BuildState& s, const Keyword& kw);
///@}

/// @name *SOLID SECTION, *BEAM SECTION, *SPRING (handlers_section.cpp)
///@{
void handle_solid_section(BuildState& s, const Keyword& kw);
void handle_section_controls(BuildState& s, const Keyword& kw);
void handle_beam_section(BuildState& s, const Keyword& kw);
void handle_shell_section(BuildState& s, const Keyword& kw);
void handle_shell_general_section(BuildState& s, const Keyword& kw);
void handle_section_points(BuildState& s, const Keyword& kw);
void handle_beam_added_inertia(BuildState& s, const Keyword& kw);
void handle_nodal_thickness(BuildState& s, const Keyword& kw);
void handle_beam_transverse_shear(BuildState& s, const Keyword& kw);
void handle_beam_general_section(BuildState& s, const Keyword& kw);
void handle_transverse_shear(BuildState& s, const Keyword& kw);
void handle_spring(BuildState& s, const Keyword& kw);
void handle_dashpot(BuildState& s, const Keyword& kw);
void handle_orientation(BuildState& s, const Keyword& kw); ///< orientation.cpp
/// *SPRING, NONLINEAR (handle_spring): the DOF line and the (force, relative displacement)
/// table into `sec`, added to the model (handlers_dashpot.cpp, beside the dashpot's table).
void read_nonlinear_spring(BuildState& s, const Keyword& kw, SpringSection sec);
void handle_mass(BuildState& s, const Keyword& kw);
void handle_rotary_inertia(BuildState& s, const Keyword& kw);
///@}

/// @name *GAP and its sub-options (handlers_gap.cpp)
///@{
void handle_gap(BuildState& s, const Keyword& kw);
void handle_surface_behavior(BuildState& s, const Keyword& kw);
void handle_friction(BuildState& s, const Keyword& kw);
void handle_contact_damping(BuildState& s, const Keyword& kw);
void handle_gap_conductance(BuildState& s, const Keyword& kw);
void handle_gap_radiation(BuildState& s, const Keyword& kw);
void handle_gap_heat_generation(BuildState& s, const Keyword& kw);
/// Reads *FRICTION parameters and data (shared by *GAP and *CHANGE FRICTION).
FrictionSpec read_friction(BuildState& s, const Keyword& kw);
///@}

/// @name *STEP, *END STEP, procedures, *CHANGE FRICTION (handlers_step.cpp)
///@{
void handle_step(BuildState& s, const Keyword& kw);
void handle_end_step(BuildState& s, const Keyword& kw);
/// The step's procedure (InputError when it has one already).
void set_procedure(BuildState& s, const Keyword& kw, Procedure p);
void handle_static(BuildState& s, const Keyword& kw);
void handle_heat_transfer(BuildState& s, const Keyword& kw);
void handle_dynamic(BuildState& s, const Keyword& kw);
/// *FREQUENCY (handlers_frequency.cpp)
void handle_frequency(BuildState& s, const Keyword& kw);
/// *BUCKLE (handlers_buckle.cpp)
void handle_buckle(BuildState& s, const Keyword& kw);
/// *STEADY STATE DYNAMICS, *MODAL DYNAMIC, *BASE MOTION (handlers_modal_dynamics.cpp)
void handle_steady_state_dynamics(BuildState& s, const Keyword& kw);
void handle_modal_dynamic(BuildState& s, const Keyword& kw);
void handle_base_motion(BuildState& s, const Keyword& kw);
/// *SPECTRUM, *RESPONSE SPECTRUM, *MODAL DAMPING, *SELECT EIGENMODES (handlers_modal.cpp)
void handle_spectrum(BuildState& s, const Keyword& kw);
void handle_response_spectrum(BuildState& s, const Keyword& kw);
void handle_modal_damping(BuildState& s, const Keyword& kw);
void handle_select_eigenmodes(BuildState& s, const Keyword& kw);
void handle_coupled(BuildState& s, const Keyword& kw);
void handle_change_friction(BuildState& s, const Keyword& kw);
/// *CONTROLS (handlers_controls.cpp)
void handle_controls(BuildState& s, const Keyword& kw);
/// *RESTART, WRITE (restart records) and READ (a restart deck) (handlers_controls.cpp)
void handle_restart(BuildState& s, const Keyword& kw);
/// Closes an open step at the end of the deck or at a *STEP without *END STEP.
void close_step(BuildState& s);
///@}

/// @name Boundary conditions and loads (handlers_loads.cpp)
///@{
void handle_boundary(BuildState& s, const Keyword& kw);
void handle_cload(BuildState& s, const Keyword& kw);
void handle_cflux(BuildState& s, const Keyword& kw);
void handle_dload(BuildState& s, const Keyword& kw);
void handle_dsload(BuildState& s, const Keyword& kw);
void handle_dflux(BuildState& s, const Keyword& kw);
void handle_dsflux(BuildState& s, const Keyword& kw);
void handle_film(BuildState& s, const Keyword& kw);
void handle_sfilm(BuildState& s, const Keyword& kw);
void handle_radiate(BuildState& s, const Keyword& kw);
void handle_cyclic_symmetry_model(BuildState& s, const Keyword& kw);
/// *TIE, CYCLIC SYMMETRY (handlers_cyclic.cpp), built at the end of the model data.
struct CyclicTie {
  std::string name, slave, master;
  SourceLocation loc;
  std::optional<double> tolerance;
  bool adjust = true;
};
void build_cyclic_tie(BuildState& s, const CyclicTie& t);
/// After the deck: the cyclic model's TIE= names a cyclic tie, no step needs other nodal
/// diameters.
void check_cyclic_symmetry(BuildState& s);
void handle_sradiate(BuildState& s, const Keyword& kw);
void handle_temperature(BuildState& s, const Keyword& kw);
/// At the end of a *HEAT TRANSFER or *COUPLED TEMPERATURE-DISPLACEMENT step: *TEMPERATURE on a
/// node with the temperature DOF 11 is an input error (use *BOUNDARY on DOF 11; Abaqus rule).
void check_predefined_temperatures(BuildState& s);
void handle_contact_interference(BuildState& s, const Keyword& kw);
///@}

/// @name Linear constraints (handlers_constraints.cpp)
///@{
void handle_equation(BuildState& s, const Keyword& kw);
void handle_transform(BuildState& s, const Keyword& kw);
/// *MPC, *KINEMATIC COUPLING, *COUPLING and its *KINEMATIC / *DISTRIBUTING (handlers_couplings.cpp)
void handle_mpc(BuildState& s, const Keyword& kw);
void handle_kinematic_coupling(BuildState& s, const Keyword& kw);
void handle_coupling(BuildState& s, const Keyword& kw);
void handle_kinematic(BuildState& s, const Keyword& kw);
void handle_distributing(BuildState& s, const Keyword& kw);
/// *TIE (handlers_tie.cpp)
void handle_tie(BuildState& s, const Keyword& kw);
/// Builds the rows of the constraints that waited for the complete model data (ties first).
void build_deferred_constraints(BuildState& s);
/// After the deck: a boundary condition on a constraint's dependent DOF is an error naming both
/// lines, unless the constraint yields to it (then one warning per constraint). (A DOF that is the
/// dependent DOF of two constraints is reported by fem/ConstraintSet, which knows the DOFs.)
void check_constraints(BuildState& s);
///@}

/// @name Output requests (handlers_output.cpp)
///@{
void handle_node_print(BuildState& s, const Keyword& kw);
void handle_el_print(BuildState& s, const Keyword& kw);
void handle_output(BuildState& s, const Keyword& kw);
void handle_node_output(BuildState& s, const Keyword& kw);
void handle_element_output(BuildState& s, const Keyword& kw);
/// *NODE FILE / *EL FILE: results written to job.frd (CalculiX's format, for cgx).
void handle_node_file(BuildState& s, const Keyword& kw);
void handle_el_file(BuildState& s, const Keyword& kw);
void handle_monitor(BuildState& s, const Keyword& kw);
/// *ENERGY PRINT, *CONTACT PRINT, *FILE FORMAT, *MONITOR, *PREPRINT and the other print and
/// results-file controls: accepted with one note per keyword (they do not change the analysis).
void handle_print_control(BuildState& s, const Keyword& kw);
/// *ENERGY OUTPUT, *CONTACT OUTPUT after *OUTPUT: history ones silently (already remarked), field
/// ones with a note.
void handle_output_suboption(BuildState& s, const Keyword& kw);
/// Fills VARIABLE=PRESELECT/ALL field requests once the step's procedure is known.
void resolve_preset_outputs(BuildState& s);
/// A step that is not *DYNAMIC and whose output requests (its own or carried over) name V, VR, A
/// or AR: one warning naming them; the writers leave them out.
void check_rate_outputs(BuildState& s, Step& st);
///@}

} // namespace gapfem::inp
