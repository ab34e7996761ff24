/**
 * @file
 * The interface element of a face pair.
 */
#include "interface_element.h"

#include <cmath>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      InterfaceElement::InterfaceElement(const bool gauss)
      {
        if (gauss)
          {
            q_points = {{0.5 - 0.5 / std::sqrt(3.), 0.5 + 0.5 / std::sqrt(3.)}};
            q_weights = {{0.5, 0.5}};
          }
        else
          {
            q_points  = {{0., 1.}};
            q_weights = {{0.5, 0.5}};
          }
      }

      std::array<double, 4>
      InterfaceElement::shapes(const unsigned int q) const
      {
        const double xi = q_points[q % 2], eta = q_points[q / 2];
        return {
          {(1 - xi) * (1 - eta), xi * (1 - eta), (1 - xi) * eta, xi * eta}};
      }

      void
      InterfaceElement::jumps(const unsigned int            a,
                              const dealii::Vector<double> &ue,
                              std::array<Local3, n_points> &jumps) const
      {
        for (unsigned int q = 0; q < n_points; ++q)
          {
            const auto N    = shapes(q);
            Local3    &jump = jumps[q];
            jump            = {{0, 0, 0}};
            for (unsigned int v = 0; v < 4; ++v)
              for (unsigned int k = 0; k < 3; ++k)
                {
                  const unsigned int d = (a + k) % 3;
                  jump[k] += N[v] * (ue[12 + 3 * v + d] - ue[3 * v + d]);
                }
          }
      }

      void
      InterfaceElement::local(const unsigned int                   a,
                              const double                         area,
                              const std::array<Local3, n_points>  &tractions,
                              const std::array<Local33, n_points> &tangents,
                              dealii::Vector<double>              &fi,
                              dealii::FullMatrix<double>          *ki) const
      {
        fi = 0;
        if (ki)
          *ki = 0;
        for (unsigned int qy = 0; qy < 2; ++qy)
          for (unsigned int qx = 0; qx < 2; ++qx)
            {
              const unsigned int q  = qx + 2 * qy;
              const auto         N  = shapes(q);
              const double       dA = area * q_weights[qx] * q_weights[qy];
              const Local3      &t  = tractions[q];
              const Local33     &D  = tangents[q];
              for (unsigned int v = 0; v < 8; ++v)
                {
                  const double sv = (v < 4 ? -1. : 1.) * N[v % 4];
                  for (unsigned int k = 0; k < 3; ++k)
                    {
                      const unsigned int row = 3 * v + (a + k) % 3;
                      fi[row] += sv * t[k] * dA;
                      if (ki)
                        for (unsigned int w = 0; w < 8; ++w)
                          {
                            const double sw = (w < 4 ? -1. : 1.) * N[w % 4];
                            for (unsigned int l = 0; l < 3; ++l)
                              (*ki)(row, 3 * w + (a + l) % 3) +=
                                sv * sw * D[k][l] * dA;
                          }
                    }
                }
            }
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
