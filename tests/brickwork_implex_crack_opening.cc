/**
 * `IMPL-EX crack opening' of the damage-plasticity law, at one point, against
 * the closed forms of the law's IMPL-EX stress
 * (doc/notes/implex-step-control.md): stress = (1 - d_t) P(s) + (1 - d_c) (s -
 * P(s)) with s = C0 : (e - e_p*), the damages and e_p* extrapolated and frozen.
 *
 * (a) Uniaxial strain in tension (e_xx only, E0 = 10 GPa, nu = 0.2, f_t =
 *     1 MPa, G_f = 50 J/m^2, crack band 0.01 m, `Maximum damage' 0.95,
 *     `Tensile plastic strain ratio' 0.1), implicit updates in steps of
 *     2e-5 until the tensile damage is at its cap and the crack still opens
 *     (plastic strain grows). The tensile plastic flow is along
 *     C0^-1 : s+, so e - e_p stays a uniaxial strain and every principal
 *     effective stress is positive: P(s) = s and the stress is
 *     (1 - d_max) C0 : (e - e_p*). All the plastic strain of this path is
 *     the cracks' opening, so with `frozen' e_p* is the last converged
 *     e_p_n, and with `extrapolated' (ratio 1) e_p_n + (e_p_n - e_p_n-1).
 *     C0 from E0 and nu (Lame constants), not from the law.
 * (b) Uniaxial strain in compression past the elastic limit: the plastic
 *     strain is compressive flow, extrapolated by both choices, so both
 *     give the same stress, which differs from the stress with e_p frozen.
 * (c) The state: 6 values more per point with `frozen' (crack_strain).
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <iostream>

#include "vault_tests.h"

using namespace dealii;
using masonry::brickwork::BrickMaterial;
using masonry::brickwork::BrickPoint;
using vault_tests::check;

namespace
{
  const double E = 10e9, nu = 0.2, d_max = 0.95;

  std::unique_ptr<BrickMaterial>
  law(const std::string &opening)
  {
    ParameterHandler prm;
    masonry::plugins::Registry<BrickMaterial>::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Brick material\nset Model = damage plasticity\n"
      "subsection Damage plasticity\n"
      "set Young's modulus = 10e9\nset Poisson's ratio = 0.2\n"
      "set Tensile strength = 1e6\nset Tensile fracture energy = 50\n"
      "set Maximum damage = 0.95\nset Tensile plastic strain ratio = 0.1\n"
      "set IMPL-EX crack opening = " +
      opening + "\nend\nend\n");
    return masonry::plugins::Registry<BrickMaterial>::create(prm);
  }

  unsigned int
  n_state(const BrickMaterial &l)
  {
    return masonry::brickwork::n_state_values(l.state_variables());
  }

  /** C0 : e from E and nu. */
  SymmetricTensor<2, 3>
  hooke(const SymmetricTensor<2, 3> &e)
  {
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
                 mu     = E / (2 * (1 + nu));
    return lambda * trace(e) * unit_symmetric_tensor<3>() + 2 * mu * e;
  }

  /** The plastic strain of a state (its first six values). */
  SymmetricTensor<2, 3>
  plastic(const std::vector<double> &state)
  {
    SymmetricTensor<2, 3> p;
    for (unsigned int i = 0; i < 6; ++i)
      p.access_raw_entry(i) = state[i];
    return p;
  }

  /** Two consecutive converged states of a uniaxial-strain path. */
  struct Pair
  {
    double              strain = 0;
    std::vector<double> older, old;
  };

  /**
   * Uniaxial strain in steps of @p step from zero until @p done(old,
   * older) holds (at most 20000 steps).
   */
  template <class Done>
  Pair
  path(const BrickMaterial &l, const double step, const Done &done)
  {
    BrickPoint point;
    point.characteristic_length = 0.01;
    Pair p;
    p.old.assign(n_state(l), 0.);
    p.older = p.old;
    for (unsigned int k = 1; k <= 20000; ++k)
      {
        SymmetricTensor<2, 3> e, stress;
        SymmetricTensor<4, 3> C;
        e[0][0] = k * step;
        std::vector<double> updated(p.old.size());
        l.evaluate(e, p.old, point, updated, stress, C);
        p.older  = p.old;
        p.old    = updated;
        p.strain = e[0][0];
        if (k > 1 && done(p.old, p.older))
          return p;
      }
    return p;
  }

  SymmetricTensor<2, 3>
  extrapolated(const BrickMaterial &l, const Pair &p, const double strain)
  {
    BrickPoint point;
    point.characteristic_length = 0.01;
    SymmetricTensor<2, 3> e, stress;
    e[0][0] = strain;
    l.extrapolated_stress(e, p.old, p.older, 1., point, stress);
    return stress;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto frozen = law("frozen"), former = law("extrapolated");

  // (a) a crack at the damage cap that still opens
  const double step    = 2e-5;
  const auto   opening = [](const std::vector<double> &old,
                          const std::vector<double> &older) {
    return old[10] >= d_max * (1 - 1e-12) &&
           plastic(old)[0][0] > plastic(older)[0][0] * (1 + 1e-3);
  };
  const Pair a = path(*frozen, step, opening);
  const Pair b = path(*former, step, opening);
  check(opening(a.old, a.older) && opening(b.old, b.older) &&
          a.strain == b.strain,
        "tension: both reach a crack at the damage cap that still opens, at "
        "the same strain");
  const double          e = a.strain + step;
  SymmetricTensor<2, 3> strain;
  strain[0][0]                    = e;
  const SymmetricTensor<2, 3> p_n = plastic(a.old), p_older = plastic(a.older);
  const SymmetricTensor<2, 3> expect_frozen = (1 - d_max) * hooke(strain - p_n);
  const SymmetricTensor<2, 3> expect_former =
    (1 - d_max) * hooke(strain - p_n - (p_n - p_older));
  const SymmetricTensor<2, 3> s_frozen = extrapolated(*frozen, a, e),
                              s_former = extrapolated(*former, b, e);
  std::cout << "tension at strain " << e << ": frozen " << s_frozen[0][0] / 1e3
            << " kPa (closed form " << expect_frozen[0][0] / 1e3
            << "), extrapolated " << s_former[0][0] / 1e3
            << " kPa (closed form " << expect_former[0][0] / 1e3 << ")\n";
  check((s_frozen - expect_frozen).norm() <= 1e-9 * expect_frozen.norm(),
        "frozen: (1 - d_max) C0 : (e - e_p_n), the opening of the last step "
        "not extrapolated (1e-9)");
  check((s_former - expect_former).norm() <= 1e-9 * expect_former.norm(),
        "extrapolated: (1 - d_max) C0 : (e - e_p_n - (e_p_n - e_p_n-1)) "
        "(1e-9)");
  check((s_frozen - s_former).norm() > 0.01 * s_frozen.norm(),
        "the two differ by more than 1 %");

  // (b) compressive flow: extrapolated by both
  const auto flowing = [](const std::vector<double> &old,
                          const std::vector<double> &older) {
    return plastic(old)[0][0] < plastic(older)[0][0] - 5e-6;
  };
  const Pair                  c  = path(*frozen, -2e-5, flowing);
  const Pair                  d  = path(*former, -2e-5, flowing);
  const double                ec = c.strain - 2e-5;
  const SymmetricTensor<2, 3> f  = extrapolated(*frozen, c, ec),
                              g  = extrapolated(*former, d, ec);
  Pair still                     = c;
  still.older = still.old; // e_p (and the damages) not extrapolated
  const SymmetricTensor<2, 3> h = extrapolated(*frozen, still, ec);
  std::cout << "compression at strain " << ec << ": frozen " << f[0][0] / 1e6
            << " MPa, extrapolated " << g[0][0] / 1e6
            << " MPa, nothing extrapolated " << h[0][0] / 1e6 << " MPa\n";
  check(flowing(c.old, c.older) && c.strain == d.strain &&
          (f - g).norm() <= 1e-12 * f.norm() &&
          (f - h).norm() > 1e-3 * f.norm(),
        "compression: the compressive flow is extrapolated by both choices "
        "(the same stress, not the stress with e_p frozen)");

  // (c) the state
  check(n_state(*frozen) == n_state(*former) + 6,
        "frozen: 6 more state values per point (crack_strain)");
}
