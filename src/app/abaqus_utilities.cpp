#include "app/abaqus_utilities.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "parallel/parallel.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <fmt/format.h>
#include <mutex>
#include <string_view>

namespace gapfem {

namespace {

struct JobNames {
  std::mutex mutex;
  std::string job = "gapfem";
  std::string dir = ".";
};

JobNames& job_names() {
  static JobNames names;
  return names;
}

/// A Fortran CHARACTER argument without its trailing blanks.
std::string_view fortran_string(const char* s, std::size_t length) {
  std::string_view v(s, length);
  const auto end = v.find_last_not_of(' ');
  return end == std::string_view::npos ? std::string_view() : v.substr(0, end + 1);
}

/// Fills a Fortran CHARACTER argument (blank padded); the length of what fits.
int fill_fortran_string(char* out, std::size_t length, const std::string& value) {
  const std::size_t n = std::min(length, value.size());
  std::memcpy(out, value.data(), n);
  std::memset(out + n, ' ', length - n);
  return static_cast<int>(n);
}

/// STRING with %I, %R and %S replaced by the next INTV, REALV and CHARV (8 characters each).
std::string substitute(std::string_view text, const int* intv, const double* realv,
                       const char* charv, std::size_t charv_length) {
  std::string out;
  int ni = 0, nr = 0, ns = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (text[i] == '%' && (next == 'I' || next == 'i') && intv) {
      out += fmt::format("{}", intv[ni++]);
    } else if (text[i] == '%' && (next == 'R' || next == 'r') && realv) {
      out += fmt::format("{:.7g}", realv[nr++]);
    } else if (text[i] == '%' && (next == 'S' || next == 's') && charv) {
      out += fortran_string(charv + ns++ * charv_length, charv_length);
    } else {
      out += text[i];
      continue;
    }
    ++i;
  }
  return out;
}

/// The tensor indices of shear component k: 12, 13, 23 (with one direct component 12, 13).
std::array<int, 2> shear_pair(int ndi, int k) {
  static constexpr std::array<std::array<int, 2>, 3> kPairs{{{0, 1}, {0, 2}, {1, 2}}};
  return kPairs[static_cast<std::size_t>(ndi == 1 && k == 1 ? 1 : k)];
}

int shear_count(int ndi, int nshr) {
  return std::clamp(nshr, 0, ndi == 1 ? 2 : 3);
}

/// The 3x3 tensor of Abaqus's component vector: NDI direct components, then NSHR shear ones;
/// engineering shear halved when `strain`.
Eigen::Matrix3d tensor_of(const double* s, int ndi, int nshr, bool strain) {
  Eigen::Matrix3d t = Eigen::Matrix3d::Zero();
  for (int i = 0; i < std::clamp(ndi, 0, 3); ++i) t(i, i) = s[i];
  for (int k = 0; k < shear_count(ndi, nshr); ++k) {
    const auto [a, b] = shear_pair(ndi, k);
    t(a, b) = t(b, a) = strain ? 0.5 * s[ndi + k] : s[ndi + k];
  }
  return t;
}

/// The component vector of a tensor (the inverse of tensor_of).
void components_of(const Eigen::Matrix3d& t, double* s, int ndi, int nshr, bool strain) {
  for (int i = 0; i < std::clamp(ndi, 0, 3); ++i) s[i] = t(i, i);
  for (int k = 0; k < shear_count(ndi, nshr); ++k) {
    const auto [a, b] = shear_pair(ndi, k);
    s[ndi + k] = strain ? 2.0 * t(a, b) : t(a, b);
  }
}

} // namespace

void set_abaqus_job(const std::string& job, const std::filesystem::path& output_dir) {
  auto& names = job_names();
  const std::lock_guard lock(names.mutex);
  names.job = job;
  std::error_code ec;
  const auto absolute = std::filesystem::absolute(output_dir, ec);
  names.dir = (ec ? output_dir : absolute).lexically_normal().string();
  while (names.dir.size() > 1 && names.dir.back() == '/') names.dir.pop_back();
}

} // namespace gapfem

using gapfem::AnalysisError;

extern "C" {

/// CALL XIT: the analysis stops; what converged is written.
void xit_() {
  throw AnalysisError("the user code called XIT, which ends the analysis (results up to the last "
                      "converged increment are written); see the user code's messages above for "
                      "why");
}

/// CALL STDB_ABQERR(LOP, STRING, INTV, REALV, CHARV): 1 information, -1 warning, -2 and -3 an
/// error that ends the analysis.
void stdb_abqerr_(const int* lop, const char* string, const int* intv, const double* realv,
                  const char* charv, std::size_t string_length, std::size_t charv_length) {
  const std::string text = gapfem::substitute(gapfem::fortran_string(string, string_length), intv,
                                              realv, charv, charv_length);
  const int kind = lop ? *lop : 1;
  if (kind == 1) {
    gapfem::log::info("user code: {}", text);
  } else if (kind == -1) {
    gapfem::log::warning("user code: {}", text);
  } else { // the message is the analysis's error
    throw AnalysisError(fmt::format("the user code reported an error (STDB_ABQERR with LOP={}): "
                                    "{}; the analysis stops",
                                    kind, text));
  }
}

/// CALL GETJOBNAME(JOBNAME, LENJOBNAME)
void getjobname_(char* name, int* length, std::size_t name_length) {
  auto& names = gapfem::job_names();
  const std::lock_guard lock(names.mutex);
  *length = gapfem::fill_fortran_string(name, name_length, names.job);
}

/// CALL GETOUTDIR(OUTDIR, LENOUTDIR): the absolute output folder, without a trailing slash.
void getoutdir_(char* dir, int* length, std::size_t dir_length) {
  auto& names = gapfem::job_names();
  const std::lock_guard lock(names.mutex);
  *length = gapfem::fill_fortran_string(dir, dir_length, names.dir);
}

/// CALL GETNUMCPUS(NUMPROCESSES): the number of MPI processes.
void getnumcpus_(int* count) {
  *count = gapfem::parallel::size();
}

/// CALL GETRANK(KPROCESSNUM): this process's rank, from 0.
void getrank_(int* rank) {
  *rank = gapfem::parallel::rank();
}

/// ID = GET_THREAD_ID(): 0, gapfem calls user code from one thread at a time.
int get_thread_id_() {
  return 0;
}

/// CALL MUTEXINIT(ID), MUTEXLOCK(ID), MUTEXUNLOCK(ID): nothing to do, gapfem already calls user
/// code from one thread at a time.
void mutexinit_(const int*) {}
void mutexlock_(const int*) {}
void mutexunlock_(const int*) {}

/// CALL SINV(STRESS, SINV1, SINV2, NDI, NSHR): trace / 3 and the Mises stress.
void sinv_(const double* stress, double* sinv1, double* sinv2, const int* ndi, const int* nshr) {
  const Eigen::Matrix3d t = gapfem::tensor_of(stress, *ndi, *nshr, false);
  const double mean = t.trace() / 3.0;
  const Eigen::Matrix3d dev = t - mean * Eigen::Matrix3d::Identity();
  *sinv1 = mean;
  *sinv2 = std::sqrt(1.5 * dev.cwiseProduct(dev).sum());
}

/// CALL SPRIND(S, PS, AN, LSTR, NDI, NSHR): principal values PS(I) and their directions
/// AN(I, 1:3) (LSTR = 2: S holds strains with engineering shear).
void sprind_(const double* s, double* ps, double* an, const int* lstr, const int* ndi,
             const int* nshr) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(
      gapfem::tensor_of(s, *ndi, *nshr, *lstr == 2));
  for (int i = 0; i < 3; ++i) {
    ps[i] = eig.eigenvalues()(i);
    if (an)
      for (int j = 0; j < 3; ++j) an[i + 3 * j] = eig.eigenvectors()(j, i);
  }
}

/// CALL SPRINC(S, PS, LSTR, NDI, NSHR): the principal values.
void sprinc_(const double* s, double* ps, const int* lstr, const int* ndi, const int* nshr) {
  sprind_(s, ps, nullptr, lstr, ndi, nshr);
}

/// CALL ROTSIG(S, R, SPRIME, LSTR, NDI, NSHR): SPRIME = R S R^T (LSTR = 2: engineering shear).
void rotsig_(const double* s, const double* r, double* sprime, const int* lstr, const int* ndi,
             const int* nshr) {
  const Eigen::Map<const Eigen::Matrix3d> rotation(r); // column-major as Fortran's R(3,3)
  const bool strain = *lstr == 2;
  const Eigen::Matrix3d t = gapfem::tensor_of(s, *ndi, *nshr, strain);
  gapfem::components_of(rotation * t * rotation.transpose(), sprime, *ndi, *nshr, strain);
}

} // extern "C"
