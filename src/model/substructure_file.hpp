#pragma once
/// @file substructure_file.hpp
/// gapfem's substructure library file, `<library>_<Zn>.sub` (docs/substructures.md): the reduced
/// stiffness of one substructure over its retained DOFs, and the recovery data (the internal part
/// of the stiffness) with which a usage analysis recovers the internal displacements.
///
/// Layout, all numbers in the machine's byte order (common/archive.hpp):
///   "GAPFEM-SUBSTRUCTURE\n", format version (u32), checksum of what follows (u64), then
///   type name, generation deck path, generation job name, generation model fingerprint (u64),
///   retained nodes: labels (i64), coordinates (3 f64 each), DOFs per node (lists of i32),
///   largest dimension (f64), reduced stiffness (n x n f64, row-major), mass flag (u8) and,
///   when set, the reduced mass (n x n f64, row-major; format version 2 on),
///   recovery flag (u8) and, when set: internal DOFs (node label i64, Abaqus DOF i32 each),
///   K_II and K_IR in compressed rows (row pointers i64, columns i32, values f64).
#include "model/substructure.hpp"

#include <cstdint>
#include <filesystem>
#include <stdexcept>

namespace gapfem {

/// A substructure file that cannot be read (missing, damaged, of another version).
class SubstructureFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// K_II and K_IR of a substructure, over its internal DOFs (rows) and internal / retained DOFs
/// (columns): u_I = -K_II^-1 K_IR u_R.
struct SubstructureRecovery {
  std::vector<Label> internal_node; ///< per internal DOF: its node's label at generation
  std::vector<int> internal_dof;    ///< ... and its Abaqus DOF number
  std::vector<std::int64_t> ii_ptr, ir_ptr;
  std::vector<std::int32_t> ii_col, ir_col;
  std::vector<double> ii_val, ir_val;
};

struct SubstructureLibrary {
  SubstructureType type;
  std::string deck; ///< the generation deck (absolute path)
  std::string job;
  std::uint64_t fingerprint = 0; ///< of the generation model (mesh and elements)
  bool has_recovery = false;
  SubstructureRecovery recovery;
};

void write_substructure_file(const std::filesystem::path& file, const SubstructureLibrary& lib);
/// Reads a library file; the recovery data only when `recovery` is true.
SubstructureLibrary read_substructure_file(const std::filesystem::path& file, bool recovery);

} // namespace gapfem
