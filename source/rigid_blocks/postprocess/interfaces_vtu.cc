/**
 * @file
 * Postprocessor `interfaces vtu`: interfaces.vtu.
 */
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/core/vtu_grid.h>
#include <masonry/rigid_blocks/postprocess/interface.h>


namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      /**
       * The interfaces as quadrilaterals between neighbouring stations, on
       * the first block's side, in the displaced configuration.
       */
      class InterfacesVtu : public Interface
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &)
        {}

        void
        execute(const Result &result, RunContext &context) override
        {
          context.summary["displacement_amplification"] =
            result.amplification();
          if (!result.is_root())
            return;
          const BlockModel                 &model      = result.model();
          const auto                       &interfaces = model.interfaces();
          const double                      a          = result.amplification();
          VtuGrid                           grid;
          std::vector<double>               opening, normal_force, support;
          std::vector<dealii::Tensor<1, 3>> displacement, ground;
          unsigned int                      p = 0;
          for (unsigned int k = 0; k < interfaces.size(); ++k)
            {
              const rigid_blocks::Interface &i    = interfaces[k];
              const unsigned int             base = grid.points.size();
              const bool                     on_support =
                i.second == rigid_blocks::Interface::support;
              double force = 0;
              for (const auto &c : i.points)
                {
                  const dealii::Tensor<1, 3> u =
                    result.motion().displacement(model, i.first, c.position);
                  grid.points.push_back(c.position + a * u);
                  displacement.push_back(u);
                  ground.push_back(
                    on_support ?
                      result.support_motion(c.position, i.support_label) :
                      dealii::Tensor<1, 3>());
                  if (p < result.n_forces())
                    force += result.force(p)[0];
                  ++p;
                }
              // points come in (intrados, extrados) pairs per station
              for (unsigned int s = 0; s + 3 < i.points.size(); s += 2)
                {
                  for (const unsigned int v :
                       {base + s, base + s + 2, base + s + 3, base + s + 1})
                    grid.connectivity.push_back(v);
                  opening.push_back(result.interface_opening()[k]);
                  normal_force.push_back(force);
                  support.push_back(on_support ? 1 : 0);
                }
            }
          grid.nodes_per_cell = 4;
          grid.cell_type      = 9;
          grid.cell_data.emplace_back("opening", std::move(opening));
          grid.cell_data.emplace_back("normal_force", std::move(normal_force));
          grid.cell_data.emplace_back("support", std::move(support));
          grid.point_vectors.emplace_back("displacement",
                                          std::move(displacement));
          grid.point_vectors.emplace_back("support_motion", std::move(ground));
          OutputFile out(context.output.file("interfaces.vtu"));
          grid.write(out);
          out.close();
        }
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  masonry::rigid_blocks::postprocess::InterfacesVtu,
  "interfaces vtu",
  "interfaces.vtu: every interface as quadrilaterals between its stations "
  "on the first block's side, displaced like blocks.vtu, with the cell "
  "data opening (the largest normal opening of the interface, m), "
  "normal_force (the sum of its normal contact forces, N) and support (1 "
  "on a support joint, 0 between blocks), and the point data displacement "
  "(of the first block, m, not amplified) and support_motion (the "
  "prescribed motion of the ground at a support point, m; zero elsewhere).")
