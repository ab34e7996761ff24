#include <masonry/core/scripts.h>

#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <system_error>

namespace masonry
{
  std::vector<std::string>
  script_directories()
  {
    namespace fs = std::filesystem;
    std::vector<fs::path> bases;
    std::error_code       error;
    const fs::path        exe = fs::read_symlink("/proc/self/exe", error);
    if (!error)
      bases.push_back(exe.parent_path());
    // the library holding this function: a program linked against
    // libmasonry (a test, a user's driver) finds the scripts next to it
    Dl_info info;
    if (dladdr(reinterpret_cast<void *>(&script_directories), &info) != 0 &&
        info.dli_fname != nullptr)
      {
        const fs::path library =
          fs::weakly_canonical(fs::path(info.dli_fname), error);
        if (!error)
          bases.push_back(library.parent_path());
      }
    std::vector<fs::path> candidates;
    if (const char *own = std::getenv("MASONRY_SCRIPT_DIR"); own && *own)
      candidates.emplace_back(own);
    for (const auto &base : bases)
      {
        candidates.push_back(base.parent_path() / "share/masonry/scripts");
        candidates.push_back(base / "share/masonry/scripts");
      }
    std::vector<std::string> directories;
    for (const fs::path &candidate : candidates)
      {
        const std::string d     = candidate.lexically_normal().string();
        bool              known = false;
        for (const auto &k : directories)
          known = known || k == d;
        if (!known)
          directories.push_back(d);
      }
    return directories;
  }

  std::string
  find_script(const std::string &name)
  {
    for (const auto &directory : script_directories())
      {
        const std::filesystem::path script =
          std::filesystem::path(directory) / name;
        std::error_code error;
        if (std::filesystem::is_regular_file(script, error))
          return script.string();
      }
    return "";
  }
} // namespace masonry
