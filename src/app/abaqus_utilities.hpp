#pragma once
/// @file abaqus_utilities.hpp
/// The Abaqus/Standard utility routines a UEL (or any user code loaded with --user) may call:
/// XIT, STDB_ABQERR, GETJOBNAME, GETOUTDIR, GETNUMCPUS, GETRANK, GET_THREAD_ID, MUTEXINIT,
/// MUTEXLOCK, MUTEXUNLOCK, SINV, SPRINC, SPRIND and ROTSIG, with Fortran's calling convention
/// (lower case, trailing underscore, every argument by reference, a character argument's length
/// appended by value). The gapfem executable exports them (src/app/abaqus_utilities.list) so that a
/// user library finds them when it is loaded. Their meaning: docs/user-elements.md, "Utility
/// routines".
#include <filesystem>
#include <string>

namespace gapfem {

/// The job whose name and output folder GETJOBNAME and GETOUTDIR return.
void set_abaqus_job(const std::string& job, const std::filesystem::path& output_dir);

} // namespace gapfem
