/**
 * An interface law defined in this file, with a plastic-slip state of its
 * own, runs a cyclic wallette through the model with no edit elsewhere
 * (issue 15, acceptance (b) and (e)). The law: elastic normal response
 * t_n = k_n u_n, Coulomb friction with linear hardening of the cohesion,
 * |t_s| <= c + H kappa - mu t_n, slip along the shear traction (no
 * dilatancy); state = plastic slip (2 components) and accumulated slip
 * kappa.
 *
 * The specimen: two stack-bonded bricks with one bed joint, bricks a
 * million times stiffer than the joint, so the jump of the joint is the
 * platen's motion, which goes sideways and down, d = (2, 0, -1)/sqrt(5).
 * At platen displacement u the joint slides a = 2u/sqrt(5) and closes
 * b = u/sqrt(5); while it slips forward, kappa = (k_s a - mu k_n b - c) /
 * (k_s + H), and kappa is the largest value reached (no slip back in the
 * unloadings here). The shear traction is k_s (a - kappa), the normal
 * traction -k_n b, and the platen stress along d is (2 t_s + k_n b) /
 * sqrt(5). Checked against this: every point of the cyclic curve (elastic
 * stiffness from the penalties, slip only past the friction limit,
 * hardening, elastic unloading) and the state fields of every interfaces
 * VTU file. With deformable bricks and no friction, the run converges
 * without cut-backs (a law without damage variables changes the tangent:
 * the model must not keep solving with the factorisation of the elastic
 * matrix). A run stopped by `Maximum steps' and resumed from its
 * checkpoint gives the uninterrupted curve (1e-12) and lists every output
 * step of it in its PVD files.
 */
#include <masonry/brickwork/interface_law.h>

#include "brickwork_tests.h"

namespace
{
  using namespace dealii;
  using namespace masonry::brickwork;

  /** Coulomb friction with hardening and plastic slip (see above). */
  class TestFriction : public InterfaceLaw
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Cohesion", "0.1e6", Patterns::Double(0), "c, Pa");
      prm.declare_entry("Friction coefficient",
                        "0.5",
                        Patterns::Double(0),
                        "mu (dimensionless)");
      prm.declare_entry("Hardening modulus",
                        "1e10",
                        Patterns::Double(0),
                        "H, Pa/m");
    }
    void
    parse_parameters(ParameterHandler &prm) override
    {
      c  = prm.get_double("Cohesion");
      mu = prm.get_double("Friction coefficient");
      H  = prm.get_double("Hardening modulus");
    }
    std::vector<StateVariable>
    state_variables() const override
    {
      return {{"plastic_slip", 2}, {"accumulated_slip", 1}};
    }
    void
    evaluate(const Local3  &jump,
             ConstStateView old,
             const InterfacePoint &,
             StateView updated,
             Local3   &t,
             Local33  &D) const override
    {
      const double kn = normal_stiffness, ks = shear_stiffness;
      for (auto &row : D)
        row = {{0, 0, 0}};
      std::copy(old.begin(), old.end(), updated.begin());
      t[0]                  = kn * jump[0];
      D[0][0]               = kn;
      const double trial[2] = {ks * (jump[1] - old[0]),
                               ks * (jump[2] - old[1])};
      const double norm     = std::hypot(trial[0], trial[1]);
      const double f        = norm + mu * t[0] - c - H * old[2];
      if (f <= 0)
        {
          t[1]    = trial[0];
          t[2]    = trial[1];
          D[1][1] = D[2][2] = ks;
          return;
        }
      // return mapping along the trial direction
      const double n[2]  = {trial[0] / norm, trial[1] / norm};
      const double slip  = f / (ks + H);
      const double shear = norm - ks * slip;
      t[1]               = shear * n[0];
      t[2]               = shear * n[1];
      updated[0]         = old[0] + slip * n[0];
      updated[1]         = old[1] + slip * n[1];
      updated[2]         = old[2] + slip;
      for (unsigned int i = 0; i < 2; ++i)
        {
          D[1 + i][0] = -ks * mu * kn / (ks + H) * n[i];
          for (unsigned int j = 0; j < 2; ++j)
            D[1 + i][1 + j] =
              ks * H / (ks + H) * n[i] * n[j] +
              ks * shear / norm * ((i == j ? 1. : 0.) - n[i] * n[j]);
        }
    }

    double c = 0.1e6, mu = 0.5, H = 1e10;
  };

  /** The values of DataArray @p name of an ASCII VTU file. */
  std::vector<double>
  vtu_array(const std::string &file, const std::string &name)
  {
    std::ifstream       in(file);
    std::string         line;
    std::vector<double> values;
    bool                inside = false;
    while (std::getline(in, line))
      {
        if (line.find("Name=\"" + name + "\"") != std::string::npos)
          inside = true;
        else if (inside && line.find("</DataArray>") != std::string::npos)
          break;
        else if (inside)
          values.push_back(std::stod(line));
      }
    return values;
  }
} // namespace

MASONRY_REGISTER_INTERFACE_LAW(TestFriction,
                               "test friction",
                               "Coulomb friction with hardening, in a test")

int
main(int argc, char **argv)
{
  using namespace brickwork_tests;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double       kn = 2e9, ks = 1e9, c = 1e4, mu = 0.5, H = 1e9;
  const double       height = 0.15; // two courses of 0.075 m
  std::ostringstream law;
  law << "subsection Interface law\nset Law = test friction\n"
      << "set Normal stiffness = " << kn << "\nset Shear stiffness = " << ks
      << "\nsubsection Test friction\nset Cohesion = " << c
      << "\nset Friction coefficient = " << mu
      << "\nset Hardening modulus = " << H << "\nend\nend\n"
      << "subsection Bond\nset Pattern = stack\nend\n"
      << "subsection Brick material\nset Model = elastic\n"
      << "subsection Elastic\nset Young's modulus = 1e15\nend\nend\n";
  // friction limit at u_y = c sqrt(5) / (2 k_s - mu k_n); the cycles go to
  // twice and four times it
  const double       u_y = c * std::sqrt(5.) / (2 * ks - mu * kn);
  std::ostringstream wallette;
  wallette << "set Courses = 2\nset Length in bricks = 1\n"
           << "set Elements along the length = 2\n"
           << "set Elements along the width = 1\n"
           << "set Elements along the height = 1\nset Protocol = cyclic\n"
           << "set Platen lateral restraint = fixed\n"
           << "set Platen direction = 2, 0, -1\n"
           << "set Cycle amplitudes = " << 2 * u_y / height << ", "
           << 4 * u_y / height << "\nset Target strain = " << 4 * u_y / height
           << "\nset Number of steps = 8\nset Unloading stress = 0\n"
           << "set Write VTU = true\nset Output interval = 2\n";
  const auto full = run("full", prm(wallette.str(), law.str()));
  const auto a    = curve("full");

  // the theory along the applied displacements of the curve
  const double        s5 = std::sqrt(5.);
  std::vector<double> kappa(a.size()), stress(a.size());
  double              largest = 0;
  for (unsigned int i = 0; i < a.size(); ++i)
    {
      const double u = a[i][1], slide = 2 * u / s5, closing = u / s5;
      largest =
        std::max(largest, (ks * slide - mu * kn * closing - c) / (ks + H));
      kappa[i]  = largest;
      stress[i] = (2 * ks * (slide - kappa[i]) + kn * closing) / s5;
    }
  double worst = 0;
  for (unsigned int i = 1; i < a.size(); ++i)
    worst = std::max(worst, std::abs(a[i][4] - stress[i]) / c);
  check(full.at("status").get<std::string>() == "completed" && a.size() > 10 &&
          kappa.back() > 0 && worst < 1e-5,
        "cyclic curve = theory of rigid bricks on the test law: elastic "
        "(4 k_s + k_n) / 5, slip past the friction limit, hardening, "
        "elastic unloading (1e-5 c)");

  // the state fields of every interfaces file against the theory
  bool         fields = true;
  unsigned int files  = 0;
  for (const std::string &entry : pvd_entries("results/full/interfaces.pvd"))
    {
      const auto         at   = entry.find("file=\"") + 6;
      const std::string  file = entry.substr(at, entry.find('"', at) - at);
      const unsigned int step = std::stoi(file.substr(file.find('_') + 1, 4));
      const auto k  = vtu_array("results/full/" + file, "accumulated_slip");
      const auto s0 = vtu_array("results/full/" + file, "plastic_slip_0");
      const auto s1 = vtu_array("results/full/" + file, "plastic_slip_1");
      // one value per face pair (two along the length)
      fields = fields && step < a.size() && k.size() == 2 && s0.size() == 2 &&
               s1.size() == 2;
      for (unsigned int f = 0; fields && f < k.size(); ++f)
        fields = std::abs(k[f] - kappa[step]) < 1e-5 * u_y &&
                 std::abs(std::hypot(s0[f], s1[f]) - kappa[step]) < 1e-5 * u_y;
      ++files;
    }
  check(fields && files > 5 && kappa.back() > 0,
        "accumulated_slip, plastic_slip_0 and plastic_slip_1 are fields of "
        "every interfaces_NNNN.vtu and equal the theory (1e-5 u_y)");

  // deformable bricks (the joints' tangent matters): Newton with the law's
  // tangent, not the kept factorisation of the elastic matrix
  std::ostringstream soft;
  soft << "subsection Interface law\nset Law = test friction\n"
       << "subsection Test friction\nset Cohesion = " << c
       << "\nset Friction coefficient = 0\nset Hardening modulus = " << H
       << "\nend\nend\nsubsection Bond\nset Pattern = stack\nend\n";
  const auto   deformable = run("deformable", prm(wallette.str(), soft.str()));
  const auto   d          = curve("deformable");
  unsigned int most       = 0;
  for (const auto &row : d)
    most = std::max(most, static_cast<unsigned int>(row[5]));
  check(deformable.at("status").get<std::string>() == "completed" &&
          deformable.at("cut_backs").get<double>() == 0 && most <= 6,
        "bricks of 10 GPa, no friction: Newton converges in every step "
        "without cut-backs in at most 6 iterations (the assembly uses the "
        "law's tangent of the slipping joints)");

  const std::string prm_stopped =
    prm(wallette.str() + "set Maximum steps = 11\n", law.str());
  const auto stopped = run("resumed", prm_stopped);
  const auto resumed =
    run("resumed", prm(wallette.str() + "set Resume = true\n", law.str()));
  const auto   b    = curve("resumed");
  const double diff = curve_difference(a, b);
  check(stopped.at("status").get<std::string>() == "interrupted" &&
          resumed.at("status").get<std::string>() == "completed" &&
          diff < 1e-12,
        "checkpointed after 11 steps and resumed: the curve of the "
        "uninterrupted run (1e-12)");
  check(contains(pvd_entries("results/resumed/solution.pvd"),
                 pvd_entries("results/full/solution.pvd")) &&
          contains(pvd_entries("results/resumed/interfaces.pvd"),
                   pvd_entries("results/full/interfaces.pvd")),
        "solution.pvd and interfaces.pvd of the resumed run list every "
        "output step of the uninterrupted run");
}
