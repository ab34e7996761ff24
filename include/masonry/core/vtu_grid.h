/**
 * @file
 * The project's one writer for grids that are not a deal.II mesh: the
 * rigid blocks and their interfaces, the joints of a wallette (one
 * quadrilateral per face pair), as ASCII VTU or as HDF5 with an XDMF time
 * series. Fields on deal.II meshes go through deal.II's DataOut.
 *
 * Why not deal.II's DataOutBase::write_vtu(): in deal.II 9.4 it writes
 * points and data as Float32 only (7 digits; these files have 10), it has
 * no cell data (block id, patch, opening and force are per cell here), and
 * a DataOutBase::Patch has the same number of subdivisions in every
 * direction (a block is k × k × 1 hexahedra: curved in u and v, straight
 * across the thickness). ParaView, meshio and users' scripts read these
 * ASCII files. deal.II's XDMFEntry has point data only, so the XDMF grids
 * with cell data are written here too.
 */
#ifndef masonry_core_vtu_grid_h
#define masonry_core_vtu_grid_h

#include <deal.II/base/point.h>

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace masonry
{
  /** An unstructured grid of one cell type with cell and point data. */
  struct VtuGrid
  {
    /** Point coordinates, m. */
    std::vector<dealii::Point<3>> points;
    /** Points per cell (8: hexahedron, 4: quadrilateral). */
    unsigned int nodes_per_cell = 8;
    /** VTK cell type (12: hexahedron, 9: quadrilateral). */
    unsigned int cell_type = 12;
    /** nodes_per_cell point indices per cell. */
    std::vector<unsigned int> connectivity;
    /** Integer cell data (written first): name and one value per cell. */
    std::vector<std::pair<std::string, std::vector<int>>> integer_cell_data;
    /** Real cell data: name and one value per cell. */
    std::vector<std::pair<std::string, std::vector<double>>> cell_data;
    /** Vector point data: name and one vector per point. */
    std::vector<std::pair<std::string, std::vector<dealii::Tensor<1, 3>>>>
      point_vectors;

    /** Write the grid as an ASCII VTU file, 10 significant digits. */
    void
    write(std::ostream &out) const;

    /**
     * Write the grid as the HDF5 file @p path (double precision): datasets
     * `nodes` (points x 3, m), `cells` (cells x nodes_per_cell, point
     * indices from 0), one dataset per cell data (one value per cell) and
     * one per point vector (points x 3). The file is whole or absent: an
     * error of the HDF5 library throws an ExcMessage naming @p path.
     */
    void
    write_hdf5(const std::string &path) const;

    /**
     * The XDMF `<Grid>` element (Xdmf 2) of this grid written by
     * write_hdf5() to @p h5 (a name relative to the XDMF file) at time
     * @p time, for a temporal collection written by write_xdmf_series().
     */
    std::string
    xdmf_grid(const std::string &h5, const double time) const;
  };

  /**
   * Write an XDMF temporal collection of the grids @p grids (each from
   * VtuGrid::xdmf_grid()) to @p out; ParaView opens it with its XDMF reader.
   */
  void
  write_xdmf_series(std::ostream &out, const std::vector<std::string> &grids);
} // namespace masonry

#endif
