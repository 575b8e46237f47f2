#pragma once
/// @file user_code_loader.hpp
/// `gapfem --user FILE`: the user's element code compiled with the Debian toolchain (gfortran for
/// .f/.for/.f77 (fixed form) and .f90/.f95 (free form), gcc for .c, g++ for .cpp/.cc/.cxx) into a
/// shared library in a scratch folder, or a ready .so, loaded and checked for its entry points: an
/// Abaqus UEL subroutine or a gapfem element plugin (docs/user-elements.md).
#include <filesystem>
#include <memory>

namespace gapfem {

class UserCode;

/// Compiles (when needed) and loads `source`; `scratch` is a folder gapfem may create and fill
/// (removed again when the library is loaded). InputError, naming the file, for a source that does
/// not compile (with the compiler's messages), a library that cannot be loaded, one without a UEL
/// or plugin entry, or a plugin of another ABI version.
std::shared_ptr<const UserCode> load_user_code(const std::filesystem::path& source,
                                               const std::filesystem::path& scratch);

/// The ABA_PARAM.INC gapfem provides to UEL sources (Abaqus's: implicit double precision).
extern const char* const kAbaParamInc;

} // namespace gapfem
