/**
 * A linear solver added from outside the library, in this file: `dense lu',
 * which copies the tangent into a dense matrix and solves it by LAPACK's LU
 * factorisation, registered with one MASONRY_REGISTER_LINEAR_SOLVER line
 * and selected with `Linear solver = dense lu', with no edit anywhere else.
 * Two stack-bonded bricks pulled apart across a softening bed joint (a
 * non-linear run: the joint cracks and softens) give the same curve with it
 * as with the built-in `direct' (MUMPS) solver, to round-off, and every
 * linear solve of the run went through the new solver.
 */
#include <masonry/brickwork/linear_solver.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <iomanip>

#include "brickwork_tests.h"

using namespace brickwork_tests;
using namespace masonry::brickwork;

namespace
{
  /** Solves done by the dense solver. */
  unsigned int n_dense_solves = 0;

  /** The tangent as a dense matrix, factorised by LAPACK at every solve
   * (one rank). */
  class DenseLu : public LinearSolver
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &)
    {}

    void
    forget() override
    {}

  protected:
    void
    do_solve(const Matrix &matrix,
             Vector       &du,
             const Vector &rhs,
             const bool,
             const bool) override
    {
      AssertThrow(rhs.locally_owned_elements().size() == rhs.size(),
                  dealii::ExcMessage("dense lu: one rank only"));
      const unsigned int               n = matrix.m();
      dealii::LAPACKFullMatrix<double> a(n, n);
      for (auto entry = matrix.begin(); entry != matrix.end(); ++entry)
        a(entry->row(), entry->column()) = entry->value();
      a.compute_lu_factorization();
      dealii::Vector<double> x(n);
      for (unsigned int i = 0; i < n; ++i)
        x[i] = rhs[i];
      a.solve(x);
      for (unsigned int i = 0; i < n; ++i)
        du[i] = x[i];
      du.compress(dealii::VectorOperation::insert);
      ++n_dense_solves;
    }

    bool
    kept_is_initial() const override
    {
      return false;
    }
  };

  /** Two bricks (stack bond, 2 x 1 x 1 cells each) pulled apart across a
   * bilinear bed joint past its strength, with @p solver. */
  std::string
  wall(const std::string &solver)
  {
    return prm("  set Linear solver = " + solver +
                 "\n"
                 "  set Courses = 2\n"
                 "  set Length in bricks = 1\n"
                 "  set Elements along the length = 2\n"
                 "  set Elements along the width = 1\n"
                 "  set Elements along the height = 1\n"
                 "  set Platen direction = 0, 0, 1\n"
                 "  set Target strain = 0.0005\n"
                 "  set Number of steps = 20\n"
                 "  set Output interval = 0\n",
               "subsection Bond\n"
               "  set Pattern = stack\n"
               "end\n"
               "subsection Interface law\n"
               "  set Law = bilinear\n"
               "  subsection Bilinear\n"
               "    set Tensile strength = 0.2e6\n"
               "  end\n"
               "end\n"
               "subsection Postprocess\n"
               "  subsection Wallette\n"
               "    set List of postprocessors = curve tables\n"
               "  end\n"
               "end\n");
  }
} // namespace

MASONRY_REGISTER_LINEAR_SOLVER(DenseLu,
                               "dense lu",
                               "The tangent as a dense matrix, solved by "
                               "LAPACK's LU factorisation (the test's own).")

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);
  const auto mumps = run("direct", wall("direct"));
  const auto dense = run("dense", wall("dense lu"));
  const auto a = table("direct", "curve.csv"), b = table("dense", "curve.csv");
  check(mumps.at("status").get<std::string>() == "completed" &&
          dense.at("status").get<std::string>() == "completed",
        "both runs complete");
  // the columns: step, displacement, strain, force, stress, ...
  bool   same  = a.size() == b.size() && !a.empty();
  double worst = 0;
  for (unsigned int i = 0; same && i < a.size(); ++i)
    {
      const double scale = std::abs(a[i][4]) + 1e-3 * 0.2e6;
      worst              = std::max(worst, std::abs(a[i][4] - b[i][4]) / scale);
    }
  if (!check(same && worst < 1e-8,
             "the dense solver's curve is the direct solver's, step by step"))
    std::cout << "  " << a.size() << " / " << b.size()
              << " rows, largest difference " << worst << "\n";
  const double peak = dense.at("peak_stress").get<double>();
  if (!check(peak > 0.9 * 0.2e6 && peak <= 0.2e6 * (1 + 1e-9),
             "the joint softens after a peak just below its strength"))
    std::cout << "  peak " << peak << " Pa\n";
  // every Newton iteration of every step (curve.csv's column 5) solves
  // once at least
  double iterations = 0;
  for (const auto &row : b)
    iterations += row[5];
  const unsigned int solves = dense.at("linear_solves").get<unsigned int>();
  if (!check(solves > 0 && solves == n_dense_solves &&
               n_dense_solves >= iterations,
             "every linear solve of the run went through the dense solver"))
    std::cout << "  " << solves << " solves, " << n_dense_solves
              << " by the dense solver, " << iterations
              << " Newton iterations\n";
  return 0;
}
