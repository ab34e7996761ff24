/**
 * @file
 * Helpers for the rigid-block tests: run a prm text in-process and read the
 * summary.json it wrote.
 */
#ifndef masonry_tests_vault_tests_h
#define masonry_tests_vault_tests_h

#include <masonry/core/application.h>
#include <masonry/core/json.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace vault_tests
{
#ifdef MASONRY_SOURCE_DIR
  /**
   * The text of the shipped example prm/examples/@p name.prm ("" if it
   * cannot be read), for a test that runs an example with overrides
   * appended (only in the tests compiled with MASONRY_SOURCE_DIR, see
   * tests/CMakeLists.txt).
   */
  inline std::string
  example_text(const std::string &name)
  {
    std::ifstream in(std::string(MASONRY_SOURCE_DIR) + "/prm/examples/" + name +
                     ".prm");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
#endif

  /**
   * Write @p prm_text to NAME.prm (with `Output directory = results/NAME`),
   * run masonry on it with screen output discarded and return its
   * summary.json. Aborts the test with a message if the run fails.
   */
  inline masonry::Json
  run(const std::string &name,
      const std::string &prm_text,
      const MPI_Comm     comm = MPI_COMM_WORLD)
  {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    if (rank == 0)
      {
        std::ofstream prm(name + ".prm");
        prm << "set Output directory = results/" << name << "\n" << prm_text;
      }
    MPI_Barrier(comm);
    std::ostringstream screen;
    std::streambuf    *old  = std::cout.rdbuf(screen.rdbuf());
    const int          code = masonry::run_application({name + ".prm"}, comm);
    std::cout.rdbuf(old);
    if (code != 0)
      {
        std::cout << "FAILED: masonry returned " << code << " for " << name
                  << "\n"
                  << screen.str();
        std::exit(1);
      }
    // rank 0 writes summary.json
    MPI_Barrier(comm);
    std::ifstream     in("results/" + name + "/summary.json");
    std::stringstream text;
    text << in.rdbuf();
    return masonry::parse_json(text.str());
  }

  /** Print "OK what" or "FAILED what" for a check (rank 0 of the world
   * communicator prints, so that a test can run on several ranks). */
  inline bool
  check(const bool ok, const std::string &what)
  {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0)
      std::cout << (ok ? "OK " : "FAILED ") << what << "\n";
    return ok;
  }

  /** Relative difference of @p a and @p b. */
  inline double
  relative(const double a, const double b)
  {
    return std::abs(a - b) / std::max(std::abs(b), 1e-300);
  }

  /** A prm text for a settlement of a circular barrel vault (span 6 m,
   * rise 3 m, length 6 m, thickness 0.3 m, density 2000 kg/m³) with @p n x
   * @p n blocks per half, support motion @p settlement (m, in x; y; z) and
   * the joints of the Interface model text @p joints. */
  inline std::string
  barrel_prm(const unsigned int n,
             const std::string &settlement,
             const std::string &joints)
  {
    return "set Analysis = settlement\n"
           "subsection Geometry model\n  set Model name = barrel vault\n"
           "  set Thickness = 0.3\n  set Density = 2000\n"
           "  subsection Barrel vault\n    set Shape = circular\n"
           "    set Span = 6\n    set Rise = 3\n    set Length = 6\n"
           "  end\nend\n"
           "subsection Settlement\n  set Blocks along u = " +
           std::to_string(n) + "\n  set Blocks along v = " + std::to_string(n) +
           "\n  set Settlement = " + settlement +
           "\n  set Write picture = false\nend\n"
           "subsection Interface model\n" +
           joints + "end\n";
  }

  /** A prm text for a semicircular arch of radius R (thickness t, depth 1 m,
   * density 2000 kg/m³) with @p n blocks per half under @p settlement of the
   * right springing. */
  inline std::string
  arch_prm(const double       R,
           const double       t,
           const unsigned int n,
           const std::string &settlement,
           const std::string &contact = "unilateral",
           const std::string &solver  = "clp")
  {
    std::ostringstream s;
    s.precision(17);
    s << "set Analysis = settlement\n"
      << "subsection Geometry model\n  set Model name = arch\n"
      << "  set Thickness = " << t << "\n  set Density = 2000\n"
      << "  subsection Arch\n    set Shape = circular\n    set Span = " << 2 * R
      << "\n    set Rise = " << R << "\n    set Depth = 1\n  end\nend\n"
      << "subsection Settlement\n  set Blocks along u = " << n
      << "\n  set Blocks along v = 1\n  set Stations per edge = 2\n"
      << "  set Supported edges = springing left, springing right\n"
      << "  set Settling edges = springing right\n"
      << "  set Settlement = " << settlement << "\n"
      << "  set Support contact = " << contact << "\n"
      << "  set Write picture = false\nend\n"
      << "subsection LP solver\n  set Solver = " << solver << "\nend\n";
    return s.str();
  }

  /** Mohr-Coulomb joints of the LP tests (friction 0.6, cohesion 10 kPa,
   * tension cut-off 5 kPa, compression cap 0.3 MPa). */
  inline std::string
  mohr_coulomb_joints()
  {
    return "subsection Interface model\n  set Model = mohr coulomb\n"
           "  subsection Mohr coulomb\n    set Friction coefficient = 0.6\n"
           "    set Cohesion = 1e4\n    set Tensile strength = 5e3\n"
           "    set Compressive strength = 3e5\n  end\nend\n";
  }

  /** The limit load of an arch (span 10 m, rise 5 m, thickness 1 m, 16
   * blocks) under a horizontal acceleration, mohr_coulomb_joints(). */
  inline std::string
  arch_limit_load_prm()
  {
    return "set Analysis = limit load\n"
           "subsection Geometry model\n  set Model name = arch\n"
           "  set Thickness = 1\n  set Density = 2000\n"
           "  subsection Arch\n    set Span = 10\n    set Rise = 5\n"
           "    set Depth = 1\n  end\nend\n"
           "subsection Limit load\n  set Blocks along u = 16\n"
           "  set Blocks along v = 1\n  set Stations per edge = 2\n"
           "  set Supported edges = springing left, springing right\n"
           "  set Live acceleration = 1; 0; 0\n"
           "  set Write picture = false\nend\n" +
           mohr_coulomb_joints();
  }

  /**
   * The five-hinge mechanism of a semicircular arch (R = 1; hinges at the
   * crown extrados, the haunch intrados at β from the crown and the
   * springing extrados): moment equilibrium of the segment [0, β] about the
   * haunch hinge and of the half arch about the springing hinge.
   */
  namespace arch_theory
  {
    /**
     * t/R and H/(γRt) of the five-hinge mechanism with the haunch hinge at
     * β (rad), R = 1; @p true_centroid: weight of annular sectors at their
     * true centroids, else on the centreline.
     */
    std::pair<double, double>
    five_hinge(const double beta, const bool true_centroid)
    {
      auto residual = [&](const double t) {
        const double re = 1 + t / 2, ri = 1 - t / 2;
        auto         xbar = [&](const double phi) {
          return true_centroid ? (re * re * re - ri * ri * ri) / 3 *
                                   (1 - std::cos(phi)) / (t * phi) :
                                         (1 - std::cos(phi)) / phi;
        };
        const double W1 = t * beta, W = t * M_PI / 2;
        const double H1 =
          W1 * (ri * std::sin(beta) - xbar(beta)) / (re - ri * std::cos(beta));
        const double H2 = W * (re - xbar(M_PI / 2)) / re;
        return std::make_pair(H1 - H2, H2);
      };
      double lo = 0.01, hi = 0.3;
      for (unsigned int i = 0; i < 200; ++i)
        {
          const double mid = 0.5 * (lo + hi);
          if (residual(lo).first * residual(mid).first <= 0)
            hi = mid;
          else
            lo = mid;
        }
      return {lo, residual(lo).second / lo};
    }

    /** Maximise t(β) by golden-section search: (t/R, β in degrees, h). */
    std::array<double, 3>
    milankovitch(const bool true_centroid)
    {
      double       a = 0.5, b = 1.3;
      const double g = (std::sqrt(5.) - 1) / 2;
      for (unsigned int i = 0; i < 200; ++i)
        {
          const double c = b - g * (b - a), d = a + g * (b - a);
          if (five_hinge(c, true_centroid).first >
              five_hinge(d, true_centroid).first)
            b = d;
          else
            a = c;
        }
      const double beta = 0.5 * (a + b);
      const auto   th   = five_hinge(beta, true_centroid);
      return {{th.first, beta * 180 / M_PI, th.second}};
    }
  } // namespace arch_theory
} // namespace vault_tests

#endif
