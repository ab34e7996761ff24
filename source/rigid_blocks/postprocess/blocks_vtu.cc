/**
 * @file
 * Postprocessor `blocks vtu`: blocks.vtu.
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
       * The blocks in the displaced configuration: every block is sampled
       * in parameter space as `Output subdivisions` × `Output subdivisions`
       * curved hexahedra (one across the thickness).
       */
      class BlocksVtu : public Interface
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
          const BlockModel                 &model  = result.model();
          const auto                       &blocks = model.blocks();
          const unsigned int                k = result.options().subdivisions;
          const unsigned int                per_block = (k + 1) * (k + 1) * 2;
          const double                      a         = result.amplification();
          VtuGrid                           grid;
          std::vector<dealii::Tensor<1, 3>> displacement;
          for (unsigned int b = 0; b < blocks.size(); ++b)
            for (unsigned int z = 0; z < 2; ++z)
              for (unsigned int j = 0; j <= k; ++j)
                for (unsigned int i = 0; i <= k; ++i)
                  {
                    const dealii::Point<3> x =
                      model.solid_point(b,
                                        dealii::Point<2>(double(i) / k,
                                                         double(j) / k),
                                        z == 0 ? -0.5 : 0.5);
                    const auto u = result.motion().displacement(model, b, x);
                    grid.points.push_back(x + a * u);
                    displacement.push_back(u);
                  }
          const auto id = [&](unsigned int b,
                              unsigned int i,
                              unsigned int j,
                              unsigned int z) {
            return b * per_block + z * (k + 1) * (k + 1) + j * (k + 1) + i;
          };
          std::vector<int> block_id, patch;
          for (unsigned int b = 0; b < blocks.size(); ++b)
            for (unsigned int j = 0; j < k; ++j)
              for (unsigned int i = 0; i < k; ++i)
                {
                  for (const unsigned int z : {0u, 1u})
                    for (const unsigned int v : {id(b, i, j, z),
                                                 id(b, i + 1, j, z),
                                                 id(b, i + 1, j + 1, z),
                                                 id(b, i, j + 1, z)})
                      grid.connectivity.push_back(v);
                  block_id.push_back(b);
                  patch.push_back(blocks[b].patch);
                }
          grid.nodes_per_cell = 8;
          grid.cell_type      = 12;
          grid.integer_cell_data.emplace_back("block_id", std::move(block_id));
          grid.integer_cell_data.emplace_back("patch", std::move(patch));
          grid.point_vectors.emplace_back("displacement",
                                          std::move(displacement));
          OutputFile out(context.output.file("blocks.vtu"));
          grid.write(out);
          out.close();
        }
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  masonry::rigid_blocks::postprocess::BlocksVtu,
  "blocks vtu",
  "blocks.vtu: the blocks in the displaced configuration (displacements "
  "multiplied by the analysis' `Displacement amplification', also the "
  "summary entry `displacement_amplification'), each sampled as `Output "
  "subdivisions' squared curved hexahedra, with cell data block_id and "
  "patch and the point data displacement (m, not amplified).")
