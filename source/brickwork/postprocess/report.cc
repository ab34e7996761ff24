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
      describe_model(const ModelView &view)
      {
        const LawSet        &laws     = view.laws;
        const BrickMaterial *mortar   = laws.n_regions() > mortar_region ?
                                          &laws.brick_law(mortar_region) :
                                          nullptr;
        const Geometry      &geometry = view.geometry;
        const auto &triangulation = view.system.dof_handler.get_triangulation();
        const auto &settings      = view.settings;
        const Joints       &joints  = view.joints;
        ConditionalOStream &pcout   = view.context.pcout;
        Json               &summary = view.context.summary;
        summary["n_bricks"]         = geometry.n_bricks;
        summary["n_cells"]          = triangulation.n_active_cells();
        summary["n_dofs"]           = view.system.dof_handler.n_dofs();
        summary["height"]           = geometry.height;
        summary["length"]           = geometry.length;
        summary["thickness"]        = geometry.thickness;
        summary["gross_area"]       = geometry.gross_area;
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
        if (laws.has_joint_law(splitting_type))
          {
            const unsigned int t                   = splitting_type;
            summary["n_split_units"]               = geometry.n_split_units;
            summary["n_splitting_interface_faces"] = nf[t];
            pcout << "Splitting interfaces: " << geometry.n_split_units
                  << " of " << geometry.n_bricks << " units split, " << nf[t]
                  << " face pairs\n";
          }
        // every value a law computed from its inputs
        const BrickMaterial &units = laws.brick_law(unit_region);
        const InterfaceLaw  &law   = laws.joint_law(0);
        const std::pair<const char *, std::vector<DerivedValue>> derived[] = {
          {"brick_material", units.derived_values()},
          {"mortar_material",
           mortar ? mortar->derived_values() : std::vector<DerivedValue>()},
          {"interface_law", law.derived_values()},
          {"splitting_interfaces",
           laws.has_joint_law(splitting_type) ?
             laws.joint_law(splitting_type).derived_values() :
             std::vector<DerivedValue>()},
          {"detailed_model",
           detailed_values(
             units, mortar, law, settings.mesh.mortar_thickness)}};
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
        const MPI_Comm comm       = view.context.mpi_communicator;
        const Joints  &joints     = view.joints;
        const LawSet  &laws       = view.laws;
        const auto &triangulation = view.system.dof_handler.get_triangulation();
        std::vector<double> d;
        double              joint = 0;
        // joints and splitting interfaces
        for (unsigned int n = 0; n < joints.faces.size(); ++n)
          if (joints.faces[n].owned)
            {
              const InterfaceLaw &l = view.joint_law_of(n);
              d.resize(l.damage_names().size());
              for (unsigned int q = 0; q < InterfaceElement::n_points; ++q)
                {
                  l.damages(view.joint_state(InterfaceElement::n_points * n +
                                             q),
                            d);
                  for (const double x : d)
                    joint = std::max(joint, x);
                }
            }
        // each region's damages in their columns (0 over the other
        // regions' cells)
        std::vector<double> brick(laws.brick_damage_names().size(), 0.), b;
        // each region's first column and number of damages
        std::vector<unsigned int> first, count;
        for (unsigned int r = 0; r < laws.n_regions(); ++r)
          {
            first.push_back(laws.first_brick_damage(r));
            count.push_back(laws.brick_law(r).damage_names().size());
          }
        if (!laws.bricks_linear())
          for (const auto &cell : triangulation.active_cell_iterators())
            {
              const unsigned int c = cell->active_cell_index();
              if (!cell->is_locally_owned() || view.specimen.deleted[c])
                continue;
              const unsigned int   r   = view.cell_region(c);
              const BrickMaterial &law = laws.brick_law(r);
              b.resize(count[r]);
              for (unsigned int q = 0; q < 8; ++q)
                {
                  law.damages(view.brick_state(8 * c + q), b);
                  for (unsigned int k = 0; k < b.size(); ++k)
                    brick[first[r] + k] = std::max(brick[first[r] + k], b[k]);
                }
            }
        for (auto &x : brick)
          x = Utilities::MPI::max(x, comm);
        return {Utilities::MPI::max(joint, comm), brick};
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
