/**
 * A brick material defined in this file, with three state variables of its
 * own, runs a cyclic wallette through the model with no edit elsewhere
 * (issue 15, acceptance (a) and (e)): an isotropic damage law sigma =
 * (1 - d) C0 : eps with the equivalent strain kappa = |eps| (the largest
 * reached), d = 0.5 (1 - kappa_0 / kappa) and the largest mean pressure
 * reached. Checked: the run completes and damages the bricks (curve.csv
 * column brick_damage, the material's own damage name); a run stopped by
 * `Maximum steps' and resumed from its checkpoint reproduces the
 * uninterrupted curve (1e-12); the three variables are fields of the VTU
 * output; and solution.pvd and interfaces.pvd of the resumed run list every
 * output step of the uninterrupted run; with `Output interval' = 0 the
 * last step of the cyclic run (the end of an unloading leg) is written.
 */
#include <masonry/brickwork/brick_material.h>

#include <cstdio>

#include "brickwork_tests.h"
#include "tests.h"

namespace
{
  using namespace dealii;
  using namespace masonry::brickwork;

  /** Isotropic damage with three state variables (see above). */
  class TestDamage : public BrickMaterial
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Threshold strain",
                        "2e-4",
                        Patterns::Double(0),
                        "kappa_0 (dimensionless)");
    }
    void
    parse_parameters(ParameterHandler &prm) override
    {
      kappa_0 = prm.get_double("Threshold strain");
    }
    bool
    is_linear() const override
    {
      return false;
    }
    double
    youngs_modulus() const override
    {
      return 10e9;
    }
    double
    poissons_ratio() const override
    {
      return 0.2;
    }
    std::vector<StateVariable>
    state_variables() const override
    {
      return {{"kappa", 1}, {"damage", 1}, {"max_pressure", 1}};
    }
    std::vector<std::string>
    damage_names() const override
    {
      return {"damage"};
    }
    void
    damages(ConstStateView s, ArrayView<double> d) const override
    {
      d[0] = s[1];
    }
    void
    evaluate(const SymmetricTensor<2, 3> &strain,
             ConstStateView               old,
             const BrickPoint &,
             StateView              updated,
             SymmetricTensor<2, 3> &stress,
             SymmetricTensor<4, 3> &tangent) const override
    {
      const SymmetricTensor<4, 3> C     = elastic_stiffness();
      const double                trial = strain.norm();
      const double                kappa = std::max(old[0], trial);
      const double d = kappa > kappa_0 ? 0.5 * (1 - kappa_0 / kappa) : 0.;
      stress         = (1 - d) * (C * strain);
      tangent        = (1 - d) * C;
      if (trial > old[0] && trial > kappa_0)
        // loading: d depends on the strain through kappa = |eps|
        tangent -= 0.5 * kappa_0 / (kappa * kappa * kappa) *
                   outer_product(C * strain, strain);
      updated[0] = kappa;
      updated[1] = d;
      updated[2] = std::max(old[2], -trace(stress) / 3);
    }

  private:
    double kappa_0 = 2e-4;
  };

  /** The times of the steps of an XDMF file, as written. */
  std::vector<std::string>
  xdmf_times(const std::string &file)
  {
    std::ifstream            in(file);
    std::string              line;
    std::vector<std::string> times;
    while (std::getline(in, line))
      if (line.find("<Time Value") != std::string::npos)
        times.push_back(line.substr(line.find("<Time Value")));
    return times;
  }
} // namespace

MASONRY_REGISTER_BRICK_MATERIAL(TestDamage,
                                "test damage",
                                "isotropic damage defined in a test")

int
main(int argc, char **argv)
{
  using namespace brickwork_tests;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                wallette =
    "set Courses = 2\nset Length in bricks = 1\n"
    "set Elements along the length = 2\nset Elements along the width = 1\n"
    "set Elements along the height = 1\nset Protocol = cyclic\n"
    "set Cycle amplitudes = 0.0005, 0.001\nset Target strain = 0.001\n"
    "set Number of steps = 10\nset Unloading stress = 0\n"
    "set Write VTU = true\nset Output interval = 3\n";
  const std::string plugins =
    "subsection Brick material\nset Model = test damage\nend\n"
    "subsection Interface law\nset Law = elastic\nend\n";
  const auto full       = run("full", prm(wallette, plugins));
  const auto c          = curve("full");
  double     max_damage = 0;
  for (const auto &row : c)
    max_damage = std::max(max_damage, row.back());
  check(full.at("status").get<std::string>() == "completed" &&
          max_damage > 0.1 &&
          std::abs(full.at("max_brick_damage").get<double>() - max_damage) <
            1e-10,
        "the test material runs the cyclic wallette and its damage reaches "
        "the curve and the summary");
  const auto stopped =
    run("resumed", prm(wallette + "set Maximum steps = 13\n", plugins));
  const auto resumed =
    run("resumed", prm(wallette + "set Resume = true\n", plugins));
  const auto   a = curve("full"), b = curve("resumed");
  const double diff = curve_difference(a, b);
  check(stopped.at("status").get<std::string>() == "interrupted" &&
          resumed.at("status").get<std::string>() == "completed" &&
          diff < 1e-12,
        "checkpointed after 13 steps and resumed: the curve of the "
        "uninterrupted run (1e-12)");
  std::ifstream     vtu("results/resumed/solution_0000.0.vtu");
  const std::string text((std::istreambuf_iterator<char>(vtu)),
                         std::istreambuf_iterator<char>());
  check(text.find("Name=\"kappa\"") != std::string::npos &&
          text.find("Name=\"damage\"") != std::string::npos &&
          text.find("Name=\"max_pressure\"") != std::string::npos,
        "the three state variables are fields of solution_NNNN.vtu");
  check(contains(pvd_entries("results/resumed/solution.pvd"),
                 pvd_entries("results/full/solution.pvd")) &&
          contains(pvd_entries("results/resumed/interfaces.pvd"),
                   pvd_entries("results/full/interfaces.pvd")),
        "solution.pvd and interfaces.pvd of the resumed run list every "
        "output step of the uninterrupted run");
  // Output interval = 0: the initial and the final state only; a cyclic
  // run ends on an unloading leg, whose last step is written too
  std::string only_ends = wallette;
  only_ends.replace(only_ends.find("Output interval = 3"),
                    std::string("Output interval = 3").size(),
                    "Output interval = 0");
  run("ends", prm(only_ends, plugins));
  const auto        ends_curve = curve("ends");
  const std::string last_file  = [&] {
    char name[32];
    std::snprintf(name,
                  sizeof(name),
                  "_%04d.",
                  int(ends_curve.empty() ? -1 : ends_curve.back()[0]));
    return std::string(name);
  }();
  const auto solution_ends   = pvd_entries("results/ends/solution.pvd");
  const auto interfaces_ends = pvd_entries("results/ends/interfaces.pvd");
  check(solution_ends.size() == 2 && interfaces_ends.size() == 2 &&
          solution_ends.back().find(last_file) != std::string::npos &&
          interfaces_ends.back().find(last_file) != std::string::npos,
        "Output interval = 0: solution.pvd and interfaces.pvd list the "
        "initial state and the last step of the curve");
  // the same with the brick fields as HDF5: solution.xdmf
  const std::string hdf5 = wallette + "set Output format = hdf5\n";
  run("full_hdf5", prm(hdf5, plugins));
  run("resumed_hdf5", prm(hdf5 + "set Maximum steps = 13\n", plugins));
  run("resumed_hdf5", prm(hdf5 + "set Resume = true\n", plugins));
  const auto all = xdmf_times("results/full_hdf5/solution.xdmf");
  check(all.size() > 3 &&
          contains(xdmf_times("results/resumed_hdf5/solution.xdmf"), all),
        "Output format = hdf5: solution.xdmf of the resumed run lists every "
        "output step of the uninterrupted run");
  // the law has no IMPL-EX extrapolation (its extrapolates() is false):
  // under `Damage integration = implex' the run stops before its first
  // step with one line naming the entry, instead of running the implicit
  // law without extrapolation or IMPL-EX's damage error
  testing::write_file("implex.prm",
                      "set Output directory = results/implex\n" +
                        prm(wallette + "set Damage integration = implex\n",
                            plugins));
  const testing::Result refused = testing::run({"implex.prm"});
  check(refused.exit_code != 0 && testing::n_lines(refused.err) == 1 &&
          refused.err.rfind("masonry: error: ", 0) == 0 &&
          refused.err.find("`Brick material/Model'") != std::string::npos &&
          !std::ifstream("results/implex/curve.csv"),
        "Damage integration = implex with a law that does not extrapolate: "
        "a one-line error naming `Brick material/Model', no curve");
  const testing::Result validated = testing::run({"--validate", "implex.prm"});
  check(validated.exit_code != 0 && testing::n_lines(validated.err) == 1 &&
          validated.err.find("`Brick material/Model'") != std::string::npos,
        "--validate refuses the same file with the same one-line error");
}
