/**
 * The direct check of a prescribed support motion (`Check support motion`,
 * rigid_blocks::check_support_motion()) against independent computations:
 *
 * - A circular barrel vault (span 6 m, rise 3 m, length 6 m, thickness
 *   0.3 m, 4 x 4 blocks per half, 3 stations per edge) bonded to both
 *   springings; the right one moves by (s y, 0, -5 mm), s = 0.01 / 6. At
 *   the springing the support face of a block is the plane z = 0 with
 *   contact points at x = R -+ t/2 (intrados, extrados) and at the
 *   stations y_j of the block's edge (length L_b = 1.5 m). A rigid motion
 *   t + θ × (p − c) can follow the shear s y in x only by θ_z = -s, which
 *   moves the intrados and extrados points apart in y. Least squares over
 *   θ_z (the other components fit exactly), with y', x' the coordinates
 *   about the points' centre, X = N_stations Σ_k x'_k² and Y = 2 Σ_j y'_j²:
 *   θ_z = -s Y / (X + Y), residuals r_x = s X y' / (X + Y) and
 *   r_y = -s Y x' / (X + Y), so the largest misfit (at y' = ±L_b/2,
 *   x' = ±t/2) is s sqrt(X² L_b²/4 + Y² t²/4) / (X + Y), the same for the
 *   4 blocks of the right springing. The run must end `incompatible`
 *   without an LP, naming that edge, a block on it and that misfit
 *   (1e-9), for Mohr-Coulomb and for no tension no sliding joints.
 * - The same with `Check support motion = false`: the LP's own verdict is
 *   `incompatible` too, located by its phase 1 (kind `lp`), whose least
 *   total misfit cannot exceed that of the least-squares fits (the sum of
 *   |residual components| at their points: the joints between blocks
 *   admit any jump with a compression cap, so the fitted motions are
 *   feasible for it).
 * - Blocks tied where no joint can open: with joints that admit no jump at
 *   all (an interface model registered here, without yield planes) the
 *   whole vault is one rigid body, so its support points on both
 *   springings are fitted by one rigid motion. The left springing fixed,
 *   the right one dropping by δ = 1 cm: with every support point in the
 *   plane z = 0 at x = ±a, ±b (a, b = R -+ t/2) the fit is a drop of δ/2
 *   and a rotation θ_y = (δ/2)(a + b)/(a² + b²) about the y axis, whose
 *   largest misfit is (δ/2) max(|1 - a(a + b)/(a² + b²)|,
 *   |1 - b(a + b)/(a² + b²)|), found as one group (1e-9); each block on its
 *   own could follow (a translation).
 * - No false positives: a rigid motion of both springings (a translation
 *   and a small rotation of the whole vault) is followed by the rigid
 *   vault: `optimal`, a largest misfit of 0 (1e-12 m), and the loads' work
 *   is the weight times the drop of the vault's centroid (x = 0 and
 *   y = 3 m by symmetry), 1e-7 relative, with either joint model; and on
 *   every shipped settlement example, unilateral and bonded, the status
 *   (and an optimum) is the same with the check as without.
 */
#include <masonry/rigid_blocks/interface_model.h>

#include <deal.II/base/mpi.h>

#include <filesystem>

#include "vault_tests.h"

using namespace vault_tests;

namespace
{
  /** Joints that admit no jump: no yield plane at all. */
  class RigidJoints : public masonry::rigid_blocks::InterfaceModel
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &)
    {}

    void
    parse_parameters(dealii::ParameterHandler &) override
    {}

    const std::vector<masonry::rigid_blocks::YieldPlane> &
    yield_planes() const override
    {
      return planes;
    }

  private:
    std::vector<masonry::rigid_blocks::YieldPlane> planes;
  };

  const std::string mohr_coulomb =
    "  set Model = mohr coulomb\n  subsection Mohr coulomb\n"
    "    set Cohesion = 2e4\n    set Friction coefficient = 0.5\n"
    "    set Tensile strength = 3e4\n    set Compressive strength = 2.6e6\n"
    "  end\n";
  const std::string no_tension = "  set Model = no tension no sliding\n";

  /** barrel_prm() with bonded supports, both springings supported, and
   * @p extra lines in the Settlement subsection. */
  std::string
  bonded_barrel(const std::string &settlement,
                const std::string &joints,
                const std::string &extra     = "",
                const double       thickness = 0.3)
  {
    std::string       prm  = barrel_prm(4, settlement, joints);
    const std::string from = "  set Thickness = 0.3\n";
    prm.replace(prm.find(from),
                from.size(),
                "  set Thickness = " + std::to_string(thickness) + "\n");
    const std::string at = "subsection Settlement\n";
    prm.insert(prm.find(at) + at.size(),
               "  set Support contact = bonded\n" + extra);
    return prm + "subsection Postprocess\n  subsection Rigid blocks\n"
                 "    set List of postprocessors =\n  end\nend\n";
  }

  /** The shear case's largest and root-mean-square misfit, m. */
  std::pair<double, double>
  shear_misfit()
  {
    const double s = 0.01 / 6, t = 0.3, Lb = 1.5;
    // three stations at y' = -Lb/2, 0, Lb/2; x' = -+t/2
    const double X = 3 * 2 * (t / 2) * (t / 2);
    const double Y = 2 * 2 * (Lb / 2) * (Lb / 2);
    const double largest =
      s * std::sqrt(X * X * Lb * Lb / 4 + Y * Y * t * t / 4) / (X + Y);
    // mean over the six points of r_x² + r_y²
    const double mean_y2 = 2 * (Lb / 2) * (Lb / 2) / 3, mean_x2 = t * t / 4;
    const double rms =
      s * std::sqrt(X * X * mean_y2 + Y * Y * mean_x2) / (X + Y);
    return {largest, rms};
  }

  /** The sum over the six points of |r_x| + |r_y| of one block's fit, m. */
  double
  shear_l1_misfit()
  {
    const double s = 0.01 / 6, t = 0.3, Lb = 1.5;
    const double X = 3 * 2 * (t / 2) * (t / 2);
    const double Y = 2 * 2 * (Lb / 2) * (Lb / 2);
    // |y'| = Lb/2 at four points, 0 at two; |x'| = t/2 at all six
    return s * (X * 4 * Lb / 2 + Y * 6 * t / 2) / (X + Y);
  }

  void
  check_shear(const std::string &name, const std::string &joints)
  {
    const masonry::Json s =
      run(name, bonded_barrel("0.01*y/6; 0; -0.005", joints));
    const auto [largest, rms] = shear_misfit();
    const auto &x             = s.at("incompatibility");
    const auto  block = static_cast<unsigned int>(x.at("block").get<double>());
    check(s.at("status").get<std::string>() == "incompatible" &&
            x.at("kind").get<std::string>() == "support" &&
            s.at("lp_solves").get<double>() == 0,
          name + ": incompatible by the direct check, no LP solved");
    check(x.at("support_edge").get<std::string>() == "springing right" &&
            x.at("centroid").at(0).get<double>() > 0 &&
            x.at("count").get<double>() == 4,
          name + ": the 4 blocks of the right springing, edge and block named");
    check(relative(x.at("misfit").get<double>(), largest) < 1e-9 &&
            relative(x.at("rms_misfit").get<double>(), rms) < 1e-9,
          name + ": misfit and its RMS as by hand (1e-9)");
    const std::string e = s.at("explanation").get<std::string>();
    check(e.find("springing right") != std::string::npos &&
            e.find("block " + std::to_string(block)) != std::string::npos &&
            e.find(" m at (") != std::string::npos,
          name + ": the explanation names the edge, the block, its position "
                 "and the misfit");
    std::cout << "  misfit " << std::setprecision(6) << largest << " m, rms "
              << rms << " m\n";
  }

  /** The settlement examples of prm/examples (not the adapted ones). */
  std::vector<std::string>
  examples()
  {
    std::vector<std::string> files;
    for (const auto &f : std::filesystem::directory_iterator(
           std::string(MASONRY_SOURCE_DIR) + "/prm/examples"))
      {
        const std::string name = f.path().filename().string();
        std::ifstream     in(f.path());
        std::stringstream text;
        text << in.rdbuf();
        if (name.find("adapted") == std::string::npos &&
            text.str().find("set Analysis = settlement") != std::string::npos)
          files.push_back(f.path().string());
      }
    std::sort(files.begin(), files.end());
    return files;
  }
} // namespace

MASONRY_REGISTER_INTERFACE_MODEL(RigidJoints,
                                 "rigid joints",
                                 "Joints that admit no jump (a test).")

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // incompatible, found by the direct check
  check_shear("shear-mohr-coulomb", mohr_coulomb);
  check_shear("shear-no-tension", no_tension);

  // the same left to the LP
  {
    const masonry::Json s =
      run("shear-lp",
          bonded_barrel("0.01*y/6; 0; -0.005",
                        mohr_coulomb,
                        "  set Check support motion = false\n"));
    const auto &x = s.at("incompatibility");
    check(s.at("status").get<std::string>() == "incompatible" &&
            x.at("kind").get<std::string>() == "lp" &&
            s.at("lp_message").get<std::string>().find("phase 1") !=
              std::string::npos,
          "without the check: incompatible by the LP's phase 1");
    const double bound = 4 * shear_l1_misfit();
    check(x.at("total_misfit").get<double>() > 0 &&
            x.at("total_misfit").get<double>() <= bound * (1 + 1e-6),
          "its least total misfit is positive and at most that of the "
          "least-squares fits");
  }

  // blocks tied by joints that cannot open: one group
  {
    const masonry::Json s =
      run("rigid-joints",
          bonded_barrel("0; 0; -0.01", "  set Model = rigid joints\n"));
    const double a = 2.85, b = 3.15, q = (a + b) / (a * a + b * b);
    const double largest =
      0.005 * std::max(std::abs(1 - a * q), std::abs(1 - b * q));
    const auto &x = s.at("incompatibility");
    check(s.at("status").get<std::string>() == "incompatible" &&
            x.at("kind").get<std::string>() == "support" &&
            x.at("count").get<double>() == 1 &&
            s.at("support_check").at("supported_groups").get<double>() == 1,
          "rigid joints: the vault is one group, which cannot follow");
    check(relative(x.at("misfit").get<double>(), largest) < 1e-9,
          "rigid joints: the misfit of one rigid motion as by hand (1e-9)");
    std::cout << "  misfit " << std::setprecision(6) << largest << " m\n";
  }

  // a rigid motion of every support: followed, and the work is the
  // weight times the drop of the centroid
  const std::string rigid = "0.001 + 0.0003*z + 0.0002*y; "
                            "-0.002 - 0.0002*x - 0.0005*z; "
                            "-0.005 + 0.0005*y - 0.0003*x";
  for (const auto &[name, joints] :
       {std::make_pair(std::string("rigid-mohr-coulomb"), mohr_coulomb),
        std::make_pair(std::string("rigid-no-tension"), no_tension)})
    {
      const masonry::Json s =
        run(name,
            bonded_barrel(
              rigid,
              joints,
              "  set Settling edges = springing left, springing right\n",
              0.5));
      const double drop = -(-0.005 + 0.0005 * 3);
      check(s.at("status").get<std::string>() == "optimal" &&
              s.at("support_check").at("largest_misfit").get<double>() < 1e-12,
            name + ": a rigid motion of both springings is followed");
      check(relative(s.at("objective").get<double>(),
                     s.at("total_weight").get<double>() * drop) < 1e-7,
            name + ": work = weight x drop of the centroid (1e-7)");
    }

  // the shipped examples, unilateral and bonded: the same status with and
  // without the check
  unsigned int n = 0, same = 0;
  for (const auto &file : examples())
    for (const std::string contact : {"unilateral", "bonded"})
      {
        std::ifstream     in(file);
        std::stringstream text;
        text << in.rdbuf();
        const std::string stem = std::filesystem::path(file).stem().string();
        const std::string tail =
          "subsection Settlement\n  set Support contact = " + contact +
          "\n  set Write picture = false\n";
        const std::string off = "  set Check support motion = false\n";
        const std::string end =
          "end\nsubsection Postprocess\n  subsection Rigid blocks\n"
          "    set List of postprocessors =\n  end\nend\n";
        const masonry::Json with =
          run(stem + "-" + contact, text.str() + tail + end);
        const masonry::Json without =
          run(stem + "-" + contact + "-lp", text.str() + tail + off + end);
        const std::string status = with.at("status").get<std::string>();
        ++n;
        if (status == without.at("status").get<std::string>() &&
            (status != "optimal" ||
             std::abs(with.at("objective").get<double>() -
                      without.at("objective").get<double>()) <=
               1e-8 *
                 std::max(1., std::abs(with.at("objective").get<double>()))))
          ++same;
      }
  check(n == 10 && same == n,
        "every settlement example, unilateral and bonded: the same status "
        "and optimum with the check as without");
}
