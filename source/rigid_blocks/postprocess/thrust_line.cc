/**
 * @file
 * Postprocessor `thrust line`: thrust_line.csv.
 */
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/rigid_blocks/postprocess/interface.h>

#include <cmath>
#include <iomanip>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      /**
       * The line of thrust: for every interface the centre of pressure of
       * its normal contact forces, the resultants and the eccentricity
       * across the thickness. Written for the analyses with fixed supports
       * (limit load, minimum thickness), whose contact forces are the
       * statically admissible state at collapse.
       */
      class ThrustLine : public Interface
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &)
        {}

        void
        execute(const Result &result, RunContext &context) override
        {
          if (!result.is_root() || result.supports_move())
            return;
          OutputFile csv(context.output.file("thrust_line.csv"));
          csv << "# line of thrust: per interface the centre of pressure of "
                 "the normal contact forces (m), the resultant normal force N "
                 "and shear forces (N, from the LP dual), the eccentricity e "
                 "(m) of the centre of pressure across the thickness (towards "
                 "the extrados positive) and e/(t/2)\n";
          csv << "interface,first_block,second_block,x,y,z,normal_force,"
                 "shear_across,shear_along,eccentricity,eccentricity_ratio\n";
          csv << std::setprecision(10);
          unsigned int p          = 0;
          const auto  &interfaces = result.model().interfaces();
          for (unsigned int k = 0; k < interfaces.size(); ++k)
            {
              const auto          &i = interfaces[k];
              double               n = 0, sa = 0, sl = 0, half = 0;
              dealii::Tensor<1, 3> moment;
              for (const auto &c : i.points)
                {
                  if (p < result.n_forces())
                    {
                      const auto f = result.force(p);
                      n += f[0];
                      sa += f[1];
                      sl += f[2];
                      moment += f[0] * (c.position - i.centre);
                    }
                  half = std::max(half,
                                  std::abs((c.position - i.centre) * c.across));
                  ++p;
                }
              if (std::abs(n) < 1e-12 * (std::abs(sa) + std::abs(sl) + 1e-300))
                continue;
              const dealii::Point<3> x = i.centre + moment / n;
              const double e = (x - i.centre) * i.points.front().across;
              csv << k << "," << i.first << ","
                  << (i.second == rigid_blocks::Interface::support ?
                        std::string("support") :
                        std::to_string(i.second))
                  << "," << x[0] << "," << x[1] << "," << x[2] << "," << n
                  << "," << sa << "," << sl << "," << e << ","
                  << (half > 0 ? e / half : 0.) << "\n";
            }
          csv.close();
        }
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  masonry::rigid_blocks::postprocess::ThrustLine,
  "thrust line",
  "thrust_line.csv (analyses with fixed supports: limit load, minimum "
  "thickness): per interface the centre of pressure of the normal contact "
  "forces (the line of thrust of an arch, m), the normal and shear "
  "resultants (N) and the eccentricity across the thickness (m and "
  "relative to t/2). Computed from the contact forces of `interface "
  "forces', so not unique where the vault is statically indeterminate at "
  "collapse (the default interior point and `Crossover = always' differ); "
  "tension within a joint's cut-off can put the centre of pressure outside "
  "the section (e/(t/2) > 1).")
