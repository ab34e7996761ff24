/**
 * A loading protocol added from outside the library, in this file: `free
 * rotation', the monotonic ramp with a top platen on a spherical seat. The
 * platen stays a rigid plane and its centre follows the ramp, but it may
 * tilt about both horizontal axes, so it transmits a force and no moment.
 * The protocol only overrides Protocol::hold_platen() (the plane as
 * constraints of the top face's vertical DOFs on three of its nodes, one of
 * them tied to the centre's displacement) and Protocol::move_platen() (the
 * plane shifted to the new centre displacement, its tilt kept).
 *
 * A postprocessor, also defined here, takes the platen's nodal forces and
 * the top face's displacements at the end of the run. Checked against
 * statics and symmetry, not against the code's own numbers:
 * - an elastic stack of two bricks is symmetric: the free platen does not
 *   tilt and the wall carries the same stress as under the fixed platen;
 * - two columns of two bricks pulled apart across their bed joints, whose
 *   strengths differ (`Strength scatter'), crack on one side first:
 *   the free platen tilts, its nodal forces have no resultant moment about
 *   the centre (the seat's equilibrium), the top face stays a plane whose
 *   centre sits at the applied displacement (these two are sanity checks
 *   of the protocol's constraints, which impose them); under the fixed platen
 * the same wall does carry a moment (so the moment check can fail), and its
 * peak is not below the free platen's (the clamp holds the weak side open with
 * the strong one).
 */
#include <masonry/brickwork/postprocessor.h>
#include <masonry/brickwork/protocol.h>

#include <deal.II/base/exceptions.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <limits>

#include "../source/brickwork/postprocess/view.h"
#include "brickwork_tests.h"

using namespace brickwork_tests;
using namespace masonry::brickwork;

namespace
{
  /** The monotonic ramp with the top platen free to tilt about its centre
   * (a spherical seat). For a platen moving along z. */
  class FreeRotation : public Protocol
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &)
    {}

    void
    initialize(const double height) override
    {
      target = target_strain * height;
    }

    std::vector<Leg>
    legs() const override
    {
      return {{target, false, 1}};
    }

    double
    amplitude(const unsigned int) const override
    {
      return target;
    }

    double
    target_displacement() const override
    {
      return target;
    }

    std::string
    description() const override
    {
      return "monotonic, the top platen free to tilt about its centre";
    }

    /**
     * The top face's vertical DOFs as a plane through three nodes A, B,
     * C at the corners (x0, y0), (x1, y0), (x0, y1): every other node
     * follows the plane with its barycentric weights; B follows A and C so
     * that the plane's height at the centre is held (the platen's
     * displacement). The lateral DOFs as the default platen.
     */
    void
    hold_platen(const Platen                      &platen,
                dealii::AffineConstraints<double> &constraints) const override
    {
      AssertThrow(std::abs(platen.direction[2]) == 1,
                  dealii::ExcMessage("free rotation: `Platen direction' "
                                     "must be 0, 0, -1 or 0, 0, 1"));
      corners(platen);
      const std::array<double, 3> c = weights(platen.centre);
      for (unsigned int i = 0; i < platen.dofs.size(); ++i)
        {
          for (unsigned int d = 0; d < 2; ++d)
            if (platen.lateral_fixed &&
                !constraints.is_constrained(platen.dofs[i][d]))
              constraints.add_line(platen.dofs[i][d]);
          const auto z = platen.dofs[i][2];
          if (i == node[0] || i == node[2] || constraints.is_constrained(z))
            continue;
          constraints.add_line(z);
          if (i == node[1])
            {
              // the centre's height is held: w_c = sum c_k w_k = 0 (the
              // increments)
              constraints.add_entry(z, dof(platen, 0), -c[0] / c[1]);
              constraints.add_entry(z, dof(platen, 2), -c[2] / c[1]);
              continue;
            }
          const std::array<double, 3> l = weights(platen.positions[i]);
          for (unsigned int k = 0; k < 3; ++k)
            if (l[k] != 0)
              constraints.add_entry(z, dof(platen, k), l[k]);
        }
    }

    /** The plane shifted so that its centre is at @p displacement, its tilt
     * kept (serial runs: the three nodes' values are read from @p u). */
    void
    move_platen(const Platen                            &platen,
                const double                             displacement,
                const dealii::AffineConstraints<double> &constraints,
                dealii::TrilinosWrappers::MPI::Vector   &u) const override
    {
      AssertThrow(u.locally_owned_elements().size() == u.size(),
                  dealii::ExcMessage("free rotation: one rank only"));
      corners(platen);
      const std::array<double, 3> c = weights(platen.centre);
      std::array<double, 3>       w;
      double                      centre = 0;
      for (unsigned int k = 0; k < 3; ++k)
        {
          w[k] = u[dof(platen, k)];
          centre += c[k] * w[k];
        }
      const double shift = displacement * platen.direction[2] - centre;
      for (unsigned int i = 0; i < platen.dofs.size(); ++i)
        {
          for (unsigned int d = 0; d < 2; ++d)
            if (constraints.is_constrained(platen.dofs[i][d]))
              u[platen.dofs[i][d]] = displacement * platen.direction[d];
          const std::array<double, 3> l = weights(platen.positions[i]);
          double                      z = 0;
          for (unsigned int k = 0; k < 3; ++k)
            z += l[k] * (w[k] + shift);
          u[platen.dofs[i][2]] = z;
        }
      u.compress(dealii::VectorOperation::insert);
    }

  private:
    /** Platen displacement at the end, m. */
    double target = 0;
    /** The top face's extent, m, and its nodes A, B, C. */
    mutable double                      x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    mutable std::array<unsigned int, 3> node{{0, 0, 0}};

    /** The extent of the top face and the nodes nearest its corners
     * (x0, y0), (x1, y0), (x0, y1). */
    void
    corners(const Platen &platen) const
    {
      x0 = y0 = std::numeric_limits<double>::max();
      x1 = y1 = -x0;
      for (const auto &p : platen.positions)
        {
          x0 = std::min(x0, p[0]);
          x1 = std::max(x1, p[0]);
          y0 = std::min(y0, p[1]);
          y1 = std::max(y1, p[1]);
        }
      const dealii::Point<3> corner[3] = {{x0, y0, 0},
                                          {x1, y0, 0},
                                          {x0, y1, 0}};
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int i = 0; i < platen.positions.size(); ++i)
          {
            const dealii::Point<3> &p = platen.positions[i],
                                   &q = platen.positions[node[k]];
            if (std::hypot(p[0] - corner[k][0], p[1] - corner[k][1]) <
                std::hypot(q[0] - corner[k][0], q[1] - corner[k][1]))
              node[k] = i;
          }
    }

    /** The barycentric weights of @p p on A, B, C. */
    std::array<double, 3>
    weights(const dealii::Point<3> &p) const
    {
      const double b = (p[0] - x0) / (x1 - x0), c = (p[1] - y0) / (y1 - y0);
      return {{1 - b - c, b, c}};
    }

    /** The vertical DOF of node @p k (0 A, 1 B, 2 C). */
    dealii::types::global_dof_index
    dof(const Platen &platen, const unsigned int k) const
    {
      return platen.dofs[node[k]][2];
    }
  };

  /** What the postprocessor takes of the top platen at the end. */
  struct TopFace
  {
    /** Resultant force along z (N) and moments about the centre (N m). */
    double force = 0, moment_x = 0, moment_y = 0;
    /** The face's vertical displacements: spread (m), the largest
     * distance of a node from the plane fitted through all of them (m),
     * and that plane's height at the centre (m). */
    double spread = 0, off_plane = 0, centre = 0;
    /** The face's half-length, m. */
    double half_length = 0;
  } top_face;

  /** Takes TopFace from the model at the end of the run: the platen and
   * the solution from the public view, the internal forces (the platen's
   * nodal reactions) from the model's System, private to the library. */
  class TopFaceProbe : public postprocess::Postprocessor
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &)
    {}

    void
    finish(const ModelView &view, masonry::Json &) override
    {
      const Platen &top = view.top_platen();
      const auto    u   = view.solution();
      const auto   &f   = view.system.f_int;
      const auto   &c   = top.centre;
      TopFace       t;
      double        lo = 1e300, hi = -1e300;
      // least squares plane w = a + b (x - xc) + d (y - yc)
      dealii::FullMatrix<double> m(3, 3);
      dealii::Vector<double>     r(3), abd(3);
      for (unsigned int i = 0; i < top.dofs.size(); ++i)
        {
          const auto  &p = top.positions[i];
          const double w = u[top.dofs[i][2]], fz = f[top.dofs[i][2]];
          t.force += fz;
          t.moment_x += fz * (p[1] - c[1]);
          t.moment_y += fz * (p[0] - c[0]);
          t.half_length = std::max(t.half_length, std::abs(p[0] - c[0]));
          lo            = std::min(lo, w);
          hi            = std::max(hi, w);
          const double basis[3] = {1, p[0] - c[0], p[1] - c[1]};
          for (unsigned int a = 0; a < 3; ++a)
            {
              r(a) += basis[a] * w;
              for (unsigned int b = 0; b < 3; ++b)
                m(a, b) += basis[a] * basis[b];
            }
        }
      m.gauss_jordan();
      m.vmult(abd, r);
      for (unsigned int i = 0; i < top.dofs.size(); ++i)
        {
          const auto &p = top.positions[i];
          t.off_plane =
            std::max(t.off_plane,
                     std::abs(u[top.dofs[i][2]] - abd(0) -
                              abd(1) * (p[0] - c[0]) - abd(2) * (p[1] - c[1])));
        }
      t.spread = hi - lo;
      t.centre = abd(0);
      top_face = t;
    }
  };

  /** A wallette of two bricks (stack bond, 2 x 2 x 1 cells each) under
   * @p protocol with the probe, the other entries in @p wallette and
   * @p laws. */
  std::string
  wall(const std::string &protocol,
       const std::string &wallette,
       const std::string &laws)
  {
    return prm("  set Protocol = " + protocol +
                 "\n"
                 "  set Courses = 2\n"
                 "  set Length in bricks = 1\n"
                 "  set Elements along the length = 2\n"
                 "  set Elements along the width = 2\n"
                 "  set Elements along the height = 1\n"
                 "  set Output interval = 0\n" +
                 wallette,
               "subsection Bond\n"
               "  set Pattern = stack\n"
               "end\n" +
                 laws +
                 "subsection Postprocess\n"
                 "  subsection Wallette\n"
                 "    set List of postprocessors = curve tables, top face\n"
                 "  end\n"
                 "end\n");
  }

  /** Run @p name and return its summary and top face. */
  std::pair<masonry::Json, TopFace>
  run_wall(const std::string &name, const std::string &text)
  {
    top_face                = TopFace();
    const masonry::Json sum = run(name, text);
    check(sum.at("status").get<std::string>() == "completed",
          name + ": the run completes");
    return {sum, top_face};
  }
} // namespace

MASONRY_REGISTER_PROTOCOL(FreeRotation,
                          "free rotation",
                          "The monotonic ramp with the top platen free to "
                          "tilt about its centre (a spherical seat).")
MASONRY_REGISTER_WALLETTE_POSTPROCESSOR(TopFaceProbe,
                                        "top face",
                                        "The test's probe of the top platen.")

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);

  // 1. symmetric: an elastic stack in compression, the platens free to
  //    slide
  const std::string elastic = "subsection Interface law\n"
                              "  set Law = elastic\n"
                              "end\n";
  const std::string squeeze = "  set Platen lateral restraint = free\n"
                              "  set Target strain = 0.0005\n"
                              "  set Number of steps = 2\n";
  const auto [fixed_sum, fixed] =
    run_wall("elastic_fixed", wall("monotonic", squeeze, elastic));
  const auto [free_sum, free] =
    run_wall("elastic_free", wall("free rotation", squeeze, elastic));
  const double s_fixed = fixed_sum.at("peak_stress").get<double>(),
               s_free  = free_sum.at("peak_stress").get<double>();
  if (!check(relative(s_free, s_fixed) < 1e-9 &&
               free.spread < 1e-9 * std::abs(free.centre),
             "symmetric elastic stack: the free platen does not tilt and the "
             "stress is the fixed platen's"))
    std::cout << "  stress " << s_free << " / " << s_fixed << " Pa, spread "
              << free.spread << " m at " << free.centre << " m\n";

  // 2. asymmetric: two columns whose bed joints have different strengths,
  //    pulled apart
  const std::string joint = "subsection Interface law\n"
                            "  set Law = bilinear\n"
                            "  subsection Bilinear\n"
                            "    set Tensile strength = 0.2e6\n"
                            "  end\n"
                            "end\n";
  const std::string pull  = "  set Platen direction = 0, 0, 1\n"
                            "  set Target strain = 0.0005\n"
                            "  set Number of steps = 40\n"
                            "  set Length in bricks = 2\n"
                            "  set Strength scatter = 0.3\n"
                            "  set Random seed = 3\n";
  const auto [clamp_sum, clamp] =
    run_wall("pull_fixed", wall("monotonic", pull, joint));
  const auto [seat_sum, seat] =
    run_wall("pull_free", wall("free rotation", pull, joint));
  const double applied = seat_sum.at("final_strain").get<double>() *
                         seat_sum.at("height").get<double>();
  const double moment_free = std::hypot(seat.moment_x, seat.moment_y) /
                             (std::abs(seat.force) * seat.half_length),
               moment_fixed = std::hypot(clamp.moment_x, clamp.moment_y) /
                              (std::abs(clamp.force) * clamp.half_length);
  if (!check(seat.spread > 1e-3 * applied,
             "scattered joint: the free platen tilts"))
    std::cout << "  spread " << seat.spread << " m, applied " << applied
              << " m\n";
  if (!check(moment_free < 1e-6,
             "scattered joint: the free platen's forces have no moment about "
             "its centre"))
    std::cout << "  |M| / (F L/2) = " << moment_free << "\n";
  if (!check(seat.off_plane < 1e-9 * applied &&
               std::abs(seat.centre - applied) < 1e-9 * applied,
             "scattered joint: the top face is a plane whose centre is at the "
             "applied displacement"))
    std::cout << "  off the plane " << seat.off_plane << " m, centre "
              << seat.centre << " m, applied " << applied << " m\n";
  if (!check(moment_fixed > 1e-3,
             "scattered joint: the fixed platen carries a moment"))
    std::cout << "  |M| / (F L/2) = " << moment_fixed << "\n";
  const double peak_free  = seat_sum.at("peak_stress").get<double>(),
               peak_fixed = clamp_sum.at("peak_stress").get<double>();
  if (!check(peak_free <= peak_fixed * (1 + 1e-9),
             "scattered joint: the free platen's peak is not above the "
             "fixed platen's"))
    std::cout << "  peaks " << peak_free << " / " << peak_fixed << " Pa\n";
  std::cout << std::flush;
  return 0;
}
