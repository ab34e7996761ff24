/**
 * @file
 * The record of a run: one point per converged step.
 */
#ifndef masonry_brickwork_model_curve_h
#define masonry_brickwork_model_curve_h

#include <vector>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** Summary of one converged step. */
      struct CurvePoint
      {
        double       displacement = 0, strain = 0, force = 0, stress = 0;
        double       max_damage = 0, gauge_strain = 0;
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
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
