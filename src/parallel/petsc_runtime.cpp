// parallel.hpp with PETSc and MPI.
#include "parallel/petsc_runtime.hpp"

#include "parallel/parallel.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <petscsys.h>
#ifdef GAPFEM_HAVE_SLEPC
#include <slepcsys.h>
#endif
#include <stdexcept>
#include <thread>

// Open MPI keeps what its runtime allocates while it starts and stops (in components it loads and
// unloads itself, so LeakSanitizer cannot even name them): the sanitized build does not count it
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GAPFEM_LSAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define GAPFEM_LSAN 1
#endif
#ifdef GAPFEM_LSAN
#include <sanitizer/lsan_interface.h>
#endif

namespace gapfem::parallel {

namespace {
/// LeakSanitizer ignores what is allocated while one of these lives (nothing without it).
struct MpiRuntimeAllocations {
#ifdef GAPFEM_LSAN
  MpiRuntimeAllocations() {
    __lsan_disable();
  }
  ~MpiRuntimeAllocations() {
    __lsan_enable();
  }
#endif
};
constexpr int kFailureWaitSeconds = 10;
bool g_started = false;
int g_rank = 0, g_size = 1;
/// A communicator of its own for finish(): its barrier never meets a collective of the solvers
MPI_Comm g_exit_comm = MPI_COMM_NULL;
void finalize() {
  [[maybe_unused]] const MpiRuntimeAllocations runtime;
#ifdef GAPFEM_HAVE_SLEPC
  if (g_started) SlepcFinalize(); // and PETSc, which SlepcInitialize started
#else
  if (g_started) PetscFinalize();
#endif
  g_started = false;
}
} // namespace

bool available() {
  return true;
}
bool started() {
  return g_started;
}
int rank() {
  return g_rank;
}
int size() {
  return g_size;
}

void start(const std::vector<std::string>& petsc_options) {
  if (g_started) return;
  [[maybe_unused]] const MpiRuntimeAllocations runtime;
  // PETSc reads its options from an argv: the program name, ours, then the user's (which win)
  static std::vector<std::string> words;
  words = {"gapfem", "-no_signal_handler"};
  words.insert(words.end(), petsc_options.begin(), petsc_options.end());
  static std::vector<char*> args;
  args.clear();
  for (std::string& w : words) args.push_back(w.data());
  args.push_back(nullptr);
  int argc = static_cast<int>(words.size());
  char** argv = args.data();
#ifdef GAPFEM_HAVE_SLEPC
  if (SlepcInitialize(&argc, &argv, nullptr, nullptr) != 0) // SLEPc starts PETSc
    throw std::runtime_error("PETSc could not be started (SlepcInitialize failed)");
#else
  if (PetscInitialize(&argc, &argv, nullptr, nullptr) != 0)
    throw std::runtime_error("PETSc could not be started (PetscInitialize failed)");
#endif
  // errors come back as codes, which petsc_check turns into exceptions with a sentence
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  g_started = true;
  MPI_Comm_rank(PETSC_COMM_WORLD, &g_rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &g_size);
  MPI_Comm_dup(PETSC_COMM_WORLD, &g_exit_comm);
  std::atexit(finalize);
}

void abort_job(int exit_code) {
  if (g_started && g_size > 1) MPI_Abort(PETSC_COMM_WORLD, exit_code);
}

int finish(int exit_code, const std::string& error) {
  if (!g_started || g_size == 1) return exit_code;
  [[maybe_unused]] const MpiRuntimeAllocations runtime; // the non-blocking barrier's schedule
  MPI_Request request{};
  MPI_Ibarrier(g_exit_comm, &request);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(kFailureWaitSeconds);
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return exit_code; // every rank is here
    if (exit_code != 0 && std::chrono::steady_clock::now() > until) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  // this rank failed alone: the others are still computing, or waiting for it
  if (g_rank > 0 && !error.empty())
    std::fprintf(stderr, "gapfem (rank %d): %s\n", g_rank, error.c_str());
  std::fprintf(stderr, "gapfem: rank %d of %d failed; stopping the whole job\n", g_rank, g_size);
  std::fflush(stderr);
  MPI_Abort(PETSC_COMM_WORLD, exit_code);
  return exit_code;
}

double max_over_ranks(double v) {
  if (!g_started || g_size == 1) return v;
  double out = v;
  MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  return out;
}
int max_over_ranks(int v) {
  if (!g_started || g_size == 1) return v;
  int out = v;
  MPI_Allreduce(&v, &out, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  return out;
}
void barrier() {
  if (g_started && g_size > 1) MPI_Barrier(PETSC_COMM_WORLD);
}

void petsc_check(int code, const char* what) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(static_cast<PetscErrorCode>(code), &text, nullptr);
  throw std::runtime_error(
      fmt::format("PETSc failed in {}: {} (error {})", what, text ? text : "unknown error", code));
}

} // namespace gapfem::parallel
