// The informational options: --help, --version, --print-parameters (prm and
// JSON; the JSON is parsed back) and a wrong format.
#include <masonry/config.h>

#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const testing::Result help = testing::run({"--help"});
  std::cout << "--help: exit code " << help.exit_code << ", starts with "
            << help.out.substr(0, help.out.find('\n')) << ", stderr '"
            << help.err << "'\n";

  const testing::Result none = testing::run({});
  std::cout << "no arguments: exit code " << none.exit_code
            << ", usage on stderr: "
            << (none.err.rfind("Usage:", 0) == 0 ? "yes" : "no") << "\n";

  const testing::Result version = testing::run({"--version"});
  std::cout << "--version: exit code " << version.exit_code << ", correct: "
            << (version.out ==
                    std::string("masonry ") + MASONRY_VERSION + "\n" ?
                  "yes" :
                  "no")
            << "\n";

  const testing::Result prm = testing::run({"--print-parameters"});
  std::cout << "--print-parameters: exit code " << prm.exit_code
            << ", declares:";
  for (const std::string entry : {"set Additional shared libraries",
                                  "set Analysis",
                                  "set Output directory",
                                  "subsection Test",
                                  "set Length"})
    std::cout << " '" << entry << "' "
              << (prm.out.find(entry) != std::string::npos ? "yes" : "no");
  std::cout << "\n";

  const testing::Result json = testing::run({"--print-parameters=json"});
  std::cout << "--print-parameters=json: exit code " << json.exit_code << "\n";
  try
    {
      const masonry::Json j = masonry::parse_json(json.out);
      std::cout
        << "  parses as JSON: yes\n"
        << "  Analysis: value '"
        << j.at("Analysis").at("value").get<std::string>()
        << "', pattern description '"
        << j.at("Analysis").at("pattern_description").get<std::string>()
        << "'\n"
        << "  Test/Length: default '"
        << j.at("Test").at("Length").at("default_value").get<std::string>()
        << "', documentation '"
        << j.at("Test").at("Length").at("documentation").get<std::string>()
        << "'\n"
        << "  Output directory declared: "
        << (j.contains("Output directory") ? "yes" : "no") << "\n";
    }
  catch (const std::exception &exc)
    {
      std::cout << "  parses as JSON: no: " << exc.what() << "\n";
    }

  std::cout << "--print-parameters=xml:\n";
  testing::check_error(testing::run({"--print-parameters=xml"}));
}
