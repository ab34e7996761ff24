/**
 * @file
 * The record of a wallette run: one point per converged step (curve.csv).
 */
#ifndef masonry_brickwork_curve_h
#define masonry_brickwork_curve_h

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
  } // namespace brickwork
} // namespace masonry

#endif
