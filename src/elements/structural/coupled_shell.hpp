#pragma once
/// @file coupled_shell.hpp
/// The coupled temperature-displacement shells S3RT, S4T, S4RT and S8RT: node DOFs 1-6 and the
/// temperatures 11, 12, … 10 + n at the n section points (SNEG to SPOS). The mechanics is the
/// stress/displacement shell of the same shape (S3R, S4, S4R, S8R: shell.hpp) whose thermal
/// strain comes from those temperatures: per node their mean through the thickness and the
/// gradient of their least-squares line, with Simpson's weights (the membrane and bending thermal
/// strains then integrate the section points' temperatures as Simpson's rule does); heat
/// conduction, capacity and thermal loads are those of the heat-transfer shell of the shape (DS3,
/// DS4, DS8: heat_shell.hpp). docs/theory/thermal.md.
///
/// Tangent blocks: K_uu the shell's stiffness, K_uT = d r_u / d T (thermal strain and
/// temperature-dependent elasticity), K_Tu = 0 (conduction on the reference geometry, no
/// thermoelastic heating, as the coupled continuum elements), K_TT conduction and capacity.
#include "elements/element_kernel.hpp"

#include <memory>

namespace gapfem {

std::unique_ptr<ElementKernel> make_coupled_shell_kernel(const KernelContext& ctx);

} // namespace gapfem
