/**
 * @file
 * Helpers shared by the tests: run masonry in-process with its screen and
 * error output captured, normalise what is not deterministic, and check the
 * one-line error contract.
 */
#ifndef masonry_tests_tests_h
#define masonry_tests_tests_h

#include <masonry/core/application.h>
#include <masonry/core/json.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace testing
{
  /** What one call of masonry::run_application() did. */
  struct Result
  {
    int         exit_code;
    std::string out;
    std::string err;
  };

  /** Run masonry with @p arguments, capturing std::cout and std::cerr. */
  inline Result
  run(const std::vector<std::string> &arguments,
      const MPI_Comm                  comm = MPI_COMM_WORLD)
  {
    std::ostringstream out, err;
    std::streambuf    *old_out = std::cout.rdbuf(out.rdbuf());
    std::streambuf    *old_err = std::cerr.rdbuf(err.rdbuf());
    const int          code    = masonry::run_application(arguments, comm);
    std::cout.rdbuf(old_out);
    std::cerr.rdbuf(old_err);
    return {code, out.str(), err.str()};
  }

  /** Replace timings and the working directory by fixed text. */
  inline std::string
  normalise(const std::string &text)
  {
    std::string       s   = std::regex_replace(text,
                                       std::regex("Wall time: [0-9.]+ s"),
                                       "Wall time: <seconds> s");
    const std::string cwd = std::filesystem::current_path().string() + "/";
    for (std::size_t p = s.find(cwd); p != std::string::npos; p = s.find(cwd))
      s.replace(p, cwd.size(), "<cwd>/");
    return s;
  }

  /** Write @p text into the file @p name. */
  inline void
  write_file(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  /** The contents of the file @p name ("" if it does not exist). */
  inline std::string
  read_file(const std::string &name)
  {
    std::ifstream     in(name);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /** The number of lines of @p text. */
  inline unsigned int
  n_lines(const std::string &text)
  {
    unsigned int n = 0;
    for (const char c : text)
      n += (c == '\n');
    if (!text.empty() && text.back() != '\n')
      ++n;
    return n;
  }

  /**
   * Print whether @p result follows the error contract (non-zero exit code,
   * exactly one line on stderr starting with "masonry: error:", no stack
   * trace, nothing on stdout) and the (normalised) error line itself.
   */
  inline void
  check_error(const Result &result)
  {
    const std::string prefix = "masonry: error: ";
    std::cout << "exit code non-zero: "
              << (result.exit_code != 0 ? "yes" : "no")
              << "\nlines on stderr: " << n_lines(result.err)
              << "\nstarts with 'masonry: error:': "
              << (result.err.rfind(prefix, 0) == 0 ? "yes" : "no")
              << "\nstack trace: "
              << (result.err.find("Stacktrace") != std::string::npos ||
                      result.err.find("-----") != std::string::npos ?
                    "yes" :
                    "no")
              << "\nlines on stdout: " << n_lines(result.out)
              << "\nstderr: " << normalise(result.err) << std::flush;
  }
} // namespace testing

#endif
