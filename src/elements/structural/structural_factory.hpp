#pragma once
/// @file structural_factory.hpp
/// Property and material checks shared by the spring, truss and beam factories. Each throws an
/// InputError that names the deck line to fix.
#include "elements/element_kernel.hpp"
#include "model/material.hpp"
#include "model/section.hpp"

#include <string>

namespace gapfem::structural {

/// The *SOLID SECTION of a truss block (InputError if the block has another or no property).
const SolidSection& solid_section_of(const KernelContext& ctx);
/// The *BEAM SECTION of a beam block (InputError if the block has another or no property).
const BeamSection& beam_section_of(const KernelContext& ctx);
/// The material a section refers to; it must have *ELASTIC.
const Material& section_material(const Model& model, int material, const SourceLocation& loc,
                                 const std::string& entity);
/// InputError at the *DLOAD line when a GRAV load of any step acts on an element of the block
/// whose material has no *DENSITY.
void check_density_for_gravity(const KernelContext& ctx, const Material& material);

} // namespace gapfem::structural
