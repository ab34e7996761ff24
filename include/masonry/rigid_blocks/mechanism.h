/**
 * @file
 * The kinematic linear program shared by the rigid-block analyses: block
 * motions, plastic multipliers of the interface model and the contact
 * constraints (seed paper eqs. 5–8 with an associative flow rule).
 */
#ifndef masonry_rigid_blocks_mechanism_h
#define masonry_rigid_blocks_mechanism_h

#include <masonry/lp/linear_program.h>
#include <masonry/rigid_blocks/block_model.h>

#include <array>
#include <functional>

namespace masonry
{
  namespace lp
  {
    struct Solution;
  }
  namespace rigid_blocks
  {
    class InterfaceModel;
    struct Motion;

    /** Motion of the ground at a support point with an edge label. */
    using SupportMotion =
      std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &,
                                         const std::string &)>;

    /**
     * The constraints of a mechanism, as a linear program without
     * objective.
     *
     * Columns: for every block b, the translation of its centroid
     * (columns 6b, 6b+1, 6b+2, in the velocity unit of the problem) and its
     * rotation multiplied by `length` (6b+3 ... 6b+5), so that all entries
     * are O(1); then the plastic multipliers of the interface model (one
     * per yield plane and contact point, ≥ 0).
     *
     * Rows: three per contact point, in the order of the interfaces and
     * their points: the jump along the normal, across and along. Between
     * blocks the jump is v_second − v_first, at a support u0 − v_first.
     * - `no tension no sliding`: normal jump ≥ 0, tangential jumps = 0;
     * - other models: jump − Σ_k λ_k a_k = 0;
     * - bonded supports: all three jumps = 0 (the block follows u0).
     * The dual of a row is the contact force in that direction (N per unit
     * of the objective's force scale).
     *
     * Without plastic multipliers (`no tension no sliding`, bonded
     * supports), the rows of an interface that follow from its other rows
     * are left out (point_rows): equality rows that are, with their
     * right-hand side, linear combinations of kept ones (on a plane
     * interface the tangential jumps at all points follow from three), and
     * inequality rows that are nonnegative combinations of at most three
     * kept ones (the middle station of a straight edge). The feasible set
     * is the same; the contact forces are then carried by the kept rows.
     */
    struct MechanismProblem
    {
      /** The LP; every objective coefficient is zero. */
      lp::LinearProgram lp;
      /** 6 × number of blocks. */
      unsigned int n_block_columns = 0;
      /**
       * Dissipation per unit value of every column, N (tributary area ×
       * plane right-hand side; zero for block columns).
       */
      std::vector<double> dissipation;
      /** The length that scales rotations, m. */
      double length = 1;
      /**
       * For every contact point (in the order of the interfaces and their
       * points) the LP rows of its normal, across and along jump, or −1
       * for a row left out because the others imply it.
       */
      std::vector<std::array<int, 3>> point_rows;
    };

    /**
     * Build the constraints for @p model with joints of @p joints. @p u0
     * gives the ground motion at support points in the velocity unit of the
     * columns (nullptr: fixed ground). @p bonded_supports makes the
     * supports rigid (no multipliers). With @p leave_out_implied_rows, rows
     * that follow from the others are left out (see MechanismProblem).
     */
    MechanismProblem
    build_mechanism_problem(const BlockModel     &model,
                            const InterfaceModel &joints,
                            const SupportMotion  &u0,
                            const bool            bonded_supports,
                            const bool leave_out_implied_rows = true);

    /**
     * Objective coefficients of the block columns for the work of forces
     * @p force (N, at the centroids) and moments @p moment (N·m) divided by
     * @p force_scale (N).
     */
    std::vector<double>
    load_work(const std::vector<dealii::Tensor<1, 3>> &force,
              const std::vector<dealii::Tensor<1, 3>> &moment,
              const double                             length,
              const double                             force_scale);

    /**
     * The block motions of a solution: translations × @p velocity_scale
     * (m) and rotations × @p velocity_scale / length (rad).
     */
    Motion
    motion_from_solution(const MechanismProblem    &problem,
                         const std::vector<double> &x,
                         const double               velocity_scale);

    /**
     * Contact forces from the row duals: per contact point the normal,
     * across and along force, N, compression positive, given the force
     * unit @p force_scale of the objective and the sense in which it was
     * optimised (the dual of a maximisation and a minimisation differ in
     * sign). A point's component whose row was left out (see
     * MechanismProblem) is zero.
     */
    std::vector<std::array<double, 3>>
    contact_forces(const MechanismProblem &problem,
                   const lp::Solution     &solution,
                   const double            force_scale,
                   const bool              maximised);

    /** Total dissipation of a solution, in the objective's units. */
    double
    dissipated(const MechanismProblem &problem, const std::vector<double> &x);
  } // namespace rigid_blocks
} // namespace masonry

#endif
