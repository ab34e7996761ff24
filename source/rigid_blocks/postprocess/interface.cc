#include <masonry/rigid_blocks/postprocess/interface.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      Result::Result(const BlockModel                         &model,
                     const Motion                             &motion,
                     const SupportMotion                      &support_motion,
                     const std::vector<std::array<double, 3>> &forces,
                     const OutputOptions                      &options,
                     const bool                                supports_move,
                     const MPI_Comm                            mpi_communicator,
                     const bool                                has_solution)
        : block_model(model)
        , block_motion(motion)
        , ground(support_motion)
        , contact_forces(forces)
        , output_options(options)
        , moving_supports(supports_move)
        , mpi_communicator(mpi_communicator)
        , root(dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        , solution(has_solution)
      {
        const auto &interfaces = model.interfaces();
        // the scales of "zero" jumps and of the amplification: the largest
        // block displacement and the largest prescribed support motion
        for (const auto &i : interfaces)
          for (const auto &c : i.points)
            {
              largest_displacement = std::max(
                largest_displacement,
                motion.displacement(model, i.first, c.position).norm());
              if (i.second == rigid_blocks::Interface::support)
                largest_support_motion =
                  std::max(largest_support_motion,
                           ground(c.position, i.support_label).norm());
            }
        opening.assign(interfaces.size(), 0.);
        for (unsigned int k = 0; k < interfaces.size(); ++k)
          for (unsigned int p = 0; p < interfaces[k].points.size(); ++p)
            {
              const auto  &c = interfaces[k].points[p];
              const double o = jump(interfaces[k], c) * c.normal;
              opening[k]     = p == 0 ? o : std::max(opening[k], o);
            }
        // the support motion counts too, so that the round-off motion of
        // blocks that stay put (a vault lifting off a settling support) is
        // not blown up to 5 % of the vault
        const double scale =
          std::max(largest_displacement, largest_support_motion);
        displacement_amplification =
          options.amplification > 0 ?
            options.amplification :
            (scale > 0 ? 0.05 * model.length_scale() / scale : 1.0);
      }

      dealii::Tensor<1, 3>
      Result::jump(const rigid_blocks::Interface &i,
                   const ContactPoint            &c) const
      {
        const dealii::Tensor<1, 3> first =
          block_motion.displacement(block_model, i.first, c.position);
        const dealii::Tensor<1, 3> second =
          i.second == rigid_blocks::Interface::support ?
            ground(c.position, i.support_label) :
            block_motion.displacement(block_model, i.second, c.position);
        return second - first;
      }

      dealii::Tensor<1, 2>
      Result::view_direction() const
      {
        const BlockModel    &model = block_model;
        dealii::Tensor<1, 3> centre, weighted;
        double               weight = 0;
        for (const auto &b : model.blocks())
          centre += b.centroid / double(model.blocks().size());
        for (const auto &i : model.interfaces())
          if (i.second == rigid_blocks::Interface::support)
            {
              const double w = ground(i.centre, i.support_label).norm();
              weighted += w * (i.centre - dealii::Point<3>(centre));
              weight += w;
            }
        if (weight == 0)
          for (unsigned int b = 0; b < model.blocks().size(); ++b)
            weighted += block_motion.translation[b].norm() *
                        (model.blocks()[b].centroid - dealii::Point<3>(centre));
        dealii::Tensor<1, 2> d;
        d[0] = weighted[0];
        d[1] = weighted[1];
        return d.norm() >
                   1e-9 * model.length_scale() *
                     std::max(largest_displacement, largest_support_motion) ?
                 d / d.norm() :
                 dealii::Tensor<1, 2>();
      }

      void
      Result::render(const ScriptJob                            &job,
                     std::function<void(const std::string &why)> done) const
      {
        pictures.emplace_back(job, std::move(done));
      }

      double
      Result::render_pictures() const
      {
        if (pictures.empty())
          return 0;
        const auto             start = std::chrono::steady_clock::now();
        std::vector<ScriptJob> jobs;
        for (const auto &p : pictures)
          jobs.push_back(p.first);
        const std::vector<std::string> why = run_scripts(jobs);
        for (unsigned int j = 0; j < pictures.size(); ++j)
          pictures[j].second(why[j]);
        pictures.clear();
        return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                             start)
          .count();
      }

      const char *
      Interface::default_plugin()
      {
        return "support reactions, thrust line, cracks, interface forces, "
               "blocks csv, blocks vtu, interfaces vtu, vault pvd, "
               "vault picture, crack map, report";
      }

      std::string
      Interface::selection_documentation()
      {
        return "Comma-separated list of the outputs of the rigid-block "
               "analyses (settlement, limit load, minimum thickness), "
               "written once the LP has an optimum (`report' also for a "
               "run without one: status and explanation); an output that "
               "needs "
               "another (the picture reads the VTU files) runs it too. "
               "The default writes every output; a shorter list skips the "
               "work and the files of the others. A plugin of an "
               "`Additional shared libraries' file is listed by its name.";
      }



      std::vector<std::string>
      Interface::required_plugins() const
      {
        return {};
      }

      bool
      Interface::writes_without_solution() const
      {
        return false;
      }
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry
