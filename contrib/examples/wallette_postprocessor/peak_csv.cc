/**
 * @file
 * An output added to masonry's wallette analysis from outside: the
 * postprocessor `peak csv` writes peak.csv, the curve point of the largest
 * stress and the largest value of each component of the joints' state at
 * the end of the run. It reads the run through the public model view only.
 */
#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/postprocessor.h>
#include <masonry/core/output_directory.h>

#include <deal.II/base/mpi.h>

#include <fstream>
#include <iomanip>

namespace
{
  using namespace masonry::brickwork;

  class PeakCsv : public postprocess::Postprocessor
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("File name",
                        "peak.csv",
                        dealii::Patterns::FileName(),
                        "The file, in the output directory.");
    }

    void
    parse_parameters(dealii::ParameterHandler &prm) override
    {
      file_name = prm.get("File name");
    }

    void
    finish(const ModelView &view, masonry::Json &) override
    {
      // the states of the law of the bed joints (also that of the head
      // and collar joints), over the faces of that law: largest value of
      // each component on this rank, then over the ranks (a rank holds
      // current states of its own faces only, the others keep the initial
      // state)
      const InterfaceLaw            &law = view.laws.joint_law(0);
      const std::vector<std::string> names =
        component_names(law.state_variables());
      std::vector<double> largest(names.size(), -1e300);
      for (unsigned int p = 0; p < view.n_joint_points(); ++p)
        {
          if (&view.joint_law_of(p / 4) != &law)
            continue;
          const ConstStateView state = view.joint_state(p);
          for (unsigned int k = 0; k < names.size(); ++k)
            largest[k] = std::max(largest[k], state[k]);
        }
      for (auto &x : largest)
        x = dealii::Utilities::MPI::max(x, view.context.mpi_communicator);
      if (!view.is_root())
        return;
      const auto  &curve = view.curve;
      unsigned int peak  = 0;
      for (unsigned int i = 0; i < curve.size(); ++i)
        if (curve[i].stress > curve[peak].stress)
          peak = i;
      std::ofstream csv(view.context.output.file(file_name));
      csv << std::setprecision(12) << "quantity,value\n"
          << "step," << peak << "\n"
          << "strain," << curve[peak].strain << "\n"
          << "stress_Pa," << curve[peak].stress << "\n"
          << "displacement_m," << curve[peak].displacement << "\n"
          << "force_N," << curve[peak].force << "\n"
          << "height_m," << view.height() << "\n";
      for (unsigned int k = 0; k < names.size(); ++k)
        csv << "max_joint_" << names[k] << "," << largest[k] << "\n";
    }

  private:
    std::string file_name;
  };
} // namespace

MASONRY_REGISTER_WALLETTE_POSTPROCESSOR(
  PeakCsv,
  "peak csv",
  "peak.csv (`File name'): the step of the largest stress with its strain, "
  "stress (Pa), platen displacement (m) and force (N), the height (m), and "
  "the largest value of each component of the joints' state at the end.")
