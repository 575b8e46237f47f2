#pragma once
/// @file scoped_env.hpp
/// Sets an environment variable for a scope (solvers and kernels read their switches when made).
#include <cstdlib>

namespace gapfem::test {

struct ScopedEnv {
  ScopedEnv(const char* name, const char* value) : _name(name) { ::setenv(name, value, 1); }
  ~ScopedEnv() { ::unsetenv(_name); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;
  const char* _name;
};

} // namespace gapfem::test
