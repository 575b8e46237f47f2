#pragma once
/// @file stabilization.hpp
/// Abaqus/Standard's automatic stabilization of static steps (*STATIC, STABILIZE): viscous forces
/// f_v = c M* (u - u_start) / dt, M* the lumped mass matrix of unit density, hold parts whose
/// support is not there yet (a body on open gaps until they close) and damp local instabilities.
/// The damping factor c comes from the dissipated energy fraction f: the viscous energy of an
/// increment dt0 over the elastic energy of the same increment, both estimated with the diagonal
/// of the stiffness and of M*, c = f dt0 sum(K_ii) / (2 sum(M*_ii)) (docs/theory/stabilization.md);
/// with ALLSDTOL the factor adapts so that ALLSD / ALLIE stays below it. In the step problem the
/// viscous forces are a damping operator c M* whose velocities come from a backward Euler
/// integrator in the step's time (StepProblem::add_stabilization, solver/time_integrator.hpp).
#include "fem/assembler.hpp"

#include <vector>

namespace gapfem {

struct Stabilization;

/// M* per slot: the equivalent nodal load of a unit body force (per volume) in the slot's
/// direction, over every element that carries body forces (continua, trusses, beams); 0 at other
/// slots (rotations, temperatures, nodes of gaps and springs only).
std::vector<double> unit_density_mass(Discretization& disc, Assembler& assembler,
                                      const FieldView& fields, const StepContext& ctx);

/// The initial damping factor of a step: FACTOR when given, else from the dissipated energy
/// fraction with the increment dt0, the mass M* and the diagonal stiffness of the non-gap elements.
double initial_stabilization_factor(const Stabilization& spec, double dt0,
                                    const std::vector<double>& mass,
                                    const std::vector<double>& stiffness_diagonal);

/// Adaptive stabilization after an accepted increment: the new factor keeping ALLSD / ALLIE below
/// ALLSDTOL (unchanged when ALLSDTOL is 0 or the ratio is within it).
double adapted_stabilization_factor(const Stabilization& spec, double c, double allsd,
                                    double allie);

} // namespace gapfem
