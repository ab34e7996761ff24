/**
 * @file
 * Direct and AMG-Krylov solvers of the Newton corrections.
 */
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include "linear_solvers.h"

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>
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

      void
      LinearSolver::solve(System               &system,
                          System::Vector       &du,
                          const System::Vector &rhs,
                          const bool            initial_tangent)
      {
        const auto start = Clock::now();
        ++statistics.n_solves;
        // the factorisation (or AMG hierarchy) of the initial tangent is
        // kept while the tangent stays the initial one: every step of a
        // linear model, the elastic steps of a nonlinear one
        const bool reuse = initial_tangent && kept_is_initial();
        if (reuse)
          ++statistics.n_factorisations_reused;
        do_solve(system, du, rhs, initial_tangent, reuse);
        statistics.seconds +=
          std::chrono::duration<double>(Clock::now() - start).count();
      }

      void
      LinearSolver::solve_with_kept_factors(System &,
                                            System::Vector &,
                                            const System::Vector &)
      {
        AssertThrow(false, ExcInternalError());
      }

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

        /** Amesos on the matrix, whose sparsity never changes, so the
         * symbolic analysis (ordering) is done once and every new tangent
         * only costs a numeric factorisation. */
        class Direct : public LinearSolver
        {
        public:
          /** @p name: Amesos_Mumps or Amesos_Klu. */
          explicit Direct(const std::string &name)
            : name(name)
          {}

          /** GMRES with the last factorisation first, up to @p iterations
           * (0: never), to the relative @p linear_tolerance (`Factorisation
           * reuse iterations'). */
          void
          enable_reuse(const unsigned int iterations,
                       const double       linear_tolerance)
          {
            reuse_iterations = iterations;
            tolerance        = linear_tolerance;
          }

          /** Factorise the current matrix and solve. */
          void
          factorise_and_solve(System               &system,
                              System::Vector       &du,
                              const System::Vector &rhs,
                              const bool            initial_tangent)
          {
            if (!direct)
              make(system);
            solve_with(du, rhs, true, initial_tangent);
          }

          void
          forget() override
          {
            is_initial = false;
          }

          bool
          has_kept_factors() const override
          {
            return direct != nullptr && factorised;
          }

          void
          solve_with_kept_factors(System &,
                                  System::Vector       &du,
                                  const System::Vector &rhs) override
          {
            const auto start = Clock::now();
            ++statistics.n_solves;
            ++statistics.n_chord_solves;
            apply_factors(du, rhs);
            statistics.seconds +=
              std::chrono::duration<double>(Clock::now() - start).count();
          }

        protected:
          void
          do_solve(System               &system,
                   System::Vector       &du,
                   const System::Vector &rhs,
                   const bool            initial_tangent,
                   const bool            reuse) override
          {
            const bool fresh = !direct;
            if (fresh)
              make(system);
            if (!fresh && !reuse && reuse_iterations > 0 && factorised &&
                solve_with_old_factors(system, du, rhs))
              {
                // the kept factorisation is no longer that of this matrix
                is_initial = false;
                return;
              }
            solve_with(du, rhs, fresh || !reuse, initial_tangent);
          }

          bool
          kept_is_initial() const override
          {
            return is_initial;
          }

        private:
          /** The last factorisation as a preconditioner. */
          struct OldFactors
          {
            Direct *direct;
            void
            vmult(System::Vector &dst, const System::Vector &src) const
            {
              direct->apply_factors(dst, src);
            }
          };

          /** dst = the kept factors' inverse times src. */
          void
          apply_factors(System::Vector &dst, const System::Vector &src)
          {
            int result = 0;
            problem.SetLHS(&dst.trilinos_vector());
            problem.SetRHS(
              const_cast<Epetra_MultiVector *>(&src.trilinos_vector()));
            quietly([&]() { return direct->Solve(); }, result);
            if (result != 0 || failed())
              fail("failed in the solve with the factorised tangent");
          }

          /**
           * GMRES (right-preconditioned: the true residual) on the current
           * matrix with the last factorisation as the preconditioner, to
           * the relative `tolerance'; false (du zeroed) when it needs more
           * than `reuse_iterations' or fails.
           */
          bool
          solve_with_old_factors(System               &system,
                                 System::Vector       &du,
                                 const System::Vector &rhs)
          {
            SolverControl control(reuse_iterations,
                                  tolerance * rhs.l2_norm(),
                                  false,
                                  false);
            try
              {
                SolverGMRES<System::Vector> gmres(
                  control,
                  SolverGMRES<System::Vector>::AdditionalData(reuse_iterations +
                                                                2,
                                                              true));
                gmres.solve(system.matrix, du, rhs, OldFactors{this});
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
          make(System &system)
          {
            problem.SetOperator(
              const_cast<Epetra_CrsMatrix *>(&system.matrix.trilinos_matrix()));
            Amesos factory;
            direct.reset(factory.Create(name.c_str(), problem));
            AssertThrow(direct != nullptr,
                        ExcMessage(name +
                                   " is not available in this Trilinos"));
            if (const auto mumps = dynamic_cast<Amesos_Mumps *>(direct.get()))
              {
                choose_ordering(*mumps, system.comm);
                // null pivot detection (MUMPS's threshold, CNTL(3) = 0): a
                // brick held only by debonded frictionless joints, or a
                // deleted cell's neighbour, is free in some direction and
                // the tangent singular there. Without it, MUMPS factorised
                // the round-off and the corrections moved such parts
                // arbitrarily far, so Newton stalled at the joints' contact
                // switches (doc/brickwork.md, Stabilisation)
                mumps->SetICNTL(24, 1);
              }
            int result = 0;
            quietly([&]() { return direct->SymbolicFactorization(); }, result);
            if (result != 0 || failed())
              fail("could not analyse the tangent");
          }

          /**
           * MUMPS's fill-reducing ordering (ICNTL(7)): of AMF, PORD and
           * QAMD the one whose analysis predicts the fewest flops of a
           * factorisation (RINFOG(1)), rank 0's choice on every rank. The
           * analysis is done once a run and the factorisation once a Newton
           * iteration, so the trial costs nothing against what it saves.
           * MUMPS's own choice (ICNTL(7) = 7) takes AMF for the single
           * cyclic example: 2.37e8 flops, where QAMD needs 1.63e8 (9 % of
           * the CPU time of its first 300 steps); PORD, its choice for the
           * double and triple ones, is the best there (triple: 4.4e9, AMF
           * 5.2e9, QAMD 5.5e9).
           * METIS and SCOTCH are not in Debian's sequential analysis
           * (contrib/benchmarks/wallette_cyclic/results-2026-11-25c.md).
           */
          void
          choose_ordering(Amesos_Mumps &mumps, const MPI_Comm comm)
          {
            int    best   = 7;
            double fewest = std::numeric_limits<double>::infinity();
            for (const int ordering : {2, 4, 6})
              {
                mumps.SetICNTL(7, ordering);
                int result = 0;
                quietly([&]() { return mumps.SymbolicFactorization(); },
                        result);
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
          solve_with(System::Vector       &du,
                     const System::Vector &rhs,
                     const bool            factorise,
                     const bool            initial_tangent)
          {
            int result = 0;
            if (factorise)
              {
                // (a failed factorisation is no longer the kept one)
                is_initial = false;
                factorised = false;
                quietly([&]() { return direct->NumericFactorization(); },
                        result);
                if (result != 0 || failed())
                  fail("could not factorise the tangent");
                ++statistics.n_factorisations;
                if (const auto mumps =
                      dynamic_cast<Amesos_Mumps *>(direct.get()))
                  if (mumps->GetINFOG()[27] > 0) // INFOG(28)
                    ++statistics.n_null_pivot_factorisations;
                factorised = true;
                is_initial = initial_tangent;
              }
            apply_factors(du, rhs);
          }

          /** Whether MUMPS reported an error (INFOG(1) < 0). */
          bool
          failed()
          {
            const auto mumps = dynamic_cast<Amesos_Mumps *>(direct.get());
            return mumps != nullptr && mumps->GetINFOG()[0] < 0;
          }

          /** A one-line error of the solver, with MUMPS's INFOG. */
          [[noreturn]] void
          fail(const std::string &what)
          {
            std::ostringstream m;
            const auto mumps = dynamic_cast<Amesos_Mumps *>(direct.get());
            if (mumps != nullptr)
              {
                const int *infog = mumps->GetINFOG();
                m << "MUMPS " << what << ": INFOG(1) = " << infog[0]
                  << ", INFOG(2) = " << infog[1] << " ("
                  << mumps_meaning(infog[0]) << ")";
              }
            else
              m << name << " " << what;
            throw LinearSolverFailure(m.str());
          }

          std::string                        name;
          unsigned int                       reuse_iterations = 0;
          double                             tolerance        = 1e-10;
          Epetra_LinearProblem               problem;
          std::unique_ptr<Amesos_BaseSolver> direct;
          bool                               is_initial = false;
          /** A numeric factorisation (of some earlier tangent) exists. */
          bool factorised = false;
        };

        /**
         * CG or GMRES with Trilinos ML AMG. Cracked and crushed regions
         * can make the tangent so badly conditioned that the Krylov solver
         * stalls or AztecOO reports a loss of precision. Damage does not
         * heal, so the tangents of the rest of the run are no better: the
         * failed solve and all later ones use MUMPS.
         */
        class KrylovWithFallback : public LinearSolver
        {
        public:
          KrylovWithFallback(const bool                  cg,
                             const double                tolerance,
                             dealii::ConditionalOStream &pcout)
            : cg(cg)
            , tolerance(tolerance)
            , pcout(pcout)
            , fallback("Amesos_Mumps")
          {}

          void
          forget() override
          {
            is_initial = false;
            fallback.forget();
          }

        protected:
          void
          do_solve(System               &system,
                   System::Vector       &du,
                   const System::Vector &rhs,
                   const bool            initial_tangent,
                   const bool            reuse) override
          {
            if (abandoned)
              {
                fallback.solve_as_fallback(
                  system, du, rhs, initial_tangent, reuse);
                return;
              }
            if (!reuse)
              amg.reset();
            if (!amg)
              make_amg(system, initial_tangent);
            // AMG-preconditioned Krylov needs tens of iterations on an
            // intact or moderately damaged tangent; a solve that needs
            // more than this is stalling
            SolverControl control(1000, tolerance * rhs.l2_norm());
            try
              {
                if (cg)
                  {
                    TrilinosWrappers::SolverCG solver(control);
                    solver.solve(system.matrix, du, rhs, *amg);
                  }
                else
                  {
                    TrilinosWrappers::SolverGMRES solver(control);
                    solver.solve(system.matrix, du, rhs, *amg);
                  }
              }
            catch (const std::exception &)
              {
                ++statistics.n_direct_fallbacks;
                abandoned = true;
                amg.reset();
                pcout << "  note: the Krylov solver failed on the damaged "
                         "tangent; MUMPS solves from here on\n";
                du = 0;
                fallback.factorise_and_solve(system, du, rhs, initial_tangent);
              }
          }

          bool
          kept_is_initial() const override
          {
            return abandoned ? fallback.initial() : is_initial;
          }

          bool
          fallen_back() const override
          {
            return abandoned;
          }

          void
          set_fallen_back() override
          {
            abandoned = true;
          }

        private:
          /** The direct solver a failed Krylov solver hands over to. */
          class Fallback : public Direct
          {
          public:
            using Direct::Direct;
            void
            solve_as_fallback(System               &system,
                              System::Vector       &du,
                              const System::Vector &rhs,
                              const bool            initial_tangent,
                              const bool            reuse)
            {
              do_solve(system, du, rhs, initial_tangent, reuse);
            }
            bool
            initial() const
            {
              return kept_is_initial();
            }
          };

          void
          make_amg(System &system, const bool initial_tangent)
          {
            amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
            TrilinosWrappers::PreconditionAMG::AdditionalData data;
            std::vector<std::vector<bool>>                    modes;
            DoFTools::extract_constant_modes(system.dof_handler,
                                             ComponentMask(3, true),
                                             modes);
            data.constant_modes        = modes;
            data.elliptic              = true;
            data.higher_order_elements = false;
            data.smoother_sweeps       = 2;
            data.aggregation_threshold = 0.02;
            amg->initialize(system.matrix, data);
            is_initial = initial_tangent;
          }

          bool                                               cg;
          double                                             tolerance;
          dealii::ConditionalOStream                        &pcout;
          Fallback                                           fallback;
          std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
          bool abandoned = false, is_initial = false;
        };
      } // namespace

      std::unique_ptr<LinearSolver>
      create_linear_solver(const LinearSolverSettings &settings,
                           dealii::ConditionalOStream &pcout)
      {
        const std::string &s = settings.linear_solver;
        if (s == "direct")
          {
            auto direct = std::make_unique<Direct>("Amesos_Mumps");
            direct->enable_reuse(settings.reuse_iterations,
                                 settings.linear_tolerance);
            return direct;
          }
        if (s == "direct klu")
          return std::make_unique<Direct>("Amesos_Klu");
        AssertThrow(s == "cg amg" || s == "gmres amg",
                    ExcMessage("unknown linear solver " + s));
        return std::make_unique<KrylovWithFallback>(s == "cg amg",
                                                    settings.linear_tolerance,
                                                    pcout);
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
