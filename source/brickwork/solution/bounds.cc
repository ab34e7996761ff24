#include <masonry/brickwork/brick_material.h>

#include "bounds.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      double
      stress_bound(const double strength,
                   const double modulus,
                   const double strain)
      {
        return stress_bound_factor *
               (std::abs(strength) +
                std::abs(modulus) * (std::abs(strain) + 1e-4));
      }

      std::array<double, 2>
      bound_materials(const LawSet &laws)
      {
        std::array<double, 2> bound = {{0., 0.}};
        for (unsigned int r = 0; r < laws.n_regions(); ++r)
          {
            const BrickMaterial &m = laws.brick_law(r);
            if (const MaterialStrengths *f = strengths_of(m))
              bound[0] = std::max(bound[0], f->compressive_strength());
            const auto C = m.elastic_stiffness();
            for (unsigned int i = 0; i < 3; ++i)
              bound[1] = std::max(bound[1], C[i][i][i][i]);
          }
        return bound;
      }

      std::string
      runaway_problem(const double stress,
                      const double strain,
                      const double strength,
                      const double modulus)
      {
        const double bound = stress_bound(strength, modulus, strain);
        if (std::abs(stress) <= bound)
          return "";
        std::ostringstream m;
        m << "the solution ran away: the platen stress " << stress * 1e-6
          << " MPa at strain " << strain << " is more than "
          << stress_bound_factor << " x (the largest compressive strength "
          << strength * 1e-6 << " MPa + the stiffest constrained modulus "
          << modulus * 1e-9 << " GPa x (|strain| + 1e-4)) = " << bound * 1e-6
          << " MPa, which no wallette of these materials can carry";
        return m.str();
      }

      std::string
      collapse_problem(const std::vector<CurvePoint> &curve, const double ratio)
      {
        if (ratio <= 0 || curve.empty() || curve.back().unloading)
          return "";
        const CurvePoint &now  = curve.back();
        double            peak = 0, leg = now.stress;
        for (const auto &p : curve)
          peak = std::max(peak, p.stress);
        for (auto p = curve.rbegin();
             p != curve.rend() && p->cycle == now.cycle && !p->unloading;
             ++p)
          leg = std::max(leg, p->stress);
        const double floor = ratio * peak;
        if (now.stress >= floor || leg - now.stress <= floor)
          return "";
        std::ostringstream m;
        m << "the specimen collapsed: at strain " << now.strain
          << " the platen stress fell to " << now.stress * 1e-6
          << " MPa, below `Collapse stress ratio' = " << ratio
          << " of the peak " << peak * 1e-6 << " MPa (" << leg * 1e-6
          << " MPa earlier in this loading); the rest of the protocol is "
             "not run";
        return m.str();
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
