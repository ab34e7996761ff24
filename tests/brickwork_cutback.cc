/**
 * Softening that needs smaller steps. (1) Two bricks pulled apart in two
 * large steps with at most 2 Newton iterations a step (and no chord
 * corrections): the steps are cut back and the run completes. (2) Soft bricks
 * (E = 0.1 GPa) in series with a brittle joint snap back: no equilibrium exists
 * beyond the peak under displacement control, so the run stops with status `not
 * converged` and a message, after writing the curve up to the last converged
 * step. In both cases every value written is finite. (3) Input errors found by
 * --validate as one line naming the file, the line and the entry: a mesh
 * that does not fit the english bond's closers, a fracture energy below
 * f_t^2 / (2 k_n) (the law would snap back at a point), a sideways platen
 * motion with frictionless platens, a nonlocal unit law with implicit
 * damage integration or with the IMPL-EX floor correction, an english bond
 * whose headers (0.31 m with the joint) do not span two stretcher widths
 * (2 x 0.1125 m).
 */
#include "brickwork_tests.h"
#include "tests.h"

using namespace brickwork_tests;

namespace
{
  std::string
  text(const double E, const unsigned int steps, const unsigned int newton)
  {
    std::ostringstream w, p;
    w << "set Courses = 2\nset Length in bricks = 1\n"
      << "set Platen direction = 0, 0, 1\n"
      << "set Target strain = 0.004\n"
      << "set Number of steps = " << steps << "\n"
      << "set Maximum Newton iterations = " << newton << "\n"
      << "set Maximum cut-backs = 6\n"
      // Newton corrections only: chord corrections, not counted against
      // `Maximum Newton iterations', converge the large steps uncut
      << "set Newton chord contraction = 0\n";
    p << "subsection Bond\nset Pattern = stack\nend\n"
      << "subsection Brick material\nsubsection Elastic\n"
      << "set Young's modulus = " << E << "\nset Poisson's ratio = 0\n"
      << "end\nend\n";
    return prm(w.str(), p.str());
  }

  bool
  finite(const std::string &name)
  {
    bool ok = true;
    for (const auto &row : curve(name))
      for (const double v : row)
        ok = ok && std::isfinite(v);
    return ok;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const masonry::Json a = run("cutback", text(10e9, 2, 2));
  check(a.at("status").get<std::string>() == "completed",
        "large steps: status completed");
  check(a.at("cut_backs").get<double>() > 0,
        "large steps: steps were cut back");
  check(finite("cutback"), "large steps: curve finite");
  check(a.at("max_damage").get<double>() == 1, "large steps: joint debonded");

  // a run without a result: exit code 1 with one line, summary.json with
  // status `failed', `complete' false and the analysis' own status
  testing::write_file("snap_back.prm",
                      "set Output directory = results/snap_back\n" +
                        text(1e8, 10, 20));
  const testing::Result snap = testing::run({"snap_back.prm"});
  check(snap.exit_code == 1 &&
          std::count(snap.err.begin(), snap.err.end(), '\n') == 1,
        "snap-back: exit code 1, one error line");
  const masonry::Json b =
    masonry::parse_json(testing::read_file("results/snap_back/summary.json"));
  check(b.at("status").get<std::string>() == "failed" &&
          !b.at("complete").get<bool>() &&
          b.at("analysis_status").get<std::string>() == "not converged",
        "snap-back: status failed (analysis status not converged)");
  check(b.contains("message") &&
          b.at("message").get<std::string>().find("no convergence at platen "
                                                  "displacement") == 0,
        "snap-back: message says where it stopped");
  check(finite("snap_back"), "snap-back: curve finite");
  check(curve("snap_back").size() == b.at("steps").get<double>() + 1,
        "snap-back: curve holds every converged step");
  check(std::isfinite(b.at("peak_stress").get<double>()),
        "snap-back: summary finite");

  const std::string head = "set Output directory = results\n"
                           "set Analysis = wallette\n";
  testing::write_file("mesh.prm",
                      head + "subsection Wallette\n"
                             "  set Elements along the length = 6\n"
                             "end\n"
                             "subsection Bond\n"
                             "  set Pattern = english\n"
                             "end\n");
  testing::check_error(testing::run({"--validate", "mesh.prm"}));
  testing::write_file("energy.prm",
                      head + "subsection Interface law\n"
                             "  subsection Bilinear\n"
                             "    set Mode I fracture energy = 0.01\n"
                             "  end\n"
                             "end\n");
  testing::check_error(testing::run({"--validate", "energy.prm"}));
  testing::write_file("platen.prm",
                      head + "subsection Wallette\n"
                             "  set Platen lateral restraint = free\n"
                             "  set Platen direction = 1, 0, 0\n"
                             "end\n");
  testing::check_error(testing::run({"--validate", "platen.prm"}));
  // the units' nonlocal average is made for the IMPL-EX step without the
  // floor correction: both other settings are refused by --validate
  for (
    const char *setting :
    {"Damage integration = implicit",
     "Damage integration = implex\n  set IMPL-EX floor correction = iterate"})
    {
      testing::write_file("nonlocal.prm",
                          head +
                            "subsection Wallette\n"
                            "  set " +
                            setting +
                            "\n"
                            "end\n"
                            "subsection Brick material\n"
                            "  set Model = damage plasticity\n"
                            "  subsection Damage plasticity\n"
                            "    set Nonlocal length = 0.02\n"
                            "  end\n"
                            "end\n");
      testing::check_error(testing::run({"--validate", "nonlocal.prm"}));
    }
  // the bond's own check (a header must span two stretcher widths), naming
  // the entry the file sets
  testing::write_file("english.prm",
                      head + "subsection Wallette\n"
                             "  set Brick length = 0.3\n"
                             "end\n"
                             "subsection Bond\n"
                             "  set Pattern = english\n"
                             "end\n");
  testing::check_error(testing::run({"--validate", "english.prm"}));
  testing::write_file("good.prm", head);
  const testing::Result r = testing::run({"--validate", "good.prm"});
  std::cout << "default wallette: exit code " << r.exit_code << ", " << r.out;
}
