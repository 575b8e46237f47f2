// gapfem: run an Abaqus input deck.  Usage: gapfem [options] job.inp
#include "app/check.hpp"
#include "app/environment.hpp"
#include "app/job.hpp"
#include "common/log.hpp"
#include "linalg/blas_workspace.hpp"
#include "linalg/constrained_solver.hpp"
#include "parallel/parallel.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <sys/resource.h>
#include <unistd.h>

namespace {

/// Under an address-space limit (ulimit -v, as batch systems set it) OpenBLAS's worker threads
/// retry a failed buffer allocation forever, inside a factorisation or in the library's shutdown
/// at exit (docs/robustness.md, "Memory limits"). The threads start when the library loads, before
/// main, so the program runs itself again with one BLAS thread (OPENBLAS_NUM_THREADS=1) before
/// anything else; a thread count the user sets is kept. Nothing happens without such a limit.
void one_blas_thread_under_address_limit(char** argv) {
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) != 0 || as.rlim_cur == RLIM_INFINITY) return;
  if (std::getenv("OPENBLAS_NUM_THREADS") != nullptr) return; // the user's (or ours, run again)
  if (setenv("OPENBLAS_NUM_THREADS", "1", 1) != 0) return;
  execv("/proc/self/exe", argv); // returns only when it failed: carry on as we are
  unsetenv("OPENBLAS_NUM_THREADS");
}

/// `gapfem check deck.inp`: validate and summarise without solving (Abaqus's datacheck).
int check_main(int argc, char** argv) {
  CLI::App app{"gapfem check: read and validate a deck, print a model summary, solve nothing"};
  gapfem::JobOptions options;
  std::string deck;
  app.add_option("deck", deck, "Abaqus input deck (job.inp)")->required();
  app.add_flag("--ignore-unknown", options.ignore_unknown,
               "report unknown keywords and parameters as warnings instead of errors");
  app.add_flag("-q,--quiet", options.quiet, "print errors only");
  app.add_option(
      "--user", options.user_code,
      "the user subroutine of the deck's user elements, compiled and loaded as for a run");
  app.add_flag("--time-factorization", options.time_factorization,
               "also factorise step 1's stiffness once and print the time (the unit of "
               "docs/performance.md's limit ratio)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : gapfem::kExitInputError;
  }
  options.deck = deck;
  try {
    return gapfem::check_job(options).exit_code;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gapfem: internal error: %s\n", e.what());
    return gapfem::kExitInternal;
  }
}

/// The backend --solver names (from the registry: linalg's and parallel's backends), or the
/// default: cholmod on one process, mumps under mpirun. Returns false (with a message) for a choice
/// this build or this run cannot honour.
bool choose_solver(const std::string& name, gapfem::JobOptions& options) {
  const bool ranks = gapfem::parallel::size() > 1;
  options.solver = name == "auto" ? (ranks ? "mumps" : "cholmod") : name;
  const gapfem::SolverBackend* b = gapfem::find_solver_backend(options.solver);
  if (!b) {
    std::fprintf(stderr, "gapfem: there is no solver '%s'; this gapfem has: %s\n", name.c_str(),
                 fmt::format("{}", fmt::join(gapfem::solver_backend_names(), ", ")).c_str());
    return false;
  }
  if (!b->unavailable.empty()) {
    std::fprintf(stderr, "gapfem: --solver %s: %s\n", options.solver.c_str(),
                 b->unavailable.c_str());
    return false;
  }
  if (ranks && b->one_process) {
    std::fprintf(stderr,
                 "gapfem: --solver %s solves on one process, but mpirun started %d: use "
                 "--solver mumps or --solver iterative\n",
                 options.solver.c_str(), gapfem::parallel::size());
    return false;
  }
  return true;
}

/// Start MPI and PETSc when mpirun started us or a PETSc solver is asked for; false (with a
/// message) when this build cannot.
bool start_processes(const std::vector<std::string>& petsc_options, bool petsc_solver) {
  if (!gapfem::launched_by_mpirun() && !petsc_solver && petsc_options.empty()) return true;
  if (!gapfem::parallel::available()) {
    std::fprintf(stderr, "gapfem: this gapfem was built without PETSc, so it cannot run under "
                         "mpirun nor take PETSc options: install Debian's petsc-dev "
                         "(scripts/install-deps.sh) and build again\n");
    return false;
  }
  gapfem::parallel::start(petsc_options);
  return true;
}

} // namespace

int main(int argc, char** argv) {
  one_blas_thread_under_address_limit(argv);
  if (const auto no_room = gapfem::reserve_blas_workspace()) {
    std::fprintf(stderr, "error: %s\n", no_room->c_str());
    return gapfem::kExitNoConvergence;
  }
  if (argc >= 2 && std::strcmp(argv[1], "check") == 0) return check_main(argc - 1, argv + 1);
  // PETSc's own options (-ksp_rtol 1e-12, -inner_pc_type hypre, ...) are not gapfem's
  const std::vector<std::string> petsc_options = gapfem::parallel::take_petsc_options(argc, argv);
  CLI::App app{"gapfem: nonlinear finite elements with Abaqus gap contact elements\n"
               "  gapfem [options] job.inp   run the analysis\n"
               "  gapfem check job.inp       validate the deck and summarise the model, no solve"};
  gapfem::JobOptions options;
  std::string deck;
  bool no_vtu = false;
  app.add_option("deck", deck, "Abaqus input deck (job.inp)")->required();
  app.add_option("-o,--output-dir", options.output_dir, "directory for job.dat, job.sta, …");
  app.add_option("-j,--job", options.job_name, "job name (default: the deck's stem)");
  app.add_flag("--ignore-unknown", options.ignore_unknown,
               "report unknown keywords and parameters as warnings instead of errors");
  app.add_flag("--no-vtu", no_vtu, "do not write ParaView files");
  app.add_option("--report-gaps", options.report_gaps,
                 "gaps job.report.html plots: element labels or element sets, comma separated "
                 "(default: the most loaded)")
      ->delimiter(',');
  app.add_flag("-q,--quiet", options.quiet, "no progress lines on the terminal");
  app.add_flag("-v,--verbose", options.verbose,
               "debug messages: every Newton iteration and the linear solver's decisions");
  std::string reuse = "auto";
  app.add_option("--factor-reuse", reuse,
                 "reuse a factorisation across Newton iterations and increments: auto (when the "
                 "measured times say it pays), always, never")
      ->check(CLI::IsMember({"auto", "always", "never"}));
  app.add_option("--user", options.user_code,
                 "the user subroutine of the deck's user elements (Abaqus's user=): a UEL in "
                 "Fortran (.f, .for, .f90) or C (.c), a gapfem element plugin in C++ (.cpp), or a "
                 "compiled .so; sources are compiled with gfortran, gcc or g++");
  app.add_flag("--restart", options.restart,
               "continue this job from the last restart record in its job.res (*RESTART, WRITE); a "
               "restart deck also needs the --oldjob it ran with");
  app.add_option("--oldjob", options.oldjob,
                 "the job a deck with *RESTART, READ continues (Abaqus's oldjob=): a job name or "
                 "the path of its .res file");
  std::string solver = "auto";
  gapfem::parallel::register_backends(); // the registry's names are --solver's choices
  std::vector<std::string> solvers{"auto"};
  for (const std::string& name : gapfem::solver_backend_names()) solvers.push_back(name);
  app.add_option("--solver", solver,
                 "the linear solver: cholmod (one process; the default), mumps (PETSc + MUMPS, "
                 "direct, any number of processes; the default under mpirun) or iterative "
                 "(PETSc: GMRES with an AMG block preconditioner, for the largest models); PETSc "
                 "options such as -ksp_rtol 1e-12 or -inner_pc_type hypre are passed to PETSc")
      ->check(CLI::IsMember(solvers));
  app.set_version_flag("--version", std::string("gapfem ") + GAPFEM_VERSION);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : gapfem::kExitInputError;
  }
  options.deck = deck;
  options.write_vtu = !no_vtu;
  options.keep_frames = false;
  options.keep_step_ends = false;
  options.factor_reuse = reuse == "always"  ? gapfem::FactorReuse::Always
                         : reuse == "never" ? gapfem::FactorReuse::Never
                                            : gapfem::FactorReuse::Auto;
  int code = gapfem::kExitOk;
  std::string error;
  try {
    const gapfem::SolverBackend* asked = gapfem::find_solver_backend(solver);
    if (!start_processes(petsc_options, asked && asked->needs_processes))
      return gapfem::kExitInputError;
    if (!choose_solver(solver, options)) {
      code = gapfem::kExitInputError;
    } else {
      // rank 0 alone writes the files and the terminal (docs/parallel.md)
      if (gapfem::parallel::rank() > 0) {
        options.write_files = false;
        options.silent = true;
      }
      const gapfem::JobResult result = gapfem::run_job(options);
      code = result.exit_code;
      error = result.error;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gapfem: internal error: %s\n", e.what());
    code = gapfem::kExitInternal;
    error = e.what();
  }
  // a rank that failed alone must not leave the others waiting: finish() ends the whole job
  return gapfem::parallel::finish(code, error);
}
