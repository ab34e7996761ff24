/**
 * @file
 * The record of a wallette run: one point per converged step (curve.csv)
 * and one record per deleted cell (deletions.csv).
 */
#ifndef masonry_brickwork_curve_h
#define masonry_brickwork_curve_h

#include <array>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    /** Summary of one converged step: a row of curve.csv. */
    struct CurvePoint
    {
      /** Platen displacement along its direction (m) and divided by the
       * height of the wallette (dimensionless). */
      double displacement = 0, strain = 0;
      /** Platen force along its direction (N) and divided by the gross
       * area (Pa). */
      double force = 0, stress = 0;
      /** Largest damage of a joint point (the interface law's
       * damage_names(), 0 to 1). */
      double max_damage = 0;
      /** Strain of the virtual LVDT (`Gauge length', dimensionless). */
      double gauge_strain = 0;
      /** Newton iterations of the step. */
      unsigned int newton = 0;
      /** Cycle (from 1; 0 for the initial state) and whether the platen
       * was unloading. */
      unsigned int cycle     = 0;
      bool         unloading = false;
      /** Cells deleted so far. */
      unsigned int deleted = 0;
      /** Largest value of each damage of the brick material
       * (BrickMaterial::damage_names()). */
      std::vector<double> brick_damages;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &displacement &strain &force &stress &max_damage &gauge_strain
          &newton &cycle &unloading &deleted &brick_damages;
      }
    };

    /** One deleted cell: when it went and what it carried then (the
     * converged state of the step after which it was deleted, before
     * its deletion). */
    struct DeletedCell
    {
      /** The step after which it went (curve.csv's `step'), its cycle
       * and whether that step unloaded (the protocol's leg). */
      unsigned int step      = 0;
      unsigned int cycle     = 0;
      bool         unloading = false;
      /** Its active cell index and region (0 unit, 1 mortar:
       * ModelView::cell_region()). */
      unsigned int  cell   = 0;
      unsigned char region = 0;
      /** Its centre, m. */
      std::array<double, 3> centre{};
      /** The largest principal value of its cell-averaged strain. */
      double strain = 0;
      /** Its cell-averaged stress (its fade included), Pa: xx, yy, zz,
       * xy, yz, xz. */
      std::array<double, 6> stress{};

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &step &cycle &unloading &cell &region &strain;
        for (auto &x : centre)
          ar &x;
        for (auto &s : stress)
          ar &s;
      }
    };
  } // namespace brickwork
} // namespace masonry

#endif
