// Hostile wallette inputs that used to end badly, each now a one-line
// error with a non-zero exit code and no stack trace:
// - a unit tensile strength of 1e-300 Pa made a law throw inside an
//   assembly worker thread, which deal.II reported with a stack trace
//   before aborting the program (this test would not finish); the
//   exception then reached the run like one thrown outside the threads,
//   but said only "composite joint: no admissible return from jump ...",
//   naming no entry. The splitting interfaces' law derived from it (its
//   friction tan(phi) = (f_c - f_t) / (2 sqrt(f_c f_t)) was 1e153) is now
//   rejected when it is made, before the first assembly, and the error
//   names the brick material's `Tensile strength' (--validate too);
// - a unit fracture energy of 1e-300 J/m^2 broke the splitting
//   interfaces' law derived from it, and the error named the entry
//   `Splitting tensile strength' that the file does not set: it now names
//   the brick material's entry it was derived from;
// - a mortar joint thicker than the smallest unit of the bond (a half
//   brick is (brick + joint) / 2 - joint) ended in deal.II's text for an
//   internal error: it now names `Joint thickness', before the output
//   directory is written, and `masonry --validate' finds it too.
#include "tests.h"

namespace
{
  const std::string wallette = "set Analysis         = wallette\n"
                               "set Output directory = results\n"
                               "subsection Wallette\n"
                               "  set Model                = detailed\n"
                               "  set Courses              = 3\n"
                               "  set Length in bricks     = 1\n"
                               "  set Splitting interfaces = true\n"
                               "  set Strength scatter     = 0.1\n"
                               "  set Assembly threads     = 2\n"
                               "  set Protocol             = monotonic\n"
                               "  set Number of steps      = 5\n";

  void
  check(const std::string &name, const std::string &text)
  {
    const std::string file = "error_wallette_hostile_" + name + ".prm";
    testing::write_file(file, text);
    const testing::Result r      = testing::run({file});
    const std::string     prefix = "masonry: error: ";
    std::cout << name
              << ": exit code non-zero: " << (r.exit_code != 0 ? "yes" : "no")
              << "\nlines on stderr: " << testing::n_lines(r.err)
              << "\nstarts with 'masonry: error:': "
              << (r.err.rfind(prefix, 0) == 0 ? "yes" : "no")
              << "\nstack trace: "
              << (r.err.find("Stacktrace") != std::string::npos ||
                      r.err.find("-----") != std::string::npos ?
                    "yes" :
                    "no")
              << '\n';
    std::cout << "stderr: " << testing::normalise(r.err);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check("tensile_strength",
        wallette + "end\n"
                   "subsection Brick material\n"
                   "  set Model = damage plasticity\n"
                   "  subsection Damage plasticity\n"
                   "    set Tensile strength = 1e-300\n"
                   "  end\n"
                   "end\n");
  check("derived_entry",
        wallette + "end\n"
                   "subsection Brick material\n"
                   "  set Model = damage plasticity\n"
                   "  subsection Damage plasticity\n"
                   "    set Tensile fracture energy = 1e-300\n"
                   "  end\n"
                   "end\n");
  check("joint_thickness",
        wallette + "  set Joint thickness = 0.3\n"
                   "end\n"
                   "subsection Brick material\n"
                   "  set Model = damage plasticity\n"
                   "end\n");
  for (const auto &[name, entry] :
       {std::pair<std::string, std::string>{"tensile_strength",
                                            "Brick material/Damage "
                                            "plasticity/Tensile strength"},
        std::pair<std::string, std::string>{"joint_thickness",
                                            "Wallette/Joint thickness"}})
    {
      const testing::Result v =
        testing::run({"--validate", "error_wallette_hostile_" + name + ".prm"});
      std::cout << name << ", --validate: exit code non-zero: "
                << (v.exit_code != 0 ? "yes" : "no") << "\nnames the entry: "
                << (v.err.find("entry '" + entry + "'") != std::string::npos ?
                      "yes" :
                      "no")
                << '\n';
    }
}
