/**
 * @file
 * The Krylov solvers with AMG.
 */
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include "krylov.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using namespace dealii;

      KrylovWithFallback::KrylovWithFallback(const bool cg)
        : cg(cg)
        , fallback("Amesos_Mumps")
      {}

      KrylovWithFallback::~KrylovWithFallback() = default;

      void
      KrylovWithFallback::forget()
      {
        is_initial = false;
        fallback.forget();
      }

      void
      KrylovWithFallback::clear()
      {
        amg.reset();
        fallback.clear();
        is_initial = false;
      }

      void
      KrylovWithFallback::do_solve(const Matrix &matrix,
                                   Vector       &du,
                                   const Vector &rhs,
                                   const bool    initial_tangent,
                                   const bool    reuse)
      {
        if (abandoned)
          {
            fallback.solve_as_fallback(matrix, du, rhs, initial_tangent, reuse);
            return;
          }
        if (!reuse)
          amg.reset();
        if (!amg)
          make_amg(matrix, initial_tangent);
        // AMG-preconditioned Krylov needs tens of iterations on an
        // intact or moderately damaged tangent; a solve that needs
        // more than this is stalling
        SolverControl control(1000, tolerance * rhs.l2_norm());
        try
          {
            if (cg)
              {
                TrilinosWrappers::SolverCG solver(control);
                solver.solve(matrix, du, rhs, *amg);
              }
            else
              {
                TrilinosWrappers::SolverGMRES solver(control);
                solver.solve(matrix, du, rhs, *amg);
              }
          }
        catch (const std::exception &)
          {
            ++statistics.n_direct_fallbacks;
            abandoned = true;
            amg.reset();
            *pcout << "  note: the Krylov solver failed on the damaged "
                      "tangent; MUMPS solves from here on\n";
            du = 0;
            fallback.factorise_and_solve(matrix, du, rhs, initial_tangent);
          }
      }

      bool
      KrylovWithFallback::kept_is_initial() const
      {
        return abandoned ? fallback.initial() : is_initial;
      }

      bool
      KrylovWithFallback::fallen_back() const
      {
        return abandoned;
      }

      void
      KrylovWithFallback::set_fallen_back()
      {
        abandoned = true;
      }

      void
      KrylovWithFallback::Fallback::solve_as_fallback(
        const Matrix &matrix,
        Vector       &du,
        const Vector &rhs,
        const bool    initial_tangent,
        const bool    reuse)
      {
        do_solve(matrix, du, rhs, initial_tangent, reuse);
      }

      bool
      KrylovWithFallback::Fallback::initial() const
      {
        return kept_is_initial();
      }

      void
      KrylovWithFallback::make_amg(const Matrix &matrix,
                                   const bool    initial_tangent)
      {
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        std::vector<std::vector<bool>>                    modes;
        DoFTools::extract_constant_modes(*dof_handler,
                                         ComponentMask(3, true),
                                         modes);
        data.constant_modes        = modes;
        data.elliptic              = true;
        data.higher_order_elements = false;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        amg->initialize(matrix, data);
        is_initial = initial_tangent;
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
