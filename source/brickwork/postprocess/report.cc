/**
 * @file
 * The model's description in summary.json and on the screen, the detailed
 * model's derived values and the largest damages of the converged states.
 */
#include <deal.II/base/mpi.h>

#include "report.h"

#include <iomanip>

#include "view.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using namespace dealii;

      void
      describe_model(const ModelView &view, const BrickMaterial *mortar)
      {
        const Geometry &geometry  = view.geometry;
        const auto &triangulation = view.system.dof_handler.get_triangulation();
        const auto &settings      = view.settings;
        const Joints       &joints        = view.joints;
        const InterfaceLaw *splitting_law = view.splitting_law;
        ConditionalOStream &pcout         = view.context.pcout;
        Json               &summary       = view.context.summary;
        summary["n_bricks"]               = geometry.n_bricks;
        summary["n_cells"]                = triangulation.n_active_cells();
        summary["n_dofs"]                 = view.system.dof_handler.n_dofs();
        summary["height"]                 = geometry.height;
        summary["length"]                 = geometry.length;
        summary["thickness"]              = geometry.thickness;
        summary["gross_area"]             = geometry.gross_area;
        const auto &nf = joints.n_faces_of_type, &nj = joints.n_joints_of_type;
        for (unsigned int t = 0; t < 3; ++t)
          {
            summary[std::string("n_") + joint_type_name[t] + "_joints"] = nj[t];
            summary[std::string("n_") + joint_type_name[t] +
                    "_interface_faces"]                                 = nf[t];
          }
        pcout << "Wallette: " << geometry.length << " x " << geometry.thickness
              << " x " << geometry.height << " m, " << geometry.n_bricks
              << " enlarged bricks, " << triangulation.n_active_cells()
              << " cells, " << view.system.dof_handler.n_dofs() << " DOFs\n"
              << "Joints (brick pairs / face pairs): bed " << nj[0] << " / "
              << nf[0] << ", head " << nj[1] << " / " << nf[1] << ", collar "
              << nj[2] << " / " << nf[2] << "\n";
        if (mortar)
          {
            const double hm            = settings.mesh.mortar_thickness;
            summary["model"]           = "detailed";
            summary["n_mortar_cells"]  = geometry.n_mortar_cells;
            summary["joint_thickness"] = hm;
            pcout << "Detailed model: units " << settings.mesh.size.length - hm
                  << " x " << settings.mesh.size.width - hm << " x "
                  << settings.mesh.size.height - hm << " m, mortar " << hm
                  << " m thick in " << geometry.n_mortar_cells
                  << " cells; joints are the unit-mortar interfaces\n";
            if (geometry.n_void_cells > 0)
              {
                auto fill = [](const double area, const double void_area) {
                  return area > 0 ? 1 - void_area / area : 1.;
                };
                summary["n_void_cells"]      = geometry.n_void_cells;
                summary["head_joint_area"]   = geometry.head_joint_area;
                summary["head_void_area"]    = geometry.head_void_area;
                summary["collar_joint_area"] = geometry.collar_joint_area;
                summary["collar_void_area"]  = geometry.collar_void_area;
                summary["head_joint_fill"] =
                  fill(geometry.head_joint_area, geometry.head_void_area);
                summary["collar_joint_fill"] =
                  fill(geometry.collar_joint_area, geometry.collar_void_area);
                pcout << "Unfilled joints: " << geometry.n_void_cells
                      << " mortar cells void; head joints "
                      << geometry.head_void_area << " of "
                      << geometry.head_joint_area << " m^2, collar joints "
                      << geometry.collar_void_area << " of "
                      << geometry.collar_joint_area << " m^2\n";
                summary["collar_bed_gap"] = settings.mesh.collar_bed_gap;
                summary["bed_void_area"]  = geometry.bed_void_area;
                if (geometry.bed_void_area > 0)
                  pcout << "Unfilled bed joints along the collar joints: "
                        << geometry.bed_void_area << " m^2 in plan (gap "
                        << settings.mesh.collar_bed_gap << " m on each side)\n";
              }
          }
        if (splitting_law)
          {
            const unsigned int t                   = splitting_type;
            summary["n_split_units"]               = geometry.n_split_units;
            summary["n_splitting_interface_faces"] = nf[t];
            pcout << "Splitting interfaces: " << geometry.n_split_units
                  << " of " << geometry.n_bricks << " units split, " << nf[t]
                  << " face pairs\n";
          }
        // every value a law computed from its inputs
        const std::pair<const char *, std::vector<DerivedValue>> derived[] = {
          {"brick_material", view.material.derived_values()},
          {"mortar_material",
           mortar ? mortar->derived_values() : std::vector<DerivedValue>()},
          {"interface_law", view.law.derived_values()},
          {"splitting_interfaces",
           splitting_law ? splitting_law->derived_values() :
                           std::vector<DerivedValue>()},
          {"detailed_model",
           detailed_values(
             view.material, mortar, view.law, settings.mesh.mortar_thickness)}};
        for (const auto &[part, values] : derived)
          {
            if (values.empty())
              continue;
            Json &out = summary["derived_values"][part];
            pcout << "Derived values (" << part << "):\n";
            for (const auto &v : values)
              {
                out[v.name] = v.value;
                pcout << "  " << v.name << " = " << std::setprecision(6)
                      << v.value << " " << v.unit << "  (" << v.how << ")\n";
              }
          }
      }

      std::vector<DerivedValue>
      detailed_values(const BrickMaterial &material,
                      const BrickMaterial *mortar,
                      const InterfaceLaw  &law,
                      const double         mortar_thickness)
      {
        std::vector<DerivedValue> values;
        if (!mortar)
          return values;
        // the bond's penalties are contact penalties here: how much they
        // add to the mortar layer, and the Lourenco-Rots stiffness that the
        // simplified model would use for the same joint
        const double hm = mortar_thickness, Eb = material.youngs_modulus(),
                     Em = mortar->youngs_modulus(),
                     kn = law.elastic_tangent()[0][0];
        values.push_back({"interface_normal_stiffness",
                          kn,
                          "Pa/m",
                          "the interface law's initial normal penalty"});
        values.push_back(
          {"contact_compliance_ratio",
           (2 / kn) / (hm / Em),
           "-",
           "(2 / k_n) / (h_m / E_m): the two unit-mortar interfaces of a bed "
           "joint against the mortar layer's compliance (small: stiff "
           "contact)"});
        if (Eb > Em)
          values.push_back(
            {"lourenco_rots_normal_stiffness",
             lourenco_rots_stiffness(Eb, Em, hm),
             "Pa/m",
             "E_b E_m / (h_m (E_b - E_m)): the simplified model's joint "
             "stiffness for these moduli, not used by the detailed model"});
        return values;
      }

      std::pair<double, std::vector<double>>
      max_damages(const ModelView &view)
      {
        const MPI_Comm       comm     = view.context.mpi_communicator;
        const Joints        &joints   = view.joints;
        const BrickMaterial &material = view.material;
        const auto &triangulation = view.system.dof_handler.get_triangulation();
        std::vector<double> d;
        double              joint = 0;
        // joints and splitting interfaces
        for (unsigned int n = 0; n < joints.faces.size(); ++n)
          if (joints.faces[n].owned)
            {
              const bool split      = joints.faces[n].type == splitting_type;
              const InterfaceLaw &l = split ? *view.splitting_law : view.law;
              const PointStates  &states =
                split ? view.splitting_points : view.joint_points;
              d.resize(l.damage_names().size());
              for (unsigned int q = 0; q < InterfaceElement::n_points; ++q)
                {
                  l.damages(states.old(InterfaceElement::n_points * n + q), d);
                  for (const double x : d)
                    joint = std::max(joint, x);
                }
            }
        const unsigned int  n_brick = material.damage_names().size();
        std::vector<double> brick(n_brick, 0.), b(n_brick);
        if (!material.is_linear())
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned() &&
                !view.specimen.deleted[cell->active_cell_index()])
              for (unsigned int q = 0; q < 8; ++q)
                {
                  material.damages(
                    view.bricks.old(8 * cell->active_cell_index() + q), b);
                  for (unsigned int k = 0; k < n_brick; ++k)
                    brick[k] = std::max(brick[k], b[k]);
                }
        for (auto &x : brick)
          x = Utilities::MPI::max(x, comm);
        return {Utilities::MPI::max(joint, comm), brick};
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
