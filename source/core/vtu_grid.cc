#include <masonry/core/vtu_grid.h>

#include <iomanip>

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
} // namespace masonry
