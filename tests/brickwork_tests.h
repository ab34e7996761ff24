/**
 * @file
 * Helpers for the brickwork tests: a parameter file for a wallette and the
 * curve a run wrote.
 */
#ifndef masonry_tests_brickwork_tests_h
#define masonry_tests_brickwork_tests_h

#include <masonry/core/application.h>
#include <masonry/core/json.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "vault_tests.h"

namespace brickwork_tests
{
  /**
   * A wallette parameter file: the analysis entries in @p wallette, the
   * other subsections verbatim in @p plugins. No pictures, no VTU.
   */
  inline std::string
  prm(const std::string &wallette, const std::string &plugins)
  {
    return "set Analysis = wallette\n"
           "subsection Wallette\n"
           "  set Write plot = false\n"
           "  set Write VTU = false\n" +
           wallette + "end\n" + plugins;
  }

  /**
   * The Wallette entries of the detailed model's coarse elastic wall of the
   * joint-geometry tests (brickwork_joint_fill, brickwork_collar_bed_gap):
   * 215 x 102.5 x 65 mm units, 10 mm joints, @p courses courses of 2
   * bricks, 2 x 1 x 1 cells per unit, free platens, one step to strain
   * 1e-4; @p extra: further Wallette entries.
   */
  inline std::string
  coarse_detailed_wall(const unsigned int courses, const std::string &extra)
  {
    return "  set Model = detailed\n"
           "  set Brick length = 0.215\n"
           "  set Brick width = 0.1025\n"
           "  set Brick height = 0.065\n"
           "  set Joint thickness = 0.010\n"
           "  set Courses = " +
           std::to_string(courses) +
           "\n"
           "  set Length in bricks = 2\n"
           "  set Elements along the length = 2\n"
           "  set Elements along the width = 1\n"
           "  set Elements along the height = 1\n"
           "  set Platen lateral restraint = free\n"
           "  set Target strain = 1e-4\n"
           "  set Number of steps = 1\n" +
           extra;
  }

  /**
   * Elastic units (E = 10 GPa, Poisson's ratio @p nu_b) and elastic mortar
   * (E = 1 GPa, 0.2) of the detailed model's elastic tests.
   */
  inline std::string
  elastic_units_and_mortar(const std::string &nu_b)
  {
    return "subsection Brick material\n"
           "  set Model = elastic\n"
           "  subsection Elastic\n"
           "    set Young's modulus = 10e9\n"
           "    set Poisson's ratio = " +
           nu_b +
           "\n"
           "  end\n"
           "end\n"
           "subsection Mortar material\n"
           "  set Model = elastic\n"
           "  subsection Elastic\n"
           "    set Young's modulus = 1e9\n"
           "    set Poisson's ratio = 0.2\n"
           "  end\n"
           "end\n";
  }

  /** Elastic bond interfaces with stiff contact penalties (1e14 Pa/m). */
  inline const std::string elastic_bond = "subsection Interface law\n"
                                          "  set Law = elastic\n"
                                          "  set Normal stiffness = 1e14\n"
                                          "  set Shear stiffness = 1e14\n"
                                          "end\n";

  /**
   * The coarse cracked wallette of the solver tests (brickwork_solver_fallback,
   * brickwork_solver_speed): 7 courses of 2 stretchers, 2 x 1 x 1 cells per
   * brick between laterally fixed platens, damage-plasticity bricks,
   * bilinear joints, 10 % strength scatter, deletion at 0.005, IMPL-EX,
   * cycled to 0.002, 0.004, 0.006, 0.008 in 40 steps. @p extra: further
   * Wallette entries (the linear solver and solver options);
   * @p damage_plasticity: further entries of the bricks' `Damage
   * plasticity' subsection.
   */
  inline std::string
  cracked_cyclic_wallette(const std::string &extra,
                          const std::string &damage_plasticity = "")
  {
    return prm(
      "set Courses = 7\nset Length in bricks = 2\n"
      "set Elements along the length = 2\nset Elements along the width = 1\n"
      "set Elements along the height = 1\n"
      "set Platen lateral restraint = fixed\nset Protocol = cyclic\n"
      "set Cycle amplitudes = 0.002, 0.004, 0.006, 0.008\n"
      "set Unloading stress = 0.1e6\nset Target strain = 0.008\n"
      "set Number of steps = 40\nset Deletion strain = 0.005\n"
      "set Strength scatter = 0.1\nset Random seed = 2\n"
      "set Damage integration = implex\n" +
        extra,
      "subsection Bond\nset Pattern = stretcher\nend\n"
      "subsection Brick material\nset Model = damage plasticity\n"
      "subsection Damage plasticity\nset Plastic strain ratio = 0.7\n"
      "set Tensile plastic strain ratio = 0.1\nset Maximum damage = 0.95\n" +
        damage_plasticity +
        "end\nend\n"
        "subsection Interface law\nset Law = bilinear\n"
        "set Normal stiffness = 2.5e11\nset Shear stiffness = 1.03e11\n"
        "end\n");
  }

  /**
   * The splitting tests' unit: one elastic unit 2 m long, 2 mm thick and
   * 0.1 m high (E = 10 GPa, Poisson's ratio @p nu) on a 40 x 1 x 8 mesh
   * between laterally fixed platens, stack bond, with splitting interfaces
   * (tensile strength 1 MPa, fracture energy 50 J/m^2, compressive
   * strength 10 MPa, stiffness 1e15 Pa/m), loaded to @p target strain in
   * @p steps steps. @p extra: further Wallette entries; @p plugins: further
   * subsections after the material.
   */
  inline std::string
  splitting_unit(const double       nu,
                 const double       target,
                 const unsigned int steps,
                 const std::string &extra   = "",
                 const std::string &plugins = "")
  {
    std::ostringstream s;
    s << "  set Brick length = 2.0\n"
         "  set Brick width = 0.002\n"
         "  set Brick height = 0.1\n"
         "  set Joint thickness = 0\n"
         "  set Courses = 1\n"
         "  set Length in bricks = 1\n"
         "  set Elements along the length = 40\n"
         "  set Elements along the width = 1\n"
         "  set Elements along the height = 8\n"
         "  set Platen lateral restraint = fixed\n"
         "  set Target strain = "
      << target << "\n  set Number of steps = " << steps << "\n"
      << extra
      << "  set Splitting interfaces = true\n"
         "  set Splitting tensile strength = 1e6\n"
         "  set Splitting fracture energy = 50\n"
         "  set Splitting compressive strength = 10e6\n"
         "  set Splitting stiffness = 1e15\n";
    std::ostringstream m;
    m << "subsection Bond\n  set Pattern = stack\nend\n"
         "subsection Brick material\n"
         "  set Model = elastic\n"
         "  subsection Elastic\n"
         "    set Young's modulus = 10e9\n"
         "    set Poisson's ratio = "
      << nu << "\n  end\nend\n"
      << plugins;
    return prm(s.str(), m.str());
  }

  // run(), check() and relative() are the rigid-block tests' helpers
  using vault_tests::check;
  using vault_tests::relative;
  using vault_tests::run;
#ifdef MASONRY_SOURCE_DIR
  using vault_tests::example_text;
#endif

  /** The columns of results/NAME/FILE (a CSV file of numbers with one
   * header line), row by row. */
  inline std::vector<std::vector<double>>
  table(const std::string &name, const std::string &file)
  {
    std::ifstream                    in("results/" + name + "/" + file);
    std::string                      line;
    std::vector<std::vector<double>> rows;
    std::getline(in, line); // header
    while (std::getline(in, line))
      {
        std::vector<double> row;
        std::stringstream   s(line);
        std::string         cell;
        while (std::getline(s, cell, ','))
          row.push_back(std::stod(cell));
        rows.push_back(row);
      }
    return rows;
  }

  /** The columns of results/NAME/curve.csv, row by row. */
  inline std::vector<std::vector<double>>
  curve(const std::string &name)
  {
    return table(name, "curve.csv");
  }
  /**
   * The numbers N of the lines `Step N ...' of a log that follow a line that
   * contains @p text (several such lines before one step: that step once),
   * in order.
   */
  inline std::vector<int>
  steps_after(const std::string &log, const std::string &text)
  {
    std::ifstream    in(log);
    std::string      line;
    std::vector<int> steps;
    bool             seen = false;
    while (std::getline(in, line))
      if (line.find(text) != std::string::npos)
        seen = true;
      else if (seen && line.rfind("Step ", 0) == 0)
        {
          steps.push_back(std::stoi(line.substr(5)));
          seen = false;
        }
    return steps;
  }
  /**
   * The number N of the first line `Step N ...' of a log after the first
   * line that contains @p text; -1 if there is none.
   */
  inline int
  first_step_after(const std::string &log, const std::string &text)
  {
    const std::vector<int> steps = steps_after(log, text);
    return steps.empty() ? -1 : steps.front();
  }
  /** The entries of the DataSet lines of a PVD file, in order. */
  inline std::vector<std::string>
  pvd_entries(const std::string &file)
  {
    std::ifstream            in(file);
    std::string              line;
    std::vector<std::string> entries;
    while (std::getline(in, line))
      if (line.find("<DataSet") != std::string::npos)
        entries.push_back(line.substr(line.find("timestep")));
    return entries;
  }

  /** Whether every entry of @p all is in @p some (and @p all is not
   * empty). */
  inline bool
  contains(const std::vector<std::string> &some,
           const std::vector<std::string> &all)
  {
    for (const auto &e : all)
      if (std::find(some.begin(), some.end(), e) == some.end())
        return false;
    return !all.empty();
  }
  /** The largest difference between two curves, relative to max(1, |a|)
   * entry by entry; 1 when they have different numbers of rows. */
  inline double
  curve_difference(const std::vector<std::vector<double>> &a,
                   const std::vector<std::vector<double>> &b)
  {
    double diff = a.size() == b.size() ? 0 : 1;
    for (unsigned int i = 0; a.size() == b.size() && i < a.size(); ++i)
      for (unsigned int j = 0; j < a[i].size(); ++j)
        diff = std::max(diff,
                        std::abs(a[i][j] - b[i][j]) /
                          std::max(1., std::abs(a[i][j])));
    return diff;
  }
} // namespace brickwork_tests

#endif
