/**
 * `Postprocess/Rigid blocks/List of postprocessors` selects the outputs of a
 * rigid-block analysis: the default writes every output; a subset writes
 * exactly the listed files plus those of the postprocessors they require
 * (`vault pvd` names blocks.vtu and interfaces.vtu), with the same contents
 * as the default run, and no summary entries of the others; an empty list
 * writes no result file; a name listed twice is one error line naming the
 * entry. Arch: semicircular, R = 2 m, t = 0.3 m, 6 blocks per half, right
 * springing settling by 1 cm.
 */
#include <deal.II/base/mpi.h>

#include <set>

#include "tests.h"
#include "vault_tests.h"

namespace
{
  std::set<std::string>
  files(const masonry::Json &summary)
  {
    std::set<std::string> names;
    const masonry::Json  &list = summary.at("files");
    for (std::size_t i = 0; i < list.size(); ++i)
      names.insert(list.at(i).get<std::string>());
    return names;
  }

  std::string
  joined(const std::set<std::string> &names)
  {
    std::string s;
    for (const auto &n : names)
      s += (s.empty() ? "" : " ") + n;
    return s;
  }

  std::string
  with_list(const std::string &list)
  {
    return vault_tests::arch_prm(2, 0.3, 6, "0; 0; -0.01") +
           "subsection Postprocess\n  subsection Rigid blocks\n"
           "    set List of postprocessors = " +
           list + "\n  end\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using vault_tests::check;
  const std::set<std::string> always = {"log.txt",
                                        "parameters.prm",
                                        "summary.json"};

  const masonry::Json all =
    vault_tests::run("default",
                     vault_tests::arch_prm(2, 0.3, 6, "0; 0; -0.01"));
  std::cout << "default: " << joined(files(all)) << "\n";
  std::set<std::string> expected = always;
  // settlement: no thrust line (moving supports); Write picture = false
  // (no vault.png, crack_map.png)
  for (const auto *f : {"interface_forces.csv",
                        "blocks.csv",
                        "blocks.vtu",
                        "interfaces.vtu",
                        "vault.pvd",
                        "crack_map.csv",
                        "report.html"})
    expected.insert(f);
  check(files(all) == expected, "default list writes every output");
  check(all.contains("cracks") && all.contains("support_reactions") &&
          all.contains("displacement_amplification"),
        "default list writes the summary entries");

  const masonry::Json some =
    vault_tests::run("subset", with_list("blocks csv, vault pvd"));
  std::cout << "blocks csv, vault pvd: " << joined(files(some)) << "\n";
  expected = always;
  for (const auto *f :
       {"blocks.csv", "blocks.vtu", "interfaces.vtu", "vault.pvd"})
    expected.insert(f);
  check(files(some) == expected,
        "subset writes the listed files and the VTU files the PVD names");
  check(!std::filesystem::exists("results/subset/interface_forces.csv"),
        "no interface_forces.csv");
  check(!some.contains("cracks") && !some.contains("n_cracks") &&
          !some.contains("support_reactions") &&
          !some.contains("seconds_picture") && !some.contains("seconds_report"),
        "no summary entries of unlisted postprocessors");
  for (const auto *f : {"blocks.csv", "blocks.vtu", "interfaces.vtu"})
    check(testing::read_file(std::string("results/subset/") + f) ==
            testing::read_file(std::string("results/default/") + f),
          std::string(f) + " identical to the default run's");
  check(some.at("external_work").get<double>() ==
          all.at("external_work").get<double>(),
        "same external work");

  const masonry::Json none = vault_tests::run("none", with_list(""));
  std::cout << "empty list: " << joined(files(none)) << "\n";
  check(files(none) == always &&
          none.at("status").get<std::string>() == "optimal",
        "empty list: no result files, status optimal");

  testing::write_file("twice.prm",
                      "set Output directory = results/twice\n" +
                        with_list("cracks, blocks csv, cracks"));
  const auto twice = testing::run({"twice.prm"});
  std::cout << "exit code " << twice.exit_code << ": " << twice.err;
}
