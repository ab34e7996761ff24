/**
 * @file
 * A physical bound on the platen stress of a wallette: past it the
 * solution has run away (a result that is finite but not a solution).
 */
#ifndef masonry_brickwork_model_bounds_h
#define masonry_brickwork_model_bounds_h

#include <array>
#include <string>

namespace masonry
{
  namespace brickwork
  {
    class BrickMaterial;

    namespace model
    {
      /**
       * Factor on the physical bound below: results beyond it are taken
       * as a solution that ran away.
       */
      constexpr double stress_bound_factor = 10;

      /**
       * The largest platen stress (Pa) that a wallette can carry at the
       * nominal strain @p strain: an elastic body of the stiffest
       * material's constrained modulus @p modulus (Pa; largest C_iiii, an
       * upper bound on any wallette's axial stiffness by Voigt's bound,
       * joints in series only soften it) strained by |strain| + 1e-4,
       * plus the largest compressive strength @p strength (Pa, 0 for
       * elastic materials) for stresses locked in by plastic strains,
       * times stress_bound_factor.
       */
      double
      stress_bound(const double strength,
                   const double modulus,
                   const double strain);

      /**
       * The largest compressive strength and the largest constrained
       * modulus C_iiii (Pa) of @p material and @p mortar (may be null): the
       * strength and modulus of stress_bound().
       */
      std::array<double, 2>
      bound_materials(const BrickMaterial &material,
                      const BrickMaterial *mortar);

      /**
       * Empty if |stress| <= stress_bound(strength, modulus, strain), else
       * the reason, one line, naming the values.
       */
      std::string
      runaway_problem(const double stress,
                      const double strain,
                      const double strength,
                      const double modulus);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
