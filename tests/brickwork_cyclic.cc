/**
 * The brick law `damage plasticity` inside the wallette model, against
 * closed forms of its uniaxial envelopes (computed here, independently of
 * the plugin):
 *  - one hexahedron (one enlarged brick, frictionless platens: uniaxial
 *    stress) under load-unload cycles: the cycle peaks lie on the input
 *    curve, the unloading slope is (1 - d_c) E0 and the residual strain the
 *    plastic strain of the envelope (1e-8), and each cycle's loop area (the
 *    work done from zero stress back to zero stress) equals the energy the
 *    law dissipates between the two envelope points (1e-4);
 *  - tension softening of one row of cubes of size h = 0.1, 0.05, 0.025 m:
 *    the work to full separation is G_f x area for every h (1e-3): the
 *    crack-band regularisation with the element's characteristic length;
 *  - element deletion in that row: cells go only once their strain exceeds
 *    the threshold, at most the cap per step, and the run goes on to the
 *    end with zero force once all are gone;
 *  - `Collapse stress ratio' 0.05 ends the row's run at the first step
 *    past the strain where the closed-form envelope falls to 5 % of the
 *    peak (status completed);
 *  - a run stopped after some steps and resumed from its checkpoint gives
 *    the curve of the uninterrupted run (1e-12); resumed with another
 *    `List of postprocessors' or another tensile strength, or from a
 *    checkpoint of another layout, it stops with a one-line error before
 *    it writes anything.
 */
#include <iomanip>

#include "brickwork_tests.h"
#include "tests.h"

using namespace brickwork_tests;

namespace
{
  // the law's parameters in this test
  const double E0 = 10e9, f_c = 20e6, ratio = 0.4, eps_c = 0.004;
  const double G_c = 20000, b_c = 0.7, f_t = 2e6, G_f = 80;

  /** Compressive envelope stress at total strain e (element size l). */
  double
  sigma_c(const double e, const double l)
  {
    const double f0 = ratio * f_c, e0 = f0 / E0;
    if (e <= e0)
      return E0 * e;
    if (e <= eps_c)
      {
        const double x = (e - e0) / (eps_c - e0);
        const double k = E0 * (eps_c - e0) / (f_c - f0);
        return f0 + (f_c - f0) * (k * x - x * x) / (1 + (k - 2) * x);
      }
    return f_c * std::exp(-(e - eps_c) * f_c * l / G_c);
  }

  /** Plastic strain on the compressive envelope. */
  double
  plastic_c(const double e, const double l)
  {
    return b_c * (e - sigma_c(e, l) / E0);
  }

  /** Energy dissipated per volume after loading to e and unloading to
   * zero stress: area under the envelope minus the unloading triangle. */
  double
  dissipated_c(const double e, const double l)
  {
    const unsigned int n    = 20000; // Simpson, even
    double             area = 0;
    for (unsigned int i = 0; i <= n; ++i)
      area += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * sigma_c(e * i / n, l);
    area *= e / n / 3;
    return area - 0.5 * sigma_c(e, l) * (e - plastic_c(e, l));
  }

  std::string
  material(const std::string &extra = "")
  {
    std::ostringstream m;
    m << std::setprecision(17)
      << "subsection Brick material\nset Model = damage plasticity\n"
         "subsection Damage plasticity\n"
      << "set Young's modulus = " << E0 << "\nset Poisson's ratio = 0.15\n"
      << "set Compressive strength = " << f_c
      << "\nset Elastic limit ratio = " << ratio
      << "\nset Strain at peak = " << eps_c
      << "\nset Compressive fracture energy = " << G_c
      << "\nset Plastic strain ratio = " << b_c
      << "\nset Tensile strength = " << f_t
      << "\nset Tensile fracture energy = " << G_f << "\n"
      << extra << "end\nend\nsubsection Bond\nset Pattern = stack\nend\n";
    return m.str();
  }

  // --- one hexahedron, cyclic uniaxial compression ------------------------
  // (compared with the closed forms to 1e-8, so converged to 1e-12: the
  // default 1e-8 passed only where Newton happened to land far below it,
  // and chord corrections stop just below it)
  const std::string hex =
    "set Newton tolerance = 1e-12\n"
    "set Courses = 1\nset Length in bricks = 1\n"
    "set Elements along the length = 1\nset Elements along the width = 1\n"
    "set Elements along the height = 1\nset Platen lateral restraint = "
    "free\nset Protocol = cyclic\nset Cycle amplitudes = 0.002, 0.0045, "
    "0.007, 0.012\nset Target strain = 0.012\nset Number of steps = "
    "600\nset Unloading stress = 0\n";
  // the enlarged brick 0.225 x 0.1125 x 0.075 m is the one cell
  const double l = std::cbrt(0.225 * 0.1125 * 0.075);

  void
  check_cycles()
  {
    const masonry::Json s = run("hex", prm(hex, material()));
    check(s.at("status").get<std::string>() == "completed", "hex: completed");
    {
      std::ifstream in("results/hex/cycles.csv");
      std::string   line;
      std::getline(in, line);
      double       peak = 0, slope = 0, residual = 0, energy = 0, previous = 0;
      unsigned int n = 0, turns = 0;
      const double amplitudes[4] = {0.002, 0.0045, 0.007, 0.012};
      while (std::getline(in, line))
        {
          std::vector<double> v;
          std::stringstream   cells(line);
          std::string         cell;
          while (std::getline(cells, cell, ','))
            v.push_back(std::stod(cell));
          // cycle,amplitude,peak,strain_at_peak,residual,modulus,ratio,energy
          const double e = v[1];
          const double d = 1 - sigma_c(e, l) / (E0 * (e - plastic_c(e, l)));
          slope          = std::max(slope, relative(v[5], (1 - d) * E0));
          residual =
            std::max(residual, std::abs(v[4] - plastic_c(e, l)) / eps_c);
          const double D = dissipated_c(e, l);
          energy         = std::max(energy, relative(v[7], D - previous));
          previous       = D;
          ++n;
        }
      // the turning point of each cycle: its largest strain
      for (const auto &row : curve("hex"))
        if (row[8] > 0 &&
            std::abs(row[2] - amplitudes[int(row[8]) - 1]) < 1e-12 * eps_c)
          {
            peak = std::max(peak, relative(row[4], sigma_c(row[2], l)));
            ++turns;
          }
      check(n == 4, "hex: 4 cycles");
      check(turns >= 4, "hex: the platen turns at the 4 amplitudes");
      check(peak < 1e-8,
            "hex: the stress at the turning points is the input curve's "
            "(1e-8)");
      check(slope < 1e-8, "hex: unloading slope (1 - d_c) E0 (1e-8)");
      check(residual < 1e-8,
            "hex: residual strain = plastic strain of the envelope (1e-8)");
      check(energy < 1e-4,
            "hex: loop area = dissipated energy of the cycle (1e-4)");
    }
  }

  // --- the same hexahedron, two cycles per amplitude -----------------------
  // (amplitudes before the peak strain, where the cycle's highest stress
  // is the stress at the amplitude) below the envelope the law unloads and
  // reloads along one line (damage
  // and plastic strain do not change), so the second cycle meets the first
  // cycle's unloading at the turning point: the common point and the
  // stability point are the envelope stress at the amplitude
  void
  check_repeated_cycles()
  {
    const std::string repeat =
      "set Courses = 1\nset Length in bricks = 1\n"
      "set Elements along the length = 1\nset Elements along the width = "
      "1\nset Elements along the height = 1\nset Platen lateral restraint "
      "= free\nset Protocol = cyclic\nset Cycle amplitudes = 0.002, "
      "0.0035\nset Cycles per amplitude = 2\nset Target strain = "
      "0.0035\nset Number of steps = 300\nset Unloading stress = 0\n";
    const masonry::Json r = run("hex_repeat", prm(repeat, material()));
    check(r.at("status").get<std::string>() == "completed",
          "hex_repeat: completed");
    std::ifstream in("results/hex_repeat/envelope.csv");
    std::string   line;
    std::getline(in, line);
    double       error = 0;
    unsigned int rows  = 0;
    while (std::getline(in, line))
      {
        // amplitude,envelope_strain,envelope,common,stability
        std::vector<double> v;
        std::stringstream   cells(line);
        std::string         cell;
        while (std::getline(cells, cell, ','))
          v.push_back(cell.empty() ? -1. : std::stod(cell));
        const double expected = sigma_c(v.at(0), l);
        for (const unsigned int k : {2u, 3u, 4u})
          error = std::max(error, std::abs(v.at(k) - expected) / f_c);
        ++rows;
      }
    check(rows == 2, "hex_repeat: 2 amplitudes in envelope.csv");
    check(error < 1e-8,
          "hex_repeat: envelope, common point and stability point = the "
          "input curve at the amplitude (1e-8 of f_c)");
  }

  // --- one row of cubes in tension: G_f x area for every size ------------
  // (Poisson's ratio 0: uniaxial strain is uniaxial stress, and Newton does
  // not meet the lateral principal stresses at the kink of the split)
  void
  check_tension_rows()
  {
    const std::string nu0 = "set Poisson's ratio = 0\n";
    for (const unsigned int n : {1u, 2u, 4u})
      {
        const double       h = 0.1 / n;
        const double       w = G_f / (f_t * h) - f_t / (2 * E0);
        std::ostringstream t;
        t << std::setprecision(17) << "set Brick length = 0.09\n"
          << "set Brick width = 0.09\nset Brick height = " << h - 0.01
          << "\nset Joint thickness = 0.01\nset Courses = 1\n"
          << "set Length in bricks = 1\nset Elements along the length = " << n
          << "\nset Elements along the width = " << n
          << "\nset Elements along the height = 1\n"
          << "set Platen lateral restraint = free\n"
          << "set Platen direction = 0, 0, 1\nset Target strain = "
          << f_t / E0 + 30 * w << "\nset Number of steps = 2000\n";
        const std::string name = "row_" + std::to_string(n);
        const auto        r    = run(name, prm(t.str(), material(nu0)));
        const double      work = r.at("external_work").get<double>();
        check(relative(work, G_f * 0.01) < 1e-3,
              name + ": work to separation = G_f x area (1e-3)");
        // the curve is the closed-form tension envelope at its strains
        double envelope = 0;
        for (const auto &row : curve(name))
          {
            const double e = row[2], e0 = f_t / E0;
            const double expected =
              e <= e0 ? E0 * e : f_t * std::exp(-(e - e0) / w);
            envelope = std::max(envelope, std::abs(row[4] - expected) / f_t);
          }
        check(envelope < 1e-8,
              name + ": the curve is the tension envelope (1e-8 of f_t)");
        check(r.at("peak_stress").get<double>() <= f_t * (1 + 1e-12) &&
                r.at("peak_stress").get<double>() > 0.99 * f_t,
              name + ": peak stress within 1 % below f_t (sampled)");
        if (n == 4)
          {
            // deletion at 5 f_t / E0, at most 3 cells a step, 16 cells
            const double threshold = 5 * f_t / E0;
            const auto   d         = run("deletion",
                               prm(t.str() + "set Deletion strain = " +
                                     std::to_string(threshold) +
                                     "\nset Maximum deletions per step = 3\n",
                                   material()));
            const auto   rows      = curve("deletion");
            bool         ok        = true;
            unsigned int last      = 0;
            for (unsigned int i = 1; i < rows.size(); ++i)
              {
                const unsigned int k = rows[i][10];
                // none before the threshold, then 3 more per step up to 16
                const unsigned int expected =
                  rows[i][2] <= threshold ? 0 : std::min(16u, last + 3);
                if (k != expected)
                  ok = false;
                last = k;
              }
            check(ok, "deletion: cells go after the threshold, 3 per step");
            check(d.at("status").get<std::string>() == "completed" &&
                    d.at("deleted_cells").get<double>() == 16 &&
                    rows.back()[4] == 0,
                  "deletion: all 16 cells gone, the run completes, force 0");
            // `Collapse stress ratio' 0.05: the run ends at the first step
            // whose stress is below 5 % of the peak, on the softening
            // branch f_t exp(-(e - e0) / w) past e0 + w ln(f_t / (0.05
            // peak))
            const auto c =
              run("collapse",
                  prm(t.str() + "set Collapse stress ratio = 0.05\n",
                      material(nu0)));
            const auto   cr   = curve("collapse");
            const double peak = c.at("peak_stress").get<double>();
            const double e_collapse =
              f_t / E0 + w * std::log(f_t / (0.05 * peak));
            const auto &last_row = cr.back(), &before = cr[cr.size() - 2];
            check(c.at("status").get<std::string>() == "completed" &&
                    c.at("message").get<std::string>().rfind(
                      "the specimen collapsed", 0) == 0,
                  "collapse: status completed, the message says so");
            check(last_row[4] < 0.05 * peak && before[4] >= 0.05 * peak &&
                    last_row[2] >= e_collapse && before[2] < e_collapse,
                  "collapse: the run ends at the first step past the strain "
                  "where the envelope falls to 5 % of the peak");
          }
      }
  }

  // --- checkpoint and resume ----------------------------------------------
  void
  check_resume()
  {
    const std::string short_hex = hex + "set Number of steps = 60\n";
    run("full", prm(short_hex, material()));
    const auto stopped =
      run("resumed", prm(short_hex + "set Maximum steps = 37\n", material()));
    check(stopped.at("status").get<std::string>() == "interrupted",
          "resume: the first part stops as interrupted");
    // (the file may spell a number otherwise: 2e6 where the stopped run's
    // material() wrote 2000000)
    const auto   resumed = run("resumed",
                             prm(short_hex + "set Resume = true\n",
                                 material("set Tensile strength = 2e6\n")));
    const auto   a = curve("full"), b = curve("resumed");
    const double diff = curve_difference(a, b);
    check(resumed.at("status").get<std::string>() == "completed" &&
            diff < 1e-12,
          "resume: the resumed run (one number spelled otherwise) "
          "reproduces the uninterrupted curve (1e-12)");

    // a checkpoint holds the data of the run's postprocessors: a resumed
    // run with another list stops with one line that names the entry
    run("other_list", prm(short_hex + "set Maximum steps = 37\n", material()));
    testing::write_file(
      "other_list.prm",
      "set Output directory = results/other_list\n" +
        prm(short_hex + "set Resume = true\n", material()) +
        "subsection Postprocess\nsubsection Wallette\n"
        "set List of postprocessors = curve tables, failure plot\nend\nend\n");
    const testing::Result other = testing::run({"other_list.prm"});
    testing::check_error(other);
    check(other.err.find("Resume") != std::string::npos &&
            other.err.find("List of postprocessors") != std::string::npos,
          "resume with another list of postprocessors: the error names "
          "`Resume' and `List of postprocessors'");

    // so does a resume with another value of any entry that shapes the run
    // (here the units' tensile strength: the same mesh and DOFs, so the
    // checkpoint's parts would load), before anything is written
    testing::write_file("other_input.prm",
                        "set Output directory = results/other_list\n" +
                          prm(short_hex + "set Resume = true\n",
                              material("set Tensile strength = 3e6\n")));
    const testing::Result input = testing::run({"other_input.prm"});
    testing::check_error(input);
    check(input.err.find("Resume") != std::string::npos &&
            input.err.find(
              "`Brick material/Damage plasticity/Tensile strength'") !=
              std::string::npos &&
            input.err.find("was `2000000' in that run, `3e6' here") !=
              std::string::npos,
          "resume with another tensile strength: the error names `Resume' "
          "and the entry, with both values");
    const masonry::Json left = masonry::parse_json(
      testing::read_file("results/other_list/summary.json"));
    check(left.at("status").get<std::string>() == "interrupted",
          "both refused resumes leave the stopped run's summary.json "
          "(status interrupted)");

    // a checkpoint of another layout (one written before the run's entries
    // were in its header, whose format tag is one less): refused with one
    // line before its parts are read
    run("old_layout", prm(short_hex + "set Maximum steps = 37\n", material()));
    std::string bytes = testing::read_file("results/old_layout/checkpoint.0");
    const std::string tag("\x33\x56\x57\x4d", 4);
    const std::size_t at = bytes.find(tag);
    if (at != std::string::npos)
      bytes.replace(at, 4, std::string("\x32\x56\x57\x4d", 4));
    testing::write_file("results/old_layout/checkpoint.0", bytes);
    testing::write_file("old_layout.prm",
                        "set Output directory = results/old_layout\n" +
                          prm(short_hex + "set Resume = true\n", material()));
    const testing::Result old = testing::run({"old_layout.prm"});
    testing::check_error(old);
    check(at != std::string::npos &&
            old.err.find("Resume") != std::string::npos &&
            old.err.find("another version of masonry") != std::string::npos,
          "resume from a checkpoint of the layout before: the error names "
          "`Resume' and says it was written by another version");
    // found before anything is written: the stopped run's summary.json
    // and log.txt are as that run left them
    const masonry::Json kept = masonry::parse_json(
      testing::read_file("results/old_layout/summary.json"));
    check(kept.at("status").get<std::string>() == "interrupted" &&
            testing::read_file("results/old_layout/log.txt")
                .find("another version") == std::string::npos,
          "the refused resume leaves the stopped run's summary.json (status "
          "interrupted) and log.txt as they were");
  }

} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  check_cycles();
  check_repeated_cycles();
  check_tension_rows();
  check_resume();
}
