#include <masonry/core/json.h>
#include <masonry/core/output_file.h>
#include <masonry/core/scripts.h>

#include <cstdio>
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

  namespace
  {
    /** @p text in single quotes for the shell, a quote inside as '\''. */
    std::string
    quoted(const std::string &text)
    {
      std::string q = "'";
      for (const char c : text)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
      return q + "'";
    }
  } // namespace

  std::vector<std::string>
  run_scripts(const std::vector<ScriptJob> &jobs)
  {
    std::vector<std::string> why(jobs.size());
    if (jobs.empty())
      return why;
    const std::string python = "/usr/bin/python3";
    const std::string runner = find_script("masonry_scripts.py");
    std::error_code   error;
    Json              list = Json::array();
    std::vector<int>  numbers; // job of each entry of list
    for (unsigned int j = 0; j < jobs.size(); ++j)
      {
        const std::string script = find_script(jobs[j].script);
        if (script.empty())
          why[j] = jobs[j].script + " not found";
        else if (runner.empty())
          why[j] = "masonry_scripts.py not found";
        else if (!std::filesystem::exists(python, error))
          why[j] = python + " not found";
        if (!why[j].empty())
          continue;
        Json job       = Json::object();
        job["script"]  = script;
        Json arguments = Json::array();
        for (const auto &a : jobs[j].arguments)
          arguments.push_back(a);
        job["arguments"] = arguments;
        job["output"]    = jobs[j].output;
        list.push_back(job);
        numbers.push_back(j);
      }
    if (numbers.empty())
      return why;
    // the runner's lines "masonry-job N ok|error CAUSE"; anything else on
    // its output (Python's own complaints) is kept for a runner that fails
    const std::string command =
      python + " " + quoted(runner) + " " + quoted(list.dump(0)) + " 2>&1";
    std::vector<bool> answered(numbers.size(), false);
    std::string       last_line;
    FILE             *pipe = popen(command.c_str(), "r");
    if (pipe == nullptr)
      {
        for (const int j : numbers)
          why[j] = "cannot start " + python;
        return why;
      }
    std::string line;
    char        buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr)
      {
        line += buffer;
        if (line.empty() || line.back() != '\n')
          continue;
        line.pop_back();
        const std::string prefix = "masonry-job ";
        unsigned int      n      = 0;
        std::size_t       end    = 0;
        if (line.rfind(prefix, 0) == 0 &&
            std::sscanf(line.c_str() + prefix.size(), "%u", &n) == 1 &&
            n < numbers.size() &&
            (end = line.find(' ', prefix.size())) != std::string::npos)
          {
            const std::string verdict = line.substr(end + 1);
            answered[n]               = true;
            if (verdict != "ok")
              why[numbers[n]] =
                jobs[numbers[n]].script + " failed: " +
                (verdict.rfind("error ", 0) == 0 ? verdict.substr(6) : verdict);
          }
        else if (!line.empty())
          last_line = line;
        line.clear();
      }
    const int status = pclose(pipe);
    // a picture that could not be written ends the run, like any file
    const std::string write_failed = "failed: write failed: ";
    for (const int j : numbers)
      {
        const auto at = why[j].find(write_failed);
        if (at != std::string::npos)
          AssertThrow(false,
                      dealii::ExcMessage(
                        write_error(jobs[j].output.empty() ? jobs[j].script :
                                                             jobs[j].output,
                                    why[j].substr(at + write_failed.size()))));
      }
    for (unsigned int n = 0; n < numbers.size(); ++n)
      if (!answered[n])
        why[numbers[n]] =
          jobs[numbers[n]].script + " not run: the Python process stopped" +
          (last_line.empty() ? " (exit status " + std::to_string(status) + ")" :
                               " (" + last_line + ")");
    return why;
  }

  std::string
  run_script(const std::string              &name,
             const std::vector<std::string> &arguments,
             const std::vector<std::string> &outputs)
  {
    std::string why;
    try
      {
        why = run_scripts({ScriptJob{name, arguments, ""}}).front();
      }
    catch (...)
      {
        std::error_code error;
        for (const auto &output : outputs)
          std::filesystem::remove(output, error);
        throw;
      }
    if (!why.empty())
      {
        std::error_code error;
        for (const auto &output : outputs)
          std::filesystem::remove(output, error);
      }
    return why;
  }
} // namespace masonry
