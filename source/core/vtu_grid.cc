#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/core/vtu_grid.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/hdf5.h>

#include <filesystem>
#include <iomanip>
#include <sstream>

namespace masonry
{
  void
  VtuGrid::write(std::ostream &out) const
  {
    const unsigned int n_cells = connectivity.size() / nodes_per_cell;
    out << std::setprecision(10);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
        << "<Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\""
        << n_cells << "\">\n";
    out << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
           "format=\"ascii\">\n";
    for (const auto &x : points)
      out << x[0] << " " << x[1] << " " << x[2] << "\n";
    out << "</DataArray></Points>\n<Cells>\n<DataArray type=\"Int64\" "
           "Name=\"connectivity\" format=\"ascii\">\n";
    for (unsigned int c = 0; c < n_cells; ++c)
      for (unsigned int v = 0; v < nodes_per_cell; ++v)
        out << connectivity[c * nodes_per_cell + v]
            << (v + 1 < nodes_per_cell ? " " : "\n");
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
           "format=\"ascii\">\n";
    for (unsigned int c = 1; c <= n_cells; ++c)
      out << nodes_per_cell * c << "\n";
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
           "format=\"ascii\">\n";
    for (unsigned int c = 0; c < n_cells; ++c)
      out << cell_type << "\n";
    out << "</DataArray>\n</Cells>\n";
    if (!integer_cell_data.empty() || !cell_data.empty())
      {
        out << "<CellData Scalars=\""
            << (integer_cell_data.empty() ? cell_data.front().first :
                                            integer_cell_data.front().first)
            << "\">\n";
        for (const auto &[name, values] : integer_cell_data)
          {
            out << "<DataArray type=\"Int32\" Name=\"" << name
                << "\" format=\"ascii\">\n";
            for (const int v : values)
              out << v << "\n";
            out << "</DataArray>\n";
          }
        for (const auto &[name, values] : cell_data)
          {
            out << "<DataArray type=\"Float64\" Name=\"" << name
                << "\" format=\"ascii\">\n";
            for (const double v : values)
              out << v << "\n";
            out << "</DataArray>\n";
          }
        out << "</CellData>\n";
      }
    if (!point_vectors.empty())
      {
        out << "<PointData Vectors=\"" << point_vectors.front().first
            << "\">\n";
        for (const auto &[name, values] : point_vectors)
          {
            out << "<DataArray type=\"Float64\" Name=\"" << name
                << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
            for (const auto &v : values)
              out << v[0] << " " << v[1] << " " << v[2] << "\n";
            out << "</DataArray>\n";
          }
        out << "</PointData>\n";
      }
    out << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  }

  void
  VtuGrid::write_hdf5(const std::string &path) const
  {
    using dealii::HDF5::File;
    const hsize_t n_points = points.size();
    const hsize_t n_cells  = connectivity.size() / nodes_per_cell;
    StagedFile    staged(path);
    try
      {
        // the file is closed when it goes out of scope, before the rename
        File file(staged.temporary_name(), File::FileAccessMode::create);
        std::vector<double> xyz;
        xyz.reserve(3 * n_points);
        for (const auto &x : points)
          xyz.insert(xyz.end(), {x[0], x[1], x[2]});
        file.create_dataset<double>("nodes", {n_points, 3}).write(xyz);
        file.create_dataset<unsigned int>("cells", {n_cells, nodes_per_cell})
          .write(connectivity);
        for (const auto &[name, values] : integer_cell_data)
          file.create_dataset<int>(name, {n_cells}).write(values);
        for (const auto &[name, values] : cell_data)
          file.create_dataset<double>(name, {n_cells}).write(values);
        for (const auto &[name, values] : point_vectors)
          {
            xyz.clear();
            for (const auto &v : values)
              xyz.insert(xyz.end(), {v[0], v[1], v[2]});
            file.create_dataset<double>(name, {n_points, 3}).write(xyz);
          }
      }
    catch (const std::exception &)
      {
        const std::string directory =
          std::filesystem::path(path).parent_path().string();
        throw dealii::ExcMessage(
          write_error(path,
                      likely_write_reason(directory.empty() ? "." : directory,
                                          "the HDF5 library failed")));
      }
    staged.commit();
  }

  std::string
  VtuGrid::xdmf_grid(const std::string &h5, const double time) const
  {
    const unsigned int n_points = points.size();
    const unsigned int n_cells  = connectivity.size() / nodes_per_cell;
    AssertThrow(cell_type == 12 || cell_type == 9,
                dealii::ExcMessage("XDMF grids of hexahedra (VTK type 12) "
                                   "or quadrilaterals (9) only"));
    const char *const topology =
      cell_type == 12 ? "Hexahedron" : "Quadrilateral";
    std::ostringstream out;
    out << std::setprecision(17);
    const auto item = [&](const std::string &dimensions,
                          const char        *type,
                          const std::string &dataset) {
      out << "          <DataItem Dimensions=\"" << dimensions
          << "\" NumberType=\"" << type << "\""
          << (std::string(type) == "Float" ? " Precision=\"8\"" : "")
          << " Format=\"HDF\">" << h5 << ":/" << dataset << "</DataItem>\n";
    };
    out << "      <Grid Name=\"mesh\" GridType=\"Uniform\">\n"
        << "        <Time Value=\"" << time << "\"/>\n"
        << "        <Geometry GeometryType=\"XYZ\">\n";
    item(std::to_string(n_points) + " 3", "Float", "nodes");
    out << "        </Geometry>\n"
        << "        <Topology TopologyType=\"" << topology
        << "\" NumberOfElements=\"" << n_cells << "\">\n";
    item(std::to_string(n_cells) + " " + std::to_string(nodes_per_cell),
         "UInt",
         "cells");
    out << "        </Topology>\n";
    const auto attribute = [&](const std::string &name,
                               const char        *kind,
                               const char        *center,
                               const std::string &dimensions,
                               const char        *type) {
      out << "        <Attribute Name=\"" << name << "\" AttributeType=\""
          << kind << "\" Center=\"" << center << "\">\n";
      item(dimensions, type, name);
      out << "        </Attribute>\n";
    };
    for (const auto &data : integer_cell_data)
      attribute(data.first, "Scalar", "Cell", std::to_string(n_cells), "Int");
    for (const auto &data : cell_data)
      attribute(data.first, "Scalar", "Cell", std::to_string(n_cells), "Float");
    for (const auto &data : point_vectors)
      attribute(
        data.first, "Vector", "Node", std::to_string(n_points) + " 3", "Float");
    out << "      </Grid>\n";
    return out.str();
  }

  void
  write_xdmf_series(std::ostream &out, const std::vector<std::string> &grids)
  {
    out << "<?xml version=\"1.0\" ?>\n"
        << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
        << "<Xdmf Version=\"2.0\">\n  <Domain>\n"
        << "    <Grid Name=\"CellTime\" GridType=\"Collection\" "
           "CollectionType=\"Temporal\">\n";
    for (const auto &grid : grids)
      out << grid;
    out << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  }
} // namespace masonry
