/**
 * @file
 * Default hooks of the postprocessors and the list of a run.
 */
#include <masonry/brickwork/postprocessor.h>

namespace masonry
{
  namespace brickwork
  {
    void
    OutputSettings::declare_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Bool;
      using dealii::Patterns::Integer;
      using dealii::Patterns::Selection;
      prm.declare_entry("Output interval",
                        "10",
                        Integer(0, 100000),
                        "Write VTU/PVTU (bricks) and VTU (interfaces) "
                        "every this many converged steps, and after the "
                        "last; 0: only the initial and the last state.");
      prm.declare_entry("Write VTU",
                        "true",
                        Bool(),
                        "Write the VTU/PVTU/PVD time series "
                        "(solution.pvd: displacement in m, stress in Pa, "
                        "MPI subdomain; interfaces.pvd: damage, normal "
                        "opening and slip in m, joint type).");
      prm.declare_entry(
        "Output format",
        "vtu",
        Selection("vtu|hdf5"),
        "Format of the brick and joint fields when `Write VTU' is true: `vtu' "
        "writes solution.pvd with solution_NNNN.pvtu and one .vtu per "
        "rank; `hdf5' writes solution.xdmf with one solution_NNNN.h5 per "
        "output step (mesh and fields, written in parallel by all ranks; "
        "open solution.xdmf in ParaView with the XDMF reader). The "
        "interfaces follow: interfaces.pvd with interfaces_NNNN.vtu, or "
        "interfaces.xdmf with interfaces_NNNN.h5.");
      prm.declare_entry("Write plot",
                        "true",
                        Bool(),
                        "Draw the stress-strain curve into curve.png "
                        "(matplotlib, /usr/bin/python3).");
      prm.declare_entry(
        "Write CalculiX input",
        "false",
        Bool(),
        "Also write calculix.inp (the mesh as C3D8 elements, the brick "
        "material, the platen conditions and the final platen displacement "
        "as one linear static step, for `ccx -i calculix') and "
        "nodal_displacements.csv (this run's final displacements, m, in "
        "the same node numbering). Needs `Joints = bonded' and an elastic "
        "brick material.");
    }

    void
    OutputSettings::parse_parameters(dealii::ParameterHandler &prm)
    {
      vtu_interval   = prm.get_integer("Output interval");
      write_vtu      = prm.get_bool("Write VTU");
      hdf5           = prm.get("Output format") == "hdf5";
      write_plot     = prm.get_bool("Write plot");
      write_calculix = prm.get_bool("Write CalculiX input");
    }

    namespace postprocess
    {
      const char *
      Postprocessor::default_plugin()
      {
        return "curve tables, fields, joint fields, curve plot, report";
      }

      std::string
      Postprocessor::selection_documentation()
      {
        return "The outputs of the wallette analysis, run in the order of "
               "the list (`curve tables' always runs first: the other "
               "outputs and summary.json use its curve). `fields' and "
               "`joint fields' run only with `Write VTU = true', `curve "
               "plot' only with `Write plot = true'; `Write CalculiX input "
               "= true' adds `calculix'. `report' needs the fields for its 3D view "
               "(it draws the curve and tables without them). Postprocessors of an `Additional "
               "shared libraries' file can be listed too.";
      }



      void
      Postprocessor::start(const ModelView &)
      {}

      void
      Postprocessor::resume(const ModelView &)
      {}

      void
      Postprocessor::step(const ModelView &)
      {}

      void
      Postprocessor::output(const ModelView &, const unsigned int, const double)
      {}

      void
      Postprocessor::finish(const ModelView &, Json &)
      {}

      void
      Postprocessor::after_summary(const ModelView &, const Json &)
      {}

      std::string
      Postprocessor::save() const
      {
        return {};
      }

      void
      Postprocessor::load(const std::string &)
      {}

    } // namespace postprocess
  }   // namespace brickwork
} // namespace masonry
