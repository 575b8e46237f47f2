#pragma once
/// @file orientation.hpp
/// *ORIENTATION as read (Abaqus Keywords Reference, *ORIENTATION,
/// https://abaqus-docs.mit.edu/2017/English/SIMACAEKEYRefMap/simakey-r-orientation.htm): kept by
/// name while the deck is read and turned into axes where something refers to it. Today *SPRING
/// and *DASHPOT, ORIENTATION= use it (SPRING1/2, DASHPOT1/2: the DOFs of the data line are then
/// local), *ROTARY INERTIA (its tensor in the local axes) and *COUPLING (its DOFs local); the other
/// keywords that take ORIENTATION= still refuse the parameter. An orientation nothing refers to
/// changes nothing and is only read.
#include "common/error.hpp"
#include "common/types.hpp"
#include "model/section.hpp"

#include <array>
#include <optional>
#include <string>

namespace gapfem::inp {

struct BuildState;

/// One *ORIENTATION as given in the deck.
struct OrientationDef {
  /// SYSTEM=: RECTANGULAR (default), CYLINDRICAL, SPHERICAL, Z RECTANGULAR, USER
  enum class System : std::uint8_t { Rectangular, Cylindrical, Spherical, ZRectangular, User };
  /// DEFINITION=: COORDINATES (default), NODES (global node labels), OFFSET TO NODES
  enum class Definition : std::uint8_t { Coordinates, Nodes, OffsetToNodes };

  std::string name;
  System system = System::Rectangular;
  Definition definition = Definition::Coordinates;
  std::array<Vec3, 3> points{};      ///< COORDINATES: points a, b and the origin c (placed)
  std::array<Label, 3> nodes{};      ///< NODES: the node keys of a, b, c (resolved at use)
  std::array<long long, 3> labels{}; ///< NODES: the numbers as written (for messages)
  bool has_origin = false;           ///< c given (else the global origin)
  int rotation_axis = 1; ///< second data line: the local direction of the additional rotation
  double rotation = 0.0; ///< the additional rotation in degrees (0: none)
  SourceLocation loc;
};

/// The local axes of a rectangular orientation from its points a, b, c: local 1 along c→a, local
/// 3 normal to the plane of c, a, b (right-handed), local 2 = 3 × 1; then the additional rotation
/// turns the two axes normal to `rotation_axis` by `rotation` degrees. No value when the points
/// span no plane (a = c, or b on the line c-a).
std::optional<std::array<Vec3, 3>> rectangular_axes(const Vec3& a, const Vec3& b, const Vec3& c,
                                                    int rotation_axis, double rotation_deg);

/// *SPRING / *DASHPOT, ORIENTATION=: checks that `type` takes one (SPRING1/2, DASHPOT1/2; the
/// Keywords Reference gives ORIENTATION for those only), that it is defined and rectangular, and
/// sets `sec.axes`; reports what is wrong through `s` (one error) and leaves `axes` empty then.
void resolve_spring_orientation(BuildState& s, SpringSection& sec, ElementType type);

/// The local axes (e1, e2, e3) of an orientation at the point x: a rectangular system's are the
/// same everywhere; a cylindrical system's are radial, tangential and axial about the axis from
/// its point a to its point b (Abaqus, *ORIENTATION, SYSTEM=CYLINDRICAL). No value, with the
/// sentence in `why`, for the other systems, OFFSET TO NODES, undefined nodes, points that span no
/// plane, or x on a cylindrical system's axis (then `on_axis`, when given, is set).
std::optional<std::array<Vec3, 3>> orientation_axes_at(const BuildState& s, const OrientationDef& o,
                                                       const Vec3& x, std::string& why,
                                                       bool* on_axis = nullptr);

/// *ROTARY INERTIA, ORIENTATION=: the tensors given in the orientation's axes turned to global
/// ones, I_global = R I R^T (R's columns the local axes); one error per orientation that is missing
/// or not rectangular.
void resolve_rotary_orientations(BuildState& s);

} // namespace gapfem::inp
