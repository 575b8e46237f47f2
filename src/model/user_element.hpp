#pragma once
/// @file user_element.hpp
/// Element types that the deck defines: user elements (*USER ELEMENT, Un) with a constant matrix
/// (LINEAR, *MATRIX) or a subroutine (Abaqus UEL in Fortran/C, or a gapfem C++ plugin), and their
/// properties (*UEL PROPERTY). docs/user-elements.md.
#include "common/error.hpp"
#include "common/types.hpp"

#include <string>
#include <vector>

namespace gapfem {

/// *USER ELEMENT, TYPE=Un.
struct UserElementType {
  std::string name; ///< "U1"
  int number = 0;   ///< n of Un (JTYPE of the UEL)
  int n_nodes = 0;  ///< NODES=
  int n_coords = 0; ///< COORDINATES= (MCRD): coordinates per node passed to the element
  bool linear = false;
  bool unsymmetric = false; ///< UNSYMM: the matrices are given in full (and the UEL's AMATRX)
  int n_properties = 0;     ///< PROPERTIES= (real properties of *UEL PROPERTY)
  int n_int_properties = 0; ///< I PROPERTIES= (integer properties)
  int n_variables = 0;      ///< VARIABLES= (solution-dependent state variables, SVARS)
  /// The Abaqus DOF numbers (1-6, 11) active at each node position, in the order of the element's
  /// vectors (node by node, each node's DOFs ascending as listed).
  std::vector<std::vector<int>> node_dofs;
  /// LINEAR: *MATRIX, TYPE=STIFFNESS and TYPE=MASS, full n_dofs x n_dofs row-major (empty: none)
  std::vector<double> stiffness, mass;
  SourceLocation loc;
  SourceLocation stiffness_loc; ///< its *MATRIX, TYPE=STIFFNESS (for messages)

  int n_dofs() const {
    int n = 0;
    for (const auto& d : node_dofs) n += static_cast<int>(d.size());
    return n;
  }
};

/// *UEL PROPERTY, ELSET=: the real and integer properties of the user elements of a set (the data
/// lines hold the PROPERTIES reals, then the I PROPERTIES integers of the type).
struct UelProperty {
  std::string elset;
  int type = -1;                   ///< index into Model::user_elements (bound with the elements)
  std::vector<double> properties;  ///< PROPS (at binding: all values of the data lines)
  std::vector<int> int_properties; ///< JPROPS
  SourceLocation loc;
};

} // namespace gapfem
