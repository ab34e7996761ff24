/**
 * The interface element of a face pair on its own (issue 15): the jumps of
 * rigid motions (zero for a common translation, the relative translation in
 * the local frame for a relative one: normal first, then the two slips);
 * the force vector of a uniform traction (A and B forces opposite, each
 * summing to traction x area); and the tangent assembled from a nonlinear
 * coupled traction law against central differences of the force vector,
 * for the three normal axes, Gauss and Lobatto points. With Lobatto points
 * (the nodes) the tangent couples each node only with itself and the node
 * facing it (each shape function is 1 at its node and exactly 0 at the
 * others), which the sparsity of the tangent relies on (System::setup);
 * with Gauss points the other nodes are coupled too.
 */
#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>
#include <random>

#include "../source/brickwork/assembly/interface_element.h"
#include "vault_tests.h"

using namespace dealii;
using masonry::brickwork::Local3;
using masonry::brickwork::Local33;
using masonry::brickwork::model::InterfaceElement;

namespace
{
  /** A nonlinear, coupled traction law t(j) and its derivative. */
  void
  law(const Local3 &j, Local3 &t, Local33 &D)
  {
    const double k[3] = {2e11, 1e11, 0.7e11}, c = 3e16;
    for (unsigned int a = 0; a < 3; ++a)
      {
        t[a] =
          k[a] * j[a] + c * j[a] * j[(a + 1) % 3] + 1e20 * std::pow(j[a], 3);
        for (unsigned int b = 0; b < 3; ++b)
          D[a][b] = 0;
        D[a][a] = k[a] + 3e20 * j[a] * j[a];
        D[a][(a + 1) % 3] += c * j[a];
        D[a][a] += c * j[(a + 1) % 3];
      }
  }

  /** Force vector of the face at the nodal values @p ue. */
  Vector<double>
  force(const InterfaceElement &e,
        const unsigned int      axis,
        const double            area,
        const Vector<double>   &ue,
        FullMatrix<double>     *k)
  {
    std::array<Local3, 4>  jumps, t;
    std::array<Local33, 4> D;
    e.jumps(axis, ue, jumps);
    for (unsigned int q = 0; q < 4; ++q)
      law(jumps[q], t[q], D[q]);
    Vector<double> f(24);
    e.local(axis, area, t, D, f, k);
    return f;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize       mpi(argc, argv, 1);
  std::mt19937                           random(3);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst_common = 0, worst_relative = 0, worst_force = 0, worst_fd = 0;
  // the largest tangent entry between different vertices (v = 0-3 on
  // either side), relative to |K|
  double other_vertex[2] = {0, 0};
  for (const bool gauss : {false, true})
    for (unsigned int axis = 0; axis < 3; ++axis)
      {
        const InterfaceElement e(gauss);
        const double           area = 0.0123;
        // a common translation: no opening; a relative one: its local
        // components (normal = the axis, then the next two axes)
        Vector<double> ue(24);
        const double   c[3] = {u(random), u(random), u(random)};
        const double   r[3] = {1e-4 * u(random),
                               1e-4 * u(random),
                               1e-4 * u(random)};
        for (unsigned int v = 0; v < 8; ++v)
          for (unsigned int d = 0; d < 3; ++d)
            ue[3 * v + d] = c[d];
        std::array<Local3, 4> jumps;
        e.jumps(axis, ue, jumps);
        for (const auto &j : jumps)
          for (const double x : j)
            worst_common = std::max(worst_common, std::abs(x));
        for (unsigned int v = 4; v < 8; ++v)
          for (unsigned int d = 0; d < 3; ++d)
            ue[3 * v + d] += r[d];
        e.jumps(axis, ue, jumps);
        for (const auto &j : jumps)
          for (unsigned int k = 0; k < 3; ++k)
            worst_relative =
              std::max(worst_relative,
                       std::abs(j[k] - r[(axis + k) % 3]) / 1e-4);
        // uniform traction: B gets +t area, A gets -t area per direction
        std::array<Local3, 4>  t;
        std::array<Local33, 4> D{};
        for (auto &x : t)
          x = {{1e5, -2e5, 3e5}};
        Vector<double> f(24);
        e.local(axis, area, t, D, f, nullptr);
        for (unsigned int k = 0; k < 3; ++k)
          {
            double fa = 0, fb = 0;
            for (unsigned int v = 0; v < 4; ++v)
              {
                fa += f[3 * v + (axis + k) % 3];
                fb += f[12 + 3 * v + (axis + k) % 3];
              }
            worst_force =
              std::max({worst_force,
                        std::abs(fb - t[0][k] * area) / 3e5 / area,
                        std::abs(fa + t[0][k] * area) / 3e5 / area});
          }
        // tangent against central differences of the force vector at a
        // random state (openings of some 1e-5 m)
        for (unsigned int i = 0; i < 24; ++i)
          ue[i] = 1e-5 * u(random);
        FullMatrix<double> k(24, 24);
        force(e, axis, area, ue, &k);
        for (unsigned int i = 0; i < 24; ++i)
          for (unsigned int j = 0; j < 24; ++j)
            if ((i % 12) / 3 != (j % 12) / 3)
              other_vertex[gauss] =
                std::max(other_vertex[gauss],
                         std::abs(k(i, j)) / k.frobenius_norm());
        const double h = 1e-10;
        for (unsigned int j = 0; j < 24; ++j)
          {
            Vector<double> p = ue, m = ue;
            p[j] += h;
            m[j] -= h;
            const Vector<double> fp = force(e, axis, area, p, nullptr),
                                 fm = force(e, axis, area, m, nullptr);
            for (unsigned int i = 0; i < 24; ++i)
              worst_fd =
                std::max(worst_fd,
                         std::abs((fp[i] - fm[i]) / (2 * h) - k(i, j)) /
                           k.frobenius_norm());
          }
      }
  vault_tests::check(worst_common < 1e-15,
                     "a common translation of both faces opens nothing");
  vault_tests::check(worst_relative < 1e-12,
                     "a relative translation gives the jump in the local "
                     "frame (normal, slip 1, slip 2) at every point");
  vault_tests::check(worst_force < 1e-12,
                     "uniform traction: the faces' forces are -t A and +t A");
  vault_tests::check(worst_fd < 1e-7,
                     "the assembled tangent = central differences of the "
                     "force vector (1e-7 of |K|), 3 axes, Gauss and Lobatto");
  vault_tests::check(other_vertex[0] == 0. && other_vertex[1] > 0.01,
                     "Lobatto points: the tangent couples no two vertices "
                     "that do not face each other (exactly 0); Gauss points "
                     "do");
}
