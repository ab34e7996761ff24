/**
 * Runs that cannot go on stop with a message, their results so far,
 * summary.json status `failed' with `complete' false and exit code 1
 * (issue 18, deliverables 2 and 3).
 *
 * (1) Stall: damage-plasticity bricks under implicit integration with
 * `Maximum Newton iterations = 2', `Step growth factor = 1' and `Maximum
 * cut-backs = 60'. Every step that needs a third iteration is halved, and
 * nothing makes a step larger again, so the steps shrink for ever (before
 * the stall detection the run crawled on with steps of 1/1000 of the
 * nominal one and less; the bound nominal / 2^60 on a failing step is far
 * away). It must stop
 * as `stalled' once 50 steps in a row are below 1e-3 x the nominal step:
 * checked on curve.csv, independently of the code's counter, the last 50
 * platen increments are below that floor and the step before them is not
 * (the stop is the first moment the rule allows).
 *
 * (2) A non-finite stress inside the solve: a brick material of this file
 * returns NaN once the strain passes 1e-4 (no valid parameter file of the
 * shipped laws produces a NaN any more: --validate rejects the values that
 * did). Halving the step cannot help, so after the cut-backs the run stops
 * with a message naming the stage (the stresses of the bricks) and the
 * entries to check (subsection Brick material). (The steps, halved before
 * the breaking point again and again, stall first: the stall is reported
 * as the NaN that caused it.) The curve stops at the last converged step,
 * still the elastic response (secant modulus = initial modulus, to 1e-6:
 * the Newton tolerance is 1e-8), and every
 * number written is finite.
 *
 * (3) The same material with NaN damages but finite stresses under
 * IMPL-EX: the NaN is in the update after the step (a NaN damage error
 * used to be dropped by std::max and the run went on); it stops at once
 * naming the damages of the bricks.
 */
#include <masonry/brickwork/brick_material.h>

#include "brickwork_tests.h"
#include "tests.h"

namespace
{
  using namespace dealii;
  using namespace masonry::brickwork;

  /** Linear elastic up to `Breaking strain' (largest |eps| reached), then a
   * NaN stress or (with `NaN damage') a NaN damage. */
  class TestBreaking : public BrickMaterial
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Breaking strain",
                        "1e-4",
                        Patterns::Double(0),
                        "(dimensionless)");
      prm.declare_entry("NaN damage", "false", Patterns::Bool(), "");
    }
    void
    parse_parameters(ParameterHandler &prm) override
    {
      breaking   = prm.get_double("Breaking strain");
      nan_damage = prm.get_bool("NaN damage");
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
      return {{"kappa", 1}};
    }
    std::vector<std::string>
    damage_names() const override
    {
      return {"damage"};
    }
    void
    damages(ConstStateView s, ArrayView<double> d) const override
    {
      d[0] = s[0] > breaking ? std::numeric_limits<double>::quiet_NaN() : 0.;
    }
    void
    evaluate(const SymmetricTensor<2, 3> &strain,
             ConstStateView               old,
             const BrickPoint &,
             StateView              updated,
             SymmetricTensor<2, 3> &stress,
             SymmetricTensor<4, 3> &tangent) const override
    {
      tangent    = elastic_stiffness();
      stress     = tangent * strain;
      updated[0] = std::max(old[0], strain.norm());
      if (!nan_damage && updated[0] > breaking)
        stress[0][0] = std::numeric_limits<double>::quiet_NaN();
    }

    // the stress does not depend on the state: the IMPL-EX response with
    // extrapolated states is the elastic one, and the law says that it
    // extrapolates (there is nothing to extrapolate)
    void
    evaluate_extrapolated(const SymmetricTensor<2, 3> &strain,
                          ConstStateView,
                          ConstStateView,
                          const double,
                          const BrickPoint &,
                          SymmetricTensor<2, 3> &stress,
                          SymmetricTensor<4, 3> &tangent) const override
    {
      tangent = elastic_stiffness();
      stress  = tangent * strain;
    }
    bool
    extrapolates() const override
    {
      return true;
    }

  private:
    double breaking   = 1e-4;
    bool   nan_damage = false;
  };

  /** masonry on @p name.prm with @p text into results/NAME. */
  std::pair<testing::Result, masonry::Json>
  failing_run(const std::string &name, const std::string &text)
  {
    testing::write_file(name + ".prm",
                        "set Output directory = results/" + name + "\n" + text);
    const testing::Result r = testing::run({name + ".prm"});
    return {r,
            masonry::parse_json(
              testing::read_file("results/" + name + "/summary.json"))};
  }

  /** The failure contract, printed; @p stage must be in the message. */
  void
  check_failure(const std::string                               &name,
                const std::pair<testing::Result, masonry::Json> &run,
                const std::string                               &analysis,
                const std::vector<std::string>                  &words)
  {
    using brickwork_tests::check;
    const auto &[r, summary] = run;
    check(r.exit_code == 1 && testing::n_lines(r.err) == 1 &&
            r.err.rfind("masonry: error: ", 0) == 0,
          name + ": exit code 1, one error line");
    check(summary.at("status").get<std::string>() == "failed" &&
            !summary.at("complete").get<bool>() &&
            summary.at("analysis_status").get<std::string>() == analysis,
          name +
            ": summary.json status failed, complete false, analysis "
            "status " +
            analysis);
    bool named = summary.contains("message");
    for (const auto &w : words)
      named =
        named &&
        summary.at("message").get<std::string>().find(w) != std::string::npos &&
        r.err.find(w) != std::string::npos;
    std::string list;
    for (const auto &w : words)
      list += (list.empty() ? "'" : ", '") + w + "'";
    check(named, name + ": the message names " + list);
    bool finite = true;
    for (const auto &row : brickwork_tests::curve(name))
      for (const double v : row)
        finite = finite && std::isfinite(v);
    check(finite && brickwork_tests::curve(name).size() ==
                      summary.at("steps").get<double>() + 1,
          name + ": curve.csv holds every converged step, all finite");
  }
} // namespace

MASONRY_REGISTER_BRICK_MATERIAL(TestBreaking,
                                "test breaking",
                                "elastic, then NaN (a test of the guards)")

int
main(int argc, char **argv)
{
  using namespace brickwork_tests;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // (1) the stall
  const double target = 0.008, n_steps = 80;
  const auto   stall = failing_run(
    "stall",
    prm("set Courses = 7\nset Length in bricks = 2\n"
          "set Elements along the length = 2\n"
          "set Elements along the width = 1\n"
          "set Elements along the height = 1\n"
          "set Platen lateral restraint = fixed\n"
          "set Target strain = 0.008\nset Number of steps = 80\n"
          "set Damage integration = implicit\n"
          "set Maximum Newton iterations = 2\n"
          "set Maximum cut-backs = 60\n"
          "set Step growth factor = 1\n",
        "subsection Bond\nset Pattern = stretcher\nend\n"
          "subsection Brick material\nset Model = damage plasticity\nend\n"
          "subsection Interface law\nset Law = bilinear\n"
          "set Normal stiffness = 2.5e11\nset Shear stiffness = 1.03e11\n"
          "end\n"));
  check_failure("stall",
                stall,
                "stalled",
                {"no progress", "Maximum Newton iterations"});
  const auto   c = curve("stall");
  const double nominal =
                 target * stall.second.at("height").get<double>() / n_steps,
               floor = 1e-3 * nominal;
  bool below         = c.size() > 52;
  for (unsigned int j = c.size() - 50; below && j < c.size(); ++j)
    below = c[j][1] - c[j - 1][1] < floor;
  check(below && c[c.size() - 51][1] - c[c.size() - 52][1] >= floor,
        "stall: stopped after exactly 50 steps in a row below 1e-3 x the "
        "nominal step (from curve.csv)");

  // (2) and (3): the NaN guards
  const std::string small = "set Courses = 2\nset Length in bricks = 1\n"
                            "set Elements along the length = 2\n"
                            "set Elements along the width = 1\n"
                            "set Elements along the height = 1\n"
                            "set Target strain = 0.001\n"
                            "set Number of steps = 10\n";
  const std::string material =
    "subsection Brick material\nset Model = test breaking\n";
  const std::string elastic_joints =
    "subsection Interface law\nset Law = elastic\nend\n";
  const auto nan_stress =
    failing_run("nan_stress",
                prm(small + "set Damage integration = implicit\n",
                    material + "end\n" + elastic_joints));
  check_failure("nan_stress",
                nan_stress,
                "failed",
                {"not finite", "the stresses of the bricks", "Brick material"});
  // what was written is the elastic response: the secant modulus of the
  // last converged step is the one of the first step
  const auto s = curve("nan_stress");
  check(s.size() > 2 &&
          std::abs(s.back()[4] / s.back()[2] / (s[1][4] / s[1][2]) - 1) < 1e-6,
        "nan_stress: the last step written is still the elastic response");
  const auto nan_damage =
    failing_run("nan_damage",
                prm(small + "set Damage integration = implex\n",
                    material +
                      "subsection Test breaking\n"
                      "set NaN damage = true\nend\nend\n" +
                      elastic_joints));
  check_failure("nan_damage",
                nan_damage,
                "failed",
                {"not finite", "the damages of the bricks", "IMPL-EX"});
}
