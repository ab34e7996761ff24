#include <masonry/core/output_directory.h>
#include <masonry/core/scripts.h>
#include <masonry/geometry/interface.h>
#include <masonry/rigid_blocks/output.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace masonry
{
  namespace rigid_blocks
  {
    dealii::Tensor<1, 3>
    Motion::displacement(const BlockModel       &model,
                         const unsigned int      b,
                         const dealii::Point<3> &x) const
    {
      return rigid_motion(translation[b],
                          rotation[b],
                          model.blocks()[b].centroid,
                          x);
    }

    void
    integrate_surface_load(const BlockModel                  &model,
                           const dealii::Function<3>         &q,
                           std::vector<dealii::Tensor<1, 3>> &force,
                           std::vector<dealii::Tensor<1, 3>> &moment)
    {
      const auto &patches = model.geometry().patches();
      for (unsigned int b = 0; b < model.blocks().size(); ++b)
        {
          const Block &block = model.blocks()[b];
          for (const auto &[uv, w] : model.quadrature(b))
            {
              const auto   ts = patches[block.patch].tangents(uv);
              const double dA =
                dealii::cross_product_3d(ts[0], ts[1]).norm() * w;
              const dealii::Point<3> x    = patches[block.patch].point(uv);
              const double           load = q.value(x);
              if (load == 0)
                continue;
              dealii::Tensor<1, 3> f;
              f[2] = -load * dA;
              force[b] += f;
              moment[b] += dealii::cross_product_3d(x - block.centroid, f);
            }
        }
    }

    namespace
    {
      /** Jump of the motion at contact point @p c of interface @p i. */
      dealii::Tensor<1, 3>
      jump(const BlockModel   &model,
           const Motion       &motion,
           const Interface    &i,
           const ContactPoint &c,
           const std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &,
                                                    const std::string &)>
             &settlement)
      {
        const dealii::Tensor<1, 3> first =
          motion.displacement(model, i.first, c.position);
        const dealii::Tensor<1, 3> second =
          i.second == Interface::support ?
            settlement(c.position, i.support_label) :
            motion.displacement(model, i.second, c.position);
        return second - first;
      }

      void
      write_vtu_header(std::ostream      &out,
                       const unsigned int n_points,
                       const unsigned int n_cells)
      {
        out << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
               "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
            << "<Piece NumberOfPoints=\"" << n_points << "\" NumberOfCells=\""
            << n_cells << "\">\n";
      }

      std::string
      xml_escape(const std::string &s)
      {
        std::string out;
        for (const char c : s)
          out += (c == '&') ? "&amp;" :
                 (c == '<') ? "&lt;" :
                 (c == '>') ? "&gt;" :
                              std::string(1, c);
        return out;
      }
    } // namespace

    void
    write_results(
      const BlockModel &model,
      const Motion     &motion,
      const std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &,
                                               const std::string &)>
                                               &settlement,
      const std::vector<std::array<double, 3>> &forces,
      const OutputOptions                      &options,
      RunContext                               &context)
    {
      const auto  start      = std::chrono::steady_clock::now();
      const auto &blocks     = model.blocks();
      const auto &interfaces = model.interfaces();
      const bool  root =
        dealii::Utilities::MPI::this_mpi_process(context.mpi_communicator) == 0;

      // largest displacement: the scale for "zero" jumps and amplification
      double max_displacement = 0;
      for (const auto &i : interfaces)
        for (const auto &c : i.points)
          max_displacement =
            std::max(max_displacement,
                     motion.displacement(model, i.first, c.position).norm());
      // prescribed support motion: jumps below 1e-6 of the larger of the two
      // scales are round-off of the LP, not cracks
      double max_support_motion = 0;
      for (const auto &i : interfaces)
        if (i.second == Interface::support)
          for (const auto &c : i.points)
            max_support_motion =
              std::max(max_support_motion,
                       settlement(c.position, i.support_label).norm());
      const double tolerance =
        1e-6 * std::max(max_displacement, max_support_motion);

      // crack list
      Json                cracks   = Json::array();
      unsigned int        n_hinges = 0;
      std::vector<double> interface_opening(interfaces.size(), 0.0);
      for (unsigned int k = 0; k < interfaces.size(); ++k)
        {
          const Interface &i           = interfaces[k];
          double           max_opening = 0, min_opening = 0, max_jump = 0;
          bool             first = true;
          for (const auto &c : i.points)
            {
              const auto   j       = jump(model, motion, i, c, settlement);
              const double opening = j * c.normal;
              max_opening = first ? opening : std::max(max_opening, opening);
              min_opening = first ? opening : std::min(min_opening, opening);
              max_jump    = std::max(max_jump, j.norm());
              first       = false;
            }
          interface_opening[k] = max_opening;
          if (max_jump <= tolerance)
            continue;
          const dealii::Tensor<1, 3> omega =
            (i.second == Interface::support ? dealii::Tensor<1, 3>() :
                                              motion.rotation[i.second]) -
            motion.rotation[i.first];
          const std::string type =
            min_opening <= tolerance ?
              (max_opening > tolerance ? "hinge" : "slip") :
              "separation";
          if (type == "hinge")
            ++n_hinges;
          Json crack           = Json::object();
          crack["interface"]   = k;
          crack["first_block"] = i.first;
          crack["second"]      = i.second == Interface::support ?
                                   Json("support: " + i.support_label) :
                                   Json(i.second);
          Json position        = Json::array();
          for (unsigned int d = 0; d < 3; ++d)
            position.push_back(i.centre[d]);
          crack["position"]          = position;
          crack["type"]              = type;
          crack["max_opening"]       = max_opening;
          crack["relative_rotation"] = omega.norm();
          cracks.push_back(crack);
        }
      context.summary["n_cracks"] = cracks.size();
      context.summary["n_hinges"] = n_hinges;
      context.summary["cracks"]   = cracks;
      context.pcout << "Cracks: " << cracks.size() << " interfaces open or "
                    << "rotate (" << n_hinges << " hinges)\n";

      if (!root)
        return;
      OutputDirectory &dir = context.output;

      // interface forces from the LP dual (a statically admissible state)
      {
        std::ofstream csv(dir.file("interface_forces.csv"));
        csv << "interface,first_block,second_block,x,y,z,intrados,"
               "normal_force_N,shear_across_N,shear_along_N\n"
            << std::setprecision(10);
        unsigned int p = 0;
        for (unsigned int k = 0; k < interfaces.size(); ++k)
          for (const auto &c : interfaces[k].points)
            {
              const auto f =
                p < forces.size() ? forces[p] : std::array<double, 3>{};
              ++p;
              csv << k << "," << interfaces[k].first << ","
                  << (interfaces[k].second == Interface::support ?
                        std::string("support") :
                        std::to_string(interfaces[k].second))
                  << "," << c.position[0] << "," << c.position[1] << ","
                  << c.position[2] << "," << (c.intrados ? 1 : 0) << "," << f[0]
                  << "," << f[1] << "," << f[2] << "\n";
            }
      }

      // rigid motion of every block, to full precision (the VTU is rounded)
      {
        std::ofstream csv(dir.file("blocks.csv"));
        csv << "block,patch,centroid_x,centroid_y,centroid_z,"
               "translation_x_m,translation_y_m,translation_z_m,"
               "rotation_x_rad,rotation_y_rad,rotation_z_rad\n"
            << std::setprecision(17);
        for (unsigned int b = 0; b < blocks.size(); ++b)
          {
            csv << b << "," << blocks[b].patch;
            for (unsigned int d = 0; d < 3; ++d)
              csv << "," << blocks[b].centroid[d];
            for (unsigned int d = 0; d < 3; ++d)
              csv << "," << motion.translation[b][d];
            for (unsigned int d = 0; d < 3; ++d)
              csv << "," << motion.rotation[b][d];
            csv << "\n";
          }
      }

      // amplification of displacements for the deformed pictures: the
      // support motion counts too, so that the round-off motion of blocks
      // that stay put (a vault lifting off a settling support) is not blown
      // up to 5 % of the vault
      const double displacement_scale =
        std::max(max_displacement, max_support_motion);
      const double amplification =
        options.amplification > 0 ?
          options.amplification :
          (displacement_scale > 0 ?
             0.05 * model.length_scale() / displacement_scale :
             1.0);
      context.summary["displacement_amplification"] = amplification;

      // blocks: curved hexahedra sampled in parameter space
      {
        const unsigned int k         = options.subdivisions;
        const unsigned int per_block = (k + 1) * (k + 1) * 2;
        std::ofstream      out(dir.file("blocks.vtu"));
        out << std::setprecision(10);
        write_vtu_header(out, blocks.size() * per_block, blocks.size() * k * k);
        std::vector<dealii::Point<3>>     points;
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
                  points.push_back(x);
                  displacement.push_back(motion.displacement(model, b, x));
                }
        out << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
               "format=\"ascii\">\n";
        for (unsigned int p = 0; p < points.size(); ++p)
          {
            const dealii::Point<3> y =
              points[p] + amplification * displacement[p];
            out << y[0] << " " << y[1] << " " << y[2] << "\n";
          }
        out << "</DataArray></Points>\n<Cells>\n<DataArray type=\"Int64\" "
               "Name=\"connectivity\" format=\"ascii\">\n";
        auto id =
          [&](unsigned int b, unsigned int i, unsigned int j, unsigned int z) {
            return b * per_block + z * (k + 1) * (k + 1) + j * (k + 1) + i;
          };
        for (unsigned int b = 0; b < blocks.size(); ++b)
          for (unsigned int j = 0; j < k; ++j)
            for (unsigned int i = 0; i < k; ++i)
              out << id(b, i, j, 0) << " " << id(b, i + 1, j, 0) << " "
                  << id(b, i + 1, j + 1, 0) << " " << id(b, i, j + 1, 0) << " "
                  << id(b, i, j, 1) << " " << id(b, i + 1, j, 1) << " "
                  << id(b, i + 1, j + 1, 1) << " " << id(b, i, j + 1, 1)
                  << "\n";
        out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
               "format=\"ascii\">\n";
        for (unsigned int c = 1; c <= blocks.size() * k * k; ++c)
          out << 8 * c << "\n";
        out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
               "format=\"ascii\">\n";
        for (unsigned int c = 0; c < blocks.size() * k * k; ++c)
          out << "12\n";
        out
          << "</DataArray>\n</Cells>\n<CellData Scalars=\"block_id\">\n"
          << "<DataArray type=\"Int32\" Name=\"block_id\" format=\"ascii\">\n";
        for (unsigned int b = 0; b < blocks.size(); ++b)
          for (unsigned int c = 0; c < k * k; ++c)
            out << b << "\n";
        out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"patch\" "
               "format=\"ascii\">\n";
        for (unsigned int b = 0; b < blocks.size(); ++b)
          for (unsigned int c = 0; c < k * k; ++c)
            out << blocks[b].patch << "\n";
        out
          << "</DataArray>\n</CellData>\n<PointData Vectors=\"displacement\">\n"
          << "<DataArray type=\"Float64\" Name=\"displacement\" "
             "NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const auto &d : displacement)
          out << d[0] << " " << d[1] << " " << d[2] << "\n";
        out << "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n"
               "</VTKFile>\n";
      }

      // interfaces: quads between stations, on the first block's side
      {
        std::vector<dealii::Point<3>>            points;
        std::vector<std::array<unsigned int, 4>> quads;
        std::vector<double>                      opening, normal_force;
        unsigned int                             p = 0;
        for (unsigned int k = 0; k < interfaces.size(); ++k)
          {
            const Interface   &i     = interfaces[k];
            const unsigned int base  = points.size();
            double             force = 0;
            for (const auto &c : i.points)
              {
                points.push_back(
                  c.position + amplification * motion.displacement(model,
                                                                   i.first,
                                                                   c.position));
                if (p < forces.size())
                  force += forces[p][0];
                ++p;
              }
            // points come in (intrados, extrados) pairs per station
            for (unsigned int s = 0; s + 3 < i.points.size(); s += 2)
              {
                quads.push_back(
                  {base + s, base + s + 2, base + s + 3, base + s + 1});
                opening.push_back(interface_opening[k]);
                normal_force.push_back(force);
              }
          }
        std::ofstream out(dir.file("interfaces.vtu"));
        out << std::setprecision(10);
        write_vtu_header(out, points.size(), quads.size());
        out << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
               "format=\"ascii\">\n";
        for (const auto &x : points)
          out << x[0] << " " << x[1] << " " << x[2] << "\n";
        out << "</DataArray></Points>\n<Cells>\n<DataArray type=\"Int64\" "
               "Name=\"connectivity\" format=\"ascii\">\n";
        for (const auto &q : quads)
          out << q[0] << " " << q[1] << " " << q[2] << " " << q[3] << "\n";
        out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
               "format=\"ascii\">\n";
        for (unsigned int c = 1; c <= quads.size(); ++c)
          out << 4 * c << "\n";
        out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
               "format=\"ascii\">\n";
        for (unsigned int c = 0; c < quads.size(); ++c)
          out << "9\n";
        out
          << "</DataArray>\n</Cells>\n<CellData Scalars=\"opening\">\n"
          << "<DataArray type=\"Float64\" Name=\"opening\" format=\"ascii\">\n";
        for (const double o : opening)
          out << o << "\n";
        out << "</DataArray>\n<DataArray type=\"Float64\" "
               "Name=\"normal_force\" format=\"ascii\">\n";
        for (const double f : normal_force)
          out << f << "\n";
        out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n"
               "</VTKFile>\n";
      }

      {
        std::ofstream pvd(dir.file("vault.pvd"));
        pvd
          << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
             "version=\"0.1\">\n<Collection>\n"
          << "<DataSet timestep=\"0\" part=\"0\" file=\"blocks.vtu\" name=\"blocks\"/>\n"
          << "<DataSet timestep=\"0\" part=\"1\" file=\"interfaces.vtu\" "
             "name=\"interfaces\"/>\n</Collection>\n</VTKFile>\n";
      }

      const auto picture_start = std::chrono::steady_clock::now();
      if (options.write_picture)
        {
          const std::string script = find_script("vault_picture.py");
          const std::string python = "/usr/bin/python3";
          if (!script.empty() && std::filesystem::exists(python))
            {
              const std::string  png = dir.path() + "vault.png";
              std::ostringstream amplification_text;
              amplification_text << std::setprecision(17) << amplification;
              const std::string command =
                python + " '" + script + "' '" + dir.path() + "blocks.vtu' '" +
                png + "' '" +
                xml_escape(context.summary.at("analysis").as_string()) +
                "' --amplification " + amplification_text.str() +
                " > /dev/null 2>&1";
              if (std::system(command.c_str()) == 0)
                dir.file("vault.png");
              else
                context.pcout << "Note: vault.png not written (matplotlib "
                                 "failed; install python3-matplotlib)\n";
            }
          else
            context.pcout << "Note: vault.png not written ("
                          << (script.empty() ? "vault_picture.py" : python)
                          << " not found)\n";
        }
      const auto end = std::chrono::steady_clock::now();
      // what writing the results costs (not part of the analysis' timings)
      context.summary["seconds_picture"] =
        std::chrono::duration<double>(end - picture_start).count();
      context.summary["seconds_output"] =
        std::chrono::duration<double>(end - start).count();
    }
  } // namespace rigid_blocks
} // namespace masonry
