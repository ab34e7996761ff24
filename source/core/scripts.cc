#include <masonry/core/output_file.h>
#include <masonry/core/scripts.h>

#include <deal.II/base/exceptions.h>

#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <unistd.h>

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

  namespace
  {
    /** The last non-empty line of @p text. */
    std::string
    last_line(const std::string &text)
    {
      std::string line;
      std::size_t end = text.find_last_not_of("\n ");
      if (end == std::string::npos)
        return "";
      const std::size_t start = text.rfind('\n', end);
      line =
        text.substr(start == std::string::npos ? 0 : start + 1,
                    end + 1 - (start == std::string::npos ? 0 : start + 1));
      return line;
    }

    /** The system's reason if @p error is a failed write, else "". */
    std::string
    write_failure(const std::string &error)
    {
      for (const char *reason : {"No space left on device",
                                 "File too large",
                                 "Disk quota exceeded",
                                 "Input/output error"})
        if (error.find(reason) != std::string::npos)
          return reason;
      return "";
    }
  } // namespace

  std::string
  run_script(const std::string              &name,
             const std::vector<std::string> &arguments,
             const std::vector<std::string> &outputs)
  {
    const std::string script = find_script(name);
    const std::string python = "/usr/bin/python3";
    if (script.empty())
      return name + " not found";
    std::error_code error;
    if (!std::filesystem::exists(python, error))
      return python + " not found";
    // each argument in single quotes, a quote inside as '\''
    auto quoted = [](const std::string &text) {
      std::string q = "'";
      for (const char c : text)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
      return q + "'";
    };
    // the script's error output, to tell a missing module from a full disk
    char      errors_name[] = "/tmp/masonry-script-XXXXXX";
    const int errors_file   = ::mkstemp(errors_name);
    if (errors_file >= 0)
      ::close(errors_file);
    std::string command = python + " " + quoted(script);
    for (const auto &argument : arguments)
      command += " " + quoted(argument);
    command += " >/dev/null 2>" +
               (errors_file >= 0 ? quoted(errors_name) : std::string("&1"));
    const int   status = std::system(command.c_str());
    std::string errors;
    if (errors_file >= 0)
      {
        std::ifstream     in(errors_name);
        std::stringstream text;
        text << in.rdbuf();
        errors = text.str();
        std::remove(errors_name);
      }
    if (status == 0)
      return "";
    for (const auto &output : outputs)
      std::filesystem::remove(output, error);
    const std::string reason = write_failure(errors);
    if (!reason.empty())
      AssertThrow(false,
                  dealii::ExcMessage(
                    write_error(outputs.empty() ?
                                  "(the output of " + name + ")" :
                                  outputs.front(),
                                reason)));
    const std::string cause   = last_line(errors);
    const std::string missing = "No module named '";
    const auto        m       = cause.find(missing);
    if (m != std::string::npos)
      {
        const std::string module =
          cause.substr(m + missing.size(),
                       cause.find('\'', m + missing.size()) - m -
                         missing.size());
        return name + " needs python3-" + module.substr(0, module.find('.'));
      }
    return name + " failed" + (cause.empty() ? "" : " (" + cause + ")");
  }
} // namespace masonry
