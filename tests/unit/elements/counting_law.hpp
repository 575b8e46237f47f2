#pragma once
// A toy solid law for the tests of the material-point seam (elements/material/solid_law.hpp):
// "linear elastic with a state counter". Registered (counting_law.cpp, one register_solid_law
// call) for materials named COUNTING; the continuum (solid/solid_law_test.cpp), shell and beam
// (structural/shell_section_law_test.cpp, structural/beam_section_law_test.cpp) kernels run it
// through their section/integration points.
//   - its stress is the built-in elastic law's; it hands its tangent over as a full Voigt matrix
//     and says it is not the built-in isotropic elastic law, so kernels take their general path;
//   - one history slot per point counts the commits the point has seen.
#include "elements/material/solid_law.hpp"

#include <atomic>

namespace gapfem::test {

/// Largest committed counter any COUNTING point has been evaluated from (the restart test).
extern std::atomic<int> g_most_commits_seen;

/// True once the toy law is registered (it is at static initialisation; the call keeps the
/// registration's object file linked).
bool counting_law_registered();

} // namespace gapfem::test
