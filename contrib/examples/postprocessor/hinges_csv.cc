/**
 * @file
 * An output added to masonry from outside: the postprocessor `hinges csv`
 * writes hinges.csv, one row per hinge of a rigid-block mechanism (an
 * interface that opens at one face and stays closed at the other).
 */
#include <masonry/core/output_directory.h>
#include <masonry/rigid_blocks/postprocess/interface.h>

#include <fstream>
#include <iomanip>

namespace
{
  using namespace masonry::rigid_blocks;

  class HingesCsv : public postprocess::Interface
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("File name",
                        "hinges.csv",
                        dealii::Patterns::FileName(),
                        "The file, in the output directory.");
    }

    void
    parse_parameters(dealii::ParameterHandler &prm) override
    {
      file_name = prm.get("File name");
    }

    void
    execute(const postprocess::Result &result,
            masonry::RunContext       &context) override
    {
      if (!result.is_root())
        return;
      std::ofstream csv(context.output.file(file_name));
      csv << "interface,x,y,z,max_opening_m,relative_rotation_rad\n"
          << std::setprecision(10);
      const auto &interfaces = result.model().interfaces();
      const auto &rotation   = result.motion().rotation;
      for (unsigned int k = 0; k < interfaces.size(); ++k)
        {
          // `Interface' alone is the postprocessor base class here
          const masonry::rigid_blocks::Interface &i = interfaces[k];
          double max_opening = -1e300, min_opening = 1e300;
          for (const auto &c : i.points)
            {
              const double opening = result.jump(i, c) * c.normal;
              max_opening          = std::max(max_opening, opening);
              min_opening          = std::min(min_opening, opening);
            }
          if (!(min_opening <= result.tolerance() &&
                max_opening > result.tolerance()))
            continue;
          const dealii::Tensor<1, 3> omega =
            (i.second == masonry::rigid_blocks::Interface::support ?
               dealii::Tensor<1, 3>() :
               rotation[i.second]) -
            rotation[i.first];
          csv << k << "," << i.centre[0] << "," << i.centre[1] << ","
              << i.centre[2] << "," << max_opening << "," << omega.norm()
              << "\n";
        }
    }

  private:
    std::string file_name;
  };
} // namespace

MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(
  HingesCsv,
  "hinges csv",
  "hinges.csv (`File name'): per hinge of the mechanism the interface, its "
  "centre (m), its largest opening (m) and the relative rotation of its "
  "blocks (rad).")
