/**
 * 1 and 2 MPI ranks give the same results for the settlement analysis.
 *
 * A semicircular arch (16 blocks per half) whose right springing settles by
 * 1 cm is run by the application on MPI_COMM_WORLD (2 ranks under
 * `mpirun -np 2`) and, as an independent reference, on MPI_COMM_SELF of rank
 * 0 (1 rank). The external work, the crack list (interfaces, types,
 * openings, rotations) and every block's translation and rotation
 * (blocks.csv, 17 digits) must agree to 1e-12 relative. To show that the
 * comparison can fail, the reference is also compared with a run whose
 * settlement is 1 % larger, which must be found different.
 */
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tests.h"
#include "vault_tests.h"

namespace
{
  /** Run @p prm_text into results/NAME on @p comm; the summary on rank 0. */
  masonry::Json
  run_on(const std::string &name,
         const std::string &prm_text,
         const MPI_Comm     comm)
  {
    const bool root =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    if (root)
      testing::write_file(name + ".prm",
                          "set Output directory = results/" + name + "\n" +
                            prm_text);
    MPI_Barrier(comm);
    const testing::Result r = testing::run({name + ".prm"}, comm);
    MPI_Barrier(comm);
    if (r.exit_code != 0)
      {
        std::cout << "FAILED: masonry returned " << r.exit_code << " for "
                  << name << "\n"
                  << r.err;
        std::exit(1);
      }
    return root ? masonry::parse_json(
                    testing::read_file("results/" + name + "/summary.json")) :
                  masonry::Json();
  }

  /**
   * Columns @p first to @p first + 2 of results/NAME/blocks.csv (header
   * skipped), row-wise: 5 for the translations, 8 for the rotations.
   */
  std::vector<double>
  block_columns(const std::string &name, const unsigned int first)
  {
    std::istringstream in(
      testing::read_file("results/" + name + "/blocks.csv"));
    std::vector<double> values;
    std::string         line;
    std::getline(in, line); // header
    while (std::getline(in, line))
      {
        std::istringstream fields(line);
        std::string        field;
        for (unsigned int column = 0; std::getline(fields, field, ',');
             ++column)
          if (column >= first && column < first + 3)
            values.push_back(std::stod(field));
      }
    return values;
  }

  /**
   * Largest difference of @p a and @p b relative to the largest magnitude in
   * @p b (so that entries that are round-off of zero do not count as large
   * relative differences); infinity if the lengths differ.
   */
  double
  difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    if (a.size() != b.size() || b.empty())
      return INFINITY;
    double diff = 0, scale = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        diff  = std::max(diff, std::abs(a[i] - b[i]));
        scale = std::max(scale, std::abs(b[i]));
      }
    return scale > 0 ? diff / scale : diff;
  }

  /** What two runs are compared by. */
  struct Comparison
  {
    double work, cracks, motions;
    bool   same_crack_list;
  };

  Comparison
  compare(const std::string   &name,
          const masonry::Json &s,
          const std::string   &reference_name,
          const masonry::Json &reference)
  {
    Comparison c;
    c.work = vault_tests::relative(s.at("external_work").get<double>(),
                                   reference.at("external_work").get<double>());
    // the crack list: same interfaces of the same type, in the same order,
    // and their openings and relative rotations
    const masonry::Json &a = s.at("cracks");
    const masonry::Json &b = reference.at("cracks");
    std::vector<double>  va, vb;
    c.same_crack_list = a.size() == b.size();
    for (unsigned int i = 0; c.same_crack_list && i < a.size(); ++i)
      {
        c.same_crack_list = a.at(i).at("interface").get<double>() ==
                              b.at(i).at("interface").get<double>() &&
                            a.at(i).at("type").get<std::string>() ==
                              b.at(i).at("type").get<std::string>();
        for (const char *key : {"max_opening", "relative_rotation"})
          {
            va.push_back(a.at(i).at(key).get<double>());
            vb.push_back(b.at(i).at(key).get<double>());
          }
      }
    c.cracks = c.same_crack_list ? difference(va, vb) : INFINITY;
    // translations (m) and rotations (rad), each relative to its own scale
    c.motions = 0;
    for (const unsigned int first : {5u, 8u})
      c.motions = std::max(c.motions,
                           difference(block_columns(name, first),
                                      block_columns(reference_name, first)));
    return c;
  }

  bool
  equal(const Comparison &c)
  {
    const double tolerance = 1e-12;
    return c.same_crack_list && c.work <= tolerance && c.cracks <= tolerance &&
           c.motions <= tolerance;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  if (rank == 0)
    std::filesystem::remove_all("results");

  const double  R = 5, t = 1;
  masonry::Json parallel =
    run_on("ranks_all",
           vault_tests::arch_prm(R, t, 16, "0; 0; -0.01"),
           MPI_COMM_WORLD);
  if (rank == 0)
    {
      const masonry::Json serial =
        run_on("rank_one",
               vault_tests::arch_prm(R, t, 16, "0; 0; -0.01"),
               MPI_COMM_SELF);
      const masonry::Json perturbed =
        run_on("rank_one_perturbed",
               vault_tests::arch_prm(R, t, 16, "0; 0; -0.0101"),
               MPI_COMM_SELF);

      std::cout << "ranks: " << parallel.at("n_mpi_ranks").get<double>()
                << " and " << serial.at("n_mpi_ranks").get<double>() << "\n"
                << "status: " << parallel.at("status").get<std::string>()
                << " and " << serial.at("status").get<std::string>() << "\n"
                << "cracks: " << parallel.at("cracks").size() << " ("
                << parallel.at("n_hinges").get<double>() << " hinges) and "
                << serial.at("cracks").size() << " ("
                << serial.at("n_hinges").get<double>() << " hinges)\n";

      const Comparison c = compare("ranks_all", parallel, "rank_one", serial);
      std::cout << "same crack list (interfaces and types): "
                << (c.same_crack_list ? "yes" : "no") << "\n";
      std::cout << "relative differences below 1e-12: external work "
                << (c.work <= 1e-12 ? "yes" : "no") << ", crack openings "
                << "and rotations " << (c.cracks <= 1e-12 ? "yes" : "no")
                << ", block motions " << (c.motions <= 1e-12 ? "yes" : "no")
                << "\n";
      if (equal(c))
        std::cout << "1 and " << parallel.at("n_mpi_ranks").get<double>()
                  << " ranks: equal\n";
      else
        std::cout << "1 and " << parallel.at("n_mpi_ranks").get<double>()
                  << " ranks: DIFFERENT (external work " << c.work
                  << ", cracks " << c.cracks << ", block motions " << c.motions
                  << ")\n";

      // the comparison can fail: a 1 % larger settlement is detected
      const Comparison p =
        compare("rank_one_perturbed", perturbed, "rank_one", serial);
      std::cout << "a run with a 1 % larger settlement is found different: "
                << (!equal(p) && p.work > 1e-3 && p.motions > 1e-3 ? "yes" :
                                                                     "no")
                << "\n";
      // and, by the linearity of the rigid-block problem in the settlement,
      // its work is 1.01 times the reference
      std::cout << "its work is 1.01 times the reference (to 1e-9): "
                << (std::abs(perturbed.at("external_work").get<double>() /
                               serial.at("external_work").get<double>() -
                             1.01) < 1e-9 ?
                      "yes" :
                      "no")
                << "\n";
    }
  MPI_Barrier(MPI_COMM_WORLD);
}
