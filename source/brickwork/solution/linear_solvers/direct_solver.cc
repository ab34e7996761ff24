/**
 * @file
 * The direct solver through Amesos.
 */
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include "direct_solver.h"

#include <Amesos.h>
#include <Amesos_Mumps.h>
#include <chrono>
#include <iostream>
#include <limits>
#include <sstream>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using namespace dealii;
      using Clock = std::chrono::steady_clock;

      namespace
      {
        /** What MUMPS's INFOG(1) < 0 means (MUMPS users' guide, section
         * Error diagnostics; the ones a tangent can cause). */
        std::string
        mumps_meaning(const int infog1)
        {
          switch (infog1)
            {
              case -6:
                return "the matrix is structurally singular";
              case -9:
              case -8:
              case -14:
              case -15:
                return "its workspace was too small (pivots were delayed: the "
                       "matrix is nearly singular)";
              case -10:
                return "the matrix is numerically singular";
              case -13:
              case -5:
              case -7:
                return "out of memory";
              default:
                return "see the MUMPS users' guide";
            }
        }

        /** Runs @p f with std::cerr diverted (Amesos writes its errors
         * there); what it wrote. */
        template <class F>
        std::string
        quietly(const F &f, int &result)
        {
          std::ostringstream captured;
          std::streambuf    *kept = std::cerr.rdbuf(captured.rdbuf());
          try
            {
              result = f();
            }
          catch (...)
            {
              std::cerr.rdbuf(kept);
              throw;
            }
          std::cerr.rdbuf(kept);
          return captured.str();
        }
      } // namespace

      DirectSolver::DirectSolver(const std::string &name)
        : name(name)
      {}

      DirectSolver::~DirectSolver() = default;

      void
      DirectSolver::factorise_and_solve(const Matrix &matrix,
                                        Vector       &du,
                                        const Vector &rhs,
                                        const bool    initial_tangent)
      {
        if (!direct)
          make(matrix);
        solve_with(du, rhs, true, initial_tangent);
      }

      void
      DirectSolver::forget()
      {
        is_initial = false;
      }

      void
      DirectSolver::clear()
      {
        // (Amesos reads the matrix's communicator when it lets MUMPS go)
        direct.reset();
        factorised = is_initial = false;
      }

      void
      DirectSolver::drop_factors()
      {
        factorised = is_initial = false;
      }

      bool
      DirectSolver::has_kept_factors() const
      {
        return direct != nullptr && factorised;
      }

      void
      DirectSolver::solve_with_kept_factors(Vector &du, const Vector &rhs)
      {
        const auto start = Clock::now();
        ++statistics.n_solves;
        ++statistics.n_chord_solves;
        apply_factors(du, rhs);
        statistics.seconds +=
          std::chrono::duration<double>(Clock::now() - start).count();
      }

      void
      DirectSolver::do_solve(const Matrix &matrix,
                             Vector       &du,
                             const Vector &rhs,
                             const bool    initial_tangent,
                             const bool    reuse)
      {
        const bool fresh = !direct;
        if (fresh)
          make(matrix);
        if (!fresh && !reuse && reuse_iterations > 0 && factorised &&
            solve_with_old_factors(matrix, du, rhs))
          {
            // the kept factorisation is no longer that of this matrix
            is_initial = false;
            return;
          }
        solve_with(du, rhs, fresh || !reuse, initial_tangent);
      }

      bool
      DirectSolver::kept_is_initial() const
      {
        return is_initial;
      }

      void
      DirectSolver::OldFactors::vmult(Vector &dst, const Vector &src) const
      {
        direct->apply_factors(dst, src);
      }

      void
      DirectSolver::apply_factors(Vector &dst, const Vector &src)
      {
        int result = 0;
        problem.SetLHS(&dst.trilinos_vector());
        problem.SetRHS(
          const_cast<Epetra_MultiVector *>(&src.trilinos_vector()));
        quietly([&]() { return direct->Solve(); }, result);
        if (result != 0 || failed())
          fail("failed in the solve with the factorised tangent");
      }

      bool
      DirectSolver::solve_with_old_factors(const Matrix &matrix,
                                           Vector       &du,
                                           const Vector &rhs)
      {
        SolverControl control(reuse_iterations,
                              tolerance * rhs.l2_norm(),
                              false,
                              false);
        try
          {
            SolverGMRES<Vector> gmres(
              control,
              SolverGMRES<Vector>::AdditionalData(reuse_iterations + 2, true));
            gmres.solve(matrix, du, rhs, OldFactors{this});
          }
        catch (const std::exception &)
          {
            du = 0;
            return false;
          }
        ++statistics.n_reuse_solves;
        statistics.n_reuse_iterations += control.last_step();
        return true;
      }

      void
      DirectSolver::make(const Matrix &matrix)
      {
        problem.SetOperator(
          const_cast<Epetra_CrsMatrix *>(&matrix.trilinos_matrix()));
        Amesos factory;
        direct.reset(factory.Create(name.c_str(), problem));
        AssertThrow(direct != nullptr,
                    ExcMessage(name + " is not available in this Trilinos"));
        if (const auto mumps = dynamic_cast<Amesos_Mumps *>(direct.get()))
          {
            choose_ordering(*mumps, matrix.get_mpi_communicator());
            // null pivot detection (MUMPS's threshold, CNTL(3) = 0): a
            // brick held only by debonded frictionless joints, or a
            // deleted cell's neighbour, is free in some direction and
            // the tangent singular there. Without it, MUMPS factorised
            // the round-off and the corrections moved such parts
            // arbitrarily far, so Newton stalled at the joints' contact
            // switches (doc/notes/implex-step-control.md)
            mumps->SetICNTL(24, 1);
          }
        int result = 0;
        quietly([&]() { return direct->SymbolicFactorization(); }, result);
        if (result != 0 || failed())
          fail("could not analyse the tangent");
      }

      void
      DirectSolver::choose_ordering(Amesos_Mumps &mumps, const MPI_Comm comm)
      {
        int    best   = 7;
        double fewest = std::numeric_limits<double>::infinity();
        for (const int ordering : {2, 4, 6})
          {
            mumps.SetICNTL(7, ordering);
            int result = 0;
            quietly([&]() { return mumps.SymbolicFactorization(); }, result);
            const double flops = mumps.GetRINFOG()[0];
            if (result == 0 && mumps.GetINFOG()[0] >= 0 &&
                mumps.GetINFOG()[6] == ordering && flops < fewest)
              {
                fewest = flops;
                best   = ordering;
              }
          }
        const int ierr = MPI_Bcast(&best, 1, MPI_INT, 0, comm);
        AssertThrowMPI(ierr);
        mumps.SetICNTL(7, best);
      }

      void
      DirectSolver::solve_with(Vector       &du,
                               const Vector &rhs,
                               const bool    factorise,
                               const bool    initial_tangent)
      {
        int result = 0;
        if (factorise)
          {
            // (a failed factorisation is no longer the kept one)
            is_initial = false;
            factorised = false;
            quietly([&]() { return direct->NumericFactorization(); }, result);
            if (result != 0 || failed())
              fail("could not factorise the tangent");
            ++statistics.n_factorisations;
            if (const auto mumps = dynamic_cast<Amesos_Mumps *>(direct.get()))
              if (mumps->GetINFOG()[27] > 0) // INFOG(28)
                ++statistics.n_null_pivot_factorisations;
            factorised = true;
            is_initial = initial_tangent;
          }
        apply_factors(du, rhs);
      }

      bool
      DirectSolver::failed()
      {
        const auto mumps = dynamic_cast<Amesos_Mumps *>(direct.get());
        return mumps != nullptr && mumps->GetINFOG()[0] < 0;
      }

      void
      DirectSolver::fail(const std::string &what)
      {
        std::ostringstream m;
        const auto         mumps = dynamic_cast<Amesos_Mumps *>(direct.get());
        if (mumps != nullptr)
          {
            const int *infog = mumps->GetINFOG();
            m << "MUMPS " << what << ": INFOG(1) = " << infog[0]
              << ", INFOG(2) = " << infog[1] << " (" << mumps_meaning(infog[0])
              << ")";
          }
        else
          m << name << " " << what;
        throw LinearSolverFailure(m.str());
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
