#pragma once
/// @file shadow_document.hpp
/// A growing document published as one complete file after every change, at the cost of the bytes
/// added since the previous publication rather than of the whole document (docs/results.md,
/// "Results that survive").
///
/// The document is a body that only grows (a stream file the writer appends to) followed by a
/// closing tail that changes each time. Two shadow files, `<final>.a` and `<final>.b`, each hold
/// a prefix of the body and a tail. A publication brings the shadow that is not live up to date:
/// its old tail is cut off, the body bytes it lacks and the new tail are appended, and the file is
/// fsync'ed. Then a hard link to it replaces `<final>` by rename. The other shadow is the previous
/// document and stays untouched, so `<final>` is at every moment a complete document. finish()
/// removes the shadow names. Where hard links are not available, each publication copies the whole
/// document instead.
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace gapfem::output {

class ShadowDocument {
 public:
  /// Starts a document published as `final`; removes shadows a killed run left behind.
  void begin(const std::filesystem::path& final);
  /// Publishes the first `body_size` bytes of `body` (a flushed file) followed by `tail`. Throws
  /// AnalysisError (naming `final`) when a write fails; the previous document stays published.
  void publish(const std::filesystem::path& body, std::uintmax_t body_size, std::string_view tail);
  /// Removes the shadow names (the last published document stays under `final`).
  void finish();

 private:
  std::filesystem::path shadow(int k) const;
  void publish_by_copy(const std::filesystem::path& body, std::uintmax_t body_size,
                       std::string_view tail);

  std::filesystem::path _final;
  std::uintmax_t _body[2] = {0, 0}; ///< body bytes each shadow holds
  bool _exists[2] = {false, false};
  int _live = -1;     ///< the shadow `_final` is a link to (-1: none yet)
  bool _links = true; ///< hard links work in the output directory
};

} // namespace gapfem::output
