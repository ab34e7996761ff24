/**
 * Mesh adaptation on two MPI ranks (one island of the genetic algorithm per
 * rank, with migration of the best mesh after every generation): two runs
 * with the same seed give identical results, both ranks agree, the result
 * is never worse than the uniform mesh, and the 6-block arch under a
 * settlement is within 0.5 % of 512 uniform blocks (as on one rank). The
 * same with two threads per rank (four islands evolved concurrently).
 */
#include <deal.II/base/mpi.h>

#include "vault_tests.h"

using namespace vault_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const std::string adaptation =
    "subsection Adaptation\n  set Optimiser = genetic\n"
    "  set Population size = 12\n  set Generations = 25\n"
    "  set Stall generations = 6\n  set Seed = 3\nend\n";
  const double fine = run("fine", arch_prm(5, 1, 256, "0; 0; -0.01"))
                        .at("external_work")
                        .get<double>();
  const masonry::Json a =
    run("first", arch_prm(5, 1, 3, "0; 0; -0.01") + adaptation);
  const masonry::Json b =
    run("second", arch_prm(5, 1, 3, "0; 0; -0.01") + adaptation);
  std::string threaded = adaptation;
  threaded.insert(threaded.find("end\n"), "  set Threads = 2\n");
  const masonry::Json c =
    run("threads_first", arch_prm(5, 1, 3, "0; 0; -0.01") + threaded);
  const masonry::Json d =
    run("threads_second", arch_prm(5, 1, 3, "0; 0; -0.01") + threaded);

  // the best genes of every rank, gathered on rank 0
  std::vector<double> genes;
  for (unsigned int i = 0; i < a.at("adaptation").at("best_genes").size(); ++i)
    genes.push_back(a.at("adaptation").at("best_genes").at(i).get<double>());
  const auto all = dealii::Utilities::MPI::gather(MPI_COMM_WORLD, genes, 0);
  if (rank != 0)
    return 0;
  const auto &ad = a.at("adaptation");
  check(ad.at("islands").get<double>() == 2, "two islands, one per rank");
  check(all[0] == all[1], "both ranks end with the same best mesh");
  bool same =
    a.at("external_work").get<double>() == b.at("external_work").get<double>();
  for (unsigned int i = 0; i < ad.at("best_genes").size(); ++i)
    same = same && ad.at("best_genes").at(i).get<double>() ==
                     b.at("adaptation").at("best_genes").at(i).get<double>();
  check(same, "the same seed on two ranks reproduces the result exactly");
  check(ad.at("best_fitness").get<double>() >=
          ad.at("uniform_fitness").get<double>(),
        "adapted work ≥ uniform mesh's");
  check(relative(a.at("external_work").get<double>(), fine) < 5e-3,
        "6 blocks adapted on two ranks: work within 0.5 % of 512 uniform "
        "blocks");

  const auto &cd = c.at("adaptation");
  check(cd.at("islands").get<double>() == 4 &&
          cd.at("threads").get<double>() == 2,
        "two threads per rank: four islands");
  same =
    c.at("external_work").get<double>() == d.at("external_work").get<double>();
  for (unsigned int i = 0; i < cd.at("best_genes").size(); ++i)
    same = same && cd.at("best_genes").at(i).get<double>() ==
                     d.at("adaptation").at("best_genes").at(i).get<double>();
  check(same,
        "the same seed on two ranks with two threads reproduces the result "
        "exactly");
  check(cd.at("best_fitness").get<double>() >=
            cd.at("uniform_fitness").get<double>() &&
          relative(c.at("external_work").get<double>(), fine) < 5e-3,
        "four islands: adapted work ≥ uniform mesh's and within 0.5 % of 512 "
        "uniform blocks");
}
