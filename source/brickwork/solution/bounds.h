/**
 * @file
 * A physical bound on the platen stress of a wallette: past it the
 * solution has run away (a result that is finite but not a solution); and
 * the end of a specimen that has collapsed.
 */
#ifndef masonry_brickwork_model_bounds_h
#define masonry_brickwork_model_bounds_h

#include <masonry/brickwork/curve.h>
#include <masonry/brickwork/law_set.h>

#include <array>
#include <string>
#include <vector>

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
       * modulus C_iiii (Pa) of the laws of the cell regions in @p laws: the
       * strength and modulus of stress_bound().
       */
      std::array<double, 2>
      bound_materials(const LawSet &laws);

      /**
       * Empty if |stress| <= stress_bound(strength, modulus, strain), else
       * the reason, one line, naming the values.
       */
      std::string
      runaway_problem(const double stress,
                      const double strain,
                      const double strength,
                      const double modulus);

      /**
       * Empty unless the specimen has collapsed at the last point of
       * @p curve: on a loading leg, the platen stress has fallen below
       * @p ratio times the largest stress of the run and by more than that
       * from the largest stress of this leg (a reloading that starts near
       * zero has not collapsed); then the reason, one line, naming the
       * values. @p ratio = 0: never.
       */
      std::string
      collapse_problem(const std::vector<CurvePoint> &curve,
                       const double                   ratio);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
