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
          const BlockModel   &model      = result.model();
          const auto         &interfaces = model.interfaces();
          const double        a          = result.amplification();
          VtuGrid             grid;
          std::vector<double> opening, normal_force;
          unsigned int        p = 0;
          for (unsigned int k = 0; k < interfaces.size(); ++k)
            {
              const rigid_blocks::Interface &i     = interfaces[k];
              const unsigned int             base  = grid.points.size();
              double                         force = 0;
              for (const auto &c : i.points)
                {
                  grid.points.push_back(
                    c.position + a * result.motion().displacement(model,
                                                                  i.first,
                                                                  c.position));
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
                }
            }
          grid.nodes_per_cell = 4;
          grid.cell_type      = 9;
          grid.cell_data.emplace_back("opening", std::move(opening));
          grid.cell_data.emplace_back("normal_force", std::move(normal_force));
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
  "data opening (the largest normal opening of the interface, m) and "
  "normal_force (the sum of its normal contact forces, N).")
