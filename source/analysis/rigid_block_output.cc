/**
 * @file
 * The output of the rigid-block analyses (RigidBlockAnalysis): the result
 * line and the outputs of a run without a solution, the postprocessors'
 * results, the LP's MPS export and the summary's records of the model,
 * the LP and its check.
 */
#include <masonry/analysis/rigid_block_analysis.h>
#include <masonry/core/json.h>
#include <masonry/core/output_directory.h>
#include <masonry/rigid_blocks/postprocess/interface.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace masonry
{
  namespace analysis
  {
    namespace
    {
      using Clock = std::chrono::steady_clock;

      /** Seconds since @p start. */
      double
      seconds_since(const Clock::time_point &start)
      {
        return std::chrono::duration<double>(Clock::now() - start).count();
      }
    } // namespace

    void
    RigidBlockAnalysis::report(RunContext        &context,
                               const std::string &status,
                               const std::string &explanation) const
    {
      context.summary["status"]      = status;
      context.summary["explanation"] = explanation;
      context.pcout << "Result: " << status << " — " << explanation << "\n";
      if (quiet || !model)
        return;
      // no solution: the blocks at rest, no contact forces; the outputs
      // that can say something without one (the report page) run
      const auto                               start = Clock::now();
      const rigid_blocks::Motion               rest(model->blocks().size());
      const std::vector<std::array<double, 3>> no_forces;
      const rigid_blocks::SupportMotion ground = prescribed_support_motion();
      bool                              moves  = false;
      for (const auto &i : model->interfaces())
        if (i.second == rigid_blocks::Interface::support)
          for (const auto &c : i.points)
            moves = moves || ground(c.position, i.support_label).norm() > 0;
      const rigid_blocks::postprocess::Result result(*model,
                                                     rest,
                                                     ground,
                                                     no_forces,
                                                     output_options,
                                                     moves,
                                                     context.mpi_communicator,
                                                     false);
      bool                                    any = false;
      for (const auto &[name, postprocessor] : postprocessors)
        if (postprocessor->writes_without_solution())
          {
            postprocessor->execute(result, context);
            any = true;
          }
      if (any)
        {
          result.render_pictures();
          context.summary["seconds_output"] = seconds_since(start);
        }
    }

    double
    RigidBlockAnalysis::centimetre_scale(const std::vector<double> &x) const
    {
      double largest = 0;
      for (unsigned int b = 0; b < model->blocks().size(); ++b)
        for (unsigned int d = 0; d < 3; ++d)
          largest = std::max(largest, std::abs(x[6 * b + d]));
      return largest > 0 ? 0.01 / largest : 1.;
    }

    void
    RigidBlockAnalysis::write_results(
      const rigid_blocks::Motion               &motion,
      const rigid_blocks::SupportMotion        &support_motion,
      const bool                                supports_move,
      const std::vector<std::array<double, 3>> &forces,
      RunContext                               &context) const
    {
      const auto                              start = Clock::now();
      const rigid_blocks::postprocess::Result result(*model,
                                                     motion,
                                                     support_motion,
                                                     forces,
                                                     output_options,
                                                     supports_move,
                                                     context.mpi_communicator);
      for (const auto &[name, postprocessor] : postprocessors)
        postprocessor->execute(result, context);
      // the pictures the postprocessors queued, in one Python process
      const double seconds_picture = result.render_pictures();
      if (seconds_picture > 0)
        context.summary["seconds_picture"] = seconds_picture;
      // what writing the results costs (not part of the analysis' timings)
      context.summary["seconds_output"] = seconds_since(start);
    }

    void
    RigidBlockAnalysis::write_mechanism(
      const rigid_blocks::Motion               &motion,
      const std::vector<std::array<double, 3>> &forces,
      RunContext                               &context) const
    {
      write_results(
        motion,
        [](const dealii::Point<3> &, const std::string &) {
          return dealii::Tensor<1, 3>();
        },
        false,
        forces,
        context);
    }

    void
    RigidBlockAnalysis::export_lp(const lp::LinearProgram &lp,
                                  RunContext              &context,
                                  const std::string       &mps_name) const
    {
      if (!quiet && solver->export_mps() &&
          dealii::Utilities::MPI::this_mpi_process(context.mpi_communicator) ==
            0)
        lp.write_mps(context.output.file(mps_name));
    }

    void
    RigidBlockAnalysis::check_solution(const lp::Solution &solution,
                                       RunContext         &context) const
    {
      const lp::PairCheck &c       = solution.check;
      Json                &summary = context.summary;
      summary["lp_max_violation"]  = c.primal_residual;
      summary["lp_dual_violation"] = c.dual_residual;
      summary["lp_relative_gap"]   = c.relative_gap();
      const bool passed            = c.within(solver->check_tolerance());
      summary["lp_check"]          = passed ? "passed" : "failed";
      if (!passed)
        {
          std::ostringstream line;
          line << std::setprecision(3)
               << "Warning: the LP solver's optimum fails the check on the "
                  "LP (tolerance "
               << solver->check_tolerance() << ", LP units): bound violation "
               << c.primal_residual << ", dual sign violation "
               << c.dual_residual << ", relative duality gap "
               << c.relative_gap()
               << "; the results are uncertain by about that much\n";
          context.pcout << line.str();
        }
    }

    void
    RigidBlockAnalysis::record_model(RunContext              &context,
                                     const lp::LinearProgram *lp) const
    {
      Json &summary               = context.summary;
      summary["n_blocks"]         = model->blocks().size();
      summary["n_interfaces"]     = model->interfaces().size();
      summary["n_contact_points"] = model->n_contact_points();
      summary["interface_model"]  = joints_name;
      if (lp)
        {
          summary["lp_rows"]     = lp->n_rows();
          summary["lp_columns"]  = lp->n_columns();
          summary["lp_nonzeros"] = lp->n_nonzeros();
        }
      summary["lp_solver"]         = solver_name;
      summary["lp_solves"]         = n_solves;
      summary["lp_iterations"]     = n_iterations;
      summary["seconds_geometry"]  = seconds_geometry;
      summary["seconds_assembly"]  = seconds_assembly;
      summary["seconds_solve"]     = seconds_solve;
      summary["cpu_seconds_solve"] = cpu_seconds_solve;
    }

    void
    RigidBlockAnalysis::record(const lp::LinearProgram &lp,
                               const lp::Solution      &solution,
                               RunContext              &context) const
    {
      record_model(context, &lp);
      Json &summary         = context.summary;
      summary["lp_message"] = solution.message;
      if (solution.status == lp::Status::optimal)
        check_solution(solution, context);
    }
  } // namespace analysis
} // namespace masonry
