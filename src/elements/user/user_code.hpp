#pragma once
/// @file user_code.hpp
/// The user's compiled element code, as the kernels call it: an Abaqus UEL subroutine (Fortran,
/// or C with Fortran's calling convention) or a gapfem element plugin (include/gapfem/plugin.hpp).
/// The job compiles and loads it (app/user_code_loader); the model holds it (Model::user_code).
#include <gapfem/plugin.hpp>
#include <mutex>
#include <string>

namespace gapfem {

/// SUBROUTINE UEL(RHS, AMATRX, SVARS, ENERGY, NDOFEL, NRHS, NSVARS, PROPS, NPROPS, COORDS, MCRD,
/// NNODE, U, DU, V, A, JTYPE, TIME, DTIME, KSTEP, KINC, JELEM, PARAMS, NDLOAD, JDLTYP, ADLMAG,
/// PREDEF, NPREDF, LFLAGS, MLVARX, DDLMAG, MDLOAD, PNEWDT, JPROPS, NJPROP, PERIOD): every argument
/// by reference, arrays column-major, INTEGER = int (implicit real*8 for the rest, ABA_PARAM.INC).
using UelFunction = void (*)(double* rhs, double* amatrx, double* svars, double* energy,
                             int* ndofel, int* nrhs, int* nsvars, double* props, int* nprops,
                             double* coords, int* mcrd, int* nnode, double* u, double* du,
                             double* v, double* a, int* jtype, double* time, double* dtime,
                             int* kstep, int* kinc, int* jelem, double* params, int* ndload,
                             int* jdltyp, double* adlmag, double* predef, int* npredf, int* lflags,
                             int* mlvarx, double* ddlmag, int* mdload, double* pnewdt, int* jprops,
                             int* njprop, double* period);

class UserCode {
 public:
  UserCode(UelFunction uel_fn, gapfem_element_fn element_fn, std::string source)
      : _uel(uel_fn), _element(element_fn), _source(std::move(source)) {}
  virtual ~UserCode() = default;
  UelFunction uel() const { return _uel; }              ///< null when the code has no UEL
  gapfem_element_fn plugin() const { return _element; } ///< null when it is no plugin
  const std::string& source() const { return _source; } ///< the file the user gave
  /// Calls into the code are serialised (Fortran SAVE variables and COMMON blocks are shared).
  std::mutex& mutex() const { return _mutex; }

 private:
  UelFunction _uel;
  gapfem_element_fn _element;
  std::string _source;
  mutable std::mutex _mutex;
};

} // namespace gapfem
