// Fuzz test of the parameter reading (issue: no crash, no hang, no NaN,
// whatever the parameter file says). tests/fuzz_parameters.py makes 300
// mutated copies of prm/examples (0, negative, 1e-300, 1e300, nan, inf,
// words in numeric entries, bad function expressions, overlong values and
// names, include cycles, a byte-order mark, empty files, bad output
// directories, a result file that cannot be written, ...). Each is checked
// in-process with `masonry --validate`, and the cheap ones (small
// rigid-block models) are run. Every outcome must be exit code 0 with
// finite results (no nan, inf or null in summary.json and the CSV files), or
// exit code 1 with one line `masonry: error: ...` that names an entry (or
// the file, for errors of the file itself). A signal or a hang fails the
// test as a whole; fuzz-progress.txt names the file being checked.
#include <masonry/config.h>

#include <chrono>
#include <cstdlib>
#include <regex>

#include "tests.h"

namespace
{
  bool
  has_non_finite(const std::string &directory)
  {
    namespace fs = std::filesystem;
    if (!fs::is_directory(directory))
      return false;
    const std::regex bad("(^|[^a-zA-Z_])(nan|NaN|inf|Infinity|null)([^a-zA-Z_]"
                         "|$)");
    for (const auto &f : fs::directory_iterator(directory))
      {
        const std::string name = f.path().filename().string();
        if (name != "summary.json" &&
            (name.size() < 4 || name.substr(name.size() - 4) != ".csv"))
          continue;
        std::ifstream in(f.path());
        std::string   line;
        bool          header = name != "summary.json";
        while (std::getline(in, line))
          {
            if (!header && std::regex_search(line, bad))
              return true;
            header = false;
          }
      }
    return false;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::filesystem::remove_all("fuzz");
  const std::string source = MASONRY_SOURCE_DIR;
  const std::string generate =
    "/usr/bin/python3 " + source + "/tests/fuzz_parameters.py generate " +
    source + "/prm/examples fuzz --count 300 --seed 1 > fuzz-generate.txt";
  if (std::system(generate.c_str()) != 0)
    {
      std::cout << "the generator failed: " << generate << "\n";
      return 1;
    }
  std::ifstream manifest("fuzz/manifest.txt");
  std::vector<std::pair<std::string, std::string>> cases;
  std::string                                      name, mode;
  while (manifest >> name >> mode)
    cases.emplace_back(name, mode);

  // the files include each other by names relative to their directory
  std::filesystem::current_path("fuzz");
  unsigned int n_runs = 0, n_bad = 0, n_errors = 0, n_results = 0;
  double       slowest = 0;
  std::string  slowest_name;
  const auto   start = std::chrono::steady_clock::now();
  for (const auto &[name, mode] : cases)
    {
      std::ofstream("../fuzz-progress.txt") << name << " " << mode << "\n";
      const auto            t0 = std::chrono::steady_clock::now();
      const testing::Result r  = mode == "run" ?
                                   testing::run({name + ".prm"}) :
                                   testing::run({"--validate", name + ".prm"});
      const double          seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
          .count();
      if (seconds > slowest)
        {
          slowest      = seconds;
          slowest_name = name;
        }
      n_runs += mode == "run";
      std::string problem;
      if (r.exit_code == 0)
        {
          ++n_results;
          if (!r.err.empty())
            problem = "exit code 0 but error output: " + r.err.substr(0, 200);
          else if (mode == "run" && has_non_finite("out/" + name))
            problem = "exit code 0 with a non-finite number in the results";
        }
      else
        {
          ++n_errors;
          const std::string prefix = "masonry: error: ";
          const auto lines = std::count(r.err.begin(), r.err.end(), '\n');
          const bool names = r.err.find("entry '") != std::string::npos ||
                             r.err.find("subsection '") != std::string::npos;
          const bool file_level =
            r.err.find("no Analysis set") != std::string::npos ||
            r.err.find("include") != std::string::npos ||
            r.err.find("the results in out/") != std::string::npos;
          if (r.exit_code != 1 || lines != 1 || r.err.rfind(prefix, 0) != 0)
            problem = "not a one-line error (exit code " +
                      std::to_string(r.exit_code) +
                      "): " + r.err.substr(0, 300);
          else if (!names && !file_level)
            problem = "the error names no entry: " + r.err.substr(0, 300);
        }
      if (!problem.empty())
        {
          ++n_bad;
          std::cout << "BAD " << name << " (" << mode << "): " << problem
                    << "\n";
        }
    }
  const double total =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
  // timings are not deterministic: in a file, not in the compared output
  std::ofstream("../fuzz-summary.txt")
    << "fuzz: " << cases.size() << " files, " << n_runs << " real runs, "
    << n_errors << " clean errors, " << n_results << " results, " << n_bad
    << " bad; " << total << " s in total, slowest " << slowest_name << " "
    << slowest << " s\n";
  // the numbers depend on the shipped examples: only their size is fixed
  std::cout << "files: " << cases.size() << ", of them at least 20 real runs: "
            << (n_runs >= 20 ? "yes" : "no") << "\n"
            << "outcomes that are neither a finite result nor a one-line "
               "error naming an entry: "
            << n_bad << "\n";
  return n_bad == 0 ? 0 : 1;
}
