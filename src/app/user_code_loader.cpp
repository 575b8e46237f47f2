#include "app/user_code_loader.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/safe_file.hpp"
#include "elements/user/user_code.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <dlfcn.h>
#include <fmt/format.h>
#include <optional>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace gapfem {

namespace embedded {
extern const char plugin_hpp[];
extern const std::size_t plugin_hpp_size;
} // namespace embedded

const char* const kAbaParamInc = "      implicit real*8(a-h,o-z)\n"
                                 "      parameter (nprecd=2)\n";

namespace {

namespace fs = std::filesystem;

/// A loaded library: closed when the last user of its code is gone.
class LoadedLibrary final : public UserCode {
 public:
  LoadedLibrary(void* handle, UelFunction uel_fn, gapfem_element_fn element_fn, std::string source)
      : UserCode(uel_fn, element_fn, std::move(source)), _handle(handle) {}
  ~LoadedLibrary() override { dlclose(_handle); }

 private:
  void* _handle;
};

enum class Language { Fixed, Free, C, Cpp, Library };

std::optional<Language> language_of(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".f" || ext == ".for" || ext == ".f77") return Language::Fixed;
  if (ext == ".f90" || ext == ".f95" || ext == ".f03" || ext == ".f08") return Language::Free;
  if (ext == ".c") return Language::C;
  if (ext == ".cpp" || ext == ".cc" || ext == ".cxx" || ext == ".c++") return Language::Cpp;
  if (ext == ".so") return Language::Library;
  return std::nullopt;
}

/// Single-quoted for /bin/sh.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// Runs a command, returning its exit status and everything it printed.
std::pair<int, std::string> run(const std::string& command) {
  std::string output;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return {-1, "the compiler could not be started"};
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) output.append(buf.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

bool on_path(const std::string& program) {
  return run("command -v " + program + " >/dev/null").first == 0;
}

/// Writes the files a source may include: ABA_PARAM.INC (both cases) and gapfem/plugin.hpp, into
/// the fresh private scratch folder (never through a link: common/safe_file.hpp).
void write_includes(const fs::path& dir, const SourceLocation& at) {
  auto failed = [&](const fs::path& what) {
    return InputError(at, "--user",
                      fmt::format("cannot write '{}' in the scratch folder: {}; check that the "
                                  "output directory is writable",
                                  what.string(), std::strerror(errno)));
  };
  try {
    if (!files::fresh_private_directory(dir)) throw failed(dir);
    if (::mkdir((dir / "gapfem").c_str(), 0700) != 0) throw failed(dir / "gapfem");
    for (const char* name : {"ABA_PARAM.INC", "aba_param.inc"})
      if (!files::write_new(dir / name, kAbaParamInc)) throw failed(dir / name);
    const fs::path plugin = dir / "gapfem" / "plugin.hpp";
    if (!files::write_new(plugin,
                          std::string_view(embedded::plugin_hpp, embedded::plugin_hpp_size)))
      throw failed(plugin);
  } catch (const AnalysisError& e) { // a link, pipe or another user's folder in its place
    throw InputError(at, "--user", e.what());
  }
}

/// Compiles `source` into scratch/libuser.so; InputError with the compiler's messages on failure.
fs::path compile(const fs::path& source, Language lang, const fs::path& scratch) {
  const char* compiler = lang == Language::C ? "gcc" : lang == Language::Cpp ? "g++" : "gfortran";
  if (!on_path(compiler))
    throw InputError(SourceLocation{source.string(), 0, {}}, "--user",
                     fmt::format("{} is needed to compile this file but is not installed; install "
                                 "it (apt-get install {}) or give a compiled .so",
                                 compiler, compiler));
  write_includes(scratch, SourceLocation{source.string(), 0, {}});
  // a name of its own: dlopen would hand back a library already loaded under the same name
  static int count = 0;
  const fs::path lib = scratch / fmt::format("libuser-{}-{}.so", getpid(), ++count);
  // -fexceptions: XIT and STDB_ABQERR end the analysis with an exception through the user's frames
  std::string flags = "-O2 -fPIC -shared -fexceptions";
  if (lang == Language::Fixed) flags += " -ffixed-form";
  if (lang == Language::Free) flags += " -ffree-form";
  if (lang == Language::Cpp) flags += " -std=c++20";
  const std::string command =
      fmt::format("{} {} -I{} -I{} -o {} {}", compiler, flags, quoted(scratch.string()),
                  quoted(source.parent_path().empty() ? "." : source.parent_path().string()),
                  quoted(lib.string()), quoted(source.string()));
  log::info("Compiling {} with {}", source.string(), compiler);
  const auto [status, output] = run(command);
  if (status != 0 || !fs::exists(lib))
    throw InputError(SourceLocation{source.string(), 0, {}}, "--user",
                     fmt::format("{} could not compile this file; fix it and run again. The "
                                 "compiler said:\n{}",
                                 compiler, output));
  if (!output.empty()) log::info("{} said:\n{}", compiler, output);
  return lib;
}

std::shared_ptr<const UserCode> open_library(const fs::path& lib, const fs::path& source) {
  const SourceLocation at{source.string(), 0, {}};
  void* handle = dlopen(lib.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw InputError(at, "--user",
                     fmt::format("the library cannot be loaded: {}; give a shared library built "
                                 "for this machine (or the source, which gapfem compiles)",
                                 why ? why : "unknown reason"));
  }
  auto symbol = [&](const char* name) { return dlsym(handle, name); };
  UelFunction uel = nullptr;
  for (const char* name : {"uel_", "uel", "UEL", "UEL_"})
    if (void* f = symbol(name)) {
      uel = reinterpret_cast<UelFunction>(f);
      break;
    }
  auto element = reinterpret_cast<gapfem_element_fn>(symbol("gapfem_element"));
  if (element) {
    auto version =
        reinterpret_cast<gapfem_plugin_abi_version_fn>(symbol("gapfem_plugin_abi_version"));
    const int v = version ? version() : -1;
    if (v != GAPFEM_PLUGIN_ABI_VERSION) {
      dlclose(handle);
      throw InputError(at, "--user",
                       version
                           ? fmt::format("this element plugin was built for plugin ABI version "
                                         "{}, but this gapfem has version {}; rebuild it "
                                         "against this gapfem's gapfem/plugin.hpp",
                                         v, GAPFEM_PLUGIN_ABI_VERSION)
                           : "this element plugin does not export gapfem_plugin_abi_version(); "
                             "define it (return GAPFEM_PLUGIN_ABI_VERSION), see gapfem/plugin.hpp");
    }
  }
  if (!uel && !element) {
    dlclose(handle);
    throw InputError(at, "--user",
                     "this file defines neither a UEL subroutine (SUBROUTINE UEL, symbol uel_) nor "
                     "a gapfem element plugin (extern \"C\" int gapfem_element, see "
                     "gapfem/plugin.hpp); check the subroutine's name");
  }
  if (uel && element) {
    dlclose(handle);
    throw InputError(at, "--user",
                     "this file defines both a UEL subroutine and a gapfem element plugin; give "
                     "one of them");
  }
  return std::make_shared<LoadedLibrary>(handle, uel, element, source.filename().string());
}

} // namespace

std::shared_ptr<const UserCode> load_user_code(const fs::path& source, const fs::path& scratch) {
  const SourceLocation at{source.string(), 0, {}};
  std::error_code ec;
  if (!fs::is_regular_file(source, ec))
    throw InputError(at, "--user", "this file does not exist or is not a regular file");
  const auto lang = language_of(source);
  if (!lang)
    throw InputError(at, "--user",
                     "give a Fortran (.f, .for, .f90), C (.c) or C++ (.cpp) source, or a compiled "
                     "shared library (.so)");
  if (*lang == Language::Library) return open_library(fs::absolute(source), source);
  const fs::path lib = compile(source, *lang, scratch);
  auto code = open_library(lib, source);
  fs::remove_all(scratch, ec); // the loaded library stays mapped
  return code;
}

} // namespace gapfem
