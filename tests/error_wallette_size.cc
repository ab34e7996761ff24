// A wallette size too small to mesh (the grid lines of the bond would merge
// within the mesh's tolerance): before, a brick 1e-30 m high ran to
// `completed' on a wall without unit cells, a brick 1e-30 m wide stopped
// with deal.II's "No vertices given", and a detailed model's mortar 1e-30 m
// thick ran without mortar cells. Each is now a one-line error naming the
// entry, found by `--validate'.
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const auto &[name, entries] :
       {std::pair<std::string, std::string>{"height",
                                            "  set Brick height = 1e-30\n"},
        {"width", "  set Brick width = 1e-30\n"},
        {"joint", "  set Model = detailed\n  set Joint thickness = 1e-9\n"}})
    {
      const std::string file = "error_wallette_size_" + name + ".prm";
      testing::write_file(file,
                          "set Analysis         = wallette\n"
                          "set Output directory = results\n"
                          "subsection Wallette\n" +
                            entries + "end\n");
      testing::check_error(testing::run({"--validate", file}));
    }
}
