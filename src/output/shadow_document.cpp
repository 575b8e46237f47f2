#include "output/shadow_document.hpp"

#include "common/error.hpp"
#include "common/safe_file.hpp"
#include "output/output_file.hpp"

#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <unistd.h>

namespace gapfem::output {

namespace {

std::filesystem::path with_suffix(const std::filesystem::path& p, const char* suffix) {
  std::filesystem::path out = p;
  out += suffix;
  return out;
}

} // namespace

std::filesystem::path ShadowDocument::shadow(int k) const {
  return with_suffix(_final, k == 0 ? ".a" : ".b");
}

void ShadowDocument::begin(const std::filesystem::path& final) {
  _final = final;
  _body[0] = _body[1] = 0;
  _exists[0] = _exists[1] = false;
  _live = -1;
  _links = true;
  // leftovers of a killed run; anything but a regular file there is refused when it is opened
  for (int k = 0; k < 2; ++k) files::remove_regular(shadow(k));
  files::remove_regular(with_suffix(_final, ".tmp"));
}

void ShadowDocument::publish(const std::filesystem::path& body, std::uintmax_t body_size,
                             std::string_view tail) {
  if (!_links) {
    publish_by_copy(body, body_size, tail);
    return;
  }
  const int k = _live == 0 ? 1 : 0; // the shadow that is not published
  const std::uintmax_t keep = _exists[k] ? _body[k] : 0;
  {
    OutputFile out;
    out.open_update(shadow(k), keep, _final);
    _exists[k] = true;
    _body[k] = 0; // not a valid prefix until the update is complete
    out.append_file_range(body, keep, body_size);
    out.write(tail);
    out.close(); // fsync
    _body[k] = body_size;
  }
  const std::filesystem::path tmp = with_suffix(_final, ".tmp");
  std::error_code ec;
  std::filesystem::remove(tmp, ec);
  if (::link(shadow(k).c_str(), tmp.c_str()) != 0) {
    const int err = errno;
    if (err == EPERM || err == EOPNOTSUPP || err == EXDEV || err == EMLINK || err == ENOSYS) {
      _links = false; // e.g. a FAT or some network file systems: copy from now on
      publish_by_copy(body, body_size, tail);
      return;
    }
    errno = err;
    throw AnalysisError(fmt::format("cannot replace results file '{}': {}; check that the output "
                                    "directory is writable and has free space",
                                    _final.string(), std::strerror(err)));
  }
  bool replaced = false;
  try {
    replaced = files::replace(tmp, _final);
  } catch (...) {
    std::filesystem::remove(tmp, ec);
    throw;
  }
  if (!replaced) {
    const int err = errno;
    std::filesystem::remove(tmp, ec);
    throw AnalysisError(fmt::format("cannot replace results file '{}': {}; check that the output "
                                    "directory is writable",
                                    _final.string(), std::strerror(err)));
  }
  sync_directory(_final.parent_path());
  _live = k;
}

void ShadowDocument::publish_by_copy(const std::filesystem::path& body, std::uintmax_t body_size,
                                     std::string_view tail) {
  OutputFile doc;
  doc.open(_final, OutputFile::Mode::Replace);
  doc.append_file_range(body, 0, body_size);
  doc.write(tail);
  doc.close();
}

void ShadowDocument::finish() {
  std::error_code ec;
  for (int k = 0; k < 2; ++k)
    if (_exists[k]) std::filesystem::remove(shadow(k), ec);
  _exists[0] = _exists[1] = false;
  _live = -1;
}

} // namespace gapfem::output
